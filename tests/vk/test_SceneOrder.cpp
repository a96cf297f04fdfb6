// Golden tests of what gets drawn and in which order (JSR-184 1.1,
// Graphics3D.render and Node): Appearance layers, opaque before blended, render(World) vs
// render(Node, Transform) vs immediate mode with scope, near-plane
// clipping, SkinnedMesh and MorphingMesh drawn from deformed vertices.
// Graphics3D's exceptions are CPU tests (tests/unit/test_Graphics3DNullBackend.cpp).
#include "SceneKit.h"
#include "VkTestSupport.h"

#include <cmath>

using namespace m3g;
using m3gtest::begin;
using m3gtest::makeQuad;
using m3gtest::Quad;
using m3gtest::Rgba;
using m3gtest::translation;
using m3gtest::VkTest;

namespace {

const Rgba kRed{255, 0, 0, 255}, kGreen{0, 255, 0, 255}, kBlue{0, 0, 255, 255}, kClear{0, 0, 0, 0};

/// A World with an identity camera (active) and no background.
Ref<World> worldWithCamera() {
    Ref<World> world(new World());
    Ref<Camera> cam(new Camera());
    world->addChild(cam.get());
    world->setActiveCamera(cam.get());
    return world;
}

Ref<Appearance> flatColour(int layer, int blending, bool depthTest) {
    Ref<Appearance> a(new Appearance());
    a->setLayer(layer);
    Ref<CompositingMode> cm(new CompositingMode());
    cm->setBlending(blending);
    cm->setDepthTestEnable(depthTest);
    a->setCompositingMode(cm.get());
    return a;
}

Ref<Mesh> mesh(const Quad& q, std::uint32_t argb, Appearance* app) {
    q.vb->setDefaultColor(static_cast<int>(argb));
    return Ref<Mesh>(new Mesh(q.vb.get(), q.ib.get(), app));
}

}  // namespace

TEST_F(VkTest, AppearanceLayerOrder) {
    // Depth test off so that the drawing order decides. Left: red (layer 1)
    // added before green (layer 0): red is drawn last. Right: blue (layer 0)
    // added before white (layer -5): blue is drawn last.
    auto img = target(64, 64);
    Ref<World> world = worldWithCamera();
    auto l1 = flatColour(1, CompositingMode::REPLACE, false), l0 = flatColour(0, CompositingMode::REPLACE, false),
         lm5 = flatColour(-5, CompositingMode::REPLACE, false);
    Ref<Mesh> meshes[4] = {mesh(makeQuad(-1, -1, 0, 1), 0xFFFF0000u, l1.get()),
                           mesh(makeQuad(-1, -1, 0, 1), 0xFF00FF00u, l0.get()),
                           mesh(makeQuad(0, -1, 1, 1), 0xFF0000FFu, l0.get()),
                           mesh(makeQuad(0, -1, 1, 1), 0xFFFFFFFFu, lm5.get())};
    for (auto& m : meshes) world->addChild(m.get());
    Graphics3D* g = Graphics3D::getInstance();
    g->bindTarget(img.get());
    g->render(world.get());
    g->releaseTarget();
    EXPECT_PIXEL_TOL(*img, 16, 32, 0, kRed);
    EXPECT_PIXEL_TOL(*img, 48, 32, 0, kBlue);
    expectGolden(*img, "order_layers", 3, 0.0);
}

TEST_F(VkTest, OpaqueBeforeBlendedWithinLayer) {
    // Left, same layer: 50% blue (ALPHA) added before opaque red; the opaque
    // one is drawn first, so the blue blends over it: (127, 0, 128). Right:
    // the blended one in layer -1 is drawn before the opaque red of layer 0,
    // which then covers it.
    auto img = target(64, 64);
    Ref<World> world = worldWithCamera();
    auto blended = flatColour(0, CompositingMode::ALPHA, false), opaque = flatColour(0, CompositingMode::REPLACE, false),
         blendedBelow = flatColour(-1, CompositingMode::ALPHA, false);
    Ref<Mesh> meshes[4] = {mesh(makeQuad(-1, -1, 0, 1), 0x800000FFu, blended.get()),
                           mesh(makeQuad(-1, -1, 0, 1), 0xFFFF0000u, opaque.get()),
                           mesh(makeQuad(0, -1, 1, 1), 0x800000FFu, blendedBelow.get()),
                           mesh(makeQuad(0, -1, 1, 1), 0xFFFF0000u, opaque.get())};
    for (auto& m : meshes) world->addChild(m.get());
    Graphics3D* g = Graphics3D::getInstance();
    g->bindTarget(img.get());
    g->render(world.get());
    g->releaseTarget();
    const double a = 0x80 / 255.0;
    EXPECT_PIXEL(*img, 16, 32, Rgba{m3gtest::level(1 - a), 0, m3gtest::level(a), -1});
    EXPECT_PIXEL_TOL(*img, 48, 32, 0, Rgba{255, 0, 0, -1});
    expectGolden(*img, "order_opaque_before_blended", 3, 0.0);
}

