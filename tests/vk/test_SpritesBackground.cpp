// Golden tests of Sprite3D and Background (JSR-184 1.1, Sprite3D and Background).
// Sprites use a parallel camera 2 units tall on a 64x64 target, so one unit
// is 32 pixels and a scaled sprite (a 1x1 square) is 32x32 pixels.
#include "SceneKit.h"
#include "VkTestSupport.h"

#include <cmath>

using namespace m3g;
using m3gtest::begin;
using m3gtest::level;
using m3gtest::makeQuad;
using m3gtest::Quad;
using m3gtest::Rgba;
using m3gtest::translation;
using m3gtest::VkTest;

namespace {

const Rgba kRed{255, 0, 0, 255}, kGreen{0, 255, 0, 255}, kBlue{0, 0, 255, 255}, kWhite{255, 255, 255, 255};
const Rgba kClear{0, 0, 0, 0};

/// An RGBA image n x n: top-left red, top-right green, bottom-left blue,
/// bottom-right white (quadrants of n/2), all opaque.
Ref<Image2D> quadrants(int n) {
    std::vector<std::uint8_t> px;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const bool right = x >= n / 2, bottom = y >= n / 2;
            const std::uint8_t r = right == bottom ? 255 : 0, gch = right ? 255 : 0, b = bottom ? 255 : 0;
            px.insert(px.end(), {r, gch, b, 255});
        }
    return Ref<Image2D>(new Image2D(Image2D::RGBA, n, n, std::span<const std::uint8_t>(px)));
}

Ref<Sprite3D> sprite(bool scaled, Image2D* image, Appearance* app = nullptr) {
    Ref<Appearance> a = app ? Ref<Appearance>(app) : Ref<Appearance>(new Appearance());
    return Ref<Sprite3D>(new Sprite3D(scaled, image, a.get()));
}

}  // namespace

TEST_F(VkTest, SpriteUnscaledIsCropSizeInPixels) {
    // Unscaled: |crop| pixels centred on the projected origin. One at the
    // centre (pixels 28..35), one at (0.5, 0.5) (pixels 44..51 x 12..19).
    auto img = target(64, 64);
    Ref<Camera> cam = m3gtest::parallelCamera();
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Image2D> image = quadrants(8);
    auto s = sprite(false, image.get());
    Transform t = translation(0, 0, -5);
    g->render(s.get(), &t);
    t = translation(0.5f, 0.5f, -5);
    g->render(s.get(), &t);
    g->releaseTarget();
    EXPECT_PIXEL_TOL(*img, 28, 28, 0, kRed);
    EXPECT_PIXEL_TOL(*img, 35, 28, 0, kGreen);
    EXPECT_PIXEL_TOL(*img, 28, 35, 0, kBlue);
    EXPECT_PIXEL_TOL(*img, 35, 35, 0, kWhite);
    EXPECT_PIXEL_TOL(*img, 27, 32, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 36, 32, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 32, 27, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 32, 36, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 44, 12, 0, kRed);
    EXPECT_PIXEL_TOL(*img, 51, 19, 0, kWhite);
    EXPECT_PIXEL_TOL(*img, 43, 16, 0, kClear);
    expectGolden(*img, "sprite_unscaled", 3, 0.0);
}

TEST_F(VkTest, SpriteScaledIsProjectedUnitSquare) {
    // Scaled: the projected 1x1 square (32x32 pixels at the centre), and a
    // node scale of 0.25 at (0.75, 0.75): 8x8 pixels, 52..59 x 4..11.
    auto img = target(64, 64);
    Ref<Camera> cam = m3gtest::parallelCamera();
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Image2D> image = quadrants(8);
    auto s = sprite(true, image.get());
    Transform t = translation(0, 0, -5);
    g->render(s.get(), &t);
    t = translation(0.75f, 0.75f, -5);
    t.postScale(0.25f, 0.25f, 0.25f);
    g->render(s.get(), &t);
    g->releaseTarget();
    EXPECT_PIXEL_TOL(*img, 16, 16, 0, kRed);
    EXPECT_PIXEL_TOL(*img, 47, 16, 0, kGreen);
    EXPECT_PIXEL_TOL(*img, 16, 47, 0, kBlue);
    EXPECT_PIXEL_TOL(*img, 47, 47, 0, kWhite);
    EXPECT_PIXEL_TOL(*img, 15, 32, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 48, 32, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 52, 4, 0, kRed);
    EXPECT_PIXEL_TOL(*img, 59, 11, 0, kWhite);
    EXPECT_PIXEL_TOL(*img, 51, 8, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 60, 8, 0, kClear);
    expectGolden(*img, "sprite_scaled", 3, 0.0);
}

