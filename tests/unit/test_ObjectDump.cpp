// tools/m3g/ObjectDump (m3g info reporting): JSON dump of every getter value,
// scene tree, counts by class. The JSON is read back with nlohmann::json,
// which rejects invalid documents (NaN, Infinity, trailing commas, ...).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <m3g/m3g.h>
#include <nlohmann/json.hpp>

#include "ObjectDump.h"

using namespace m3g;
using m3gcli::countByClass;
using m3gcli::dumpJson;
using m3gcli::dumpTree;
using json = nlohmann::json;

namespace {

using Array = json::array_t;
using Floats = std::vector<double>;

/// Parses a whole document (throws on invalid JSON) and also rejects an
/// object with the same key twice, which nlohmann would silently collapse.
json parse(const std::string& text) {
    std::vector<std::set<std::string>> keys;  // the keys of each open object
    auto noDuplicateKeys = [&keys](int, json::parse_event_t event, json& parsed) {
        switch (event) {
        case json::parse_event_t::object_start: keys.emplace_back(); break;
        case json::parse_event_t::object_end: keys.pop_back(); break;
        case json::parse_event_t::key:
            if (!keys.back().insert(parsed.get<std::string>()).second)
                throw std::runtime_error("duplicate key " + parsed.get<std::string>());
            break;
        default: break;
        }
        return true;
    };
    return json::parse(text, noDuplicateKeys);
}

std::string dump(Object3D* root, const m3gcli::DumpOptions& opt = {}) {
    Object3D* roots[] = {root};
    return dumpJson(roots, opt);
}

/// The object with `id` (checks that ids are the array positions).
const json& object(const json& doc, int id) {
    const json& o = doc.at("objects").at(static_cast<std::size_t>(id));
    if (o.at("id").get<int>() != id) throw std::runtime_error("ids are not positions");
    return o;
}

/// The first object of class `cls` with user ID `userID`.
const json& find(const json& doc, const std::string& cls, int userID) {
    for (const json& o : doc.at("objects").get_ref<const Array&>())
        if (o.at("class").get<std::string>() == cls && o.at("userID").get<int>() == userID) return o;
    throw std::runtime_error("no " + cls + " with userID " + std::to_string(userID));
}

/// How many objects of class `cls` the document lists.
int countClass(const json& doc, const std::string& cls) {
    int n = 0;
    for (const json& o : doc.at("objects").get_ref<const Array&>())
        if (o.at("class").get<std::string>() == cls) ++n;
    return n;
}

// ---------------------------------------------------------------------------
// A scene using every common class.

struct Scene {
    Ref<World> world = new World();
    Ref<Camera> camera = new Camera();
    Ref<Light> light = new Light();
    Ref<Background> background = new Background();
    Ref<VertexArray> positions = new VertexArray(4, 3, 2);
    Ref<VertexArray> normals = new VertexArray(4, 3, 1);
    Ref<VertexArray> colors = new VertexArray(4, 4, 1);
    Ref<VertexArray> texCoords = new VertexArray(4, 2, 2);
    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<TriangleStripArray> strip;
    Ref<Material> material = new Material();
    Ref<CompositingMode> compositing = new CompositingMode();
    Ref<PolygonMode> polygon = new PolygonMode();
    Ref<Fog> fog = new Fog();
    Ref<Image2D> image;
    Ref<Texture2D> texture;
    Ref<Appearance> appearance = new Appearance();
    Ref<Mesh> mesh1;
    Ref<Mesh> mesh2;
    Ref<Group> group = new Group();
    Ref<KeyframeSequence> sequence = new KeyframeSequence(2, 3, KeyframeSequence::LINEAR);
    Ref<AnimationController> controller = new AnimationController();
    Ref<AnimationTrack> track;

