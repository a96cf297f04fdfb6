// The Vulkan back end of Graphics3D (frame::FrameBackend). For each clear or
// render call it first prepares the call's DrawList (uploads what is stale,
// deforms on the GPU, looks up or creates pipelines and descriptor sets:
// anything that can fail or allocate), then records it with Recorder,
// which can do neither. One command buffer per bound target, opened at the
// first call and submitted at releaseTarget together with the frame's
// upload and compute commands; the pixels are then read back into the bound
// Image2D or Graphics, or a window's image is presented.
#pragma once

#include <memory>
#include <vector>

#include <m3g/frame/FrameBackend.h>

#include "Context.h"
#include "FrameTarget.h"
#include "Pipelines.h"
#include "PreparedDraw.h"
#include "Recorder.h"
#include "ResourceCache.h"
#include "ShaderCounter.h"
#include "StreamBuffers.h"

namespace m3g::vk {

class Renderer final : public frame::FrameBackend {
public:
    Renderer();
    ~Renderer() override;

    frame::DrawOptions options() const noexcept override;
    void clear(const frame::Target& target, const frame::ViewState& view, const frame::DrawList& list,
               frame::FrameSources& sources) override;
    void draw(const frame::Target& target, const frame::ViewState& view, const frame::DrawList& list,
              frame::FrameSources& sources) override;
    void release(const frame::Target& target, std::span<const std::uint64_t> released) override;

    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

private:
    // ---- Prepare (may create GPU objects, upload, throw) ----
    /// The frame's images and streaming memory, unless a frame is open.
    void startFrame(const frame::Target& target);
    void prepare(const frame::Draw& draw, const frame::DrawList& list, frame::FrameSources& sources,
                 PreparedDraw& out);
    /// The multisampled frame's prior-contents quad.
    void preparePrior();
    /// The vertices of `quad` in the frame's quad memory, bound as `p`'s streams.
    void bindQuad(const frame::Quad& quad, PreparedDraw& p);

    // ---- Record (vkCmd* only) ----
    /// Opens the command buffer and the target's images (FrameTarget::begin)
    /// unless a frame is open.
    void openFrame(const frame::Target& target, const float* clearColor, bool covered);
    /// Begins the rendering unless it is open; draws the prior contents into
    /// a multisampled target first.
    void openRendering() noexcept;
    void setView(const frame::ViewState& view) noexcept;

    std::shared_ptr<Context> ctx_;
    std::unique_ptr<Pipelines> pipelines_;
    std::unique_ptr<ResourceCache> resources_;
    std::unique_ptr<StreamBuffers> streams_;
    FrameTarget target_;
    Recorder recorder_;
    ShaderCounter counter_;  // shader invocation counting, when on
    VkCommandPool commandPool_ = VK_NULL_HANDLE;  // this renderer's own (threading.md)
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    bool started_ = false;        // startFrame done for the open frame
    bool recording_ = false;      // cmd_ begun
    bool renderingOpen_ = false;  // vkCmdBeginRendering recorded
    VkViewport viewport_{};
    VkRect2D scissor_{};
    std::vector<PreparedDraw> prepared_;
    std::vector<frame::PipelineKey> drawKeys_;  // draw()'s scratch: the list's pipeline keys
    PreparedDraw prior_;  // the prior contents' quad of a multisampled frame
    // The pipeline of the previous draw prepared in this frame: consecutive
    // draws mostly share it, and it is already marked used by the frame.
    std::uint64_t lastKey_ = ~0ull;
    VkPipeline lastPipeline_ = VK_NULL_HANDLE;
};

}  // namespace m3g::vk
