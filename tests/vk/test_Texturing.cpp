// Golden tests of texturing (JSR-184 1.1, Texture2D): the texture environment
// table for every function and Image2D format, two units, texture
// transforms, wrapping, filtering, mipmapping and texcoord scale/bias.
#include "SceneKit.h"
#include "VkTestSupport.h"

#include <algorithm>
#include <cmath>

using namespace m3g;
using m3gtest::begin;
using m3gtest::level;
using m3gtest::makeQuad;
using m3gtest::pixelQuad;
using m3gtest::Quad;
using m3gtest::Rgba;
using m3gtest::VkTest;

namespace {

struct Colour {
    double r, g, b, a;
};

double clamp01(double v) { return std::clamp(v, 0.0, 1.0); }

Rgba asRgba(const Colour& c) { return {level(c.r), level(c.g), level(c.b), level(c.a)}; }

constexpr int kFormats[5] = {Image2D::ALPHA, Image2D::LUMINANCE, Image2D::LUMINANCE_ALPHA, Image2D::RGB, Image2D::RGBA};
constexpr int kFuncs[5] = {Texture2D::FUNC_REPLACE, Texture2D::FUNC_MODULATE, Texture2D::FUNC_DECAL,
                           Texture2D::FUNC_BLEND, Texture2D::FUNC_ADD};

/// The texture function table of JSR-184 1.1, Texture2D, written out cell by
/// cell. `t` holds the texel as the
/// format stores it: luminance in r (and g, b), colour in rgb, alpha in a.
/// Returns false for the cells the table leaves undefined.
bool textureEnv(int func, int format, const Colour& f, const Colour& t, const Colour& cc, Colour& out) {
    auto blend = [](double cf, double ct, double c) { return cf * (1 - ct) + c * ct; };
    switch (format) {
    case Image2D::ALPHA:
        if (func == Texture2D::FUNC_DECAL) return false;
        out = {f.r, f.g, f.b, func == Texture2D::FUNC_REPLACE ? t.a : f.a * t.a};
        return true;
    case Image2D::LUMINANCE:
    case Image2D::LUMINANCE_ALPHA: {
        const bool la = format == Image2D::LUMINANCE_ALPHA;
        const double l = t.r;
        switch (func) {
        case Texture2D::FUNC_REPLACE: out = {l, l, l, la ? t.a : f.a}; return true;
        case Texture2D::FUNC_MODULATE: out = {f.r * l, f.g * l, f.b * l, la ? f.a * t.a : f.a}; return true;
        case Texture2D::FUNC_BLEND:
            out = {blend(f.r, l, cc.r), blend(f.g, l, cc.g), blend(f.b, l, cc.b), la ? f.a * t.a : f.a};
            return true;
        case Texture2D::FUNC_ADD:
            out = {clamp01(f.r + l), clamp01(f.g + l), clamp01(f.b + l), la ? f.a * t.a : f.a};
            return true;
        default: return false;
        }
    }
    case Image2D::RGB:
    case Image2D::RGBA: {
        const bool rgba = format == Image2D::RGBA;
        switch (func) {
        case Texture2D::FUNC_REPLACE: out = {t.r, t.g, t.b, rgba ? t.a : f.a}; return true;
        case Texture2D::FUNC_MODULATE: out = {f.r * t.r, f.g * t.g, f.b * t.b, rgba ? f.a * t.a : f.a}; return true;
        case Texture2D::FUNC_DECAL:
            if (rgba) out = {blend(f.r, t.a, t.r), blend(f.g, t.a, t.g), blend(f.b, t.a, t.b), f.a};
            else out = {t.r, t.g, t.b, f.a};
            return true;
        case Texture2D::FUNC_BLEND:
            out = {blend(f.r, t.r, cc.r), blend(f.g, t.g, cc.g), blend(f.b, t.b, cc.b), rgba ? f.a * t.a : f.a};
            return true;
        case Texture2D::FUNC_ADD:
            out = {clamp01(f.r + t.r), clamp01(f.g + t.g), clamp01(f.b + t.b), rgba ? f.a * t.a : f.a};
            return true;
        default: return false;
        }
    }
    default: return false;
    }
}

double c8(int v) { return v / 255.0; }

/// A 2x2 image of one texel of `format`, from the texel's bytes.
Ref<Image2D> texelImage(int format) {
    switch (format) {
    case Image2D::ALPHA: return m3gtest::solidImage(format, 2, 2, {0x40});
    case Image2D::LUMINANCE: return m3gtest::solidImage(format, 2, 2, {0x60});
    case Image2D::LUMINANCE_ALPHA: return m3gtest::solidImage(format, 2, 2, {0x60, 0x40});
    case Image2D::RGB: return m3gtest::solidImage(format, 2, 2, {0xFF, 0x80, 0x20});
    default: return m3gtest::solidImage(format, 2, 2, {0xFF, 0x80, 0x20, 0x40});
    }
}

Colour texelColour(int format) {
    switch (format) {
    case Image2D::ALPHA: return {1, 1, 1, c8(0x40)};
    case Image2D::LUMINANCE: return {c8(0x60), c8(0x60), c8(0x60), 1};
    case Image2D::LUMINANCE_ALPHA: return {c8(0x60), c8(0x60), c8(0x60), c8(0x40)};
    case Image2D::RGB: return {1, c8(0x80), c8(0x20), 1};
    default: return {1, c8(0x80), c8(0x20), c8(0x40)};
    }
}

Ref<Appearance> textured(Texture2D* unit0, Texture2D* unit1 = nullptr) {
    Ref<Appearance> a(new Appearance());
    a->setTexture(0, unit0);
    a->setTexture(1, unit1);
    return a;
}

/// 2x2 RGB image: red, green (top row); blue, white (bottom row).
Ref<Image2D> fourColours() {
    return m3gtest::image(Image2D::RGB, 2, 2, {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255});
}

const Rgba kRed{255, 0, 0, -1}, kGreen{0, 255, 0, -1}, kBlue{0, 0, 255, -1}, kWhite{255, 255, 255, -1};

}  // namespace

