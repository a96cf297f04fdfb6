// Per-class decoding of .m3g object records (JSR-184 1.1 file format, section
// "Per-Class Data", and §8).
#include "ObjectDecoder.h"

#include <algorithm>
#include <array>
#include <climits>
#include <memory>
#include <new>
#include <typeinfo>
#include <unordered_map>
#include <utility>

#include <m3g/AnimationController.h>
#include <m3g/AnimationTrack.h>
#include <m3g/Appearance.h>
#include <m3g/Background.h>
#include <m3g/Camera.h>
#include <m3g/CompositingMode.h>
#include <m3g/Exception.h>
#include <m3g/Fog.h>
#include <m3g/Group.h>
#include <m3g/Image2D.h>
#include <m3g/IndexBuffer.h>
#include <m3g/KeyframeSequence.h>
#include <m3g/Light.h>
#include <m3g/Material.h>
#include <m3g/Mesh.h>
#include <m3g/MorphingMesh.h>
#include <m3g/Node.h>
#include <m3g/PolygonMode.h>
#include <m3g/SkinnedMesh.h>
#include <m3g/Sprite3D.h>
#include <m3g/Texture2D.h>
#include <m3g/Transform.h>
#include <m3g/TriangleStripArray.h>
#include <m3g/VertexArray.h>
#include <m3g/VertexBuffer.h>
#include <m3g/World.h>

#include "Check.h"

namespace m3g::detail {

namespace {

/// Largest mutable Image2D accepted (a mutable image has no pixel data in
/// the file, so its size must be bounded explicitly).
constexpr std::uint32_t kMaxMutableImageDimension = 16384;
constexpr std::uint64_t kMaxMutableImageBytes = 64ull << 20;
/// Deepest node hierarchy accepted (Group children, SkinnedMesh skeletons).
/// Traversal and destruction recurse over the hierarchy, so a hostile file
/// with a chain of 100 000 nested groups must not get through; real scenes
/// nest a few dozen levels.
constexpr int kMaxNodeDepth = 1000;

// ---- inherited blocks (JSR-184 1.1 file format, section "Per-Class Data"),
// read first, applied once the object exists ----

struct Object3DBlock {
    std::uint32_t userID = 0;
    std::vector<Ref<AnimationTrack>> tracks;  // null entries: skipped (lenient)
    std::shared_ptr<UserParameters> parameters;  // null when the count is 0
};

struct TransformableBlock {
    Object3DBlock base;
    bool hasComponent = false;
    std::array<float, 3> translation{}, scale{}, axis{};
    float angle = 0;
    bool hasGeneral = false;
    std::array<float, 16> matrix{};
};

struct NodeBlock {
    TransformableBlock base;
    bool rendering = true, picking = true;
    std::uint8_t alpha = 255;
    std::uint32_t scope = 0;
    bool hasAlignment = false;
    int zTarget = Node::NONE, yTarget = Node::NONE;
    Ref<Node> zRef, yRef;
};

struct GroupBlock {
    NodeBlock node;
    std::vector<Ref<Node>> children;
};

struct MeshBlock {
    NodeBlock node;
    Ref<VertexBuffer> vertexBuffer;
    std::vector<Ref<IndexBuffer>> indexBuffers;
    std::vector<Ref<Appearance>> appearances;
};

/// A span that is never "null" (Java null is a span whose data() is null),
/// also for an empty vector.
template <class T>
std::span<const T> nonNull(const std::vector<T>& v) {
    static const T kNone[1] = {};
    return v.empty() ? std::span<const T>(kNone, 0) : std::span<const T>(v);
}

const char* exceptionKind(const std::exception& e) {
    if (dynamic_cast<const IllegalArgumentException*>(&e)) return "IllegalArgumentException";
    if (dynamic_cast<const IndexOutOfBoundsException*>(&e)) return "IndexOutOfBoundsException";
    if (dynamic_cast<const IllegalStateException*>(&e)) return "IllegalStateException";
    if (dynamic_cast<const NullPointerException*>(&e)) return "NullPointerException";
    if (dynamic_cast<const ArithmeticException*>(&e)) return "ArithmeticException";
    if (dynamic_cast<const OutOfMemoryError*>(&e)) return "OutOfMemoryError";
    if (dynamic_cast<const std::bad_alloc*>(&e)) return "out of memory";
    return "exception";
}

class Decoder {
public:
    Decoder(const M3GFile& file, LoadLog& log, const ExternalResolver& resolve)
        : file_(file), log_(log), resolve_(resolve) {
        const std::size_t n = file.objects.empty() ? 0 : file.objects.size() - 1;
        out_.table.resize(n);
        out_.referenced.assign(n, false);
        out_.skipped.assign(n, false);
    }

    DecodedObjects run() {
        for (std::size_t i = 1; i < file_.objects.size(); ++i) decodeOne(file_.objects[i]);
        return std::move(out_);
    }

private:
    const M3GFile& file_;
    LoadLog& log_;
    const ExternalResolver& resolve_;
    DecodedObjects out_;
    std::uint32_t current_ = 0;   // ObjectIndex of the object being decoded
    bool touchedSkipped_ = false;  // it referred to a skipped object
    std::unordered_map<const Node*, int> height_;  // node hierarchy height