    Scene() {
        world->setUserID(1);
        camera->setUserID(2);
        camera->setPerspective(60.0f, 1.5f, 0.25f, 100.0f);
        camera->setTranslation(0.0f, 1.0f, 10.0f);
        world->addChild(camera);
        world->setActiveCamera(camera);
        light->setUserID(3);
        light->setMode(Light::OMNI);
        light->setColor(0x123456);
        light->setIntensity(2.5f);
        light->setAttenuation(1.0f, 0.5f, 0.25f);
        world->addChild(light);
        background->setColor(static_cast<int>(0x80FF0000u));
        world->setBackground(background);

        const std::int16_t pos[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, -7};
        positions->set(0, 4, std::span<const std::int16_t>(pos));
        const float bias[] = {1.0f, 2.0f, 3.0f};
        vb->setPositions(positions, 0.5f, bias);
        const std::int8_t nrm[] = {0, 0, 127, 0, 0, 127, 0, 0, 127, 0, 0, -128};
        normals->set(0, 4, std::span<const std::int8_t>(nrm));
        vb->setNormals(normals);
        vb->setColors(colors);
        const float tcBias[] = {0.25f, 0.75f};
        vb->setTexCoords(0, texCoords, 2.0f, tcBias);
        vb->setDefaultColor(static_cast<int>(0xFF102030u));
        const int lengths[] = {4};
        strip = new TriangleStripArray(0, lengths);

        material->setColor(Material::DIFFUSE, static_cast<int>(0x80112233u));
        material->setColor(Material::SPECULAR, 0x00445566);
        material->setShininess(12.5f);
        material->setVertexColorTrackingEnable(true);
        compositing->setBlending(CompositingMode::ALPHA);
        compositing->setAlphaThreshold(0.5f);
        compositing->setDepthOffset(-1.0f, 2.0f);
        polygon->setCulling(PolygonMode::CULL_NONE);
        polygon->setTwoSidedLightingEnable(true);
        fog->setMode(Fog::EXPONENTIAL);
        fog->setDensity(0.125f);
        const std::uint8_t pixels[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
        image = new Image2D(Image2D::RGB, 2, 2, pixels);
        texture = new Texture2D(image);
        texture->setBlending(Texture2D::FUNC_DECAL);
        texture->setWrapping(Texture2D::WRAP_CLAMP, Texture2D::WRAP_REPEAT);
        texture->setBlendColor(0x00ABCDEF);
        appearance->setLayer(-3);
        appearance->setMaterial(material);
        appearance->setCompositingMode(compositing);
        appearance->setPolygonMode(polygon);
        appearance->setFog(fog);
        appearance->setTexture(0, texture);

        // Two meshes sharing the vertex buffer, index buffer and appearance.
        mesh1 = new Mesh(vb, strip, appearance);
        mesh1->setUserID(10);
        mesh2 = new Mesh(vb, strip, appearance);
        mesh2->setUserID(11);
        mesh2->setRenderingEnable(false);
        mesh2->setAlphaFactor(0.5f);
        mesh2->setScope(6);
        group->setUserID(20);
        group->addChild(mesh1);
        group->addChild(mesh2);
        world->addChild(group);

        const float k0[] = {0.0f, 0.0f, 0.0f};
        const float k1[] = {10.0f, 20.0f, 30.0f};
        sequence->setKeyframe(0, 0, k0);
        sequence->setKeyframe(1, 100, k1);
        sequence->setDuration(200);
        sequence->setRepeatMode(KeyframeSequence::LOOP);
        controller->setActiveInterval(0, 1000);
        controller->setSpeed(2.0f, 0);
        track = new AnimationTrack(sequence, AnimationTrack::TRANSLATION);
        track->setController(controller);
        group->addAnimationTrack(track);
    }
};

}  // namespace

// ---------------------------------------------------------------------------

TEST(ObjectDump, JsonIsValidAndListsEveryObjectOnce) {
    Scene s;
    const std::string text = dump(s.world);
    const json doc = parse(text);
    const auto& objects = doc.at("objects").get_ref<const Array&>();
    ASSERT_EQ(doc.at("objectCount").get<int>(), static_cast<int>(objects.size()));
    ASSERT_EQ(doc.at("roots").get_ref<const Array&>().size(), 1u);
    EXPECT_EQ(doc.at("roots").at(0).get<int>(), 0);
    EXPECT_EQ(object(doc, 0).at("class").get<std::string>(), "World");
    // World, Camera, Light, Background, Group, AnimationTrack, KeyframeSequence,
    // AnimationController, 2 Mesh, VertexBuffer, 4 VertexArray, TriangleStripArray,
    // Appearance, CompositingMode, Fog, PolygonMode, Material, Texture2D, Image2D.
    EXPECT_EQ(objects.size(), 23u);
    for (std::size_t i = 0; i < objects.size(); ++i) EXPECT_EQ(objects.at(i).at("id").get<int>(), static_cast<int>(i));
    // Every reference is an existing id.
    for (const json& o : objects)
        for (const json& r : o.at("references").get_ref<const Array&>()) {
            ASSERT_FALSE(r.is_null());
            EXPECT_LT(r.get<int>(), static_cast<int>(objects.size()));
        }
    // Depth-first order of first visit: World's references are its children
    // (camera, light, group), then the active camera (seen) and the background.
    EXPECT_EQ(object(doc, 1).at("class").get<std::string>(), "Camera");
    EXPECT_EQ(object(doc, 2).at("class").get<std::string>(), "Light");
    EXPECT_EQ(object(doc, 3).at("class").get<std::string>(), "Group");
    EXPECT_EQ(object(doc, 4).at("class").get<std::string>(), "AnimationTrack");  // tracks come first
    EXPECT_EQ(object(doc, 5).at("class").get<std::string>(), "KeyframeSequence");
    EXPECT_EQ(object(doc, 6).at("class").get<std::string>(), "AnimationController");
    EXPECT_EQ(object(doc, 7).at("class").get<std::string>(), "Mesh");
    EXPECT_EQ(objects.back().at("class").get<std::string>(), "Background");

    const auto counts = countByClass(std::span<Object3D* const>(std::vector<Object3D*>{s.world.get()}));
    EXPECT_EQ(counts.at("Mesh"), 2);
    EXPECT_EQ(counts.at("VertexArray"), 4);
    EXPECT_EQ(counts.at("Appearance"), 1);
    EXPECT_EQ(counts.at("Material"), 1);
    int total = 0;
    for (const auto& [cls, n] : counts) total += n;
    EXPECT_EQ(total, 23);
}

TEST(ObjectDump, NodeAndCameraAndLightValues) {
    Scene s;
    const json doc = parse(dump(s.world));
    const json& world = find(doc, "World", 1);
    const json& camera = find(doc, "Camera", 2);
    const json& light = find(doc, "Light", 3);
    const json& group = find(doc, "Group", 20);
    EXPECT_EQ(world.at("activeCamera").get<int>(), camera.at("id").get<int>());
    EXPECT_EQ(object(doc, world.at("background").get<int>()).at("class").get<std::string>(), "Background");
    EXPECT_EQ(world.at("childCount").get<int>(), 3);
    EXPECT_EQ(world.at("children").at(2).get<int>(), group.at("id").get<int>());
    EXPECT_TRUE(world.at("parent").is_null());

    EXPECT_EQ(camera.at("projection").get<std::string>(), "PERSPECTIVE");
    EXPECT_EQ(camera.at("projectionParams").get<Floats>(), (Floats{60.0, 1.5, 0.25, 100.0}));
    EXPECT_EQ(camera.at("projectionMatrix").get_ref<const Array&>().size(), 16u);
    EXPECT_EQ(camera.at("translation").get<Floats>(), (Floats{0.0, 1.0, 10.0}));
    EXPECT_EQ(camera.at("scale").get<Floats>(), (Floats{1.0, 1.0, 1.0}));
    EXPECT_EQ(camera.at("compositeTransform").get<Floats>().at(7), 1.0);   // row 1, column 3 = ty
    EXPECT_EQ(camera.at("compositeTransform").get<Floats>().at(11), 10.0);  // tz
    EXPECT_EQ(camera.at("parent").get<int>(), 0);
    EXPECT_TRUE(camera.at("renderingEnabled").get<bool>());
    EXPECT_EQ(camera.at("scope").get<int>(), -1);
    EXPECT_EQ(camera.at("alignment").at("zTarget").get<std::string>(), "NONE");
    EXPECT_TRUE(camera.at("alignment").at("zReference").is_null());

    EXPECT_EQ(light.at("mode").get<std::string>(), "OMNI");
    EXPECT_EQ(light.at("color").get<std::string>(), "0x00123456");
    EXPECT_EQ(light.at("intensity").get<double>(), 2.5);
    EXPECT_EQ(light.at("attenuation").get<Floats>(), (Floats{1.0, 0.5, 0.25}));
    EXPECT_EQ(light.at("spotAngle").get<double>(), 45.0);

    const json& mesh2 = find(doc, "Mesh", 11);
    EXPECT_FALSE(mesh2.at("renderingEnabled").get<bool>());
    EXPECT_TRUE(mesh2.at("pickingEnabled").get<bool>());
    EXPECT_EQ(mesh2.at("alphaFactor").get<double>(), 0.5);
    EXPECT_EQ(mesh2.at("scope").get<int>(), 6);
    EXPECT_EQ(mesh2.at("parent").get<int>(), group.at("id").get<int>());

    const json& bg = object(doc, world.at("background").get<int>());
    EXPECT_EQ(bg.at("color").get<std::string>(), "0x80FF0000");
    EXPECT_EQ(bg.at("imageModeX").get<std::string>(), "BORDER");
    EXPECT_TRUE(bg.at("image").is_null());
    EXPECT_TRUE(bg.at("depthClearEnabled").get<bool>());
}

TEST(ObjectDump, MeshComponentsAreSharedAndDumpedOnce) {
    Scene s;
    const std::string text = dump(s.world);
    const json doc = parse(text);
    const json& m1 = find(doc, "Mesh", 10);
    const json& m2 = find(doc, "Mesh", 11);
    EXPECT_EQ(m1.at("vertexBuffer").get<int>(), m2.at("vertexBuffer").get<int>());
    EXPECT_EQ(m1.at("submeshCount").get<int>(), 1);
    EXPECT_EQ(m1.at("submeshes").at(0).at("appearance").get<int>(), m2.at("submeshes").at(0).at("appearance").get<int>());
    EXPECT_EQ(m1.at("submeshes").at(0).at("indexBuffer").get<int>(), m2.at("submeshes").at(0).at("indexBuffer").get<int>());
    EXPECT_EQ(countClass(doc, "Appearance"), 1);
    EXPECT_EQ(countClass(doc, "VertexBuffer"), 1);

    const json& vb = object(doc, m1.at("vertexBuffer").get<int>());
    EXPECT_EQ(vb.at("vertexCount").get<int>(), 4);
    EXPECT_EQ(vb.at("positions").at("scale").get<double>(), 0.5);
    EXPECT_EQ(vb.at("positions").at("bias").get<Floats>(), (Floats{1.0, 2.0, 3.0}));
    EXPECT_EQ(vb.at("defaultColor").get<std::string>(), "0xFF102030");
    EXPECT_EQ(vb.at("texCoords").at(0).at("scale").get<double>(), 2.0);
    EXPECT_EQ(vb.at("texCoords").at(0).at("bias").get<Floats>(), (Floats{0.25, 0.75}));
    EXPECT_TRUE(vb.at("texCoords").at(1).is_null());

    const json& pos = object(doc, vb.at("positions").at("array").get<int>());
    EXPECT_EQ(pos.at("class").get<std::string>(), "VertexArray");
    EXPECT_EQ(pos.at("componentCount").get<int>(), 3);
    EXPECT_EQ(pos.at("componentType").get<int>(), 2);
    EXPECT_EQ(pos.at("values").at(3).get<Floats>(), (Floats{1.0, 1.0, -7.0}));
    EXPECT_FALSE(pos.at("truncated").get<bool>());
    const json& nrm = object(doc, vb.at("normals").get<int>());
    EXPECT_EQ(nrm.at("values").at(3).get<Floats>(), (Floats{0.0, 0.0, -128.0}));

    const json& ib = object(doc, m1.at("submeshes").at(0).at("indexBuffer").get<int>());
    EXPECT_EQ(ib.at("class").get<std::string>(), "TriangleStripArray");
    EXPECT_EQ(ib.at("indexCount").get<int>(), 6);
    EXPECT_EQ(ib.at("indices").get<Floats>(), (Floats{0, 1, 2, 1, 3, 2}));
    EXPECT_EQ(ib.at("stripLengths").get<Floats>(), (Floats{4}));

    const json& ap = object(doc, m1.at("submeshes").at(0).at("appearance").get<int>());
    EXPECT_EQ(ap.at("layer").get<int>(), -3);
    const json& mat = object(doc, ap.at("material").get<int>());
    EXPECT_EQ(mat.at("diffuseColor").get<std::string>(), "0x80112233");
    EXPECT_EQ(mat.at("ambientColor").get<std::string>(), "0x00333333");
    EXPECT_EQ(mat.at("specularColor").get<std::string>(), "0x00445566");
    EXPECT_EQ(mat.at("emissiveColor").get<std::string>(), "0x00000000");
    EXPECT_EQ(mat.at("shininess").get<double>(), 12.5);
    EXPECT_TRUE(mat.at("vertexColorTrackingEnabled").get<bool>());
    const json& cm = object(doc, ap.at("compositingMode").get<int>());
    EXPECT_EQ(cm.at("blending").get<std::string>(), "ALPHA");
    EXPECT_EQ(cm.at("alphaThreshold").get<double>(), 0.5);
    EXPECT_EQ(cm.at("depthOffsetFactor").get<double>(), -1.0);
    EXPECT_EQ(cm.at("depthOffsetUnits").get<double>(), 2.0);
    const json& pm = object(doc, ap.at("polygonMode").get<int>());
    EXPECT_EQ(pm.at("culling").get<std::string>(), "CULL_NONE");
    EXPECT_EQ(pm.at("shading").get<std::string>(), "SHADE_SMOOTH");
    EXPECT_EQ(pm.at("winding").get<std::string>(), "WINDING_CCW");
    EXPECT_TRUE(pm.at("twoSidedLightingEnabled").get<bool>());
    const json& fog = object(doc, ap.at("fog").get<int>());
    EXPECT_EQ(fog.at("mode").get<std::string>(), "EXPONENTIAL");
    EXPECT_EQ(fog.at("density").get<double>(), 0.125);
    const json& tex = object(doc, ap.at("textures").at(0).get<int>());
    EXPECT_EQ(tex.at("blending").get<std::string>(), "FUNC_DECAL");
    EXPECT_EQ(tex.at("wrappingS").get<std::string>(), "WRAP_CLAMP");
    EXPECT_EQ(tex.at("wrappingT").get<std::string>(), "WRAP_REPEAT");
    EXPECT_EQ(tex.at("levelFilter").get<std::string>(), "FILTER_BASE_LEVEL");
    EXPECT_EQ(tex.at("blendColor").get<std::string>(), "0x00ABCDEF");
    EXPECT_EQ(tex.at("translation").get<Floats>(), (Floats{0, 0, 0}));
    const json& img = object(doc, tex.at("image").get<int>());
    EXPECT_EQ(img.at("format").get<std::string>(), "RGB");
    EXPECT_EQ(img.at("width").get<int>(), 2);
    EXPECT_EQ(img.at("height").get<int>(), 2);
    EXPECT_FALSE(img.at("mutable").get<bool>());
    EXPECT_EQ(img.at("pixelBytes").get<int>(), 12);
    EXPECT_EQ(img.at("pixelChecksum").get<std::string>().size(), 10u);
    EXPECT_TRUE(ap.at("textures").at(1).is_null());
}

TEST(ObjectDump, AnimationValuesAndAnimatedState) {
    Scene s;
    s.world->animate(25);  // controller speed 2: sequence time 50, halfway
    m3gcli::DumpOptions opt;
    opt.worldTime = 25;
    const json doc = parse(dump(s.world, opt));
    const json& group = find(doc, "Group", 20);
    ASSERT_EQ(group.at("animationTracks").get_ref<const Array&>().size(), 1u);
    const json& track = object(doc, group.at("animationTracks").at(0).get<int>());
    EXPECT_EQ(track.at("class").get<std::string>(), "AnimationTrack");
    EXPECT_EQ(track.at("targetProperty").get<std::string>(), "TRANSLATION");
    const json& seq = object(doc, track.at("keyframeSequence").get<int>());
    EXPECT_EQ(seq.at("keyframeCount").get<int>(), 2);
    EXPECT_EQ(seq.at("componentCount").get<int>(), 3);
    EXPECT_EQ(seq.at("interpolation").get<std::string>(), "LINEAR");
    EXPECT_EQ(seq.at("repeatMode").get<std::string>(), "LOOP");
    EXPECT_EQ(seq.at("duration").get<int>(), 200);
    EXPECT_EQ(seq.at("validRange").get<Floats>(), (Floats{0, 1}));
    EXPECT_EQ(seq.at("keyframeTimes").get<Floats>(), (Floats{0, 100}));
    EXPECT_EQ(seq.at("keyframeValues").at(1).get<Floats>(), (Floats{10, 20, 30}));
    const json& ctl = object(doc, track.at("controller").get<int>());
    EXPECT_EQ(ctl.at("activeInterval").get<Floats>(), (Floats{0, 1000}));
    EXPECT_EQ(ctl.at("speed").get<double>(), 2.0);
    EXPECT_EQ(ctl.at("weight").get<double>(), 1.0);
    EXPECT_EQ(ctl.at("position").get<double>(), 50.0);
    EXPECT_TRUE(ctl.at("active").get<bool>());
    EXPECT_EQ(group.at("translation").get<Floats>(), (Floats{5, 10, 15}));

    // Without a world time the controller has no position/active fields.
    const json plain = parse(dump(s.world));
    EXPECT_FALSE(object(plain, track.at("controller").get<int>()).contains("position"));
}

TEST(ObjectDump, SkinnedMeshBonesAndSkeleton) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    vb->setPositions(new VertexArray(8, 3, 2), 1.0f, {});
    const int lengths[] = {8};
    Ref<TriangleStripArray> ib = new TriangleStripArray(0, lengths);
    Ref<Group> skeleton = new Group();
    Ref<Group> upper = new Group();
    Ref<Group> lower = new Group();
    upper->setUserID(100);
    lower->setUserID(101);
    skeleton->addChild(upper);
    upper->addChild(lower);
    lower->setTranslation(0.0f, 2.0f, 0.0f);
    Ref<SkinnedMesh> mesh = new SkinnedMesh(vb, ib, nullptr, skeleton);
    mesh->addTransform(lower, 1, 0, 3);
    mesh->addTransform(upper, 1, 2, 6);

