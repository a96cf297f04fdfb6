// Shader invocation counting (m3g::vk::setShaderInvocationCounting,
// RenderStats): a quad whose vertices and covered pixels are known by hand,
// counted by the device's pipeline-statistics query.
#include "SceneKit.h"
#include "VkTestSupport.h"

using namespace m3g;
using m3gtest::VkTest;

namespace {

constexpr int kSize = 64;

/// Turns counting off again whatever the test's outcome (it is process-wide).
struct CountingOn {
    CountingOn() { vk::setShaderInvocationCounting(true); }
    ~CountingOn() { vk::setShaderInvocationCounting(false); }
};

/// One frame: a black clear, then the white quad over pixels [8, 40) x [16, 48)
/// (1,024 pixels; one strip of 4 vertices, two triangles) unless `quad` is
/// false.
void drawFrame(Image2D* image, bool quad) {
    Ref<Camera> camera(new Camera());  // identity projection: pixelQuad's NDC
    Graphics3D* g = m3gtest::begin(image, camera.get());
    Ref<Background> bg(new Background());
    bg->setColor(static_cast<int>(0xFF000000u));
    g->clear(bg.get());
    if (quad) {
        m3gtest::Quad q = m3gtest::pixelQuad(8, 16, 40, 48, kSize);
        Ref<Appearance> app(new Appearance());
        g->render(q.vb.get(), q.ib.get(), app.get(), nullptr);
    }
    g->releaseTarget();
}

int coveredPixels(const Image2D& image) {
    std::vector<std::uint8_t> rgba;
    image.getPixelsRGBA8(rgba);
    int n = 0;
    for (std::size_t i = 0; i < rgba.size(); i += 4) n += rgba[i] > 128 ? 1 : 0;
    return n;
}

}  // namespace

TEST_F(VkTest, ShaderInvocationsOfAQuadAreItsVerticesAndAtLeastItsPixels) {
    Ref<Image2D> image = target(kSize, kSize);
    drawFrame(image.get(), true);  // the device exists from here on
    if (!vk::shaderInvocationCountingSupported())
        GTEST_SKIP() << "the device lacks pipelineStatisticsQuery: nothing to count";
    CountingOn on;
    const vk::RenderStats before = vk::renderStats();
    drawFrame(image.get(), true);
    const vk::RenderStats after = vk::renderStats();
    ASSERT_EQ(coveredPixels(*image), 32 * 32);  // the quad is where the counts below assume
    EXPECT_EQ(after.countedFrames - before.countedFrames, 1u);
    const std::uint64_t vertices = after.vertexShaderInvocations - before.vertexShaderInvocations;
    const std::uint64_t fragments = after.fragmentShaderInvocations - before.fragmentShaderInvocations;
    // Two triangles over four vertices: each shaded at least once, at most
    // once per triangle corner. lavapipe shades each index of a draw's
    // segment once (docs/rendering.md, "Measuring").
    EXPECT_GE(vertices, 4u);
    EXPECT_LE(vertices, 6u);
    if (vk::currentDevice().type == "cpu") {
        EXPECT_EQ(vertices, 4u);
    }
    // Every covered pixel is shaded; a device may count more (helper
    // invocations in 2x2 quads, lavapipe's whole 4x4 blocks along the
    // diagonal, counted for both triangles), never twice the quad. The Background is a
    // clear, not shading.
    EXPECT_GE(fragments, 32u * 32u);
    EXPECT_LT(fragments, 2u * 32u * 32u);
}

TEST_F(VkTest, ShaderInvocationsAreNotCountedForClearsOrWhileOff) {
    Ref<Image2D> image = target(kSize, kSize);
    drawFrame(image.get(), false);
    if (!vk::shaderInvocationCountingSupported())
        GTEST_SKIP() << "the device lacks pipelineStatisticsQuery: nothing to count";
    vk::RenderStats before = vk::renderStats();
    drawFrame(image.get(), true);  // counting is off
    vk::RenderStats after = vk::renderStats();
    EXPECT_EQ(after.frames - before.frames, 1u);
    EXPECT_EQ(after.countedFrames, before.countedFrames);
    EXPECT_EQ(after.vertexShaderInvocations, before.vertexShaderInvocations);
    EXPECT_EQ(after.fragmentShaderInvocations, before.fragmentShaderInvocations);

    CountingOn on;
    before = vk::renderStats();
    drawFrame(image.get(), false);  // a Background colour only: the attachment's clear
    after = vk::renderStats();
    EXPECT_EQ(after.countedFrames - before.countedFrames, 1u);
    EXPECT_EQ(after.vertexShaderInvocations, before.vertexShaderInvocations);
    EXPECT_EQ(after.fragmentShaderInvocations, before.fragmentShaderInvocations);
    EXPECT_EQ(coveredPixels(*image), 0);
}
