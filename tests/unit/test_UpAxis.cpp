// The scene's up axis (tools/m3g/UpAxis.h) and the views that turn about it:
// render --turntable's CameraOrbit, the viewer's OrbitCamera, and the glTF
// export's upright root node. Expected values are worked by hand from the
// rotations (a camera turned 90 degrees about +X has its +Y along +Z).
#include <gtest/gtest.h>

#include <cmath>

#include <m3g/m3g.h>

#include "GltfExport.h"
#include "OrbitCamera.h"
#include "SceneRender.h"
#include "UpAxis.h"

using namespace m3g;
using m3gcli::Axis;

namespace {

std::array<float, 3> apply(const Transform& t, std::array<float, 4> v) {
    t.transform(std::span<float>(v.data(), 4));
    return {v[0], v[1], v[2]};
}

Ref<World> worldWithCamera(float angle, float ax, float ay, float az) {
    Ref<World> world(new World());
    Ref<Camera> camera(new Camera());
    camera->setOrientation(angle, ax, ay, az);
    world->addChild(camera.get());
    world->setActiveCamera(camera.get());
    return world;
}

}  // namespace

TEST(UpAxis, ActiveCameraUpSnapsToTheNearestAxis) {
    EXPECT_EQ(m3gcli::sceneUp(*worldWithCamera(0, 0, 0, 1)), (Axis{0, 1, 0}));
    EXPECT_EQ(m3gcli::sceneUp(*worldWithCamera(90, 1, 0, 0)), (Axis{0, 0, 1}));   // 3ds Max / Blender style
    EXPECT_EQ(m3gcli::sceneUp(*worldWithCamera(80, 1, 0, 0)), (Axis{0, 0, 1}));   // tilted: still nearest +Z
    EXPECT_EQ(m3gcli::sceneUp(*worldWithCamera(-90, 0, 0, 1)), (Axis{1, 0, 0}));  // +Y turned to +X
    EXPECT_EQ(m3gcli::sceneUp(*worldWithCamera(180, 1, 0, 0)), (Axis{0, -1, 0}));
    Ref<World> none(new World());
    EXPECT_EQ(m3gcli::sceneUp(*none), (Axis{0, 1, 0}));
}

TEST(UpAxis, ParentTransformsCount) {
    Ref<World> world(new World());
    Ref<Group> rig(new Group());
    rig->setOrientation(90, 1, 0, 0);
    Ref<Camera> camera(new Camera());
    rig->addChild(camera.get());
    world->addChild(rig.get());
    world->setActiveCamera(camera.get());
    EXPECT_EQ(m3gcli::sceneUp(*world), (Axis{0, 0, 1}));
}

TEST(UpAxis, ParsesAndNamesAxes) {
    EXPECT_EQ(m3gcli::parseAxis("z"), (Axis{0, 0, 1}));
    EXPECT_EQ(m3gcli::parseAxis("+Y"), (Axis{0, 1, 0}));
    EXPECT_EQ(m3gcli::parseAxis("-x"), (Axis{-1, 0, 0}));
    EXPECT_FALSE(m3gcli::parseAxis("w").has_value());
    EXPECT_FALSE(m3gcli::parseAxis("up").has_value());
    EXPECT_FALSE(m3gcli::parseAxis("").has_value());
    EXPECT_EQ(m3gcli::axisName({0, 0, -1}), "-Z");
    EXPECT_EQ(m3gcli::axisName({1, 0, 0}), "+X");
}

TEST(UpAxis, UpFromYTakesPlusYToEachAxis) {
    for (const Axis& up : {Axis{0, 1, 0}, Axis{0, -1, 0}, Axis{1, 0, 0}, Axis{-1, 0, 0}, Axis{0, 0, 1}, Axis{0, 0, -1}}) {
        const auto y = apply(m3gcli::upFromY(up), {0, 1, 0, 0});
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(y[k], up[k], 1e-6f) << m3gcli::axisName(up) << " component " << k;
    }
}

TEST(UpAxis, OrbitCameraTurnsAboutTheSceneUp) {
    m3gview::OrbitCamera c;
    c.up = {0, 0, 1};
    c.frame({1, 2, 3}, 1.0f, 45.0f);
    // Pitch 20 degrees above the horizon: the eye is d*sin(20) above the target along +Z.
    const auto eye = c.eye();
    EXPECT_NEAR(eye[2] - 3.0f, c.distance * std::sin(20.0f * 3.14159265f / 180.0f), 1e-4f);
    // The view's up leans towards +Z, never sideways.
    const auto viewUp = apply(c.transform(), {0, 1, 0, 0});
    EXPECT_GT(viewUp[2], 0.9f);
    // A horizontal drag turns about Z: the height stays, the horizontal radius too.
    c.orbit(100.0f, 0.0f);
    const auto turned = c.eye();
    EXPECT_NEAR(turned[2], eye[2], 1e-4f);
    EXPECT_NEAR(std::hypot(turned[0] - 1, turned[1] - 2), std::hypot(eye[0] - 1, eye[1] - 2), 1e-4f);
    EXPECT_GT(std::hypot(turned[0] - eye[0], turned[1] - eye[1]), 0.5f);
}

TEST(UpAxis, TurntableOrbitsAboutTheActiveCamerasUp) {
    Ref<World> world = worldWithCamera(90, 1, 0, 0);  // up +Z
    Ref<Camera> camera = world->getActiveCamera();
    camera->setTranslation(0, -5, 1);
    m3gcli::CameraOrbit orbit(*camera, *world, {0, 0, 0});
    orbit.setAngle(90.0f);
    Transform t;
    ASSERT_TRUE(camera->getTransformTo(world.get(), &t));
    // 90 degrees about +Z takes (0, -5, 1) to (5, 0, 1); the camera's up stays +Z.
    EXPECT_NEAR(t.at(0, 3), 5.0f, 1e-4f);
    EXPECT_NEAR(t.at(1, 3), 0.0f, 1e-4f);
    EXPECT_NEAR(t.at(2, 3), 1.0f, 1e-4f);
    EXPECT_NEAR(t.at(2, 1), 1.0f, 1e-4f);
}

TEST(UpAxis, ExportTurnsAZUpSceneUpright) {
    Ref<World> world = worldWithCamera(90, 1, 0, 0);
    Ref<Group> content(new Group());
    world->addChild(content.get());
    Object3D* roots[] = {world.get()};
    const auto result = m3gcli::gltf::exportScene(roots);
    const auto& doc = result.document.json();
    const auto& sceneNodes = doc["scenes"][0]["nodes"];
    ASSERT_EQ(sceneNodes.size(), 1u);
    const auto& upright = doc["nodes"][sceneNodes[0].get<int>()];
    const double s = std::sqrt(0.5);
    ASSERT_TRUE(upright.contains("rotation"));
    EXPECT_NEAR(upright["rotation"][0].get<double>(), -s, 1e-9);  // -90 degrees about X: +Z to +Y
    EXPECT_NEAR(upright["rotation"][3].get<double>(), s, 1e-9);
    EXPECT_EQ(upright["children"].size(), 2u);  // the camera and the group
    bool noted = false;
    for (const auto& w : result.warnings) noted = noted || w.find("up axis is +Z") != std::string::npos;
    EXPECT_TRUE(noted);
    // A +Y scene keeps its nodes at the root; an explicit --up wins over the camera.
    const auto yUp = m3gcli::gltf::exportScene(roots, {Axis{0, 1, 0}});
    EXPECT_EQ(yUp.document.json()["scenes"][0]["nodes"].size(), 2u);
}
