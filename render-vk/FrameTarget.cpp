#include "FrameTarget.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>

#include <m3g/Graphics3D.h>
#include <m3g/vk/ImageTarget.h>
#include <m3g/vk/WindowOverlay.h>
#include <m3g/vk/WindowTarget.h>

#include "Swapchain.h"

namespace m3g::vk {

namespace {

void barrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to,
             VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage,
             VkAccessFlags2 dstAccess) {
    imageBarrier(cmd, image, aspect, 0, 1, from, to, srcStage, srcAccess, dstStage, dstAccess);
}

constexpr VkPipelineStageFlags2 kAttachmentStage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
constexpr VkAccessFlags2 kAttachmentAccess = VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;

}  // namespace

FrameTarget::~FrameTarget() {
    endFrame();
    ctx_.destroy(transfer_);
    ctx_.destroy(color_);
    ctx_.destroy(depth_);
    ctx_.destroy(msaaColor_);
    ctx_.destroy(initial_);
}

void FrameTarget::ensureImages(std::uint32_t width, std::uint32_t height, VkSampleCountFlagBits samples, bool& remade) {
    remade = false;
    if (color_.image && width_ == width && height_ == height && samples_ == samples) return;
    ctx_.waitIdle();
    remade = true;
    ctx_.destroy(color_);
    ctx_.destroy(depth_);
    ctx_.destroy(transfer_);
    ctx_.destroy(msaaColor_);
    ctx_.destroy(initial_);
    samples_ = samples;
    const VkImageUsageFlags colorUsage =
        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    // On a CPU device the colour target is linear host memory, read back in
    // place instead of copied into transfer_ first (lavapipe's copy was ~12%
    // of an empty 1280x960 frame). M3G_VK_HOST_TARGET=0 keeps the copy.
    const char* hostTarget = std::getenv("M3G_VK_HOST_TARGET");
    if ((!hostTarget || std::string(hostTarget) != "0") &&
        ctx_.hostImageUsable(VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT |
                                                           VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT |
                                                           VK_FORMAT_FEATURE_TRANSFER_SRC_BIT |
                                                           VK_FORMAT_FEATURE_TRANSFER_DST_BIT)) {
        color_ = ctx_.createHostImage(width, height, VK_FORMAT_R8G8B8A8_UNORM, colorUsage);
        if (color_.rowPitch != static_cast<VkDeviceSize>(width) * 4) ctx_.destroy(color_);  // read as one span only
    }
    if (!color_.image) color_ = ctx_.createImage(width, height, VK_FORMAT_R8G8B8A8_UNORM, colorUsage);
    depth_ = ctx_.createImage(width, height, ctx_.depthFormat(), VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, 1, samples);
    if (samples != VK_SAMPLE_COUNT_1_BIT) {
        msaaColor_ = ctx_.createImage(width, height, VK_FORMAT_R8G8B8A8_UNORM, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, 1,
                                      samples);
        initial_ = ctx_.createImage(width, height, VK_FORMAT_R8G8B8A8_UNORM,
                                    VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    }
    transfer_ = ctx_.createHostBuffer(static_cast<VkDeviceSize>(width) * height * 4,
                                      VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                      Context::HostAccess::Read);
    width_ = width;
    height_ = height;
}

bool FrameTarget::prepare(const frame::Target& t) {
    endFrame();  // a frame that was never submitted
    const auto w = static_cast<std::uint32_t>(t.width), h = static_cast<std::uint32_t>(t.height);
    window_ = WindowTarget::find(t.identity);
    external_ = window_ ? nullptr : ImageTarget::find(t.identity);
    // An application's depth image is the depth attachment itself, single
    // sampled: the ANTIALIAS hint is not applied then (ImageTarget.h).
    const bool externalDepth = external_ && external_->depth().image && t.depthBuffer;
    // ANTIALIAS: multisampling when the device has it (JSR-184 1.1, Graphics3D.ANTIALIAS).
    const bool antialias = (t.hints & Graphics3D::ANTIALIAS) != 0 && ctx_.maxSamples() != VK_SAMPLE_COUNT_1_BIT &&
                           !externalDepth;
    bool remade = false;
    ensureImages(w, h, antialias ? ctx_.maxSamples() : VK_SAMPLE_COUNT_1_BIT, remade);
    hasDepth_ = t.depthBuffer;
    if (externalDepth) {
        externalDepth_ = external_->depth().image;
        externalDepthView_ = externalDepthView(externalDepth_, external_->depth().format);
    }
    // A window keeps its contents on the GPU (black when its image is new).
    target_ = &color_;
    if (window_) {
        bool created = false;
        target_ = &window_->swapchain().back(w, h, created);
        if (created) window_->setFreshContents(true);
    }
    return remade;
}

void FrameTarget::endFrame() noexcept {
    if (externalDepthView_) vkDestroyImageView(ctx_.device(), externalDepthView_, nullptr);
    externalDepthView_ = VK_NULL_HANDLE;
    externalDepth_ = VK_NULL_HANDLE;
}

VkImageView FrameTarget::externalDepthView(VkImage image, VkFormat format) {
    // Made per frame: the application may destroy its image between frames
    // and a new one may come back with the same handle.
    VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vi.image = image;
    vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vi.format = format;
    vi.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    check(vkCreateImageView(ctx_.device(), &vi, nullptr, &view), "vkCreateImageView (ImageTarget depth)");
    return view;
}

void FrameTarget::begin(VkCommandBuffer cmd, const frame::Target& t, const float* clearColor, bool covered) {
    const auto w = width_, h = height_;
    const bool overwrite = (t.hints & Graphics3D::OVERWRITE) != 0;
    const bool msaa = samples_ != VK_SAMPLE_COUNT_1_BIT;
    // Where the prior contents come from: a window keeps them on the GPU;
    // other targets upload their pixels. A first command that clears every
    // pixel makes them moot.
    enum class Prior { None, Upload, Keep, Black, External } prior =
        overwrite || clearColor || covered ? Prior::None : Prior::Upload;
    if (window_) {
        if (prior != Prior::None) prior = window_->freshContents() ? Prior::Black : Prior::Keep;
        window_->setFreshContents(false);
    }
    // An application's image: its contents, unless its layout says they are gone.
    externalColorLayout_ = external_ ? external_->color().layoutBefore : VK_IMAGE_LAYOUT_UNDEFINED;
    if (external_ && prior != Prior::None)
        prior = externalColorLayout_ == VK_IMAGE_LAYOUT_UNDEFINED ? Prior::Black : Prior::External;
    if (prior == Prior::Upload && t.pixels)
        t.pixels->read({static_cast<std::uint8_t*>(transfer_.mapped), static_cast<std::size_t>(transfer_.size)});

    const VkImage colorImage = target_->image;
    // The prior contents: straight into the colour attachment, or with
    // multisampling into initial_, drawn into the samples when the
    // rendering opens. A window's image was left in TRANSFER_SRC layout by
    // the previous present.
    bool colorReady = false;  // colorImage already in attachment layout
    if (prior == Prior::Upload || prior == Prior::External || (prior == Prior::Keep && msaa)) {
        VkImage dst = msaa ? initial_.image : colorImage;
        barrier(cmd, dst, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        if (prior == Prior::Upload) {
            copyBufferToImage(cmd, transfer_.buffer, dst, w, h);
        } else if (prior == Prior::External) {
            // Whatever the application's earlier commands did to its image
            // comes before the read (the wait semaphore orders other batches).
            const ImageTarget::Attachment& a = external_->color();
            barrier(cmd, a.image, VK_IMAGE_ASPECT_COLOR_BIT, externalColorLayout_, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                    VK_ACCESS_2_TRANSFER_READ_BIT);
            externalColorLayout_ = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
            copyExternal(cmd, a.image, externalColorLayout_, a.format, dst, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         VK_FORMAT_R8G8B8A8_UNORM);
        } else {
            VkImageCopy region{};
            region.srcSubresource = region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.extent = {w, h, 1};
            vkCmdCopyImage(cmd, colorImage, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        }
        if (msaa) {
            barrier(cmd, dst, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                    VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        } else {
            barrier(cmd, dst, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT, kAttachmentStage, kAttachmentAccess);
            colorReady = true;
        }
    }
    if (!colorReady) {
        // Kept contents change layout in place; anything else starts undefined.
        const bool keep = prior == Prior::Keep && !msaa;
        barrier(cmd, colorImage, VK_IMAGE_ASPECT_COLOR_BIT,
                keep ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED,
                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                window_ ? VK_PIPELINE_STAGE_2_TRANSFER_BIT : VK_PIPELINE_STAGE_2_NONE, 0, kAttachmentStage,
                kAttachmentAccess);
    }
    if (msaa)
        barrier(cmd, msaaColor_.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, 0, kAttachmentStage,
                kAttachmentAccess);
    // An application's depth image keeps its values unless its layout says
    // they are gone; m3g-vk's own starts far.
    const bool loadDepth = externalDepthView_ && external_->depth().layoutBefore != VK_IMAGE_LAYOUT_UNDEFINED;
    barrier(cmd, externalDepthView_ ? externalDepth_ : depth_.image, VK_IMAGE_ASPECT_DEPTH_BIT,
            loadDepth ? external_->depth().layoutBefore : VK_IMAGE_LAYOUT_UNDEFINED,
            VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
            loadDepth ? VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT : VK_PIPELINE_STAGE_2_NONE,
            loadDepth ? VK_ACCESS_2_MEMORY_WRITE_BIT : 0,
            VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);

    // The rendering itself opens at the first command that needs it: a
    // clear of the whole target before it becomes the colour attachment's
    // load operation.
    VkRenderingAttachmentInfo& c = colorAttachment_;
    c = {VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    c.imageView = msaa ? msaaColor_.view : target_->view;
    c.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    c.loadOp = (prior == Prior::Black || clearColor) ? VK_ATTACHMENT_LOAD_OP_CLEAR
               : (prior == Prior::None || msaa)      ? VK_ATTACHMENT_LOAD_OP_DONT_CARE
                                                     : VK_ATTACHMENT_LOAD_OP_LOAD;
    c.clearValue.color = {{0.0f, 0.0f, 0.0f, 1.0f}};  // a new Graphics is opaque black
    if (clearColor) std::memcpy(c.clearValue.color.float32, clearColor, 4 * sizeof(float));
    c.storeOp = msaa ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
    if (msaa) {
        c.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
        c.resolveImageView = target_->view;
        c.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    }
    VkRenderingAttachmentInfo& d = depthAttachment_;
    d = {VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    d.imageView = externalDepthView_ ? externalDepthView_ : depth_.view;
    d.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    d.loadOp = loadDepth ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;  // a fresh target's depth is far
    d.storeOp = externalDepthView_ ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
    d.clearValue.depthStencil = {1.0f, 0};
    // With multisampling the prior contents are drawn into every sample
    // when the rendering opens (unless a clear of every pixel comes first).
    drawPrior_ = msaa && (prior == Prior::Upload || prior == Prior::Keep || prior == Prior::External);
}

FrameTarget::Ending FrameTarget::finish(VkCommandBuffer cmd) {
    Ending e;
    const VkImage colorImage = target_->image;
    // A window reads back only on request (screenshots); an application's
    // image never (its frame stays on the GPU); other targets always.
    e.readback = window_ ? window_->takeReadbackRequest() : !external_;
    // A window screenshot with its overlay reads the swapchain image instead.
    e.overlayWanted = e.readback && window_ && window_->readbackWithOverlay();
    bool readbackBgra = e.overlayWanted;
    // A host image target is read where it is (GENERAL layout for host access).
    e.inPlace = !window_ && !external_ && color_.mapped;
    if (e.inPlace) {
        barrier(cmd, colorImage, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    } else {
        barrier(cmd, colorImage, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        if (e.readback && !readbackBgra) copyToHost(cmd, colorImage);
    }
    if (external_) finishExternal(cmd);
    e.presenting = window_ && recordPresent(cmd, readbackBgra);
    if (readbackBgra && !e.presenting) readbackBgra = false;
    e.bgra = readbackBgra;
    return e;
}

void FrameTarget::submit(std::span<const VkCommandBuffer> cmds, VkFence fence, const Ending& e) {
    if (e.presenting) {
        Swapchain& swapchain = window_->swapchain();
        ctx_.submit(cmds, fence, swapchain.acquiredSemaphore(), VK_PIPELINE_STAGE_TRANSFER_BIT,
                    swapchain.renderedSemaphore());
        swapchain.present();
        window_->markPresented();
    } else if (external_) {
        VkPipelineStageFlags stages = 0;
        const VkSemaphore wait = external_->takeWait(stages);
        ctx_.submit(cmds, fence, wait, stages, external_->takeSignal());
    } else {
        ctx_.submit(cmds, fence);
    }
}

bool FrameTarget::writeBack(const frame::Target& t, const Ending& e) {
    endFrame();
    // A window screenshot that could not be taken stays not ready.
    if (!e.readback || (e.overlayWanted && !e.bgra)) return false;
    if (window_) window_->markReadback();
    // Texels are RGBA, except a swapchain image's (the window with its overlay).
    const bool bgra = e.bgra && window_->swapchain().format() == VK_FORMAT_B8G8R8A8_UNORM;
    const auto* src = static_cast<const std::uint8_t*>(e.inPlace ? color_.mapped : transfer_.mapped);
    if (!t.pixels) return false;
    t.pixels->write(src, bgra);
    return true;
}

void FrameTarget::copyToHost(VkCommandBuffer cmd, VkImage image) {
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {width_, height_, 1};
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, transfer_.buffer, 1, &copy);
    VkMemoryBarrier2 hostRead{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    hostRead.srcStageMask = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
    hostRead.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    hostRead.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    hostRead.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &hostRead;
    vkCmdPipelineBarrier2(cmd, &dep);
}

void FrameTarget::copyExternal(VkCommandBuffer cmd, VkImage from, VkImageLayout fromLayout, VkFormat fromFormat,
                               VkImage to, VkImageLayout toLayout, VkFormat toFormat) {
    const auto w = static_cast<std::int32_t>(width_), h = static_cast<std::int32_t>(height_);
    if (fromFormat == toFormat) {
        VkImageCopy region{};
        region.srcSubresource = region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.extent = {width_, height_, 1};
        vkCmdCopyImage(cmd, from, fromLayout, to, toLayout, 1, &region);
        return;
    }
    // Same extent both sides: NEAREST converts the format, never filters.
    VkImageBlit blit{};
    blit.srcSubresource = blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.srcOffsets[1] = blit.dstOffsets[1] = {w, h, 1};
    vkCmdBlitImage(cmd, from, fromLayout, to, toLayout, 1, &blit, VK_FILTER_NEAREST);
}

void FrameTarget::finishExternal(VkCommandBuffer cmd) {
    // The frame is in target_ (TRANSFER_SRC, finish()); into the application's image.
    const ImageTarget::Attachment& a = external_->color();
    barrier(cmd, a.image, VK_IMAGE_ASPECT_COLOR_BIT, externalColorLayout_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
            VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
            externalColorLayout_ == VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL ? VK_ACCESS_2_NONE : VK_ACCESS_2_MEMORY_WRITE_BIT,
            VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    copyExternal(cmd, target_->image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_FORMAT_R8G8B8A8_UNORM, a.image,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, a.format);
    // The application's later commands, whatever they are, see the frame.
    barrier(cmd, a.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, a.layoutAfter,
            VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
            VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
    externalColorLayout_ = a.layoutAfter;
    if (externalDepthView_)
        barrier(cmd, externalDepth_, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                external_->depth().layoutAfter,
                VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
}

bool FrameTarget::recordPresent(VkCommandBuffer cmd, bool& readback) {
    Swapchain& swapchain = window_->swapchain();
    if (!swapchain.acquire(width_, height_)) return false;  // minimised: nothing to show
    if (!swapchain.readable() || swapchain.extent().width != width_ || swapchain.extent().height != height_)
        readback = false;
    const VkImage image = swapchain.image();
    // The wait on the acquire semaphore is at the transfer stage (submit).
    barrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
            VK_PIPELINE_STAGE_2_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    // A blit converts RGBA to the swapchain's channel order (and scales if
    // the surface imposed another size).
    const VkExtent2D extent = swapchain.extent();
    VkImageBlit blit{};
    blit.srcSubresource = blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.srcOffsets[1] = {static_cast<std::int32_t>(width_), static_cast<std::int32_t>(height_), 1};
    blit.dstOffsets[1] = {static_cast<std::int32_t>(extent.width), static_cast<std::int32_t>(extent.height), 1};
    vkCmdBlitImage(cmd, target_->image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_NEAREST);
    VkImageLayout layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
    VkAccessFlags2 access = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    if (WindowOverlay* overlay = window_->overlay()) {
        barrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, stage,
                access, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        overlay->record(cmd, swapchain);
        layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        stage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
        access = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
    }
    if (readback) {
        // The presented image, overlay included (a screenshot of the window).
        barrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, stage, access,
                VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        copyToHost(cmd, image);
        layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        stage = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
        access = 0;
    }
    barrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, layout, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, stage, access,
            VK_PIPELINE_STAGE_2_NONE, 0);
    return true;
}

}  // namespace m3g::vk