    const json doc = parse(dump(mesh));
    const json& m = object(doc, 0);
    EXPECT_EQ(m.at("class").get<std::string>(), "SkinnedMesh");
    EXPECT_EQ(object(doc, m.at("skeleton").get<int>()).at("class").get<std::string>(), "Group");
    EXPECT_TRUE(m.at("submeshes").at(0).at("appearance").is_null());
    ASSERT_EQ(m.at("bones").get_ref<const Array&>().size(), 2u);
    const json& b0 = m.at("bones").at(0);  // bone index order: lower was added first
    EXPECT_EQ(object(doc, b0.at("bone").get<int>()).at("userID").get<int>(), 101);
    EXPECT_EQ(b0.at("vertexCount").get<int>(), 3);
    EXPECT_EQ(b0.at("atRestTransform").get<Floats>().at(7), -2.0);  // mesh -> bone space: ty = -2
    const json& b1 = m.at("bones").at(1);
    EXPECT_EQ(object(doc, b1.at("bone").get<int>()).at("userID").get<int>(), 100);
    EXPECT_EQ(b1.at("vertexCount").get<int>(), 6);
    EXPECT_EQ(object(doc, m.at("skeleton").get<int>()).at("parent").get<int>(), 0);
    EXPECT_EQ(doc.at("objectCount").get<int>(), 7);  // mesh, vb, array, strips, skeleton, upper, lower
    // v0, v1: lower only; v2: both (equal weights); v3..v7: upper only. The
    // five upper-only vertices share their slots: one run of the mesh's own
    // order (at least kMinRun = 4), the other three loose in it.
    const json& layout = m.at("influenceLayout");
    EXPECT_EQ(layout.at("verticesByInfluenceCount").get<std::vector<int>>(), (std::vector<int>{0, 7, 1, 0, 0}));
    EXPECT_EQ(layout.at("runs").get<int>(), 1);
    EXPECT_EQ(layout.at("runVertices").get<int>(), 5);
    EXPECT_EQ(layout.at("longestRun").get<int>(), 5);
    EXPECT_EQ(layout.at("looseVertices").get<int>(), 3);
    // The compact space, where MeshDeformer skins all eight: v3..v7 one run;
    // v0, v1 (lower) and v2 (both), too few to share a run.
    EXPECT_EQ(layout.at("compactRuns").get<int>(), 1);
    EXPECT_EQ(layout.at("compactRunVertices").get<int>(), 5);
    EXPECT_EQ(layout.at("compactBoneRuns").get<int>(), 0);
    EXPECT_EQ(layout.at("compactBoneRunVertices").get<int>(), 0);
    EXPECT_EQ(layout.at("compactLooseVertices").get<int>(), 3);
    EXPECT_FALSE(layout.at("rigidBinding").get<bool>());  // two bones
    // Which kernels the split is for, and their run block: 16 lanes with
    // AVX-512, 8 with AVX2, none where bone runs are vertex lists.
    const std::string kernels = layout.at("kernels").get<std::string>();
    const int block = kernels == "avx512" ? 16 : kernels == "avx2" ? 8 : 0;
    EXPECT_TRUE(kernels == "avx512" || kernels == "avx2" || kernels == "sse2" || kernels == "scalar") << kernels;
    EXPECT_EQ(layout.at("runBlock").get<int>(), block) << kernels;

