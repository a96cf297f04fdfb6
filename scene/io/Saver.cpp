// The .m3g writer of the JSR-184 1.1 file format: object ordering (file format
// §8), per-class serialisation (section "Per-Class Data") and the section
// layer (sections "File Structure" and "Header Object").
#include <m3g/Saver.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <unordered_map>

#include <zlib.h>

#include <m3g/AnimationController.h>
#include <m3g/AnimationTrack.h>
#include <m3g/Appearance.h>
#include <m3g/Background.h>
#include <m3g/Camera.h>
#include <m3g/CompositingMode.h>
#include <m3g/Fog.h>
#include <m3g/Group.h>
#include <m3g/Image2D.h>
#include <m3g/KeyframeSequence.h>
#include <m3g/Light.h>
#include <m3g/Limits.h>
#include <m3g/Material.h>
#include <m3g/MorphingMesh.h>
#include <m3g/PolygonMode.h>
#include <m3g/SkinnedMesh.h>
#include <m3g/Sprite3D.h>
#include <m3g/Texture2D.h>
#include <m3g/TriangleStripArray.h>
#include <m3g/VertexArray.h>
#include <m3g/VertexBuffer.h>
#include <m3g/World.h>

#include "ByteReader.h"
#include "ByteWriter.h"
#include "Check.h"
#include "M3GSections.h"
#include "PropertyUtil.h"

namespace m3g {
namespace {

using detail::ByteWriter;
using detail::str;

constexpr std::uint32_t kFirstObjectIndex = 2;  // 0 = null, 1 = the header


std::uint32_t checkedSize(std::size_t n, const char* what) {
    if (n > std::numeric_limits<std::uint32_t>::max())
        throw IOException(str("Saver: ", what, " of ", n, " bytes exceeds the 4 GiB the format can describe"));
    return static_cast<std::uint32_t>(n);
}

/// Serialises one object's data (the bytes after ObjectType and Length).
/// In the dependency pass (`deps` set) every ObjectIndex is recorded in
/// `deps` and written as 0; otherwise it is looked up in `index`.
class ObjectSerializer {
public:
    std::unordered_map<const Object3D*, std::uint32_t> index;
    std::vector<const Object3D*>* deps = nullptr;
    ByteWriter w;

    /// Writes `o`'s data into `w` and returns its ObjectType.
    std::uint8_t write(const Object3D& o);

private:
    void ref(const Object3D* o);
    void f32(float v, const char* what) { w.writeFloat32(v, what); }

    void object3D(const Object3D& o);
    void transformable(const Transformable& o);
    void node(const Node& o);
    void group(const Group& o);
    void mesh(const Mesh& o);

