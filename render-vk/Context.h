// The process-wide Vulkan instance and device (docs/rendering.md, docs/threading.md: one
// device per process, shared by every Graphics3D). Functions come through
// volk, so a missing libvulkan is a VulkanError at first use, not a failure
// to start the program.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include <volk.h>

#include <m3g/vk/ExternalDevice.h>
#include <m3g/vk/Vulkan.h>

namespace m3g::vk {

/// Records one image layout transition (mip levels [level, level + count)).
void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, std::uint32_t level,
                  std::uint32_t count, VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 srcStage,
                  VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);
/// Records a copy of `width` x `height` RGBA texels from `buffer` into mip
/// level 0 of `image` (in TRANSFER_DST_OPTIMAL layout).
void copyBufferToImage(VkCommandBuffer cmd, VkBuffer buffer, VkImage image, std::uint32_t width, std::uint32_t height);

/// A shader module from SPIR-V (`bytes` long, as embedded by glslangValidator).
VkShaderModule createShaderModule(VkDevice device, const std::uint32_t* code, std::size_t bytes);

/// A descriptor pool of `sets` sets holding `perSet` descriptors of one
/// `type` each; `what` names it in the error.
VkDescriptorPool createDescriptorPool(VkDevice device, VkDescriptorType type, std::uint32_t sets,
                                      std::uint32_t perSet, const char* what, VkDescriptorPoolCreateFlags flags = 0);

/// Throws VulkanError naming `what` when `result` is not VK_SUCCESS.
void check(VkResult result, const char* what);
const char* resultName(VkResult result);

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr;  ///< persistently mapped (host-visible buffers)
};

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    std::uint32_t width = 0, height = 0, mipLevels = 1;
    VkDeviceSize bytes = 0;
    void* mapped = nullptr;     ///< createHostImage: the texels, rows rowPitch bytes apart
    VkDeviceSize rowPitch = 0;  ///< createHostImage only
};

class Context {
public:
    /// The shared context, created on first call (throws VulkanError).
    static Context& get();
    /// The same, shared: holders (renderers) keep the device alive until
    /// they are gone, whatever the order of static destruction.
    static std::shared_ptr<Context> shared();
    /// True once get() has succeeded.
    static bool exists() noexcept;
    /// The shared context if it exists, else null; never creates one.
    static std::shared_ptr<Context> existing() noexcept;
    /// Runs `f` and returns true if the device has not been created yet
    /// (under the lock that creation takes); false otherwise.
    static bool beforeCreation(const std::function<void()>& f);
    /// useDevice(): the shared context on the application's device, made
    /// now (ISE when one exists already).
    static void adopt(const ExternalDevice& device);
    /// releaseDevice(): drops the shared context (ISE while renderers hold it).
    static void release();

    VkInstance instance() const noexcept { return instance_; }
    VkPhysicalDevice physicalDevice() const noexcept { return physical_; }
    VkDevice device() const noexcept { return device_; }
    VkQueue queue() const noexcept { return queue_; }
    std::uint32_t queueFamily() const noexcept { return queueFamily_; }
    const VkPhysicalDeviceProperties& properties() const noexcept { return properties_; }
    const DeviceInfo& info() const noexcept { return info_; }
    VkFormat depthFormat() const noexcept { return depthFormat_; }
    VkSampleCountFlagBits maxSamples() const noexcept { return maxSamples_; }
    bool validation() const noexcept { return validation_; }
    /// Made on the application's device (useDevice), which it does not own.
    bool external() const noexcept { return external_; }

    /// What the host does with a host buffer's memory: writes it for the
    /// device (uniforms, vertices, staging), or reads what the device wrote
    /// (read-back).
    enum class HostAccess { Write, Read };
    /// Host-visible, coherent, persistently mapped buffer. Write: device-local
    /// too where the device has such memory (lavapipe, resizable BAR), which
    /// the device reads at full speed. Read: host-cached where the device has
    /// it, since the CPU reads uncached device-local memory at a small
    /// fraction of its speed (docs/gpu.md).
    Buffer createHostBuffer(VkDeviceSize size, VkBufferUsageFlags usage, HostAccess access = HostAccess::Write);
    void destroy(Buffer& buffer) noexcept;
    /// Device-local 2D image with a view (colour or depth aspect by format).
    Image createImage(std::uint32_t width, std::uint32_t height, VkFormat format, VkImageUsageFlags usage,
                      std::uint32_t mipLevels = 1, VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT);
    /// A single-sampled 2D image with linear tiling in host-visible,
    /// coherent memory, persistently mapped (Image::mapped, rowPitch), for
    /// `usage`; only where hostImageUsable(format, features) is true.
    Image createHostImage(std::uint32_t width, std::uint32_t height, VkFormat format, VkImageUsageFlags usage);
    /// Whether a linear image of `format` supports `features` and is worth
    /// using as a render target read by the host: CPU devices only (on a
    /// GPU, rendering to linear memory is slow or unsupported).
    bool hostImageUsable(VkFormat format, VkFormatFeatureFlags features) const;
    void destroy(Image& image) noexcept;

