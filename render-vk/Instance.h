// The Vulkan loader and instance of render-vk, the validation layer's
// message counters, and what an application asks for before the device
// exists (Vulkan.h: requestValidation, requestWindowExtensions).
#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "Context.h"

namespace m3g::vk {

/// What to install or set when Vulkan cannot be used (ends VulkanError messages).
extern const char* const kInstallHint;

/// Validation messages counted so far, and the last one (guarded by gMessageMutex).
extern std::atomic<std::uint64_t> gValidationMessages;
extern std::mutex gMessageMutex;
extern std::string gLastMessage;
/// requestValidation: -1 from the environment (M3G_VK_VALIDATION), 0 off, 1 on.
extern int gValidationRequest;
/// requestWindowExtensions: instance extensions a windowed application needs.
extern std::vector<std::string> gWindowExtensions;

/// Whether the validation layer is wanted (request, else environment, else build type).
bool envValidation();
/// ", with VK_DRIVER_FILES=..." for the loader variables that choose drivers, or "".
std::string driverOverrides();
/// Opens the system's Vulkan loader for volk (once; VulkanError saying what
/// is missing).
void loadLoader();
/// Loads the Vulkan loader (once) and creates an instance; `validation` is
/// set when the layer was found and enabled. VulkanError saying what is missing.
VkInstance createInstance(bool wantValidation, bool& validation);
/// Counts and prints the layer's warnings and errors.
VkDebugUtilsMessengerEXT createMessenger(VkInstance instance);
std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance);
DeviceInfo describe(VkPhysicalDevice device);
/// Preference of a device type: discrete 0, integrated 1, virtual 2, CPU 3, other 4.
int typeRank(VkPhysicalDeviceType type);
std::string lower(std::string s);

}  // namespace m3g::vk