    void animationController(const AnimationController& o);
    void animationTrack(const AnimationTrack& o);
    void appearance(const Appearance& o);
    void background(const Background& o);
    void camera(const Camera& o);
    void compositingMode(const CompositingMode& o);
    void fog(const Fog& o);
    void polygonMode(const PolygonMode& o);
    void image2D(const Image2D& o);
    void triangleStripArray(const TriangleStripArray& o);
    void light(const Light& o);
    void material(const Material& o);
    void morphingMesh(const MorphingMesh& o);
    void skinnedMesh(const SkinnedMesh& o);
    void texture2D(const Texture2D& o);
    void sprite3D(const Sprite3D& o);
    void keyframeSequence(const KeyframeSequence& o);
    void vertexArray(const VertexArray& o);
    void vertexBuffer(const VertexBuffer& o);
    void world(const World& o);
};

void ObjectSerializer::ref(const Object3D* o) {
    if (deps) {
        if (o) deps->push_back(o);
        w.writeObjectIndex(0);
        return;
    }
    if (!o) {
        w.writeObjectIndex(0);
        return;
    }
    auto it = index.find(o);
    if (it == index.end())
        throw IOException(str("Saver: internal error: a ", o->getClassName(), " is referenced before it is written"));
    w.writeObjectIndex(it->second);
}

std::uint8_t ObjectSerializer::write(const Object3D& o) {
    using namespace detail;
    // Most derived classes first.
    if (auto* p = dynamic_cast<const World*>(&o)) return world(*p), kTypeWorld;
    if (auto* p = dynamic_cast<const Group*>(&o)) return group(*p), kTypeGroup;
    if (auto* p = dynamic_cast<const SkinnedMesh*>(&o)) return skinnedMesh(*p), kTypeSkinnedMesh;
    if (auto* p = dynamic_cast<const MorphingMesh*>(&o)) return morphingMesh(*p), kTypeMorphingMesh;
    if (auto* p = dynamic_cast<const Mesh*>(&o)) return mesh(*p), kTypeMesh;
    if (auto* p = dynamic_cast<const Camera*>(&o)) return camera(*p), kTypeCamera;
    if (auto* p = dynamic_cast<const Light*>(&o)) return light(*p), kTypeLight;
    if (auto* p = dynamic_cast<const Sprite3D*>(&o)) return sprite3D(*p), kTypeSprite3D;
    if (auto* p = dynamic_cast<const Texture2D*>(&o)) return texture2D(*p), kTypeTexture2D;
    if (auto* p = dynamic_cast<const AnimationController*>(&o)) return animationController(*p), kTypeAnimationController;
    if (auto* p = dynamic_cast<const AnimationTrack*>(&o)) return animationTrack(*p), kTypeAnimationTrack;
    if (auto* p = dynamic_cast<const Appearance*>(&o)) return appearance(*p), kTypeAppearance;
    if (auto* p = dynamic_cast<const Background*>(&o)) return background(*p), kTypeBackground;
    if (auto* p = dynamic_cast<const CompositingMode*>(&o)) return compositingMode(*p), kTypeCompositingMode;
    if (auto* p = dynamic_cast<const Fog*>(&o)) return fog(*p), kTypeFog;
    if (auto* p = dynamic_cast<const PolygonMode*>(&o)) return polygonMode(*p), kTypePolygonMode;
    if (auto* p = dynamic_cast<const Image2D*>(&o)) return image2D(*p), kTypeImage2D;
    if (auto* p = dynamic_cast<const TriangleStripArray*>(&o)) return triangleStripArray(*p), kTypeTriangleStripArray;
    if (auto* p = dynamic_cast<const Material*>(&o)) return material(*p), kTypeMaterial;
    if (auto* p = dynamic_cast<const KeyframeSequence*>(&o)) return keyframeSequence(*p), kTypeKeyframeSequence;
    if (auto* p = dynamic_cast<const VertexArray*>(&o)) return vertexArray(*p), kTypeVertexArray;
    if (auto* p = dynamic_cast<const VertexBuffer*>(&o)) return vertexBuffer(*p), kTypeVertexBuffer;
    throw IOException(str("Saver: a ", o.getClassName(), " has no M3G file representation"));
}

// ---- inherited blocks (JSR-184 1.1 file format, section "Per-Class Data") ----

void ObjectSerializer::object3D(const Object3D& o) {
    w.writeUInt32(static_cast<std::uint32_t>(o.getUserID()));
    const int tracks = o.getAnimationTrackCount();
    w.writeUInt32(static_cast<std::uint32_t>(tracks));
    for (int i = 0; i < tracks; ++i) ref(o.getAnimationTrack(i).get());
    const UserParameters* params = o.getUserParameters();
    if (!params) {
        w.writeUInt32(0);
        return;
    }
    w.writeUInt32(checkedSize(params->size(), "user parameter count"));
    for (const auto& [id, value] : *params) {
        w.writeUInt32(static_cast<std::uint32_t>(id));
        checkedSize(value.size(), "user parameter");
        w.writeByteArray(value);
    }
}

void ObjectSerializer::transformable(const Transformable& o) {
    object3D(o);
    float t[3], s[3], aa[4];
    o.getTranslation(t);
    o.getScale(s);
    o.getOrientation(aa);
    const auto& q = o.orientationQuat();
    const bool identityRotation = q[0] == 0.0f && q[1] == 0.0f && q[2] == 0.0f;
    const bool hasComponent = t[0] != 0.0f || t[1] != 0.0f || t[2] != 0.0f || s[0] != 1.0f || s[1] != 1.0f ||
                              s[2] != 1.0f || !identityRotation;
    w.writeBoolean(hasComponent);
    if (hasComponent) {
        w.writeVector3D(t, "translation");
        w.writeVector3D(s, "scale");
        if (identityRotation) {
            f32(0.0f, "orientation angle");
            const float axis[3] = {0.0f, 0.0f, 0.0f};
            w.writeVector3D(axis, "orientation axis");
        } else {
            f32(aa[0], "orientation angle");
            w.writeVector3D(aa + 1, "orientation axis");
        }
    }
    Transform m;
    o.getTransform(&m);
    const bool hasGeneral = !(m == Transform());
    w.writeBoolean(hasGeneral);
    if (hasGeneral) w.writeMatrix(m.rows(), "transform matrix");
}

void ObjectSerializer::node(const Node& o) {
    transformable(o);
    w.writeBoolean(o.isRenderingEnabled());
    w.writeBoolean(o.isPickingEnabled());
    w.writeByte(static_cast<std::uint8_t>(detail::channelToByte(o.getAlphaFactor())));
    w.writeUInt32(static_cast<std::uint32_t>(o.getScope()));
    const int zTarget = o.getAlignmentTarget(Node::Z_AXIS);
    const int yTarget = o.getAlignmentTarget(Node::Y_AXIS);
    const bool hasAlignment = zTarget != Node::NONE || yTarget != Node::NONE;
    w.writeBoolean(hasAlignment);
    if (hasAlignment) {
        w.writeByte(static_cast<std::uint8_t>(zTarget));
        w.writeByte(static_cast<std::uint8_t>(yTarget));
        ref(o.getAlignmentReference(Node::Z_AXIS).get());
        ref(o.getAlignmentReference(Node::Y_AXIS).get());
    }
}

void ObjectSerializer::group(const Group& o) {
    node(o);
    const int n = o.getChildCount();
    w.writeUInt32(static_cast<std::uint32_t>(n));
    for (int i = 0; i < n; ++i) ref(o.getChild(i).get());
}

void ObjectSerializer::world(const World& o) {
    group(o);
    ref(o.getActiveCamera().get());
    ref(o.getBackground().get());
}

void ObjectSerializer::mesh(const Mesh& o) {
    node(o);
    ref(o.vertexBuffer());
    const int n = o.getSubmeshCount();
    w.writeUInt32(static_cast<std::uint32_t>(n));
    for (int i = 0; i < n; ++i) {
        ref(o.indexBuffer(i));
        ref(o.appearance(i));
    }
}

// ---- per-class data (JSR-184 1.1 file format, section "Per-Class Data") ----

void ObjectSerializer::animationController(const AnimationController& o) {
    object3D(o);
    f32(o.getSpeed(), "AnimationController speed");
    f32(o.getWeight(), "AnimationController weight");
    w.writeInt32(o.getActiveIntervalStart());
    w.writeInt32(o.getActiveIntervalEnd());
    f32(o.getPosition(o.getRefWorldTime()), "AnimationController reference sequence time");
    w.writeInt32(o.getRefWorldTime());
}

void ObjectSerializer::animationTrack(const AnimationTrack& o) {
    object3D(o);
    ref(o.getKeyframeSequence().get());
    ref(o.getController().get());
    w.writeUInt32(static_cast<std::uint32_t>(o.getTargetProperty()));
}

void ObjectSerializer::appearance(const Appearance& o) {
    object3D(o);
    w.writeByte(static_cast<std::uint8_t>(static_cast<std::int8_t>(o.getLayer())));
    ref(o.getCompositingMode().get());
    ref(o.getFog().get());
    ref(o.getPolygonMode().get());
    ref(o.getMaterial().get());
    const int units = getLimits().numTextureUnits;
    int count = 0;
    for (int i = 0; i < units; ++i)
        if (o.getTexture(i)) count = i + 1;
    w.writeUInt32(static_cast<std::uint32_t>(count));
    for (int i = 0; i < count; ++i) ref(o.getTexture(i).get());
}

void ObjectSerializer::background(const Background& o) {
    object3D(o);
    w.writeColorRGBA(static_cast<std::uint32_t>(o.getColor()));
    ref(o.getImage().get());
    w.writeByte(static_cast<std::uint8_t>(o.getImageModeX()));
    w.writeByte(static_cast<std::uint8_t>(o.getImageModeY()));
    w.writeInt32(o.getCropX());
    w.writeInt32(o.getCropY());
    w.writeInt32(o.getCropWidth());
    w.writeInt32(o.getCropHeight());
    // File-format order (JSR-184 1.1 file format, section "Per-Class Data",
    // Background): depth clear first, then color clear. Nokia's M3G
    // implementation (reference) reads them the other way round.
    w.writeBoolean(o.isDepthClearEnabled());
    w.writeBoolean(o.isColorClearEnabled());
}

void ObjectSerializer::camera(const Camera& o) {
    node(o);
    float params[4] = {0, 0, 0, 0};
    const int type = o.getProjection(std::span<float>(params));
    w.writeByte(static_cast<std::uint8_t>(type));
    if (type == Camera::GENERIC) {
        Transform m;
        o.getProjection(&m);
        w.writeMatrix(m.rows(), "Camera projection matrix");
    } else {
        f32(params[0], type == Camera::PERSPECTIVE ? "Camera fovy" : "Camera height");
        f32(params[1], "Camera aspect ratio");
        f32(params[2], "Camera near");
        f32(params[3], "Camera far");
    }
}

void ObjectSerializer::compositingMode(const CompositingMode& o) {
    object3D(o);
    w.writeBoolean(o.isDepthTestEnabled());
    w.writeBoolean(o.isDepthWriteEnabled());
    w.writeBoolean(o.isColorWriteEnabled());
    w.writeBoolean(o.isAlphaWriteEnabled());
    w.writeByte(static_cast<std::uint8_t>(o.getBlending()));
    w.writeByte(static_cast<std::uint8_t>(detail::channelToByte(o.getAlphaThreshold())));
    f32(o.getDepthOffsetFactor(), "CompositingMode depth offset factor");
    f32(o.getDepthOffsetUnits(), "CompositingMode depth offset units");
}

void ObjectSerializer::fog(const Fog& o) {
    object3D(o);
    w.writeColorRGB(static_cast<std::uint32_t>(o.getColor()));
    w.writeByte(static_cast<std::uint8_t>(o.getMode()));
    if (o.getMode() == Fog::EXPONENTIAL) {
        f32(o.getDensity(), "Fog density");
    } else {
        f32(o.getNearDistance(), "Fog near");
        f32(o.getFarDistance(), "Fog far");
    }
}

void ObjectSerializer::polygonMode(const PolygonMode& o) {
    object3D(o);
    w.writeByte(static_cast<std::uint8_t>(o.getCulling()));
    w.writeByte(static_cast<std::uint8_t>(o.getShading()));
    w.writeByte(static_cast<std::uint8_t>(o.getWinding()));
    w.writeBoolean(o.isTwoSidedLightingEnabled());
    w.writeBoolean(o.isLocalCameraLightingEnabled());
    w.writeBoolean(o.isPerspectiveCorrectionEnabled());
}

void ObjectSerializer::image2D(const Image2D& o) {
    object3D(o);
    w.writeByte(static_cast<std::uint8_t>(o.getFormat()));
    w.writeBoolean(o.isMutable());
    w.writeUInt32(static_cast<std::uint32_t>(o.getWidth()));
    w.writeUInt32(static_cast<std::uint32_t>(o.getHeight()));
    // A render target: no pixel data (JSR-184 1.1 file format, section
    // "Per-Class Data", Image2D).
    if (o.isMutable()) return;
    const std::size_t count = static_cast<std::size_t>(o.getWidth()) * static_cast<std::size_t>(o.getHeight());
    if (o.isPalettized()) {
        // At most 256 entries; the constructor ignores the rest anyway.
        const std::size_t maxPalette = 256u * static_cast<std::size_t>(o.bytesPerPixel());
        auto palette = o.palette();
        w.writeByteArray(palette.first(std::min(palette.size(), maxPalette)));
        auto indices = o.paletteIndices();
        w.writeByteArray(indices.first(std::min(indices.size(), count)));
    } else {
        w.writeUInt32(0);  // empty palette: direct pixels
        auto pixels = o.pixels();
        const std::size_t n = count * static_cast<std::size_t>(o.bytesPerPixel());
        checkedSize(n, "Image2D pixel data");
        w.writeByteArray(pixels.first(std::min(pixels.size(), n)));
    }
}

void ObjectSerializer::triangleStripArray(const TriangleStripArray& o) {
    object3D(o);
    const auto indices = o.stripIndices();
    bool implicit = !indices.empty();
    int maxIndex = 0;
    for (std::size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] != indices[0] + static_cast<int>(i)) implicit = false;
        maxIndex = std::max(maxIndex, indices[i]);
    }
    if (implicit) {
        const int start = indices[0];
        if (start <= 0xFF) {
            w.writeByte(1);
            w.writeByte(static_cast<std::uint8_t>(start));
        } else if (start <= 0xFFFF) {
            w.writeByte(2);
            w.writeUInt16(static_cast<std::uint16_t>(start));
        } else {
            w.writeByte(0);
            w.writeUInt32(static_cast<std::uint32_t>(start));
        }
    } else {
        const auto n = static_cast<std::uint32_t>(indices.size());
        if (maxIndex <= 0xFF) {
            w.writeByte(129);
            w.writeUInt32(n);
            for (int i : indices) w.writeByte(static_cast<std::uint8_t>(i));
        } else if (maxIndex <= 0xFFFF) {
            w.writeByte(130);
            w.writeUInt32(n);
            for (int i : indices) w.writeUInt16(static_cast<std::uint16_t>(i));
        } else {
            w.writeByte(128);
            w.writeUInt32(n);
            for (int i : indices) w.writeUInt32(static_cast<std::uint32_t>(i));
        }
    }
    const auto lengths = o.stripLengths();
    w.writeUInt32(static_cast<std::uint32_t>(lengths.size()));
    for (int len : lengths) w.writeUInt32(static_cast<std::uint32_t>(len));
}