    void decodeOne(const M3GObject& o) {
        current_ = o.index;
        touchedSkipped_ = false;
        ByteReader r = objectReader(o, &log_);
        Ref<Object3D> obj;
        try {
            obj = decode(o.type, r);
            if (obj) r.expectEnd("object data");
        } catch (const IOException&) {
            throw;
        } catch (const NullPointerException& e) {
            if (log_.lenient() && touchedSkipped_) {
                log_.warn(str(objectContext(o), ": skipped because it needs an object that was skipped (", e.what(),
                              ") at byte offset ", o.dataOffset));
                out_.skipped[o.index - 2] = true;
                return;
            }
            rethrow(o, r, e);
        } catch (const std::exception& e) {
            rethrow(o, r, e);
        }
        if (!obj) {
            out_.skipped[o.index - 2] = true;
            return;
        }
        if (const Node* n = dynamic_cast<const Node*>(obj.get())) {
            std::vector<Node*> kids;
            n->collectChildren(kids);
            int h = 1;
            for (const Node* k : kids) {
                auto it = height_.find(k);
                h = std::max(h, 1 + (it == height_.end() ? 1 : it->second));
            }
            if (h > kMaxNodeDepth)
                throw IOException(str(objectContext(o), ": node hierarchy deeper than ", kMaxNodeDepth,
                                      " levels at byte offset ", o.dataOffset));
            height_[n] = h;
        }
        out_.table[o.index - 2] = std::move(obj);
    }

    [[noreturn]] void rethrow(const M3GObject& o, const ByteReader& r, const std::exception& e) {
        throw IOException(str(objectContext(o), ": value rejected (", exceptionKind(e), ": ", e.what(),
                              ") in the object data at byte offset ", o.dataOffset, ", read up to byte offset ",
                              r.offset(), o.inflated ? str(" of the inflated data of section ", o.section) : ""));
    }

    // ---- references (JSR-184 1.1 file format §8) ----

    Object3D* refAny(ByteReader& r, const char* what, std::size_t& pos, std::uint32_t& idx) {
        pos = r.position();
        idx = r.readObjectIndex();
        if (idx == 0) return nullptr;
        if (idx == 1) r.failAt(pos, str(what, ": ObjectIndex 1 refers to the header object"));
        if (idx == current_) r.failAt(pos, str(what, ": ObjectIndex ", idx, " refers to the object itself"));
        if (idx > current_)
            r.failAt(pos, str(what, ": forward reference to ObjectIndex ", idx, " (object ", current_,
                              " may refer only to earlier objects)"));
        const std::size_t k = idx - 2;
        out_.referenced[k] = true;
        if (out_.skipped[k]) {
            touchedSkipped_ = true;
            return nullptr;
        }
        return out_.table[k].get();
    }

    template <class T>
    T* ref(ByteReader& r, const char* what, const char* expected) {
        std::size_t pos;
        std::uint32_t idx;
        Object3D* o = refAny(r, what, pos, idx);
        if (!o) return nullptr;
        T* t = dynamic_cast<T*>(o);
        if (!t)
            r.failAt(pos, str(what, ": ObjectIndex ", idx, " is a ", o->getClassName(), ", expected ", expected));
        return t;
    }

    // ---- inherited blocks ----

    Object3DBlock readObject3D(ByteReader& r) {
        Object3DBlock b;
        b.userID = r.readUInt32();
        const std::uint32_t trackCount = r.readCount(4, "animationTracks");
        b.tracks.reserve(trackCount);
        for (std::uint32_t i = 0; i < trackCount; ++i) {
            const bool before = touchedSkipped_;
            touchedSkipped_ = false;
            AnimationTrack* t = ref<AnimationTrack>(r, "animation track", "AnimationTrack");
            if (!t && touchedSkipped_) {
                r.warn(str("animation track ", i, " refers to a skipped object; left out"));
            } else if (!t) {
                r.fail(str("animation track ", i, " is null"));
            } else {
                b.tracks.emplace_back(t);
            }
            touchedSkipped_ = touchedSkipped_ || before;
        }
        const std::uint32_t paramCount = r.readCount(8, "user parameters");
        if (paramCount > 0) {
            b.parameters = std::make_shared<UserParameters>();
            for (std::uint32_t i = 0; i < paramCount; ++i) {
                const std::size_t idPos = r.position();
                const std::uint32_t id = r.readUInt32();
                auto value = r.readByteArray("user parameter value");
                if (!b.parameters->emplace(static_cast<int>(id), std::move(value)).second)
                    r.failAt(idPos, str("duplicate user parameter ID ", id));
            }
        }
        return b;
    }

    void apply(Object3D& o, const Object3DBlock& b) {
        o.setUserID(static_cast<int>(b.userID));
        for (const auto& t : b.tracks) o.addAnimationTrack(t.get());
        if (b.parameters) o.setUserObject(std::shared_ptr<const UserParameters>(b.parameters));
    }

