#include "Context.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>
#include <string_view>
#include <vector>

#include "DeviceSelection.h"
#include "HostHeap.h"
#include "Instance.h"

namespace m3g::vk {

namespace {
std::mutex gContextMutex;
std::shared_ptr<Context> gContext;
std::atomic<bool> gExists{false};
}  // namespace

bool Context::exists() noexcept { return gExists.load(); }

Context& Context::get() { return *shared(); }

bool Context::beforeCreation(const std::function<void()>& f) {
    std::lock_guard lock(gContextMutex);
    if (gContext) return false;
    f();
    return true;
}

namespace {
// Keeps `context` as the shared one (gContextMutex held).
void install(std::shared_ptr<Context> context) {
    gContext = std::move(context);
    gExists = true;
    // Destroy the device before the driver's and layers' static
    // destructors (registered before this handler, so they run after it).
    static const bool registered = [] {
        std::atexit([] {
            std::shared_ptr<Context> last;
            {
                std::lock_guard inner(gContextMutex);
                last.swap(gContext);
                gExists = false;
            }
        });
        return true;
    }();
    (void)registered;
}
}  // namespace

std::shared_ptr<Context> Context::existing() noexcept {
    std::lock_guard lock(gContextMutex);
    return gContext;
}

std::shared_ptr<Context> Context::shared() {
    std::lock_guard lock(gContextMutex);
    if (!gContext) install(std::shared_ptr<Context>(new Context()));
    return gContext;
}

void Context::adopt(const ExternalDevice& device) {
    std::lock_guard lock(gContextMutex);
    if (gContext)
        throw IllegalStateException(std::string("m3g::vk::useDevice: m3g-vk already renders with ") +
                                    (gContext->external() ? "an application's" : "its own") + " device \"" +
                                    gContext->info().name +
                                    "\"; call useDevice before the first Graphics3D clear or render, or after "
                                    "m3g::vk::releaseDevice()");
    install(std::shared_ptr<Context>(new Context(device)));
}

void Context::release() {
    std::shared_ptr<Context> last;
    {
        std::lock_guard lock(gContextMutex);
        if (!gContext) return;
        if (const long holders = gContext.use_count() - 1; holders > 0)
            throw IllegalStateException("m3g::vk::releaseDevice: " + std::to_string(holders) +
                                        " renderer(s) still use the device; call Graphics3D::releaseRenderer() on "
                                        "each thread's Graphics3D that rendered (and release bound targets) first");
        last.swap(gContext);
        gExists = false;
    }
    // Destroyed here, outside the lock: it waits for the device.
}

Context::Context() {
    instance_ = createInstance(envValidation(), validation_);
    try {
        if (validation_) messenger_ = createMessenger(instance_);
        const std::vector<VkPhysicalDevice> devices = physicalDevices(instance_);
        physical_ = choosePhysicalDevice(devices);
        vkGetPhysicalDeviceProperties(physical_, &properties_);
        vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
        info_ = describe(physical_);
        // lavapipe's per-draw vertex storage comes from the host heap (HostHeap.h).
        if (properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) keepHostHeap();
        if (properties_.apiVersion < VK_API_VERSION_1_3)
            throw VulkanError("m3g-vk: device \"" + info_.name + "\" supports only Vulkan " +
                              std::to_string(VK_API_VERSION_MAJOR(properties_.apiVersion)) + "." +
                              std::to_string(VK_API_VERSION_MINOR(properties_.apiVersion)) + "; m3g-vk needs 1.3");
        queueFamily_ = graphicsComputeFamily(physical_, info_.name);
        depthFormat_ = chooseDepthFormat(physical_);
        maxSamples_ = antialiasSamples(properties_);
        createDevice(devices);
        volkLoadDevice(device_);
        vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
        pool_ = createCommandPool();
    } catch (...) {
        if (device_) vkDestroyDevice(device_, nullptr);
        if (messenger_) vkDestroyDebugUtilsMessengerEXT(instance_, messenger_, nullptr);
        vkDestroyInstance(instance_, nullptr);
        throw;
    }
}

void Context::createDevice(const std::vector<VkPhysicalDevice>& devices) {
    VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    f2.pNext = &f13;
    vkGetPhysicalDeviceFeatures2(physical_, &f2);
    if (!f13.dynamicRendering || !f13.synchronization2)
        throw VulkanError("m3g-vk: device \"" + info_.name + "\" lacks dynamicRendering or synchronization2");
    VkPhysicalDeviceVulkan13Features enable13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    enable13.dynamicRendering = VK_TRUE;
    enable13.synchronization2 = VK_TRUE;
    VkPhysicalDeviceFeatures2 enable{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    enable.pNext = &enable13;
    enable.features.samplerAnisotropy = VK_FALSE;
    // Wireframe debug view only (DebugView::wireframe).
    enable.features.fillModeNonSolid = f2.features.fillModeNonSolid;
    wireframe_ = f2.features.fillModeNonSolid == VK_TRUE;
    // Shader invocation counting (setShaderInvocationCounting): a query
    // only while it is on, so enabling the feature costs nothing otherwise.
    enable.features.pipelineStatisticsQuery = f2.features.pipelineStatisticsQuery;
    pipelineStatistics_ = f2.features.pipelineStatisticsQuery == VK_TRUE;

    std::vector<const char*> extensions;
    std::uint32_t ne = 0;
    vkEnumerateDeviceExtensionProperties(physical_, nullptr, &ne, nullptr);
    std::vector<VkExtensionProperties> available(ne);
    vkEnumerateDeviceExtensionProperties(physical_, nullptr, &ne, available.data());
    // Swapchains only for windowed applications (requestWindowExtensions).
    if (!gWindowExtensions.empty())
        for (const auto& e : available)
            if (std::strcmp(e.extensionName, VK_KHR_SWAPCHAIN_EXTENSION_NAME) == 0) {
                extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
                swapchain_ = true;
            }

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qi{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qi.queueFamilyIndex = queueFamily_;
    qi.queueCount = 1;
    qi.pQueuePriorities = &priority;
    VkDeviceCreateInfo di{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    di.pNext = &enable;
    di.queueCreateInfoCount = 1;
    di.pQueueCreateInfos = &qi;
    di.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    di.ppEnabledExtensionNames = extensions.data();
    const VkResult r = vkCreateDevice(physical_, &di, nullptr, &device_);
    if (r != VK_SUCCESS) {
        // The driver loaded and showed the device, then refused it: a broken
        // driver or a GPU that is gone. Name the device as M3G_VK_DEVICE
        // selects it, and the other ways out.
        const auto index = std::find(devices.begin(), devices.end(), physical_) - devices.begin();
        throw VulkanError("m3g-vk: the Vulkan driver could not create a device on device " + std::to_string(index) +
                          " \"" + info_.name + "\" (vkCreateDevice: " + resultName(r) + ", " +
                          std::to_string(static_cast<int>(r)) + ")" + driverOverrides() +
                          "; the driver or the GPU is not working (check with vulkaninfo): " + kInstallHint +
                          ", or another driver with VK_DRIVER_FILES");
    }
}

Context::~Context() {
    if (external_) {
        // The application's device and instance stay; only what m3g-vk made goes.
        {
            std::lock_guard lock(*queueLock_);
            vkDeviceWaitIdle(device_);
        }
        vkDestroyCommandPool(device_, pool_, nullptr);
        return;
    }
    if (device_) {
        vkDeviceWaitIdle(device_);
        vkDestroyCommandPool(device_, pool_, nullptr);
        vkDestroyDevice(device_, nullptr);
    }
    if (messenger_) vkDestroyDebugUtilsMessengerEXT(instance_, messenger_, nullptr);
    if (instance_) vkDestroyInstance(instance_, nullptr);
}

std::uint32_t Context::memoryType(std::uint32_t bits, VkMemoryPropertyFlags want, VkMemoryPropertyFlags fallback) const {
    for (VkMemoryPropertyFlags flags : {want, fallback})
        for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
            if ((bits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & flags) == flags) return i;
    throw VulkanError("m3g-vk: no suitable memory type");
}

Buffer Context::createHostBuffer(VkDeviceSize size, VkBufferUsageFlags usage, HostAccess access) {
    Buffer b;
    b.size = size;
    VkBufferCreateInfo bi{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bi.size = size;
    bi.usage = usage;
    bi.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    check(vkCreateBuffer(device_, &bi, nullptr, &b.buffer), "vkCreateBuffer");
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device_, b.buffer, &req);
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    constexpr VkMemoryPropertyFlags kHost = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    const VkMemoryPropertyFlags preferred = access == HostAccess::Read ? kHost | VK_MEMORY_PROPERTY_HOST_CACHED_BIT
                                                                       : kHost | VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    ai.memoryTypeIndex = memoryType(req.memoryTypeBits, preferred, kHost);
    VkResult r = vkAllocateMemory(device_, &ai, nullptr, &b.memory);
    if (r != VK_SUCCESS) {
        vkDestroyBuffer(device_, b.buffer, nullptr);
        check(r, "vkAllocateMemory (buffer)");
    }
    vkBindBufferMemory(device_, b.buffer, b.memory, 0);
    check(vkMapMemory(device_, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
    ++liveBuffers;
    memoryBytes += static_cast<std::int64_t>(req.size);
    b.size = size;
    return b;
}

void Context::destroy(Buffer& b) noexcept {
    if (!b.buffer) return;
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device_, b.buffer, &req);
    memoryBytes -= static_cast<std::int64_t>(req.size);
    --liveBuffers;
    vkDestroyBuffer(device_, b.buffer, nullptr);
    vkFreeMemory(device_, b.memory, nullptr);
    b = Buffer{};
}

Image Context::createImage(std::uint32_t width, std::uint32_t height, VkFormat format, VkImageUsageFlags usage,
                           std::uint32_t mipLevels, VkSampleCountFlagBits samples) {
    return makeImage(width, height, format, usage, mipLevels, samples, false);
}

Image Context::createHostImage(std::uint32_t width, std::uint32_t height, VkFormat format, VkImageUsageFlags usage) {
    return makeImage(width, height, format, usage, 1, VK_SAMPLE_COUNT_1_BIT, true);
}

bool Context::hostImageUsable(VkFormat format, VkFormatFeatureFlags features) const {
    if (properties_.deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU) return false;
    VkFormatProperties fp;
    vkGetPhysicalDeviceFormatProperties(physical_, format, &fp);
    return (fp.linearTilingFeatures & features) == features;
}

Image Context::makeImage(std::uint32_t width, std::uint32_t height, VkFormat format, VkImageUsageFlags usage,
                         std::uint32_t mipLevels, VkSampleCountFlagBits samples, bool host) {
    Image img;
    img.format = format;
    img.width = width;
    img.height = height;
    img.mipLevels = mipLevels;
    VkImageCreateInfo ii{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ii.imageType = VK_IMAGE_TYPE_2D;
    ii.format = format;
    ii.extent = {width, height, 1};
    ii.mipLevels = mipLevels;
    ii.arrayLayers = 1;
    ii.samples = samples;
    ii.tiling = host ? VK_IMAGE_TILING_LINEAR : VK_IMAGE_TILING_OPTIMAL;
    ii.usage = usage;
    ii.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    check(vkCreateImage(device_, &ii, nullptr, &img.image), "vkCreateImage");
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device_, img.image, &req);
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    const VkMemoryPropertyFlags hostFlags = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    VkResult r = VK_ERROR_OUT_OF_DEVICE_MEMORY;
    try {
        ai.memoryTypeIndex = host ? memoryType(req.memoryTypeBits, hostFlags, hostFlags)
                                  : memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0);
        r = vkAllocateMemory(device_, &ai, nullptr, &img.memory);
    } catch (...) {
        vkDestroyImage(device_, img.image, nullptr);
        throw;
    }
    if (r != VK_SUCCESS) {
        vkDestroyImage(device_, img.image, nullptr);
        check(r, "vkAllocateMemory (image)");
    }
    vkBindImageMemory(device_, img.image, img.memory, 0);
    if (host) {
        const VkImageSubresource sub{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0};
        VkSubresourceLayout layout;
        vkGetImageSubresourceLayout(device_, img.image, &sub, &layout);
        img.rowPitch = layout.rowPitch;
        void* base = nullptr;
        check(vkMapMemory(device_, img.memory, 0, VK_WHOLE_SIZE, 0, &base), "vkMapMemory (image)");
        img.mapped = static_cast<char*>(base) + layout.offset;
    }
    const bool depth = format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D16_UNORM;
    VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vi.image = img.image;
    vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vi.format = format;
    vi.subresourceRange = {static_cast<VkImageAspectFlags>(depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT),
                           0, mipLevels, 0, 1};
    check(vkCreateImageView(device_, &vi, nullptr, &img.view), "vkCreateImageView");
    img.bytes = req.size;
    memoryBytes += static_cast<std::int64_t>(req.size);
    ++liveTextures;
    return img;
}

void Context::destroy(Image& img) noexcept {
    if (!img.image) return;
    memoryBytes -= static_cast<std::int64_t>(img.bytes);
    --liveTextures;
    vkDestroyImageView(device_, img.view, nullptr);
    vkDestroyImage(device_, img.image, nullptr);
    vkFreeMemory(device_, img.memory, nullptr);
    img = Image{};
}

void Context::submitNow(const std::function<void(VkCommandBuffer)>& record) {
    VkCommandBuffer cmd;
    {
        // Recording into a buffer of the shared pool is host access to the
        // pool: hold its lock until the buffer is ended.
        std::lock_guard lock(poolMutex_);
        VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        ai.commandPool = pool_;
        ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        ai.commandBufferCount = 1;
        check(vkAllocateCommandBuffers(device_, &ai, &cmd), "vkAllocateCommandBuffers");
        VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        vkBeginCommandBuffer(cmd, &bi);
        try {
            record(cmd);
        } catch (...) {
            vkEndCommandBuffer(cmd);
            vkFreeCommandBuffers(device_, pool_, 1, &cmd);
            throw;
        }
        vkEndCommandBuffer(cmd);
    }
    auto freeCommandBuffer = [&] {
        std::lock_guard lock(poolMutex_);
        vkFreeCommandBuffers(device_, pool_, 1, &cmd);
    };
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    VkResult r = vkCreateFence(device_, &fi, nullptr, &fence);
    if (r != VK_SUCCESS) {
        freeCommandBuffer();
        check(r, "vkCreateFence");
    }
    try {
        submit(cmd, fence);
    } catch (...) {
        vkDestroyFence(device_, fence, nullptr);
        freeCommandBuffer();
        throw;
    }
    r = vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX);
    vkDestroyFence(device_, fence, nullptr);
    freeCommandBuffer();
    check(r, "vkWaitForFences (upload)");
}

void Context::submit(std::span<const VkCommandBuffer> cmds, VkFence fence, VkSemaphore wait,
                     VkPipelineStageFlags waitStage, VkSemaphore signal) {
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = static_cast<std::uint32_t>(cmds.size());
    si.pCommandBuffers = cmds.data();
    si.waitSemaphoreCount = wait ? 1 : 0;
    si.pWaitSemaphores = &wait;
    si.pWaitDstStageMask = &waitStage;
    si.signalSemaphoreCount = signal ? 1 : 0;
    si.pSignalSemaphores = &signal;
    std::lock_guard lock(*queueLock_);
    check(vkQueueSubmit(queue_, 1, &si, fence), "vkQueueSubmit");
}

VkResult Context::present(const VkPresentInfoKHR& info) {
    std::lock_guard lock(*queueLock_);
    return vkQueuePresentKHR(queue_, &info);
}

void Context::waitIdle() {
    std::lock_guard lock(*queueLock_);
    vkDeviceWaitIdle(device_);
}

VkCommandPool Context::createCommandPool() {
    VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pi.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pi.queueFamilyIndex = queueFamily_;
    VkCommandPool pool = VK_NULL_HANDLE;
    check(vkCreateCommandPool(device_, &pi, nullptr, &pool), "vkCreateCommandPool");
    return pool;
}


}  // namespace m3g::vk