void ObjectSerializer::light(const Light& o) {
    node(o);
    f32(o.getConstantAttenuation(), "Light constant attenuation");
    f32(o.getLinearAttenuation(), "Light linear attenuation");
    f32(o.getQuadraticAttenuation(), "Light quadratic attenuation");
    w.writeColorRGB(static_cast<std::uint32_t>(o.getColor()));
    w.writeByte(static_cast<std::uint8_t>(o.getMode()));
    f32(o.getIntensity(), "Light intensity");
    f32(o.getSpotAngle(), "Light spot angle");
    f32(o.getSpotExponent(), "Light spot exponent");
}

void ObjectSerializer::material(const Material& o) {
    object3D(o);
    w.writeColorRGB(static_cast<std::uint32_t>(o.getColor(Material::AMBIENT)));
    w.writeColorRGBA(static_cast<std::uint32_t>(o.getColor(Material::DIFFUSE)));
    w.writeColorRGB(static_cast<std::uint32_t>(o.getColor(Material::EMISSIVE)));
    w.writeColorRGB(static_cast<std::uint32_t>(o.getColor(Material::SPECULAR)));
    f32(o.getShininess(), "Material shininess");
    w.writeBoolean(o.isVertexColorTrackingEnabled());
}

void ObjectSerializer::morphingMesh(const MorphingMesh& o) {
    mesh(o);
    const int n = o.getMorphTargetCount();
    const auto weights = o.weights();
    w.writeUInt32(static_cast<std::uint32_t>(n));
    for (int i = 0; i < n; ++i) {
        ref(o.morphTarget(i));
        f32(weights[static_cast<std::size_t>(i)], "MorphingMesh weight");
    }
}