    TransformableBlock readTransformable(ByteReader& r) {
        TransformableBlock b;
        b.base = readObject3D(r);
        b.hasComponent = r.readBoolean();
        if (b.hasComponent) {
            b.translation = r.readVector3D();
            b.scale = r.readVector3D();
            b.angle = r.readFloat32();
            b.axis = r.readVector3D();
        }
        b.hasGeneral = r.readBoolean();
        if (b.hasGeneral) b.matrix = r.readMatrix();
        return b;
    }

    void apply(Transformable& o, const TransformableBlock& b) {
        apply(static_cast<Object3D&>(o), b.base);
        if (b.hasComponent) {
            o.setTranslation(b.translation[0], b.translation[1], b.translation[2]);
            o.setScale(b.scale[0], b.scale[1], b.scale[2]);
            o.setOrientation(b.angle, b.axis[0], b.axis[1], b.axis[2]);
        }
        if (b.hasGeneral) {
            Transform t;
            t.set(std::span<const float>(b.matrix));
            o.setTransform(&t);
        }
    }

    NodeBlock readNode(ByteReader& r) {
        NodeBlock b;
        b.base = readTransformable(r);
        b.rendering = r.readBoolean();
        b.picking = r.readBoolean();
        b.alpha = r.readByte();
        b.scope = r.readUInt32();
        b.hasAlignment = r.readBoolean();
        if (b.hasAlignment) {
            b.zTarget = r.readByte();
            b.yTarget = r.readByte();
            b.zRef = ref<Node>(r, "zReference", "Node");
            b.yRef = ref<Node>(r, "yReference", "Node");
        }
        return b;
    }

    void apply(Node& o, const NodeBlock& b) {
        apply(static_cast<Transformable&>(o), b.base);
        o.setRenderingEnable(b.rendering);
        o.setPickingEnable(b.picking);
        o.setAlphaFactor(static_cast<float>(b.alpha) / 255.0f);
        o.setScope(static_cast<int>(b.scope));
        if (b.hasAlignment) o.setAlignment(b.zRef.get(), b.zTarget, b.yRef.get(), b.yTarget);
    }

    GroupBlock readGroup(ByteReader& r) {
        GroupBlock b;
        b.node = readNode(r);
        const std::uint32_t n = r.readCount(4, "children");
        b.children.reserve(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            const bool before = touchedSkipped_;
            touchedSkipped_ = false;
            Node* c = ref<Node>(r, "child", "Node");
            if (!c && touchedSkipped_) {
                r.warn(str("child ", i, " refers to a skipped object; left out"));
            } else {
                b.children.emplace_back(c);  // null: addChild throws NPE
            }
            touchedSkipped_ = touchedSkipped_ || before;
        }
        return b;
    }

    void apply(Group& o, const GroupBlock& b) {
        apply(static_cast<Node&>(o), b.node);
        for (const auto& c : b.children) o.addChild(c.get());
    }

    MeshBlock readMesh(ByteReader& r) {
        MeshBlock b;
        b.node = readNode(r);
        b.vertexBuffer = ref<VertexBuffer>(r, "vertexBuffer", "VertexBuffer");
        const std::uint32_t n = r.readCount(8, "submeshes");
        b.indexBuffers.reserve(n);
        b.appearances.reserve(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            b.indexBuffers.emplace_back(ref<IndexBuffer>(r, "indexBuffer", "IndexBuffer"));
            b.appearances.emplace_back(ref<Appearance>(r, "appearance", "Appearance"));
        }
        return b;
    }

    // ---- per class (JSR-184 1.1 file format, section "Per-Class Data") ----

    Ref<Object3D> decode(std::uint8_t type, ByteReader& r) {
        switch (type) {
        case kTypeAnimationController: return animationController(r);
        case kTypeAnimationTrack: return animationTrack(r);
        case kTypeAppearance: return appearance(r);
        case kTypeBackground: return background(r);
        case kTypeCamera: return camera(r);
        case kTypeCompositingMode: return compositingMode(r);
        case kTypeFog: return fog(r);
        case kTypePolygonMode: return polygonMode(r);
        case kTypeGroup: return group(r);
        case kTypeImage2D: return image2D(r);
        case kTypeTriangleStripArray: return triangleStripArray(r);
        case kTypeLight: return light(r);
        case kTypeMaterial: return material(r);
        case kTypeMesh: return mesh(r);
        case kTypeMorphingMesh: return morphingMesh(r);
        case kTypeSkinnedMesh: return skinnedMesh(r);
        case kTypeTexture2D: return texture2D(r);
        case kTypeSprite3D: return sprite3D(r);
        case kTypeKeyframeSequence: return keyframeSequence(r);
        case kTypeVertexArray: return vertexArray(r);
        case kTypeVertexBuffer: return vertexBuffer(r);
        case kTypeWorld: return world(r);
        case kTypeExternalReference: return externalReference(r);
        default: r.failAt(0, str("unexpected ObjectType ", int(type)));
        }
    }

