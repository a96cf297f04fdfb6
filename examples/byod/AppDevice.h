// The application's side of the bring-your-own-device example (main.cpp):
// an engine's own Vulkan instance, device, queue and images, made with the
// plain Vulkan API (libvulkan), as an engine that m3g-vk is ported into
// already has them. Nothing here is m3g-vk; the test of the feature
// (tests/byod) drives m3g-vk with the same objects.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace byod {

struct AppImage {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    std::uint32_t width = 0, height = 0;
};

class AppDevice {
public:
    /// A Vulkan 1.3 instance (with VK_LAYER_KHRONOS_validation when
    /// `validation` and installed), the first device with a graphics and
    /// compute queue, and that queue; dynamicRendering and synchronization2
    /// enabled, as m3g-vk needs. Throws std::runtime_error saying what failed.
    explicit AppDevice(bool validation);
    ~AppDevice();
    /// Destroys the device and the instance (the validation layer reports
    /// any object still alive on them then).
    void close() noexcept;
    AppDevice(const AppDevice&) = delete;
    AppDevice& operator=(const AppDevice&) = delete;

    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    std::uint32_t queueFamily = 0;
    bool validation = false;
    std::string deviceName;

    /// Warnings and errors the validation layer reported on this instance.
    std::uint64_t validationMessages() const noexcept { return messages_.load(); }

    /// A device-local 2D image with `usage`, left in UNDEFINED layout.
    AppImage createImage(std::uint32_t width, std::uint32_t height, VkFormat format, VkImageUsageFlags usage);
    void destroy(AppImage& image) noexcept;
    VkSemaphore createSemaphore();
    void destroy(VkSemaphore semaphore) noexcept;

    /// Records `record` into a one-shot command buffer and submits it,
    /// waiting for `wait` at `waitStages` and signalling `signal` (either may
    /// be null); returns when the GPU is done with it.
    void submit(const std::function<void(VkCommandBuffer)>& record, VkSemaphore wait = VK_NULL_HANDLE,
                VkPipelineStageFlags waitStages = 0, VkSemaphore signal = VK_NULL_HANDLE);
    /// A layout transition of every texel of `image` (colour or depth aspect).
    static void transition(VkCommandBuffer cmd, const AppImage& image, VkImageLayout from, VkImageLayout to);
    /// A 2D view of every texel of `image` (colour or depth aspect by format).
    VkImageView createView(const AppImage& image);
    /// The application's own frame: `color` cleared to `clear` (RGBA bytes)
    /// and `depth` (if any) to far, then a panel of colour `panel` at depth 0
    /// (nearer than anything) over the columns from `panelX` on; both left in
    /// their attachment layouts; the submission signals `signal`.
    void drawPanelFrame(const AppImage& color, const AppImage* depth, const std::uint8_t (&clear)[4],
                        const std::uint8_t (&panel)[4], std::uint32_t panelX, VkSemaphore signal);
    /// The texels of a 4-byte colour image in `layout` (TRANSFER_SRC usage),
    /// rows top to bottom, as the format stores them; waits for `wait` first.
    std::vector<std::uint8_t> read(const AppImage& image, VkImageLayout layout, VkSemaphore wait = VK_NULL_HANDLE);

private:
    std::uint32_t memoryType(std::uint32_t bits, VkMemoryPropertyFlags flags) const;

    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    std::atomic<std::uint64_t> messages_{0};
};

}  // namespace byod