void ObjectSerializer::skinnedMesh(const SkinnedMesh& o) {
    mesh(o);
    ref(o.getSkeleton().get());
    const auto added = o.addedTransforms();
    w.writeUInt32(static_cast<std::uint32_t>(added.size()));
    for (const auto& t : added) {
        ref(o.bone(t.bone));
        w.writeUInt32(static_cast<std::uint32_t>(t.firstVertex));
        w.writeUInt32(static_cast<std::uint32_t>(t.vertexCount));
        w.writeInt32(t.weight);
    }
}

void ObjectSerializer::texture2D(const Texture2D& o) {
    transformable(o);
    ref(o.getImage().get());
    w.writeColorRGB(static_cast<std::uint32_t>(o.getBlendColor()));
    w.writeByte(static_cast<std::uint8_t>(o.getBlending()));
    w.writeByte(static_cast<std::uint8_t>(o.getWrappingS()));
    w.writeByte(static_cast<std::uint8_t>(o.getWrappingT()));
    w.writeByte(static_cast<std::uint8_t>(o.getLevelFilter()));
    w.writeByte(static_cast<std::uint8_t>(o.getImageFilter()));
}

void ObjectSerializer::sprite3D(const Sprite3D& o) {
    node(o);
    ref(o.getImage().get());
    ref(o.getAppearance().get());
    w.writeBoolean(o.isScaled());
    w.writeInt32(o.getCropX());
    w.writeInt32(o.getCropY());
    w.writeInt32(o.getCropWidth());
    w.writeInt32(o.getCropHeight());
}