TEST_F(VkTest, SpriteCropInsideOutsideAndMirrored) {
    // Quadrant centres (16, 16), (48, 16), (16, 48), (48, 48):
    //  0: unscaled, crop (4, 0, 4, 4) inside: 4x4 green, pixels 14..17;
    //  1: unscaled, crop (4, 4, 8, 8) partly outside: an 8x8 rectangle of
    //     which only the top-left 4x4 (the image's white quadrant) is drawn;
    //  2: unscaled, crop (0, 0, -8, 8): mirrored left-right;
    //  3: scaled, crop (4, 4, 8, 8): a 32x32 rectangle, top-left 16x16 white.
    auto img = target(64, 64);
    Ref<Camera> cam = m3gtest::parallelCamera();
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Image2D> image = quadrants(8);
    const int crops[4][4] = {{4, 0, 4, 4}, {4, 4, 8, 8}, {0, 0, -8, 8}, {4, 4, 8, 8}};
    for (int q = 0; q < 4; ++q) {
        auto s = sprite(q == 3, image.get());
        s->setCrop(crops[q][0], crops[q][1], crops[q][2], crops[q][3]);
        Transform t = translation(q % 2 == 0 ? -0.5f : 0.5f, q < 2 ? 0.5f : -0.5f, -5);
        g->render(s.get(), &t);
    }
    g->releaseTarget();
    // 0
    EXPECT_PIXEL_TOL(*img, 14, 14, 0, kGreen);
    EXPECT_PIXEL_TOL(*img, 17, 17, 0, kGreen);
    EXPECT_PIXEL_TOL(*img, 13, 16, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 18, 16, 0, kClear);
    // 1: rectangle 44..51 x 12..19, drawn part 44..47 x 12..15
    EXPECT_PIXEL_TOL(*img, 44, 12, 0, kWhite);
    EXPECT_PIXEL_TOL(*img, 47, 15, 0, kWhite);
    EXPECT_PIXEL_TOL(*img, 48, 13, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 45, 16, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 50, 18, 0, kClear);
    // 2: rectangle 12..19 x 44..51, mirrored in x
    EXPECT_PIXEL_TOL(*img, 12, 44, 0, kGreen);
    EXPECT_PIXEL_TOL(*img, 19, 44, 0, kRed);
    EXPECT_PIXEL_TOL(*img, 12, 51, 0, kWhite);
    EXPECT_PIXEL_TOL(*img, 19, 51, 0, kBlue);
    // 3: rectangle 32..63 x 32..63, drawn part 32..47
    EXPECT_PIXEL_TOL(*img, 32, 32, 0, kWhite);
    EXPECT_PIXEL_TOL(*img, 47, 47, 0, kWhite);
    EXPECT_PIXEL_TOL(*img, 48, 40, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 40, 48, 0, kClear);
    expectGolden(*img, "sprite_crop", 3, 0.0);
}