TEST_F(VkTest, TextureEnvTableAllFunctionsAndFormats) {
    // Rows: REPLACE, MODULATE, DECAL, BLEND, ADD; columns: ALPHA, LUMINANCE,
    // LUMINANCE_ALPHA, RGB, RGBA. Fragment colour C_f = (0.4, 0.6, 0.8, 0.5)
    // from the vertex colours, blend colour C_c = 0x20C0E0. The cells DECAL x
    // {ALPHA, LUMINANCE, LUMINANCE_ALPHA} are undefined and stay empty.
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    const Colour cf{c8(0x66), c8(0x99), c8(0xCC), c8(0x80)};
    const Colour cc{c8(0x20), c8(0xC0), c8(0xE0), 1};
    Colour expected[5][5];
    bool defined[5][5];
    for (int row = 0; row < 5; ++row) {
        for (int col = 0; col < 5; ++col) {
            defined[row][col] = textureEnv(kFuncs[row], kFormats[col], cf, texelColour(kFormats[col]), cc, expected[row][col]);
            if (!defined[row][col]) continue;
            Ref<Texture2D> tex(new Texture2D(texelImage(kFormats[col]).get()));
            tex->setBlending(kFuncs[row]);
            tex->setBlendColor(0x20C0E0);
            Quad q = pixelQuad(3 + 12 * col, 3 + 12 * row, 13 + 12 * col, 13 + 12 * row, 64);
            m3gtest::setColors(*q.vb, {0x806699CCu, 0x806699CCu, 0x806699CCu, 0x806699CCu});
            g->render(q.vb.get(), q.ib.get(), textured(tex.get()).get(), nullptr);
        }
    }
    g->releaseTarget();
    for (int row = 0; row < 5; ++row)
        for (int col = 0; col < 5; ++col) {
            SCOPED_TRACE(testing::Message() << "function row " << row << ", format column " << col);
            const Rgba want = defined[row][col] ? asRgba(expected[row][col]) : Rgba{0, 0, 0, 0};
            EXPECT_PIXEL(*img, 8 + 12 * col, 8 + 12 * row, want);
        }
    expectGolden(*img, "texture_env_table", 3, 0.0);
}

