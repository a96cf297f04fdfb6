// Group::pick through a camera (JSR-184 1.1, Group.pick): the near-to-far ray,
// distances, and scaled Sprite3Ds. Expectations worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <m3g/Camera.h>
#include <m3g/CompositingMode.h>
#include <m3g/Image2D.h>
#include <m3g/Sprite3D.h>
#include <m3g/World.h>

#include "PickTestScenes.h"

using namespace m3g;
using namespace picktest;

namespace {

/// (-50,-50,z) (100,-50,z) (-50,100,z): CCW from +z, covers x + y <= 50;
/// texture coordinates = (x, y), so S/T give the hit point.
Ref<Mesh> wall(std::int16_t z, Appearance* app = nullptr) {
    Ref<VertexBuffer> vb = positionsVB({-50, -50, z, 100, -50, z, -50, 100, z});
    vb->setTexCoords(0, shortArray({-50, -50, 100, -50, -50, 100}, 2), 1.0f, {});
    Ref<Appearance> a = app ? Ref<Appearance>(app) : Ref<Appearance>(new Appearance());
    return new Mesh(vb, triangles({0, 1, 2}), a);
}

std::vector<float> ray(const RayIntersection& ri) {
    std::vector<float> r(6);
    ri.getRay(r);
    return r;
}

void expectRay(const RayIntersection& ri, const std::vector<float>& expected, float tol = 1e-4f) {
    const std::vector<float> r = ray(ri);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(r[i], expected[i], tol) << "ray component " << i;
}

/// World with a camera at the origin: perspective fovy 90, aspect 1, near 1, far 10.
struct Scene {
    Ref<World> world = new World();
    Ref<Camera> camera = new Camera();
    Scene() {
        camera->setPerspective(90, 1, 1, 10);
        world->addChild(camera);
        world->setActiveCamera(camera);
    }
};

/// A 2x2 RGBA image whose top-left pixel has alpha 0, the others 255.
Ref<Image2D> holeImage() {
    const std::uint8_t px[] = {255, 0, 0, 0, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    return new Image2D(Image2D::RGBA, 2, 2, px);
}

/// A scaled 1x1 sprite at (0, 0, z): at depth 5 under the scene's camera it
/// covers NDC [-0.1, 0.1]^2 (half size 0.5 / 5 with P00 = P11 = 1), i.e.
/// viewport [0.45, 0.55]^2.
Ref<Sprite3D> sprite(float z, bool scaled = true, Appearance* app = nullptr) {
    Ref<Appearance> a = app ? Ref<Appearance>(app) : Ref<Appearance>(new Appearance());
    Ref<Sprite3D> s = new Sprite3D(scaled, holeImage(), a);
    s->setTranslation(0, 0, z);
    return s;
}

}  // namespace

TEST(PickCamera, PerspectiveCentre) {
    Scene s;
    Ref<Mesh> m = wall(-5);
    s.world->addChild(m);
    RayIntersection ri;
    // Ray from (0,0,-1) (near) to (0,0,-10) (far); z = -5 at t = 4/9.
    ASSERT_TRUE(s.world->pick(-1, 0.5f, 0.5f, s.camera, &ri));
    EXPECT_EQ(ri.getIntersected().get(), m.get());
    EXPECT_NEAR(ri.getDistance(), 4.0f / 9.0f, 1e-5f);
    expectRay(ri, {0, 0, -1, 0, 0, -9});
    EXPECT_NEAR(ri.getTextureS(0), 0.0f, 1e-4f);
    EXPECT_NEAR(ri.getTextureT(0), 0.0f, 1e-4f);
}

TEST(PickCamera, PerspectiveOffCentre) {
    Scene s;
    s.world->addChild(wall(-5));
    RayIntersection ri;
    // (0.75, 0.25) -> NDC (0.5, 0.5); with tan(45) = 1 the near point is
    // (0.5, 0.5, -1) and the far point (5, 5, -10); z = -5 at t = 4/9, at
    // (2.5, 2.5).
    ASSERT_TRUE(s.world->pick(-1, 0.75f, 0.25f, s.camera, &ri));
    expectRay(ri, {0.5f, 0.5f, -1, 4.5f, 4.5f, -9});
    EXPECT_NEAR(ri.getDistance(), 4.0f / 9.0f, 1e-5f);
    EXPECT_NEAR(ri.getTextureS(0), 2.5f, 1e-3f);
    EXPECT_NEAR(ri.getTextureT(0), 2.5f, 1e-3f);
    // Outside the unit square is allowed: (1.5, 0.5) -> NDC x = 2.
    ASSERT_TRUE(s.world->pick(-1, 1.5f, 0.5f, s.camera, &ri));
    expectRay(ri, {2, 0, -1, 18, 0, -9}, 1e-3f);
}

TEST(PickCamera, AspectAndFieldOfView) {
    Scene s;
    s.camera->setPerspective(60, 2, 2, 8);
    s.world->addChild(wall(-5));
    RayIntersection ri;
    // (1, 0) -> NDC (1, 1): near point (aspect h n, h n, -n) with h = tan 30,
    // far point the same times f / n = 4.
    const float h = std::tan(30.0f * 3.14159265f / 180.0f);
    ASSERT_TRUE(s.world->pick(-1, 1.0f, 0.0f, s.camera, &ri));
    expectRay(ri, {4 * h, 2 * h, -2, 12 * h, 6 * h, -6}, 1e-3f);
    EXPECT_NEAR(ri.getDistance(), 0.5f, 1e-5f);  // z = -5 halfway from -2 to -8
}

TEST(PickCamera, DistanceIsZeroAtNearAndOneAtFar) {
    {
        Scene s;
        s.world->addChild(wall(-10));  // on the far plane
        RayIntersection ri;
        ASSERT_TRUE(s.world->pick(-1, 0.5f, 0.5f, s.camera, &ri));
        EXPECT_NEAR(ri.getDistance(), 1.0f, 1e-5f);
    }
    {
        // Between the eye and the near plane: t < 0, not hit.
        Scene s;
        Ref<VertexBuffer> vb = positionsVB({-50, -50, -1, 100, -50, -1, -50, 100, -1}, 0.5f);  // z = -0.5
        s.world->addChild(new Mesh(vb, triangles({0, 1, 2}), new Appearance()));
        EXPECT_FALSE(s.world->pick(-1, 0.5f, 0.5f, s.camera, nullptr));
    }
    {
        // Just behind the near plane: z = -1.09 -> t = 0.09 / 9 = 0.01.
        Scene s;
        Ref<VertexBuffer> vb = positionsVB({-50, -50, -109, 100, -50, -109, -50, 100, -109}, 0.01f);
        s.world->addChild(new Mesh(vb, triangles({0, 1, 2}), new Appearance()));
        RayIntersection ri;
        ASSERT_TRUE(s.world->pick(-1, 0.5f, 0.5f, s.camera, &ri));
        EXPECT_NEAR(ri.getDistance(), 0.01f, 1e-5f);
    }
}

TEST(PickCamera, CameraTransformAndPickedGroupSpace) {
    Scene s;
    s.camera->setTranslation(1, 2, 10);
    s.world->addChild(wall(-5));
    RayIntersection ri;
    // Near point (1, 2, 9), far (1, 2, 0): z = -5 is beyond the far plane at t = 14/9.
    ASSERT_TRUE(s.world->pick(-1, 0.5f, 0.5f, s.camera, &ri));
    expectRay(ri, {1, 2, 9, 0, 0, -9});
    EXPECT_NEAR(ri.getDistance(), 14.0f / 9.0f, 1e-5f);

    // Camera and mesh both turned 90 degrees about Y: the same picture, the
    // ray now along -x.
    Scene r;
    r.camera->setOrientation(90, 0, 1, 0);
    Ref<Mesh> m = wall(-5);
    m->setOrientation(90, 0, 1, 0);
    r.world->addChild(m);
    ASSERT_TRUE(r.world->pick(-1, 0.5f, 0.5f, r.camera, &ri));
    expectRay(ri, {-1, 0, 0, -9, 0, 0});
    EXPECT_NEAR(ri.getDistance(), 4.0f / 9.0f, 1e-5f);

    // Picking a sub-group reports the ray in its coordinates.
    Scene g;
    Ref<Group> sub = new Group();
    sub->setTranslation(0, 0, -2);
    sub->addChild(wall(-3));  // world z = -5
    g.world->addChild(sub);
    ASSERT_TRUE(sub->pick(-1, 0.5f, 0.5f, g.camera, &ri));
    expectRay(ri, {0, 0, 1, 0, 0, -9});
    EXPECT_NEAR(ri.getDistance(), 4.0f / 9.0f, 1e-5f);
}

TEST(PickCamera, Parallel) {
    Scene s;
    s.camera->setParallel(4, 2, 2, 10);  // view volume 8 wide, 4 high
    s.world->addChild(wall(-4));
    RayIntersection ri;
    // (0.75, 0.5) -> NDC x 0.5 -> x = 0.5 * 8 / 2 = 2; the ray runs from
    // (2, 0, -2) to (2, 0, -10); z = -4 at t = 0.25.
    ASSERT_TRUE(s.world->pick(-1, 0.75f, 0.5f, s.camera, &ri));
    expectRay(ri, {2, 0, -2, 0, 0, -8});
    EXPECT_NEAR(ri.getDistance(), 0.25f, 1e-5f);
    EXPECT_NEAR(ri.getTextureS(0), 2.0f, 1e-4f);
    // (0.5, 0) -> NDC y 1 -> y = 2.
    ASSERT_TRUE(s.world->pick(-1, 0.5f, 0.0f, s.camera, &ri));
    expectRay(ri, {0, 2, -2, 0, 0, -8});

    Scene f;
    f.camera->setParallel(4, 2, 2, 10);
    f.world->addChild(wall(-10));
    ASSERT_TRUE(f.world->pick(-1, 0.5f, 0.5f, f.camera, &ri));
    EXPECT_NEAR(ri.getDistance(), 1.0f, 1e-5f);
}

TEST(PickCamera, ScaledSpriteIsHitAsItsScreenRectangle) {
    Scene s;
    Ref<Sprite3D> sp = sprite(-5);
    s.world->addChild(sp);
    RayIntersection ri;
    ASSERT_TRUE(s.world->pick(-1, 0.5f, 0.5f, s.camera, &ri));
    EXPECT_EQ(ri.getIntersected().get(), sp.get());
    EXPECT_NEAR(ri.getDistance(), 4.0f / 9.0f, 1e-5f);  // eye z -5 between -1 and -10
    EXPECT_EQ(ri.getSubmeshIndex(), 0);
    EXPECT_NEAR(ri.getTextureS(0), 0.5f, 1e-4f);
    EXPECT_NEAR(ri.getTextureT(0), 0.5f, 1e-4f);
    EXPECT_EQ(ri.getTextureS(1), 0.0f);
    EXPECT_EQ(ri.getNormalX(), 0.0f);
    EXPECT_EQ(ri.getNormalY(), 0.0f);
    EXPECT_EQ(ri.getNormalZ(), 1.0f);
    expectRay(ri, {0, 0, -1, 0, 0, -9});
    // (0.54, 0.47) -> NDC (0.08, 0.06): 90 % across, 20 % down.
    ASSERT_TRUE(s.world->pick(-1, 0.54f, 0.47f, s.camera, &ri));
    EXPECT_NEAR(ri.getTextureS(0), 0.9f, 1e-3f);
    EXPECT_NEAR(ri.getTextureT(0), 0.2f, 1e-3f);
    // Just outside: NDC x 0.12.
    EXPECT_FALSE(s.world->pick(-1, 0.56f, 0.5f, s.camera, nullptr));
    EXPECT_FALSE(s.world->pick(-1, 0.5f, 0.44f, s.camera, nullptr));
    // Mirrored by a negative crop width: S = 1 - 0.9.
    sp->setCrop(0, 0, -2, 2);
    ASSERT_TRUE(s.world->pick(-1, 0.54f, 0.47f, s.camera, &ri));
    EXPECT_NEAR(ri.getTextureS(0), 0.1f, 1e-3f);
    EXPECT_NEAR(ri.getTextureT(0), 0.2f, 1e-3f);
}

TEST(PickCamera, UnscaledSpritesAreNotHit) {
    Scene s;
    s.world->addChild(sprite(-5, false));
    EXPECT_FALSE(s.world->pick(-1, 0.5f, 0.5f, s.camera, nullptr));
    Ref<Mesh> m = wall(-8);
    s.world->addChild(m);
    RayIntersection ri;
    ASSERT_TRUE(s.world->pick(-1, 0.5f, 0.5f, s.camera, &ri));
    EXPECT_EQ(ri.getIntersected().get(), m.get());
}

TEST(PickCamera, SpriteTexelsBelowTheAlphaThresholdLetTheRayThrough) {
    Scene s;
    Ref<Appearance> app = new Appearance();
    Ref<CompositingMode> cm = new CompositingMode();
    cm->setAlphaThreshold(0.5f);
    app->setCompositingMode(cm);
    Ref<Sprite3D> sp = sprite(-5, true, app);
    Ref<Mesh> behind = wall(-8);
    s.world->addChild(sp);
    s.world->addChild(behind);
    RayIntersection ri;
    // (0.475, 0.475) -> NDC (-0.05, 0.05): the top-left texel, alpha 0.
    ASSERT_TRUE(s.world->pick(-1, 0.475f, 0.475f, s.camera, &ri));
    EXPECT_EQ(ri.getIntersected().get(), behind.get());
    EXPECT_NEAR(ri.getDistance(), 7.0f / 9.0f, 1e-5f);
    // The top-right texel is opaque.
    ASSERT_TRUE(s.world->pick(-1, 0.525f, 0.475f, s.camera, &ri));
    EXPECT_EQ(ri.getIntersected().get(), sp.get());
    // Threshold 0 (or no CompositingMode): every texel counts.
    cm->setAlphaThreshold(0.0f);
    ASSERT_TRUE(s.world->pick(-1, 0.475f, 0.475f, s.camera, &ri));
    EXPECT_EQ(ri.getIntersected().get(), sp.get());
    app->setCompositingMode(nullptr);
    ASSERT_TRUE(s.world->pick(-1, 0.475f, 0.475f, s.camera, &ri));
    EXPECT_EQ(ri.getIntersected().get(), sp.get());
    // Threshold 1 keeps fully opaque texels (alpha 255 = 1.0).
    cm->setAlphaThreshold(1.0f);
    app->setCompositingMode(cm);
    ASSERT_TRUE(s.world->pick(-1, 0.525f, 0.475f, s.camera, &ri));
    EXPECT_EQ(ri.getIntersected().get(), sp.get());
}

TEST(PickCamera, SpriteCandidatesFollowTheMeshRules) {
    Scene s;
    Ref<Sprite3D> sp = sprite(-5);
    s.world->addChild(sp);
    RayIntersection ri;
    ASSERT_TRUE(s.world->pick(-1, 0.5f, 0.5f, s.camera, &ri));
    sp->setScope(2);
    EXPECT_FALSE(s.world->pick(1, 0.5f, 0.5f, s.camera, nullptr));
    EXPECT_TRUE(s.world->pick(2, 0.5f, 0.5f, s.camera, nullptr));
    sp->setPickingEnable(false);
    EXPECT_FALSE(s.world->pick(-1, 0.5f, 0.5f, s.camera, nullptr));
    sp->setPickingEnable(true);
    sp->setAppearance(nullptr);
    EXPECT_FALSE(s.world->pick(-1, 0.5f, 0.5f, s.camera, nullptr));
    // Behind the camera.
    Scene b;
    b.world->addChild(sprite(5));
    EXPECT_FALSE(b.world->pick(-1, 0.5f, 0.5f, b.camera, nullptr));
}

TEST(PickCamera, SpritesAndMeshesCompareByDistance) {
    Scene s;
    Ref<Sprite3D> sp = sprite(-5);
    Ref<Mesh> front = wall(-3);
    s.world->addChild(sp);
    s.world->addChild(front);
    RayIntersection ri;
    ASSERT_TRUE(s.world->pick(-1, 0.5f, 0.5f, s.camera, &ri));
    EXPECT_EQ(ri.getIntersected().get(), front.get());
    EXPECT_NEAR(ri.getDistance(), 2.0f / 9.0f, 1e-5f);
    front->setTranslation(0, 0, -5);  // now at z = -8
    ASSERT_TRUE(s.world->pick(-1, 0.5f, 0.5f, s.camera, &ri));
    EXPECT_EQ(ri.getIntersected().get(), sp.get());
}

TEST(PickCamera, Exceptions) {
    Scene s;
    s.world->addChild(wall(-5));
    try {
        s.world->pick(-1, 0.5f, 0.5f, nullptr, nullptr);
        ADD_FAILURE() << "no exception";
    } catch (const NullPointerException& e) {
        EXPECT_STREQ(e.what(), "Group::pick: camera is null");
    }
    // A camera in another scene graph, or in none.
    Ref<Camera> loose = new Camera();
    loose->setPerspective(90, 1, 1, 10);
    EXPECT_THROW(s.world->pick(-1, 0.5f, 0.5f, loose, nullptr), IllegalStateException);
    Scene other;
    try {
        s.world->pick(-1, 0.5f, 0.5f, other.camera, nullptr);
        ADD_FAILURE() << "no exception";
    } catch (const IllegalStateException& e) {
        EXPECT_NE(std::string(e.what()).find("Group::pick"), std::string::npos) << e.what();
    }
    // A group below the camera's root is fine; the camera need not be inside it.
    Ref<Group> sub = new Group();
    s.world->addChild(sub);
    EXPECT_FALSE(sub->pick(-1, 0.5f, 0.5f, s.camera, nullptr));
    // Singular generic projection; near == far.
    Transform zero;
    zero.at(0, 0) = zero.at(1, 1) = zero.at(2, 2) = zero.at(3, 3) = 0.0f;
    s.camera->setGeneric(&zero);
    EXPECT_THROW(s.world->pick(-1, 0.5f, 0.5f, s.camera, nullptr), ArithmeticException);
    s.camera->setParallel(2, 1, 3, 3);
    EXPECT_THROW(s.world->pick(-1, 0.5f, 0.5f, s.camera, nullptr), ArithmeticException);
}
