// Graphics3D::clear and render (JSR-184 1.1, Graphics3D) end to end on
// scene's recording NullBackend: which calls reach a back end, with which
// draws, order and uniforms; the exceptions, thrown before anything is
// handed over; resource versions (a back end re-reads exactly what
// changed); released ids; deformed meshes on the CPU and for GPU kernels.
// The argument and state checks moved here from the device tests
// (tests/vk/test_Misuse.cpp, test_SceneOrder.cpp's Graphics3DRenderExceptions,
// test_RenderBasics.cpp's WorldOwnTransformCancelsOut): none of them needs
// a device.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <string>
#include <vector>

#include "FrameTestKit.h"

using namespace m3g;
using namespace m3g::frame;
using m3g::detail::NullBackend;
using Kind = NullBackend::Call::Kind;
using frametest::appearance;
using frametest::quadMesh;
using frametest::translation;

namespace {

float c8(int v) { return static_cast<float>(v) / 255.0f; }

/// A mutable target image.
Ref<Image2D> target(int w, int h, int format = Image2D::RGBA) { return Ref<Image2D>(new Image2D(format, w, h)); }

struct Graphics3DNull : ::testing::Test {
    frametest::NullFrame f;
    Graphics3D* g = f.g.get();
    NullBackend& nb = *f.backend;

    const DrawUniforms& uniformsOf(const NullBackend::Call& c, std::size_t draw) const {
        return c.list.uniforms.at(c.list.draws.at(draw).uniforms);
    }
    /// Binds a 16 x 16 RGBA target and an identity camera (camera-to-world `at`).
    Ref<Image2D> begin(const Transform* at = nullptr) {
        Ref<Image2D> img = target(16, 16);
        g->bindTarget(img.get());
        cam = new Camera();
        g->setCamera(cam.get(), at);
        return img;
    }
    Ref<Camera> cam;
};

/// A Mesh of a quad whose default colour tells its draws apart.
Ref<Mesh> coloured(std::uint32_t argb, Appearance* app) {
    Ref<Mesh> m = quadMesh(app);
    m->getVertexBuffer()->setDefaultColor(static_cast<int>(argb));
    return m;
}

std::vector<std::uint64_t> sorted(std::vector<std::uint64_t> v) {
    std::sort(v.begin(), v.end());
    return v;
}

}  // namespace

// ---- What reaches the back end ----

TEST_F(Graphics3DNull, RenderWorldClearsWithItsBackgroundThenDrawsSorted) {
    Ref<World> world = frametest::worldWithCamera();
    Ref<Background> bg(new Background());
    bg->setColor(static_cast<int>(0xFF102030u));
    world->setBackground(bg.get());
    Ref<Mesh> blended = coloured(0xFF0000FFu, appearance(0, CompositingMode::ALPHA).get());
    Ref<Mesh> upper = coloured(0xFFFF0000u, appearance(1).get());
    Ref<Mesh> opaque = coloured(0xFF00FF00u, appearance(0).get());
    world->addChild(blended.get());
    world->addChild(upper.get());
    world->addChild(opaque.get());
    Ref<Image2D> img = target(16, 8);
    g->bindTarget(img.get());
    g->render(world.get());
    ASSERT_EQ(f.calls().size(), 2u);
    const NullBackend::Call& clear = f.calls()[0];
    EXPECT_EQ(clear.kind, Kind::Clear);
    EXPECT_TRUE(clear.list.clear.color);
    EXPECT_TRUE(clear.list.clear.depth);
    EXPECT_NEAR(clear.list.clear.rgba[0], c8(0x10), 1e-6f);
    EXPECT_NEAR(clear.list.clear.rgba[2], c8(0x30), 1e-6f);
    EXPECT_EQ(clear.list.clear.rgba[3], 1.0f);
    EXPECT_TRUE(clear.list.clear.wholeTarget);
    const NullBackend::Call& draw = f.calls()[1];
    EXPECT_EQ(draw.kind, Kind::Draw);
    EXPECT_EQ(draw.target.width, 16);
    EXPECT_EQ(draw.target.height, 8);
    EXPECT_EQ(draw.target.identity, static_cast<const void*>(img.get()));
    EXPECT_EQ(draw.view.viewport, (Rect{0, 0, 16, 8}));
    // Layer 0 opaque (green), layer 0 blended (blue), layer 1 (red).
    ASSERT_EQ(draw.list.draws.size(), 3u);
    EXPECT_EQ(uniformsOf(draw, 0).defaultColor[1], 1.0f);
    EXPECT_EQ(uniformsOf(draw, 1).defaultColor[2], 1.0f);
    EXPECT_EQ(uniformsOf(draw, 2).defaultColor[0], 1.0f);
    EXPECT_EQ(draw.list.draws[1].pipeline.blend, 1);
    for (std::uint32_t i = 0; i < 3; ++i) EXPECT_EQ(draw.list.draws[i].uniforms, i);
    EXPECT_EQ(draw.list.draws[0].vertices.owner, opaque->getVertexBuffer()->getObjectId());
}

TEST_F(Graphics3DNull, RenderWorldWithoutBackgroundClearsToTransparentBlack) {
    Ref<World> world = frametest::worldWithCamera();
    Ref<Image2D> img = target(8, 8);
    g->bindTarget(img.get());
    g->render(world.get());
    ASSERT_EQ(f.calls().size(), 2u);
    const Clear& c = f.calls()[0].list.clear;
    EXPECT_TRUE(c.color);
    EXPECT_TRUE(c.depth);
    for (float v : c.rgba) EXPECT_EQ(v, 0.0f);
    EXPECT_FALSE(c.hasImage);
    EXPECT_TRUE(f.calls()[1].list.draws.empty());
}

TEST_F(Graphics3DNull, RenderWorldUsesItsEnabledLightsAndTheFirstEight) {
    // A disabled light first, then nine ambient lights of levels 1..9: the
    // World's enabled lights replace Graphics3D's and become its current
    // ones; a draw takes the first eight (maxLights).
    Ref<World> world = frametest::worldWithCamera();
    Ref<Light> off = frametest::light(Light::AMBIENT, 0xFFFFFF);
    off->setRenderingEnable(false);
    world->addChild(off.get());
    std::vector<Ref<Light>> lights;
    for (int i = 1; i <= 9; ++i) {
        lights.push_back(frametest::light(Light::AMBIENT, 0x010101 * i));
        world->addChild(lights.back().get());
    }
    Ref<Mesh> mesh = quadMesh(Ref<Appearance>(new Appearance()).get());
    mesh->getAppearance(0)->setMaterial(Ref<Material>(new Material()).get());
    world->addChild(mesh.get());
    Ref<Light> old = frametest::light(Light::OMNI);
    g->addLight(old.get(), nullptr);
    Ref<Image2D> img = target(8, 8);
    g->bindTarget(img.get());
    g->render(world.get());
    EXPECT_EQ(g->getLightCount(), 9);
    EXPECT_EQ(g->getLight(0, nullptr).get(), lights[0].get());
    EXPECT_EQ(g->getCamera(nullptr).get(), world->getActiveCamera().get());
    const DrawUniforms& u = uniformsOf(f.last(), 0);
    EXPECT_EQ(u.flags[1], getLimits().maxLights);
    EXPECT_NEAR(u.lights[0].color[0], c8(1), 1e-6f);
    EXPECT_NEAR(u.lights[7].color[0], c8(8), 1e-6f);
    EXPECT_EQ(f.last().list.draws[0].pipeline.lightCount, 8);
}

