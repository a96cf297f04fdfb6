// Saver: the .m3g writer (JSR-184 1.1 file format). Files are read back with the
// loader's byte layer (parseM3GFile, ByteReader) and a test-side walker that
// decodes every field of every object type (JSR-184 1.1 file format, section
// "Per-Class Data") and collects the
// ObjectIndex values. Also tests the graph comparer of RoundTrip.h.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <set>
#include <unordered_set>

#include <m3g/m3g.h>

#include "ByteReader.h"
#include "ByteWriter.h"
#include "M3GSections.h"
#include "RoundTrip.h"

using namespace m3g;
using m3g::detail::ByteReader;
using m3g::detail::LoadLog;
using m3g::detail::M3GFile;
using m3g::detail::M3GObject;
using m3g::detail::parseM3GFile;
using m3gtest::compareGraphs;
using m3gtest::GraphCompareOptions;

namespace {

using Bytes = std::vector<std::uint8_t>;

// ---- a test-side decoder of the object data -------------------------------

struct Decoded {
    std::vector<std::uint32_t> refs;  // every ObjectIndex, in field order
};

void readObject3D(ByteReader& r, Decoded& d) {
    r.readUInt32();  // userID
    for (auto i : r.readObjectIndexArray("animation tracks")) d.refs.push_back(i);
    const std::uint32_t params = r.readUInt32();
    for (std::uint32_t i = 0; i < params; ++i) {
        r.readUInt32();
        r.readByteArray("parameter value");
    }
}

void readTransformable(ByteReader& r, Decoded& d) {
    readObject3D(r, d);
    if (r.readBoolean()) r.readFloat32s(10, "component transform");
    if (r.readBoolean()) r.readMatrix();
}

void readNode(ByteReader& r, Decoded& d) {
    readTransformable(r, d);
    r.readBoolean();
    r.readBoolean();
    r.readByte();
    r.readUInt32();
    if (r.readBoolean()) {
        r.readByte();
        r.readByte();
        d.refs.push_back(r.readObjectIndex());
        d.refs.push_back(r.readObjectIndex());
    }
}

void readGroup(ByteReader& r, Decoded& d) {
    readNode(r, d);
    for (auto i : r.readObjectIndexArray("children")) d.refs.push_back(i);
}

void readMesh(ByteReader& r, Decoded& d) {
    readNode(r, d);
    d.refs.push_back(r.readObjectIndex());
    const std::uint32_t n = r.readUInt32();
    for (std::uint32_t i = 0; i < n; ++i) {
        d.refs.push_back(r.readObjectIndex());
        d.refs.push_back(r.readObjectIndex());
    }
}

/// Decodes the whole object (every field, all lengths consumed exactly).
Decoded decode(const M3GObject& o) {
    LoadLog log;
    ByteReader r = m3g::detail::objectReader(o, &log);
    Decoded d;
    auto ref = [&] { d.refs.push_back(r.readObjectIndex()); };
    switch (o.type) {
    case 1:
        readObject3D(r, d);
        r.readFloat32(), r.readFloat32(), r.readInt32(), r.readInt32(), r.readFloat32(), r.readInt32();
        break;
    case 2:
        readObject3D(r, d);
        ref(), ref();
        r.readUInt32();
        break;
    case 3:
        readObject3D(r, d);
        r.readByte();
        ref(), ref(), ref(), ref();
        for (auto i : r.readObjectIndexArray("textures")) d.refs.push_back(i);
        break;
    case 4:
        readObject3D(r, d);
        r.readColorRGBA();
        ref();
        r.readByte(), r.readByte();
        r.readInt32(), r.readInt32(), r.readInt32(), r.readInt32();
        r.readBoolean(), r.readBoolean();
        break;
    case 5:
        readNode(r, d);
        if (r.readByte() == Camera::GENERIC)
            r.readMatrix();
        else
            r.readFloat32s(4, "projection");
        break;
    case 6:
        readObject3D(r, d);
        for (int i = 0; i < 4; ++i) r.readBoolean();
        r.readByte(), r.readByte();
        r.readFloat32(), r.readFloat32();
        break;
    case 7:
        readObject3D(r, d);
        r.readColorRGB();
        if (r.readByte() == Fog::EXPONENTIAL)
            r.readFloat32();
        else
            r.readFloat32(), r.readFloat32();
        break;
    case 8:
        readObject3D(r, d);
        r.readByte(), r.readByte(), r.readByte();
        r.readBoolean(), r.readBoolean(), r.readBoolean();
        break;
    case 9: readGroup(r, d); break;
    case 10:
        readObject3D(r, d);
        r.readByte();
        if (!r.readBoolean()) {
            r.readUInt32(), r.readUInt32();
            r.readByteArray("palette");
            r.readByteArray("pixels");
        } else {
            r.readUInt32(), r.readUInt32();
        }
        break;
    case 11: {
        readObject3D(r, d);
        switch (r.readByte()) {
        case 0: r.readUInt32(); break;
        case 1: r.readByte(); break;
        case 2: r.readUInt16(); break;
        case 128: r.readUInt32Array("indices"); break;
        case 129: r.readByteArray("indices"); break;
        case 130: r.readUInt16Array("indices"); break;
        default: r.fail("bad strip encoding");
        }
        r.readUInt32Array("strip lengths");
        break;
    }
    case 12:
        readNode(r, d);
        r.readFloat32s(3, "attenuation");
        r.readColorRGB();
        r.readByte();
        r.readFloat32s(3, "intensity, spot");
        break;
    case 13:
        readObject3D(r, d);
        r.readColorRGB(), r.readColorRGBA(), r.readColorRGB(), r.readColorRGB();
        r.readFloat32();
        r.readBoolean();
        break;
    case 14: readMesh(r, d); break;
    case 15: {
        readMesh(r, d);
        const std::uint32_t n = r.readUInt32();
        for (std::uint32_t i = 0; i < n; ++i) ref(), r.readFloat32();
        break;
    }
    case 16: {
        readMesh(r, d);
        ref();
        const std::uint32_t n = r.readUInt32();
        for (std::uint32_t i = 0; i < n; ++i) ref(), r.readUInt32(), r.readUInt32(), r.readInt32();
        break;
    }
    case 17:
        readTransformable(r, d);
        ref();
        r.readColorRGB();
        for (int i = 0; i < 5; ++i) r.readByte();
        break;
    case 18:
        readNode(r, d);
        ref(), ref();
        r.readBoolean();
        for (int i = 0; i < 4; ++i) r.readInt32();
        break;
    case 19: {
        readObject3D(r, d);
        r.readByte(), r.readByte();
        EXPECT_EQ(r.readByte(), 0);
        r.readUInt32(), r.readUInt32(), r.readUInt32();
        const std::uint32_t comps = r.readUInt32();
        const std::uint32_t keys = r.readUInt32();
        for (std::uint32_t k = 0; k < keys; ++k) r.readInt32(), r.readFloat32s(comps, "keyframe");
        break;
    }
    case 20: {
        readObject3D(r, d);
        const int size = r.readByte();
        const int comps = r.readByte();
        EXPECT_EQ(r.readByte(), 0);
        const int count = r.readUInt16();
        r.skip(static_cast<std::uint64_t>(size) * comps * count, "values");
        break;
    }
    case 21: {
        readObject3D(r, d);
        r.readColorRGBA();
        ref();
        r.readFloat32s(4, "position bias, scale");
        ref(), ref();
        const std::uint32_t n = r.readUInt32();
        for (std::uint32_t i = 0; i < n; ++i) ref(), r.readFloat32s(4, "texcoord bias, scale");
        break;
    }
    case 22:
        readGroup(r, d);
        ref(), ref();
        break;
    default: ADD_FAILURE() << "unexpected object type " << int(o.type);
    }
    r.expectEnd();
    return d;
}

// The parsed file holds spans into `bytes`: a temporary would dangle.
M3GFile parse(Bytes&&) = delete;

M3GFile parse(const Bytes& bytes) {
    LoadLog log;  // strict
    M3GFile f = parseM3GFile(bytes, log);
    EXPECT_TRUE(log.warnings.empty());
    return f;
}

const M3GObject& only(const M3GFile& f, std::uint8_t type) {
    const M3GObject* found = nullptr;
    for (const auto& o : f.objects)
        if (o.type == type) {
            EXPECT_EQ(found, nullptr) << "more than one object of type " << int(type);
            found = &o;
        }
    if (!found) throw std::runtime_error("no object of type " + std::to_string(type));
    return *found;
}

std::size_t countType(const M3GFile& f, std::uint8_t type) {
    std::size_t n = 0;
    for (const auto& o : f.objects) n += o.type == type;
    return n;
}

/// Every object reachable through getReferences, alignment references and bones.
std::size_t reachableCount(const std::vector<Object3D*>& roots) {
    std::unordered_set<const Object3D*> seen;
    std::vector<const Object3D*> work(roots.begin(), roots.end());
    while (!work.empty()) {
        const Object3D* o = work.back();
        work.pop_back();
        if (!o || !seen.insert(o).second) continue;
        std::vector<Ref<Object3D>> refs(static_cast<std::size_t>(o->getReferences()));
        o->getReferences(refs);
        for (auto& r : refs) work.push_back(r.get());
        if (auto* n = dynamic_cast<const Node*>(o)) {
            work.push_back(n->getAlignmentReference(Node::Z_AXIS).get());
            work.push_back(n->getAlignmentReference(Node::Y_AXIS).get());
        }
    }
    return seen.size();
}

std::uint32_t floatBits(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    return u;
}

// ---- one of every class -----------------------------------------------------

struct Scene {
    Ref<World> world;
    Ref<Camera> camera;
    Ref<Light> light;
    Ref<Background> background;
    Ref<Appearance> appearance;
    Ref<Material> material;
    Ref<CompositingMode> compositing;
    Ref<VertexArray> positions;
    Ref<TriangleStripArray> strips;
    Ref<SkinnedMesh> skinned;
    Ref<Group> bone;
    Ref<Image2D> paletted;
    Ref<KeyframeSequence> keys;
    Ref<Group> group;
};

Scene makeScene() {
    Scene s;
    s.world = new World();
    s.world->setUserID(1);

    s.camera = new Camera();
    s.camera->setPerspective(60.0f, 1.5f, 0.25f, 100.0f);
    s.camera->setUserID(2);
    s.camera->setTranslation(0, 0, 10);

    s.light = new Light();
    s.light->setMode(Light::SPOT);
    s.light->setColor(0x123456);
    s.light->setIntensity(-0.0f);
    s.light->setSpotAngle(30);
    s.light->setAttenuation(1, 0.5f, 0.25f);
    s.light->setUserID(3);
    // The alignment reference (not in getReferences) must be written first:
    // the light is the world's first child, the camera comes later.
    s.light->setAlignment(s.camera.get(), Node::ORIGIN, nullptr, Node::NONE);
    s.world->addChild(s.light.get());
    s.world->addChild(s.camera.get());
    s.world->setActiveCamera(s.camera.get());

    const std::uint8_t rgb[4 * 2 * 3] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24};
    Ref<Image2D> bgImage = new Image2D(Image2D::RGB, 4, 2, rgb);
    s.background = new Background();
    s.background->setColor(static_cast<int>(0x80FF4020u));
    s.background->setImage(bgImage.get());
    s.background->setImageMode(Background::REPEAT, Background::BORDER);
    s.background->setCrop(1, 0, 3, 2);
    s.background->setDepthClearEnable(false);
    s.background->setColorClearEnable(true);
    s.world->setBackground(s.background.get());