    // Every vertex on `upper` alone (twice added: one slot, weight 1): a
    // rigid binding.
    Ref<Group> bone = new Group();
    Ref<SkinnedMesh> rigid = new SkinnedMesh(vb, ib, nullptr, bone);
    rigid->addTransform(bone, 1, 0, 5);
    rigid->addTransform(bone, 2, 4, 4);
    EXPECT_TRUE(object(parse(dump(rigid)), 0).at("influenceLayout").at("rigidBinding").get<bool>());
}

TEST(ObjectDump, BonesAndAlignmentTargetsOutsideReferencesAreIncluded) {
    // An alignment reference to a node that nothing else references.
    Ref<Group> root = new Group();
    Ref<Group> child = new Group();
    Ref<Camera> outside = new Camera();
    outside->setUserID(77);
    root->addChild(child);
    child->setAlignment(outside, Node::ORIGIN, nullptr, Node::NONE);
    const json doc = parse(dump(root));
    ASSERT_EQ(doc.at("objectCount").get<int>(), 3);
    const json& c = object(doc, 1);
    EXPECT_EQ(c.at("alignment").at("zTarget").get<std::string>(), "ORIGIN");
    EXPECT_EQ(c.at("alignment").at("yTarget").get<std::string>(), "NONE");
    EXPECT_EQ(object(doc, c.at("alignment").at("zReference").get<int>()).at("userID").get<int>(), 77);
    EXPECT_TRUE(c.at("references").get_ref<const Array&>().empty());  // getReferences does not list it
}

