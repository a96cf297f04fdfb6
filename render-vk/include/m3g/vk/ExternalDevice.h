// Rendering on the application's own Vulkan device (an m3g-vk extension;
// docs/library.md, "Bring your own device"). An engine that already has an
// instance, a device and a queue hands them to m3g-vk before the first
// Graphics3D clear or render; every Graphics3D then renders with them, and
// m3g::vk::ImageTarget draws into the application's own images.
//
// This header includes the application's Vulkan headers (<vulkan/vulkan.h>).
#pragma once

#include <m3g/Export.h>

#include <cstdint>
#include <mutex>

#include <vulkan/vulkan.h>

namespace m3g::vk {

/// The application's Vulkan objects m3g-vk renders with. m3g-vk never
/// destroys them; the application keeps them alive until releaseDevice().
///
/// Requirements (not checkable through Vulkan, so stated here): the instance
/// was created for Vulkan 1.3 (VkApplicationInfo::apiVersion), the physical
/// device supports 1.3, and the device was created with the Vulkan 1.3
/// features `dynamicRendering` and `synchronization2` enabled and with a
/// queue of `queueFamilyIndex`, a family with both graphics and compute.
struct ExternalDevice {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    std::uint32_t queueFamilyIndex = 0;
    /// The loader entry point the application's instance came from (pass
    /// vkGetInstanceProcAddr); null: the system's libvulkan.so.1.
    PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;
    /// Locked by m3g-vk around each of its vkQueueSubmit, vkQueueWaitIdle and
    /// vkDeviceWaitIdle calls; the application locks it around its own queue
    /// calls when it submits from other threads than the ones that render
    /// (Vulkan requires queue access to be externally synchronised). Null:
    /// m3g-vk's own lock, enough when the application submits only from the
    /// threads that call Graphics3D.
    std::mutex* queueMutex = nullptr;
    /// The device was created with the `fillModeNonSolid` feature (for the
    /// wireframe debug view; otherwise it draws filled).
    bool fillModeNonSolid = false;
    /// The device was created with VK_KHR_swapchain (for WindowTarget).
    bool swapchain = false;
    /// The device was created with the `pipelineStatisticsQuery` feature
    /// (for shader invocation counting, setShaderInvocationCounting;
    /// otherwise nothing is counted).
    bool pipelineStatisticsQuery = false;
};

/// Makes every Graphics3D render with `device` from the next clear or render
/// on. Only before m3g-vk has made its own device (the first Graphics3D
/// clear or render, m3g::vk::currentDevice()) or after releaseDevice():
/// IllegalStateException otherwise. NullPointerException naming the field
/// when a handle is null; VulkanError when the physical device supports less
/// than Vulkan 1.3, lacks dynamicRendering or synchronization2, or when
/// queueFamilyIndex is not a graphics and compute family of it (checked
/// here: m3g-vk sets up on the device in this call).
M3G_API void useDevice(const ExternalDevice& device);

/// Frees every object m3g-vk made on the device, so the application can
/// destroy it: call after Graphics3D::releaseRenderer() on each thread's
/// Graphics3D that rendered, once no target is bound. IllegalStateException
/// naming how many renderers still hold the device otherwise. Waits for the
/// device to be idle. The next clear or render after it uses a device given
/// by a new useDevice() call, or else makes m3g-vk's own. Does nothing when no
/// device exists.
M3G_API void releaseDevice();

}  // namespace m3g::vk