    // Components.
    s.material = new Material();
    s.material->setColor(Material::AMBIENT, 0x00112233);
    s.material->setColor(Material::DIFFUSE, static_cast<int>(0x80445566u));
    s.material->setColor(Material::EMISSIVE, 0x00778899);
    s.material->setColor(Material::SPECULAR, 0x00AABBCC);
    s.material->setShininess(12.5f);
    s.material->setVertexColorTrackingEnable(true);
    s.compositing = new CompositingMode();
    s.compositing->setBlending(CompositingMode::ALPHA_ADD);
    s.compositing->setAlphaThreshold(0.4f);
    s.compositing->setDepthOffset(-1.0f, 2.0f);
    s.compositing->setAlphaWriteEnable(false);
    Ref<PolygonMode> polygon = new PolygonMode();
    polygon->setCulling(PolygonMode::CULL_NONE);
    polygon->setTwoSidedLightingEnable(true);
    Ref<Fog> fog = new Fog();
    fog->setMode(Fog::EXPONENTIAL);
    fog->setDensity(0.125f);
    fog->setColor(0x0A0B0C);
    const std::uint8_t palette[2 * 3] = {255, 0, 0, 0, 0, 255};
    const std::uint8_t indices[4 * 4] = {0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1, 0};
    s.paletted = new Image2D(Image2D::RGB, 4, 4, indices, palette);
    Ref<Texture2D> texture = new Texture2D(s.paletted.get());
    texture->setBlending(Texture2D::FUNC_ADD);
    texture->setWrapping(Texture2D::WRAP_CLAMP, Texture2D::WRAP_REPEAT);
    texture->setFiltering(Texture2D::FILTER_LINEAR, Texture2D::FILTER_LINEAR);
    texture->setBlendColor(0x405060);
    texture->setTranslation(0.5f, 0, 0);
    s.appearance = new Appearance();
    s.appearance->setLayer(-5);
    s.appearance->setMaterial(s.material.get());
    s.appearance->setCompositingMode(s.compositing.get());
    s.appearance->setPolygonMode(polygon.get());
    s.appearance->setFog(fog.get());
    s.appearance->setTexture(1, texture.get());  // unit 0 empty

    // Animation on the material.
    s.keys = new KeyframeSequence(2, 3, KeyframeSequence::LINEAR);
    const float k0[3] = {0.0f, 0.5f, 1.0f}, k1[3] = {1.0f, -0.0f, 0.25f};
    s.keys->setKeyframe(0, 0, k0);
    s.keys->setKeyframe(1, 1000, k1);
    s.keys->setDuration(2000);
    s.keys->setRepeatMode(KeyframeSequence::LOOP);
    Ref<AnimationController> controller = new AnimationController();
    controller->setActiveInterval(10, 5000);
    controller->setSpeed(2.0f, 100);
    controller->setPosition(3.0f, 100);
    controller->setWeight(0.75f);
    Ref<AnimationTrack> track = new AnimationTrack(s.keys.get(), AnimationTrack::DIFFUSE_COLOR);
    track->setController(controller.get());
    s.material->addAnimationTrack(track.get());

