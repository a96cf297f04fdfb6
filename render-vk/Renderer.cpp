#include "Renderer.h"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <string>

#include <m3g/frame/UniformHelpers.h>
#include <m3g/vk/Vulkan.h>

#include "FrameWait.h"

namespace m3g::vk {

namespace {

/// Floats per vertex of each stream in a VertexMirror, in bytes.
constexpr VkDeviceSize kStreamStrides[frame::STREAM_COUNT] = {12, 12, 16, 12, 12};

}  // namespace

Renderer::Renderer() : ctx_(Context::shared()), target_(*ctx_), counter_(*ctx_) {
    pipelines_ = std::make_unique<Pipelines>(*ctx_);
    resources_ = std::make_unique<ResourceCache>(*ctx_, pipelines_->textureSetLayout());
    streams_ = std::make_unique<StreamBuffers>(*ctx_, pipelines_->uniformSetLayout());
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    check(vkCreateFence(ctx_->device(), &fi, nullptr, &fence_), "vkCreateFence");
    // A pool of this renderer's own: renderers on different threads record concurrently.
    commandPool_ = ctx_->createCommandPool();
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = commandPool_;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(ctx_->device(), &ai, &cmd_), "vkAllocateCommandBuffers");
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
    ctx_->waitIdle();
    resources_.reset();
    streams_.reset();
    vkDestroyFence(ctx_->device(), fence_, nullptr);
    vkDestroyCommandPool(ctx_->device(), commandPool_, nullptr);  // frees cmd_
}

frame::DrawOptions Renderer::options() const noexcept {
    const DebugView debug = debugView();
    frame::DrawOptions o;
    o.wireframe = debug.wireframe;
    o.unlit = debug.unlit;
    o.clampLit = litColorClamping();
    o.vulkanClipSpace = true;
    return o;
}

// ---- Prepare ----

void Renderer::startFrame(const frame::Target& target) {
    if (started_) return;
    if (target_.prepare(target)) resources_->forgetTextureSets();  // they may name the old prior image
    resources_->beginFrame();
    streams_->beginFrame();
    lastKey_ = ~0ull;  // pipelines may have been evicted at the last frame's end
    if (target_.samples() != VK_SAMPLE_COUNT_1_BIT) preparePrior();
    counter_.prepare();
    started_ = true;
}

void Renderer::preparePrior() {
    frame::DrawUniforms u;
    frame::quadUniforms(u, frame::TEX_REPLACE, true, true, true);
    frame::PipelineKey key = frame::pipelineFeatures(u);
    key.samples = static_cast<std::uint8_t>(target_.samples());
    prior_ = PreparedDraw{};
    prior_.pipelineKey = key.packed();
    prior_.pipeline = pipelines_->get(key);
    streams_->uniforms(u, prior_.uniforms, prior_.uniformOffset);
    prior_.textures = resources_->textureSet(&target_.priorImage(), resources_->sampler(frame::kNearestClampSampler), nullptr,
                                             VK_NULL_HANDLE);
    bindQuad(frame::Quad{}, prior_);  // the whole target, texture coordinates 0..1
    prior_.raster.cull = 0;
    prior_.raster.depthTest = prior_.raster.depthWrite = 0;
}

void Renderer::bindQuad(const frame::Quad& quad, PreparedDraw& p) {
    // Six vertices of position xyz and texture coordinates st (+ pad): the
    // position and first texture coordinate streams read the same buffer.
    VkDeviceSize offset = 0;
    const VkBuffer quads = streams_->quad(quad, offset);
    p.buffers = {quads, streams_->dummy(), streams_->dummy(), quads, streams_->dummy()};
    p.offsets = {offset, 0, 0, offset + 3 * sizeof(float), 0};
    p.strides = {6 * sizeof(float), 0, 0, 6 * sizeof(float), 0};
    p.indexBuffer = VK_NULL_HANDLE;
    p.count = 6;
}