    Ref<Object3D> animationController(ByteReader& r) {
        const Object3DBlock b = readObject3D(r);
        const float speed = r.readFloat32();
        const float weight = r.readFloat32();
        const std::int32_t start = r.readInt32();
        const std::int32_t end = r.readInt32();
        const float refSequenceTime = r.readFloat32();
        const std::int32_t refWorldTime = r.readInt32();
        Ref<AnimationController> c = make<AnimationController>();
        apply(*c, b);
        c->setPosition(refSequenceTime, refWorldTime);
        c->setSpeed(speed, refWorldTime);
        c->setWeight(weight);
        c->setActiveInterval(start, end);
        return c;
    }

    Ref<Object3D> animationTrack(ByteReader& r) {
        const Object3DBlock b = readObject3D(r);
        Ref<KeyframeSequence> seq = ref<KeyframeSequence>(r, "keyframeSequence", "KeyframeSequence");
        Ref<AnimationController> ctrl = ref<AnimationController>(r, "animationController", "AnimationController");
        const std::uint32_t property = r.readUInt32();
        Ref<AnimationTrack> t = make<AnimationTrack>(seq.get(), static_cast<int>(property));
        apply(*t, b);
        if (ctrl) t->setController(ctrl.get());
        return t;
    }

    Ref<Object3D> appearance(ByteReader& r) {
        const Object3DBlock b = readObject3D(r);
        // Two's complement, as Nokia's M3G implementation (reference) reads it.
        const int layer = static_cast<std::int8_t>(r.readByte());
        Ref<CompositingMode> cm = ref<CompositingMode>(r, "compositingMode", "CompositingMode");
        Ref<Fog> fog = ref<Fog>(r, "fog", "Fog");
        Ref<PolygonMode> pm = ref<PolygonMode>(r, "polygonMode", "PolygonMode");
        Ref<Material> mat = ref<Material>(r, "material", "Material");
        const std::uint32_t n = r.readCount(4, "textures");
        std::vector<Ref<Texture2D>> textures;
        textures.reserve(n);
        for (std::uint32_t i = 0; i < n; ++i) textures.emplace_back(ref<Texture2D>(r, "texture", "Texture2D"));
        Ref<Appearance> a = make<Appearance>();
        apply(*a, b);
        a->setLayer(layer);
        a->setCompositingMode(cm.get());
        a->setFog(fog.get());
        a->setPolygonMode(pm.get());
        a->setMaterial(mat.get());
        // Null entries leave the unit empty (setTexture is not called, so a
        // null past the implementation's unit count is not an error).
        for (std::uint32_t i = 0; i < n; ++i)
            if (textures[i]) a->setTexture(static_cast<int>(i), textures[i].get());
        return a;
    }

    Ref<Object3D> background(ByteReader& r) {
        const Object3DBlock b = readObject3D(r);
        const std::uint32_t color = r.readColorRGBA();
        Ref<Image2D> image = ref<Image2D>(r, "backgroundImage", "Image2D");
        const int modeX = r.readByte();
        const int modeY = r.readByte();
        const std::int32_t cropX = r.readInt32();
        const std::int32_t cropY = r.readInt32();
        const std::int32_t cropW = r.readInt32();
        const std::int32_t cropH = r.readInt32();
        // File-format order (JSR-184 1.1 file format, section "Per-Class Data",
        // Background): depthClearEnabled, then colorClearEnabled. Nokia's M3G
        // implementation (reference) reads them the other way round.
        const bool depthClear = r.readBoolean();
        const bool colorClear = r.readBoolean();
        Ref<Background> g = make<Background>();
        apply(*g, b);
        g->setColor(static_cast<int>(color));
        g->setImage(image.get());
        g->setImageMode(modeX, modeY);
        g->setCrop(cropX, cropY, cropW, cropH);
        g->setDepthClearEnable(depthClear);
        g->setColorClearEnable(colorClear);
        return g;
    }

    Ref<Object3D> camera(ByteReader& r) {
        const NodeBlock b = readNode(r);
        const std::size_t typePos = r.position();
        const int projection = r.readByte();
        Ref<Camera> c = make<Camera>();
        if (projection == Camera::GENERIC) {
            const auto m = r.readMatrix();
            apply(*c, b);
            Transform t;
            t.set(std::span<const float>(m));
            c->setGeneric(&t);
        } else if (projection == Camera::PERSPECTIVE || projection == Camera::PARALLEL) {
            const float p0 = r.readFloat32();
            const float aspect = r.readFloat32();
            const float nearZ = r.readFloat32();
            const float farZ = r.readFloat32();
            apply(*c, b);
            if (projection == Camera::PERSPECTIVE) c->setPerspective(p0, aspect, nearZ, farZ);
            else c->setParallel(p0, aspect, nearZ, farZ);
        } else {
            r.failAt(typePos, str("invalid projectionType ", projection, " (48, 49 or 50)"));
        }
        return c;
    }