    // Geometry.
    s.positions = new VertexArray(4, 3, 2);
    const std::int16_t pos[12] = {-1, -1, 0, 1, -1, 0, -1, 1, 0, 1, 1, -32768};
    s.positions->set(0, 4, pos);
    Ref<VertexArray> normals = new VertexArray(4, 3, 1);
    const std::int8_t nrm[12] = {0, 0, 127, 0, 0, 127, 0, 0, -128, 0, 0, 127};
    normals->set(0, 4, nrm);
    Ref<VertexArray> colors = new VertexArray(4, 4, 1);
    const std::int8_t col[16] = {-1, 0, 0, -1, 0, -1, 0, -1, 0, 0, -1, -1, 1, 2, 3, 4};
    colors->set(0, 4, col);
    Ref<VertexArray> uv = new VertexArray(4, 2, 2);
    const std::int16_t tc[8] = {0, 0, 1, 0, 0, 1, 1, 1};
    uv->set(0, 4, tc);
    Ref<VertexBuffer> vb = new VertexBuffer();
    const float bias[3] = {0.5f, -0.5f, 2.0f};
    vb->setPositions(s.positions.get(), 0.25f, bias);
    vb->setNormals(normals.get());
    vb->setColors(colors.get());
    const float tbias[2] = {0.125f, 0.0f};
    vb->setTexCoords(1, uv.get(), 0.5f, tbias);
    vb->setDefaultColor(static_cast<int>(0xFF102030u));
    const int lengths[1] = {4};
    s.strips = new TriangleStripArray(0, lengths);
    const int explicitIdx[5] = {3, 2, 1, 0, 3};
    const int lengths5[1] = {5};
    Ref<TriangleStripArray> explicitStrips = new TriangleStripArray(explicitIdx, lengths5);

    s.group = new Group();
    s.group->setAlphaFactor(0.5f);
    s.group->setScope(0x0F);
    s.group->setPickingEnable(false);
    s.group->setUserObject(std::make_shared<const UserParameters>(
        UserParameters{{7, {1, 2, 3}}, {-1, {}}}));
    s.world->addChild(s.group.get());

    Ref<Mesh> mesh = new Mesh(vb.get(), s.strips.get(), s.appearance.get());
    Transform m;
    m.postScale(2, 3, 4);
    mesh->setTransform(&m);
    mesh->setOrientation(90, 0, 1, 0);
    s.group->addChild(mesh.get());

    Ref<VertexBuffer> target = new VertexBuffer();
    target->setPositions(s.positions.get(), 0.5f, bias);
    const Ref<VertexBuffer> targets[1] = {target};
    Ref<MorphingMesh> morph = new MorphingMesh(vb.get(), targets, explicitStrips.get(), s.appearance.get());
    const float w[1] = {0.3f};
    morph->setWeights(w);
    s.group->addChild(morph.get());

    Ref<Group> skeleton = new Group();
    s.bone = new Group();
    s.bone->setTranslation(1, 0, 0);
    skeleton->addChild(s.bone.get());
    s.skinned = new SkinnedMesh(vb.get(), s.strips.get(), s.appearance.get(), skeleton.get());
    s.skinned->addTransform(s.bone.get(), 3, 0, 2);
    s.skinned->addTransform(skeleton.get(), 1, 1, 3);
    s.skinned->addTransform(s.bone.get(), 2, 2, 2);
    s.group->addChild(s.skinned.get());

    Ref<Image2D> mutableImage = new Image2D(Image2D::LUMINANCE, 3, 5);
    Ref<Sprite3D> sprite = new Sprite3D(true, mutableImage.get(), s.appearance.get());
    sprite->setCrop(1, 1, 2, -3);
    s.group->addChild(sprite.get());
    return s;
}

Bytes saveScene(const Scene& s, const SaverOptions& options = {}) {
    Object3D* roots[] = {s.world.get()};
    return Saver::save(roots, options);
}

/// Checks every object decodes and every reference points backwards at an
/// existing object; returns the decoded objects (index i -> objects[i + 1]).
std::vector<Decoded> checkReferences(const M3GFile& f) {
    std::vector<Decoded> all;
    for (std::size_t i = 1; i < f.objects.size(); ++i) {
        const M3GObject& o = f.objects[i];
        Decoded d = decode(o);
        for (std::uint32_t r : d.refs) {
            EXPECT_NE(r, 1u) << "object " << o.index << " references the header";
            EXPECT_LT(r, o.index) << "object " << o.index << " (type " << int(o.type) << ") has forward reference " << r;
        }
        all.push_back(std::move(d));
    }
    return all;
}

ByteReader readerAfterObject3D(const M3GObject& o, Decoded& d) {
    ByteReader r = m3g::detail::objectReader(o, nullptr);
    readObject3D(r, d);
    return r;
}

}  // namespace

// ---- file structure ---------------------------------------------------------

TEST(Saver, HeaderAndSections) {
    Scene s = makeScene();
    SaverOptions options;
    options.authoringField = "unit test \xC3\xA9";
    const Bytes bytes = saveScene(s, options);
    ASSERT_GE(bytes.size(), 12u);
    EXPECT_TRUE(std::equal(m3g::detail::kM3GFileIdentifier.begin(), m3g::detail::kM3GFileIdentifier.end(),
                           bytes.begin()));
    M3GFile f = parse(bytes);
    EXPECT_EQ(f.header.versionMajor, 1);
    EXPECT_EQ(f.header.versionMinor, 0);
    EXPECT_FALSE(f.header.hasExternalReferences);
    EXPECT_EQ(f.header.totalFileSize, bytes.size());
    EXPECT_EQ(f.header.approximateContentSize, bytes.size());
    EXPECT_EQ(f.header.authoringField, options.authoringField);
    EXPECT_EQ(f.fileSize, bytes.size());
    ASSERT_EQ(f.sections.size(), 2u);
    for (const auto& sec : f.sections) {
        EXPECT_EQ(sec.compressionScheme, 0);
        EXPECT_EQ(sec.uncompressedLength, sec.totalSectionLength - 13);
        // The stored checksum is the Adler-32 of everything before it.
        std::span<const std::uint8_t> covered(bytes.data() + sec.fileOffset, sec.totalSectionLength - 4);
        EXPECT_EQ(sec.checksum, m3g::detail::adler32Of(covered));
    }
    EXPECT_EQ(f.sections[0].objectCount, 1u);
    EXPECT_EQ(f.sections[1].fileOffset + f.sections[1].totalSectionLength, bytes.size());
    EXPECT_EQ(f.objects[0].type, m3g::detail::kTypeHeader);
}

TEST(Saver, CompressedSectionInflatesToTheSameObjects) {
    Scene s = makeScene();
    SaverOptions zipped;
    zipped.compress = true;
    const Bytes plain = saveScene(s);
    const Bytes packed = saveScene(s, zipped);
    M3GFile a = parse(plain);
    M3GFile b = parse(packed);
    ASSERT_EQ(b.sections.size(), 2u);
    EXPECT_EQ(b.sections[0].compressionScheme, 0);  // the header section stays plain
    EXPECT_EQ(b.sections[1].compressionScheme, 1);
    EXPECT_EQ(b.sections[1].uncompressedLength, a.sections[1].uncompressedLength);
    EXPECT_LT(packed.size(), plain.size());
    EXPECT_EQ(b.header.totalFileSize, packed.size());
    ASSERT_EQ(a.sections[1].objects.size(), b.sections[1].objects.size());
    EXPECT_TRUE(std::equal(a.sections[1].objects.begin(), a.sections[1].objects.end(),
                           b.sections[1].objects.begin()));
    std::span<const std::uint8_t> covered(packed.data() + b.sections[1].fileOffset,
                                          b.sections[1].totalSectionLength - 4);
    EXPECT_EQ(b.sections[1].checksum, m3g::detail::adler32Of(covered));
    checkReferences(b);
}

