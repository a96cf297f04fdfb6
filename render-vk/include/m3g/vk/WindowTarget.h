// A Graphics surface shown in a window through a Vulkan swapchain: the
// m3g-vk stand-in for a MIDlet's Canvas (an extension; M3G itself only
// knows lcdui Graphics and Image2D, JSR-184 1.1, Graphics3D.bindTarget). A port binds it as
// any Graphics: bindTarget(window) ... releaseTarget() presents the frame.
//
// Unlike a plain Graphics, whose pixels travel to the GPU at bindTarget and
// back at releaseTarget, a WindowTarget's pixels stay on the GPU between
// frames (what was drawn last frame is still there when a frame does not
// clear, as on a handset's back buffer); pixels() is only filled on request
// (requestReadback, for screenshots).
#pragma once

#include <m3g/Export.h>

#include <cstdint>
#include <functional>
#include <memory>

#include <m3g/Graphics.h>

namespace m3g::vk {

class Swapchain;
class WindowOverlay;

class M3G_API WindowTarget : public Graphics {
public:
    /// Creates a window surface: called once with the VkInstance (as a
    /// pointer) when the device exists; returns the VkSurfaceKHR (as an
    /// integer), e.g. from glfwCreateWindowSurface. Throwing is allowed.
    using SurfaceFactory = std::function<std::uint64_t(void* vkInstance)>;

    /// A target of `width` x `height` pixels (the window's framebuffer
    /// size). The surface and swapchain are made at the first present, so
    /// the application must have requested its instance extensions with
    /// requestWindowExtensions() before the device is created. `vsync`
    /// false prefers a present mode that does not wait for the display.
    /// IAE unless width > 0 and height > 0; NPE if `createSurface` is empty.
    WindowTarget(SurfaceFactory createSurface, int width, int height, bool vsync = true);
    ~WindowTarget() override;

    /// Follows a window resize (framebuffer size); the swapchain is rebuilt
    /// at the next present. Not while bound to Graphics3D (ISE). IAE unless
    /// both are positive (a minimised window: skip rendering instead).
    void resize(int width, int height);

    /// The next releaseTarget also copies the frame into pixels() (rows top
    /// to bottom, 0xAARRGGBB), for screenshots: the 3D view, or with
    /// `withOverlay` the presented image, overlay included (when the
    /// surface's size is the target's).
    void requestReadback(bool withOverlay = false) noexcept {
        readbackRequested_ = true;
        readbackOverlay_ = withOverlay;
        readbackReady_ = false;
    }
    /// True after a releaseTarget that honoured requestReadback(); cleared
    /// by the next requestReadback().
    bool readbackReady() const noexcept { return readbackReady_; }

    /// Drawn into the swapchain image after the 3D frame, every present
    /// (e.g. the viewer's UI); null removes it.
    void setOverlay(std::shared_ptr<WindowOverlay> overlay);

    /// Frames presented so far.
    std::uint64_t presentedFrames() const noexcept { return presented_; }

    // ---- Engine interface (render-vk) ----
    /// The live WindowTarget whose address (as a Graphics) is `identity`,
    /// or null: how the renderer knows a bound Graphics is a window.
    static WindowTarget* find(const void* identity) noexcept;
    Swapchain& swapchain();
    WindowOverlay* overlay() const noexcept { return overlay_.get(); }
    bool takeReadbackRequest() noexcept;
    bool readbackWithOverlay() const noexcept { return readbackOverlay_; }
    void markReadback() noexcept { readbackReady_ = true; }
    void markPresented() noexcept { ++presented_; }
    /// True until the renderer has drawn into its images once at this size
    /// (the persistent contents start black then).
    bool freshContents() const noexcept { return fresh_; }
    void setFreshContents(bool fresh) noexcept { fresh_ = fresh; }

private:
    SurfaceFactory createSurface_;
    bool vsync_;
    std::unique_ptr<Swapchain> swapchain_;
    std::shared_ptr<WindowOverlay> overlay_;
    bool readbackRequested_ = false, readbackOverlay_ = false, readbackReady_ = false, fresh_ = true;
    std::uint64_t presented_ = 0;
};

}  // namespace m3g::vk
