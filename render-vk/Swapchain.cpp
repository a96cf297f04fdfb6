#include "Swapchain.h"

#include <algorithm>
#include <string>

namespace m3g::vk {

namespace {

// M3G colours are display values (GL ES 1.x does no sRGB conversion), so the
// swapchain takes them as they are: a UNORM format, never an _SRGB one.
VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice physical, VkSurfaceKHR surface) {
    std::uint32_t n = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &n, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(n);
    vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &n, formats.data());
    for (VkFormat want : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_A8B8G8R8_UNORM_PACK32})
        for (const auto& f : formats)
            if (f.format == want) return f;
    if (formats.empty()) throw VulkanError("m3g-vk: the window surface reports no formats");
    return formats.front();
}

VkPresentModeKHR choosePresentMode(VkPhysicalDevice physical, VkSurfaceKHR surface, bool vsync) {
    if (vsync) return VK_PRESENT_MODE_FIFO_KHR;  // always supported
    std::uint32_t n = 0;
    vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &n, nullptr);
    std::vector<VkPresentModeKHR> modes(n);
    vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &n, modes.data());
    for (VkPresentModeKHR want : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
        if (std::find(modes.begin(), modes.end(), want) != modes.end()) return want;
    return VK_PRESENT_MODE_FIFO_KHR;
}

}  // namespace

