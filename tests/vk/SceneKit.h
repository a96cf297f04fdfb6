// Small scene-building helpers for the feature golden tests (test_Lighting,
// test_Texturing, test_Compositing, test_SpritesBackground, test_SceneOrder):
// quads built with the public API, a frame that binds a target with a
// camera and no lights, and a pixel check with a per-channel tolerance.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <sstream>
#include <vector>

#include <m3g/m3g.h>

namespace m3gtest {

/// Expected colour as 0..255 channels; a negative channel is not checked.
struct Rgba {
    int r = -1, g = -1, b = -1, a = -1;
};

/// Rounds a 0..1 value to an 8-bit level (clamped).
inline int level(double v) {
    if (v < 0.0) v = 0.0;
    if (v > 1.0) v = 1.0;
    return static_cast<int>(std::lround(v * 255.0));
}

/// Actual RGBA of an RGB/RGBA Image2D.
inline std::array<int, 4> rgbaAt(const m3g::Image2D& image, int x, int y) {
    std::vector<std::uint8_t> px;
    image.getPixelsRGBA8(px);
    const std::size_t i = (static_cast<std::size_t>(y) * image.getWidth() + x) * 4;
    return {px[i], px[i + 1], px[i + 2], px[i + 3]};
}

inline ::testing::AssertionResult pixelNear(const m3g::Image2D& image, int x, int y, Rgba want, int tolerance) {
    const auto got = rgbaAt(image, x, y);
    const int w[4] = {want.r, want.g, want.b, want.a};
    for (int k = 0; k < 4; ++k) {
        if (w[k] >= 0 && std::abs(got[k] - w[k]) > tolerance) {
            std::ostringstream s;
            s << "pixel (" << x << ", " << y << ") is (" << got[0] << ", " << got[1] << ", " << got[2] << ", "
              << got[3] << "), expected (" << w[0] << ", " << w[1] << ", " << w[2] << ", " << w[3]
              << ") +-" << tolerance << " (-1: any)";
            return ::testing::AssertionFailure() << s.str();
        }
    }
    return ::testing::AssertionSuccess();
}

/// EXPECT that pixel (x, y) is `want` within +-3 levels per channel.
#define EXPECT_PIXEL(image, x, y, ...) EXPECT_TRUE(::m3gtest::pixelNear((image), (x), (y), __VA_ARGS__, 3))
/// The same with an explicit tolerance.
#define EXPECT_PIXEL_TOL(image, x, y, tol, ...) EXPECT_TRUE(::m3gtest::pixelNear((image), (x), (y), __VA_ARGS__, (tol)))

/// Quad geometry: 4 vertices in strip order bottom-left, bottom-right,
/// top-left, top-right (counter-clockwise seen from +Z), normals +Z,
/// texture coordinates on units 0 and 1 with s = 0..1 left to right and
/// t = 0 at the top edge (the image appears upright).
struct Quad {
    m3g::Ref<m3g::VertexBuffer> vb;
    m3g::Ref<m3g::IndexBuffer> ib;
};

/// NDC x of the left edge of pixel column `px` in a `size`-pixel viewport
/// (identity camera), and NDC y of the top edge of pixel row `py`.
inline float ndcX(int px, int size) { return 2.0f * static_cast<float>(px) / static_cast<float>(size) - 1.0f; }
inline float ndcY(int py, int size) { return 1.0f - 2.0f * static_cast<float>(py) / static_cast<float>(size); }

/// Positions are stored as shorts of 1/1024 units (scale 1/1024), so any
/// multiple of 1/1024 is exact.
inline m3g::Ref<m3g::VertexArray> positions(std::initializer_list<std::array<float, 3>> points) {
    m3g::Ref<m3g::VertexArray> a(new m3g::VertexArray(static_cast<int>(points.size()), 3, 2));
    std::vector<std::int16_t> v;
    for (const auto& p : points)
        for (float c : p) v.push_back(static_cast<std::int16_t>(std::lround(c * 1024.0f)));
    a->set(0, static_cast<int>(points.size()), std::span<const std::int16_t>(v));
    return a;
}

inline constexpr float kPositionScale = 1.0f / 1024.0f;

inline Quad makeQuad(float x0, float y0, float x1, float y1, float z = 0.0f, std::array<std::int8_t, 3> normal = {0, 0, 127}) {
    Quad q;
    q.vb = new m3g::VertexBuffer();
    const float zero[3] = {0, 0, 0};
    q.vb->setPositions(positions({{x0, y0, z}, {x1, y0, z}, {x0, y1, z}, {x1, y1, z}}).get(), kPositionScale, zero);
    m3g::Ref<m3g::VertexArray> n(new m3g::VertexArray(4, 3, 1));
    std::vector<std::int8_t> nv;
    for (int i = 0; i < 4; ++i) nv.insert(nv.end(), normal.begin(), normal.end());
    n->set(0, 4, std::span<const std::int8_t>(nv));
    q.vb->setNormals(n.get());
    m3g::Ref<m3g::VertexArray> t(new m3g::VertexArray(4, 2, 1));
    const std::int8_t tv[] = {0, 1, 1, 1, 0, 0, 1, 0};
    t->set(0, 4, std::span<const std::int8_t>(tv));
    q.vb->setTexCoords(0, t.get(), 1.0f, zero);
    q.vb->setTexCoords(1, t.get(), 1.0f, zero);
    const int lengths[] = {4};
    q.ib = new m3g::TriangleStripArray(0, lengths);
    return q;
}

/// A quad covering the pixel rectangle [px0, px1) x [py0, py1) of a
/// `size` x `size` viewport under an identity camera.
inline Quad pixelQuad(int px0, int py0, int px1, int py1, int size, float z = 0.0f) {
    return makeQuad(ndcX(px0, size), ndcY(py1, size), ndcX(px1, size), ndcY(py0, size), z);
}

/// A grid of `rows` x `cols` vertices (vertex r * cols + c) as triangle
/// strips, one per pair of neighbouring rows.
inline m3g::Ref<m3g::TriangleStripArray> gridStrips(int rows, int cols) {
    std::vector<int> strips, lengths;
    for (int r = 0; r + 1 < rows; ++r) {
        for (int c = 0; c < cols; ++c) strips.insert(strips.end(), {r * cols + c, (r + 1) * cols + c});
        lengths.push_back(cols * 2);
    }
    return new m3g::TriangleStripArray(strips, lengths);
}

/// Per-vertex colours (0xAARRGGBB) in the quad's vertex order.
inline void setColors(m3g::VertexBuffer& vb, std::initializer_list<std::uint32_t> argb) {
    m3g::Ref<m3g::VertexArray> c(new m3g::VertexArray(static_cast<int>(argb.size()), 4, 1));
    std::vector<std::int8_t> v;
    for (std::uint32_t x : argb) {
        v.push_back(static_cast<std::int8_t>((x >> 16) & 0xFF));
        v.push_back(static_cast<std::int8_t>((x >> 8) & 0xFF));
        v.push_back(static_cast<std::int8_t>(x & 0xFF));
        v.push_back(static_cast<std::int8_t>((x >> 24) & 0xFF));
    }
    c->set(0, static_cast<int>(argb.size()), std::span<const std::int8_t>(v));
    vb.setColors(c.get());
}

/// An Image2D of `format` from tightly packed bytes (immutable).
inline m3g::Ref<m3g::Image2D> image(int format, int w, int h, std::initializer_list<std::uint8_t> bytes) {
    std::vector<std::uint8_t> v(bytes);
    return m3g::Ref<m3g::Image2D>(new m3g::Image2D(format, w, h, std::span<const std::uint8_t>(v)));
}

/// An RGBA image with every pixel the same.
inline m3g::Ref<m3g::Image2D> solidImage(int format, int w, int h, std::initializer_list<std::uint8_t> texel) {
    std::vector<std::uint8_t> v;
    for (int i = 0; i < w * h; ++i) v.insert(v.end(), texel.begin(), texel.end());
    return m3g::Ref<m3g::Image2D>(new m3g::Image2D(format, w, h, std::span<const std::uint8_t>(v)));
}

/// An orthographic camera looking down -Z from the origin: `height` world
/// units span the viewport height, aspect 1, near 0.1, far 100.
inline m3g::Ref<m3g::Camera> parallelCamera(float height = 2.0f) {
    m3g::Ref<m3g::Camera> c(new m3g::Camera());
    c->setParallel(height, 1.0f, 0.1f, 100.0f);
    return c;
}

/// Binds `target`, sets `camera` (identity camera-to-world) and clears the
/// light list. Release with Graphics3D::releaseTarget() (also done by the
/// fixture's TearDown).
inline m3g::Graphics3D* begin(m3g::Image2D* target, m3g::Camera* camera) {
    m3g::Graphics3D* g = m3g::Graphics3D::getInstance();
    g->bindTarget(target);
    g->resetLights();
    g->setCamera(camera, nullptr);
    return g;
}

inline m3g::Transform translation(float x, float y, float z) {
    m3g::Transform t;
    t.postTranslate(x, y, z);
    return t;
}

}  // namespace m3gtest