    /// Records `record` into a one-shot command buffer of the shared pool,
    /// submits it and waits (callable from any thread: the pool is locked
    /// while recording, the queue while submitting).
    void submitNow(const std::function<void(VkCommandBuffer)>& record);
    /// Submits `cmd` signalling `fence` (queue access is serialised).
    void submit(VkCommandBuffer cmd, VkFence fence) { submit(std::span<const VkCommandBuffer>(&cmd, 1), fence); }
    /// Submits `cmds` in order, in one batch, signalling `fence`; with
    /// `wait`, the batch waits for it at `waitStage`, and with `signal` it
    /// signals that semaphore too (a swapchain frame).
    void submit(std::span<const VkCommandBuffer> cmds, VkFence fence, VkSemaphore wait = VK_NULL_HANDLE,
                VkPipelineStageFlags waitStage = 0, VkSemaphore signal = VK_NULL_HANDLE);
    /// vkQueuePresentKHR under the queue lock; returns its result.
    VkResult present(const VkPresentInfoKHR& info);
    /// Whether VK_KHR_swapchain was enabled (requestWindowExtensions).
    bool swapchainEnabled() const noexcept { return swapchain_; }
    /// Whether polygon mode LINE can be used (the wireframe debug view).
    bool wireframeSupported() const noexcept { return wireframe_; }
    /// Whether pipeline-statistics queries can be used (shader invocation
    /// counting, setShaderInvocationCounting).
    bool pipelineStatisticsSupported() const noexcept { return pipelineStatistics_; }
    /// vkDeviceWaitIdle with the queue locked (Vulkan requires external
    /// synchronisation of every queue of the device for it).
    void waitIdle();
    /// The queue lock, for any other direct use of queue() (e.g.
    /// vkQueuePresentKHR): hold it for the duration of the call.
    [[nodiscard]] std::unique_lock<std::mutex> lockQueue() { return std::unique_lock(*queueLock_); }

    /// A resettable command pool of the queue family for one thread's (one
    /// renderer's) own command buffers: a pool and the buffers allocated from
    /// it must be used by one thread at a time, so renderers never share one.
    VkCommandPool createCommandPool();

    /// The shared pool of submitNow; use only with poolMutex() held.
    VkCommandPool commandPool() const noexcept { return pool_; }
    std::mutex& poolMutex() noexcept { return poolMutex_; }

    std::atomic<std::uint64_t> pipelinesCreated{0}, pipelinesEvicted{0}, draws{0}, bufferUploads{0},
        textureUploads{0}, frames{0}, computeDispatches{0}, pipelineCacheBytesLoaded{0}, pipelineCacheSaves{0},
        frameWaitNanos{0}, readBackNanos{0}, countedFrames{0}, vertexInvocations{0}, fragmentInvocations{0};
    std::atomic<std::int64_t> liveBuffers{0}, liveTextures{0}, livePipelines{0}, memoryBytes{0};

    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

private:
    Context();
    explicit Context(const ExternalDevice& device);
    /// The logical device on physical_ with the features and extensions render-vk uses.
    void createDevice(const std::vector<VkPhysicalDevice>& devices);
    std::uint32_t memoryType(std::uint32_t bits, VkMemoryPropertyFlags want, VkMemoryPropertyFlags fallback) const;
    /// createImage and createHostImage: the image, its memory and its view.
    Image makeImage(std::uint32_t width, std::uint32_t height, VkFormat format, VkImageUsageFlags usage,
                    std::uint32_t mipLevels, VkSampleCountFlagBits samples, bool host);

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    std::uint32_t queueFamily_ = 0;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties_{};
    VkPhysicalDeviceMemoryProperties memory_{};
    DeviceInfo info_;
    VkFormat depthFormat_ = VK_FORMAT_D32_SFLOAT;
    VkSampleCountFlagBits maxSamples_ = VK_SAMPLE_COUNT_1_BIT;
    bool validation_ = false;
    bool swapchain_ = false;
    bool wireframe_ = false;
    bool pipelineStatistics_ = false;
    bool external_ = false;
    std::mutex queueMutex_, poolMutex_;
    std::mutex* queueLock_ = &queueMutex_;  // queueMutex_ or the application's (ExternalDevice::queueMutex)
};

}  // namespace m3g::vk