void ObjectSerializer::keyframeSequence(const KeyframeSequence& o) {
    object3D(o);
    w.writeByte(static_cast<std::uint8_t>(o.getInterpolationType()));
    w.writeByte(static_cast<std::uint8_t>(o.getRepeatMode()));
    w.writeByte(0);  // encoding 0: Float32 values
    w.writeUInt32(static_cast<std::uint32_t>(o.getDuration()));
    w.writeUInt32(static_cast<std::uint32_t>(o.getValidRangeFirst()));
    w.writeUInt32(static_cast<std::uint32_t>(o.getValidRangeLast()));
    const int components = o.getComponentCount();
    const int keys = o.getKeyframeCount();
    w.writeUInt32(static_cast<std::uint32_t>(components));
    w.writeUInt32(static_cast<std::uint32_t>(keys));
    const auto times = o.keyTimes();
    const auto values = o.keyValues();
    for (int k = 0; k < keys; ++k) {
        w.writeInt32(times[static_cast<std::size_t>(k)]);
        for (int c = 0; c < components; ++c)
            f32(values[static_cast<std::size_t>(k) * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)],
                "KeyframeSequence value");
    }
}

void ObjectSerializer::vertexArray(const VertexArray& o) {
    object3D(o);
    const int size = o.getComponentType();
    const int components = o.getComponentCount();
    const int vertices = o.getVertexCount();
    w.writeByte(static_cast<std::uint8_t>(size));
    w.writeByte(static_cast<std::uint8_t>(components));
    w.writeByte(0);  // encoding 0: plain values
    w.writeUInt16(static_cast<std::uint16_t>(vertices));
    for (int v = 0; v < vertices; ++v)
        for (int c = 0; c < components; ++c) {
            if (size == 1)
                w.writeByte(static_cast<std::uint8_t>(static_cast<std::int8_t>(o.value(v, c))));
            else
                w.writeInt16(static_cast<std::int16_t>(o.value(v, c)));
        }
}