void Renderer::prepare(const frame::Draw& d, const frame::DrawList& list, frame::FrameSources& sources,
                       PreparedDraw& p) {
    frame::PipelineKey key = d.pipeline;
    key.samples = static_cast<std::uint8_t>(target_.samples());
    p.pipelineKey = key.packed();
    if (p.pipelineKey != lastKey_) {
        lastPipeline_ = pipelines_->get(key);
        lastKey_ = p.pipelineKey;
    }
    p.pipeline = lastPipeline_;
    p.raster = d.raster;
    streams_->uniforms(list.uniforms[d.uniforms], p.uniforms, p.uniformOffset);
    const Image* images[2] = {nullptr, nullptr};
    VkSampler samplers[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
    for (int unit = 0; unit < 2; ++unit) {
        const frame::TextureRef& t = d.textures[static_cast<std::size_t>(unit)];
        if (!t.id) continue;
        images[unit] = &resources_->texture(t, sources);
        samplers[unit] = resources_->sampler(t.sampler);
    }
    p.textures = resources_->textureSet(images[0], samplers[0], images[1], samplers[1]);
    if (d.kind == frame::Draw::Kind::Quad) {
        bindQuad(d.quad, p);
        return;
    }
    const VertexMirror& vm = resources_->vertices(d.vertices, sources);
    for (std::size_t i = 0; i < frame::STREAM_COUNT; ++i) {
        p.buffers[i] = vm.present[i] ? vm.buffer.buffer : streams_->dummy();
        p.offsets[i] = vm.present[i] ? vm.offsets[i] : 0;
        p.strides[i] = vm.present[i] ? kStreamStrides[i] : 0;
    }
    const IndexMirror& im = resources_->indices(d.indices, sources);
    p.indexBuffer = im.buffer.buffer;
    p.count = im.count;
}

// ---- Record ----

void Renderer::openFrame(const frame::Target& target, const float* clearColor, bool covered) {
    if (recording_) return;
    vkResetCommandBuffer(cmd_, 0);
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cmd_, &bi), "vkBeginCommandBuffer");
    target_.begin(cmd_, target, clearColor, covered);
    counter_.begin(cmd_);
    recorder_.reset(cmd_, pipelines_->layout(), target_.hasDepth());
    recording_ = true;
    renderingOpen_ = false;
}

void Renderer::openRendering() noexcept {
    if (renderingOpen_) return;
    renderingOpen_ = true;
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = {{0, 0}, {target_.width(), target_.height()}};
    ri.layerCount = 1;
    ri.colorAttachmentCount = 1;
    ri.pColorAttachments = &target_.colorAttachment();
    ri.pDepthAttachment = &target_.depthAttachment();
    vkCmdBeginRendering(cmd_, &ri);
    if (target_.drawPrior()) {
        target_.setDrawPrior(false);
        // The prior contents, drawn over the whole target into every sample;
        // then the view of the command that opened the rendering.
        const VkViewport whole{0, 0, static_cast<float>(target_.width()), static_cast<float>(target_.height()), 0.0f,
                               1.0f};
        recorder_.setViewport(whole, {{0, 0}, {target_.width(), target_.height()}});
        recorder_.record(prior_);
        ++ctx_->draws;
        recorder_.setViewport(viewport_, scissor_);
    }
}

void Renderer::setView(const frame::ViewState& view) noexcept {
    viewport_ = {static_cast<float>(view.viewport.x), static_cast<float>(view.viewport.y),
                 static_cast<float>(view.viewport.w), static_cast<float>(view.viewport.h), view.depthNear, view.depthFar};
    scissor_ = {{view.scissor.x, view.scissor.y},
                {static_cast<std::uint32_t>(view.scissor.w), static_cast<std::uint32_t>(view.scissor.h)}};
    if (!view.scissor.empty()) recorder_.setViewport(viewport_, scissor_);
}

// ---- The back end's calls ----

