#include <m3g/vk/WindowTarget.h>

#include <m3g/Graphics3D.h>

#include <mutex>
#include <unordered_map>

#include "Swapchain.h"

namespace m3g::vk {

namespace {
// The live windows, by their address as a Graphics (frame::Target::identity).
std::mutex gWindowsMutex;
std::unordered_map<const void*, WindowTarget*> gWindows;
}  // namespace

WindowTarget::WindowTarget(SurfaceFactory createSurface, int width, int height, bool vsync)
    : Graphics(width, height), createSurface_(std::move(createSurface)), vsync_(vsync) {
    if (!createSurface_) throw NullPointerException("m3g::vk::WindowTarget: the surface factory is empty");
    std::lock_guard lock(gWindowsMutex);
    gWindows[static_cast<const Graphics*>(this)] = this;
}

WindowTarget::~WindowTarget() {
    std::lock_guard lock(gWindowsMutex);
    gWindows.erase(static_cast<const Graphics*>(this));
}

WindowTarget* WindowTarget::find(const void* identity) noexcept {
    std::lock_guard lock(gWindowsMutex);
    const auto it = gWindows.find(identity);
    return it == gWindows.end() ? nullptr : it->second;
}

void WindowTarget::resize(int width, int height) {
    if (Graphics3D::getInstance()->targetGraphics() == this)
        throw IllegalStateException("m3g::vk::WindowTarget::resize: the target is bound to Graphics3D; resize "
                                    "between releaseTarget and the next bindTarget");
    if (width == getWidth() && height == getHeight()) return;
    resizeSurface(width, height);
    fresh_ = true;
    readbackReady_ = false;
}

void WindowTarget::setOverlay(std::shared_ptr<WindowOverlay> overlay) { overlay_ = std::move(overlay); }

Swapchain& WindowTarget::swapchain() {
    if (!swapchain_) swapchain_ = std::make_unique<Swapchain>(Context::get(), createSurface_(Context::get().instance()), vsync_);
    return *swapchain_;
}

bool WindowTarget::takeReadbackRequest() noexcept {
    const bool r = readbackRequested_;
    readbackRequested_ = false;
    if (r) readbackReady_ = false;
    return r;
}

}  // namespace m3g::vk