// Moved from tests/vk/test_RenderBasics.cpp (WorldOwnTransformCancelsOut):
// the camera and meshes are placed relative to the World (the camera's
// getTransformTo(world)), so moving the World itself changes nothing.
TEST_F(Graphics3DNull, WorldOwnTransformCancelsOut) {
    auto render = [&](float worldX) {
        Ref<World> world(new World());
        Ref<Camera> camera(new Camera());
        camera->setTranslation(0, 0, 5);
        world->addChild(camera.get());
        world->setActiveCamera(camera.get());
        Ref<Mesh> mesh = quadMesh(Ref<Appearance>(new Appearance()).get());
        mesh->setTranslation(1, 0, 0);
        world->addChild(mesh.get());
        world->setTranslation(worldX, 0.0f, 0.0f);
        Ref<Image2D> img = target(8, 8);
        g->bindTarget(img.get());
        g->render(world.get());
        g->releaseTarget();
        const NullBackend::Call& draw = f.calls()[f.calls().size() - 2];  // before the Release
        EXPECT_EQ(draw.kind, Kind::Draw);
        EXPECT_EQ(draw.list.draws.size(), 1u);
        return uniformsOf(draw, 0);
    };
    const DrawUniforms a = render(0.0f), b = render(0.7f);
    // The whole uniform block (model-view, normal matrix, projection, ...) is the same.
    EXPECT_EQ(std::memcmp(&a, &b, sizeof(DrawUniforms)), 0);
    // Mesh at world x 1, camera at world z 5: eye-space translation (1, 0, -5).
    EXPECT_FLOAT_EQ(a.modelView[12], 1.0f);
    EXPECT_FLOAT_EQ(a.modelView[13], 0.0f);
    EXPECT_FLOAT_EQ(a.modelView[14], -5.0f);
}

TEST_F(Graphics3DNull, RenderNodeIgnoresItsOwnTransformAndDoesNotClear) {
    // render(Node, Transform): the node's own transformation is ignored, its
    // children's apply, and `transform` is the node-to-world one.
    begin();
    Ref<Mesh> red = quadMesh(Ref<Appearance>(new Appearance()).get());
    red->setTranslation(0.5f, 0.5f, 0);
    g->render(red.get(), nullptr);
    const Transform down = translation(0, -0.5f, 0);
    g->render(red.get(), &down);
    Ref<Group> group(new Group());
    group->setTranslation(0, 0.5f, 0);
    Ref<Mesh> green = quadMesh(Ref<Appearance>(new Appearance()).get());
    green->setTranslation(-0.5f, 0, 0);
    group->addChild(green.get());
    g->render(group.get(), nullptr);
    ASSERT_EQ(f.calls().size(), 3u);
    for (const auto& c : f.calls()) EXPECT_EQ(c.kind, Kind::Draw);
    const float* mv0 = uniformsOf(f.calls()[0], 0).modelView;
    EXPECT_EQ(mv0[12], 0.0f);
    EXPECT_EQ(mv0[13], 0.0f);
    EXPECT_EQ(uniformsOf(f.calls()[1], 0).modelView[13], -0.5f);
    EXPECT_EQ(uniformsOf(f.calls()[2], 0).modelView[12], -0.5f);
    EXPECT_EQ(uniformsOf(f.calls()[2], 0).modelView[13], 0.0f);
}

TEST_F(Graphics3DNull, RenderNodeUsesTheCurrentCameraAndLightsInEyeSpace) {
    // Camera at world (0, 0, 5); an omni light at world (1, 0, 0) is at eye
    // (1, 0, -5); an empty light slot is skipped.
    const Transform cameraAt = translation(0, 0, 5);
    begin(&cameraAt);
    Ref<Light> omni = frametest::light(Light::OMNI, 0x808080, 0.5f);
    const Transform lightAt = translation(1, 0, 0);
    g->addLight(omni.get(), &lightAt);
    Ref<Light> spare = frametest::light(Light::AMBIENT);
    g->addLight(spare.get(), nullptr);
    g->setLight(1, nullptr, nullptr);
    Ref<Appearance> app(new Appearance());
    app->setMaterial(Ref<Material>(new Material()).get());
    Ref<Mesh> mesh = quadMesh(app.get());
    g->render(mesh.get(), nullptr);
    const DrawUniforms& u = uniformsOf(f.last(), 0);
    EXPECT_EQ(u.modelView[14], -5.0f);
    ASSERT_EQ(u.flags[1], 1);
    EXPECT_FLOAT_EQ(u.lights[0].position[0], 1.0f);
    EXPECT_FLOAT_EQ(u.lights[0].position[2], -5.0f);
    EXPECT_FLOAT_EQ(u.lights[0].position[3], 1.0f);
    EXPECT_NEAR(u.lights[0].color[0], 0.5f * c8(0x80), 1e-6f);
    EXPECT_EQ(u.lights[0].color[3], 2.0f);  // OMNI
}

TEST_F(Graphics3DNull, ImmediateModeDrawsOneSubmeshAndReadsItsData) {
    begin();
    Ref<VertexBuffer> vb = frametest::vertexBuffer({-2, -2, 0, 2, -2, 0, -2, 2, 0, 2, 2, 0}, 0.5f, {1, 0, 0});
    const int lengths[] = {4};
    Ref<IndexBuffer> ib(new TriangleStripArray(0, lengths));
    const Transform t = translation(0, 0, -3);
    g->render(vb.get(), ib.get(), Ref<Appearance>(new Appearance()).get(), &t);
    ASSERT_EQ(f.calls().size(), 1u);
    const NullBackend::Call& c = f.last();
    ASSERT_EQ(c.list.draws.size(), 1u);
    const Draw& d = c.list.draws[0];
    EXPECT_EQ(d.vertices.owner, vb->getObjectId());
    EXPECT_EQ(d.vertices.source, VertexSource::Plain);
    EXPECT_EQ(d.vertices.vertexCount, 4);
    EXPECT_EQ(d.vertices.present, (std::array<bool, STREAM_COUNT>{true, false, false, false, false}));
    EXPECT_EQ(d.indices.id, ib->getObjectId());
    EXPECT_EQ(uniformsOf(c, 0).modelView[14], -3.0f);
    // Plain positions are the raw values; scale 0.5 and bias (1, 0, 0) go to the shader.
    EXPECT_EQ(nb.lastStreams(vb->getObjectId())[POSITIONS],
              (std::vector<float>{-2, -2, 0, 2, -2, 0, -2, 2, 0, 2, 2, 0}));
    EXPECT_EQ(uniformsOf(c, 0).positionScaleBias[3], 0.5f);
    EXPECT_EQ(uniformsOf(c, 0).positionScaleBias[0], 1.0f);
    // The strip's two triangles, provoking vertex first.
    EXPECT_EQ(nb.lastTriangles(ib->getObjectId()), (std::vector<std::uint32_t>{2, 0, 1, 3, 2, 1}));
}

TEST_F(Graphics3DNull, ImmediateModeOutsideTheCameraScopeHandsNothing) {
    begin();
    cam->setScope(1);
    frametest::Quad q = frametest::quad();
    Ref<Appearance> app(new Appearance());
    g->render(q.vb.get(), q.ib.get(), app.get(), nullptr, 2);
    EXPECT_TRUE(f.calls().empty());
    EXPECT_EQ(nb.uploads().vertices, 0);
    g->render(q.vb.get(), q.ib.get(), app.get(), nullptr, 3);
    ASSERT_EQ(f.calls().size(), 1u);
    EXPECT_EQ(f.last().list.draws.size(), 1u);
}