TEST_F(VkTest, SpriteAlphaFactorWithBlending) {
    // ALPHA blending on opaque black. Left: opaque image, node alpha 0.5
    // (scaled, 32x32 at (-0.5, 0)); right: image alpha 0x80, node alpha 0.5
    // (product 0.25).
    auto img = target(64, 64, 0xFF000000u);
    Ref<Camera> cam = m3gtest::parallelCamera();
    Graphics3D* g = begin(img.get(), cam.get());
    Ref<CompositingMode> cm(new CompositingMode());
    cm->setBlending(CompositingMode::ALPHA);
    Ref<Appearance> app(new Appearance());
    app->setCompositingMode(cm.get());
    Ref<Image2D> opaque = quadrants(8);
    auto left = sprite(true, opaque.get(), app.get());
    left->setAlphaFactor(0.5f);
    Ref<Image2D> half = m3gtest::solidImage(Image2D::RGBA, 8, 8, {255, 255, 255, 0x80});
    auto right = sprite(true, half.get(), app.get());
    right->setAlphaFactor(0.5f);
    Transform t = translation(-0.5f, 0, -5);
    g->render(left.get(), &t);
    t = translation(0.5f, 0, -5);
    g->render(right.get(), &t);
    g->releaseTarget();
    auto over = [](double as) { return level(as * as + (1 - as)); };
    EXPECT_PIXEL(*img, 8, 24, Rgba{level(0.5), 0, 0, over(0.5)});  // red quadrant
    EXPECT_PIXEL(*img, 24, 40, Rgba{level(0.5), level(0.5), level(0.5), over(0.5)});  // white quadrant
    const double a = 0x80 / 255.0 * 0.5;
    EXPECT_PIXEL(*img, 48, 32, Rgba{level(a), level(a), level(a), over(a)});
    EXPECT_PIXEL_TOL(*img, 48, 8, 0, Rgba{0, 0, 0, 255});
    expectGolden(*img, "sprite_alpha_factor", 3, 0.0);
}

TEST_F(VkTest, SpriteFogAtOriginDepth) {
    // Linear fog 5..25, blue: unscaled sprites at depth 10 (f = 0.75, left)
    // and 20 (f = 0.25, right).
    auto img = target(64, 64);
    Ref<Camera> cam = m3gtest::parallelCamera();
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Fog> fog(new Fog());
    fog->setMode(Fog::LINEAR);
    fog->setLinear(5, 25);
    fog->setColor(0x0000FF);
    Ref<Appearance> app(new Appearance());
    app->setFog(fog.get());
    Ref<Image2D> image = quadrants(8);
    auto s = sprite(false, image.get(), app.get());
    Transform t = translation(-0.5f, 0, -10);
    g->render(s.get(), &t);
    t = translation(0.5f, 0, -20);
    g->render(s.get(), &t);
    g->releaseTarget();
    for (int i = 0; i < 2; ++i) {
        const double f = i == 0 ? 0.75 : 0.25;
        const int x0 = i == 0 ? 12 : 44;  // rectangle x0..x0+7, y 28..35
        SCOPED_TRACE(i);
        EXPECT_PIXEL(*img, x0, 28, Rgba{level(f), 0, level(1 - f), 255});           // red texel
        EXPECT_PIXEL(*img, x0 + 7, 35, Rgba{level(f), level(f), 255, 255});         // white texel
        EXPECT_PIXEL(*img, x0 + 7, 28, Rgba{0, level(f), level(1 - f), 255});       // green texel
    }
    expectGolden(*img, "sprite_fog", 3, 0.0);
}

namespace {

/// What the background shows at viewport pixel (lx, ly) of a 32x32 viewport
/// for a 4x4 quadrant image (2x2 texels per quadrant) and crop (cx, cy, cw,
/// ch): the crop rectangle covers the viewport; BORDER shows `colour`
/// outside the image, REPEAT tiles it.
Rgba backgroundAt(int lx, int ly, const int crop[4], bool repeatX, bool repeatY, Rgba colour) {
    const double x = crop[0] + (lx + 0.5) * crop[2] / 32.0, y = crop[1] + (ly + 0.5) * crop[3] / 32.0;
    if ((!repeatX && (x < 0 || x >= 4)) || (!repeatY && (y < 0 || y >= 4))) return colour;
    const int tx = ((static_cast<int>(std::floor(x)) % 4) + 4) % 4, ty = ((static_cast<int>(std::floor(y)) % 4) + 4) % 4;
    const bool right = tx >= 2, bottom = ty >= 2;
    if (!right && !bottom) return kRed;
    if (right && !bottom) return kGreen;
    if (!right) return kBlue;
    return kWhite;
}

}  // namespace