void ObjectSerializer::vertexBuffer(const VertexBuffer& o) {
    object3D(o);
    w.writeColorRGBA(static_cast<std::uint32_t>(o.getDefaultColor()));
    ref(o.positions());
    w.writeVector3D(o.positionBias().data(), "VertexBuffer position bias");
    f32(o.positionScale(), "VertexBuffer position scale");
    ref(o.normals());
    ref(o.colors());
    const int units = getLimits().numTextureUnits;
    int count = 0;
    for (int i = 0; i < units; ++i)
        if (o.texCoords(i)) count = i + 1;
    w.writeUInt32(static_cast<std::uint32_t>(count));
    for (int i = 0; i < count; ++i) {
        ref(o.texCoords(i));
        if (o.texCoords(i)) {
            w.writeVector3D(o.texCoordBias(i).data(), "VertexBuffer texture coordinate bias");
            f32(o.texCoordScale(i), "VertexBuffer texture coordinate scale");
        } else {  // an empty unit below a used one: neutral values
            const float zero[3] = {0.0f, 0.0f, 0.0f};
            w.writeVector3D(zero);
            f32(1.0f, "VertexBuffer texture coordinate scale");
        }
    }
}

// ---- ordering ------------------------------------------------------------

/// Every object reachable from `roots`, each after everything it references
/// (post-order of an iterative depth-first walk, roots in order). The
/// dependencies of an object are exactly the ObjectIndex fields its
/// serialisation writes (so alignment references and SkinnedMesh bones are
/// included although getReferences does not list them).
std::vector<const Object3D*> orderObjects(std::span<Object3D* const> roots, ObjectSerializer& ser) {
    enum class State : std::uint8_t { Visiting, Done };
    std::unordered_map<const Object3D*, State> state;
    std::vector<const Object3D*> order;

    struct Frame {
        const Object3D* object;
        std::vector<const Object3D*> deps;
        std::size_t next = 0;
    };
    std::vector<Frame> stack;
    auto push = [&](const Object3D* o) {
        Frame f{o, {}, 0};
        ser.deps = &f.deps;
        ser.w.clear();
        try {
            ser.write(*o);
        } catch (...) {
            ser.deps = nullptr;
            throw;
        }
        ser.deps = nullptr;
        state[o] = State::Visiting;
        stack.push_back(std::move(f));
    };

    for (const Object3D* root : roots) {
        if (state.contains(root)) continue;
        push(root);
        while (!stack.empty()) {
            Frame& top = stack.back();
            if (top.next < top.deps.size()) {
                const Object3D* d = top.deps[top.next++];
                auto it = state.find(d);
                if (it == state.end()) {
                    push(d);
                } else if (it->second == State::Visiting) {
                    throw IOException(str("Saver: reference cycle: a ", top.object->getClassName(),
                                          " references a ", d->getClassName(),
                                          " that (indirectly) references it; the M3G format allows only "
                                          "backward references (an alignment reference to an ancestor cannot "
                                          "be stored)"));
                }
            } else {
                state[top.object] = State::Done;
                order.push_back(top.object);
                stack.pop_back();
            }
        }
    }
    ser.w.clear();
    return order;
}