TEST(ObjectDump, UserParametersAsHex) {
    Ref<Group> g = new Group();
    auto params = std::make_shared<UserParameters>();
    (*params)[7] = {0x00, 0xAB, 0x10};
    (*params)[-2] = {};
    g->setUserObject(std::shared_ptr<const UserParameters>(params));
    Ref<Group> other = new Group();
    other->setUserObject(42);
    g->addChild(other);
    const json doc = parse(dump(g));
    EXPECT_EQ(object(doc, 0).at("userObject").get<std::string>(), "UserParameters");
    EXPECT_EQ(object(doc, 0).at("userParameters").at("7").get<std::string>(), "00ab10");
    EXPECT_EQ(object(doc, 0).at("userParameters").at("-2").get<std::string>(), "");
    EXPECT_EQ(object(doc, 1).at("userObject").get<std::string>(), "other");
    EXPECT_TRUE(object(doc, 1).at("userParameters").is_null());
}

TEST(ObjectDump, NonFiniteFloatsAreNull) {
    Ref<Group> g = new Group();
    Ref<Light> light = new Light();
    light->setIntensity(std::numeric_limits<float>::infinity());
    Ref<Fog> fog = new Fog();
    fog->setLinear(std::numeric_limits<float>::quiet_NaN(), -std::numeric_limits<float>::infinity());
    Ref<Appearance> ap = new Appearance();
    ap->setFog(fog);
    Ref<Sprite3D> sprite = new Sprite3D(true, new Image2D(Image2D::RGBA, 4, 2), ap);
    sprite->setCrop(1, 0, -2, 2);
    g->addChild(light);
    g->addChild(sprite);
    const std::string text = dump(g);
    EXPECT_EQ(text.find("nan"), std::string::npos);
    EXPECT_EQ(text.find("inf"), std::string::npos);
    const json doc = parse(text);
    EXPECT_TRUE(find(doc, "Light", 0).at("intensity").is_null());
    const json& f = find(doc, "Fog", 0);
    EXPECT_TRUE(f.at("nearDistance").is_null());
    EXPECT_TRUE(f.at("farDistance").is_null());
    const json& sp = find(doc, "Sprite3D", 0);
    EXPECT_TRUE(sp.at("scaled").get<bool>());
    EXPECT_EQ(sp.at("crop").get<Floats>(), (Floats{1, 0, -2, 2}));
    const json& img = object(doc, sp.at("image").get<int>());
    EXPECT_EQ(img.at("format").get<std::string>(), "RGBA");
    EXPECT_TRUE(img.at("mutable").get<bool>());
}

