// Camera (JSR-184 1.1, Camera): projections, checks, animation clamping.
#include <gtest/gtest.h>

#include <cmath>

#include <m3g/AnimationTrack.h>
#include <m3g/Camera.h>

using namespace m3g;

namespace {
void expectRows(const Transform& t, const std::array<float, 16>& rows, float eps = 1e-5f) {
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(t.rows()[i], rows[i], eps) << "element " << i;
}
}  // namespace

TEST(Camera, DefaultIsGenericIdentity) {
    Ref<Camera> c = make<Camera>();
    Transform t = Transform::fromRows({9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9, 9});
    EXPECT_EQ(c->getProjection(&t), Camera::GENERIC);
    EXPECT_EQ(t, Transform());
    float params[4] = {7, 7, 7, 7};
    EXPECT_EQ(c->getProjection(std::span<float>(params)), Camera::GENERIC);
    for (float p : params) EXPECT_EQ(p, 7.0f);  // untouched for GENERIC
    EXPECT_STREQ(c->getClassName(), "Camera");
}

TEST(Camera, PerspectiveMatrixFovy90Aspect2) {
    Ref<Camera> c = make<Camera>();
    c->setPerspective(90, 2, 1, 3);
    Transform t;
    EXPECT_EQ(c->getProjection(&t), Camera::PERSPECTIVE);
    // h = tan 45 = 1: 1/(2*1), 1/1, -(3+1)/(3-1), -2*3*1/(3-1).
    expectRows(t, {0.5f, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2, -3, 0, 0, -1, 0});
    float params[4];
    EXPECT_EQ(c->getProjection(std::span<float>(params)), Camera::PERSPECTIVE);
    EXPECT_EQ(params[0], 90.0f);
    EXPECT_EQ(params[1], 2.0f);
    EXPECT_EQ(params[2], 1.0f);
    EXPECT_EQ(params[3], 3.0f);
}

TEST(Camera, PerspectiveMatrixFovy60) {
    Ref<Camera> c = make<Camera>();
    c->setPerspective(60, 1, 1, 11);
    Transform t;
    c->getProjection(&t);
    // h = tan 30 = 0.5773503; 1/h = 1.7320508; -(12)/10; -2*11/10.
    expectRows(t, {1.7320508f, 0, 0, 0, 0, 1.7320508f, 0, 0, 0, 0, -1.2f, -2.2f, 0, 0, -1, 0});
}

TEST(Camera, ParallelMatrix) {
    Ref<Camera> c = make<Camera>();
    c->setParallel(4, 2, -1, 1);
    Transform t;
    EXPECT_EQ(c->getProjection(&t), Camera::PARALLEL);
    // 2/(2*4), 2/4, -2/(1-(-1)), -(1+(-1))/(1-(-1)).
    expectRows(t, {0.25f, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1});
}

TEST(Camera, ParallelAcceptsNearGreaterThanFar) {
    Ref<Camera> c = make<Camera>();
    c->setParallel(2, 1, 5, 1);
    Transform t;
    c->getProjection(&t);
    // -2/(1-5) = 0.5; -(1+5)/(1-5) = 1.5.
    expectRows(t, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0.5f, 1.5f, 0, 0, 0, 1});
    float params[4];
    c->getProjection(std::span<float>(params));
    EXPECT_EQ(params[0], 2.0f);
    EXPECT_EQ(params[2], 5.0f);
    EXPECT_EQ(params[3], 1.0f);
}

TEST(Camera, GenericRoundTrip) {
    Ref<Camera> c = make<Camera>();
    c->setPerspective(45, 1, 1, 100);
    const Transform g = Transform::fromRows({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16});
    c->setGeneric(&g);
    Transform t;
    EXPECT_EQ(c->getProjection(&t), Camera::GENERIC);
    EXPECT_EQ(t, g);
    EXPECT_THROW(c->setGeneric(nullptr), NullPointerException);
}

TEST(Camera, PerspectiveArgumentChecks) {
    Ref<Camera> c = make<Camera>();
    EXPECT_THROW(c->setPerspective(0, 1, 1, 2), IllegalArgumentException);
    EXPECT_THROW(c->setPerspective(180, 1, 1, 2), IllegalArgumentException);
    EXPECT_THROW(c->setPerspective(-10, 1, 1, 2), IllegalArgumentException);
    EXPECT_THROW(c->setPerspective(60, 0, 1, 2), IllegalArgumentException);
    EXPECT_THROW(c->setPerspective(60, -1, 1, 2), IllegalArgumentException);
    EXPECT_THROW(c->setPerspective(60, 1, 0, 2), IllegalArgumentException);
    EXPECT_THROW(c->setPerspective(60, 1, -1, 2), IllegalArgumentException);
    EXPECT_THROW(c->setPerspective(60, 1, 1, 0), IllegalArgumentException);
    EXPECT_THROW(c->setPerspective(60, 1, 1, NAN), IllegalArgumentException);
    EXPECT_EQ(c->getProjection(static_cast<Transform*>(nullptr)), Camera::GENERIC);  // unchanged
    EXPECT_NO_THROW(c->setPerspective(179.9f, 0.1f, 10, 1));                        // near > far is fine
}

TEST(Camera, ParallelArgumentChecks) {
    Ref<Camera> c = make<Camera>();
    EXPECT_THROW(c->setParallel(0, 1, 1, 2), IllegalArgumentException);
    EXPECT_THROW(c->setParallel(-1, 1, 1, 2), IllegalArgumentException);
    EXPECT_THROW(c->setParallel(1, 0, 1, 2), IllegalArgumentException);
    EXPECT_NO_THROW(c->setParallel(1, 1, -5, -7));
}