TEST_F(VkTest, BackgroundImageBorderRepeatCropInViewports) {
    // Four 32x32 viewports, background colour opaque grey, 4x4 quadrant image:
    //  top-left: BORDER/BORDER, crop (-2, -2, 8, 8): the image in the middle;
    //  top-right: REPEAT/REPEAT, same crop: tiled;
    //  bottom-left: REPEAT in x, BORDER in y;
    //  bottom-right: crop (2, 0, 2, 2): the green quadrant fills the viewport.
    auto img = target(64, 64, 0xFF000000u);
    Ref<Image2D> image = quadrants(4);
    const Rgba grey{0x40, 0x40, 0x40, 255};
    const int crops[4][4] = {{-2, -2, 8, 8}, {-2, -2, 8, 8}, {-2, -2, 8, 8}, {2, 0, 2, 2}};
    const bool repX[4] = {false, true, true, false}, repY[4] = {false, true, false, false};
    Graphics3D* g = Graphics3D::getInstance();
    g->bindTarget(img.get());
    for (int v = 0; v < 4; ++v) {
        Ref<Background> bg(new Background());
        bg->setColor(static_cast<int>(0xFF404040u));
        bg->setImage(image.get());
        bg->setImageMode(repX[v] ? Background::REPEAT : Background::BORDER, repY[v] ? Background::REPEAT : Background::BORDER);
        bg->setCrop(crops[v][0], crops[v][1], crops[v][2], crops[v][3]);
        g->setViewport(32 * (v % 2), 32 * (v / 2), 32, 32);
        g->clear(bg.get());
    }
    g->releaseTarget();
    int mismatches = 0;
    for (int v = 0; v < 4; ++v)
        for (int ly = 0; ly < 32; ++ly)
            for (int lx = 0; lx < 32; ++lx) {
                const auto r = m3gtest::pixelNear(*img, 32 * (v % 2) + lx, 32 * (v / 2) + ly,
                                                  backgroundAt(lx, ly, crops[v], repX[v], repY[v], grey), 0);
                if (!r && ++mismatches <= 5) ADD_FAILURE() << "viewport " << v << ": " << r.message();
            }
    EXPECT_EQ(mismatches, 0);
    expectGolden(*img, "background_image_modes", 3, 0.0);
}

TEST_F(VkTest, BackgroundColorAndDepthClearFlags) {
    // Green at z -0.5 everywhere (identity camera). A clear with both flags
    // off keeps colour and depth: red at z 0.5 on the left stays hidden. A
    // clear of depth only: white at z 0.5 on the right shows; the colour is
    // never cleared.
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    Ref<Background> first(new Background());
    first->setColor(static_cast<int>(0xFF0000FFu));
    g->clear(first.get());
    Ref<Appearance> app(new Appearance());
    Quad green = makeQuad(-1, -1, 1, 1, -0.5f);
    green.vb->setDefaultColor(static_cast<int>(0xFF00FF00u));
    g->render(green.vb.get(), green.ib.get(), app.get(), nullptr);
    Ref<Background> none(new Background());
    none->setColor(static_cast<int>(0xFFFF00FFu));
    none->setColorClearEnable(false);
    none->setDepthClearEnable(false);
    g->clear(none.get());
    Quad red = makeQuad(-1, -1, 0, 1, 0.5f);
    red.vb->setDefaultColor(static_cast<int>(0xFFFF0000u));
    g->render(red.vb.get(), red.ib.get(), app.get(), nullptr);
    Ref<Background> depthOnly(new Background());
    depthOnly->setColor(static_cast<int>(0xFFFF00FFu));
    depthOnly->setColorClearEnable(false);
    g->clear(depthOnly.get());
    Quad white = makeQuad(0, -1, 1, 1, 0.5f);
    white.vb->setDefaultColor(static_cast<int>(0xFFFFFFFFu));
    g->render(white.vb.get(), white.ib.get(), app.get(), nullptr);
    g->releaseTarget();
    EXPECT_PIXEL_TOL(*img, 16, 32, 0, kGreen);
    EXPECT_PIXEL_TOL(*img, 48, 32, 0, kWhite);
    expectGolden(*img, "background_clear_flags", 3, 0.0);
}

