#include "Renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <string>

#include <glm/glm.hpp>

#include <m3g/Appearance.h>
#include <m3g/Background.h>
#include <m3g/CompositingMode.h>
#include <m3g/Fog.h>
#include <m3g/Graphics.h>
#include <m3g/Graphics3D.h>
#include <m3g/Image2D.h>
#include <m3g/Light.h>
#include <m3g/Material.h>
#include <m3g/Mesh.h>
#include <m3g/PolygonMode.h>
#include <m3g/Sprite3D.h>
#include <m3g/Texture2D.h>
#include <m3g/VertexBuffer.h>
#include <m3g/vk/WindowOverlay.h>
#include <m3g/vk/WindowTarget.h>

#include "RenderQueue.h"
#include "SpriteProjection.h"
#include "Swapchain.h"

namespace m3g::vk {

namespace {

constexpr std::uint32_t kDrawsPerChunk = 256;
constexpr VkDeviceSize kQuadBytes = 6 * 6 * sizeof(float);

void toColumns(const Transform& t, float* out) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) out[c * 4 + r] = t.at(r, c);
}

void identity(float* out) {
    std::memset(out, 0, 16 * sizeof(float));
    out[0] = out[5] = out[10] = out[15] = 1.0f;
}

/// OpenGL clip space to Vulkan's: y down, z from [-w, w] to [0, w].
Transform vulkanProjection(const Transform& gl) {
    Transform fix = Transform::fromRows({1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 0.5f, 0.5f, 0, 0, 0, 1});
    return fix * gl;
}

void argb(std::uint32_t c, float* out, bool withAlpha) {
    out[0] = static_cast<float>((c >> 16) & 0xFF) / 255.0f;
    out[1] = static_cast<float>((c >> 8) & 0xFF) / 255.0f;
    out[2] = static_cast<float>(c & 0xFF) / 255.0f;
    out[3] = withAlpha ? static_cast<float>((c >> 24) & 0xFF) / 255.0f : 1.0f;
}

std::uint8_t blendIndex(const CompositingMode* cm) {
    if (!cm) return 0;
    switch (cm->getBlending()) {
    case CompositingMode::ALPHA: return 1;
    case CompositingMode::ALPHA_ADD: return 2;
    case CompositingMode::MODULATE: return 3;
    case CompositingMode::MODULATE_X2: return 4;
    default: return 0;
    }
}

std::uint8_t writeMask(const CompositingMode* cm) {
    return static_cast<std::uint8_t>(
        ((!cm || cm->isColorWriteEnabled()) ? (VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT)
                                            : 0) |
        ((!cm || cm->isAlphaWriteEnabled()) ? VK_COLOR_COMPONENT_A_BIT : 0));
}

/// `count` RGBA (or BGRA) texels to opaque 0xAARRGGBB words. Four texels
/// per SSE2 step: at 1280x960 the byte-by-byte loop was a quarter of an
/// empty headless frame's CPU time (GCC does not vectorise it at -O2).
void toArgb(const std::uint8_t* src, std::uint32_t* out, std::size_t count, bool bgra) {
    std::size_t i = 0;
#if defined(__SSE2__)
    const __m128i opaque = _mm_set1_epi32(static_cast<int>(0xFF000000u));
    const __m128i green = _mm_set1_epi32(0x0000FF00);
    const __m128i low = _mm_set1_epi32(0x000000FF);
    for (; i + 4 <= count; i += 4) {
        const __m128i t = _mm_loadu_si128(reinterpret_cast<const __m128i*>(src + i * 4));
        __m128i argb;
        if (bgra) {
            argb = _mm_or_si128(t, opaque);
        } else {  // R | G << 8 | B << 16 -> B | G << 8 | R << 16
            const __m128i r = _mm_slli_epi32(_mm_and_si128(t, low), 16);
            const __m128i b = _mm_and_si128(_mm_srli_epi32(t, 16), low);
            argb = _mm_or_si128(_mm_or_si128(r, b), _mm_or_si128(_mm_and_si128(t, green), opaque));
        }
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i), argb);
    }
#endif
    const int red = bgra ? 2 : 0, blue = bgra ? 0 : 2;
    for (; i < count; ++i)
        out[i] = 0xFF000000u | (static_cast<std::uint32_t>(src[i * 4 + red]) << 16) |
                 (static_cast<std::uint32_t>(src[i * 4 + 1]) << 8) | src[i * 4 + blue];
}

/// The pipeline of a draw with uniforms `u`: blending and write mask from
/// `cm` (null: REPLACE, every channel), the shader features `u` uses.
PipelineKey pipelineKey(const DrawUniforms& u, const CompositingMode* cm, std::uint8_t samples) {
    PipelineKey key;
    key.blend = blendIndex(cm);
    key.writeMask = writeMask(cm);
    key.samples = samples;
    key.discard = (u.misc[1] > 0.0f || u.texEnv[0][3] != 0 || u.texEnv[1][3] != 0) ? 1 : 0;
    for (int unit = 0; unit < 2; ++unit) {
        key.texFunc[unit] = static_cast<std::uint8_t>(u.texEnv[unit][0]);
        key.texFormat[unit] = static_cast<std::uint8_t>((u.texEnv[unit][1] ? 1 : 0) | (u.texEnv[unit][2] ? 2 : 0));
        // Column-major: the bottom row is elements 3, 7, 11, 15.
        const float* m = u.texMatrix[unit];
        const bool affine = m[3] == 0.0f && m[7] == 0.0f && m[11] == 0.0f && m[15] == 1.0f;
        key.texProjective[unit] = key.texFunc[unit] != 0 && !affine ? 1 : 0;
    }
    key.fog = u.fogParams[0] != 0.0f ? 1 : 0;
    key.flat = (u.flags[0] & F_FLAT) ? 1 : 0;
    if (u.flags[0] & F_LIGHTING) {
        key.lighting = (u.flags[0] & F_TWO_SIDED) ? 3 : 1;
        key.lightCount = static_cast<std::uint8_t>(u.flags[1]);
        for (int i = 0; i < u.flags[1]; ++i)
            key.lightModes = static_cast<std::uint16_t>(key.lightModes | (static_cast<int>(u.lights[i].color[3]) << (2 * i)));
        key.specular = (u.matSpecular[0] != 0.0f || u.matSpecular[1] != 0.0f || u.matSpecular[2] != 0.0f) ? 1 : 0;
    }
    return key;
}

