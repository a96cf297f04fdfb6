// Dear ImGui (Debian libimgui-dev) drawn over a WindowTarget's frame: the
// viewer's UI. Only the drawing is here; the application runs ImGui itself
// (its GLFW backend, NewFrame, widgets, Render) and attaches this overlay
// with WindowTarget::setOverlay. Library m3g_vk_imgui.
#pragma once

#include <m3g/Export.h>

#include <cstdint>
#include <memory>

#include <m3g/vk/WindowOverlay.h>

namespace m3g {
class Image2D;
}

namespace m3g::vk {

class M3G_API ImGuiOverlay final : public WindowOverlay {
public:
    /// Uses the current ImGui context (ISE if none): builds and uploads its
    /// font atlas now (call again uploadFonts() after changing fonts).
    /// Creates the Vulkan device if needed (VulkanError).
    ImGuiOverlay();
    void uploadFonts();
    ~ImGuiOverlay() override;

    /// Draws ImGui::GetDrawData() when it is valid (after ImGui::Render()).
    void record(void* cmd, Swapchain& swapchain) override;

    /// A texture id for ImGui::Image showing `image` (any Image2D format,
    /// uploaded again when the image changes). Needs the Vulkan device.
    /// Sampled bilinearly, or nearest-neighbour when `nearest` is set (a
    /// magnified image then shows its texels as squares: the viewer's
    /// texture inspector); both share one upload.
    void* texture(const Image2D& image, bool nearest = false);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace m3g::vk