    Ref<Object3D> compositingMode(ByteReader& r) {
        const Object3DBlock b = readObject3D(r);
        const bool depthTest = r.readBoolean();
        const bool depthWrite = r.readBoolean();
        const bool colorWrite = r.readBoolean();
        const bool alphaWrite = r.readBoolean();
        const int blending = r.readByte();
        const std::uint8_t threshold = r.readByte();
        const float factor = r.readFloat32();
        const float units = r.readFloat32();
        Ref<CompositingMode> c = make<CompositingMode>();
        apply(*c, b);
        c->setDepthTestEnable(depthTest);
        c->setDepthWriteEnable(depthWrite);
        c->setColorWriteEnable(colorWrite);
        c->setAlphaWriteEnable(alphaWrite);
        c->setBlending(blending);
        c->setAlphaThreshold(static_cast<float>(threshold) / 255.0f);
        c->setDepthOffset(factor, units);
        return c;
    }

    Ref<Object3D> fog(ByteReader& r) {
        const Object3DBlock b = readObject3D(r);
        const std::uint32_t color = r.readColorRGB();
        const std::size_t modePos = r.position();
        const int mode = r.readByte();
        Ref<Fog> f = make<Fog>();
        apply(*f, b);
        f->setColor(static_cast<int>(color));
        if (mode == Fog::EXPONENTIAL) {
            const float density = r.readFloat32();
            f->setMode(mode);
            f->setDensity(density);
        } else if (mode == Fog::LINEAR) {
            const float nearZ = r.readFloat32();
            const float farZ = r.readFloat32();
            f->setMode(mode);
            f->setLinear(nearZ, farZ);
        } else {
            r.failAt(modePos, str("invalid fog mode ", mode, " (80 or 81)"));
        }
        return f;
    }

    Ref<Object3D> polygonMode(ByteReader& r) {
        const Object3DBlock b = readObject3D(r);
        const int culling = r.readByte();
        const int shading = r.readByte();
        const int winding = r.readByte();
        const bool twoSided = r.readBoolean();
        const bool localCamera = r.readBoolean();
        const bool perspective = r.readBoolean();
        Ref<PolygonMode> p = make<PolygonMode>();
        apply(*p, b);
        p->setCulling(culling);
        p->setShading(shading);
        p->setWinding(winding);
        p->setTwoSidedLightingEnable(twoSided);
        p->setLocalCameraLightingEnable(localCamera);
        p->setPerspectiveCorrectionEnable(perspective);
        return p;
    }

    Ref<Object3D> group(ByteReader& r) {
        const GroupBlock b = readGroup(r);
        Ref<Group> g = make<Group>();
        apply(*g, b);
        return g;
    }

    Ref<Object3D> image2D(ByteReader& r) {
        const Object3DBlock b = readObject3D(r);
        const std::size_t formatPos = r.position();
        const int format = r.readByte();
        const bool isMutable = r.readBoolean();
        const std::size_t sizePos = r.position();
        const std::uint32_t width = r.readUInt32();
        const std::uint32_t height = r.readUInt32();
        const int bpp = Image2D::bytesPerPixel(format);
        if (bpp == 0) r.failAt(formatPos, str("invalid image format ", format, " (96..100)"));
        if (width == 0 || height == 0 || width > INT_MAX || height > INT_MAX)
            r.failAt(sizePos, str("invalid image size ", width, " x ", height));
        const std::uint64_t pixelCount = std::uint64_t(width) * height;
        Ref<Image2D> img;
        if (isMutable) {
            if (width > kMaxMutableImageDimension || height > kMaxMutableImageDimension ||
                pixelCount * std::uint64_t(bpp) > kMaxMutableImageBytes)
                r.failAt(sizePos, str("mutable image ", width, " x ", height, " is larger than the loader accepts (",
                                      kMaxMutableImageDimension, " per side, ", kMaxMutableImageBytes, " bytes)"));
            img = make<Image2D>(format, static_cast<int>(width), static_cast<int>(height));
        } else {
            const std::size_t palettePos = r.position();
            const std::uint32_t paletteLength = r.readCount(1, "palette");
            const auto palette = r.readBytes(paletteLength, "palette");
            const std::size_t pixelsPos = r.position();
            const std::uint32_t pixelsLength = r.readCount(1, "pixels");
            const auto pixels = r.readBytes(pixelsLength, "pixels");
            if (paletteLength > 0) {
                if (paletteLength % std::uint32_t(bpp) != 0 || paletteLength > 256u * std::uint32_t(bpp))
                    r.failAt(palettePos, str("palette of ", paletteLength, " bytes is not a whole number of at most "
                                             "256 entries of ", bpp, " bytes"));
                if (pixelsLength != pixelCount)
                    r.failAt(pixelsPos, str("paletted image ", width, " x ", height, " needs ", pixelCount,
                                            " index bytes, the file has ", pixelsLength));
                img = make<Image2D>(format, static_cast<int>(width), static_cast<int>(height), pixels, palette);
            } else {
                if (pixelsLength != pixelCount * std::uint64_t(bpp))
                    r.failAt(pixelsPos, str("image ", width, " x ", height, " needs ", pixelCount * std::uint64_t(bpp),
                                            " pixel bytes, the file has ", pixelsLength));
                img = make<Image2D>(format, static_cast<int>(width), static_cast<int>(height), pixels);
            }
        }
        apply(*img, b);
        return img;
    }

