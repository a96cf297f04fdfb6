#include <m3g/vk/ImageTarget.h>

#include <m3g/Graphics3D.h>

#include <mutex>
#include <string>
#include <unordered_map>

#include "Context.h"

namespace m3g::vk {

namespace {
// The live image targets, by their address as a Graphics (frame::Target::identity).
std::mutex gTargetsMutex;
std::unordered_map<const void*, ImageTarget*> gTargets;

bool usableAfter(VkImageLayout layout) {
    return layout != VK_IMAGE_LAYOUT_UNDEFINED && layout != VK_IMAGE_LAYOUT_PREINITIALIZED;
}

std::string formatName(VkFormat format) { return "VkFormat " + std::to_string(static_cast<int>(format)); }
}  // namespace

ImageTarget::ImageTarget(int width, int height, const Attachment& color, const Attachment& depth)
    : Graphics(width, height) {
    check(color, depth, "ImageTarget");
    color_ = color;
    depth_ = depth;
    std::lock_guard lock(gTargetsMutex);
    gTargets[static_cast<const Graphics*>(this)] = this;
}

ImageTarget::~ImageTarget() {
    std::lock_guard lock(gTargetsMutex);
    gTargets.erase(static_cast<const Graphics*>(this));
}

ImageTarget* ImageTarget::find(const void* identity) noexcept {
    std::lock_guard lock(gTargetsMutex);
    const auto it = gTargets.find(identity);
    return it == gTargets.end() ? nullptr : it->second;
}

void ImageTarget::setImages(const Attachment& color, const Attachment& depth) {
    if (Graphics3D::getInstance()->targetGraphics() == this)
        throw IllegalStateException("m3g::vk::ImageTarget::setImages: the target is bound to Graphics3D; change "
                                    "images between releaseTarget and the next bindTarget");
    check(color, depth, "setImages");
    color_ = color;
    depth_ = depth;
}

VkFormat ImageTarget::depthFormat() { return Context::get().depthFormat(); }

void ImageTarget::check(const Attachment& color, const Attachment& depth, const char* method) const {
    const std::string where = std::string("m3g::vk::ImageTarget::") + method + ": ";
    if (!color.image) throw NullPointerException(where + "the colour image is null");
    if (!usableAfter(color.layoutAfter))
        throw IllegalArgumentException(where + "the colour image's layoutAfter must be a layout an image can be in "
                                               "(not UNDEFINED or PREINITIALIZED)");
    Context& ctx = Context::get();
    if (color.format != VK_FORMAT_R8G8B8A8_UNORM) {
        // Other formats are converted by vkCmdBlitImage, both ways when the
        // prior contents are kept.
        VkFormatProperties props;
        vkGetPhysicalDeviceFormatProperties(ctx.physicalDevice(), color.format, &props);
        VkFormatFeatureFlags need = VK_FORMAT_FEATURE_BLIT_DST_BIT;
        if (color.layoutBefore != VK_IMAGE_LAYOUT_UNDEFINED) need |= VK_FORMAT_FEATURE_BLIT_SRC_BIT;
        if ((props.optimalTilingFeatures & need) != need)
            throw IllegalArgumentException(where + "the colour image's format (" + formatName(color.format) +
                                           ") cannot be a blit " +
                                           (need & VK_FORMAT_FEATURE_BLIT_SRC_BIT ? "source and destination"
                                                                                  : "destination") +
                                           " on device \"" + ctx.info().name +
                                           "\" (use VK_FORMAT_R8G8B8A8_UNORM or a B8G8R8A8 format)");
    }
    if (!depth.image) return;
    if (depth.format != ctx.depthFormat())
        throw IllegalArgumentException(where + "the depth image's format (" + formatName(depth.format) +
                                       ") is not m3g-vk's depth format (" + formatName(ctx.depthFormat()) +
                                       ", ImageTarget::depthFormat())");
    if (!usableAfter(depth.layoutAfter))
        throw IllegalArgumentException(where + "the depth image's layoutAfter must be a layout an image can be in "
                                               "(not UNDEFINED or PREINITIALIZED)");
}

}  // namespace m3g::vk