TEST_F(VkTest, BackgroundColorOnlyInsideViewport) {
    auto img = target(64, 64, 0xFF000000u);
    Ref<Background> bg(new Background());
    bg->setColor(static_cast<int>(0x80FF8000u));
    Graphics3D* g = Graphics3D::getInstance();
    g->bindTarget(img.get());
    g->setViewport(8, 16, 40, 24);
    g->clear(bg.get());
    g->releaseTarget();
    EXPECT_PIXEL_TOL(*img, 8, 16, 0, Rgba{255, 128, 0, 128});
    EXPECT_PIXEL_TOL(*img, 47, 39, 0, Rgba{255, 128, 0, 128});
    EXPECT_PIXEL_TOL(*img, 7, 20, 0, Rgba{0, 0, 0, 255});
    EXPECT_PIXEL_TOL(*img, 48, 20, 0, Rgba{0, 0, 0, 255});
    EXPECT_PIXEL_TOL(*img, 20, 15, 0, Rgba{0, 0, 0, 255});
    EXPECT_PIXEL_TOL(*img, 20, 40, 0, Rgba{0, 0, 0, 255});
    expectGolden(*img, "background_viewport_colour", 3, 0.0);
}

TEST_F(VkTest, SpriteScaledUnderPerspective) {
    // Perspective camera, 90 degrees: a scaled sprite at distance 2 is
    // 0.5 / 2 NDC half-wide (16x16 pixels at 24..39); at (2, -2, -4) it is
    // centred on NDC (0.5, -0.5), pixel (48, 48), 8x8 pixels (44..51).
    // The unscaled one at (-2, 2, -4) keeps its 8x8 crop size at (16, 16).
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    cam->setPerspective(90, 1, 0.5f, 50);
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Image2D> image = quadrants(8);
    auto scaled = sprite(true, image.get());
    auto unscaled = sprite(false, image.get());
    Transform t = translation(0, 0, -2);
    g->render(scaled.get(), &t);
    t = translation(2, -2, -4);
    g->render(scaled.get(), &t);
    t = translation(-2, 2, -4);
    g->render(unscaled.get(), &t);
    g->releaseTarget();
    EXPECT_PIXEL_TOL(*img, 24, 24, 0, kRed);
    EXPECT_PIXEL_TOL(*img, 39, 39, 0, kWhite);
    EXPECT_PIXEL_TOL(*img, 23, 32, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 44, 44, 0, kRed);
    EXPECT_PIXEL_TOL(*img, 51, 51, 0, kWhite);
    EXPECT_PIXEL_TOL(*img, 52, 48, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 43, 48, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 12, 12, 0, kRed);
    EXPECT_PIXEL_TOL(*img, 19, 19, 0, kWhite);
    EXPECT_PIXEL_TOL(*img, 11, 16, 0, kClear);
    EXPECT_PIXEL_TOL(*img, 20, 16, 0, kClear);
    expectGolden(*img, "sprite_perspective", 3, 0.002);
}

TEST_F(VkTest, BackgroundRgbImageOnRgbTarget) {
    // The format rule in the other direction: an RGB image clears an RGB
    // target (the quadrant image without alpha, crop = whole image).
    Ref<Image2D> rgbTarget(new Image2D(Image2D::RGB, 32, 32));
    Ref<Background> bg(new Background());
    bg->setImage(m3gtest::image(Image2D::RGB, 2, 2, {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255}).get());
    Graphics3D* g = Graphics3D::getInstance();
    g->bindTarget(rgbTarget.get());
    g->clear(bg.get());
    g->releaseTarget();
    EXPECT_PIXEL_TOL(*rgbTarget, 0, 0, 0, kRed);
    EXPECT_PIXEL_TOL(*rgbTarget, 31, 0, 0, kGreen);
    EXPECT_PIXEL_TOL(*rgbTarget, 0, 31, 0, kBlue);
    EXPECT_PIXEL_TOL(*rgbTarget, 31, 31, 0, kWhite);
    EXPECT_PIXEL_TOL(*rgbTarget, 15, 16, 0, kBlue);
    expectGolden(*rgbTarget, "background_rgb_target", 3, 0.0);
}

