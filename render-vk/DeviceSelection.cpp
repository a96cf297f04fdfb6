#include "DeviceSelection.h"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <string_view>

#include "Instance.h"

namespace m3g::vk {

VkPhysicalDevice choosePhysicalDevice(const std::vector<VkPhysicalDevice>& devices) {
    std::vector<VkPhysicalDevice> usable;
    for (auto pd : devices) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(pd, &p);
        if (p.apiVersion >= VK_API_VERSION_1_3) usable.push_back(pd);
    }
    if (devices.empty())
        throw VulkanError("m3g-vk: the Vulkan loader reports no device" + driverOverrides() + "; " + kInstallHint);
    if (usable.empty())
        throw VulkanError(std::string("m3g-vk: no Vulkan 1.3 device found (") + std::to_string(devices.size()) +
                          " device(s) of older versions); " + kInstallHint);
    if (const char* want = std::getenv("M3G_VK_DEVICE"); want && *want) {
        char* end = nullptr;
        const long index = std::strtol(want, &end, 10);
        if (end && *end == '\0') {
            if (index < 0 || index >= static_cast<long>(devices.size()))
                throw VulkanError("m3g-vk: M3G_VK_DEVICE=" + std::string(want) + " is out of range [0, " +
                                  std::to_string(devices.size()) + ")");
            return devices[static_cast<std::size_t>(index)];
        }
        for (auto pd : devices)
            if (lower(describe(pd).name).find(lower(want)) != std::string::npos) return pd;
        throw VulkanError("m3g-vk: no device name contains M3G_VK_DEVICE=\"" + std::string(want) + "\"");
    }
    return *std::min_element(usable.begin(), usable.end(), [](VkPhysicalDevice a, VkPhysicalDevice b) {
        VkPhysicalDeviceProperties pa, pb;
        vkGetPhysicalDeviceProperties(a, &pa);
        vkGetPhysicalDeviceProperties(b, &pb);
        return typeRank(pa.deviceType) < typeRank(pb.deviceType);
    });
}

std::uint32_t graphicsComputeFamily(VkPhysicalDevice device, const std::string& name) {
    std::uint32_t n = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &n, nullptr);
    std::vector<VkQueueFamilyProperties> families(n);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &n, families.data());
    constexpr VkQueueFlags kBoth = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    for (std::uint32_t i = 0; i < n; ++i)
        if ((families[i].queueFlags & kBoth) == kBoth) return i;
    throw VulkanError("m3g-vk: device \"" + name + "\" has no graphics+compute queue");
}

VkFormat chooseDepthFormat(VkPhysicalDevice device) {
    // 16-bit UNORM, as the reference renders (Nokia's engine asks EGL for at
    // least 8 depth bits and EGL picks the smallest: Mesa's 16), so surfaces
    // closer than 1/65535 of the depth range tie under LEQUAL the same way.
    // D16_UNORM is mandatory for depth attachments; M3G_VK_DEPTH_BITS=32
    // prefers D32_SFLOAT (docs/rendering.md) for precision.
    const char* depthBits = std::getenv("M3G_VK_DEPTH_BITS");
    const bool wide = depthBits != nullptr && std::string_view(depthBits) == "32";
    const VkFormat narrowFirst[2] = {VK_FORMAT_D16_UNORM, VK_FORMAT_D32_SFLOAT};
    const VkFormat wideFirst[2] = {VK_FORMAT_D32_SFLOAT, VK_FORMAT_D16_UNORM};
    for (VkFormat f : wide ? wideFirst : narrowFirst) {
        VkFormatProperties fp;
        vkGetPhysicalDeviceFormatProperties(device, f, &fp);
        if (fp.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT) return f;
    }
    throw VulkanError("m3g-vk: no usable depth format");
}

VkSampleCountFlagBits antialiasSamples(const VkPhysicalDeviceProperties& properties) {
    const VkSampleCountFlags counts =
        properties.limits.framebufferColorSampleCounts & properties.limits.framebufferDepthSampleCounts;
    return (counts & VK_SAMPLE_COUNT_4_BIT)   ? VK_SAMPLE_COUNT_4_BIT
           : (counts & VK_SAMPLE_COUNT_2_BIT) ? VK_SAMPLE_COUNT_2_BIT
                                              : VK_SAMPLE_COUNT_1_BIT;
}

}  // namespace m3g::vk
