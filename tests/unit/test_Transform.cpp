// Transform (JSR-184 1.1, Transform): row-major layout, products and exceptions,
// against hand-computed matrices.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <m3g/Transform.h>

using namespace m3g;

namespace {
std::array<float, 16> rowsOf(const Transform& t) {
    std::array<float, 16> m;
    t.get(m);
    return m;
}
void expectRowsNear(const Transform& t, const std::array<float, 16>& expected, float eps = 1e-5f) {
    const auto m = rowsOf(t);
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(m[i], expected[i], eps) << "element " << i << " (row " << i / 4 << ")";
}
}  // namespace

TEST(Transform, DefaultIsIdentity) {
    Transform t;
    expectRowsNear(t, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, 0);
}

TEST(Transform, SetGetAreRowMajor) {
    Transform t;
    std::array<float, 16> in;
    for (int i = 0; i < 16; ++i) in[i] = float(i + 1);
    t.set(std::span<const float>(in));
    // Element (row 0, col 3) is the 4th value: translation x in column vectors.
    EXPECT_EQ(t.at(0, 3), 4.0f);
    EXPECT_EQ(t.at(3, 0), 13.0f);
    expectRowsNear(t, in, 0);
}

TEST(Transform, SetGetArgumentChecks) {
    Transform t;
    std::array<float, 15> shortArray{};
    EXPECT_THROW(t.set(std::span<const float>(shortArray)), IllegalArgumentException);
    EXPECT_THROW(t.get(std::span<float>(shortArray)), IllegalArgumentException);
    EXPECT_THROW(t.set(std::span<const float>()), NullPointerException);
    EXPECT_THROW(t.get(std::span<float>()), NullPointerException);
    EXPECT_THROW(t.set(static_cast<const Transform*>(nullptr)), NullPointerException);
    EXPECT_THROW(t.postMultiply(nullptr), NullPointerException);
}

TEST(Transform, PostTranslateThenPostScaleComposeOnTheRight) {
    // M = T(1,2,3) * S(2,3,4): a point p maps to T(S p).
    Transform t;
    t.postTranslate(1, 2, 3);
    t.postScale(2, 3, 4);
    expectRowsNear(t, {2, 0, 0, 1, 0, 3, 0, 2, 0, 0, 4, 3, 0, 0, 0, 1});
    std::array<float, 4> p{1, 1, 1, 1};
    t.transform(p);
    EXPECT_FLOAT_EQ(p[0], 3);
    EXPECT_FLOAT_EQ(p[1], 5);
    EXPECT_FLOAT_EQ(p[2], 7);
    EXPECT_FLOAT_EQ(p[3], 1);
}

TEST(Transform, PostRotate90AboutZ) {
    // Rz(90): x -> y, y -> -x (right-handed, counter-clockwise).
    Transform t;
    t.postRotate(90, 0, 0, 1);
    expectRowsNear(t, {0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
}

TEST(Transform, PostRotateNonUnitAxisIsNormalised) {
    Transform a, b;
    a.postRotate(30, 0, 5, 0);
    b.postRotate(30, 0, 1, 0);
    const float c = std::cos(30 * 3.14159265f / 180), s = std::sin(30 * 3.14159265f / 180);
    expectRowsNear(a, {c, 0, s, 0, 0, 1, 0, 0, -s, 0, c, 0, 0, 0, 0, 1});
    expectRowsNear(b, rowsOf(a));
}

TEST(Transform, PostRotateZeroAxis) {
    Transform t;
    EXPECT_THROW(t.postRotate(10, 0, 0, 0), IllegalArgumentException);
    EXPECT_NO_THROW(t.postRotate(0, 0, 0, 0));  // zero angle: no rotation, no axis needed
    expectRowsNear(t, rowsOf(Transform()), 0);
}

TEST(Transform, PostRotateQuatNormalises) {
    // (0, 0, sin45, cos45) scaled by 3 is still Rz(90).
    Transform t;
    const float h = std::sqrt(0.5f) * 3;
    t.postRotateQuat(0, 0, h, h);
    expectRowsNear(t, {0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
    EXPECT_THROW(t.postRotateQuat(0, 0, 0, 0), IllegalArgumentException);
}

TEST(Transform, InvertHandComputed) {
    // inverse of T(1,2,3) S(2,4,8) = S(1/2,1/4,1/8) T(-1,-2,-3)
    Transform t;
    t.postTranslate(1, 2, 3);
    t.postScale(2, 4, 8);
    t.invert();
    expectRowsNear(t, {0.5f, 0, 0, -0.5f, 0, 0.25f, 0, -0.5f, 0, 0, 0.125f, -0.375f, 0, 0, 0, 1});
}

TEST(Transform, InvertSingularThrowsAndLeavesMatrix) {
    Transform t;
    t.postScale(1, 0, 1);
    const auto before = rowsOf(t);
    EXPECT_THROW(t.invert(), ArithmeticException);
    expectRowsNear(t, before, 0);
}

TEST(Transform, InvertOfSmallButRegularScaleSucceeds) {
    Transform t;
    t.postScale(1e-3f, 1e-3f, 1e-3f);
    ASSERT_NO_THROW(t.invert());
    EXPECT_NEAR(t.at(0, 0), 1000.0f, 1e-2f);
}

TEST(Transform, Transpose) {
    Transform t;
    std::array<float, 16> in;
    for (int i = 0; i < 16; ++i) in[i] = float(i);
    t.set(std::span<const float>(in));
    t.transpose();
    EXPECT_EQ(t.at(0, 1), 4.0f);
    EXPECT_EQ(t.at(1, 0), 1.0f);
    EXPECT_EQ(t.at(3, 2), 11.0f);
}

TEST(Transform, PostMultiplyOrder) {
    Transform a, b;
    a.postTranslate(5, 0, 0);
    b.postScale(2, 2, 2);
    a.postMultiply(&b);  // T * S
    std::array<float, 4> p{1, 0, 0, 1};
    a.transform(p);
    EXPECT_FLOAT_EQ(p[0], 7);  // 5 + 2*1
}

TEST(Transform, TransformArrayChecks) {
    Transform t;
    std::vector<float> v(6);
    EXPECT_THROW(t.transform(std::span<float>(v)), IllegalArgumentException);
    EXPECT_THROW(t.transform(std::span<float>()), NullPointerException);
    std::vector<float> w{1, 2, 3, 0, 4, 5, 6, 1};
    t.postTranslate(10, 20, 30);
    t.transform(std::span<float>(w));
    // w = 0 vectors are directions: translation does not apply.
    EXPECT_EQ(w, (std::vector<float>{1, 2, 3, 0, 14, 25, 36, 1}));
}