// ---- sections (JSR-184 1.1 file format, section "File Structure") ---------

void appendSection(std::vector<std::uint8_t>& file, std::span<const std::uint8_t> objects, bool compress) {
    const std::uint32_t uncompressed = checkedSize(objects.size(), "objects section");
    std::vector<std::uint8_t> packed;
    std::span<const std::uint8_t> stored = objects;
    if (compress) {
        uLongf packedSize = compressBound(static_cast<uLong>(objects.size()));
        packed.resize(packedSize);
        const int rc = compress2(packed.data(), &packedSize, objects.data(), static_cast<uLong>(objects.size()),
                                 Z_BEST_COMPRESSION);
        if (rc != Z_OK) throw IOException(str("Saver: zlib compress2 failed (", rc, ")"));
        packed.resize(packedSize);
        stored = packed;
    }
    ByteWriter s;
    s.writeByte(compress ? 1 : 0);
    s.writeUInt32(checkedSize(stored.size() + 13, "section"));
    s.writeUInt32(uncompressed);
    s.writeBytes(stored);
    const auto& b = s.bytes();
    const uLong adler = adler32(adler32(0L, Z_NULL, 0), b.data(), static_cast<uInt>(b.size()));
    s.writeUInt32(static_cast<std::uint32_t>(adler));
    file.insert(file.end(), s.bytes().begin(), s.bytes().end());
}

}  // namespace