TEST(ObjectDump, LargeArraysAreTruncated) {
    Ref<VertexArray> big = new VertexArray(100, 2, 1);
    std::vector<std::int8_t> v(200);
    for (int i = 0; i < 200; ++i) v[static_cast<std::size_t>(i)] = static_cast<std::int8_t>(i - 100);
    big->set(0, 100, std::span<const std::int8_t>(v));
    Ref<KeyframeSequence> seq = new KeyframeSequence(70, 1, KeyframeSequence::STEP);
    std::vector<int> lengths(80, 3);
    Ref<TriangleStripArray> strips = new TriangleStripArray(0, lengths);
    Object3D* roots[] = {big.get(), seq.get(), strips.get()};
    const json doc = parse(dumpJson(roots));
    EXPECT_EQ(doc.at("roots").get<Floats>(), (Floats{0, 1, 2}));
    const json& a = object(doc, 0);
    EXPECT_EQ(a.at("vertexCount").get<int>(), 100);
    EXPECT_EQ(a.at("values").get_ref<const Array&>().size(), 64u);
    EXPECT_EQ(a.at("values").at(63).get<Floats>(), (Floats{26, 27}));
    EXPECT_TRUE(a.at("truncated").get<bool>());
    const json& k = object(doc, 1);
    EXPECT_EQ(k.at("keyframeTimes").get_ref<const Array&>().size(), 64u);
    EXPECT_EQ(k.at("interpolation").get<std::string>(), "STEP");
    EXPECT_TRUE(k.at("truncated").get<bool>());
    const json& t = object(doc, 2);
    EXPECT_EQ(t.at("indexCount").get<int>(), 240);
    EXPECT_EQ(t.at("indices").get_ref<const Array&>().size(), 192u);
    EXPECT_TRUE(t.at("truncated").get<bool>());
    EXPECT_EQ(t.at("stripCount").get<int>(), 80);

    m3gcli::DumpOptions opt;
    opt.maxVertices = 1000;
    const json full = parse(dumpJson(roots, opt));
    EXPECT_FALSE(object(full, 0).at("truncated").get<bool>());
    EXPECT_EQ(object(full, 0).at("values").get_ref<const Array&>().size(), 100u);
}