TEST_F(Graphics3DNull, ImmediateModeTakesTheFirstMaxLightsLights) {
    begin();
    std::vector<Ref<Light>> lights;
    for (int i = 1; i <= 9; ++i) {
        lights.push_back(frametest::light(Light::AMBIENT, 0x010101 * i));
        g->addLight(lights.back().get(), nullptr);
    }
    Ref<Appearance> app(new Appearance());
    app->setMaterial(Ref<Material>(new Material()).get());
    frametest::Quad q = frametest::quad();
    g->render(q.vb.get(), q.ib.get(), app.get(), nullptr);
    const DrawUniforms& u = uniformsOf(f.last(), 0);
    EXPECT_EQ(u.flags[1], 8);
    EXPECT_NEAR(u.lights[7].color[1], c8(8), 1e-6f);
}

TEST_F(Graphics3DNull, ClearHandsTheBackgroundAndItsImage) {
    Ref<Image2D> img = target(8, 8);
    g->bindTarget(img.get());
    g->setViewport(2, 2, 4, 4);
    Ref<Background> bg(new Background());
    bg->setColor(static_cast<int>(0x40FF0000u));
    Ref<Image2D> picture = frametest::image(Image2D::RGBA, 4, 2);
    bg->setImage(picture.get());
    g->clear(bg.get());
    ASSERT_EQ(f.calls().size(), 1u);
    const NullBackend::Call& c = f.last();
    EXPECT_EQ(c.kind, Kind::Clear);
    EXPECT_EQ(c.view.scissor, (Rect{2, 2, 4, 4}));
    EXPECT_FALSE(c.list.clear.wholeTarget);
    EXPECT_NEAR(c.list.clear.rgba[3], c8(0x40), 1e-6f);
    ASSERT_TRUE(c.list.clear.hasImage);
    EXPECT_EQ(c.list.clear.image.textures[0].id, picture->getObjectId());
    EXPECT_EQ(nb.uploads().textures, 1);
    EXPECT_TRUE(c.list.draws.empty());
    g->clear(nullptr);
    ASSERT_EQ(f.calls().size(), 2u);
    EXPECT_FALSE(f.last().list.clear.hasImage);
    EXPECT_EQ(f.last().list.clear.rgba[0], 0.0f);
    EXPECT_EQ(nb.uploads().textures, 1);
}

TEST_F(Graphics3DNull, TargetDescribesTheBinding) {
    Ref<Graphics> gr(new Graphics(40, 30));
    g->bindTarget(gr.get(), false, Graphics3D::ANTIALIAS | Graphics3D::DITHER);
    g->clear(nullptr);
    const Target& t = f.last().target;
    EXPECT_EQ(t.width, 40);
    EXPECT_EQ(t.height, 30);
    EXPECT_FALSE(t.depthBuffer);
    EXPECT_EQ(t.hints, Graphics3D::ANTIALIAS | Graphics3D::DITHER);
    EXPECT_EQ(t.identity, static_cast<const void*>(gr.get()));
    EXPECT_NE(t.pixels, nullptr);
    g->releaseTarget();
    ASSERT_EQ(f.calls().size(), 2u);
    EXPECT_EQ(f.last().kind, Kind::Release);
    g->releaseTarget();  // unbound: a no-op, nothing handed
    EXPECT_EQ(f.calls().size(), 2u);
}

TEST_F(Graphics3DNull, BackEndOptionsApplyToTheTranslation) {
    DrawOptions o;
    o.unlit = true;
    o.vulkanClipSpace = false;
    o.wireframe = true;
    nb.setOptions(o);
    begin();
    Ref<Appearance> app(new Appearance());
    app->setMaterial(Ref<Material>(new Material()).get());
    Ref<Mesh> mesh = quadMesh(app.get());
    g->render(mesh.get(), nullptr);
    const DrawUniforms& u = uniformsOf(f.last(), 0);
    EXPECT_FALSE(u.flags[0] & F_LIGHTING);
    EXPECT_EQ(u.projection[5], 1.0f);  // OpenGL clip space: no y flip
    EXPECT_EQ(u.projection[10], 1.0f);
    EXPECT_EQ(f.last().list.draws[0].pipeline.wireframe, 1);
}

TEST_F(Graphics3DNull, SpriteInAWorldIsAQuadDrawWithItsImage) {
    Ref<World> world = frametest::worldWithCamera();
    Ref<Image2D> picture = frametest::image(Image2D::RGBA, 4, 4);
    Ref<Sprite3D> sprite(new Sprite3D(false, picture.get(), Ref<Appearance>(new Appearance()).get()));
    sprite->setTranslation(0, 0, -0.5f);
    world->addChild(sprite.get());
    Ref<Image2D> img = target(8, 8);
    g->bindTarget(img.get());
    g->render(world.get());
    const NullBackend::Call& c = f.last();
    ASSERT_EQ(c.list.draws.size(), 1u);
    EXPECT_EQ(c.list.draws[0].kind, Draw::Kind::Quad);
    EXPECT_EQ(c.list.draws[0].textures[0].id, picture->getObjectId());
    // 4 x 4 pixels of an 8 x 8 viewport: half of NDC.
    EXPECT_NEAR(c.list.draws[0].quad.x0, -0.5f, 1e-6f);
    EXPECT_NEAR(c.list.draws[0].quad.y1, 0.5f, 1e-6f);
    EXPECT_EQ(nb.uploads().textures, 1);
    EXPECT_EQ(nb.uploads().vertices, 0);
}

TEST_F(Graphics3DNull, EmptyIndexBufferDrawsNothing) {
    begin();
    Ref<VertexBuffer> vb = frametest::vertexBuffer({0, 0, 0, 1, 0, 0, 0, 1, 0});
    Ref<frametest::TriangleList> none(new frametest::TriangleList({}));
    Ref<Mesh> mesh(new Mesh(vb.get(), none.get(), Ref<Appearance>(new Appearance()).get()));
    g->render(mesh.get(), nullptr);
    ASSERT_EQ(f.calls().size(), 1u);
    EXPECT_TRUE(f.last().list.draws.empty());
    EXPECT_TRUE(f.last().list.uniforms.empty());
}

TEST_F(Graphics3DNull, EmptyScissorHandsAnEmptyDrawList) {
    // A viewport wholly outside the target is legal and draws nothing.
    Ref<Image2D> img = target(8, 8);
    g->bindTarget(img.get());
    Ref<World> world = frametest::worldWithCamera();
    world->addChild(quadMesh(Ref<Appearance>(new Appearance()).get()).get());
    g->setViewport(100, 100, 8, 8);
    g->render(world.get());
    ASSERT_EQ(f.calls().size(), 2u);
    EXPECT_EQ(f.calls()[0].kind, Kind::Clear);
    EXPECT_TRUE(f.calls()[0].view.scissor.empty());
    EXPECT_FALSE(f.calls()[0].list.clear.wholeTarget);
    EXPECT_TRUE(f.calls()[1].view.scissor.empty());
    EXPECT_TRUE(f.calls()[1].list.draws.empty());
    EXPECT_EQ(nb.uploads().vertices, 0);
    EXPECT_EQ(nb.uploads().indices, 0);
}

// ---- Exceptions: thrown before anything is handed to the back end ----

