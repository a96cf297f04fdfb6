// The Vulkan side of a WindowTarget: its surface, swapchain, the persistent
// back image the renderer draws into, and the semaphores of a present.
#pragma once

#include <cstdint>
#include <vector>

#include "Context.h"

namespace m3g::vk {

class Swapchain {
public:
    /// Takes ownership of `surface` (a VkSurfaceKHR from the WindowTarget's
    /// factory) and checks that the device can present to it (VulkanError
    /// if not; the surface is destroyed then).
    Swapchain(Context& ctx, std::uint64_t surface, bool vsync);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    /// The image a frame renders into, width x height RGBA8, kept between
    /// frames (usage: colour attachment, transfer source and destination).
    /// Returns true in `created` when it was (re)made: contents undefined.
    Image& back(std::uint32_t width, std::uint32_t height, bool& created);

    /// Acquires the next swapchain image for a frame of width x height,
    /// rebuilding the swapchain when the size changed or it is out of date.
    /// False when there is nothing to present to (zero-sized surface).
    bool acquire(std::uint32_t width, std::uint32_t height);
    VkImage image() const noexcept { return images_[index_]; }
    VkImageView view() const noexcept { return views_[index_]; }
    VkFormat format() const noexcept { return format_; }
    VkExtent2D extent() const noexcept { return extent_; }
    /// Whether the images can be copied from (window screenshots).
    bool readable() const noexcept { return readable_; }
    VkSemaphore acquiredSemaphore() const noexcept { return acquired_; }
    VkSemaphore renderedSemaphore() const noexcept { return rendered_[index_]; }
    /// Presents the acquired image (after the submit signalling
    /// renderedSemaphore); an out-of-date swapchain is rebuilt next frame.
    void present();

private:
    void build(std::uint32_t width, std::uint32_t height);
    void destroySwapchain() noexcept;

    Context& ctx_;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkPresentModeKHR presentMode_ = VK_PRESENT_MODE_FIFO_KHR;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkColorSpaceKHR colorSpace_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    VkExtent2D extent_{0, 0};
    std::vector<VkImage> images_;
    std::vector<VkImageView> views_;
    std::vector<VkSemaphore> rendered_;  // one per swapchain image
    VkSemaphore acquired_ = VK_NULL_HANDLE;
    std::uint32_t index_ = 0;
    bool outOfDate_ = false;
    bool readable_ = false;
    Image back_;
};

}  // namespace m3g::vk