TEST_F(VkTest, TextureTwoUnits) {
    // Left: unit 0 RGB MODULATE then unit 1 LUMINANCE ADD; right: unit 1 alone.
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Texture2D> rgb(new Texture2D(m3gtest::solidImage(Image2D::RGB, 2, 2, {0xFF, 0x80, 0x20}).get()));
    rgb->setBlending(Texture2D::FUNC_MODULATE);
    Ref<Texture2D> lum(new Texture2D(m3gtest::solidImage(Image2D::LUMINANCE, 2, 2, {0x40}).get()));
    lum->setBlending(Texture2D::FUNC_ADD);
    Quad left = makeQuad(-1, -1, 0, 1);
    m3gtest::setColors(*left.vb, {0x806699CCu, 0x806699CCu, 0x806699CCu, 0x806699CCu});
    g->render(left.vb.get(), left.ib.get(), textured(rgb.get(), lum.get()).get(), nullptr);
    Quad right = makeQuad(0, -1, 1, 1);
    m3gtest::setColors(*right.vb, {0x806699CCu, 0x806699CCu, 0x806699CCu, 0x806699CCu});
    g->render(right.vb.get(), right.ib.get(), textured(nullptr, lum.get()).get(), nullptr);
    g->releaseTarget();
    const double l = c8(0x40);
    EXPECT_PIXEL(*img, 16, 32,
                 Rgba{level(c8(0x66) * 1 + l), level(c8(0x99) * c8(0x80) + l), level(c8(0xCC) * c8(0x20) + l), 0x80});
    EXPECT_PIXEL(*img, 48, 32, Rgba{level(c8(0x66) + l), level(c8(0x99) + l), level(c8(0xCC) + l), 0x80});
    expectGolden(*img, "texture_two_units", 3, 0.0);
}

TEST_F(VkTest, TextureTransformTranslateAndScale) {
    // Texture2D is Transformable: its composite transform maps (s, t, r, 1).
    // Quadrants: identity; translate s by 0.5; scale by 2; translate t by 0.5
    // (REPEAT, NEAREST).
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Image2D> colours = fourColours();
    for (int q = 0; q < 4; ++q) {
        Ref<Texture2D> tex(new Texture2D(colours.get()));
        tex->setBlending(Texture2D::FUNC_REPLACE);
        if (q == 1) tex->setTranslation(0.5f, 0, 0);
        if (q == 2) tex->setScale(2, 2, 1);
        if (q == 3) tex->setTranslation(0, 0.5f, 0);
        const float x0 = (q % 2 == 0) ? -1.0f : 0.0f, y0 = (q < 2) ? 0.0f : -1.0f;
        Quad quad = makeQuad(x0, y0, x0 + 1, y0 + 1);
        g->render(quad.vb.get(), quad.ib.get(), textured(tex.get()).get(), nullptr);
    }
    g->releaseTarget();
    // Identity (top-left quadrant).
    EXPECT_PIXEL(*img, 8, 8, kRed);
    EXPECT_PIXEL(*img, 24, 8, kGreen);
    EXPECT_PIXEL(*img, 8, 24, kBlue);
    EXPECT_PIXEL(*img, 24, 24, kWhite);
    // s + 0.5 (top-right): the right column on the left, wrapped on the right.
    EXPECT_PIXEL(*img, 40, 8, kGreen);
    EXPECT_PIXEL(*img, 56, 8, kRed);
    EXPECT_PIXEL(*img, 40, 24, kWhite);
    EXPECT_PIXEL(*img, 56, 24, kBlue);
    // Scale 2 (bottom-left): the image tiled 2 x 2, 8 pixels per texel.
    EXPECT_PIXEL(*img, 4, 36, kRed);
    EXPECT_PIXEL(*img, 12, 36, kGreen);
    EXPECT_PIXEL(*img, 20, 36, kRed);
    EXPECT_PIXEL(*img, 4, 44, kBlue);
    EXPECT_PIXEL(*img, 28, 60, kWhite);
    // t + 0.5 (bottom-right): the bottom row on top.
    EXPECT_PIXEL(*img, 40, 40, kBlue);
    EXPECT_PIXEL(*img, 56, 40, kWhite);
    EXPECT_PIXEL(*img, 40, 56, kRed);
    EXPECT_PIXEL(*img, 56, 56, kGreen);
    expectGolden(*img, "texture_transform", 3, 0.0);
}