// Moved from tests/vk/test_SceneOrder.cpp (Graphics3DRenderExceptions, first part).
TEST_F(Graphics3DNull, NoTargetThrowsIllegalStateAndHandsNothing) {
    Ref<Camera> camera(new Camera());
    g->setCamera(camera.get(), nullptr);
    frametest::Quad q = frametest::quad();
    Ref<Appearance> app(new Appearance());
    Ref<Mesh> m(new Mesh(q.vb.get(), q.ib.get(), app.get()));
    Ref<World> world = frametest::worldWithCamera();
    EXPECT_THROW(g->render(q.vb.get(), q.ib.get(), app.get(), nullptr), IllegalStateException);
    EXPECT_THROW(g->render(m.get(), nullptr), IllegalStateException);
    EXPECT_THROW(g->render(world.get()), IllegalStateException);
    EXPECT_THROW(g->clear(nullptr), IllegalStateException);
    EXPECT_TRUE(f.calls().empty());
}

// Moved from tests/vk/test_Misuse.cpp (MisuseNullArgumentsThrowNullPointerException).
TEST_F(Graphics3DNull, NullArgumentsThrowNullPointerException) {
    frametest::Quad q = frametest::quad();
    Ref<Appearance> app(new Appearance());
    // Null checks come first, with or without a target.
    EXPECT_THROW(g->render(static_cast<World*>(nullptr)), NullPointerException);
    EXPECT_THROW(g->render(static_cast<Node*>(nullptr), nullptr), NullPointerException);
    begin();
    EXPECT_THROW(g->render(static_cast<World*>(nullptr)), NullPointerException);
    EXPECT_THROW(g->render(static_cast<Node*>(nullptr), nullptr), NullPointerException);
    EXPECT_THROW(g->render(nullptr, q.ib.get(), app.get(), nullptr), NullPointerException);
    EXPECT_THROW(g->render(q.vb.get(), nullptr, app.get(), nullptr), NullPointerException);
    EXPECT_THROW(g->render(q.vb.get(), q.ib.get(), nullptr, nullptr), NullPointerException);
    EXPECT_THROW(g->render(q.vb.get(), q.ib.get(), nullptr, nullptr, 1), NullPointerException);
    EXPECT_TRUE(f.calls().empty());
}

// Moved from tests/vk/test_Misuse.cpp (MisuseNoCurrentCameraThrowsIllegalState).
TEST_F(Graphics3DNull, NoCurrentCameraThrowsIllegalStateButClearNeedsNone) {
    frametest::Quad q = frametest::quad();
    Ref<Appearance> app(new Appearance());
    Ref<Mesh> mesh(new Mesh(q.vb.get(), q.ib.get(), app.get()));
    Ref<Image2D> img = target(8, 8);
    g->bindTarget(img.get());
    EXPECT_THROW(g->render(mesh.get(), nullptr), IllegalStateException);
    EXPECT_THROW(g->render(q.vb.get(), q.ib.get(), app.get(), nullptr), IllegalStateException);
    EXPECT_TRUE(f.calls().empty());
    EXPECT_NO_THROW(g->clear(nullptr));
    ASSERT_EQ(f.calls().size(), 1u);
    EXPECT_EQ(f.last().kind, Kind::Clear);
}

// Moved from tests/vk/test_SceneOrder.cpp (Graphics3DRenderExceptions).
TEST_F(Graphics3DNull, RenderWorldNeedsItsOwnActiveCameraAndRenderNodeARenderableNode) {
    Ref<Image2D> img = target(8, 8);
    g->bindTarget(img.get());
    Ref<World> noCamera(new World());
    EXPECT_THROW(g->render(noCamera.get()), IllegalStateException);
    Ref<World> foreign(new World());
    Ref<Camera> outside(new Camera());
    foreign->setActiveCamera(outside.get());
    EXPECT_THROW(g->render(foreign.get()), IllegalStateException);
    Ref<Camera> camera(new Camera());
    g->setCamera(camera.get(), nullptr);
    Ref<Light> light(new Light());
    EXPECT_THROW(g->render(light.get(), nullptr), IllegalArgumentException);
    EXPECT_THROW(g->render(camera.get(), nullptr), IllegalArgumentException);
    EXPECT_TRUE(f.calls().empty());
}