TEST_F(VkTest, BackgroundNearestRowsAtExactTexelEdges) {
    // A 64x64 image stretched over 320x240 (the corpus scenes' sky): 3.75
    // pixels per texel row, so the centre of pixel row y = 15m + 7 falls
    // exactly on a texel edge: (y + 0.5) * 64 / 240 = 4m + 2. Nearest sampling
    // takes texel floor((y + 0.5) * 64 / 240) on every row, the ties included,
    // as Nokia's renders show (nokia_on_ice.m3g rows 7 and 22 repeat texel
    // rows 2 and 6). Texel row r is grey 4r, so each pixel names its texel row.
    auto img = target(320, 240, 0xFF000000u);
    std::vector<std::uint8_t> px;
    for (int r = 0; r < 64; ++r)
        for (int c = 0; c < 64; ++c) {
            px.insert(px.end(), 3, static_cast<std::uint8_t>(4 * r));
            px.push_back(255);
        }
    Ref<Image2D> rows(new Image2D(Image2D::RGBA, 64, 64, std::span<const std::uint8_t>(px)));  // the target's format
    Ref<Background> bg(new Background());
    bg->setImage(rows.get());
    Graphics3D* g = Graphics3D::getInstance();
    g->bindTarget(img.get());
    g->clear(bg.get());
    g->releaseTarget();
    int mismatches = 0;
    for (int y = 0; y < 240; ++y) {
        const int texelRow = (2 * y + 1) * 64 / 480;  // floor((y + 0.5) * 64 / 240), exact
        for (int x : {0, 77, 160, 319}) {
            const auto r = m3gtest::pixelNear(*img, x, y, Rgba{4 * texelRow, 4 * texelRow, 4 * texelRow, 255}, 0);
            if (!r && ++mismatches <= 5) ADD_FAILURE() << "row " << y << ": " << r.message();
        }
    }
    EXPECT_EQ(mismatches, 0);
}

TEST_F(VkTest, BackgroundImageCoveringEveryPixelAfterOtherClears) {
    // Clears before a frame's first draw become load operations, and a
    // background image whose crop lies inside the image writes every pixel
    // with no colour clear at all: neither the earlier clears (red) nor the
    // background colour (magenta) nor the prior contents (black) may show.
    // Crop (1, 1, 2, 2) of the 4x4 quadrant image is one texel of each
    // colour: red, green / blue, white, stretched over the viewport.
    auto img = target(64, 64, 0xFF000000u);
    Ref<Image2D> image = quadrants(4);
    Ref<Background> red(new Background());
    red->setColor(static_cast<int>(0xFFFF0000u));
    Ref<Background> covering(new Background());
    covering->setColor(static_cast<int>(0xFFFF00FFu));
    covering->setImage(image.get());
    covering->setImageMode(Background::BORDER, Background::BORDER);
    covering->setCrop(1, 1, 2, 2);
    auto quadrantColour = [](int x, int y, int w, int h) {
        const bool right = x >= w / 2, bottom = y >= h / 2;
        return right ? (bottom ? kWhite : kGreen) : (bottom ? kBlue : kRed);
    };
    Graphics3D* g = Graphics3D::getInstance();
    g->bindTarget(img.get());
    g->clear(nullptr);
    g->clear(red.get());
    g->clear(covering.get());
    g->releaseTarget();
    int mismatches = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const auto r = m3gtest::pixelNear(*img, x, y, quadrantColour(x, y, 64, 64), 0);
            if (!r && ++mismatches <= 5) ADD_FAILURE() << "first frame: " << r.message();
        }
    // The next frame covers the left half only: the right half keeps the
    // first frame's pixels (the prior contents are loaded).
    g->bindTarget(img.get());
    g->setViewport(0, 0, 32, 64);
    g->clear(covering.get());
    g->releaseTarget();
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const Rgba want = x < 32 ? quadrantColour(x, y, 32, 64) : quadrantColour(x, y, 64, 64);
            const auto r = m3gtest::pixelNear(*img, x, y, want, 0);
            if (!r && ++mismatches <= 10) ADD_FAILURE() << "second frame: " << r.message();
        }
    EXPECT_EQ(mismatches, 0);
}