TEST_F(VkTest, TextureProjectiveTransformDividesByQ) {
    // A general texture matrix with bottom row (0.5, 0, 0, 0.5): q = (s + 1)
    // / 2, so the shader samples at s' = 2s / (s + 1), t' = 2t / (s + 1)
    // (affine matrices compile the division out, PipelineKey::texProjective).
    // Over the 64x64 quad s = (x + 0.5) / 64: the texel columns meet at
    // s' = 0.5, that is s = 1/3 (x = 20.8) instead of x = 32.
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Texture2D> tex(new Texture2D(fourColours().get()));
    tex->setBlending(Texture2D::FUNC_REPLACE);
    const Transform projective = Transform::fromRows({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5f, 0, 0, 0.5f});
    tex->setTransform(&projective);
    Quad quad = makeQuad(-1, -1, 1, 1);
    g->render(quad.vb.get(), quad.ib.get(), textured(tex.get()).get(), nullptr);
    g->releaseTarget();
    auto expected = [](int x, int y) {
        const double s = (x + 0.5) / 64.0, t = (y + 0.5) / 64.0, q = 0.5 * s + 0.5;
        const double sp = s / q, tp = std::fmod(t / q, 1.0);  // REPEAT
        return sp < 0.5 ? (tp < 0.5 ? kRed : kBlue) : (tp < 0.5 ? kGreen : kWhite);
    };
    for (const auto& [x, y] : {std::pair{16, 4}, {26, 4}, {60, 4}, {4, 60}, {26, 30}, {60, 40}}) {
        SCOPED_TRACE(::testing::Message() << "pixel " << x << ", " << y);
        EXPECT_PIXEL_TOL(*img, x, y, 0, expected(x, y));
    }
    EXPECT_PIXEL_TOL(*img, 26, 4, 0, kGreen);  // s = 0.41: the left texel without the division
}

TEST_F(VkTest, TextureUnitReadsItsOwnCoordinatesAndTransform) {
    // Only unit 1 is textured (four colours, REPLACE). Its coordinate set is
    // biased by s + 0.5 and its Texture2D translated by t + 0.5, while unit
    // 0's coordinates stay unbiased: the image appears shifted by half in
    // both directions (white top-left). Right: the same without the shifts.
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Image2D> colours = fourColours();
    Ref<Texture2D> shifted(new Texture2D(colours.get()));
    shifted->setBlending(Texture2D::FUNC_REPLACE);
    shifted->setTranslation(0, 0.5f, 0);
    Quad left = makeQuad(-1, -0.5f, 0, 0.5f);
    const float bias[2] = {0.5f, 0.0f};
    left.vb->setTexCoords(1, left.vb->getTexCoords(1).get(), 1.0f, bias);
    g->render(left.vb.get(), left.ib.get(), textured(nullptr, shifted.get()).get(), nullptr);
    Ref<Texture2D> plain(new Texture2D(colours.get()));
    plain->setBlending(Texture2D::FUNC_REPLACE);
    Quad right = makeQuad(0, -0.5f, 1, 0.5f);
    g->render(right.vb.get(), right.ib.get(), textured(nullptr, plain.get()).get(), nullptr);
    g->releaseTarget();
    EXPECT_PIXEL(*img, 8, 24, kWhite);
    EXPECT_PIXEL(*img, 24, 24, kBlue);
    EXPECT_PIXEL(*img, 8, 40, kGreen);
    EXPECT_PIXEL(*img, 24, 40, kRed);
    EXPECT_PIXEL(*img, 40, 24, kRed);
    EXPECT_PIXEL(*img, 56, 24, kGreen);
    EXPECT_PIXEL(*img, 40, 40, kBlue);
    EXPECT_PIXEL(*img, 56, 40, kWhite);
    expectGolden(*img, "texture_unit1_coordinates", 3, 0.0);
}

namespace {

/// The 2x1 texture (black, white) sampled at s as OpenGL does: NEAREST
/// picks texel floor(2s); LINEAR mixes texels floor(u), floor(u) + 1 at
/// u = 2s - 0.5; CLAMP (to edge) clamps texel indices, REPEAT wraps them.
double sampleBlackWhite(double s, bool linear, bool repeat) {
    auto texel = [repeat](long i) -> double {
        if (repeat) return ((i % 2) + 2) % 2 == 1 ? 1.0 : 0.0;
        return i >= 1 ? 1.0 : 0.0;
    };
    if (!linear) return texel(static_cast<long>(std::floor(2 * s)));
    const double u = 2 * s - 0.5;
    const double i0 = std::floor(u), w = u - i0;
    return texel(static_cast<long>(i0)) * (1 - w) + texel(static_cast<long>(i0) + 1) * w;
}

}  // namespace