std::vector<std::uint8_t> Saver::save(std::span<Object3D* const> roots, const SaverOptions& options) {
    const char* where = "Saver::save";
    if (roots.data() == nullptr) detail::throwNull(where, "roots");
    for (std::size_t i = 0; i < roots.size(); ++i)
        if (!roots[i]) throw NullPointerException(str(where, ": roots[", i, "] is null"));
    const std::string& authoring = options.authoringField;
    if (authoring.find('\0') != std::string::npos)
        detail::throwIAE(str(where, ": the authoring field contains a NUL character"));
    if (!detail::isValidUtf8(std::span(reinterpret_cast<const std::uint8_t*>(authoring.data()), authoring.size())))
        detail::throwIAE(str(where, ": the authoring field is not valid UTF-8"));

    ObjectSerializer ser;
    const std::vector<const Object3D*> order = orderObjects(roots, ser);

    // The objects area: ObjectType, Length, Data per object.
    ByteWriter objects;
    for (std::size_t i = 0; i < order.size(); ++i) {
        const Object3D* o = order[i];
        ser.w.clear();
        const std::uint8_t type = ser.write(*o);
        objects.writeByte(type);
        objects.writeUInt32(checkedSize(ser.w.size(), "object"));
        objects.writeBytes(ser.w.bytes());
        // Indices are assigned once written, so every reference points back.
        ser.index[o] = kFirstObjectIndex + static_cast<std::uint32_t>(i);
    }

    std::vector<std::uint8_t> objectSection;
    appendSection(objectSection, objects.bytes(), options.compress);

    // Section 0: the header object, uncompressed (JSR-184 1.1 file format,
    // sections "File Structure" and "Header Object").
    const std::size_t headerData = 2 + 1 + 4 + 4 + authoring.size() + 1;
    const std::size_t headerSection = 13 + 5 + headerData;
    const std::uint32_t fileSize = checkedSize(
        detail::kM3GFileIdentifier.size() + headerSection + objectSection.size(), "file");

    ByteWriter header;
    header.writeByte(detail::kTypeHeader);
    header.writeUInt32(static_cast<std::uint32_t>(headerData));
    header.writeByte(1);  // version 1.0
    header.writeByte(0);
    header.writeBoolean(false);  // no external references
    header.writeUInt32(fileSize);
    header.writeUInt32(fileSize);  // approximate content size: this file only
    header.writeString(authoring);

    std::vector<std::uint8_t> file(detail::kM3GFileIdentifier.begin(), detail::kM3GFileIdentifier.end());
    file.reserve(fileSize);
    appendSection(file, header.bytes(), false);
    file.insert(file.end(), objectSection.begin(), objectSection.end());
    if (file.size() != fileSize) throw IOException("Saver: internal error: file size mismatch");
    return file;
}

void Saver::save(const std::string& path, std::span<Object3D* const> roots, const SaverOptions& options) {
    const std::vector<std::uint8_t> bytes = save(roots, options);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw IOException(str("Saver::save: cannot open \"", path, "\" for writing"));
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw IOException(str("Saver::save: writing \"", path, "\" failed"));
}

}  // namespace m3g