TEST(Saver, ReferencesPointBackwardsAndSharedObjectsAreWrittenOnce) {
    Scene s = makeScene();
    const Bytes fBytes = saveScene(s);
    M3GFile f = parse(fBytes);
    checkReferences(f);
    std::vector<Object3D*> roots = {s.world.get()};
    EXPECT_EQ(f.objects.size() - 1, reachableCount(roots));
    // One Appearance, Material, VertexBuffer base... shared by four meshes.
    EXPECT_EQ(countType(f, m3g::detail::kTypeAppearance), 1u);
    EXPECT_EQ(countType(f, m3g::detail::kTypeMaterial), 1u);
    EXPECT_EQ(countType(f, m3g::detail::kTypeVertexBuffer), 2u);  // base + morph target
    EXPECT_EQ(countType(f, m3g::detail::kTypeVertexArray), 4u);   // positions shared by both buffers
    EXPECT_EQ(countType(f, m3g::detail::kTypeImage2D), 3u);
    EXPECT_EQ(countType(f, m3g::detail::kTypeGroup), 3u);  // group, skeleton, bone
    // The world is the only root and comes last.
    EXPECT_EQ(f.objects.back().type, m3g::detail::kTypeWorld);
    // Every object except the world is referenced by some object.
    std::set<std::uint32_t> referenced;
    for (const auto& d : checkReferences(f)) referenced.insert(d.refs.begin(), d.refs.end());
    for (std::size_t i = 1; i + 1 < f.objects.size(); ++i)
        EXPECT_TRUE(referenced.contains(f.objects[i].index)) << "object " << f.objects[i].index << " is a root";
}

TEST(Saver, SeveralRootsAndSharedObjectsAcrossRoots) {
    Ref<Material> shared = new Material();
    Ref<Appearance> a1 = new Appearance();
    Ref<Appearance> a2 = new Appearance();
    a1->setMaterial(shared.get());
    a2->setMaterial(shared.get());
    Object3D* roots[] = {a1.get(), a2.get(), a1.get(), shared.get()};
    const Bytes fBytes = Saver::save(roots);
    M3GFile f = parse(fBytes);
    ASSERT_EQ(f.objects.size(), 4u);  // header, material, a1, a2
    EXPECT_EQ(f.objects[1].type, m3g::detail::kTypeMaterial);
    EXPECT_EQ(f.objects[2].type, m3g::detail::kTypeAppearance);
    EXPECT_EQ(f.objects[3].type, m3g::detail::kTypeAppearance);
    const auto decoded = checkReferences(f);
    EXPECT_EQ(decoded[1].refs, (std::vector<std::uint32_t>{0, 0, 0, 2}));  // cm, fog, pm, material
    EXPECT_EQ(decoded[2].refs, (std::vector<std::uint32_t>{0, 0, 0, 2}));
}

TEST(Saver, AlignmentReferenceIsWrittenBeforeTheNode) {
    Scene s = makeScene();
    const Bytes fBytes = saveScene(s);
    M3GFile f = parse(fBytes);
    const M3GObject& light = only(f, m3g::detail::kTypeLight);
    const M3GObject& camera = only(f, m3g::detail::kTypeCamera);
    EXPECT_LT(camera.index, light.index);
    LoadLog log;
    ByteReader r = m3g::detail::objectReader(light, &log);
    Decoded d;
    readTransformable(r, d);
    EXPECT_TRUE(r.readBoolean());
    EXPECT_TRUE(r.readBoolean());
    EXPECT_EQ(r.readByte(), 255);
    EXPECT_EQ(r.readUInt32(), 0xFFFFFFFFu);
    EXPECT_TRUE(r.readBoolean());  // hasAlignment
    EXPECT_EQ(r.readByte(), Node::ORIGIN);
    EXPECT_EQ(r.readByte(), Node::NONE);
    EXPECT_EQ(r.readObjectIndex(), camera.index);
    EXPECT_EQ(r.readObjectIndex(), 0u);
}

TEST(Saver, DeepHierarchyNeedsNoRecursion) {
    Ref<Group> root = new Group();
    Group* g = root.get();
    for (int i = 0; i < 3000; ++i) {
        Ref<Group> child = new Group();
        g->addChild(child.get());
        g = child.get();
    }
    Object3D* roots[] = {root.get()};
    const Bytes fBytes = Saver::save(roots);
    M3GFile f = parse(fBytes);
    EXPECT_EQ(f.objects.size(), 3002u);
    checkReferences(f);
}

TEST(Saver, AlignmentCycleIsAnIOException) {
    Ref<Group> parent = new Group();
    Ref<Group> child = new Group();
    parent->addChild(child.get());
    child->setAlignment(parent.get(), Node::ORIGIN, nullptr, Node::NONE);
    Object3D* roots[] = {parent.get()};
    EXPECT_THROW(Saver::save(roots), IOException);
}

TEST(Saver, NullRootsAndEntries) {
    EXPECT_THROW(Saver::save(std::span<Object3D* const>()), NullPointerException);
    Object3D* roots[] = {nullptr};
    EXPECT_THROW(Saver::save(roots), NullPointerException);
    Ref<Group> g = new Group();
    Object3D* some[] = {g.get(), nullptr};
    EXPECT_THROW(Saver::save(some), NullPointerException);
    // An empty (non-null) root list gives a file with an empty objects section.
    Object3D* dummy = nullptr;
    const Bytes fBytes = Saver::save(std::span<Object3D* const>(&dummy, 0));
    M3GFile f = parse(fBytes);
    EXPECT_EQ(f.objects.size(), 1u);
}

TEST(Saver, BadAuthoringField) {
    Ref<Group> g = new Group();
    Object3D* roots[] = {g.get()};
    SaverOptions o;
    o.authoringField = std::string("a\0b", 3);
    EXPECT_THROW(Saver::save(roots, o), IllegalArgumentException);
    o.authoringField = "\xFF";
    EXPECT_THROW(Saver::save(roots, o), IllegalArgumentException);
}

TEST(Saver, NonFiniteFloatIsAnIOException) {
    Ref<Light> light = new Light();
    light->setIntensity(std::numeric_limits<float>::quiet_NaN());
    Object3D* roots[] = {light.get()};
    EXPECT_THROW(Saver::save(roots), IOException);
    light->setIntensity(std::numeric_limits<float>::infinity());
    EXPECT_THROW(Saver::save(roots), IOException);
}

