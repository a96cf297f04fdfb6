// First device tests: clear, a lit-less triangle, viewport and culling,
// checked at hand-picked pixels against hand-computed expectations.
#include "VkTestSupport.h"

using namespace m3g;

namespace {

struct Triangle {
    Ref<VertexBuffer> vb;
    Ref<IndexBuffer> ib;
};

/// A counter-clockwise triangle covering the left half of NDC space at z = 0
/// under an identity camera, per-vertex colours red, green, blue.
Triangle makeTriangle(bool colors = true) {
    Ref<VertexArray> pos(new VertexArray(3, 3, 2));
    const std::int16_t p[] = {-1, -1, 0, 0, -1, 0, -1, 1, 0};
    pos->set(0, 3, std::span<const std::int16_t>(p));
    Ref<VertexBuffer> vb(new VertexBuffer());
    const float bias[3] = {0, 0, 0};
    vb->setPositions(pos.get(), 1.0f, bias);
    if (colors) {
        Ref<VertexArray> col(new VertexArray(3, 3, 1));
        const std::int8_t c[] = {-1, 0, 0, 0, -1, 0, 0, 0, -1};
        col->set(0, 3, std::span<const std::int8_t>(c));
        vb->setColors(col.get());
    }
    const int lengths[] = {3};
    Ref<IndexBuffer> ib(new TriangleStripArray(0, lengths));
    return {vb, ib};
}

}  // namespace

using m3gtest::VkTest;

TEST_F(VkTest, ClearNullIsTransparentBlack) {
    auto img = target(8, 8, 0xFF123456u);
    Graphics3D* g = Graphics3D::getInstance();
    g->bindTarget(img.get());
    g->clear(nullptr);
    g->releaseTarget();
    EXPECT_EQ(pixel(*img, 3, 3), 0x00000000u);
}

TEST_F(VkTest, ClearBackgroundColorWithinViewport) {
    auto img = target(16, 16, 0xFF000000u);
    Ref<Background> bg(new Background());
    bg->setColor(static_cast<int>(0x80FF8000u));
    Graphics3D* g = Graphics3D::getInstance();
    g->bindTarget(img.get());
    g->setViewport(4, 4, 8, 8);
    g->clear(bg.get());
    g->releaseTarget();
    EXPECT_EQ(pixel(*img, 5, 5), 0x80FF8000u);
    EXPECT_EQ(pixel(*img, 1, 1), 0xFF000000u);  // outside the viewport: untouched
    EXPECT_EQ(pixel(*img, 12, 12), 0xFF000000u);
}

TEST_F(VkTest, UnlitTriangleWithVertexColors) {
    auto img = target(64, 64);
    Triangle t = makeTriangle();
    Ref<Appearance> app(new Appearance());
    Ref<Camera> cam(new Camera());  // generic identity projection
    Graphics3D* g = Graphics3D::getInstance();
    g->bindTarget(img.get());
    g->setCamera(cam.get(), nullptr);
    g->clear(nullptr);
    g->render(t.vb.get(), t.ib.get(), app.get(), nullptr);
    g->releaseTarget();
    // Near the red vertex (bottom-left), mostly red; right half untouched.
    const std::uint32_t nearRed = pixel(*img, 1, 62);
    EXPECT_GT((nearRed >> 16) & 0xFF, 230u);
    EXPECT_LT((nearRed >> 8) & 0xFF, 20u);
    const std::uint32_t nearBlue = pixel(*img, 0, 3);  // top-left is the blue vertex (y up in NDC)
    EXPECT_GT(nearBlue & 0xFF, 230u);
    EXPECT_EQ(pixel(*img, 48, 32), 0x00000000u);
}

TEST_F(VkTest, BackFaceCulledByDefault) {
    auto img = target(32, 32);
    Triangle t = makeTriangle();
    Ref<Appearance> app(new Appearance());
    Ref<Camera> cam(new Camera());
    Transform mirror;
    mirror.postScale(-1, 1, 1);  // mirrors the triangle to the right half and flips its winding
    Graphics3D* g = Graphics3D::getInstance();
    g->bindTarget(img.get());
    g->setCamera(cam.get(), nullptr);
    g->clear(nullptr);
    g->render(t.vb.get(), t.ib.get(), app.get(), &mirror);
    g->releaseTarget();
    EXPECT_EQ(pixel(*img, 30, 16), 0x00000000u);

    Ref<PolygonMode> pm(new PolygonMode());
    pm->setCulling(PolygonMode::CULL_NONE);
    app->setPolygonMode(pm.get());
    g->bindTarget(img.get());
    g->render(t.vb.get(), t.ib.get(), app.get(), &mirror);
    g->releaseTarget();
    EXPECT_NE(pixel(*img, 30, 17) & 0xFFFFFF, 0u);
}

TEST_F(VkTest, AntialiasSmoothsEdgesAndKeepsPriorContents) {
    // With ANTIALIAS the diagonal edge of the triangle gets intermediate
    // colours (multisampling), and pixels outside it keep the target's
    // previous contents.
    Triangle t = makeTriangle(false);
    Ref<Appearance> app(new Appearance());
    Ref<Camera> cam(new Camera());
    Graphics3D* g = Graphics3D::getInstance();
    auto countPartial = [&](int hints) {
        auto img = target(32, 32, 0xFF0000FFu);  // opaque blue
        g->bindTarget(img.get(), true, hints);
        g->setCamera(cam.get(), nullptr);
        g->render(t.vb.get(), t.ib.get(), app.get(), nullptr);  // white triangle (default colour)
        g->releaseTarget();
        int partial = 0;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) {
                const std::uint32_t red = (pixel(*img, x, y) >> 16) & 0xFF;
                partial += red > 10 && red < 245;
            }
        EXPECT_EQ(pixel(*img, 31, 0), 0xFF0000FFu);  // untouched corner keeps the prior colour
        return partial;
    };
    EXPECT_EQ(countPartial(0), 0);
    if (m3g::Graphics3D::getProperties().at("supportAntialiasing") == m3g::Graphics3D::Property(true))
        EXPECT_GT(countPartial(Graphics3D::ANTIALIAS), 10);
    else
        GTEST_SKIP() << "device without multisampling";
}
