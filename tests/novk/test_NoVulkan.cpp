// Without a usable Vulkan (no loader, no driver, a driver that cannot be
// loaded, or one that shows a device and then fails vkCreateDevice:
// fake_icd_no_device.c) the library must fail clearly at the first Graphics3D use
// and keep everything else working. The device is created once per process,
// so this program is run by CTest once per broken setup, with the loader's
// environment (VK_DRIVER_FILES, LD_LIBRARY_PATH) set before it starts and
// M3G_EXPECT_NO_VULKAN=1; without that variable every test is skipped.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include <m3g/m3g.h>
#include <m3g/vk/Vulkan.h>

#include "SampleScene.h"

using namespace m3g;

namespace {

bool expectNoVulkan() {
    const char* v = std::getenv("M3G_EXPECT_NO_VULKAN");
    return v && std::string(v) == "1";
}

/// The message says it is m3g-vk's Vulkan back end and what to install.
void expectClearMessage(const std::string& what) {
    EXPECT_NE(what.find("m3g-vk: "), std::string::npos) << what;
    EXPECT_NE(what.find("apt-get install libvulkan1 mesa-vulkan-drivers"), std::string::npos) << what;
    if (const char* want = std::getenv("M3G_EXPECT_MESSAGE")) {
        EXPECT_NE(what.find(want), std::string::npos) << "expected \"" << want << "\" in: " << what;
    }
}

}  // namespace

TEST(NoVulkan, FirstGraphics3DUseThrowsVulkanError) {
    if (!expectNoVulkan()) GTEST_SKIP() << "run by CTest with a broken Vulkan setup (M3G_EXPECT_NO_VULKAN=1)";
    Graphics3D* g = Graphics3D::getInstance();
    Ref<Image2D> img(new Image2D(Image2D::RGBA, 8, 8));
    std::vector<std::uint8_t> initial;
    img->getPixelsRGBA8(initial);
    // Binding is object-model state: no Vulkan yet.
    ASSERT_NO_THROW(g->bindTarget(img.get()));
    try {
        g->clear(nullptr);
        ADD_FAILURE() << "clear() did not throw without Vulkan";
    } catch (const vk::VulkanError& e) {
        expectClearMessage(e.what());
    }
    // Every later use fails the same way (no half-made device, no crash).
    Ref<World> world = m3gcli::buildSampleScene();
    EXPECT_THROW(g->render(world.get()), vk::VulkanError);
    // VulkanError is an IllegalStateException, as a Java port would catch it.
    EXPECT_THROW(g->clear(nullptr), IllegalStateException);
    EXPECT_NO_THROW(g->releaseTarget());
    EXPECT_EQ(g->getTarget(), nullptr);
    std::vector<std::uint8_t> px;
    img->getPixelsRGBA8(px);
    EXPECT_EQ(px, initial);  // untouched
    // Independent instances too.
    std::unique_ptr<Graphics3D> other = Graphics3D::create();
    other->bindTarget(img.get());
    EXPECT_THROW(other->clear(nullptr), vk::VulkanError);
    other.reset();
    // The queries that need the device say so; the others answer.
    EXPECT_THROW(vk::currentDevice(), vk::VulkanError);
    EXPECT_FALSE(vk::validationEnabled());
    const vk::RenderStats stats = vk::renderStats();
    EXPECT_EQ(stats.frames, 0u);
    EXPECT_EQ(stats.deviceMemoryBytes, 0u);
    EXPECT_FALSE(Graphics3D::getProperties().empty());
}

TEST(NoVulkan, ObjectModelAndLoaderKeepWorking) {
    if (!expectNoVulkan()) GTEST_SKIP() << "run by CTest with a broken Vulkan setup (M3G_EXPECT_NO_VULKAN=1)";
    // Make sure the device was tried and failed in this process first.
    Ref<Image2D> img(new Image2D(Image2D::RGB, 4, 4));
    Graphics3D* g = Graphics3D::getInstance();
    g->bindTarget(img.get());
    EXPECT_THROW(g->clear(nullptr), vk::VulkanError);
    g->releaseTarget();

    Ref<World> world = m3gcli::buildSampleScene();
    Object3D* roots[] = {world.get()};
    const std::vector<std::uint8_t> bytes = Saver::save(roots);
    ASSERT_FALSE(bytes.empty());
    const std::vector<Ref<Object3D>> loaded = Loader::load(bytes, 0);
    ASSERT_EQ(loaded.size(), 1u);
    auto* copy = dynamic_cast<World*>(loaded[0].get());
    ASSERT_NE(copy, nullptr);
    ASSERT_NE(copy->getActiveCamera(), nullptr);
    EXPECT_EQ(copy->getChildCount(), world->getChildCount());
    EXPECT_GE(copy->animate(500), 0);
    Ref<Object3D> duplicate = copy->duplicate();
    EXPECT_NE(dynamic_cast<World*>(duplicate.get()), nullptr);
    // Picking is CPU work: through the middle of the view of the sample scene.
    RayIntersection ri;
    EXPECT_NO_THROW(copy->pick(-1, 0.5f, 0.5f, copy->getActiveCamera().get(), &ri));
}
