// A Graphics whose pixels are the application's own VkImage (an m3g-vk
// extension; docs/library.md, "Bring your own device"): with useDevice()
// (ExternalDevice.h), Graphics3D.bindTarget(imageTarget) ... releaseTarget()
// composites the M3G frame into the application's image on the GPU, ordered
// with the application's work by semaphores. M3G itself only knows lcdui
// Graphics and Image2D targets (JSR-184 1.1, Graphics3D.bindTarget).
//
// The frame is drawn in m3g-vk's own R8G8B8A8 image, which starts from the
// application's image (its contents are kept unless the layout before is
// UNDEFINED: then it starts opaque black, as a new Graphics) and is copied
// back into it at releaseTarget: bit for bit where the format is
// VK_FORMAT_R8G8B8A8_UNORM, otherwise converted as vkCmdBlitImage converts
// (other channel orders; sRGB formats take M3G's colours as linear). A
// given depth image is the frame's depth buffer itself: the scene is
// depth-tested against the application's depth (M3G's depth range: 0 near,
// 1 far, LEQUAL), and the Graphics3D ANTIALIAS hint is then not applied.
//
// This header includes the application's Vulkan headers (<vulkan/vulkan.h>).
#pragma once

#include <m3g/Export.h>

#include <cstdint>

#include <vulkan/vulkan.h>

#include <m3g/Graphics.h>

namespace m3g::vk {

/// One image of the application, with the layouts around m3g-vk's work.
struct ImageAttachment {
    VkImage image = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    /// The layout the image is in when the frame's commands run;
    /// UNDEFINED discards its contents (colour: opaque black; depth: far).
    VkImageLayout layoutBefore = VK_IMAGE_LAYOUT_UNDEFINED;
    /// The layout releaseTarget's commands leave it in (not UNDEFINED
    /// or PREINITIALIZED).
    VkImageLayout layoutAfter = VK_IMAGE_LAYOUT_GENERAL;
};

class M3G_API ImageTarget : public Graphics {
public:
    using Attachment = ImageAttachment;

    /// A target of `width` x `height` pixels drawn into `color`, a 2D image of
    /// that extent, one mip level and one layer, optimal tiling, single
    /// sampled, made on the device given to useDevice() with usage
    /// TRANSFER_DST (and TRANSFER_SRC unless its layout before is UNDEFINED),
    /// in a format whose optimal tiling supports BLIT_DST (and BLIT_SRC) unless
    /// it is R8G8B8A8_UNORM. `depth`, optional (a null image: m3g-vk's own
    /// depth buffer, far at each bindTarget), has the same extent, the format
    /// depthFormat() names and usage DEPTH_STENCIL_ATTACHMENT.
    /// NullPointerException when the colour image is null;
    /// IllegalArgumentException naming the problem when a size is not
    /// positive, a format is unusable or a layout after is
    /// UNDEFINED/PREINITIALIZED; VulkanError when no device can be made.
    ImageTarget(int width, int height, const Attachment& color, const Attachment& depth = {});
    ~ImageTarget() override;

    /// Draws the following frames into other images of the same extent
    /// (e.g. the next image of the application's swapchain ring); the same
    /// rules as the constructor. Not while bound to Graphics3D (ISE).
    void setImages(const Attachment& color, const Attachment& depth = {});

    /// The next releaseTarget's commands wait for `semaphore` (a binary
    /// semaphore whose signal operation the application has submitted
    /// before that releaseTarget) at `stages`; used once. Null: no wait.
    void waitFor(VkSemaphore semaphore, VkPipelineStageFlags stages = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT) noexcept {
        wait_ = semaphore;
        waitStages_ = stages;
    }
    /// The next releaseTarget's commands signal `semaphore` (binary) when
    /// they are done; used once. Null: no signal.
    void signalWhenDone(VkSemaphore semaphore) noexcept { signal_ = semaphore; }

    /// The depth format a depth attachment must have: the format of
    /// m3g-vk's pipelines on the current device (VK_FORMAT_D16_UNORM unless
    /// M3G_VK_DEPTH_BITS=32 chose VK_FORMAT_D32_SFLOAT, docs/rendering.md).
    /// Sets up on the device given to useDevice() if it was not yet.
    static VkFormat depthFormat();

    const Attachment& color() const noexcept { return color_; }
    const Attachment& depth() const noexcept { return depth_; }

    // ---- Engine interface (render-vk) ----
    /// The live ImageTarget whose address (as a Graphics) is `identity`, or
    /// null: how the renderer knows a bound Graphics is one.
    static ImageTarget* find(const void* identity) noexcept;
    /// The semaphores of this frame, cleared for the next.
    VkSemaphore takeWait(VkPipelineStageFlags& stages) noexcept {
        stages = waitStages_;
        const VkSemaphore s = wait_;
        wait_ = VK_NULL_HANDLE;
        return s;
    }
    VkSemaphore takeSignal() noexcept {
        const VkSemaphore s = signal_;
        signal_ = VK_NULL_HANDLE;
        return s;
    }

private:
    void check(const Attachment& color, const Attachment& depth, const char* method) const;

    Attachment color_, depth_;
    VkSemaphore wait_ = VK_NULL_HANDLE, signal_ = VK_NULL_HANDLE;
    VkPipelineStageFlags waitStages_ = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
};

}  // namespace m3g::vk