// A camera whose transform to the World cannot be inverted gives no view:
// ArithmeticException as setCamera throws (a fuzzed file had a camera scaled
// by zero), naming render(World); nothing reaches the back end and the
// current camera stays.
TEST_F(Graphics3DNull, RenderWorldWithASingularCameraTransformIsArithmetic) {
    Ref<Image2D> img = begin();
    Ref<World> world = frametest::worldWithCamera();
    world->getActiveCamera()->setScale(1.0f, 0.0f, 1.0f);
    try {
        g->render(world.get());
        ADD_FAILURE() << "no exception";
    } catch (const ArithmeticException& e) {
        EXPECT_NE(std::string(e.what()).find("Graphics3D::render(World)"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(f.calls().empty());
    EXPECT_EQ(g->getCamera(nullptr).get(), cam.get());
    world->getActiveCamera()->setScale(1.0f, 1.0f, 1.0f);
    EXPECT_NO_THROW(g->render(world.get()));
}

// Moved from tests/vk/test_Misuse.cpp (MisuseBackgroundFormatAgainstTarget)
// and test_SceneOrder.cpp (Graphics3DRenderExceptions, background part).
TEST_F(Graphics3DNull, BackgroundImageFormatMustBeTheTargets) {
    Ref<Background> rgbBackground(new Background());
    rgbBackground->setImage(frametest::image(Image2D::RGB, 2, 2).get());
    Ref<Background> rgbaBackground(new Background());
    rgbaBackground->setImage(frametest::image(Image2D::RGBA, 2, 2).get());
    // RGBA Image2D target: only RGBA background images.
    Ref<Image2D> rgba = target(8, 8, Image2D::RGBA);
    g->bindTarget(rgba.get());
    EXPECT_THROW(g->clear(rgbBackground.get()), IllegalArgumentException);
    EXPECT_TRUE(f.calls().empty());
    EXPECT_NO_THROW(g->clear(rgbaBackground.get()));
    EXPECT_EQ(f.calls().size(), 1u);
    g->releaseTarget();
    nb.clearCalls();
    // RGB Image2D target: clear() throws IllegalArgumentException, render(World) IllegalStateException.
    Ref<Image2D> rgb = target(8, 8, Image2D::RGB);
    g->bindTarget(rgb.get());
    EXPECT_THROW(g->clear(rgbaBackground.get()), IllegalArgumentException);
    Ref<World> world = frametest::worldWithCamera();
    world->setBackground(rgbaBackground.get());
    EXPECT_THROW(g->render(world.get()), IllegalStateException);
    EXPECT_TRUE(f.calls().empty());
    g->releaseTarget();
    nb.clearCalls();
    // A Graphics surface counts as RGB.
    Ref<Graphics> graphics(new Graphics(8, 8));
    g->bindTarget(graphics.get());
    EXPECT_THROW(g->clear(rgbaBackground.get()), IllegalArgumentException);
    EXPECT_TRUE(f.calls().empty());
    EXPECT_NO_THROW(g->clear(rgbBackground.get()));
    EXPECT_EQ(f.calls().size(), 1u);
}

// Moved from tests/vk/test_Misuse.cpp (MisuseVertexBufferWithoutPositions).
TEST_F(Graphics3DNull, VertexBufferWithoutPositionsThrowsIllegalState) {
    frametest::Quad q = frametest::quad();
    Ref<VertexBuffer> empty(new VertexBuffer());
    Ref<Appearance> app(new Appearance());
    begin();
    // Immediate mode: the vertex data is invalid.
    EXPECT_THROW(g->render(empty.get(), q.ib.get(), app.get(), nullptr), IllegalStateException);
    // The same through a Mesh (render(Node)): found while preparing the frame.
    Ref<Mesh> mesh(new Mesh(empty.get(), q.ib.get(), app.get()));
    EXPECT_THROW(g->render(mesh.get(), nullptr), IllegalStateException);
    EXPECT_TRUE(f.calls().empty());
    EXPECT_EQ(nb.uploads().vertices, 0);
}

// Moved from tests/vk/test_SceneOrder.cpp (Graphics3DRenderExceptions, index part).
TEST_F(Graphics3DNull, IndexBeyondTheVerticesThrowsIllegalStateAndTheFrameGoesOn) {
    begin();
    Ref<VertexBuffer> three = frametest::vertexBuffer({0, 0, 0, 1, 0, 0, 0, 1, 0});
    frametest::Quad q = frametest::quad();  // its strip refers to vertex 3
    Ref<Appearance> app(new Appearance());
    EXPECT_THROW(g->render(three.get(), q.ib.get(), app.get(), nullptr), IllegalStateException);
    Ref<Mesh> bad(new Mesh(three.get(), q.ib.get(), app.get()));
    EXPECT_THROW(g->render(bad.get(), nullptr), IllegalStateException);
    EXPECT_TRUE(f.calls().empty());
    // Still bound and usable.
    g->render(q.vb.get(), q.ib.get(), app.get(), nullptr);
    ASSERT_EQ(f.calls().size(), 1u);
    EXPECT_EQ(f.last().list.draws.size(), 1u);
}

TEST_F(Graphics3DNull, InvalidMeshInAWorldHandsNothing) {
    // render(World) prepares its draws before it clears: the exception
    // comes before the back end sees the clear or any draw.
    Ref<World> world = frametest::worldWithCamera();
    Ref<VertexBuffer> three = frametest::vertexBuffer({0, 0, 0, 1, 0, 0, 0, 1, 0});
    frametest::Quad q = frametest::quad();
    world->addChild(Ref<Mesh>(new Mesh(three.get(), q.ib.get(), Ref<Appearance>(new Appearance()).get())).get());
    Ref<Image2D> img = target(8, 8);
    g->bindTarget(img.get());
    EXPECT_THROW(g->render(world.get()), IllegalStateException);
    EXPECT_TRUE(f.calls().empty());
}

// Moved from tests/vk/test_Misuse.cpp (MisuseBindTwiceKeepsTheFirstTarget).
TEST_F(Graphics3DNull, BindTwiceKeepsTheFirstTarget) {
    Ref<Image2D> img = target(8, 8);
    Ref<Graphics> graphics(new Graphics(8, 8));
    g->bindTarget(img.get());
    EXPECT_THROW(g->bindTarget(graphics.get()), IllegalStateException);
    EXPECT_THROW(g->bindTarget(img.get(), false, Graphics3D::ANTIALIAS), IllegalStateException);
    EXPECT_EQ(g->getTarget().get(), static_cast<RefCounted*>(img.get()));
    g->releaseTarget();
    g->bindTarget(graphics.get());
    EXPECT_THROW(g->bindTarget(img.get()), IllegalStateException);
    EXPECT_EQ(g->getTarget().get(), static_cast<RefCounted*>(graphics.get()));
    g->releaseTarget();
    // Release without a bound target: a no-op, however often.
    g->releaseTarget();
    g->releaseTarget();
    EXPECT_EQ(g->getTarget(), nullptr);
    // One Release per bound target, nothing else.
    ASSERT_EQ(f.calls().size(), 2u);
    EXPECT_EQ(f.calls()[0].kind, Kind::Release);
    EXPECT_EQ(f.calls()[0].target.identity, static_cast<const void*>(img.get()));
    EXPECT_EQ(f.calls()[1].target.identity, static_cast<const void*>(graphics.get()));
}

// Moved from tests/vk/test_Misuse.cpp (MisuseTargetOfWrongFormatOrSize).
TEST_F(Graphics3DNull, TargetOfWrongFormatOrSizeIsRejected) {
    for (int format : {Image2D::ALPHA, Image2D::LUMINANCE, Image2D::LUMINANCE_ALPHA}) {
        Ref<Image2D> wrong(new Image2D(format, 4, 4));
        EXPECT_THROW(g->bindTarget(wrong.get()), IllegalArgumentException) << "format " << format;
    }
    const std::uint8_t px[12] = {};
    Ref<Image2D> immutableRgb(new Image2D(Image2D::RGB, 2, 2, std::span<const std::uint8_t>(px)));
    EXPECT_THROW(g->bindTarget(immutableRgb.get()), IllegalArgumentException);
    const Limits& l = getLimits();
    Ref<Image2D> tooWide(new Image2D(Image2D::RGB, l.maxViewportWidth + 1, 1));
    EXPECT_THROW(g->bindTarget(tooWide.get()), IllegalArgumentException);
    Ref<Image2D> tooTall(new Image2D(Image2D::RGBA, 1, l.maxViewportHeight + 1));
    EXPECT_THROW(g->bindTarget(tooTall.get()), IllegalArgumentException);
    EXPECT_EQ(g->getTarget(), nullptr);
    EXPECT_THROW(g->clear(nullptr), IllegalStateException);  // nothing was bound
    EXPECT_TRUE(f.calls().empty());
}

// ---- Versions: a back end re-reads exactly what changed ----

namespace {

struct TexturedScene {
    Ref<VertexArray> positions = frametest::shorts(3, {-1, -1, 0, 1, -1, 0, -1, 1, 0, 1, 1, 0});
    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<frametest::TriangleList> ib = new frametest::TriangleList({0, 1, 2, 2, 1, 3});
    Ref<Image2D> picture = frametest::image(Image2D::RGB, 4, 4);
    Ref<Appearance> app = new Appearance();
    Ref<Mesh> mesh;
    TexturedScene() {
        const float zero[3] = {0, 0, 0};
        vb->setPositions(positions.get(), 1.0f, zero);
        vb->setTexCoords(0, frametest::shorts(2, {0, 0, 1, 0, 0, 1, 1, 1}).get(), 1.0f, zero);
        app->setTexture(0, Ref<Texture2D>(new Texture2D(picture.get())).get());
        mesh = new Mesh(vb.get(), ib.get(), app.get());
    }
};

}  // namespace

TEST_F(Graphics3DNull, SecondRenderOfAnUnchangedSceneReadsNothing) {
    begin();
    TexturedScene s;
    g->render(s.mesh.get(), nullptr);
    EXPECT_EQ(nb.uploads().vertices, 1);
    EXPECT_EQ(nb.uploads().indices, 1);
    EXPECT_EQ(nb.uploads().textures, 1);
    EXPECT_EQ(nb.resident(), 3u);
    const VertexRef first = f.last().list.draws[0].vertices;
    g->render(s.mesh.get(), nullptr);
    EXPECT_EQ(nb.uploads().vertices, 1);
    EXPECT_EQ(nb.uploads().indices, 1);
    EXPECT_EQ(nb.uploads().textures, 1);
    EXPECT_EQ(f.last().list.draws[0].vertices.version, first.version);
}

TEST_F(Graphics3DNull, ChangingAVertexArrayReReadsOnlyTheVertices) {
    begin();
    TexturedScene s;
    g->render(s.mesh.get(), nullptr);
    const std::int16_t moved[3] = {-3, -1, 0};
    s.positions->set(0, 1, std::span<const std::int16_t>(moved));
    g->render(s.mesh.get(), nullptr);
    EXPECT_EQ(nb.uploads().vertices, 2);
    EXPECT_EQ(nb.uploads().indices, 1);
    EXPECT_EQ(nb.uploads().textures, 1);
    EXPECT_EQ(nb.lastStreams(s.vb->getObjectId())[POSITIONS][0], -3.0f);
}

TEST_F(Graphics3DNull, ChangingTheDefaultColourChangesOnlyTheUniforms) {
    // The default colour is uniform data (JSR-184 1.1,
    // VertexBuffer.setDefaultColor): the vertex copy stays.
    begin();
    TexturedScene s;
    g->render(s.mesh.get(), nullptr);
    s.vb->setDefaultColor(static_cast<int>(0x80402010u));
    g->render(s.mesh.get(), nullptr);
    EXPECT_EQ(nb.uploads().vertices, 1);
    const DrawUniforms& u = uniformsOf(f.last(), 0);
    EXPECT_FLOAT_EQ(u.defaultColor[0], c8(0x40));
    EXPECT_FLOAT_EQ(u.defaultColor[1], c8(0x20));
    EXPECT_FLOAT_EQ(u.defaultColor[2], c8(0x10));
    EXPECT_FLOAT_EQ(u.defaultColor[3], c8(0x80));
}

TEST_F(Graphics3DNull, ChangingAnIndexBufferReReadsOnlyTheTriangles) {
    begin();
    TexturedScene s;
    g->render(s.mesh.get(), nullptr);
    s.ib->set({3, 2, 1});
    g->render(s.mesh.get(), nullptr);
    EXPECT_EQ(nb.uploads().vertices, 1);
    EXPECT_EQ(nb.uploads().indices, 2);
    EXPECT_EQ(nb.uploads().textures, 1);
    EXPECT_EQ(f.last().list.draws[0].indices.revision, s.ib->getRevision());
    EXPECT_EQ(nb.lastTriangles(s.ib->getObjectId()), (std::vector<std::uint32_t>{1, 3, 2}));
}

TEST_F(Graphics3DNull, ChangingAnImageReReadsOnlyTheTexture) {
    begin();
    TexturedScene s;
    g->render(s.mesh.get(), nullptr);
    const std::uint8_t texel[3] = {1, 2, 3};
    s.picture->set(0, 0, 1, 1, texel);
    g->render(s.mesh.get(), nullptr);
    EXPECT_EQ(nb.uploads().vertices, 1);
    EXPECT_EQ(nb.uploads().indices, 1);
    EXPECT_EQ(nb.uploads().textures, 2);
    EXPECT_EQ(f.last().list.draws[0].textures[0].revision, s.picture->getRevision());
}

TEST_F(Graphics3DNull, SharedDataIsReadOncePerVersion) {
    // Two meshes share the VertexBuffer, IndexBuffer and texture: one read each.
    begin();
    TexturedScene s;
    Ref<Group> group(new Group());
    group->addChild(s.mesh.get());
    Ref<Mesh> twin(new Mesh(s.vb.get(), s.ib.get(), s.app.get()));
    group->addChild(twin.get());
    g->render(group.get(), nullptr);
    ASSERT_EQ(f.last().list.draws.size(), 2u);
    EXPECT_EQ(f.last().list.draws[0].vertices.owner, f.last().list.draws[1].vertices.owner);
    EXPECT_EQ(nb.uploads().vertices, 1);
    EXPECT_EQ(nb.uploads().indices, 1);
    EXPECT_EQ(nb.uploads().textures, 1);
}

TEST_F(Graphics3DNull, ReleaseTargetNamesTheObjectsThatNoLongerExist) {
    Ref<Image2D> img = begin();
    std::vector<std::uint64_t> ids;
    {
        TexturedScene s;
        ids = {s.vb->getObjectId(), s.ib->getObjectId(), s.picture->getObjectId()};
        g->render(s.mesh.get(), nullptr);
        EXPECT_EQ(nb.resident(), 3u);
        // Still alive at this release: nothing to free.
        g->releaseTarget();
        ASSERT_EQ(f.last().kind, Kind::Release);
        EXPECT_TRUE(f.last().released.empty());
        EXPECT_EQ(nb.resident(), 3u);
        g->bindTarget(img.get());
        g->render(s.mesh.get(), nullptr);
    }  // the scene's last references go here
    g->releaseTarget();
    ASSERT_EQ(f.last().kind, Kind::Release);
    EXPECT_EQ(sorted(f.last().released), sorted(ids));
    EXPECT_EQ(nb.resident(), 0u);
    // Each id is named once.
    g->bindTarget(img.get());
    g->releaseTarget();
    EXPECT_TRUE(f.last().released.empty());
}

// ---- Deformed meshes ----

namespace {

/// A SkinnedMesh of four vertices, positions (-2, -2, 0) .. (2, 2, 0) with
/// scale 0.5 and bias (1, 0, 0): (0, -1, 0), (2, -1, 0), (0, 1, 0), (2, 1, 0).
/// Bone a holds all four vertices, bone b (same weight) vertices 0 and 1.
struct SkinScene {
    Ref<VertexBuffer> vb = frametest::vertexBuffer({-2, -2, 0, 2, -2, 0, -2, 2, 0, 2, 2, 0}, 0.5f, {1, 0, 0});
    Ref<Group> skeleton = new Group();
    Ref<Group> a = new Group(), b = new Group();
    Ref<SkinnedMesh> mesh;
    SkinScene() {
        skeleton->addChild(a.get());
        skeleton->addChild(b.get());
        const int lengths[] = {4};
        mesh = new SkinnedMesh(vb.get(), Ref<IndexBuffer>(new TriangleStripArray(0, lengths)).get(),
                               Ref<Appearance>(new Appearance()).get(), skeleton.get());
        mesh->addTransform(a.get(), 1, 0, 4);
        mesh->addTransform(b.get(), 1, 0, 2);
    }
};

// The CPU-deformed vertices come in the deformer's order (the one-bone
// vertices 2 and 3, then the two-bone vertices 0 and 1), so the draw's
// triangles are remapped: the strip's own list 2 0 1, 3 2 1 (provoking
// vertex first) becomes 0 2 3, 1 0 3.
const std::vector<std::uint32_t> kStripTriangles{2, 0, 1, 3, 2, 1};
const std::vector<std::uint32_t> kSkinSceneSlots{2, 3, 0, 1};  // slot of mesh vertex v

/// The slot of each mesh vertex as the last draw's triangles give it,
/// corner by corner against the strip's own list (each vertex one slot).
std::vector<std::uint32_t> slotsOf(const NullBackend& nb, const Draw& d) {
    const auto& remapped = nb.lastTriangles(d.indices.id, d.indices.vertexOrder);
    std::vector<std::uint32_t> slot(4, 99);
    EXPECT_EQ(remapped.size(), kStripTriangles.size());
    for (std::size_t i = 0; i < std::min(remapped.size(), kStripTriangles.size()); ++i) {
        std::uint32_t& s = slot[kStripTriangles[i]];
        EXPECT_TRUE(s == 99 || s == remapped[i]) << "corner " << i;
        s = remapped[i];
    }
    return slot;
}

/// Vertex v of a stream in the mesh's order (a MorphingMesh's).
void expectXyz(const std::vector<float>& s, int v, float x, float y, float z) {
    ASSERT_GE(s.size(), static_cast<std::size_t>(v) * 3 + 3);
    EXPECT_NEAR(s[v * 3], x, 1e-5f) << "vertex " << v;
    EXPECT_NEAR(s[v * 3 + 1], y, 1e-5f) << "vertex " << v;
    EXPECT_NEAR(s[v * 3 + 2], z, 1e-5f) << "vertex " << v;
}

/// Mesh vertex v of the last draw's positions, found through its triangles.
void expectXyz(const NullBackend& nb, const Draw& d, std::uint32_t v, float x, float y, float z) {
    const auto& s = nb.lastStreams(d.vertices.owner)[POSITIONS];
    const std::size_t at = slotsOf(nb, d)[v];
    ASSERT_GE(s.size(), at * 3 + 3);
    EXPECT_NEAR(s[at * 3], x, 1e-5f) << "vertex " << v;
    EXPECT_NEAR(s[at * 3 + 1], y, 1e-5f) << "vertex " << v;
    EXPECT_NEAR(s[at * 3 + 2], z, 1e-5f) << "vertex " << v;
}

}  // namespace

TEST_F(Graphics3DNull, SkinnedMeshDeformedOnTheCpu) {
    // JSR-184 1.1, SkinnedMesh: v' = sum_i w_i M_i B_i v with the weights
    // normalised. Bone a moves by (1, 0, 0), bone b by (0, 2, 0): vertices
    // 0 and 1 (half each) move by (0.5, 1, 0), vertices 2 and 3 by (1, 0, 0).
    g->setSkinningMode(Graphics3D::SKINNING_CPU);
    begin();
    SkinScene s;
    s.a->setTranslation(1, 0, 0);
    s.b->setTranslation(0, 2, 0);
    g->render(s.mesh.get(), nullptr);
    const Draw& d = f.last().list.draws.at(0);
    EXPECT_EQ(d.vertices.source, VertexSource::Deformed);
    EXPECT_EQ(d.vertices.owner, s.mesh->getObjectId());
    EXPECT_EQ(d.indices.vertexOrder, s.mesh->getObjectId());
    EXPECT_EQ(nb.lastTriangles(d.indices.id, d.indices.vertexOrder),
              (std::vector<std::uint32_t>{0, 2, 3, 1, 0, 3}));
    EXPECT_EQ(slotsOf(nb, d), kSkinSceneSlots);
    expectXyz(nb, d, 0, 0.5f, 0.0f, 0.0f);
    expectXyz(nb, d, 1, 2.5f, 0.0f, 0.0f);
    expectXyz(nb, d, 2, 1.0f, 1.0f, 0.0f);
    expectXyz(nb, d, 3, 3.0f, 1.0f, 0.0f);
    // Deformed positions are already scaled and biased.
    const DrawUniforms& u = uniformsOf(f.last(), 0);
    EXPECT_EQ(u.positionScaleBias[0], 0.0f);
    EXPECT_EQ(u.positionScaleBias[3], 1.0f);
}

TEST_F(Graphics3DNull, SkinnedMeshReReadOnlyWhenThePoseChanges) {
    g->setSkinningMode(Graphics3D::SKINNING_CPU);
    begin();
    SkinScene s;
    g->render(s.mesh.get(), nullptr);
    const std::uint64_t v1 = f.last().list.draws[0].vertices.version;
    expectXyz(nb, f.last().list.draws[0], 3, 2.0f, 1.0f, 0.0f);  // at rest
    g->render(s.mesh.get(), nullptr);
    EXPECT_EQ(f.last().list.draws[0].vertices.version, v1);
    EXPECT_EQ(nb.uploads().vertices, 1);
    s.a->setTranslation(0, 0, 1);
    g->render(s.mesh.get(), nullptr);
    EXPECT_GT(f.last().list.draws[0].vertices.version, v1);
    EXPECT_EQ(nb.uploads().vertices, 2);
    EXPECT_EQ(nb.uploads().indices, 1);  // the same order: the remapped copy is kept
    expectXyz(nb, f.last().list.draws[0], 3, 2.0f, 1.0f, 1.0f);
    expectXyz(nb, f.last().list.draws[0], 0, 0.0f, -1.0f, 0.5f);
}

TEST_F(Graphics3DNull, SkinnedMeshStaticStreamsAndTrianglesFollowTheDeformedOrder) {
    g->setSkinningMode(Graphics3D::SKINNING_CPU);
    begin();
    {
        SkinScene s;
        // Colours and texture coordinates of vertex v: v * 10 + component.
        s.vb->setColors(frametest::bytes(4, {0, 1, 2, 3, 10, 11, 12, 13, 20, 21, 22, 23, 30, 31, 32, 33}).get());
        const std::array<float, 3> zero{};
        s.vb->setTexCoords(0, frametest::shorts(2, {0, 1, 10, 11, 20, 21, 30, 31}).get(), 1.0f, zero);
        g->render(s.mesh.get(), nullptr);
        const Draw& d = f.last().list.draws.at(0);
        ASSERT_EQ(slotsOf(nb, d), kSkinSceneSlots);
        const auto& streams = nb.lastStreams(s.mesh->getObjectId());
        ASSERT_EQ(streams[COLORS].size(), 16u);
        ASSERT_EQ(streams[TEXCOORDS0].size(), 12u);
        for (std::uint32_t v = 0; v < 4; ++v) {
            const std::size_t at = kSkinSceneSlots[v];
            for (std::size_t k = 0; k < 4; ++k)
                EXPECT_NEAR(streams[COLORS][at * 4 + k], static_cast<float>(v * 10 + k) / 255.0f, 1e-6f) << v;
            for (std::size_t k = 0; k < 2; ++k)
                EXPECT_EQ(streams[TEXCOORDS0][at * 3 + k], static_cast<float>(v * 10 + k)) << v;
        }
        // The colours are converted once per change of their array (or of
        // the order), not at every pose; an edit is read.
        s.a->setTranslation(1, 0, 0);
        g->render(s.mesh.get(), nullptr);
        EXPECT_NEAR(nb.lastStreams(s.mesh->getObjectId())[COLORS][kSkinSceneSlots[3] * 4], 30.0f / 255.0f, 1e-6f);
        const std::int8_t red[] = {100, 0, 0, 0};
        s.vb->colors()->set(3, 1, std::span<const std::int8_t>(red));
        g->render(s.mesh.get(), nullptr);
        EXPECT_NEAR(nb.lastStreams(s.mesh->getObjectId())[COLORS][kSkinSceneSlots[3] * 4], 100.0f / 255.0f, 1e-6f);
        // Bone b on vertices 2 and 3 too: one influence set, the mesh's own
        // order, so the IndexBuffer's triangles as they are (a new copy).
        s.mesh->addTransform(s.b.get(), 1, 2, 2);
        g->render(s.mesh.get(), nullptr);
        const Draw& same = f.last().list.draws.at(0);
        EXPECT_EQ(same.indices.vertexOrder, 0u);
        EXPECT_EQ(nb.lastTriangles(same.indices.id), kStripTriangles);
        EXPECT_EQ(nb.uploads().indices, 2);
        EXPECT_NEAR(nb.lastStreams(s.mesh->getObjectId())[COLORS][4], 10.0f / 255.0f, 1e-6f);
    }
    // The remapped copy goes with the mesh.
    g->releaseTarget();
    EXPECT_EQ(nb.resident(), 0u);
}

TEST_F(Graphics3DNull, SkinnedMeshesSharingAnIndexBufferEachDrawItInTheirOwnOrder) {
    // Two SkinnedMeshes on one VertexBuffer and IndexBuffer: the first with
    // SkinScene's influences (its own order 2 3 0 1), the second with one
    // bone on every vertex (the mesh's order). Each draw gets its triangles:
    // one copy per (IndexBuffer, vertex order).
    g->setSkinningMode(Graphics3D::SKINNING_CPU);
    begin();
    SkinScene s;
    Ref<Group> skeleton = new Group(), bone = new Group();
    skeleton->addChild(bone.get());
    Ref<SkinnedMesh> plain = new SkinnedMesh(s.vb.get(), s.mesh->getIndexBuffer(0).get(),
                                             Ref<Appearance>(new Appearance()).get(), skeleton.get());
    plain->addTransform(bone.get(), 1, 0, 4);
    g->render(s.mesh.get(), nullptr);
    const IndexRef first = f.last().list.draws.at(0).indices;
    g->render(plain.get(), nullptr);
    const IndexRef second = f.last().list.draws.at(0).indices;
    EXPECT_EQ(first.id, second.id);
    EXPECT_EQ(first.vertexOrder, s.mesh->getObjectId());
    EXPECT_EQ(second.vertexOrder, 0u);
    EXPECT_EQ(nb.lastTriangles(first.id, first.vertexOrder), (std::vector<std::uint32_t>{0, 2, 3, 1, 0, 3}));
    EXPECT_EQ(nb.lastTriangles(second.id), kStripTriangles);
    EXPECT_EQ(nb.uploads().indices, 2);
    g->render(s.mesh.get(), nullptr);  // both copies kept
    EXPECT_EQ(nb.uploads().indices, 2);
}

TEST_F(Graphics3DNull, SkinnedMeshForTheGpuHandsTheKernelInputs) {
    g->setSkinningMode(Graphics3D::SKINNING_COMPUTE);
    begin();
    SkinScene s;
    s.a->setTranslation(1, 0, 0);
    g->render(s.mesh.get(), nullptr);
    const Draw& d = f.last().list.draws.at(0);
    EXPECT_EQ(d.vertices.source, VertexSource::GpuSkinned);
    EXPECT_NE(d.vertices.inputVersion, 0u);
    EXPECT_TRUE(d.vertices.present[POSITIONS]);
    EXPECT_FALSE(d.vertices.present[NORMALS]);
    EXPECT_EQ(nb.uploads().skinVertices, 4);
    // The kernel writes the positions: the host hands none.
    EXPECT_TRUE(nb.lastStreams(s.mesh->getObjectId())[POSITIONS].empty());
    EXPECT_EQ(uniformsOf(f.last(), 0).positionScaleBias[3], 1.0f);
    // A new pose: new version, same static inputs.
    const VertexRef before = d.vertices;
    s.a->setTranslation(2, 0, 0);
    g->render(s.mesh.get(), nullptr);
    EXPECT_GT(f.last().list.draws[0].vertices.version, before.version);
    EXPECT_EQ(f.last().list.draws[0].vertices.inputVersion, before.inputVersion);
    EXPECT_EQ(nb.uploads().skinVertices, 8);
}

namespace {

/// A MorphingMesh: base quad (-1..1) red, one target moved by (2, 0, 0) and green.
Ref<MorphingMesh> morphing(float weight) {
    frametest::Quad base = frametest::quad();
    base.vb->setColors(frametest::bytes(4, {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255}).get());
    Ref<VertexBuffer> target = frametest::vertexBuffer({1, -1, 0, 3, -1, 0, 1, 1, 0, 3, 1, 0});
    target->setColors(frametest::bytes(4, {0, 255, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255}).get());
    const Ref<VertexBuffer> targets[] = {target};
    Ref<MorphingMesh> m(new MorphingMesh(base.vb.get(), targets, base.ib.get(), Ref<Appearance>(new Appearance()).get()));
    const float w[] = {weight};
    m->setWeights(w);
    return m;
}

}  // namespace

TEST_F(Graphics3DNull, MorphingMeshDeformedOnTheCpu) {
    // B + w (T - B) with w = 0.5: positions move by (1, 0, 0), colours (0.5, 0.5, 0, 1).
    g->setSkinningMode(Graphics3D::SKINNING_CPU);
    begin();
    Ref<MorphingMesh> m = morphing(0.5f);
    g->render(m.get(), nullptr);
    const Draw& d = f.last().list.draws.at(0);
    EXPECT_EQ(d.vertices.source, VertexSource::Deformed);
    EXPECT_TRUE(d.vertices.present[COLORS]);
    const auto& streams = nb.lastStreams(m->getObjectId());
    expectXyz(streams[POSITIONS], 0, 0.0f, -1.0f, 0.0f);
    expectXyz(streams[POSITIONS], 3, 2.0f, 1.0f, 0.0f);
    ASSERT_EQ(streams[COLORS].size(), 16u);
    EXPECT_NEAR(streams[COLORS][0], 0.5f, 1e-6f);
    EXPECT_NEAR(streams[COLORS][1], 0.5f, 1e-6f);
    EXPECT_NEAR(streams[COLORS][2], 0.0f, 1e-6f);
    EXPECT_NEAR(streams[COLORS][3], 1.0f, 1e-6f);
    // New weights: re-read.
    const float w[] = {1.0f};
    m->setWeights(w);
    g->render(m.get(), nullptr);
    EXPECT_EQ(nb.uploads().vertices, 2);
    expectXyz(nb.lastStreams(m->getObjectId())[POSITIONS], 0, 1.0f, -1.0f, 0.0f);
}

TEST_F(Graphics3DNull, MorphingMeshForTheGpuHandsTheKernelInputs) {
    g->setSkinningMode(Graphics3D::SKINNING_COMPUTE);
    begin();
    Ref<MorphingMesh> m = morphing(0.25f);
    g->render(m.get(), nullptr);
    const Draw& d = f.last().list.draws.at(0);
    EXPECT_EQ(d.vertices.source, VertexSource::GpuMorphed);
    EXPECT_TRUE(d.vertices.present[COLORS]);
    EXPECT_EQ(nb.uploads().morphVertices, 4);
    EXPECT_EQ(nb.uploads().skinVertices, 0);
    // The kernel writes every morphed stream, colours included.
    EXPECT_TRUE(nb.lastStreams(m->getObjectId())[POSITIONS].empty());
    EXPECT_TRUE(nb.lastStreams(m->getObjectId())[COLORS].empty());
}

TEST_F(Graphics3DNull, SwitchingTheSkinningModeReReadsTheMesh) {
    begin();
    SkinScene s;
    g->setSkinningMode(Graphics3D::SKINNING_CPU);
    g->render(s.mesh.get(), nullptr);
    g->setSkinningMode(Graphics3D::SKINNING_COMPUTE);
    g->render(s.mesh.get(), nullptr);
    EXPECT_EQ(f.last().list.draws[0].vertices.source, VertexSource::GpuSkinned);
    EXPECT_EQ(nb.uploads().vertices, 2);
    g->setSkinningMode(Graphics3D::SKINNING_CPU);
    g->render(s.mesh.get(), nullptr);
    EXPECT_EQ(f.last().list.draws[0].vertices.source, VertexSource::Deformed);
    EXPECT_EQ(nb.uploads().vertices, 3);
    expectXyz(nb, f.last().list.draws[0], 1, 2.0f, -1.0f, 0.0f);
}