    Ref<Object3D> triangleStripArray(ByteReader& r) {
        const Object3DBlock b = readObject3D(r);
        const std::size_t encPos = r.position();
        const int encoding = r.readByte();
        bool implicit = true;
        long long start = 0;
        std::vector<int> indices;
        switch (encoding) {
        case 0: start = r.readUInt32(); break;
        case 1: start = r.readByte(); break;
        case 2: start = r.readUInt16(); break;
        case 128: {
            implicit = false;
            const std::uint32_t n = r.readCount(4, "indices");
            indices.resize(n);
            for (auto& x : indices) {
                const std::size_t p = r.position();
                const std::uint32_t v = r.readUInt32();
                if (v > 65535) r.failAt(p, str("index ", v, " out of range [0, 65535]"));
                x = static_cast<int>(v);
            }
            break;
        }
        case 129: {
            implicit = false;
            const std::uint32_t n = r.readCount(1, "indices");
            indices.resize(n);
            for (auto& x : indices) x = r.readByte();
            break;
        }
        case 130: {
            implicit = false;
            const std::uint32_t n = r.readCount(2, "indices");
            indices.resize(n);
            for (auto& x : indices) x = r.readUInt16();
            break;
        }
        default:
            r.failAt(encPos, str("invalid TriangleStripArray encoding ", encoding, " (0, 1, 2, 128, 129 or 130)"));
        }
        const std::uint32_t n = r.readCount(4, "stripLengths");
        std::vector<int> lengths(n);
        for (auto& x : lengths) {
            const std::size_t p = r.position();
            const std::uint32_t v = r.readUInt32();
            if (v > 65536) r.failAt(p, str("strip length ", v, " is larger than 65536"));
            x = static_cast<int>(v);
        }
        if (implicit && start > 65535) r.failAt(encPos + 1, str("startIndex ", start, " out of range [0, 65535]"));
        Ref<TriangleStripArray> t = implicit ? make<TriangleStripArray>(static_cast<int>(start), nonNull(lengths))
                                             : make<TriangleStripArray>(nonNull(indices), nonNull(lengths));
        apply(*t, b);
        return t;
    }

    Ref<Object3D> light(ByteReader& r) {
        const NodeBlock b = readNode(r);
        const float c = r.readFloat32();
        const float l = r.readFloat32();
        const float q = r.readFloat32();
        const std::uint32_t color = r.readColorRGB();
        const int mode = r.readByte();
        const float intensity = r.readFloat32();
        const float spotAngle = r.readFloat32();
        const float spotExponent = r.readFloat32();
        Ref<Light> li = make<Light>();
        apply(*li, b);
        li->setAttenuation(c, l, q);
        li->setColor(static_cast<int>(color));
        li->setMode(mode);
        li->setIntensity(intensity);
        li->setSpotAngle(spotAngle);
        li->setSpotExponent(spotExponent);
        return li;
    }

    Ref<Object3D> material(ByteReader& r) {
        const Object3DBlock b = readObject3D(r);
        const std::uint32_t ambient = r.readColorRGB();
        const std::uint32_t diffuse = r.readColorRGBA();
        const std::uint32_t emissive = r.readColorRGB();
        const std::uint32_t specular = r.readColorRGB();
        const float shininess = r.readFloat32();
        const bool tracking = r.readBoolean();
        Ref<Material> m = make<Material>();
        apply(*m, b);
        m->setColor(Material::AMBIENT, static_cast<int>(ambient));
        m->setColor(Material::DIFFUSE, static_cast<int>(diffuse));
        m->setColor(Material::EMISSIVE, static_cast<int>(emissive));
        m->setColor(Material::SPECULAR, static_cast<int>(specular));
        m->setShininess(shininess);
        m->setVertexColorTrackingEnable(tracking);
        return m;
    }

    Ref<Object3D> mesh(ByteReader& r) {
        const MeshBlock b = readMesh(r);
        Ref<Mesh> m = make<Mesh>(b.vertexBuffer.get(), nonNull(b.indexBuffers), nonNull(b.appearances));
        apply(*m, b.node);
        return m;
    }

    Ref<Object3D> morphingMesh(ByteReader& r) {
        const MeshBlock b = readMesh(r);
        const std::uint32_t n = r.readCount(8, "morph targets");
        std::vector<Ref<VertexBuffer>> targets;
        std::vector<float> weights;
        targets.reserve(n);
        weights.reserve(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            targets.emplace_back(ref<VertexBuffer>(r, "morphTarget", "VertexBuffer"));
            weights.push_back(r.readFloat32());
        }
        Ref<MorphingMesh> m = make<MorphingMesh>(b.vertexBuffer.get(), nonNull(targets), nonNull(b.indexBuffers),
                                                 nonNull(b.appearances));
        apply(*m, b.node);
        if (!weights.empty()) m->setWeights(weights);
        return m;
    }