void Renderer::clear(const frame::Target& target, const frame::ViewState& view, const frame::DrawList& list,
                     frame::FrameSources& sources) {
    const frame::Clear& c = list.clear;
    startFrame(target);
    const bool drawImage = c.hasImage && !view.scissor.empty();
    PreparedDraw image;
    if (drawImage) prepare(c.image, list, sources, image);

    // Until the rendering opens (the frame's first draw), a clear of every
    // pixel's colour is the colour attachment's load operation (none when the
    // image covers every pixel anyway), and a depth clear is moot: the depth
    // attachment loads as far. vkCmdClearAttachments costs lavapipe a fill of
    // the image on its submitting thread, after the tile clears of the load
    // operations (measured: ~40% of an empty 1280x960 frame's CPU time).
    const bool drawn = recording_ && renderingOpen_;
    const bool asLoadOp = !drawn && c.color && c.wholeTarget;
    if (recording_ && asLoadOp) {  // nothing drawn yet: the prior contents are moot
        VkRenderingAttachmentInfo& color = target_.colorAttachment();
        color.loadOp = c.imageCovers ? VK_ATTACHMENT_LOAD_OP_DONT_CARE : VK_ATTACHMENT_LOAD_OP_CLEAR;
        std::memcpy(color.clearValue.color.float32, c.rgba, sizeof(c.rgba));
        target_.setDrawPrior(false);
    }
    openFrame(target, asLoadOp && !c.imageCovers ? c.rgba : nullptr, asLoadOp);
    setView(view);
    if (view.scissor.empty()) return;
    // An application's depth image is loaded, not cleared: a depth clear of
    // the whole target before the first draw becomes its load operation,
    // any other is recorded.
    if (!drawn && c.depth && c.wholeTarget && target_.hasDepth() && target_.depthLoaded())
        target_.depthAttachment().loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;  // its clear value is far
    const bool clearDepth = c.depth && target_.hasDepth() && (drawn || target_.depthLoaded());
    const VkClearRect rect{scissor_, 0, 1};
    VkClearAttachment attachments[2]{};
    std::uint32_t count = 0;
    if (c.color && !asLoadOp && !c.imageCovers) {
        attachments[count].aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
        attachments[count].colorAttachment = 0;
        std::memcpy(attachments[count].clearValue.color.float32, c.rgba, sizeof(c.rgba));
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
    if (drawImage) {
        openRendering();
        recorder_.record(image);
        ++ctx_->draws;
    }
}

void Renderer::draw(const frame::Target& target, const frame::ViewState& view, const frame::DrawList& list,
                    frame::FrameSources& sources) {
    startFrame(target);
    prepared_.resize(view.scissor.empty() ? 0 : list.draws.size());
    // The states this list meets for the first time, created side by side.
    drawKeys_.resize(prepared_.size());
    for (std::size_t i = 0; i < prepared_.size(); ++i) {
        drawKeys_[i] = list.draws[i].pipeline;
        drawKeys_[i].samples = static_cast<std::uint8_t>(target_.samples());
    }
    pipelines_->createMissing(drawKeys_);
    for (std::size_t i = 0; i < prepared_.size(); ++i) prepare(list.draws[i], list, sources, prepared_[i]);
    openFrame(target, nullptr, false);
    setView(view);
    for (const PreparedDraw& p : prepared_) {
        if (p.count == 0) continue;
        openRendering();  // before any state below: drawing the prior contents changes it
        recorder_.record(p);
        ++ctx_->draws;
    }
}

void Renderer::release(const frame::Target& target, std::span<const std::uint64_t> released) {
    if (!recording_) {
        // Nothing in flight: the copies of released objects can go now.
        resources_->release(released);
        resources_->endFrame();
        target_.endFrame();
        started_ = false;
        return;
    }
    recording_ = false;
    started_ = false;
    openRendering();  // a frame of clears only: their load operation
    vkCmdEndRendering(cmd_);
    counter_.end(cmd_);
    const FrameTarget::Ending ending = target_.finish(cmd_);
    check(vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");
    vkResetFences(ctx_->device(), 1, &fence_);
    // The frame's uploads and compute deformations first, in the same batch:
    // their closing barriers order them before the draws' reads.
    VkCommandBuffer cmds[3];
    std::size_t n = 0;
    if (VkCommandBuffer uploads = resources_->finishUploads()) cmds[n++] = uploads;
    if (VkCommandBuffer compute = resources_->finishCompute()) cmds[n++] = compute;
    cmds[n++] = cmd_;
    // The frame's fixed cost, split for RenderStats (m3g bench render's
    // columns): the submit and the wait for the device, then the read-back.
    using Clock = std::chrono::steady_clock;
    auto nanos = [](Clock::duration d) {
        return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(d).count());
    };
    const Clock::time_point submitted = Clock::now();
    target_.submit({cmds, n}, fence_, ending);
    check(waitForFence(ctx_->device(), fence_, fenceSpinMicros()), "vkWaitForFences (frame)");
    ctx_->frameWaitNanos += nanos(Clock::now() - submitted);
    ++ctx_->frames;
    counter_.collect();
    resources_->release(released);
    resources_->endFrame();
    pipelines_->endFrame();
    streams_->endFrame();
    const Clock::time_point finished = Clock::now();
    if (target_.writeBack(target, ending)) ctx_->readBackNanos += nanos(Clock::now() - finished);
}

}  // namespace m3g::vk
