// Bring your own device (docs/library.md): an application that owns its
// Vulkan instance, device, queue and images draws its own frame, has m3g-vk
// composite an M3G scene into it on the GPU, then reads the result back and
// writes it as a PNG. The application's frame is a blue clear with an orange
// panel in front (depth 0) over its right third; the M3G scene is drawn over
// the blue and depth-tested against the application's depth, so the panel
// hides it. Order between the two is kept by semaphores.
//
//   m3g_byod scene.m3g out.png
//
// Exits 1 on any error or validation message (the application's instance has
// the validation layer when installed and M3G_VK_VALIDATION is not 0).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <m3g/m3g.h>
#include <m3g/vk/ExternalDevice.h>
#include <m3g/vk/ImageTarget.h>

#include "AppDevice.h"

namespace {

constexpr std::uint32_t kWidth = 320, kHeight = 240;

// The application's own frame: a blue clear, an orange panel nearer than
// anything over the right third.
constexpr std::uint8_t kClear[4] = {0x20, 0x40, 0x80, 0xFF};
constexpr std::uint8_t kPanel[4] = {0xE0, 0x90, 0x20, 0xFF};

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) return std::fprintf(stderr, "usage: %s scene.m3g out.png\n", argv[0]), 2;
    const char* env = std::getenv("M3G_VK_VALIDATION");
    std::uint64_t messages = 0;
    try {
        byod::AppDevice app(!env || std::strcmp(env, "0") != 0);
        {
            // m3g-vk renders with the application's device from here on.
            m3g::vk::ExternalDevice device;
            device.instance = app.instance;
            device.physicalDevice = app.physicalDevice;
            device.device = app.device;
            device.queue = app.queue;
            device.queueFamilyIndex = app.queueFamily;
            device.getInstanceProcAddr = vkGetInstanceProcAddr;
            m3g::vk::useDevice(device);

            // The application's frame: a swapchain-like BGRA image and a depth image of m3g-vk's format.
            byod::AppImage color = app.createImage(kWidth, kHeight, VK_FORMAT_B8G8R8A8_UNORM,
                                                   VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                                       VK_IMAGE_USAGE_TRANSFER_DST_BIT);
            byod::AppImage depth = app.createImage(kWidth, kHeight, m3g::vk::ImageTarget::depthFormat(),
                                                   VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
            VkSemaphore appDrawn = app.createSemaphore(), sceneDrawn = app.createSemaphore();
            app.drawPanelFrame(color, &depth, kClear, kPanel, kWidth * 2 / 3, appDrawn);

            // The M3G scene, composited over the application's frame: its
            // Background clears neither colour nor depth (as a MIDlet draws
            // 3D over its 2D; render(World) without a Background would clear
            // both, JSR-184 1.1 Graphics3D.render).
            m3g::World* world = nullptr;
            const auto objects = m3g::Loader::load(argv[1]);
            for (const auto& o : objects)
                if (auto* w = dynamic_cast<m3g::World*>(o.get())) world = w;
            if (!world) throw std::runtime_error(std::string("no World in ") + argv[1]);
            auto keep = m3g::make<m3g::Background>();
            keep->setColorClearEnable(false);
            keep->setDepthClearEnable(false);
            world->setBackground(keep.get());
            world->animate(0);
            auto target = m3g::make<m3g::vk::ImageTarget>(
                kWidth, kHeight,
                m3g::vk::ImageAttachment{color.image, color.format, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                         VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL},
                m3g::vk::ImageAttachment{depth.image, depth.format, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                                         VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL});
            target->waitFor(appDrawn, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT);
            target->signalWhenDone(sceneDrawn);
            m3g::Graphics3D* g3d = m3g::Graphics3D::getInstance();
            g3d->bindTarget(target.get());
            g3d->render(world);
            g3d->releaseTarget();

            // The application reads its image after m3g-vk's work (B, G, R, A bytes) and saves it.
            const std::vector<std::uint8_t> bgra = app.read(color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, sceneDrawn);
            auto png = m3g::make<m3g::Image2D>(m3g::Image2D::RGBA, static_cast<int>(kWidth), static_cast<int>(kHeight));
            std::vector<std::uint8_t> rgba(bgra.size());
            for (std::size_t i = 0; i < bgra.size(); i += 4) {
                rgba[i] = bgra[i + 2];
                rgba[i + 1] = bgra[i + 1];
                rgba[i + 2] = bgra[i];
                rgba[i + 3] = bgra[i + 3];
            }
            png->set(0, 0, static_cast<int>(kWidth), static_cast<int>(kHeight), rgba);
            m3g::writePng(*png, argv[2]);
            std::printf("composited %s into the application's %ux%u B8G8R8A8 image on %s: %s\n", argv[1], kWidth,
                        kHeight, app.deviceName.c_str(), argv[2]);

            // Before the application destroys its device: m3g-vk lets go of it.
            g3d->releaseRenderer();
            m3g::vk::releaseDevice();
            app.destroy(appDrawn);
            app.destroy(sceneDrawn);
            app.destroy(color);
            app.destroy(depth);
        }
        app.close();  // counts what the layer says of objects left alive on the device
        messages = app.validationMessages();
        if (!app.validation) std::printf("(the validation layer was not used)\n");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "m3g_byod: %s\n", e.what());
        return 1;
    }
    std::printf("validation messages: %llu\n", static_cast<unsigned long long>(messages));
    return messages == 0 ? 0 : 1;
}
