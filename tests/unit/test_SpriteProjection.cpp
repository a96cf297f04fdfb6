// detail::projectSprite (JSR-184 1.1, Sprite3D): the screen rectangle, depth and
// image coordinates of a Sprite3D, against hand-computed values.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include <m3g/Appearance.h>
#include <m3g/Image2D.h>
#include <m3g/Sprite3D.h>
#include <m3g/Transform.h>

#include "SpriteProjection.h"

using namespace m3g;
using detail::projectSprite;
using detail::SpriteRect;

namespace {

/// Camera::setPerspective's matrix for fovy 90, aspect 1, near 1, far 10:
/// h = 1, z row (-(f+n)/(f-n), -2fn/(f-n)) = (-11/9, -20/9).
Transform perspective90() {
    return Transform::fromRows({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -11.0f / 9, -20.0f / 9, 0, 0, -1, 0});
}

Transform translation(float x, float y, float z) {
    Transform t;
    t.postTranslate(x, y, z);
    return t;
}

Ref<Sprite3D> makeSprite(bool scaled, int w = 16, int h = 8) {
    return new Sprite3D(scaled, new Image2D(Image2D::RGB, w, h), new Appearance());
}

void expectRect(const SpriteRect& r, float x0, float y0, float x1, float y1, float tol = 1e-5f) {
    EXPECT_NEAR(r.x0, x0, tol);
    EXPECT_NEAR(r.y0, y0, tol);
    EXPECT_NEAR(r.x1, x1, tol);
    EXPECT_NEAR(r.y1, y1, tol);
}

void expectTex(const SpriteRect& r, float s0, float t0, float s1, float t1) {
    EXPECT_FLOAT_EQ(r.s0, s0);
    EXPECT_FLOAT_EQ(r.t0, t0);
    EXPECT_FLOAT_EQ(r.s1, s1);
    EXPECT_FLOAT_EQ(r.t1, t1);
}

}  // namespace

TEST(SpriteProjection, UnscaledIsCropSizedInPixels) {
    Ref<Sprite3D> s = makeSprite(false);
    // Viewport 200 x 100: one pixel is 0.01 x 0.02 in NDC; 16 x 8 pixels
    // centred at the origin's projection give half sizes 0.08 and 0.08.
    const SpriteRect r = projectSprite(*s, translation(0, 0, -5), perspective90(), 200, 100);
    ASSERT_TRUE(r.visible);
    expectRect(r, -0.08f, -0.08f, 0.08f, 0.08f);
    // Depth: z_clip = (-11/9)(-5) - 20/9 = 35/9, w = 5, NDC z = 7/9.
    EXPECT_NEAR(r.ndcZ, 7.0f / 9.0f, 1e-6f);
    EXPECT_FLOAT_EQ(r.clipW, 5.0f);
    EXPECT_FLOAT_EQ(r.eyeDepth, 5.0f);
    expectTex(r, 0, 0, 1, 1);
    // Off axis: origin (1, 0.5, -5) projects to (0.2, 0.1); the size is unchanged.
    const SpriteRect o = projectSprite(*s, translation(1, 0.5f, -5), perspective90(), 200, 100);
    ASSERT_TRUE(o.visible);
    expectRect(o, 0.12f, 0.02f, 0.28f, 0.18f);
    // Farther away: still 16 x 8 pixels.
    const SpriteRect f = projectSprite(*s, translation(0, 0, -9), perspective90(), 200, 100);
    expectRect(f, -0.08f, -0.08f, 0.08f, 0.08f);
}