TEST_F(VkTest, RenderNodeIgnoresOwnTransformAppliesChildren) {
    // render(Node, Transform): the node's own transformation is ignored, its
    // children's apply, and the given transform is the node -> world one.
    //  red mesh, translation (0.5, 0.5) ignored: at the centre (24..39);
    //  the same with the transform (0, -0.5): 24..39 x 40..55;
    //  a group translated (0, 0.5) (ignored) holding a green mesh
    //  translated (-0.5, 0): 8..23 x 24..39;
    //  blue in immediate mode with the transform (0.5, 0.5): 40..55 x 8..23.
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Appearance> app(new Appearance());
    Ref<Mesh> red = mesh(makeQuad(-0.25f, -0.25f, 0.25f, 0.25f), 0xFFFF0000u, app.get());
    red->setTranslation(0.5f, 0.5f, 0);
    g->render(red.get(), nullptr);
    Transform down = translation(0, -0.5f, 0);
    g->render(red.get(), &down);
    Ref<Group> group(new Group());
    group->setTranslation(0, 0.5f, 0);
    Ref<Mesh> green = mesh(makeQuad(-0.25f, -0.25f, 0.25f, 0.25f), 0xFF00FF00u, app.get());
    green->setTranslation(-0.5f, 0, 0);
    group->addChild(green.get());
    g->render(group.get(), nullptr);
    Quad blue = makeQuad(-0.25f, -0.25f, 0.25f, 0.25f);
    blue.vb->setDefaultColor(static_cast<int>(0xFF0000FFu));
    Transform upRight = translation(0.5f, 0.5f, 0);
    g->render(blue.vb.get(), blue.ib.get(), app.get(), &upRight);
    g->releaseTarget();
    EXPECT_PIXEL_TOL(*img, 24, 24, 0, kRed);
    EXPECT_PIXEL_TOL(*img, 39, 39, 0, kRed);
    EXPECT_PIXEL_TOL(*img, 32, 48, 0, kRed);
    EXPECT_PIXEL_TOL(*img, 48, 16, 0, kBlue);
    EXPECT_PIXEL_TOL(*img, 16, 32, 0, kGreen);
    EXPECT_PIXEL_TOL(*img, 16, 16, 0, kClear);  // where the group's own translation would put it
    EXPECT_PIXEL_TOL(*img, 52, 12, 0, kBlue);
    EXPECT_PIXEL_TOL(*img, 40, 32, 0, kClear);
    expectGolden(*img, "order_render_node", 3, 0.0);
}

TEST_F(VkTest, ImmediateModeScope) {
    // Camera scope 1: an immediate draw with scope 2 is skipped, with scope 3 drawn.
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    cam->setScope(1);
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Appearance> app(new Appearance());
    Quad left = makeQuad(-1, -1, 0, 1), right = makeQuad(0, -1, 1, 1);
    left.vb->setDefaultColor(static_cast<int>(0xFFFF0000u));
    right.vb->setDefaultColor(static_cast<int>(0xFF00FF00u));
    g->render(left.vb.get(), left.ib.get(), app.get(), nullptr, 2);
    g->render(right.vb.get(), right.ib.get(), app.get(), nullptr, 3);
    g->releaseTarget();
    EXPECT_PIXEL_TOL(*img, 16, 32, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 48, 32, 0, kGreen);
    expectGolden(*img, "order_immediate_scope", 3, 0.0);
}

