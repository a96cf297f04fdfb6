// The images a renderer draws a frame into and how the frame starts and
// ends: colour (a host-readable linear image on CPU devices, or a window's
// back image), depth, the multisampled colour and the prior contents under
// ANTIALIAS (JSR-184 1.1, Graphics3D hints), the layout barriers that open
// a frame, the attachments of its rendering, and at release the read-back
// into the bound target and the present of a window.
#pragma once

#include <cstdint>

#include <m3g/frame/FrameBackend.h>

#include "Context.h"

namespace m3g::vk {

class ImageTarget;
class WindowTarget;

class FrameTarget {
public:
    explicit FrameTarget(Context& ctx) : ctx_(ctx) {}
    ~FrameTarget();

    /// Makes the images for `target` (waits for the device and returns true
    /// when they had to be remade: descriptor sets naming the old prior
    /// image are then stale).
    bool prepare(const frame::Target& target);
    /// Frees what only this frame used (the view of an application's depth
    /// image); after the frame's fence, or when it was never submitted.
    void endFrame() noexcept;
    /// Records the opening of a frame into `cmd`: the prior contents (the
    /// target's pixels uploaded, a window's kept image, or none when the
    /// first command writes every pixel: `covered`, or a clear to
    /// `clearColor` which becomes the load operation) and every image in its
    /// attachment layout.
    void begin(VkCommandBuffer cmd, const frame::Target& target, const float* clearColor, bool covered);

    VkRenderingAttachmentInfo& colorAttachment() noexcept { return colorAttachment_; }
    VkRenderingAttachmentInfo& depthAttachment() noexcept { return depthAttachment_; }
    /// Multisampled: the prior contents are still to be drawn into the samples.
    bool drawPrior() const noexcept { return drawPrior_; }
    void setDrawPrior(bool v) noexcept { drawPrior_ = v; }
    /// The prior contents as a texture (multisampled frames only).
    const Image& priorImage() const noexcept { return initial_; }
    std::uint32_t width() const noexcept { return width_; }
    std::uint32_t height() const noexcept { return height_; }
    VkSampleCountFlagBits samples() const noexcept { return samples_; }
    bool hasDepth() const noexcept { return hasDepth_; }
    /// The depth attachment keeps the values it had (an application's depth
    /// image): a depth clear cannot be skipped as moot.
    bool depthLoaded() const noexcept { return depthAttachment_.loadOp == VK_ATTACHMENT_LOAD_OP_LOAD; }

    /// What finish() recorded.
    struct Ending {
        bool readback = false;      ///< the frame's pixels reach the host
        bool bgra = false;          ///< read from a B8G8R8A8 swapchain image
        bool presenting = false;    ///< a window image was acquired and will be presented
        bool inPlace = false;       ///< read from the host-visible colour image itself
        bool overlayWanted = false; ///< a window screenshot with its overlay was asked for
    };
    /// After the rendering has ended: the colour image's final barrier, its
    /// copy to the host and a window's present.
    Ending finish(VkCommandBuffer cmd);
    /// Submits `cmds` with `fence` (and the window's semaphores, then presents).
    void submit(std::span<const VkCommandBuffer> cmds, VkFence fence, const Ending& ending);
    /// Once the fence is signalled: the pixels into the bound target. True
    /// when pixels were copied into the target's memory (a Graphics surface
    /// or Image2D; a window's screenshot).
    bool writeBack(const frame::Target& target, const Ending& ending);

    FrameTarget(const FrameTarget&) = delete;
    FrameTarget& operator=(const FrameTarget&) = delete;

private:
    void ensureImages(std::uint32_t width, std::uint32_t height, VkSampleCountFlagBits samples, bool& remade);
    void copyToHost(VkCommandBuffer cmd, VkImage image);
    /// An application's image (ImageTarget) to or from `own` (an RGBA image of
    /// this frame's size): a copy where the formats match, else a blit.
    void copyExternal(VkCommandBuffer cmd, VkImage from, VkImageLayout fromLayout, VkFormat fromFormat, VkImage to,
                      VkImageLayout toLayout, VkFormat toFormat);
    /// The frame's colour into the application's image, and both of its
    /// images into their layouts after (ImageTarget).
    void finishExternal(VkCommandBuffer cmd);
    /// A view of the application's depth image (made once per image).
    VkImageView externalDepthView(VkImage image, VkFormat format);
    bool recordPresent(VkCommandBuffer cmd, bool& readback);

    Context& ctx_;
    Image color_, depth_;             // single-sampled colour (read back) and depth
    Image* target_ = &color_;         // the colour image of this frame: color_ or a window's back image
    WindowTarget* window_ = nullptr;  // the bound target when it is a window
    ImageTarget* external_ = nullptr;  // the bound target when it is an application's image
    VkImageLayout externalColorLayout_ = VK_IMAGE_LAYOUT_UNDEFINED;  // its layout as this frame's commands go
    VkImage externalDepth_ = VK_NULL_HANDLE;  // the application's depth image of externalDepthView_
    VkImageView externalDepthView_ = VK_NULL_HANDLE;
    Image msaaColor_, initial_;       // ANTIALIAS: multisampled colour and the prior contents to start from
    VkSampleCountFlagBits samples_ = VK_SAMPLE_COUNT_1_BIT;
    std::uint32_t width_ = 0, height_ = 0;
    Buffer transfer_;  // upload of the target's pixels and read-back
    VkRenderingAttachmentInfo colorAttachment_{}, depthAttachment_{};
    bool hasDepth_ = true;
    bool drawPrior_ = false;
};

}  // namespace m3g::vk