TEST(Camera, NearEqualsFarIsArithmeticOnGetProjection) {
    Ref<Camera> c = make<Camera>();
    c->setPerspective(60, 1, 2, 2);  // accepted
    Transform t;
    EXPECT_THROW(c->getProjection(&t), ArithmeticException);
    EXPECT_EQ(c->getProjection(static_cast<Transform*>(nullptr)), Camera::PERSPECTIVE);
    float params[4];
    EXPECT_EQ(c->getProjection(std::span<float>(params)), Camera::PERSPECTIVE);
    c->setParallel(1, 1, 3, 3);
    EXPECT_THROW(c->getProjection(&t), ArithmeticException);
}

TEST(Camera, GetProjectionParamsChecks) {
    Ref<Camera> c = make<Camera>();
    c->setPerspective(60, 1, 1, 2);
    float shortArr[3];
    EXPECT_THROW(c->getProjection(std::span<float>(shortArr)), IllegalArgumentException);
    EXPECT_EQ(c->getProjection(std::span<float>()), Camera::PERSPECTIVE);  // null array
}

TEST(Camera, SettersTouch) {
    Ref<Camera> c = make<Camera>();
    auto r = c->getRevision();
    c->setPerspective(60, 1, 1, 2);
    EXPECT_GT(c->getRevision(), r);
    r = c->getRevision();
    c->setParallel(1, 1, 1, 2);
    EXPECT_GT(c->getRevision(), r);
    r = c->getRevision();
    Transform g;
    c->setGeneric(&g);
    EXPECT_GT(c->getRevision(), r);
}

TEST(Camera, Animatable) {
    Ref<Camera> c = make<Camera>();
    EXPECT_TRUE(c->isAnimatable(AnimationTrack::FIELD_OF_VIEW));
    EXPECT_TRUE(c->isAnimatable(AnimationTrack::NEAR_DISTANCE));
    EXPECT_TRUE(c->isAnimatable(AnimationTrack::FAR_DISTANCE));
    EXPECT_TRUE(c->isAnimatable(AnimationTrack::ALPHA));
    EXPECT_TRUE(c->isAnimatable(AnimationTrack::TRANSLATION));
    EXPECT_FALSE(c->isAnimatable(AnimationTrack::COLOR));
    EXPECT_FALSE(c->isAnimatable(AnimationTrack::INTENSITY));
    EXPECT_FALSE(c->isAnimatable(AnimationTrack::DENSITY));
}

TEST(Camera, UpdatePropertyClampsPerspective) {
    Ref<Camera> c = make<Camera>();
    c->setPerspective(60, 1, 1, 10);
    float v = 200;
    c->updateProperty(AnimationTrack::FIELD_OF_VIEW, std::span<const float>(&v, 1));
    float p[4];
    c->getProjection(std::span<float>(p));
    EXPECT_EQ(p[0], 180.0f);
    v = -5;
    c->updateProperty(AnimationTrack::FIELD_OF_VIEW, std::span<const float>(&v, 1));
    v = -1;
    c->updateProperty(AnimationTrack::NEAR_DISTANCE, std::span<const float>(&v, 1));
    v = -2;
    c->updateProperty(AnimationTrack::FAR_DISTANCE, std::span<const float>(&v, 1));
    c->getProjection(std::span<float>(p));
    EXPECT_EQ(p[0], 0.0f);
    EXPECT_EQ(p[2], 0.0f);
    EXPECT_EQ(p[3], 0.0f);
    v = 7;
    c->updateProperty(AnimationTrack::FAR_DISTANCE, std::span<const float>(&v, 1));
    c->getProjection(std::span<float>(p));
    EXPECT_EQ(p[3], 7.0f);
}

TEST(Camera, UpdatePropertyParallelClampsHeightOnly) {
    Ref<Camera> c = make<Camera>();
    c->setParallel(2, 1, 1, 10);
    float v = -3;
    c->updateProperty(AnimationTrack::FIELD_OF_VIEW, std::span<const float>(&v, 1));
    float w = -4;
    c->updateProperty(AnimationTrack::NEAR_DISTANCE, std::span<const float>(&w, 1));
    float p[4];
    c->getProjection(std::span<float>(p));
    EXPECT_EQ(p[0], 0.0f);
    EXPECT_EQ(p[2], -4.0f);
    float h = 300;
    c->updateProperty(AnimationTrack::FIELD_OF_VIEW, std::span<const float>(&h, 1));
    c->getProjection(std::span<float>(p));
    EXPECT_EQ(p[0], 300.0f);  // no upper bound for a height
}

TEST(Camera, DuplicateKeepsProjection) {
    Ref<Camera> c = make<Camera>();
    c->setPerspective(90, 2, 1, 3);
    c->setUserID(12);
    Ref<Object3D> d = c->duplicate();
    Ref<Camera> dc = dynamicCast<Camera>(d);
    ASSERT_TRUE(dc);
    EXPECT_NE(dc.get(), c.get());
    Transform a, b;
    c->getProjection(&a);
    EXPECT_EQ(dc->getProjection(&b), Camera::PERSPECTIVE);
    EXPECT_EQ(a, b);
    EXPECT_EQ(dc->getUserID(), 12);
}
