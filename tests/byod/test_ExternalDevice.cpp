// Bring your own device (ExternalDevice.h, ImageTarget.h): m3g-vk renders with
// an application's Vulkan device into the application's images, ordered by
// its semaphores. The application's side is the example's (examples/byod,
// plain libvulkan with the validation layer); the expected pixels come from
// m3g-vk's ordinary Image2D path on the same device, and from the colours the
// application drew itself. The environment at the end checks that the
// application can destroy its device with zero validation messages, i.e.
// that releaseDevice() left nothing of m3g-vk's on it.
//
// One process per test (gtest_discover_tests): each makes its own device.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <vector>

#include <m3g/m3g.h>
#include <m3g/vk/ExternalDevice.h>
#include <m3g/vk/ImageTarget.h>
#include <m3g/vk/Vulkan.h>

#include "AppDevice.h"
#include "HoldDriver.h"
#include "SampleScene.h"

namespace {

constexpr std::uint32_t kW = 96, kH = 72;
// The application's clear and its near panel (right third), exact in UNORM8.
constexpr std::uint8_t kClear[4] = {0x20, 0x40, 0x80, 0xFF};
constexpr std::uint8_t kPanel[4] = {0xE0, 0x90, 0x20, 0xFF};
constexpr std::uint32_t kPanelX = kW * 2 / 3;

byod::AppDevice* gApp = nullptr;

class AppEnvironment : public ::testing::Environment {
public:
    void SetUp() override {
        m3gtest::holdLavapipeLoaded();  // LeakSanitizer builds: see HoldDriver.h
        gApp = new byod::AppDevice(true);
    }
    void TearDown() override {
        // Whatever a test left: m3g-vk lets go of the device, then the
        // application destroys it (the layer reports objects left alive).
        m3g::Graphics3D::getInstance()->releaseRenderer();
        m3g::vk::releaseDevice();
        const bool validation = gApp->validation;
        gApp->close();
        EXPECT_TRUE(validation) << "VK_LAYER_KHRONOS_validation is not installed (scripts/setup installs it)";
        EXPECT_EQ(gApp->validationMessages(), 0u) << "the validation layer reported messages (printed above)";
        delete gApp;
        gApp = nullptr;
    }
};
const auto* const gEnvironment = ::testing::AddGlobalTestEnvironment(new AppEnvironment);

m3g::vk::ExternalDevice external() {
    m3g::vk::ExternalDevice d;
    d.instance = gApp->instance;
    d.physicalDevice = gApp->physicalDevice;
    d.device = gApp->device;
    d.queue = gApp->queue;
    d.queueFamilyIndex = gApp->queueFamily;
    d.getInstanceProcAddr = vkGetInstanceProcAddr;
    return d;
}

// The application's frame (AppDevice::drawPanelFrame): kClear with far
// depth, the panel at depth 0 over the right third.
void drawAppFrame(const byod::AppImage& color, const byod::AppImage* depth, VkSemaphore signal) {
    gApp->drawPanelFrame(color, depth, kClear, kPanel, kPanelX, signal);
}

// The sample scene (lit textured cube, ground, blended sprite, fog) with its
// Background clearing colour and depth to `clear` (keep = false), or neither.
m3g::Ref<m3g::World> scene(bool keep, const std::uint8_t (&clear)[4] = kClear) {
    m3g::Ref<m3g::World> world = m3gcli::buildSampleScene();
    auto background = m3g::make<m3g::Background>();
    background->setColor(static_cast<int>((std::uint32_t{clear[3]} << 24) | (std::uint32_t{clear[0]} << 16) |
                                          (std::uint32_t{clear[1]} << 8) | clear[2]));
    background->setColorClearEnable(!keep);
    background->setDepthClearEnable(!keep);
    world->setBackground(background.get());
    world->animate(0);
    return world;
}

// m3g-vk's ordinary path on the same device: RGBA bytes.
std::vector<std::uint8_t> reference(m3g::World* world) {
    auto image = m3g::make<m3g::Image2D>(m3g::Image2D::RGBA, static_cast<int>(kW), static_cast<int>(kH));
    m3g::Graphics3D* g3d = m3g::Graphics3D::getInstance();
    g3d->bindTarget(image.get());
    g3d->render(world);
    g3d->releaseTarget();
    std::vector<std::uint8_t> rgba;
    image->getPixelsRGBA8(rgba);
    return rgba;
}

void render(m3g::vk::ImageTarget* target, m3g::World* world) {
    m3g::Graphics3D* g3d = m3g::Graphics3D::getInstance();
    g3d->bindTarget(target);
    g3d->render(world);
    g3d->releaseTarget();
}

// An RGBA image of the application's that m3g-vk draws into and the test
// reads back (no colour-attachment use of the application's own).
byod::AppImage readableImage() {
    return gApp->createImage(kW, kH, VK_FORMAT_R8G8B8A8_UNORM,
                             VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
}

// `image` as a colour attachment whose prior contents are discarded and
// which is left ready to be read back.
m3g::vk::ImageAttachment freshAttachment(const byod::AppImage& image) {
    return {image.image, image.format, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
}

// The pixel at (x, y) of an image read from the application as RGBA.
const std::uint8_t* at(const std::vector<std::uint8_t>& rgba, std::uint32_t x, std::uint32_t y) {
    return &rgba[(static_cast<std::size_t>(y) * kW + x) * 4];
}

std::vector<std::uint8_t> bgraToRgba(std::vector<std::uint8_t> p) {
    for (std::size_t i = 0; i < p.size(); i += 4) std::swap(p[i], p[i + 2]);
    return p;
}

::testing::AssertionResult samePixel(const std::uint8_t* a, const std::uint8_t* b, std::uint32_t x, std::uint32_t y) {
    for (int c = 0; c < 4; ++c)
        if (a[c] != b[c])
            return ::testing::AssertionFailure()
                   << "pixel (" << x << ", " << y << ") is " << int(a[0]) << "," << int(a[1]) << "," << int(a[2]) << ","
                   << int(a[3]) << ", expected " << int(b[0]) << "," << int(b[1]) << "," << int(b[2]) << "," << int(b[3]);
    return ::testing::AssertionSuccess();
}

}  // namespace

// The scene over the application's BGRA frame, depth-tested against its
// depth, ordered by semaphores: left of the panel the pixels are those of
// m3g-vk's own path with a Background of the application's colour; the panel,
// nearer than anything, stays.
TEST(Byod, CompositesIntoTheApplicationsFrameAndDepth) {
    m3g::vk::useDevice(external());
    m3g::Ref<m3g::World> keep = scene(true), cleared = scene(false);
    const std::vector<std::uint8_t> expected = reference(cleared.get());

    byod::AppImage color = gApp->createImage(kW, kH, VK_FORMAT_B8G8R8A8_UNORM,
                                             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                                 VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    byod::AppImage depth =
        gApp->createImage(kW, kH, m3g::vk::ImageTarget::depthFormat(), VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
    VkSemaphore appDrawn = gApp->createSemaphore(), sceneDrawn = gApp->createSemaphore();
    drawAppFrame(color, &depth, appDrawn);
    auto target = m3g::make<m3g::vk::ImageTarget>(
        kW, kH,
        m3g::vk::ImageAttachment{color.image, color.format, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                 VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL},
        m3g::vk::ImageAttachment{depth.image, depth.format, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                                 VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL});
    target->waitFor(appDrawn, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT);
    target->signalWhenDone(sceneDrawn);
    render(target.get(), keep.get());
    const std::vector<std::uint8_t> actual =
        bgraToRgba(gApp->read(color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, sceneDrawn));

    int drawn = 0, mismatches = 0;
    for (std::uint32_t y = 0; y < kH; ++y)
        for (std::uint32_t x = 0; x < kW; ++x) {
            const std::uint8_t* want = x >= kPanelX ? kPanel : at(expected, x, y);
            if (x < kPanelX && std::memcmp(want, kClear, 4) != 0) ++drawn;
            const auto same = samePixel(at(actual, x, y), want, x, y);
            if (!same && ++mismatches <= 5) ADD_FAILURE() << same.message();
        }
    EXPECT_EQ(mismatches, 0);
    EXPECT_GT(drawn, static_cast<int>(kW * kH / 4)) << "the scene should cover much of the left part";

    gApp->destroy(appDrawn);
    gApp->destroy(sceneDrawn);
    gApp->destroy(color);
    gApp->destroy(depth);
}

// A Background that clears depth clears the application's depth too: the
// scene then covers the panel as m3g-vk's own path draws it.
TEST(Byod, SceneDepthClearClearsTheApplicationsDepth) {
    m3g::vk::useDevice(external());
    m3g::Ref<m3g::World> world = scene(false);
    const std::vector<std::uint8_t> expected = reference(world.get());
    byod::AppImage color = gApp->createImage(kW, kH, VK_FORMAT_R8G8B8A8_UNORM,
                                             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                                 VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    byod::AppImage depth =
        gApp->createImage(kW, kH, m3g::vk::ImageTarget::depthFormat(), VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
    VkSemaphore appDrawn = gApp->createSemaphore();
    drawAppFrame(color, &depth, appDrawn);
    auto target = m3g::make<m3g::vk::ImageTarget>(
        kW, kH,
        m3g::vk::ImageAttachment{color.image, color.format, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                 VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL},
        m3g::vk::ImageAttachment{depth.image, depth.format, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                                 VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL});
    target->waitFor(appDrawn);
    render(target.get(), world.get());
    const std::vector<std::uint8_t> actual = gApp->read(color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    int mismatches = 0;
    for (std::uint32_t y = 0; y < kH; ++y)
        for (std::uint32_t x = 0; x < kW; ++x) {
            const auto same = samePixel(at(actual, x, y), at(expected, x, y), x, y);
            if (!same && ++mismatches <= 5) ADD_FAILURE() << same.message();
        }
    EXPECT_EQ(mismatches, 0);
    gApp->destroy(appDrawn);
    gApp->destroy(color);
    gApp->destroy(depth);
}

// Contents in UNDEFINED layout are gone: without a clear the frame starts
// opaque black, as a new Graphics; m3g-vk's own depth buffer serves. Two
// frames into the same target: the second starts from the first's result.
TEST(Byod, UndefinedContentsStartBlackAndFramesFollowEachOther) {
    m3g::vk::useDevice(external());
    const std::uint8_t black[4] = {0, 0, 0, 0xFF};
    m3g::Ref<m3g::World> keep = scene(true), cleared = scene(false, black);
    const std::vector<std::uint8_t> expected = reference(cleared.get());
    byod::AppImage color = readableImage();
    auto target = m3g::make<m3g::vk::ImageTarget>(kW, kH, freshAttachment(color));
    render(target.get(), keep.get());
    const std::vector<std::uint8_t> first = gApp->read(color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    EXPECT_EQ(first, expected);
    // Kept contents: the same frame drawn again over itself changes only
    // what blending adds (the sprite); opaque pixels stay.
    target->setImages(m3g::vk::ImageAttachment{color.image, color.format, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL});
    render(target.get(), keep.get());
    const std::vector<std::uint8_t> second = gApp->read(color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    EXPECT_EQ(std::memcmp(at(second, 0, 0), black, 4), 0) << "a corner the scene does not draw keeps the first frame";
    int same = 0;
    for (std::size_t i = 0; i < first.size(); i += 4) same += std::memcmp(&first[i], &second[i], 4) == 0;
    EXPECT_GT(same, static_cast<int>(kW * kH * 9 / 10));
    gApp->destroy(color);
}

// RenderStats splits a frame's fixed cost (m3g bench render's last two
// columns): every submitted frame adds its wait for the device; only a frame
// copied into the application's memory (an Image2D here) adds read-back
// time, a frame left in a Vulkan image adds none.
TEST(Byod, FrameStatsCountTheWaitAndOnlyRealReadBacks) {
    m3g::vk::useDevice(external());
    m3g::Ref<m3g::World> world = scene(false);
    const m3g::vk::RenderStats s0 = m3g::vk::renderStats();
    const std::vector<std::uint8_t> pixels = reference(world.get());  // an Image2D target
    ASSERT_FALSE(pixels.empty());
    const m3g::vk::RenderStats s1 = m3g::vk::renderStats();
    EXPECT_EQ(s1.frames - s0.frames, 1u);
    EXPECT_GT(s1.frameWaitNanoseconds, s0.frameWaitNanoseconds);
    EXPECT_GT(s1.readBackNanoseconds, s0.readBackNanoseconds);

    byod::AppImage color = readableImage();
    auto target = m3g::make<m3g::vk::ImageTarget>(kW, kH, freshAttachment(color));
    render(target.get(), world.get());
    const m3g::vk::RenderStats s2 = m3g::vk::renderStats();
    EXPECT_EQ(s2.frames - s1.frames, 1u);
    EXPECT_GT(s2.frameWaitNanoseconds, s1.frameWaitNanoseconds);
    EXPECT_EQ(s2.readBackNanoseconds, s1.readBackNanoseconds) << "a frame left in the application's image was read back";
    gApp->destroy(color);
}

// Shader invocation counting needs the pipelineStatisticsQuery feature,
// which only the application can enable on its device: the application's
// device here was made without it and ExternalDevice says so (its default),
// so nothing is counted and no query is made (the validation layer would
// report a statistics query on a device without the feature).
TEST(Byod, ShaderCountingNeedsTheApplicationsFeature) {
    m3g::vk::useDevice(external());
    EXPECT_FALSE(m3g::vk::shaderInvocationCountingSupported());
    m3g::vk::setShaderInvocationCounting(true);
    m3g::Ref<m3g::World> world = scene(false);
    const m3g::vk::RenderStats s0 = m3g::vk::renderStats();
    const std::vector<std::uint8_t> pixels = reference(world.get());
    m3g::vk::setShaderInvocationCounting(false);
    ASSERT_FALSE(pixels.empty());
    const m3g::vk::RenderStats s1 = m3g::vk::renderStats();
    EXPECT_EQ(s1.frames - s0.frames, 1u);
    EXPECT_EQ(s1.countedFrames, s0.countedFrames);
    EXPECT_EQ(s1.vertexShaderInvocations, s0.vertexShaderInvocations);
}

TEST(Byod, MisuseIsRefusedWithClearErrors) {
    // A null handle: nothing is set up, so the real device can follow.
    m3g::vk::ExternalDevice missing = external();
    missing.queue = VK_NULL_HANDLE;
    EXPECT_THROW(m3g::vk::useDevice(missing), m3g::NullPointerException);
    m3g::vk::ExternalDevice badFamily = external();
    badFamily.queueFamilyIndex = 1000;
    try {
        m3g::vk::useDevice(badFamily);
        ADD_FAILURE() << "a queue family the device lacks was accepted";
    } catch (const m3g::vk::VulkanError& e) {
        EXPECT_NE(std::string(e.what()).find("queueFamilyIndex 1000"), std::string::npos) << e.what();
    }
    m3g::vk::useDevice(external());
    EXPECT_THROW(m3g::vk::useDevice(external()), m3g::IllegalStateException);

    byod::AppImage color = readableImage();
    const m3g::vk::ImageAttachment good = freshAttachment(color);
    EXPECT_THROW(m3g::vk::ImageTarget(kW, kH, m3g::vk::ImageAttachment{}), m3g::NullPointerException);
    EXPECT_THROW(m3g::vk::ImageTarget(kW, kH, {color.image, color.format, VK_IMAGE_LAYOUT_UNDEFINED,
                                               VK_IMAGE_LAYOUT_UNDEFINED}),
                 m3g::IllegalArgumentException);
    EXPECT_THROW(m3g::vk::ImageTarget(0, kH, good), m3g::IllegalArgumentException);
    const VkFormat wrongDepth = m3g::vk::ImageTarget::depthFormat() == VK_FORMAT_D16_UNORM ? VK_FORMAT_D32_SFLOAT
                                                                                           : VK_FORMAT_D16_UNORM;
    EXPECT_THROW(m3g::vk::ImageTarget(kW, kH, good, {color.image, wrongDepth, VK_IMAGE_LAYOUT_UNDEFINED,
                                                     VK_IMAGE_LAYOUT_GENERAL}),
                 m3g::IllegalArgumentException);

    auto target = m3g::make<m3g::vk::ImageTarget>(kW, kH, good);
    m3g::Ref<m3g::World> world = scene(false);
    m3g::Graphics3D* g3d = m3g::Graphics3D::getInstance();
    g3d->bindTarget(target.get());
    EXPECT_THROW(target->setImages(good), m3g::IllegalStateException);
    g3d->render(world.get());
    g3d->releaseTarget();
    // The renderer still holds the device.
    try {
        m3g::vk::releaseDevice();
        ADD_FAILURE() << "releaseDevice succeeded while a renderer holds the device";
    } catch (const m3g::IllegalStateException& e) {
        EXPECT_NE(std::string(e.what()).find("releaseRenderer"), std::string::npos) << e.what();
    }
    g3d->releaseRenderer();
    m3g::vk::releaseDevice();
    // Released: the device can be given again, and renders.
    m3g::vk::useDevice(external());
    render(target.get(), world.get());
    gApp->read(color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    gApp->destroy(color);
}
