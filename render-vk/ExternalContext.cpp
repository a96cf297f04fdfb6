// The shared Context on an application's own device (useDevice,
// ExternalDevice.h): what m3g-vk needs of the device is checked, nothing of
// the application's is created or destroyed.
#include "Context.h"

#include <string>
#include <vector>

#include "DeviceSelection.h"
#include "HostHeap.h"
#include "Instance.h"

namespace m3g::vk {

namespace {

void requireHandle(const void* handle, const char* field) {
    if (!handle)
        throw NullPointerException(std::string("m3g::vk::useDevice: ExternalDevice::") + field + " is null");
}

}  // namespace

Context::Context(const ExternalDevice& d) {
    requireHandle(d.instance, "instance");
    requireHandle(d.physicalDevice, "physicalDevice");
    requireHandle(d.device, "device");
    requireHandle(d.queue, "queue");
    // m3g-vk's calls go through the application's loader, instance and device.
    if (d.getInstanceProcAddr)
        volkInitializeCustom(d.getInstanceProcAddr);
    else
        loadLoader();
    volkLoadInstance(d.instance);
    volkLoadDevice(d.device);
    external_ = true;
    instance_ = d.instance;
    physical_ = d.physicalDevice;
    device_ = d.device;
    queue_ = d.queue;
    queueFamily_ = d.queueFamilyIndex;
    if (d.queueMutex) queueLock_ = d.queueMutex;
    vkGetPhysicalDeviceProperties(physical_, &properties_);
    vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
    info_ = describe(physical_);
    if (properties_.apiVersion < VK_API_VERSION_1_3)
        throw VulkanError("m3g::vk::useDevice: device \"" + info_.name + "\" supports only Vulkan " +
                          std::to_string(VK_API_VERSION_MAJOR(properties_.apiVersion)) + "." +
                          std::to_string(VK_API_VERSION_MINOR(properties_.apiVersion)) + "; m3g-vk needs 1.3");
    VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    f2.pNext = &f13;
    vkGetPhysicalDeviceFeatures2(physical_, &f2);
    if (!f13.dynamicRendering || !f13.synchronization2)
        throw VulkanError("m3g::vk::useDevice: device \"" + info_.name + "\" lacks dynamicRendering or synchronization2");
    std::uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical_, &families, nullptr);
    std::vector<VkQueueFamilyProperties> props(families);
    vkGetPhysicalDeviceQueueFamilyProperties(physical_, &families, props.data());
    constexpr VkQueueFlags kBoth = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    if (queueFamily_ >= families || (props[queueFamily_].queueFlags & kBoth) != kBoth)
        throw VulkanError("m3g::vk::useDevice: queueFamilyIndex " + std::to_string(queueFamily_) + " of device \"" +
                          info_.name + "\" is not a graphics and compute queue family (the device has " +
                          std::to_string(families) + " families)");
    // lavapipe's per-draw vertex storage comes from the host heap (HostHeap.h).
    if (properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) keepHostHeap();
    depthFormat_ = chooseDepthFormat(physical_);
    maxSamples_ = antialiasSamples(properties_);
    wireframe_ = d.fillModeNonSolid;
    pipelineStatistics_ = d.pipelineStatisticsQuery && f2.features.pipelineStatisticsQuery == VK_TRUE;
    swapchain_ = d.swapchain;
    pool_ = createCommandPool();
}

}  // namespace m3g::vk