TEST(Saver, SaveToFile) {
    Scene s = makeScene();
    const auto path = std::filesystem::temp_directory_path() / "m3g_saver_test.m3g";
    Object3D* roots[] = {s.world.get()};
    Saver::save(path.string(), roots);
    std::ifstream in(path, std::ios::binary);
    Bytes read((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(read, Saver::save(roots));
    std::filesystem::remove(path);
    EXPECT_THROW(Saver::save("/nonexistent-dir-m3g/x.m3g", roots), IOException);
}

// ---- field values -------------------------------------------------------------

TEST(Saver, Object3DBlockUserIdTracksAndParameters) {
    Scene s = makeScene();
    const Bytes fBytes = saveScene(s);
    M3GFile f = parse(fBytes);
    // The material has one animation track, written before it.
    const M3GObject& material = only(f, m3g::detail::kTypeMaterial);
    const M3GObject& track = only(f, m3g::detail::kTypeAnimationTrack);
    ByteReader r = m3g::detail::objectReader(material, nullptr);
    EXPECT_EQ(r.readUInt32(), 0u);
    EXPECT_EQ(r.readObjectIndexArray("tracks"), (std::vector<std::uint32_t>{track.index}));
    EXPECT_EQ(r.readUInt32(), 0u);
    // The group with user parameters (IDs in map order: -1 then 7).
    for (const auto& o : f.objects) {
        if (o.type != m3g::detail::kTypeGroup) continue;
        ByteReader g = m3g::detail::objectReader(o, nullptr);
        g.readUInt32();
        g.readObjectIndexArray("tracks");
        const std::uint32_t n = g.readUInt32();
        if (n == 0) continue;
        ASSERT_EQ(n, 2u);
        EXPECT_EQ(g.readUInt32(), 0xFFFFFFFFu);
        EXPECT_TRUE(g.readByteArray("value").empty());
        EXPECT_EQ(g.readUInt32(), 7u);
        EXPECT_EQ(g.readByteArray("value"), (std::vector<std::uint8_t>{1, 2, 3}));
        // Node block: alpha factor 0.5 -> 128, picking disabled, scope 15.
        EXPECT_FALSE(g.readBoolean());  // no component transform
        EXPECT_FALSE(g.readBoolean());  // no general transform
        EXPECT_TRUE(g.readBoolean());
        EXPECT_FALSE(g.readBoolean());
        EXPECT_EQ(g.readByte(), 128);
        EXPECT_EQ(g.readUInt32(), 15u);
        EXPECT_FALSE(g.readBoolean());
        return;
    }
    ADD_FAILURE() << "no group with user parameters";
}

TEST(Saver, OtherUserObjectsAreSkipped) {
    Ref<Group> g = new Group();
    g->setUserObject(std::string("not serialisable"));
    g->setUserID(-2);
    Object3D* roots[] = {g.get()};
    const Bytes fBytes = Saver::save(roots);
    M3GFile f = parse(fBytes);
    ByteReader r = m3g::detail::objectReader(f.objects[1], nullptr);
    EXPECT_EQ(r.readUInt32(), 0xFFFFFFFEu);
    EXPECT_TRUE(r.readObjectIndexArray("tracks").empty());
    EXPECT_EQ(r.readUInt32(), 0u);
}

TEST(Saver, MaterialColors) {
    Scene s = makeScene();
    const Bytes fBytes = saveScene(s);
    M3GFile f = parse(fBytes);
    Decoded d;
    ByteReader r = readerAfterObject3D(only(f, m3g::detail::kTypeMaterial), d);
    EXPECT_EQ(r.readColorRGB(), 0x112233u);
    EXPECT_EQ(r.readColorRGBA(), 0x80445566u);
    EXPECT_EQ(r.readColorRGB(), 0x778899u);
    EXPECT_EQ(r.readColorRGB(), 0xAABBCCu);
    EXPECT_EQ(r.readFloat32(), 12.5f);
    EXPECT_TRUE(r.readBoolean());
    EXPECT_TRUE(r.atEnd());
}

TEST(Saver, CameraPerspectiveAndComponentTransform) {
    Scene s = makeScene();
    const Bytes fBytes = saveScene(s);
    M3GFile f = parse(fBytes);
    ByteReader r = m3g::detail::objectReader(only(f, m3g::detail::kTypeCamera), nullptr);
    EXPECT_EQ(r.readUInt32(), 2u);
    r.readObjectIndexArray("tracks");
    r.readUInt32();
    ASSERT_TRUE(r.readBoolean());
    EXPECT_EQ(r.readVector3D(), (std::array<float, 3>{0, 0, 10}));
    EXPECT_EQ(r.readVector3D(), (std::array<float, 3>{1, 1, 1}));
    EXPECT_EQ(r.readFloat32(), 0.0f);
    EXPECT_EQ(r.readVector3D(), (std::array<float, 3>{0, 0, 0}));
    EXPECT_FALSE(r.readBoolean());
    r.skip(1 + 1 + 1 + 4 + 1, "node fields");
    EXPECT_EQ(r.readByte(), Camera::PERSPECTIVE);
    EXPECT_EQ(r.readFloat32(), 60.0f);
    EXPECT_EQ(r.readFloat32(), 1.5f);
    EXPECT_EQ(r.readFloat32(), 0.25f);
    EXPECT_EQ(r.readFloat32(), 100.0f);
    EXPECT_TRUE(r.atEnd());
}

TEST(Saver, CameraGenericAndParallel) {
    Ref<Camera> generic = new Camera();
    Transform p;
    p.postScale(1, 2, 3);
    generic->setGeneric(&p);
    Ref<Camera> parallel = new Camera();
    parallel->setParallel(5, 2, -1, -1);  // near == far is storable
    Object3D* roots[] = {generic.get(), parallel.get()};
    const Bytes fBytes = Saver::save(roots);
    M3GFile f = parse(fBytes);
    ASSERT_EQ(f.objects.size(), 3u);
    for (int i = 1; i <= 2; ++i) {
        ByteReader r = m3g::detail::objectReader(f.objects[i], nullptr);
        Decoded d;
        readNode(r, d);
        if (i == 1) {
            EXPECT_EQ(r.readByte(), Camera::GENERIC);
            EXPECT_EQ(r.readMatrix(), p.rows());
        } else {
            EXPECT_EQ(r.readByte(), Camera::PARALLEL);
            EXPECT_EQ(r.readFloat32s(4, "params"), (std::vector<float>{5, 2, -1, -1}));
        }
        EXPECT_TRUE(r.atEnd());
    }
}

TEST(Saver, GeneralTransformAndOrientation) {
    Scene s = makeScene();
    const Bytes fBytes = saveScene(s);
    M3GFile f = parse(fBytes);
    ByteReader r = m3g::detail::objectReader(only(f, m3g::detail::kTypeMesh), nullptr);
    Decoded d;
    readObject3D(r, d);
    ASSERT_TRUE(r.readBoolean());
    EXPECT_EQ(r.readVector3D(), (std::array<float, 3>{0, 0, 0}));
    EXPECT_EQ(r.readVector3D(), (std::array<float, 3>{1, 1, 1}));
    EXPECT_NEAR(r.readFloat32(), 90.0f, 1e-3f);
    const auto axis = r.readVector3D();
    EXPECT_NEAR(axis[0], 0.0f, 1e-6f);
    EXPECT_NEAR(axis[1], 1.0f, 1e-6f);
    EXPECT_NEAR(axis[2], 0.0f, 1e-6f);
    ASSERT_TRUE(r.readBoolean());
    Transform m;
    m.postScale(2, 3, 4);
    EXPECT_EQ(r.readMatrix(), m.rows());
}

TEST(Saver, LightNegativeZeroIsWrittenAsPositiveZero) {
    Scene s = makeScene();
    const Bytes fBytes = saveScene(s);
    M3GFile f = parse(fBytes);
    ByteReader r = m3g::detail::objectReader(only(f, m3g::detail::kTypeLight), nullptr);
    Decoded d;
    readNode(r, d);
    EXPECT_EQ(r.readFloat32s(3, "attenuation"), (std::vector<float>{1, 0.5f, 0.25f}));
    EXPECT_EQ(r.readColorRGB(), 0x123456u);
    EXPECT_EQ(r.readByte(), Light::SPOT);
    const std::size_t at = r.position();
    EXPECT_EQ(r.readFloat32(), 0.0f);  // strict reader: -0.0 would throw
    const auto data = only(f, m3g::detail::kTypeLight).data;
    EXPECT_EQ(data[at] | data[at + 1] | data[at + 2] | data[at + 3], 0);
    EXPECT_EQ(r.readFloat32(), 30.0f);
    EXPECT_EQ(r.readFloat32(), 0.0f);
    EXPECT_TRUE(r.atEnd());
    // Denormals too become +0.
    EXPECT_EQ(m3g::detail::float32BitsForFile(std::numeric_limits<float>::denorm_min(), "x"), 0u);
    EXPECT_EQ(m3g::detail::float32BitsForFile(-1.5f, "x"), floatBits(-1.5f));
}

TEST(Saver, BackgroundFlagsInSpecOrder) {
    Scene s = makeScene();
    const Bytes fBytes = saveScene(s);
    M3GFile f = parse(fBytes);
    const M3GObject& bg = only(f, m3g::detail::kTypeBackground);
    Decoded d;
    ByteReader r = readerAfterObject3D(bg, d);
    EXPECT_EQ(r.readColorRGBA(), 0x80FF4020u);
    const std::uint32_t image = r.readObjectIndex();
    EXPECT_GT(image, 1u);
    EXPECT_LT(image, bg.index);
    EXPECT_EQ(f.objects[image - 1].type, m3g::detail::kTypeImage2D);
    EXPECT_EQ(r.readByte(), Background::REPEAT);
    EXPECT_EQ(r.readByte(), Background::BORDER);
    EXPECT_EQ(r.readInt32(), 1);
    EXPECT_EQ(r.readInt32(), 0);
    EXPECT_EQ(r.readInt32(), 3);
    EXPECT_EQ(r.readInt32(), 2);
    EXPECT_FALSE(r.readBoolean());  // depthClearEnabled
    EXPECT_TRUE(r.readBoolean());   // colorClearEnabled
    EXPECT_TRUE(r.atEnd());
}

TEST(Saver, AppearanceLayerAndTextureUnits) {
    Scene s = makeScene();
    const Bytes fBytes = saveScene(s);
    M3GFile f = parse(fBytes);
    Decoded d;
    ByteReader r = readerAfterObject3D(only(f, m3g::detail::kTypeAppearance), d);
    EXPECT_EQ(r.readByte(), 0xFB);  // -5
    EXPECT_EQ(r.readObjectIndex(), only(f, m3g::detail::kTypeCompositingMode).index);
    EXPECT_EQ(r.readObjectIndex(), only(f, m3g::detail::kTypeFog).index);
    EXPECT_EQ(r.readObjectIndex(), only(f, m3g::detail::kTypePolygonMode).index);
    EXPECT_EQ(r.readObjectIndex(), only(f, m3g::detail::kTypeMaterial).index);
    EXPECT_EQ(r.readObjectIndexArray("textures"),
              (std::vector<std::uint32_t>{0, only(f, m3g::detail::kTypeTexture2D).index}));
}

TEST(Saver, CompositingModeFogPolygonModeTexture) {
    Scene s = makeScene();
    const Bytes fBytes = saveScene(s);
    M3GFile f = parse(fBytes);
    Decoded d;
    ByteReader c = readerAfterObject3D(only(f, m3g::detail::kTypeCompositingMode), d);
    EXPECT_TRUE(c.readBoolean());
    EXPECT_TRUE(c.readBoolean());
    EXPECT_TRUE(c.readBoolean());
    EXPECT_FALSE(c.readBoolean());
    EXPECT_EQ(c.readByte(), CompositingMode::ALPHA_ADD);
    EXPECT_EQ(c.readByte(), 102);  // round(0.4 * 255)
    EXPECT_EQ(c.readFloat32(), -1.0f);
    EXPECT_EQ(c.readFloat32(), 2.0f);
    ByteReader fog = readerAfterObject3D(only(f, m3g::detail::kTypeFog), d);
    EXPECT_EQ(fog.readColorRGB(), 0x0A0B0Cu);
    EXPECT_EQ(fog.readByte(), Fog::EXPONENTIAL);
    EXPECT_EQ(fog.readFloat32(), 0.125f);
    EXPECT_TRUE(fog.atEnd());
    ByteReader pm = readerAfterObject3D(only(f, m3g::detail::kTypePolygonMode), d);
    EXPECT_EQ(pm.readByte(), PolygonMode::CULL_NONE);
    EXPECT_EQ(pm.readByte(), PolygonMode::SHADE_SMOOTH);
    EXPECT_EQ(pm.readByte(), PolygonMode::WINDING_CCW);
    EXPECT_TRUE(pm.readBoolean());
    EXPECT_FALSE(pm.readBoolean());
    EXPECT_FALSE(pm.readBoolean());
    ByteReader t = m3g::detail::objectReader(only(f, m3g::detail::kTypeTexture2D), nullptr);
    readObject3D(t, d);
    ASSERT_TRUE(t.readBoolean());
    EXPECT_EQ(t.readVector3D(), (std::array<float, 3>{0.5f, 0, 0}));
    t.readFloat32s(7, "scale, orientation");
    EXPECT_FALSE(t.readBoolean());
    const std::uint32_t image = t.readObjectIndex();
    EXPECT_EQ(f.objects[image - 1].type, m3g::detail::kTypeImage2D);
    EXPECT_EQ(t.readColorRGB(), 0x405060u);
    EXPECT_EQ(t.readByte(), Texture2D::FUNC_ADD);
    EXPECT_EQ(t.readByte(), Texture2D::WRAP_CLAMP);
    EXPECT_EQ(t.readByte(), Texture2D::WRAP_REPEAT);
    EXPECT_EQ(t.readByte(), Texture2D::FILTER_LINEAR);
    EXPECT_EQ(t.readByte(), Texture2D::FILTER_LINEAR);
    EXPECT_TRUE(t.atEnd());
}

TEST(Saver, VertexArrayAndVertexBufferValues) {
    Scene s = makeScene();
    const Bytes fBytes = saveScene(s);
    M3GFile f = parse(fBytes);
    std::vector<const M3GObject*> arrays;
    for (const auto& o : f.objects)
        if (o.type == m3g::detail::kTypeVertexArray) arrays.push_back(&o);
    bool foundPositions = false;
    for (const M3GObject* o : arrays) {
        Decoded d;
        ByteReader r = readerAfterObject3D(*o, d);
        const int size = r.readByte();
        const int comps = r.readByte();
        EXPECT_EQ(r.readByte(), 0);  // encoding 0
        const int count = r.readUInt16();
        if (size == 2 && comps == 3) {
            foundPositions = true;
            EXPECT_EQ(count, 4);
            std::vector<std::int16_t> v;
            for (int i = 0; i < 12; ++i) v.push_back(r.readInt16());
            EXPECT_EQ(v, (std::vector<std::int16_t>{-1, -1, 0, 1, -1, 0, -1, 1, 0, 1, 1, -32768}));
        } else if (size == 1 && comps == 4) {
            std::vector<std::uint8_t> v;
            for (int i = 0; i < 16; ++i) v.push_back(r.readByte());
            EXPECT_EQ(v, (std::vector<std::uint8_t>{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 1, 2, 3, 4}));
        }
    }
    EXPECT_TRUE(foundPositions);
    // The base vertex buffer (the one with a color array) and the morph target.
    int buffers = 0;
    for (const auto& o : f.objects) {
        if (o.type != m3g::detail::kTypeVertexBuffer) continue;
        ++buffers;
        Decoded d;
        ByteReader r = readerAfterObject3D(o, d);
        const std::uint32_t color = r.readColorRGBA();
        const std::uint32_t positions = r.readObjectIndex();
        EXPECT_EQ(f.objects[positions - 1].type, m3g::detail::kTypeVertexArray);
        EXPECT_EQ(r.readFloat32s(3, "bias"), (std::vector<float>{0.5f, -0.5f, 2.0f}));
        const float scale = r.readFloat32();
        const std::uint32_t normals = r.readObjectIndex();
        const std::uint32_t colors = r.readObjectIndex();
        const std::uint32_t units = r.readUInt32();
        if (colors != 0) {
            EXPECT_EQ(color, 0xFF102030u);
            EXPECT_EQ(scale, 0.25f);
            EXPECT_NE(normals, 0u);
            ASSERT_EQ(units, 2u);  // unit 0 empty, unit 1 set
            EXPECT_EQ(r.readObjectIndex(), 0u);
            EXPECT_EQ(r.readFloat32s(4, "unit 0"), (std::vector<float>{0, 0, 0, 1}));
            EXPECT_NE(r.readObjectIndex(), 0u);
            const auto tb = r.readFloat32s(3, "unit 1 bias");
            EXPECT_EQ(tb[0], 0.125f);
            EXPECT_EQ(tb[1], 0.0f);
            EXPECT_EQ(r.readFloat32(), 0.5f);
        } else {
            EXPECT_EQ(color, 0xFFFFFFFFu);
            EXPECT_EQ(scale, 0.5f);
            EXPECT_EQ(normals, 0u);
            EXPECT_EQ(units, 0u);
        }
        EXPECT_TRUE(r.atEnd());
    }
    EXPECT_EQ(buffers, 2);
}

TEST(Saver, TriangleStripEncodings) {
    const int len3[1] = {3};
    const int idxByte[3] = {200, 1, 2};
    const int idxShort[3] = {1000, 1, 2};
    Ref<TriangleStripArray> implicitByte = new TriangleStripArray(5, len3);
    Ref<TriangleStripArray> implicitShort = new TriangleStripArray(300, len3);
    Ref<TriangleStripArray> explicitByte = new TriangleStripArray(idxByte, len3);
    Ref<TriangleStripArray> explicitShort = new TriangleStripArray(idxShort, len3);
    const int consecutive[3] = {7, 8, 9};
    Ref<TriangleStripArray> explicitButConsecutive = new TriangleStripArray(consecutive, len3);
    Object3D* roots[] = {implicitByte.get(), implicitShort.get(), explicitByte.get(), explicitShort.get(),
                         explicitButConsecutive.get()};
    const Bytes fBytes = Saver::save(roots);
    M3GFile f = parse(fBytes);
    ASSERT_EQ(f.objects.size(), 6u);
    checkReferences(f);
    auto reader = [&](int i) {
        Decoded d;
        return readerAfterObject3D(f.objects[static_cast<std::size_t>(i)], d);
    };
    {
        ByteReader r = reader(1);
        EXPECT_EQ(r.readByte(), 1);
        EXPECT_EQ(r.readByte(), 5);
        EXPECT_EQ(r.readUInt32Array("lengths"), (std::vector<std::uint32_t>{3}));
        EXPECT_TRUE(r.atEnd());
    }
    {
        ByteReader r = reader(2);
        EXPECT_EQ(r.readByte(), 2);
        EXPECT_EQ(r.readUInt16(), 300);
    }
    {
        ByteReader r = reader(3);
        EXPECT_EQ(r.readByte(), 129);
        EXPECT_EQ(r.readByteArray("indices"), (std::vector<std::uint8_t>{200, 1, 2}));
        EXPECT_EQ(r.readUInt32Array("lengths"), (std::vector<std::uint32_t>{3}));
    }
    {
        ByteReader r = reader(4);
        EXPECT_EQ(r.readByte(), 130);
        EXPECT_EQ(r.readUInt16Array("indices"), (std::vector<std::uint16_t>{1000, 1, 2}));
    }
    {
        ByteReader r = reader(5);
        EXPECT_EQ(r.readByte(), 1);  // consecutive explicit indices become implicit
        EXPECT_EQ(r.readByte(), 7);
    }
}

TEST(Saver, ImagesDirectPalettedAndMutable) {
    Scene s = makeScene();
    const Bytes fBytes = saveScene(s);
    M3GFile f = parse(fBytes);
    int seen = 0;
    for (const auto& o : f.objects) {
        if (o.type != m3g::detail::kTypeImage2D) continue;
        Decoded d;
        ByteReader r = readerAfterObject3D(o, d);
        const int format = r.readByte();
        const bool isMutable = r.readBoolean();
        const std::uint32_t w = r.readUInt32();
        const std::uint32_t h = r.readUInt32();
        if (isMutable) {
            EXPECT_EQ(format, Image2D::LUMINANCE);
            EXPECT_EQ(w, 3u);
            EXPECT_EQ(h, 5u);
            seen |= 1;
        } else if (w == 4 && h == 4) {
            EXPECT_EQ(r.readByteArray("palette"), (std::vector<std::uint8_t>{255, 0, 0, 0, 0, 255}));
            EXPECT_EQ(r.readByteArray("indices"),
                      (std::vector<std::uint8_t>{0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1, 0}));
            seen |= 2;
        } else {
            EXPECT_EQ(format, Image2D::RGB);
            EXPECT_TRUE(r.readByteArray("palette").empty());
            const auto px = r.readByteArray("pixels");
            ASSERT_EQ(px.size(), 24u);
            EXPECT_EQ(px[0], 1);
            EXPECT_EQ(px[23], 24);
            seen |= 4;
        }
        EXPECT_TRUE(r.atEnd());
    }
    EXPECT_EQ(seen, 7);
}

TEST(Saver, KeyframeSequenceTrackAndController) {
    Scene s = makeScene();
    const Bytes fBytes = saveScene(s);
    M3GFile f = parse(fBytes);
    const M3GObject& seq = only(f, m3g::detail::kTypeKeyframeSequence);
    const M3GObject& ctl = only(f, m3g::detail::kTypeAnimationController);
    Decoded d;
    ByteReader r = readerAfterObject3D(seq, d);
    EXPECT_EQ(r.readByte(), KeyframeSequence::LINEAR);
    EXPECT_EQ(r.readByte(), KeyframeSequence::LOOP);
    EXPECT_EQ(r.readByte(), 0);
    EXPECT_EQ(r.readUInt32(), 2000u);
    EXPECT_EQ(r.readUInt32(), 0u);
    EXPECT_EQ(r.readUInt32(), 1u);
    EXPECT_EQ(r.readUInt32(), 3u);
    EXPECT_EQ(r.readUInt32(), 2u);
    EXPECT_EQ(r.readInt32(), 0);
    EXPECT_EQ(r.readFloat32s(3, "k0"), (std::vector<float>{0.0f, 0.5f, 1.0f}));
    EXPECT_EQ(r.readInt32(), 1000);
    EXPECT_EQ(r.readFloat32s(3, "k1"), (std::vector<float>{1.0f, 0.0f, 0.25f}));  // -0 -> +0
    EXPECT_TRUE(r.atEnd());

    ByteReader c = readerAfterObject3D(ctl, d);
    EXPECT_EQ(c.readFloat32(), 2.0f);
    EXPECT_EQ(c.readFloat32(), 0.75f);
    EXPECT_EQ(c.readInt32(), 10);
    EXPECT_EQ(c.readInt32(), 5000);
    EXPECT_EQ(c.readFloat32(), 3.0f);
    EXPECT_EQ(c.readInt32(), 100);

    ByteReader t = readerAfterObject3D(only(f, m3g::detail::kTypeAnimationTrack), d);
    EXPECT_EQ(t.readObjectIndex(), seq.index);
    EXPECT_EQ(t.readObjectIndex(), ctl.index);
    EXPECT_EQ(t.readUInt32(), static_cast<std::uint32_t>(AnimationTrack::DIFFUSE_COLOR));
}

TEST(Saver, MeshMorphingMeshSkinnedMeshSprite) {
    Scene s = makeScene();
    const Bytes fBytes = saveScene(s);
    M3GFile f = parse(fBytes);
    const std::uint32_t app = only(f, m3g::detail::kTypeAppearance).index;
    {
        ByteReader r = m3g::detail::objectReader(only(f, m3g::detail::kTypeMorphingMesh), nullptr);
        Decoded d;
        readMesh(r, d);
        ASSERT_EQ(d.refs.size(), 3u);
        EXPECT_EQ(d.refs[2], app);
        EXPECT_EQ(r.readUInt32(), 1u);
        const std::uint32_t target = r.readObjectIndex();
        EXPECT_EQ(f.objects[target - 1].type, m3g::detail::kTypeVertexBuffer);
        EXPECT_NE(target, d.refs[0]);
        EXPECT_EQ(r.readFloat32(), 0.3f);
        EXPECT_TRUE(r.atEnd());
    }
    {
        const M3GObject& sm = only(f, m3g::detail::kTypeSkinnedMesh);
        ByteReader r = m3g::detail::objectReader(sm, nullptr);
        Decoded d;
        readMesh(r, d);
        const std::uint32_t skeleton = r.readObjectIndex();
        EXPECT_EQ(f.objects[skeleton - 1].type, m3g::detail::kTypeGroup);
        EXPECT_EQ(r.readUInt32(), 3u);
        const std::uint32_t bone = r.readObjectIndex();
        EXPECT_EQ(f.objects[bone - 1].type, m3g::detail::kTypeGroup);
        EXPECT_LT(bone, skeleton);
        EXPECT_EQ(r.readUInt32(), 0u);  // firstVertex
        EXPECT_EQ(r.readUInt32(), 2u);  // vertexCount
        EXPECT_EQ(r.readInt32(), 3);    // weight
        EXPECT_EQ(r.readObjectIndex(), skeleton);
        EXPECT_EQ(r.readUInt32(), 1u);
        EXPECT_EQ(r.readUInt32(), 3u);
        EXPECT_EQ(r.readInt32(), 1);
        EXPECT_EQ(r.readObjectIndex(), bone);
        EXPECT_EQ(r.readUInt32(), 2u);
        EXPECT_EQ(r.readUInt32(), 2u);
        EXPECT_EQ(r.readInt32(), 2);
        EXPECT_TRUE(r.atEnd());
    }
    {
        ByteReader r = m3g::detail::objectReader(only(f, m3g::detail::kTypeSprite3D), nullptr);
        Decoded d;
        readNode(r, d);
        const std::uint32_t image = r.readObjectIndex();
        EXPECT_EQ(f.objects[image - 1].type, m3g::detail::kTypeImage2D);
        EXPECT_EQ(r.readObjectIndex(), app);
        EXPECT_TRUE(r.readBoolean());
        EXPECT_EQ(r.readInt32(), 1);
        EXPECT_EQ(r.readInt32(), 1);
        EXPECT_EQ(r.readInt32(), 2);
        EXPECT_EQ(r.readInt32(), -3);
        EXPECT_TRUE(r.atEnd());
    }
    {
        const M3GObject& world = only(f, m3g::detail::kTypeWorld);
        ByteReader r = m3g::detail::objectReader(world, nullptr);
        Decoded d;
        readGroup(r, d);
        EXPECT_EQ(d.refs, (std::vector<std::uint32_t>{only(f, m3g::detail::kTypeLight).index,
                                                      only(f, m3g::detail::kTypeCamera).index,
                                                      f.objects[d.refs[2] - 1].index}));
        EXPECT_EQ(r.readObjectIndex(), only(f, m3g::detail::kTypeCamera).index);
        EXPECT_EQ(r.readObjectIndex(), only(f, m3g::detail::kTypeBackground).index);
        EXPECT_TRUE(r.atEnd());
    }
}

TEST(Saver, SkinnedMeshKeepsAddTransformCallsAcrossDuplicate) {
    Scene s = makeScene();
    const auto added = s.skinned->addedTransforms();
    ASSERT_EQ(added.size(), 3u);
    EXPECT_EQ(s.skinned->bone(added[0].bone), s.bone.get());
    EXPECT_EQ(added[0].weight, 3);
    EXPECT_EQ(added[1].firstVertex, 1);
    EXPECT_EQ(added[2].vertexCount, 2);
    Ref<SkinnedMesh> copy = dynamicCast<SkinnedMesh>(s.skinned->duplicate());
    ASSERT_TRUE(copy);
    ASSERT_EQ(copy->addedTransforms().size(), 3u);
    EXPECT_TRUE(copy->bone(copy->addedTransforms()[0].bone)->isDescendantOf(copy->getSkeleton().get()));
}

// ---- RoundTrip.h -----------------------------------------------------------

TEST(RoundTrip, DuplicateIsEquivalent) {
    Scene s = makeScene();
    Ref<Object3D> copy = s.world->duplicate();
    EXPECT_EQ(compareGraphs(s.world.get(), copy.get()), "");
    EXPECT_EQ(compareGraphs(s.world.get(), s.world.get()), "");
}

TEST(RoundTrip, ModifiedNodeIsReported) {
    Scene s = makeScene();
    Ref<Object3D> copy = s.world->duplicate();
    Ref<Light> light = dynamicCast<Light>(copy->find(3));
    ASSERT_TRUE(light);
    light->setIntensity(2.0f);
    const std::string diff = compareGraphs(s.world.get(), copy.get());
    EXPECT_NE(diff.find("Light"), std::string::npos) << diff;
    EXPECT_NE(diff.find("getIntensity"), std::string::npos) << diff;
}

TEST(RoundTrip, ModifiedComponentIsReported) {
    Scene s = makeScene();
    Ref<Object3D> copy = s.world->duplicate();
    // Components are shared by duplicate(): give the copy's mesh its own
    // appearance with a different material.
    Ref<World> world = dynamicCast<World>(copy);
    ASSERT_TRUE(world);
    Ref<Group> group = dynamicCast<Group>(world->getChild(2));
    ASSERT_TRUE(group);
    Ref<Mesh> mesh = dynamicCast<Mesh>(group->getChild(0));
    ASSERT_TRUE(mesh);
    Ref<Appearance> app = dynamicCast<Appearance>(s.appearance->duplicate());
    Ref<Material> mat = dynamicCast<Material>(s.material->duplicate());
    mat->setShininess(1.0f);
    app->setMaterial(mat.get());
    mesh->setAppearance(0, app.get());
    const std::string diff = compareGraphs(s.world.get(), copy.get());
    EXPECT_NE(diff, "");
    // The first difference is the broken sharing of the appearance (the
    // original shares one appearance between four meshes).
    EXPECT_NE(diff.find("Appearance"), std::string::npos) << diff;
}

TEST(RoundTrip, ValueDifferenceInSharedComponentPath) {
    Ref<Material> m1 = new Material();
    Ref<Material> m2 = new Material();
    m2->setColor(Material::SPECULAR, 0x010203);
    Ref<Appearance> a1 = new Appearance();
    Ref<Appearance> a2 = new Appearance();
    a1->setMaterial(m1.get());
    a2->setMaterial(m2.get());
    const std::string diff = compareGraphs(a1.get(), a2.get());
    EXPECT_EQ(diff, "roots[0] Appearance > material Material: getColor(SPECULAR) 0 != 66051");
}

TEST(RoundTrip, SharingDifferenceIsReported) {
    Ref<Material> shared = new Material();
    Ref<Material> other = new Material();
    Ref<Appearance> a = new Appearance();
    Ref<Appearance> b = new Appearance();
    Ref<Appearance> c = new Appearance();
    Ref<Appearance> d = new Appearance();
    a->setMaterial(shared.get());
    b->setMaterial(shared.get());
    c->setMaterial(shared.get());
    d->setMaterial(other.get());  // equal values, but not shared
    const Object3D* ra[] = {a.get(), b.get()};
    const Object3D* rb[] = {c.get(), d.get()};
    const std::string diff = compareGraphs(ra, rb);
    EXPECT_NE(diff.find("sharing differs"), std::string::npos) << diff;
    // The same object twice on one side and two objects on the other also differ.
    const Object3D* rc[] = {c.get(), c.get()};
    EXPECT_NE(compareGraphs(ra, rc).find("sharing differs"), std::string::npos);
    Ref<Appearance> e = new Appearance();
    e->setMaterial(shared.get());
    const Object3D* re[] = {c.get(), e.get()};
    EXPECT_EQ(compareGraphs(ra, re), "");
}

TEST(RoundTrip, QuantisedAlphaNeedsTheAlphaTolerance) {
    Ref<Group> a = new Group();
    Ref<Group> b = new Group();
    a->setAlphaFactor(0.5f);
    b->setAlphaFactor(128.0f / 255.0f);
    EXPECT_NE(compareGraphs(a.get(), b.get()), "");
    GraphCompareOptions o;
    o.alphaEpsilon = 1.0f / 255.0f;
    EXPECT_EQ(compareGraphs(a.get(), b.get(), o), "");
}

TEST(RoundTrip, ClassDifferenceIsReported) {
    Ref<Group> a = new Group();
    Ref<World> b = new World();
    EXPECT_EQ(compareGraphs(a.get(), b.get()), "roots[0]: class Group != World");
}
