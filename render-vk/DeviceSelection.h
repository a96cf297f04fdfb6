// Which Vulkan device render-vk uses and what it asks of it: the device
// (M3G_VK_DEVICE, else by type), its graphics+compute queue family, the
// depth format (16-bit as the reference renders, M3G_VK_DEPTH_BITS=32 for
// 32-bit float) and the multisample count of ANTIALIAS.
#pragma once

#include <cstdint>
#include <vector>

#include "Context.h"

namespace m3g::vk {

/// M3G_VK_DEVICE (an index into `devices` or a case-insensitive substring
/// of a device name), else the Vulkan 1.3 device of the best type
/// (discrete, integrated, virtual, CPU). VulkanError when none fits.
VkPhysicalDevice choosePhysicalDevice(const std::vector<VkPhysicalDevice>& devices);
/// The first queue family with graphics and compute; VulkanError naming `name` otherwise.
std::uint32_t graphicsComputeFamily(VkPhysicalDevice device, const std::string& name);
/// D16_UNORM first (D32_SFLOAT with M3G_VK_DEPTH_BITS=32), whichever is a depth attachment.
VkFormat chooseDepthFormat(VkPhysicalDevice device);
/// 4, else 2, else 1 sample for both colour and depth.
VkSampleCountFlagBits antialiasSamples(const VkPhysicalDeviceProperties& properties);

}  // namespace m3g::vk