TEST_F(VkTest, NearPlaneClipsTriangle) {
    // Perspective camera, 90 degrees, near 1. A floor triangle at y = -1 with
    // two corners at z = -3 (x = +-2) and one behind the camera at (0, -1, 1).
    // Clipped at the near plane, it covers the screen points whose view ray
    // meets the floor at distance t = -1 / y_ndc in [1, 3] with
    // |x_ndc| t <= (1 + t) / 2; nothing above y_ndc = -1/3 (no wrap-around).
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    cam->setPerspective(90, 1, 1, 100);
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<VertexBuffer> vb(new VertexBuffer());
    const float zero[3] = {0, 0, 0};
    vb->setPositions(m3gtest::positions({{-2, -1, -3}, {2, -1, -3}, {0, -1, 1}}).get(), m3gtest::kPositionScale, zero);
    vb->setDefaultColor(static_cast<int>(0xFFFFFFFFu));
    const int lengths[] = {3};
    Ref<IndexBuffer> ib(new TriangleStripArray(0, lengths));
    Ref<PolygonMode> pm(new PolygonMode());
    pm->setCulling(PolygonMode::CULL_NONE);
    Ref<Appearance> app(new Appearance());
    app->setPolygonMode(pm.get());
    g->render(vb.get(), ib.get(), app.get(), nullptr);
    g->releaseTarget();
    auto inside = [](double px, double py) {
        const double x = px / 32.0 - 1.0, y = 1.0 - py / 32.0;
        if (y >= 0) return false;
        const double t = -1.0 / y;
        return t >= 1.0 && t <= 3.0 && std::abs(x) * t <= (1.0 + t) / 2.0;
    };
    int checked = 0, bad = 0;
    for (int py = 0; py < 64; ++py)
        for (int px = 0; px < 64; ++px) {
            // Only pixels whose whole neighbourhood agrees (away from edges).
            const bool centre = inside(px + 0.5, py + 0.5);
            bool stable = true;
            for (double dy : {-1.0, 0.0, 2.0})
                for (double dx : {-1.0, 0.0, 2.0}) stable = stable && inside(px + dx, py + dy) == centre;
            if (!stable) continue;
            ++checked;
            const auto r = m3gtest::pixelNear(*img, px, py, centre ? Rgba{255, 255, 255, 255} : kClear, 0);
            if (!r && ++bad <= 5) ADD_FAILURE() << r.message();
        }
    EXPECT_EQ(bad, 0);
    EXPECT_GT(checked, 3500);
    expectGolden(*img, "order_near_plane_clip", 3, 0.01);
}

TEST_F(VkTest, SkinnedMeshDrawsDeformedVertices) {
    // All four vertices bound to one bone at rest; moving the bone by
    // (0.5, 0, 0) moves the drawn quad from 24..39 to 40..55.
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Quad q = makeQuad(-0.25f, -0.25f, 0.25f, 0.25f);
    q.vb->setDefaultColor(static_cast<int>(0xFFFF0000u));
    Ref<Appearance> app(new Appearance());
    Ref<Group> skeleton(new Group());
    Ref<Group> bone(new Group());
    skeleton->addChild(bone.get());
    Ref<SkinnedMesh> skinned(new SkinnedMesh(q.vb.get(), q.ib.get(), app.get(), skeleton.get()));
    skinned->addTransform(bone.get(), 1, 0, 4);
    bone->setTranslation(0.5f, 0, 0);
    g->render(skinned.get(), nullptr);
    g->releaseTarget();
    EXPECT_PIXEL_TOL(*img, 40, 24, 0, kRed);
    EXPECT_PIXEL_TOL(*img, 55, 39, 0, kRed);
    EXPECT_PIXEL_TOL(*img, 32, 32, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 56, 32, 0, kClear);
    expectGolden(*img, "order_skinned_mesh", 3, 0.0);
}

TEST_F(VkTest, MorphingMeshDrawsWeightedTarget) {
    // Base: red quad at x -0.75..-0.25; target: green quad at 0.25..0.75.
    // Weight 1 draws the target (positions and colours); weight 0.5 on a
    // second mesh (bottom half) draws the average, yellow-ish at the middle.
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Appearance> app(new Appearance());
    auto build = [&](float y0, float y1, float weight) {
        Quad base = makeQuad(-0.75f, y0, -0.25f, y1);
        m3gtest::setColors(*base.vb, {0xFFFF0000u, 0xFFFF0000u, 0xFFFF0000u, 0xFFFF0000u});
        Quad target = makeQuad(0.25f, y0, 0.75f, y1);
        m3gtest::setColors(*target.vb, {0xFF00FF00u, 0xFF00FF00u, 0xFF00FF00u, 0xFF00FF00u});
        const Ref<VertexBuffer> targets[] = {target.vb};
        Ref<MorphingMesh> m(new MorphingMesh(base.vb.get(), targets, base.ib.get(), app.get()));
        const float w[] = {weight};
        m->setWeights(w);
        return m;
    };
    auto full = build(0.0f, 1.0f, 1.0f);
    auto half = build(-1.0f, 0.0f, 0.5f);
    g->render(full.get(), nullptr);
    g->render(half.get(), nullptr);
    g->releaseTarget();
    EXPECT_PIXEL_TOL(*img, 48, 16, 0, kGreen);
    EXPECT_PIXEL_TOL(*img, 16, 16, 0, kClear);
    EXPECT_PIXEL(*img, 32, 48, Rgba{128, 128, 0, 255});  // 0.5 red + 0.5 green at x -0.25..0.25
    EXPECT_PIXEL_TOL(*img, 12, 48, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 52, 48, 0, kClear);
    expectGolden(*img, "order_morphing_mesh", 3, 0.0);
}