TEST(SpriteProjection, ScaledIsTheProjectedUnitSquare) {
    Ref<Sprite3D> s = makeSprite(true);  // 16 x 8 image: the aspect of the image does not matter
    // Node scale 2 at depth 5: eye half size 1, projected 1 * P00 / w = 0.2.
    Transform mv = translation(0, 0, -5);
    mv.postScale(2, 2, 2);
    const SpriteRect r = projectSprite(*s, mv, perspective90(), 200, 100);
    ASSERT_TRUE(r.visible);
    expectRect(r, -0.2f, -0.2f, 0.2f, 0.2f);
    expectTex(r, 0, 0, 1, 1);
    // Non-uniform node scale (3, 1): half sizes 0.3 and 0.1.
    Transform ns = translation(0, 0, -5);
    ns.postScale(3, 1, 1);
    expectRect(projectSprite(*s, ns, perspective90(), 200, 100), -0.3f, -0.1f, 0.3f, 0.1f);
    // Rotation keeps the sprite screen aligned and its size (the eye-space
    // lengths of the rotated half axes are still 0.5).
    Transform rot = translation(0, 0, -5);
    rot.postRotate(60, 0, 1, 0);
    rot.postRotate(30, 0, 0, 1);
    expectRect(projectSprite(*s, rot, perspective90(), 200, 100), -0.1f, -0.1f, 0.1f, 0.1f);
    // The viewport does not matter.
    expectRect(projectSprite(*s, mv, perspective90(), 17, 999), -0.2f, -0.2f, 0.2f, 0.2f);
}

TEST(SpriteProjection, ScaledUnderAParallelCamera) {
    // setParallel(height 4, aspect 2, near 1, far 10): P00 = 2/8, P11 = 2/4,
    // z row (-2/9, -11/9), w = 1. Eye half size 0.5 -> NDC 0.125 x 0.25.
    const Transform parallel =
        Transform::fromRows({0.25f, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, -2.0f / 9, -11.0f / 9, 0, 0, 0, 1});
    Ref<Sprite3D> s = makeSprite(true);
    const SpriteRect r = projectSprite(*s, translation(0, 0, -5.5f), parallel, 200, 100);
    ASSERT_TRUE(r.visible);
    expectRect(r, -0.125f, -0.25f, 0.125f, 0.25f);
    EXPECT_NEAR(r.ndcZ, 0.0f, 1e-6f);  // (2/9)(5.5) - 11/9 = 0
    EXPECT_FLOAT_EQ(r.clipW, 1.0f);
    EXPECT_FLOAT_EQ(r.eyeDepth, 5.5f);
}

TEST(SpriteProjection, CropInsideTheImage) {
    Ref<Sprite3D> s = makeSprite(false);
    s->setCrop(4, 2, 8, 4);
    // 8 x 4 pixels: half sizes 0.04 (x) and 0.04 (y); image coords 4/16..12/16, 2/8..6/8.
    const SpriteRect r = projectSprite(*s, translation(0, 0, -5), perspective90(), 200, 100);
    ASSERT_TRUE(r.visible);
    expectRect(r, -0.04f, -0.04f, 0.04f, 0.04f);
    expectTex(r, 0.25f, 0.25f, 0.75f, 0.75f);
    // Scaled: the whole crop fills the unit square whatever its size.
    Ref<Sprite3D> sc = makeSprite(true);
    sc->setCrop(4, 2, 8, 4);
    const SpriteRect q = projectSprite(*sc, translation(0, 0, -5), perspective90(), 200, 100);
    expectRect(q, -0.1f, -0.1f, 0.1f, 0.1f);
    expectTex(q, 0.25f, 0.25f, 0.75f, 0.75f);
}

TEST(SpriteProjection, CropPartlyOutsideDrawsOnlyTheImagePart) {
    Ref<Sprite3D> s = makeSprite(false);
    // Crop x -8..8 over a 16-wide image: the image part (x 0..8) is the right
    // half of the 16-pixel crop, which spans NDC [-0.08, 0.08].
    s->setCrop(-8, 0, 16, 8);
    SpriteRect r = projectSprite(*s, translation(0, 0, -5), perspective90(), 200, 100);
    ASSERT_TRUE(r.visible);
    expectRect(r, 0.0f, -0.08f, 0.08f, 0.08f);
    expectTex(r, 0, 0, 0.5f, 1);
    // Crop y 4..12 over an 8-high image: rows 4..8 are the upper half on
    // screen (image rows grow downwards); the crop spans NDC y [-0.08, 0.08].
    s->setCrop(0, 4, 16, 8);
    r = projectSprite(*s, translation(0, 0, -5), perspective90(), 200, 100);
    expectRect(r, -0.08f, 0.0f, 0.08f, 0.08f);
    expectTex(r, 0, 0.5f, 1, 1);
    // Scaled, crop x 8..24: the image part x 8..16 is the left half of the
    // crop; the unit square spans NDC [-0.1, 0.1].
    Ref<Sprite3D> sc = makeSprite(true);
    sc->setCrop(8, 0, 16, 8);
    r = projectSprite(*sc, translation(0, 0, -5), perspective90(), 200, 100);
    expectRect(r, -0.1f, -0.1f, 0.0f, 0.1f);
    expectTex(r, 0.5f, 0, 1, 1);
}