std::int32_t texFunc(int blending) {
    switch (blending) {
    case Texture2D::FUNC_REPLACE: return TEX_REPLACE;
    case Texture2D::FUNC_MODULATE: return TEX_MODULATE;
    case Texture2D::FUNC_DECAL: return TEX_DECAL;
    case Texture2D::FUNC_BLEND: return TEX_BLEND;
    case Texture2D::FUNC_ADD: return TEX_ADD;
    default: return TEX_MODULATE;
    }
}

void barrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to,
             VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage,
             VkAccessFlags2 dstAccess) {
    imageBarrier(cmd, image, aspect, 0, 1, from, to, srcStage, srcAccess, dstStage, dstAccess);
}

}  // namespace

Renderer::Renderer() : ctx_(Context::shared()) {
    pipelines_ = std::make_unique<Pipelines>(*ctx_);
    resources_ = std::make_unique<ResourceCache>(*ctx_, pipelines_->textureSetLayout());
    const auto align = static_cast<std::uint32_t>(ctx_->properties().limits.minUniformBufferOffsetAlignment);
    uniformStride_ = static_cast<std::uint32_t>((sizeof(DrawUniforms) + align - 1) / align * align);
    uniformPool_ = createDescriptorPool(ctx_->device(), VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1024, 1, "uniforms");
    quads_ = ctx_->createHostBuffer(kQuadBytes * 1024, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    dummy_ = ctx_->createHostBuffer(64, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    std::memset(dummy_.mapped, 0, 64);
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    check(vkCreateFence(ctx_->device(), &fi, nullptr, &fence_), "vkCreateFence");
    {
        // A pool of this renderer's own: renderers on different threads record concurrently.
        commandPool_ = ctx_->createCommandPool();
        VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        ai.commandPool = commandPool_;
        ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        ai.commandBufferCount = 1;
        check(vkAllocateCommandBuffers(ctx_->device(), &ai, &cmd_), "vkAllocateCommandBuffers");
    }
    // The common pipelines before the first frame, on GPUs, where creating a
    // pipeline is where its shaders are compiled. Not on a CPU device:
    // lavapipe's pipeline creation only prepares NIR, the machine code is
    // compiled at the first draw of each state anyway, so pre-warming there
    // only delays the first frame (measured: 230-390 ms instead of 40-75 ms,
    // with no later compile spared). M3G_VK_PREWARM=1/0 forces either way;
    // M3G_VK_NO_PREWARM=1 (older name) skips it.
    const char* prewarm = std::getenv("M3G_VK_PREWARM");
    const char* noPrewarm = std::getenv("M3G_VK_NO_PREWARM");
    bool warm = ctx_->properties().deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU;
    if (prewarm && *prewarm) warm = std::string(prewarm) == "1";
    if (noPrewarm && std::string(noPrewarm) == "1") warm = false;
    if (warm) pipelines_->prewarm(1);
}

Renderer::~Renderer() {
    VkDevice device = ctx_->device();
    ctx_->waitIdle();
    resources_.reset();
    for (auto& c : chunks_) ctx_->destroy(c.buffer);
    vkDestroyDescriptorPool(device, uniformPool_, nullptr);
    ctx_->destroy(quads_);
    for (Buffer& b : retiredQuads_) ctx_->destroy(b);
    ctx_->destroy(dummy_);
    ctx_->destroy(transfer_);
    ctx_->destroy(color_);
    ctx_->destroy(depth_);
    ctx_->destroy(msaaColor_);
    ctx_->destroy(initial_);
    vkDestroyFence(device, fence_, nullptr);
    vkDestroyCommandPool(device, commandPool_, nullptr);  // frees cmd_
}

void Renderer::ensureTargetImages(std::uint32_t width, std::uint32_t height, VkSampleCountFlagBits samples) {
    if (color_.image && width_ == width && height_ == height && samples_ == samples) return;
    ctx_->waitIdle();
    resources_->forgetTextureSets();  // they may name initial_'s view
    ctx_->destroy(color_);
    ctx_->destroy(depth_);
    ctx_->destroy(transfer_);
    ctx_->destroy(msaaColor_);
    ctx_->destroy(initial_);
    samples_ = samples;
    const VkImageUsageFlags colorUsage =
        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    // On a CPU device the colour target is linear host memory, read back in
    // place instead of copied into transfer_ first (lavapipe's copy was ~12%
    // of an empty 1280x960 frame). M3G_VK_HOST_TARGET=0 keeps the copy.
    const char* hostTarget = std::getenv("M3G_VK_HOST_TARGET");
    if ((!hostTarget || std::string(hostTarget) != "0") &&
        ctx_->hostImageUsable(VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT |
                                                            VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT |
                                                            VK_FORMAT_FEATURE_TRANSFER_SRC_BIT |
                                                            VK_FORMAT_FEATURE_TRANSFER_DST_BIT)) {
        color_ = ctx_->createHostImage(width, height, VK_FORMAT_R8G8B8A8_UNORM, colorUsage);
        if (color_.rowPitch != static_cast<VkDeviceSize>(width) * 4) ctx_->destroy(color_);  // read as one span only
    }
    if (!color_.image) color_ = ctx_->createImage(width, height, VK_FORMAT_R8G8B8A8_UNORM, colorUsage);
    depth_ = ctx_->createImage(width, height, ctx_->depthFormat(), VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, 1, samples);
    if (samples != VK_SAMPLE_COUNT_1_BIT) {
        msaaColor_ = ctx_->createImage(width, height, VK_FORMAT_R8G8B8A8_UNORM, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, 1,
                                       samples);
        initial_ = ctx_->createImage(width, height, VK_FORMAT_R8G8B8A8_UNORM,
                                     VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    }
    transfer_ = ctx_->createHostBuffer(static_cast<VkDeviceSize>(width) * height * 4,
                                       VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    width_ = width;
    height_ = height;
}

void Renderer::begin(Graphics3D& g3d, const float* clearColor, bool covered) {
    if (recording_) return;
    debug_ = debugView();
    clampLit_ = litColorClamping();
    const auto w = static_cast<std::uint32_t>(g3d.targetWidth()), h = static_cast<std::uint32_t>(g3d.targetHeight());
    // ANTIALIAS: multisampling when the device has it (spec §4.26 hints).
    const bool antialias = (g3d.getHints() & Graphics3D::ANTIALIAS) != 0 && ctx_->maxSamples() != VK_SAMPLE_COUNT_1_BIT;
    ensureTargetImages(w, h, antialias ? ctx_->maxSamples() : VK_SAMPLE_COUNT_1_BIT);
    hasDepth_ = g3d.isDepthBufferEnabled();
    const bool overwrite = (g3d.getHints() & Graphics3D::OVERWRITE) != 0;
    const bool msaa = samples_ != VK_SAMPLE_COUNT_1_BIT;

    // Where the prior contents come from: a window keeps them on the GPU
    // (black when its image is new); other targets upload their pixels.
    window_ = dynamic_cast<WindowTarget*>(g3d.targetGraphics());
    target_ = &color_;
    // A first command that clears every pixel makes the prior contents moot.
    enum class Prior { None, Upload, Keep, Black } prior =
        overwrite || clearColor || covered ? Prior::None : Prior::Upload;
    if (window_) {
        bool created = false;
        target_ = &window_->swapchain().back(w, h, created);
        if (created) window_->setFreshContents(true);
        if (prior != Prior::None) prior = window_->freshContents() ? Prior::Black : Prior::Keep;
        window_->setFreshContents(false);
    }
    if (prior == Prior::Upload) {
        auto* dst = static_cast<std::uint8_t*>(transfer_.mapped);
        if (Image2D* image = g3d.targetImage()) {
            std::vector<std::uint8_t> rgba;
            image->getPixelsRGBA8(rgba);
            std::memcpy(dst, rgba.data(), std::min<std::size_t>(rgba.size(), transfer_.size));
        } else if (Graphics* graphics = g3d.targetGraphics()) {
            const auto px = graphics->pixels();
            for (std::size_t i = 0; i < px.size(); ++i) {
                dst[i * 4 + 0] = static_cast<std::uint8_t>(px[i] >> 16);
                dst[i * 4 + 1] = static_cast<std::uint8_t>(px[i] >> 8);
                dst[i * 4 + 2] = static_cast<std::uint8_t>(px[i]);
                dst[i * 4 + 3] = static_cast<std::uint8_t>(px[i] >> 24);
            }
        }
    }

    resources_->beginFrame();
    chunk_ = 0;
    chunkOffset_ = 0;
    quadOffset_ = 0;
    boundPipeline_ = ~0ull;
    cull_ = frontFace_ = depthTest_ = depthWrite_ = biasEnabled_ = -1;
    boundTextures_ = VK_NULL_HANDLE;

    vkResetCommandBuffer(cmd_, 0);
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cmd_, &bi), "vkBeginCommandBuffer");
    constexpr VkPipelineStageFlags2 kAttachmentStage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
    constexpr VkAccessFlags2 kAttachmentAccess =
        VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
    const VkImage colorImage = target_->image;
    // The prior contents: straight into the colour attachment, or with
    // multisampling into initial_, drawn into the samples below. A window's
    // image was left in TRANSFER_SRC layout by the previous present.
    bool colorReady = false;  // colorImage already in attachment layout
    if (prior == Prior::Upload || (prior == Prior::Keep && msaa)) {
        VkImage dst = msaa ? initial_.image : colorImage;
        barrier(cmd_, dst, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        if (prior == Prior::Upload) {
            copyBufferToImage(cmd_, transfer_.buffer, dst, w, h);
        } else {
            VkImageCopy region{};
            region.srcSubresource = region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.extent = {w, h, 1};
            vkCmdCopyImage(cmd_, colorImage, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        }
        if (msaa)
            barrier(cmd_, dst, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                    VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        else {
            barrier(cmd_, dst, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT, kAttachmentStage, kAttachmentAccess);
            colorReady = true;
        }
    }
    if (!colorReady) {
        // Kept contents change layout in place; anything else starts undefined.
        const bool keep = prior == Prior::Keep && !msaa;
        barrier(cmd_, colorImage, VK_IMAGE_ASPECT_COLOR_BIT,
                keep ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED,
                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                window_ ? VK_PIPELINE_STAGE_2_TRANSFER_BIT : VK_PIPELINE_STAGE_2_NONE, 0, kAttachmentStage,
                kAttachmentAccess);
    }
    if (msaa)
        barrier(cmd_, msaaColor_.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, 0, kAttachmentStage,
                kAttachmentAccess);
    barrier(cmd_, depth_.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
            VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, 0,
            VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);

    // The rendering itself opens at the first command that needs it
    // (openRendering): a clear of the whole target before it becomes the
    // colour attachment's load operation.
    VkRenderingAttachmentInfo& colorAttachment = colorAttachment_;
    colorAttachment = {VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    colorAttachment.imageView = msaa ? msaaColor_.view : target_->view;
    colorAttachment.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    colorAttachment.loadOp = (prior == Prior::Black || clearColor) ? VK_ATTACHMENT_LOAD_OP_CLEAR
                             : (prior == Prior::None || msaa)      ? VK_ATTACHMENT_LOAD_OP_DONT_CARE
                                                                   : VK_ATTACHMENT_LOAD_OP_LOAD;
    colorAttachment.clearValue.color = {{0.0f, 0.0f, 0.0f, 1.0f}};  // a new Graphics is opaque black
    if (clearColor) std::memcpy(colorAttachment.clearValue.color.float32, clearColor, 4 * sizeof(float));
    colorAttachment.storeOp = msaa ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
    if (msaa) {
        colorAttachment.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
        colorAttachment.resolveImageView = target_->view;
        colorAttachment.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    }
    VkRenderingAttachmentInfo& depthAttachment = depthAttachment_;
    depthAttachment = {VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depthAttachment.imageView = depth_.view;
    depthAttachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depthAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;  // a fresh target's depth is far
    depthAttachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depthAttachment.clearValue.depthStencil = {1.0f, 0};
    recording_ = true;
    renderingOpen_ = false;
    // With multisampling the prior contents are drawn into every sample
    // when the rendering opens (unless a clear of every pixel comes first).
    drawPrior_ = msaa && (prior == Prior::Upload || prior == Prior::Keep);
}

void Renderer::openRendering() {
    if (renderingOpen_) return;
    renderingOpen_ = true;
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = {{0, 0}, {width_, height_}};
    ri.layerCount = 1;
    ri.colorAttachmentCount = 1;
    ri.pColorAttachments = &colorAttachment_;
    ri.pDepthAttachment = &depthAttachment_;
    vkCmdBeginRendering(cmd_, &ri);
    if (drawPrior_) {
        drawPrior_ = false;
        // The prior contents, drawn over the whole target into every sample.
        // The viewport and scissor of the frame's next command are set after.
        const VkViewport vp{0, 0, static_cast<float>(width_), static_cast<float>(height_), 0.0f, 1.0f};
        vkCmdSetViewport(cmd_, 0, 1, &vp);
        const VkRect2D sc{{0, 0}, {width_, height_}};
        vkCmdSetScissor(cmd_, 0, 1, &sc);
        TextureMirror priorTexture;
        priorTexture.image = initial_;
        VkSampler sampler = resources_->sampler(Texture2D::WRAP_CLAMP, Texture2D::WRAP_CLAMP, Texture2D::FILTER_NEAREST,
                                                Texture2D::FILTER_BASE_LEVEL);
        VkDescriptorSet set, textures;
        std::uint32_t offset;
        const DrawUniforms& u = quadUniforms(priorTexture, sampler, TEX_REPLACE, set, offset, textures);
        const float ndc[4] = {-1.0f, -1.0f, 1.0f, 1.0f};
        const float tex[4] = {0.0f, 0.0f, 1.0f, 1.0f};
        drawQuad(set, offset, textures, pipelineKey(u, nullptr, static_cast<std::uint8_t>(samples_)), false, false, ndc,
                 0.0f, tex);
        setViewportState();  // the draw that opened the rendering follows
    }
}

Renderer::Rect Renderer::drawArea(const Graphics3D& g3d, Rect& viewport) {
    const int width = g3d.targetWidth(), height = g3d.targetHeight();
    int ox = 0, oy = 0;
    Rect clip{0, 0, width, height};
    if (Graphics* g = g3d.targetGraphics()) {
        ox = g->getTranslateX();
        oy = g->getTranslateY();
        clip = {g->getClipX() + ox, g->getClipY() + oy, g->getClipWidth(), g->getClipHeight()};
    }
    viewport = {g3d.getViewportX() + ox, g3d.getViewportY() + oy, g3d.getViewportWidth(), g3d.getViewportHeight()};
    const int x0 = std::max({viewport.x, clip.x, 0});
    const int y0 = std::max({viewport.y, clip.y, 0});
    const int x1 = std::min({viewport.x + viewport.w, clip.x + clip.w, width});
    const int y1 = std::min({viewport.y + viewport.h, clip.y + clip.h, height});
    return {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
}

void Renderer::applyViewport(Graphics3D& g3d) {
    scissor_ = drawArea(g3d, viewport_);
    scissorEmpty_ = scissor_.w <= 0 || scissor_.h <= 0;
    depthNear_ = g3d.getDepthRangeNear();
    depthFar_ = g3d.getDepthRangeFar();
    if (!scissorEmpty_) setViewportState();
}

void Renderer::setViewportState() {
    VkViewport vp{static_cast<float>(viewport_.x), static_cast<float>(viewport_.y), static_cast<float>(viewport_.w),
                  static_cast<float>(viewport_.h), depthNear_, depthFar_};
    vkCmdSetViewport(cmd_, 0, 1, &vp);
    VkRect2D sc{{scissor_.x, scissor_.y}, {static_cast<std::uint32_t>(scissor_.w), static_cast<std::uint32_t>(scissor_.h)}};
    vkCmdSetScissor(cmd_, 0, 1, &sc);
}

DrawUniforms& Renderer::allocUniforms(VkDescriptorSet& set, std::uint32_t& offset) {
    if (chunk_ < chunks_.size() && chunkOffset_ + uniformStride_ > kDrawsPerChunk * uniformStride_) {
        ++chunk_;
        chunkOffset_ = 0;
    }
    if (chunk_ == chunks_.size()) {
        UniformChunk c;
        c.buffer = ctx_->createHostBuffer(static_cast<VkDeviceSize>(kDrawsPerChunk) * uniformStride_,
                                          VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
        VkDescriptorSetLayout layout = pipelines_->uniformSetLayout();
        VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        ai.descriptorPool = uniformPool_;
        ai.descriptorSetCount = 1;
        ai.pSetLayouts = &layout;
        check(vkAllocateDescriptorSets(ctx_->device(), &ai, &c.set), "vkAllocateDescriptorSets (uniforms)");
        VkDescriptorBufferInfo info{c.buffer.buffer, 0, sizeof(DrawUniforms)};
        VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstSet = c.set;
        w.descriptorCount = 1;
        w.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
        w.pBufferInfo = &info;
        vkUpdateDescriptorSets(ctx_->device(), 1, &w, 0, nullptr);
        chunks_.push_back(c);
        chunkOffset_ = 0;
    }
    set = chunks_[chunk_].set;
    offset = chunkOffset_;
    chunkOffset_ += uniformStride_;
    auto* u = reinterpret_cast<DrawUniforms*>(static_cast<char*>(chunks_[chunk_].buffer.mapped) + offset);
    std::memset(u, 0, sizeof(DrawUniforms));
    return *u;
}

void Renderer::bindPipeline(const PipelineKey& key) {
    if (boundPipeline_ == key.packed()) return;
    vkCmdBindPipeline(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_->get(key));
    boundPipeline_ = key.packed();
}

void Renderer::setDepthState(bool test, bool write, float factor, float units) {
    // A disabled depth test is ALWAYS, so depth is still written (Nokia, spec §8 item 6).
    if (!hasDepth_) test = write = false;
    if (depthTest_ == -1) {
        vkCmdSetDepthTestEnable(cmd_, VK_TRUE);
        vkCmdSetDepthBias(cmd_, 0.0f, 0.0f, 0.0f);
        biasFactor_ = biasUnits_ = 0.0f;
    }
    const int t = test ? 1 : 0, w = write ? 1 : 0;
    if (t != depthTest_) vkCmdSetDepthCompareOp(cmd_, test ? VK_COMPARE_OP_LESS_OR_EQUAL : VK_COMPARE_OP_ALWAYS);
    depthTest_ = t;
    if (w != depthWrite_) vkCmdSetDepthWriteEnable(cmd_, write ? VK_TRUE : VK_FALSE);
    depthWrite_ = w;
    const int bias = (factor != 0.0f || units != 0.0f) ? 1 : 0;
    if (bias != biasEnabled_) vkCmdSetDepthBiasEnable(cmd_, bias ? VK_TRUE : VK_FALSE);
    biasEnabled_ = bias;
    if (bias && (factor != biasFactor_ || units != biasUnits_)) {
        vkCmdSetDepthBias(cmd_, units, 0.0f, factor);
        biasFactor_ = factor;
        biasUnits_ = units;
    }
}

void Renderer::fillFog(DrawUniforms& u, const Appearance* app) const {
    const Fog* fog = app ? app->getFog().get() : nullptr;
    if (!fog) return;
    argb(static_cast<std::uint32_t>(fog->getColor()), u.fogColor, false);
    u.fogParams[0] = fog->getMode() == Fog::LINEAR ? 1.0f : 2.0f;
    u.fogParams[1] = fog->getNearDistance();
    u.fogParams[2] = fog->getFarDistance();
    u.fogParams[3] = fog->getDensity();
}

void Renderer::clear(Graphics3D& g3d, const Background* background) {
    const bool clearColor = !background || background->isColorClearEnabled();
    float color[4] = {0, 0, 0, 0};
    if (background) argb(static_cast<std::uint32_t>(background->getColor()), color, true);
    Rect viewport;
    const Rect area = drawArea(g3d, viewport);
    const bool whole = area.x == 0 && area.y == 0 && area.w == g3d.targetWidth() && area.h == g3d.targetHeight();

    // The image: the crop rectangle covers the viewport exactly (spec §5.9).
    Image2D* image = clearColor && background ? background->getImage().get() : nullptr;
    if (image && (background->getCropWidth() <= 0 || background->getCropHeight() <= 0)) image = nullptr;
    const bool repeatX = background && background->getImageModeX() == Background::REPEAT;
    const bool repeatY = background && background->getImageModeY() == Background::REPEAT;
    // A BORDER axis shows the background colour where the crop leaves the
    // image (a discard in the quad's shader). A crop inside the image maps
    // every pixel centre at least half a pixel's step inside [0, 1], so the
    // discard can go when that step is well above float rounding.
    auto inside = [](int cropPos, int cropSize, int imageSize, int viewportSize) {
        return cropPos >= 0 && cropPos + cropSize <= imageSize &&
               0.5 * cropSize / imageSize / std::max(viewportSize, 1) > 1e-5;
    };
    const bool borderX = image && !repeatX &&
                         !inside(background->getCropX(), background->getCropWidth(), image->getWidth(), viewport.w);
    const bool borderY = image && !repeatY &&
                         !inside(background->getCropY(), background->getCropHeight(), image->getHeight(), viewport.h);
    const bool imageCovers = image && !borderX && !borderY;  // the quad writes every pixel of the viewport

    // Until the rendering opens (the frame's first draw), a clear of every
    // pixel's colour is the colour attachment's load operation (none when the
    // image covers every pixel anyway), and a depth clear is moot: the depth
    // attachment loads as far. vkCmdClearAttachments costs lavapipe a fill of
    // the image on its submitting thread, after the tile clears of the load
    // operations (measured: ~40% of an empty 1280x960 frame's CPU time).
    const bool drawn = recording_ && renderingOpen_;
    const bool asLoadOp = !drawn && clearColor && whole;
    if (recording_ && asLoadOp) {  // nothing drawn yet: the prior contents are moot
        colorAttachment_.loadOp = imageCovers ? VK_ATTACHMENT_LOAD_OP_DONT_CARE : VK_ATTACHMENT_LOAD_OP_CLEAR;
        std::memcpy(colorAttachment_.clearValue.color.float32, color, sizeof(color));
        drawPrior_ = false;
    }
    begin(g3d, asLoadOp && !imageCovers ? color : nullptr, asLoadOp);
    applyViewport(g3d);
    if (scissorEmpty_) return;
    const bool clearDepth = (!background || background->isDepthClearEnabled()) && hasDepth_ && drawn;
    VkClearRect rect{{{scissor_.x, scissor_.y}, {static_cast<std::uint32_t>(scissor_.w), static_cast<std::uint32_t>(scissor_.h)}}, 0, 1};
    VkClearAttachment attachments[2]{};
    std::uint32_t count = 0;
    if (clearColor && !asLoadOp && !imageCovers) {
        attachments[count].aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
        attachments[count].colorAttachment = 0;
        std::memcpy(attachments[count].clearValue.color.float32, color, sizeof(color));
        ++count;
    }
    if (clearDepth) {
        attachments[count].aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
        attachments[count].clearValue.depthStencil = {1.0f, 0};
        ++count;
    }
    if (count) {
        openRendering();
        vkCmdClearAttachments(cmd_, count, attachments, 1, &rect);
    }

    if (!image) return;
    const TextureMirror& tex = resources_->texture(*image, false);
    VkSampler sampler = resources_->sampler(repeatX ? Texture2D::WRAP_REPEAT : Texture2D::WRAP_CLAMP,
                                            repeatY ? Texture2D::WRAP_REPEAT : Texture2D::WRAP_CLAMP,
                                            Texture2D::FILTER_NEAREST, Texture2D::FILTER_BASE_LEVEL);
    VkDescriptorSet set, textures;
    std::uint32_t offset;
    DrawUniforms& u = quadUniforms(tex, sampler, TEX_REPLACE, set, offset, textures);
    const float iw = static_cast<float>(image->getWidth()), ih = static_cast<float>(image->getHeight());
    const float texRect[4] = {static_cast<float>(background->getCropX()) / iw, static_cast<float>(background->getCropY()) / ih,
                              static_cast<float>(background->getCropX() + background->getCropWidth()) / iw,
                              static_cast<float>(background->getCropY() + background->getCropHeight()) / ih};
    u.texEnv[0][3] = (borderX ? 1 : 0) | (borderY ? 2 : 0);
    const float ndc[4] = {-1.0f, -1.0f, 1.0f, 1.0f};
    drawQuad(set, offset, textures, pipelineKey(u, nullptr, static_cast<std::uint8_t>(samples_)), false, false, ndc,
             0.0f, texRect);
}

DrawUniforms& Renderer::quadUniforms(const TextureMirror& tex, VkSampler sampler, std::int32_t func,
                                     VkDescriptorSet& set, std::uint32_t& offset, VkDescriptorSet& textures) {
    textures = resources_->textureSet(&tex, sampler, nullptr, VK_NULL_HANDLE);
    DrawUniforms& u = allocUniforms(set, offset);
    // Positions are NDC: identity model-view, only the clip-space fix-up.
    static const Transform clipFix = vulkanProjection(Transform());
    identity(u.modelView);
    toColumns(clipFix, u.projection);
    identity(u.normalMatrix);
    identity(u.texMatrix[0]);
    identity(u.texMatrix[1]);
    u.positionScaleBias[3] = 1.0f;
    u.texScaleBias[0][3] = u.texScaleBias[1][3] = 1.0f;
    u.flags[0] = F_CLIP_SPACE;
    u.texEnv[0][0] = func;
    u.texEnv[0][1] = tex.hasColor;
    u.texEnv[0][2] = tex.hasAlpha;
    u.defaultColor[0] = u.defaultColor[1] = u.defaultColor[2] = u.defaultColor[3] = 1.0f;
    u.misc[0] = 1.0f;   // alpha factor
    u.misc[2] = -1.0f;  // no fixed fog depth
    return u;
}

void Renderer::drawQuad(VkDescriptorSet uniformSet, std::uint32_t offset, VkDescriptorSet textures,
                        const PipelineKey& key, bool depthTest, bool depthWrite, const float r[4], float z,
                        const float t[4]) {
    openRendering();
    if (quadOffset_ + kQuadBytes > quads_.size) {
        // A bigger ring; the full one stays alive until the frame is done.
        retiredQuads_.push_back(quads_);
        quads_ = ctx_->createHostBuffer(quads_.size * 2, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        quadOffset_ = 0;
    }
    // Two triangles, counter-clockwise; positions then texcoords per vertex.
    // The order is the triangle strip top-left, bottom-left, top-right,
    // bottom-right as GL splits it, which is how Nokia's engine draws
    // backgrounds and sprites: attributes are interpolated from each
    // triangle's first vertex, so a pixel centre exactly on a texel edge (a
    // 64-texel image over 240 rows has one every 15 rows) then rounds as in the
    // reference renders: to the texel after the edge, as exact arithmetic says
    // (VkTest.BackgroundNearestRowsAtExactTexelEdges).
    const float tl[6] = {r[0], r[3], z, t[0], t[1], 0}, bl[6] = {r[0], r[1], z, t[0], t[3], 0},
                tr[6] = {r[2], r[3], z, t[2], t[1], 0}, br[6] = {r[2], r[1], z, t[2], t[3], 0};
    const float* order[6] = {tl, bl, tr, tr, bl, br};
    float v[6][6];
    for (int i = 0; i < 6; ++i) std::memcpy(v[i], order[i], sizeof(v[i]));
    std::memcpy(static_cast<char*>(quads_.mapped) + quadOffset_, v, sizeof(v));
    bindPipeline(key);
    setDepthState(depthTest, depthWrite, 0.0f, 0.0f);
    if (cull_ != 0) {
        vkCmdSetCullMode(cmd_, VK_CULL_MODE_NONE);
        cull_ = 0;
    }
    if (frontFace_ == -1) {
        vkCmdSetFrontFace(cmd_, VK_FRONT_FACE_COUNTER_CLOCKWISE);
        frontFace_ = 0;
    }
    vkCmdBindDescriptorSets(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_->layout(), 0, 1, &uniformSet, 1, &offset);
    if (boundTextures_ != textures) {
        vkCmdBindDescriptorSets(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_->layout(), 1, 1, &textures, 0, nullptr);
        boundTextures_ = textures;
    }
    const VkBuffer buffers[5] = {quads_.buffer, dummy_.buffer, dummy_.buffer, quads_.buffer, dummy_.buffer};
    const VkDeviceSize offsets[5] = {quadOffset_, 0, 0, quadOffset_ + 3 * sizeof(float), 0};
    const VkDeviceSize strides[5] = {6 * sizeof(float), 0, 0, 6 * sizeof(float), 0};
    vkCmdBindVertexBuffers2(cmd_, 0, 5, buffers, offsets, nullptr, strides);
    vkCmdDraw(cmd_, 6, 1, 0, 0);
    quadOffset_ += kQuadBytes;
    ++ctx_->draws;
}

void Renderer::render(Graphics3D& g3d, const detail::RenderQueue& queue) {
    begin(g3d);
    applyViewport(g3d);
    if (scissorEmpty_) return;
    toColumns(vulkanProjection(queue.projection), projection_);  // once per queue, not per draw
    computeSkinning_ = g3d.getSkinningMode() == Graphics3D::SKINNING_COMPUTE;
    for (const detail::RenderItem& item : queue.items) {
        if (item.kind == detail::RenderItem::Kind::Sprite) drawSprite(queue, item);
        else drawSubmesh(queue, item);
    }
}

void Renderer::drawSubmesh(const detail::RenderQueue& queue, const detail::RenderItem& item) {
    VertexBuffer& vb = *item.vertices;
    const Appearance* app = item.appearance;
    const auto* mesh = dynamic_cast<const Mesh*>(item.node);
    const VertexMirror& vm = resources_->vertices(vb, mesh, computeSkinning_);
    const IndexMirror& im = resources_->indices(*item.indices);
    if (im.count == 0) return;
    if (item.indices->maxIndex() >= vm.vertexCount)
        throw IllegalStateException("Graphics3D::render: an IndexBuffer refers to vertex " +
                                    std::to_string(item.indices->maxIndex()) + " but the VertexBuffer has " +
                                    std::to_string(vm.vertexCount) + " vertices");

    openRendering();  // before any state below: drawing the prior contents changes it
    VkDescriptorSet set;
    std::uint32_t offset;
    DrawUniforms& u = allocUniforms(set, offset);
    toColumns(item.modelView, u.modelView);
    std::memcpy(u.projection, projection_, sizeof(projection_));
    {
        glm::mat3 mv;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) mv[c][r] = item.modelView.at(r, c);
        const float det = glm::determinant(mv);
        const glm::mat3 n = det != 0.0f ? glm::transpose(glm::inverse(mv)) : mv;
        identity(u.normalMatrix);
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) u.normalMatrix[c * 4 + r] = n[c][r];
    }
    if (vm.deformed) {
        u.positionScaleBias[3] = 1.0f;
    } else {
        const auto& b = vb.positionBias();
        u.positionScaleBias[0] = b[0];
        u.positionScaleBias[1] = b[1];
        u.positionScaleBias[2] = b[2];
        u.positionScaleBias[3] = vb.positionScale();
    }
    argb(static_cast<std::uint32_t>(vb.getDefaultColor()), u.defaultColor, true);

    // Texture units: a unit is used when it has both a texture and coordinates.
    const TextureMirror* tex[2] = {nullptr, nullptr};
    VkSampler samplers[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
    const int units = std::min(2, getLimits().numTextureUnits);
    for (int unit = 0; unit < units; ++unit) {
        identity(u.texMatrix[unit]);
        u.texScaleBias[unit][3] = 1.0f;
        Texture2D* t = app->getTexture(unit).get();
        if (!t || !vb.texCoords(unit) || !vm.present[3 + unit]) continue;
        Image2D* image = t->getImage().get();
        const bool mipmaps = t->getLevelFilter() != Texture2D::FILTER_BASE_LEVEL;
        tex[unit] = &resources_->texture(*image, mipmaps);
        samplers[unit] = resources_->sampler(t->getWrappingS(), t->getWrappingT(), t->getImageFilter(), t->getLevelFilter());
        toColumns(t->compositeTransform(), u.texMatrix[unit]);
        const auto& b = vb.texCoordBias(unit);
        u.texScaleBias[unit][0] = b[0];
        u.texScaleBias[unit][1] = b[1];
        u.texScaleBias[unit][2] = b[2];
        u.texScaleBias[unit][3] = vb.texCoordScale(unit);
        u.texEnv[unit][0] = texFunc(t->getBlending());
        u.texEnv[unit][1] = tex[unit]->hasColor;
        u.texEnv[unit][2] = tex[unit]->hasAlpha;
        argb(static_cast<std::uint32_t>(t->getBlendColor()), u.texBlendColor[unit], false);
    }

    const PolygonMode* pm = app->getPolygonMode().get();
    const Material* material = debug_.unlit ? nullptr : app->getMaterial().get();
    std::int32_t flags = 0;
    if (vm.present[1]) flags |= F_HAS_NORMALS;
    if (vm.present[2]) flags |= F_HAS_COLORS;
    if (pm && pm->getShading() == PolygonMode::SHADE_FLAT) flags |= F_FLAT;
    if (material) {
        flags |= F_LIGHTING;
        if (clampLit_) flags |= F_CLAMP_LIT;
        if (material->isVertexColorTrackingEnabled()) flags |= F_COLOR_TRACKING;
        if (pm && pm->isTwoSidedLightingEnabled()) flags |= F_TWO_SIDED;
        if (pm && pm->isLocalCameraLightingEnabled()) flags |= F_LOCAL_CAMERA;
        argb(static_cast<std::uint32_t>(material->getColor(Material::AMBIENT)), u.matAmbient, false);
        argb(static_cast<std::uint32_t>(material->getColor(Material::DIFFUSE)), u.matDiffuse, true);
        argb(static_cast<std::uint32_t>(material->getColor(Material::EMISSIVE)), u.matEmissive, false);
        argb(static_cast<std::uint32_t>(material->getColor(Material::SPECULAR)), u.matSpecular, false);
        u.matSpecular[3] = material->getShininess();
        for (int i = 0; i < item.lightCount; ++i) {
            const detail::RenderLight& l = queue.lights[item.lights[i]];
            LightUniforms& lu = u.lights[i];
            std::copy(l.position.begin(), l.position.end(), lu.position);
            lu.color[0] = l.color[0];
            lu.color[1] = l.color[1];
            lu.color[2] = l.color[2];
            lu.color[3] = static_cast<float>(l.mode - Light::AMBIENT);
            lu.spot[0] = l.spotDirection[0];
            lu.spot[1] = l.spotDirection[1];
            lu.spot[2] = l.spotDirection[2];
            lu.spot[3] = l.spotCosCutoff;
            lu.attenuation[0] = l.attenuation[0];
            lu.attenuation[1] = l.attenuation[1];
            lu.attenuation[2] = l.attenuation[2];
            lu.attenuation[3] = l.spotExponent;
        }
        u.flags[1] = item.lightCount;
    }
    u.flags[0] = flags;
    fillFog(u, app);
    const CompositingMode* cm = app->getCompositingMode().get();
    u.misc[0] = item.alphaFactor;
    u.misc[1] = cm ? cm->getAlphaThreshold() : 0.0f;
    u.misc[2] = -1.0f;

    PipelineKey key = pipelineKey(u, cm, static_cast<std::uint8_t>(samples_));
    key.wireframe = debug_.wireframe ? 1 : 0;
    bindPipeline(key);
    setDepthState(!cm || cm->isDepthTestEnabled(), !cm || cm->isDepthWriteEnabled(), cm ? cm->getDepthOffsetFactor() : 0.0f,
                  cm ? cm->getDepthOffsetUnits() : 0.0f);
    const int culling = pm ? pm->getCulling() : PolygonMode::CULL_BACK;
    const int cull = culling == PolygonMode::CULL_NONE ? 0 : culling == PolygonMode::CULL_FRONT ? 1 : 2;
    if (cull != cull_) {
        vkCmdSetCullMode(cmd_, cull == 0 ? VK_CULL_MODE_NONE : cull == 1 ? VK_CULL_MODE_FRONT_BIT : VK_CULL_MODE_BACK_BIT);
        cull_ = cull;
    }
    // The y flip in the projection keeps on-screen orientation, so CCW stays CCW.
    const int front = (pm && pm->getWinding() == PolygonMode::WINDING_CW) ? 1 : 0;
    if (front != frontFace_) {
        vkCmdSetFrontFace(cmd_, front ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE);
        frontFace_ = front;
    }
    vkCmdBindDescriptorSets(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_->layout(), 0, 1, &set, 1, &offset);
    VkDescriptorSet textures = resources_->textureSet(tex[0], samplers[0], tex[1], samplers[1]);
    if (textures != boundTextures_) {
        vkCmdBindDescriptorSets(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_->layout(), 1, 1, &textures, 0, nullptr);
        boundTextures_ = textures;
    }
    static constexpr VkDeviceSize kStrides[5] = {12, 12, 16, 12, 12};
    VkBuffer buffers[5];
    VkDeviceSize offsets[5], strides[5];
    for (int i = 0; i < 5; ++i) {
        buffers[i] = vm.present[i] ? vm.buffer.buffer : dummy_.buffer;
        offsets[i] = vm.present[i] ? vm.offsets[i] : 0;
        strides[i] = vm.present[i] ? kStrides[i] : 0;
    }
    vkCmdBindVertexBuffers2(cmd_, 0, 5, buffers, offsets, nullptr, strides);
    vkCmdBindIndexBuffer(cmd_, im.buffer.buffer, 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd_, im.count, 1, 0, 0, 0);
    ++ctx_->draws;
}

void Renderer::drawSprite(const detail::RenderQueue& queue, const detail::RenderItem& item) {
    // Spec §5.10: a screen-aligned rectangle at the origin's depth showing
    // crop ∩ image; the image acts as a texture (colour x alpha factor); only
    // the CompositingMode and Fog of the Appearance apply.
    const auto& sprite = static_cast<const Sprite3D&>(*item.node);
    const detail::SpriteRect r =
        detail::projectSprite(sprite, item.modelView, queue.projection, viewport_.w, viewport_.h);
    if (!r.visible) return;
    Image2D* image = sprite.getImage().get();
    const TextureMirror& tex = resources_->texture(*image, false);
    VkSampler sampler = resources_->sampler(Texture2D::WRAP_CLAMP, Texture2D::WRAP_CLAMP, Texture2D::FILTER_NEAREST,
                                            Texture2D::FILTER_BASE_LEVEL);
    VkDescriptorSet set, textures;
    std::uint32_t offset;
    DrawUniforms& u = quadUniforms(tex, sampler, TEX_MODULATE, set, offset, textures);
    const Appearance* app = item.appearance;
    const CompositingMode* cm = app->getCompositingMode().get();
    fillFog(u, app);
    u.misc[0] = item.alphaFactor;
    u.misc[1] = cm ? cm->getAlphaThreshold() : 0.0f;
    u.misc[2] = r.eyeDepth;  // sprites are fogged at their origin's depth
    const PipelineKey key = pipelineKey(u, cm, static_cast<std::uint8_t>(samples_));
    const float ndc[4] = {r.x0, r.y0, r.x1, r.y1};
    const float texRect[4] = {r.s0, r.t0, r.s1, r.t1};
    drawQuad(set, offset, textures, key, !cm || cm->isDepthTestEnabled(), !cm || cm->isDepthWriteEnabled(), ndc,
             r.ndcZ, texRect);
}

void Renderer::release(Graphics3D& g3d) {
    if (!recording_) return;
    recording_ = false;
    openRendering();  // a frame of clears only: their load operation
    vkCmdEndRendering(cmd_);
    const VkImage colorImage = target_->image;
    // A window reads back only on request (screenshots); other targets always.
    const bool readback = window_ ? window_->takeReadbackRequest() : true;
    // A window screenshot with its overlay reads the swapchain image instead.
    bool readbackBgra = readback && window_ && window_->readbackWithOverlay();
    // A host image target is read where it is (GENERAL layout for host access).
    const bool inPlace = !window_ && color_.mapped;
    if (inPlace) {
        barrier(cmd_, colorImage, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    } else {
        barrier(cmd_, colorImage, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        if (readback && !readbackBgra) copyToHost(colorImage);
    }
    const bool presenting = window_ && recordPresent(*window_, readbackBgra);
    if (readbackBgra && !presenting) readbackBgra = false;
    check(vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");
    vkResetFences(ctx_->device(), 1, &fence_);
    // The frame's compute deformations first, in the same batch: their
    // closing barrier orders them before the draws' vertex reads.
    const VkCommandBuffer compute = resources_->finishCompute();
    const VkCommandBuffer both[2] = {compute, cmd_};
    const std::span<const VkCommandBuffer> cmds = compute ? std::span<const VkCommandBuffer>(both, 2)
                                                          : std::span<const VkCommandBuffer>(&cmd_, 1);
    if (presenting) {
        Swapchain& swapchain = window_->swapchain();
        ctx_->submit(cmds, fence_, swapchain.acquiredSemaphore(), VK_PIPELINE_STAGE_TRANSFER_BIT,
                     swapchain.renderedSemaphore());
        swapchain.present();
        window_->markPresented();
    } else {
        ctx_->submit(cmds, fence_);
    }
    check(vkWaitForFences(ctx_->device(), 1, &fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences (frame)");
    ++ctx_->frames;
    resources_->endFrame();
    pipelines_->endFrame();
    for (Buffer& b : retiredQuads_) ctx_->destroy(b);
    retiredQuads_.clear();
    // A window screenshot that could not be taken stays not ready.
    if (!readback || (window_ && window_->readbackWithOverlay() && !readbackBgra)) return;
    if (window_) window_->markReadback();
    // Texels are RGBA, except a swapchain image's (the window with its overlay).
    const bool bgra = readbackBgra && window_->swapchain().format() == VK_FORMAT_B8G8R8A8_UNORM;
    const auto* src = static_cast<const std::uint8_t*>(inPlace ? color_.mapped : transfer_.mapped);
    const std::size_t n = static_cast<std::size_t>(width_) * height_;
    if (Image2D* image = g3d.targetImage()) {
        if (image->getFormat() == Image2D::RGBA) {
            image->set(0, 0, static_cast<int>(width_), static_cast<int>(height_), {src, n * 4});
        } else {
            std::vector<std::uint8_t> rgb(n * 3);
            for (std::size_t i = 0; i < n; ++i)
                for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = src[i * 4 + c];
            image->set(0, 0, static_cast<int>(width_), static_cast<int>(height_), rgb);
        }
    } else if (Graphics* graphics = g3d.targetGraphics()) {
        auto px = graphics->pixels();
        toArgb(src, px.data(), std::min(n, px.size()), bgra);
    }
}

void Renderer::copyToHost(VkImage image) {
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {width_, height_, 1};
    vkCmdCopyImageToBuffer(cmd_, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, transfer_.buffer, 1, &copy);
    VkMemoryBarrier2 hostRead{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    hostRead.srcStageMask = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
    hostRead.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    hostRead.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    hostRead.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &hostRead;
    vkCmdPipelineBarrier2(cmd_, &dep);
}

bool Renderer::recordPresent(WindowTarget& window, bool& readback) {
    Swapchain& swapchain = window.swapchain();
    if (!swapchain.acquire(width_, height_)) return false;  // minimised: nothing to show
    if (!swapchain.readable() || swapchain.extent().width != width_ || swapchain.extent().height != height_)
        readback = false;
    const VkImage image = swapchain.image();
    // The wait on the acquire semaphore is at the transfer stage (submit).
    barrier(cmd_, image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
            VK_PIPELINE_STAGE_2_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    // A blit converts RGBA to the swapchain's channel order (and scales if
    // the surface imposed another size).
    const VkExtent2D extent = swapchain.extent();
    VkImageBlit blit{};
    blit.srcSubresource = blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.srcOffsets[1] = {static_cast<std::int32_t>(width_), static_cast<std::int32_t>(height_), 1};
    blit.dstOffsets[1] = {static_cast<std::int32_t>(extent.width), static_cast<std::int32_t>(extent.height), 1};
    vkCmdBlitImage(cmd_, target_->image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_NEAREST);
    VkImageLayout layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
    VkAccessFlags2 access = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    if (WindowOverlay* overlay = window.overlay()) {
        barrier(cmd_, image, VK_IMAGE_ASPECT_COLOR_BIT, layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, stage,
                access, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        overlay->record(cmd_, swapchain);
        layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        stage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
        access = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
    }
    if (readback) {
        // The presented image, overlay included (a screenshot of the window).
        barrier(cmd_, image, VK_IMAGE_ASPECT_COLOR_BIT, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, stage, access,
                VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        copyToHost(image);
        layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        stage = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
        access = 0;
    }
    barrier(cmd_, image, VK_IMAGE_ASPECT_COLOR_BIT, layout, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, stage, access,
            VK_PIPELINE_STAGE_2_NONE, 0);
    return true;
}

}  // namespace m3g::vk