TEST(ObjectDump, DeterministicAndEqualForDuplicates) {
    Scene s;
    const std::string a = dump(s.world);
    EXPECT_EQ(a, dump(s.world));
    // A duplicate has the same structure and values (components shared, nodes copied).
    Ref<Object3D> copy = s.world->duplicate();
    EXPECT_EQ(a, dump(copy));
    // 2-space indentation, one member per line, a final newline.
    EXPECT_EQ(a.substr(0, 20), "{\n  \"objectCount\": 2");
    EXPECT_EQ(a.back(), '\n');
    // Members in the documented order (ordered_json keeps the document's order).
    const nlohmann::ordered_json ordered = nlohmann::ordered_json::parse(a);
    std::vector<std::string> top;
    for (const auto& [key, value] : ordered.items()) top.push_back(key);
    EXPECT_EQ(top, (std::vector<std::string>{"objectCount", "roots", "objects"}));
    std::vector<std::string> first;
    for (const auto& [key, value] : ordered.at("objects").at(0).items()) first.push_back(key);
    ASSERT_GE(first.size(), 7u);
    EXPECT_EQ(std::vector<std::string>(first.begin(), first.begin() + 7),
              (std::vector<std::string>{"id", "class", "userID", "userObject", "userParameters", "animationTracks",
                                        "references"}));
}

TEST(ObjectDump, FloatsReadBackAsTheSameFloat) {
    Ref<Group> g = new Group();
    // Translation (any sign), then attenuation (non-negative).
    const float values[] = {0.1f, -2.7182817f, 1e-7f, std::numeric_limits<float>::max(),
                            std::numeric_limits<float>::denorm_min(), 1.0f / 3.0f};
    g->setTranslation(values[0], values[1], values[2]);
    Ref<Light> light = new Light();
    light->setAttenuation(values[3], values[4], values[5]);
    g->addChild(light);
    const std::string text = dump(g);
    const json doc = parse(text);
    const Floats t = object(doc, 0).at("translation").get<Floats>();
    const Floats att = object(doc, 1).at("attenuation").get<Floats>();
    ASSERT_EQ(t.size(), 3u);
    ASSERT_EQ(att.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(static_cast<float>(t[i]), values[i]) << i;
        EXPECT_EQ(static_cast<float>(att[i]), values[i + 3]) << i;
    }
    // Shortest float form, not the float's full double expansion.
    EXPECT_EQ(text.find("0.100000001"), std::string::npos);
}

TEST(ObjectDump, EmptyAndNullRoots) {
    Object3D* roots[] = {nullptr};
    const json doc = parse(dumpJson(roots));
    EXPECT_EQ(doc.at("objectCount").get<int>(), 0);
    EXPECT_TRUE(doc.at("objects").get_ref<const Array&>().empty());
    EXPECT_EQ(dumpTree(roots), "");
    EXPECT_TRUE(countByClass(roots).empty());
}

TEST(ObjectDump, MorphingMeshWeightsAndTargets) {
    Ref<VertexBuffer> base = new VertexBuffer();
    base->setPositions(new VertexArray(3, 3, 1), 1.0f, {});
    std::vector<Ref<VertexBuffer>> targets = {new VertexBuffer(), new VertexBuffer()};
    const int lengths[] = {3};
    Ref<MorphingMesh> m = new MorphingMesh(base, targets, new TriangleStripArray(0, lengths), nullptr);
    const float w[] = {0.25f, -1.5f};
    m->setWeights(w);
    const json doc = parse(dump(m));
    const json& o = object(doc, 0);
    EXPECT_EQ(o.at("weights").get<Floats>(), (Floats{0.25, -1.5}));
    ASSERT_EQ(o.at("morphTargets").get_ref<const Array&>().size(), 2u);
    EXPECT_EQ(object(doc, o.at("morphTargets").at(1).get<int>()).at("class").get<std::string>(), "VertexBuffer");
    EXPECT_EQ(object(doc, o.at("morphTargets").at(1).get<int>()).at("vertexCount").get<int>(), 0);
}

TEST(ObjectDump, GenericCameraAndZeroDepthRange) {
    Ref<Group> g = new Group();
    Ref<Camera> generic = new Camera();
    Ref<Camera> flat = new Camera();
    flat->setParallel(2.0f, 1.0f, 5.0f, 5.0f);  // near == far: no matrix
    g->addChild(generic);
    g->addChild(flat);
    const json doc = parse(dump(g));
    EXPECT_EQ(object(doc, 1).at("projection").get<std::string>(), "GENERIC");
    EXPECT_TRUE(object(doc, 1).at("projectionParams").is_null());
    EXPECT_EQ(object(doc, 1).at("projectionMatrix").get<Floats>().at(0), 1.0);
    EXPECT_EQ(object(doc, 2).at("projection").get<std::string>(), "PARALLEL");
    EXPECT_EQ(object(doc, 2).at("projectionParams").get<Floats>(), (Floats{2, 1, 5, 5}));
    EXPECT_TRUE(object(doc, 2).at("projectionMatrix").is_null());
}