    Ref<Object3D> skinnedMesh(ByteReader& r) {
        const MeshBlock b = readMesh(r);
        Ref<Group> skeleton = ref<Group>(r, "skeleton", "Group");
        const std::uint32_t n = r.readCount(16, "transform references");
        struct Bone {
            Ref<Node> node;
            std::uint32_t first, count;
            std::int32_t weight;
        };
        std::vector<Bone> bones;
        bones.reserve(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            const bool before = touchedSkipped_;
            touchedSkipped_ = false;
            Bone bone;
            bone.node = ref<Node>(r, "transformNode", "Node");
            bone.first = r.readUInt32();
            bone.count = r.readUInt32();
            bone.weight = r.readInt32();
            if (!bone.node && touchedSkipped_) r.warn(str("transform reference ", i, " refers to a skipped object; left out"));
            else bones.push_back(std::move(bone));
            touchedSkipped_ = touchedSkipped_ || before;
        }
        Ref<SkinnedMesh> m = make<SkinnedMesh>(b.vertexBuffer.get(), nonNull(b.indexBuffers), nonNull(b.appearances),
                                               skeleton.get());
        apply(*m, b.node);
        for (const auto& bone : bones)
            m->addTransform(bone.node.get(), bone.weight, static_cast<int>(bone.first), static_cast<int>(bone.count));
        return m;
    }

    Ref<Object3D> texture2D(ByteReader& r) {
        const TransformableBlock b = readTransformable(r);
        Ref<Image2D> image = ref<Image2D>(r, "image", "Image2D");
        const std::uint32_t blendColor = r.readColorRGB();
        const int blending = r.readByte();
        const int wrapS = r.readByte();
        const int wrapT = r.readByte();
        const int levelFilter = r.readByte();
        const int imageFilter = r.readByte();
        Ref<Texture2D> t = make<Texture2D>(image.get());
        apply(*t, b);
        t->setBlendColor(static_cast<int>(blendColor));
        t->setBlending(blending);
        t->setWrapping(wrapS, wrapT);
        t->setFiltering(levelFilter, imageFilter);
        return t;
    }

    Ref<Object3D> sprite3D(ByteReader& r) {
        const NodeBlock b = readNode(r);
        Ref<Image2D> image = ref<Image2D>(r, "image", "Image2D");
        Ref<Appearance> app = ref<Appearance>(r, "appearance", "Appearance");
        const bool scaled = r.readBoolean();
        const std::int32_t cropX = r.readInt32();
        const std::int32_t cropY = r.readInt32();
        const std::int32_t cropW = r.readInt32();
        const std::int32_t cropH = r.readInt32();
        Ref<Sprite3D> s = make<Sprite3D>(scaled, image.get(), app.get());
        apply(*s, b);
        s->setCrop(cropX, cropY, cropW, cropH);
        return s;
    }

    Ref<Object3D> keyframeSequence(ByteReader& r) {
        const Object3DBlock b = readObject3D(r);
        const int interpolation = r.readByte();
        const int repeatMode = r.readByte();
        const std::size_t encPos = r.position();
        const int encoding = r.readByte();
        const std::uint32_t duration = r.readUInt32();
        const std::uint32_t first = r.readUInt32();
        const std::uint32_t last = r.readUInt32();
        const std::size_t countPos = r.position();
        const std::uint32_t components = r.readUInt32();
        const std::uint32_t keyframes = r.readUInt32();
        if (encoding > 2) r.failAt(encPos, str("invalid keyframe encoding ", encoding, " (0, 1 or 2)"));
        if (components == 0 || keyframes == 0)
            r.failAt(countPos, str("componentCount ", components, " and keyframeCount ", keyframes,
                                   " must both be at least 1"));
        std::vector<float> bias, scale;
        std::uint64_t valueSize = 4;
        if (encoding > 0) {
            bias = r.readFloat32s(components, "vectorBias");
            scale = r.readFloat32s(components, "vectorScale");
            valueSize = encoding == 1 ? 1 : 2;
        }
        // Everything must be present before the sequence is allocated.
        r.requireAvailable(keyframes, 4 + valueSize * components, "keyframes");
        if (keyframes > INT_MAX || components > INT_MAX) r.failAt(countPos, "keyframe data too large");
        Ref<KeyframeSequence> k =
            make<KeyframeSequence>(static_cast<int>(keyframes), static_cast<int>(components), interpolation);
        apply(*k, b);
        k->setRepeatMode(repeatMode);
        k->setDuration(static_cast<int>(duration));
        k->setValidRange(static_cast<int>(first), static_cast<int>(last));
        std::vector<float> value(components);
        for (std::uint32_t i = 0; i < keyframes; ++i) {
            const std::int32_t time = r.readInt32();
            for (std::uint32_t c = 0; c < components; ++c) {
                if (encoding == 0) {
                    value[c] = r.readFloat32();
                } else if (encoding == 1) {
                    value[c] = static_cast<float>(double(bias[c]) + double(scale[c]) * r.readByte() / 255.0);
                } else {
                    value[c] = static_cast<float>(double(bias[c]) + double(scale[c]) * r.readUInt16() / 65535.0);
                }
            }
            k->setKeyframe(static_cast<int>(i), time, value);
        }
        return k;
    }