TEST_F(VkTest, TextureWrapAndImageFilter) {
    // A 2x1 LUMINANCE texture (0, 255), REPLACE, texcoords scaled by 2 and
    // biased by -0.5, so s runs from -0.5 to 1.5 across the width. Bands top
    // to bottom: NEAREST+CLAMP, NEAREST+REPEAT, LINEAR+CLAMP, LINEAR+REPEAT.
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Image2D> bw = m3gtest::image(Image2D::LUMINANCE, 2, 1, {0, 255});
    const bool linear[4] = {false, false, true, true}, repeat[4] = {false, true, false, true};
    for (int band = 0; band < 4; ++band) {
        Ref<Texture2D> tex(new Texture2D(bw.get()));
        tex->setBlending(Texture2D::FUNC_REPLACE);
        tex->setFiltering(Texture2D::FILTER_BASE_LEVEL, linear[band] ? Texture2D::FILTER_LINEAR : Texture2D::FILTER_NEAREST);
        const int wrap = repeat[band] ? Texture2D::WRAP_REPEAT : Texture2D::WRAP_CLAMP;
        tex->setWrapping(wrap, wrap);
        Quad q = pixelQuad(0, 16 * band, 64, 16 * band + 16, 64);
        const float bias[2] = {-0.5f, 0.0f};
        q.vb->setTexCoords(0, q.vb->getTexCoords(0).get(), 2.0f, bias);
        g->render(q.vb.get(), q.ib.get(), textured(tex.get()).get(), nullptr);
    }
    g->releaseTarget();
    for (int band = 0; band < 4; ++band) {
        for (int x : {1, 6, 10, 14, 20, 26, 30, 34, 38, 44, 50, 54, 58, 62}) {
            const double s = (x + 0.5) / 64.0 * 2.0 - 0.5;
            const int v = level(sampleBlackWhite(s, linear[band], repeat[band]));
            SCOPED_TRACE(testing::Message() << "band " << band << ", s = " << s);
            EXPECT_PIXEL(*img, x, 16 * band + 8, Rgba{v, v, v, 255});
        }
    }
    expectGolden(*img, "texture_wrap_filter", 3, 0.002);
}

TEST_F(VkTest, TextureMipmapOnlyWhenLevelFilterAsksForIt) {
    // A 16x16 one-texel checkerboard (texel (0, 0) white) minified 4 times
    // (texcoords 0..4 over 16 pixels, i.e. 64 texels in 16 pixels: level of
    // detail 2). The bias of 1/32 puts every pixel centre in the middle of an
    // even texel, so the base level alone shows only white; levels 1 and up
    // of the generated chain are the 50% grey average.
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    std::vector<std::uint8_t> checker(16 * 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) checker[y * 16 + x] = (x + y) % 2 == 0 ? 255 : 0;
    Ref<Image2D> board(new Image2D(Image2D::LUMINANCE, 16, 16, std::span<const std::uint8_t>(checker)));
    const int levelFilter[3] = {Texture2D::FILTER_BASE_LEVEL, Texture2D::FILTER_NEAREST, Texture2D::FILTER_LINEAR};
    const int imageFilter[3] = {Texture2D::FILTER_NEAREST, Texture2D::FILTER_NEAREST, Texture2D::FILTER_LINEAR};
    for (int i = 0; i < 3; ++i) {
        Ref<Texture2D> tex(new Texture2D(board.get()));
        tex->setBlending(Texture2D::FUNC_REPLACE);
        tex->setFiltering(levelFilter[i], imageFilter[i]);
        Quad q = pixelQuad(24 * i, 24, 24 * i + 16, 40, 64);
        const float bias[2] = {1.0f / 32, 1.0f / 32};
        q.vb->setTexCoords(0, q.vb->getTexCoords(0).get(), 4.0f, bias);
        g->render(q.vb.get(), q.ib.get(), textured(tex.get()).get(), nullptr);
    }
    g->releaseTarget();
    for (int y : {25, 30, 35, 39}) {
        for (int dx : {1, 6, 11, 15}) {
            EXPECT_PIXEL_TOL(*img, dx, y, 0, Rgba{255, 255, 255, 255});
            EXPECT_PIXEL(*img, 24 + dx, y, Rgba{128, 128, 128, 255});
            EXPECT_PIXEL(*img, 48 + dx, y, Rgba{128, 128, 128, 255});
        }
    }
    expectGolden(*img, "texture_mipmap", 3, 0.0);
}