TEST(ObjectDump, TreeLines) {
    Scene s;
    Object3D* roots[] = {s.world.get(), s.material.get()};
    const std::string tree = dumpTree(roots);
    std::vector<std::string> lines;
    for (std::size_t p = 0; p < tree.size();) {
        const std::size_t e = tree.find('\n', p);
        lines.push_back(tree.substr(p, e - p));
        p = e + 1;
    }
    ASSERT_EQ(lines.size(), 7u) << tree;
    EXPECT_EQ(lines[0], "World #0 userID=1 camera=#1 background=#22 children=3");
    EXPECT_EQ(lines[1], "  Camera #1 userID=2 PERSPECTIVE fovy=60 aspect=1.5 near=0.25 far=100");
    EXPECT_EQ(lines[2], "  Light #2 userID=3 OMNI color=0x00123456 intensity=2.5");
    EXPECT_EQ(lines[3], "  Group #3 userID=20 children=2 tracks=1");
    EXPECT_EQ(lines[4], "    Mesh #7 userID=10 submeshes=1 vertices=4 triangles=2");
    EXPECT_EQ(lines[5], "    Mesh #21 userID=11 submeshes=1 vertices=4 triangles=2 rendering=off alpha=0.5 scope=6");
    EXPECT_EQ(lines[6].substr(0, 10), "Material #");

    // A skinned mesh shows its skeleton, and the bones are marked.
    Ref<VertexBuffer> vb = new VertexBuffer();
    vb->setPositions(new VertexArray(3, 3, 2), 1.0f, {});
    const int lengths[] = {3};
    Ref<Group> skeleton = new Group();
    Ref<Group> bone = new Group();
    skeleton->addChild(bone);
    Ref<SkinnedMesh> sm = new SkinnedMesh(vb, new TriangleStripArray(0, lengths), nullptr, skeleton);
    sm->addTransform(bone, 1, 0, 3);
    Object3D* r2[] = {sm.get()};
    EXPECT_EQ(dumpTree(r2),
              "SkinnedMesh #0 submeshes=1 vertices=3 triangles=1 bones=1 rigid\n"
              "  (skeleton) Group #4 children=1\n"
              "    Group #5 children=0 bone\n");
}

// One numbering for `m3g info` and the viewer's panels: a sub-object dumped
// with the file's roots as numbering roots keeps the ids of the whole dump,
// and an object outside the numbering follows its last id.
TEST(ObjectDump, NumberingRootsKeepTheFilesIds) {
    Ref<World> world(new World());
    Ref<Group> group(new Group());
    Ref<Camera> camera(new Camera());
    Ref<Light> light(new Light());
    group->addChild(camera.get());
    group->addChild(light.get());
    world->addChild(group.get());
    world->setActiveCamera(camera.get());
    Object3D* roots[] = {world.get()};
    const json whole = json::parse(dumpJson(roots));
    const m3gcli::ObjectNumbering numbering(roots);
    for (const auto& o : whole["objects"]) {
        const int id = o["id"];
        EXPECT_GE(id, 0);
    }
    EXPECT_EQ(numbering.id(world.get()), 0);
    const int groupId = numbering.id(group.get()), lightId = numbering.id(light.get());
    EXPECT_GT(groupId, 0);
    EXPECT_EQ(numbering.label(*light), "Light #" + std::to_string(lightId));

    m3gcli::DumpOptions options;
    options.numberingRoots = {world.get()};
    Object3D* sub[] = {group.get()};
    const json part = json::parse(dumpJson(sub, options));
    EXPECT_EQ(part["roots"][0], groupId);
    EXPECT_EQ(part["objects"][0]["id"], groupId);
    bool sawLight = false;
    for (const auto& r : part["objects"][0]["children"]) sawLight = sawLight || r == lightId;
    EXPECT_TRUE(sawLight) << part["objects"][0].dump();

    // Outside the numbering (a viewer's own light): after the last id, no "#" label.
    Ref<Light> own(new Light());
    EXPECT_EQ(numbering.id(own.get()), -1);
    EXPECT_EQ(numbering.label(*own), "Light");
    Object3D* ownRoot[] = {own.get()};
    const json outside = json::parse(dumpJson(ownRoot, options));
    EXPECT_EQ(outside["objects"][0]["id"], static_cast<int>(whole["objects"].size()));
}

// `m3g info --json`: the load's header, external references and warnings
// come first when the dump is given the load.
TEST(ObjectDump, JsonStartsWithTheLoadsHeaderReferencesAndWarnings) {
    Ref<Group> group(new Group());
    LoadResult load;
    load.versionMajor = 1;
    load.authoringField = "hand made";
    load.totalFileSize = 123;
    load.approximateContentSize = 120;
    load.hasExternalReferences = true;
    load.externalReferences.push_back({"/a/main.m3g", "tex.png", "/a/tex.png", false});
    load.warnings.push_back("external reference 'tex.png': file '/a/tex.png' not found; skipped");
    m3gcli::DumpOptions options;
    options.load = &load;
    Object3D* roots[] = {group.get()};
    const json doc = json::parse(dumpJson(roots, options));
    // First in the document, before the objects (member order kept).
    EXPECT_EQ(nlohmann::ordered_json::parse(dumpJson(roots, options)).begin().key(), "file");
    EXPECT_EQ(doc["file"]["version"], "1.0");
    EXPECT_EQ(doc["file"]["authoringField"], "hand made");
    EXPECT_EQ(doc["file"]["totalFileSize"], 123);
    EXPECT_EQ(doc["file"]["hasExternalReferences"], true);
    ASSERT_EQ(doc["externalReferences"].size(), 1u);
    EXPECT_EQ(doc["externalReferences"][0]["uri"], "tex.png");
    EXPECT_EQ(doc["externalReferences"][0]["loaded"], false);
    ASSERT_EQ(doc["warnings"].size(), 1u);
    EXPECT_EQ(doc["objectCount"], 1);
    // Without the load, the document is the objects alone.
    EXPECT_FALSE(json::parse(dumpJson(roots)).contains("file"));
}
