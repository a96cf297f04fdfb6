// Something drawn over a WindowTarget's frame in the swapchain image, after
// the 3D rendering and before the present (the viewer's UI). Implementations
// live in render-vk (they record Vulkan commands); applications only attach
// them, e.g. ImGuiOverlay.
#pragma once

#include <m3g/Export.h>

namespace m3g::vk {

class Swapchain;

class M3G_API WindowOverlay {
public:
    virtual ~WindowOverlay() = default;
    /// Records the overlay into `cmd` (a VkCommandBuffer, as a pointer): the
    /// acquired swapchain image is in COLOR_ATTACHMENT_OPTIMAL layout, with
    /// `swapchain`'s format and extent, and stays in it.
    virtual void record(void* cmd, Swapchain& swapchain) = 0;
};

}  // namespace m3g::vk