TEST(SpriteProjection, NegativeCropFlips) {
    Ref<Sprite3D> s = makeSprite(false);
    s->setCrop(0, 0, -16, 8);
    SpriteRect r = projectSprite(*s, translation(0, 0, -5), perspective90(), 200, 100);
    ASSERT_TRUE(r.visible);
    expectRect(r, -0.08f, -0.08f, 0.08f, 0.08f);
    expectTex(r, 1, 0, 0, 1);
    s->setCrop(0, 0, 16, -8);
    r = projectSprite(*s, translation(0, 0, -5), perspective90(), 200, 100);
    expectTex(r, 0, 1, 1, 0);
    s->setCrop(4, 2, -8, -4);
    r = projectSprite(*s, translation(0, 0, -5), perspective90(), 200, 100);
    expectRect(r, -0.04f, -0.04f, 0.04f, 0.04f);
    expectTex(r, 0.75f, 0.75f, 0.25f, 0.25f);
    // Flipped and partly outside: crop x -8..8 mirrored, so the image part
    // (x 0..8) shows on the left half, image x 8 at the left edge.
    s->setCrop(-8, 0, -16, 8);
    r = projectSprite(*s, translation(0, 0, -5), perspective90(), 200, 100);
    expectRect(r, -0.08f, -0.08f, 0.0f, 0.08f);
    expectTex(r, 0.5f, 0, 0, 1);
}

TEST(SpriteProjection, EmptyCropsAreInvisible) {
    Ref<Sprite3D> s = makeSprite(false);
    s->setCrop(16, 0, 8, 8);  // entirely right of the image
    EXPECT_FALSE(projectSprite(*s, translation(0, 0, -5), perspective90(), 200, 100).visible);
    s->setCrop(-8, 0, 8, 8);  // touches the left edge only
    EXPECT_FALSE(projectSprite(*s, translation(0, 0, -5), perspective90(), 200, 100).visible);
    s->setCrop(0, 0, 0, 8);
    EXPECT_FALSE(projectSprite(*s, translation(0, 0, -5), perspective90(), 200, 100).visible);
    // A scaled sprite of zero size.
    Ref<Sprite3D> sc = makeSprite(true);
    Transform flat = translation(0, 0, -5);
    flat.postScale(0, 1, 1);
    EXPECT_FALSE(projectSprite(*sc, flat, perspective90(), 200, 100).visible);
}

TEST(SpriteProjection, DepthOutsideTheViewVolume) {
    Ref<Sprite3D> s = makeSprite(false);
    // Behind the camera: w = -5.
    SpriteRect r = projectSprite(*s, translation(0, 0, 5), perspective90(), 200, 100);
    EXPECT_FALSE(r.visible);
    EXPECT_FLOAT_EQ(r.clipW, -5.0f);
    EXPECT_FLOAT_EQ(r.eyeDepth, -5.0f);
    // In front of the near plane (z = -0.5: NDC z = (11/18 - 20/9) / 0.5 < -1)
    // and beyond the far plane (z = -20): not visible, but the rectangle is
    // still filled.
    r = projectSprite(*s, translation(0, 0, -0.5f), perspective90(), 200, 100);
    EXPECT_FALSE(r.visible);
    EXPECT_LT(r.ndcZ, -1.0f);
    r = projectSprite(*s, translation(0, 0, -20), perspective90(), 200, 100);
    EXPECT_FALSE(r.visible);
    EXPECT_GT(r.ndcZ, 1.0f);
    expectRect(r, -0.08f, -0.08f, 0.08f, 0.08f);
    // Just inside the near and far planes: visible.
    EXPECT_TRUE(projectSprite(*s, translation(0, 0, -1.01f), perspective90(), 200, 100).visible);
    EXPECT_TRUE(projectSprite(*s, translation(0, 0, -9.9f), perspective90(), 200, 100).visible);
}