    Ref<Object3D> vertexArray(ByteReader& r) {
        const Object3DBlock b = readObject3D(r);
        const std::size_t sizePos = r.position();
        const int componentSize = r.readByte();
        const int componentCount = r.readByte();
        const std::size_t encPos = r.position();
        const int encoding = r.readByte();
        const int vertexCount = r.readUInt16();
        if (componentSize != 1 && componentSize != 2)
            r.failAt(sizePos, str("invalid componentSize ", componentSize, " (1 or 2)"));
        if (encoding > 1) r.failAt(encPos, str("invalid vertex array encoding ", encoding, " (0 or 1)"));
        const std::uint64_t n = std::uint64_t(vertexCount) * std::uint64_t(componentCount);
        r.requireAvailable(n, std::uint64_t(componentSize), "vertex values");
        Ref<VertexArray> va = make<VertexArray>(vertexCount, componentCount, componentSize);
        apply(*va, b);
        const bool delta = encoding == 1;
        if (componentSize == 1) {
            std::vector<std::int8_t> v(n);
            for (std::uint64_t i = 0; i < n; ++i) {
                std::int8_t x = static_cast<std::int8_t>(r.readByte());
                if (delta && i >= std::uint64_t(componentCount))
                    x = static_cast<std::int8_t>(static_cast<std::uint8_t>(x) +
                                                 static_cast<std::uint8_t>(v[i - std::uint64_t(componentCount)]));
                v[i] = x;
            }
            va->set(0, vertexCount, std::span<const std::int8_t>(v));
        } else {
            std::vector<std::int16_t> v(n);
            for (std::uint64_t i = 0; i < n; ++i) {
                std::int16_t x = r.readInt16();
                if (delta && i >= std::uint64_t(componentCount))
                    x = static_cast<std::int16_t>(static_cast<std::uint16_t>(x) +
                                                  static_cast<std::uint16_t>(v[i - std::uint64_t(componentCount)]));
                v[i] = x;
            }
            va->set(0, vertexCount, std::span<const std::int16_t>(v));
        }
        return va;
    }

    Ref<Object3D> vertexBuffer(ByteReader& r) {
        const Object3DBlock b = readObject3D(r);
        const std::uint32_t defaultColor = r.readColorRGBA();
        Ref<VertexArray> positions = ref<VertexArray>(r, "positions", "VertexArray");
        const auto positionBias = r.readVector3D();
        const float positionScale = r.readFloat32();
        Ref<VertexArray> normals = ref<VertexArray>(r, "normals", "VertexArray");
        Ref<VertexArray> colors = ref<VertexArray>(r, "colors", "VertexArray");
        const std::uint32_t n = r.readCount(20, "texture coordinate arrays");
        struct TexCoords {
            Ref<VertexArray> array;
            std::array<float, 3> bias;
            float scale;
        };
        std::vector<TexCoords> tex;
        tex.reserve(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            TexCoords t;
            t.array = ref<VertexArray>(r, "texCoords", "VertexArray");
            t.bias = r.readVector3D();
            t.scale = r.readFloat32();
            tex.push_back(std::move(t));
        }
        Ref<VertexBuffer> vb = make<VertexBuffer>();
        apply(*vb, b);
        vb->setDefaultColor(static_cast<int>(defaultColor));
        // Null arrays are not set (a new VertexBuffer has none), so a null
        // texture coordinate slot past the unit count is not an error.
        if (positions) vb->setPositions(positions.get(), positionScale, positionBias);
        if (normals) vb->setNormals(normals.get());
        if (colors) vb->setColors(colors.get());
        for (std::uint32_t i = 0; i < n; ++i)
            if (tex[i].array) vb->setTexCoords(static_cast<int>(i), tex[i].array.get(), tex[i].scale, tex[i].bias);
        return vb;
    }

    Ref<Object3D> world(ByteReader& r) {
        const GroupBlock b = readGroup(r);
        Ref<Camera> cam = ref<Camera>(r, "activeCamera", "Camera");
        Ref<Background> bg = ref<Background>(r, "background", "Background");
        Ref<World> w = make<World>();
        apply(*w, b);
        if (cam) w->setActiveCamera(cam.get());
        w->setBackground(bg.get());
        return w;
    }

    Ref<Object3D> externalReference(ByteReader& r) {
        const std::string uri = r.readString();
        r.expectEnd("External Reference data");
        return resolve_(uri, r);  // null: skipped (lenient, missing file)
    }
};

}  // namespace

DecodedObjects decodeObjects(const M3GFile& file, LoadLog& log, const ExternalResolver& resolveExternal) {
    return Decoder(file, log, resolveExternal).run();
}

}  // namespace m3g::detail