Swapchain::Swapchain(Context& ctx, std::uint64_t surface, bool vsync)
    : ctx_(ctx), surface_(reinterpret_cast<VkSurfaceKHR>(surface)) {
    if (!surface_) throw VulkanError("m3g::vk::WindowTarget: the surface factory returned no surface");
    if (!ctx.swapchainEnabled()) {
        vkDestroySurfaceKHR(ctx.instance(), surface_, nullptr);
        throw VulkanError("m3g::vk::WindowTarget: the device was created without VK_KHR_swapchain; call "
                          "m3g::vk::requestWindowExtensions() before the first Graphics3D use");
    }
    VkBool32 supported = VK_FALSE;
    vkGetPhysicalDeviceSurfaceSupportKHR(ctx.physicalDevice(), ctx.queueFamily(), surface_, &supported);
    if (!supported) {
        vkDestroySurfaceKHR(ctx.instance(), surface_, nullptr);
        throw VulkanError("m3g::vk::WindowTarget: device '" + ctx.info().name +
                          "' cannot present to this window (pick another with M3G_VK_DEVICE)");
    }
    const VkSurfaceFormatKHR f = chooseFormat(ctx.physicalDevice(), surface_);
    format_ = f.format;
    colorSpace_ = f.colorSpace;
    presentMode_ = choosePresentMode(ctx.physicalDevice(), surface_, vsync);
    VkSemaphoreCreateInfo si{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    check(vkCreateSemaphore(ctx.device(), &si, nullptr, &acquired_), "vkCreateSemaphore");
}

Swapchain::~Swapchain() {
    ctx_.waitIdle();
    destroySwapchain();
    vkDestroySemaphore(ctx_.device(), acquired_, nullptr);
    ctx_.destroy(back_);
    vkDestroySurfaceKHR(ctx_.instance(), surface_, nullptr);
}

void Swapchain::destroySwapchain() noexcept {
    VkDevice device = ctx_.device();
    for (VkImageView v : views_) vkDestroyImageView(device, v, nullptr);
    for (VkSemaphore s : rendered_) vkDestroySemaphore(device, s, nullptr);
    views_.clear();
    rendered_.clear();
    images_.clear();
    if (swapchain_) vkDestroySwapchainKHR(device, swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
}

Image& Swapchain::back(std::uint32_t width, std::uint32_t height, bool& created) {
    created = false;
    if (back_.image && back_.width == width && back_.height == height) return back_;
    ctx_.waitIdle();
    ctx_.destroy(back_);
    back_ = ctx_.createImage(width, height, VK_FORMAT_R8G8B8A8_UNORM,
                             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                 VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    created = true;
    return back_;
}

void Swapchain::build(std::uint32_t width, std::uint32_t height) {
    VkDevice device = ctx_.device();
    ctx_.waitIdle();
    VkSurfaceCapabilitiesKHR caps{};
    check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_.physicalDevice(), surface_, &caps),
          "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw VulkanError("m3g::vk::WindowTarget: the surface's images cannot be transfer destinations");
    // The surface decides the size when it reports one (most platforms).
    VkExtent2D extent = caps.currentExtent;
    if (extent.width == 0xFFFFFFFFu) {
        extent.width = std::clamp(width, caps.minImageExtent.width, caps.maxImageExtent.width);
        extent.height = std::clamp(height, caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    std::uint32_t count = std::max(caps.minImageCount + 1, 2u);
    if (caps.maxImageCount) count = std::min(count, caps.maxImageCount);

    VkSwapchainKHR old = swapchain_;
    VkSwapchainCreateInfoKHR ci{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    ci.surface = surface_;
    ci.minImageCount = count;
    ci.imageFormat = format_;
    ci.imageColorSpace = colorSpace_;
    ci.imageExtent = extent;
    ci.imageArrayLayers = 1;
    // Transfer source where the surface allows it: window screenshots.
    readable_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;
    ci.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                    (readable_ ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0);
    ci.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    ci.preTransform = caps.currentTransform;
    ci.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                            ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                            : static_cast<VkCompositeAlphaFlagBitsKHR>(caps.supportedCompositeAlpha &
                                                                       -caps.supportedCompositeAlpha);
    ci.presentMode = presentMode_;
    ci.clipped = VK_TRUE;
    ci.oldSwapchain = old;
    VkSwapchainKHR created = VK_NULL_HANDLE;
    check(vkCreateSwapchainKHR(device, &ci, nullptr, &created), "vkCreateSwapchainKHR");
    destroySwapchain();  // the old one, now retired
    swapchain_ = created;
    extent_ = extent;

    std::uint32_t n = 0;
    vkGetSwapchainImagesKHR(device, swapchain_, &n, nullptr);
    images_.resize(n);
    vkGetSwapchainImagesKHR(device, swapchain_, &n, images_.data());
    for (VkImage image : images_) {
        VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        vi.image = image;
        vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
        vi.format = format_;
        vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView view = VK_NULL_HANDLE;
        check(vkCreateImageView(device, &vi, nullptr, &view), "vkCreateImageView (swapchain)");
        views_.push_back(view);
        VkSemaphoreCreateInfo si{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        VkSemaphore s = VK_NULL_HANDLE;
        check(vkCreateSemaphore(device, &si, nullptr, &s), "vkCreateSemaphore");
        rendered_.push_back(s);
    }
    outOfDate_ = false;
}

bool Swapchain::acquire(std::uint32_t width, std::uint32_t height) {
    if (width == 0 || height == 0) return false;
    for (int attempt = 0; attempt < 3; ++attempt) {
        if (!swapchain_ || outOfDate_ || extent_.width != width || extent_.height != height) build(width, height);
        if (extent_.width == 0 || extent_.height == 0) return false;
        const VkResult r =
            vkAcquireNextImageKHR(ctx_.device(), swapchain_, UINT64_MAX, acquired_, VK_NULL_HANDLE, &index_);
        if (r == VK_SUCCESS) return true;
        if (r == VK_SUBOPTIMAL_KHR) {
            outOfDate_ = true;  // usable now, rebuilt next frame
            return true;
        }
        if (r != VK_ERROR_OUT_OF_DATE_KHR) check(r, "vkAcquireNextImageKHR");
        outOfDate_ = true;
    }
    throw VulkanError("m3g::vk::WindowTarget: the swapchain stayed out of date after 3 rebuilds");
}

void Swapchain::present() {
    VkPresentInfoKHR pi{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    pi.waitSemaphoreCount = 1;
    pi.pWaitSemaphores = &rendered_[index_];
    pi.swapchainCount = 1;
    pi.pSwapchains = &swapchain_;
    pi.pImageIndices = &index_;
    const VkResult r = ctx_.present(pi);
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR)
        outOfDate_ = true;
    else
        check(r, "vkQueuePresentKHR");
}

}  // namespace m3g::vk
