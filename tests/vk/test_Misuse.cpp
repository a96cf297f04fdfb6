// Misuse of Graphics3D (JSR-184 1.1, Graphics3D) as the device sees it: a
// viewport outside the target, exceptions in the middle of a frame, and
// objects dropped while the frame that uses them is still unfinished. The
// argument and state checks that hand nothing to a back end (null
// arguments, missing camera, targets of the wrong kind, binding twice,
// background formats, vertex data without positions) are CPU tests:
// tests/unit/test_Graphics3DNullBackend.cpp.
#include <cmath>
#include <limits>

#include "RobustScenes.h"
#include "SceneKit.h"
#include "VkTestSupport.h"

using namespace m3g;
using m3gtest::VkTest;

namespace {

Graphics3D* fresh() {
    Graphics3D* g = Graphics3D::getInstance();
    g->releaseTarget();
    g->resetLights();
    g->setCamera(nullptr, nullptr);
    return g;
}

std::vector<std::uint8_t> pixelsOf(const Image2D& image) {
    std::vector<std::uint8_t> px;
    image.getPixelsRGBA8(px);
    return px;
}

}  // namespace

TEST_F(VkTest, MisuseViewportAndDepthRangeOutOfRange) {
    Graphics3D* g = fresh();
    const Limits& l = getLimits();
    auto img = target(8, 8);
    g->bindTarget(img.get());
    EXPECT_THROW(g->setViewport(0, 0, 8, 0), IllegalArgumentException);
    EXPECT_THROW(g->setViewport(0, 0, 8, l.maxViewportHeight + 1), IllegalArgumentException);
    EXPECT_THROW(g->setViewport(0, 0, -8, 8), IllegalArgumentException);
    EXPECT_EQ(g->getViewportWidth(), 8);  // unchanged by the failures
    EXPECT_THROW(g->setDepthRange(std::numeric_limits<float>::quiet_NaN(), 1.0f), IllegalArgumentException);
    EXPECT_THROW(g->setDepthRange(0.0f, std::numeric_limits<float>::infinity()), IllegalArgumentException);
    EXPECT_EQ(g->getDepthRangeFar(), 1.0f);
    // A viewport wholly outside the target is legal and draws nothing.
    g->setViewport(100, 100, 8, 8);
    g->clear(nullptr);
    g->releaseTarget();
    EXPECT_EQ(pixel(*img, 4, 4), 0xFF000000u);
}

// An exception in the middle of a frame leaves the frame usable: what was
// drawn before it reaches the target at releaseTarget.
TEST_F(VkTest, MisuseExceptionMidFrameKeepsEarlierDraws) {
    Graphics3D* g = fresh();
    auto img = target(16, 16);
    g->bindTarget(img.get());
    Ref<Camera> cam(new Camera());
    g->setCamera(cam.get(), nullptr);
    Ref<Background> red(new Background());
    red->setColor(static_cast<int>(0xFFFF0000u));
    g->clear(red.get());
    // Indices beyond the vertex count, inside a Mesh: thrown while recording.
    Ref<VertexBuffer> three(new VertexBuffer());
    const float zero[3] = {0, 0, 0};
    three->setPositions(m3gtest::positions({{-1, -1, 0}, {1, -1, 0}, {-1, 1, 0}}).get(), m3gtest::kPositionScale, zero);
    m3gtest::Quad q = m3gtest::makeQuad(-1, -1, 1, 1);
    Ref<Appearance> app(new Appearance());
    Ref<Mesh> bad(new Mesh(three.get(), q.ib.get(), app.get()));
    EXPECT_THROW(g->render(bad.get(), nullptr), IllegalStateException);
    // Still bound and recording: a green quad over the left half.
    m3gtest::Quad left = m3gtest::pixelQuad(0, 0, 8, 16, 16);
    m3gtest::setColors(*left.vb, {0xFF00FF00u, 0xFF00FF00u, 0xFF00FF00u, 0xFF00FF00u});
    g->render(left.vb.get(), left.ib.get(), app.get(), nullptr);
    g->releaseTarget();
    EXPECT_EQ(pixel(*img, 3, 8), 0xFF00FF00u);
    EXPECT_EQ(pixel(*img, 12, 8), 0xFFFF0000u);
}

// Objects whose last reference is dropped after render() and before
// releaseTarget() (while the frame that reads their GPU mirrors is not yet
// finished) are kept until the GPU is done: the image is the same as with
// the objects held, and their mirrors are freed once the frame completes.
TEST_F(VkTest, ObjectsDroppedBeforeReleaseTargetStayAliveForTheFrame) {
    constexpr int kSize = 48;
    auto frame = [&](Image2D& img, bool dropEarly, int hints) {
        Graphics3D* g = fresh();
        Ref<World> world = m3gtest::robustWorld(1);
        m3gtest::ImmediateDraw immediate = m3gtest::immediateDraw(3, kSize);
        g->bindTarget(&img, true, hints);
        g->render(world.get());
        g->render(immediate.quad.vb.get(), immediate.quad.ib.get(), immediate.appearance.get(), nullptr);
        if (dropEarly) {
            // Graphics3D keeps the World's camera and lights (JSR-184 1.1,
            // Graphics3D.render(World));
            // forget those too so that nothing of the scene survives.
            g->setCamera(nullptr, nullptr);
            g->resetLights();
            world = nullptr;
            immediate = {};
        }
        g->releaseTarget();
    };
    for (int hints : {0, Graphics3D::ANTIALIAS}) {
        SCOPED_TRACE(hints ? "ANTIALIAS" : "no hints");
        Ref<Image2D> warm = target(kSize, kSize), held = target(kSize, kSize), dropped = target(kSize, kSize);
        frame(*warm, false, hints);  // renderer, target images and pipelines exist from here on
        // A frame without the scene: frees the mirrors of the warm-up's objects.
        Graphics3D* g = fresh();
        g->bindTarget(warm.get(), true, hints);
        g->clear(nullptr);
        g->releaseTarget();
        const m3g::vk::RenderStats before = m3g::vk::renderStats();
        frame(*held, false, hints);
        frame(*dropped, true, hints);
        EXPECT_EQ(pixelsOf(*dropped), pixelsOf(*held));
        // The scene left something visible (background colour and image, meshes, sprite).
        EXPECT_NE(pixel(*held, 2, 2), pixel(*held, kSize - 3, 2));
        // Every mirror of the dropped objects is gone once the frame is done.
        const m3g::vk::RenderStats after = m3g::vk::renderStats();
        EXPECT_EQ(after.liveBuffers, before.liveBuffers);
        EXPECT_EQ(after.liveTextures, before.liveTextures);
        EXPECT_EQ(after.deviceMemoryBytes, before.deviceMemoryBytes);
    }
}
