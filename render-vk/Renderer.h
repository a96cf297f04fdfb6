// The Vulkan implementation of Graphics3D's drawing (detail::RenderBackend):
// one command buffer per bound target, opened at the first clear/render and
// submitted at releaseTarget, when the pixels are read back into the bound
// Image2D or Graphics surface.
#pragma once

#include <memory>
#include <vector>

#include "Context.h"
#include "DrawUniforms.h"
#include "Pipelines.h"
#include "RenderBackend.h"
#include "ResourceCache.h"

namespace m3g {
class Appearance;
class Image2D;
}

namespace m3g::detail {
struct RenderItem;
}

namespace m3g::vk {

class WindowTarget;

class Renderer final : public detail::RenderBackend {
public:
    Renderer();
    ~Renderer() override;

    void clear(Graphics3D& g3d, const Background* background) override;
    void render(Graphics3D& g3d, const detail::RenderQueue& queue) override;
    void release(Graphics3D& g3d) override;

private:
    struct Rect {
        int x = 0, y = 0, w = 0, h = 0;
    };
    struct UniformChunk {
        Buffer buffer;
        VkDescriptorSet set = VK_NULL_HANDLE;
    };

    /// Opens the frame's command buffer. `covered`: the first command writes
    /// every pixel, so the prior contents need not be loaded; `clearColor`
    /// (implies covered): that command is a clear to this colour, made the
    /// colour attachment's load operation.
    void begin(Graphics3D& g3d, const float* clearColor = nullptr, bool covered = false);
    /// Begins the frame's rendering (dynamic rendering with the attachments
    /// begin() prepared) unless it is open; draws the prior contents into a
    /// multisampled target first.
    void openRendering();
    /// Records viewport_, scissor_ and the depth range.
    void setViewportState();
    /// The viewport (translated by the Graphics origin) and the pixels a
    /// draw may touch: viewport ∩ Graphics clip ∩ target.
    static Rect drawArea(const Graphics3D& g3d, Rect& viewport);
    /// Records the copy of the frame into an acquired swapchain image, the
    /// overlay and the layout for presenting; false when the window cannot
    /// present now (zero size).
    /// With `readback`, also copies the presented image to transfer_ (reset
    /// to false when the surface's size is not the target's).
    bool recordPresent(WindowTarget& window, bool& readback);
    /// Records the copy of width_ x height_ texels of `image` (in
    /// TRANSFER_SRC layout) into transfer_, visible to the host after the fence.
    void copyToHost(VkImage image);
    void ensureTargetImages(std::uint32_t width, std::uint32_t height, VkSampleCountFlagBits samples);
    void applyViewport(Graphics3D& g3d);
    DrawUniforms& allocUniforms(VkDescriptorSet& set, std::uint32_t& offset);
    void drawSubmesh(const detail::RenderQueue& queue, const detail::RenderItem& item);
    void drawSprite(const detail::RenderQueue& queue, const detail::RenderItem& item);
    /// Uniforms of a screen-space textured quad (sprite, background image,
    /// prior contents): clip-space positions, unit 0 = `tex` with `func`,
    /// white vertex colour, alpha factor 1; also the texture descriptor set.
    DrawUniforms& quadUniforms(const TextureMirror& tex, VkSampler sampler, std::int32_t func, VkDescriptorSet& set,
                               std::uint32_t& offset, VkDescriptorSet& textures);
    /// A textured rectangle in NDC: corners (x0,y0)-(x1,y1), texture coordinates
    /// (s0,t0) at (x0,y1) (top-left) and (s1,t1) at (x1,y0).
    void drawQuad(VkDescriptorSet uniformSet, std::uint32_t offset, VkDescriptorSet textures,
                  const PipelineKey& key, bool depthTest, bool depthWrite, const float rect[4], float z,
                  const float tex[4]);
    void bindPipeline(const PipelineKey& key);
    void setDepthState(bool test, bool write, float factor, float units);
    void fillFog(DrawUniforms& u, const Appearance* app) const;

    std::shared_ptr<Context> ctx_;
    std::unique_ptr<Pipelines> pipelines_;
    std::unique_ptr<ResourceCache> resources_;

    // The bound target's images and the frame being recorded.
    Image color_, depth_;      // single-sampled colour (read back) and depth
    Image* target_ = &color_;  // the colour image of this frame: color_ or a window's back image
    WindowTarget* window_ = nullptr;  // the bound target when it is a window
    DebugView debug_;                 // read at each frame's start
    bool clampLit_ = false;           // litColorClamping(), read at each frame's start
    Image msaaColor_, initial_;  // ANTIALIAS: multisampled colour and the prior contents to start from
    VkSampleCountFlagBits samples_ = VK_SAMPLE_COUNT_1_BIT;
    std::uint32_t width_ = 0, height_ = 0;
    VkCommandPool commandPool_ = VK_NULL_HANDLE;  // this renderer's own (threading.md)
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    bool recording_ = false;
    bool renderingOpen_ = false;  // vkCmdBeginRendering recorded (openRendering)
    bool drawPrior_ = false;      // multisampled: the prior contents are still to be drawn
    VkRenderingAttachmentInfo colorAttachment_{}, depthAttachment_{};  // of the frame, set by begin()
    bool hasDepth_ = true;
    bool computeSkinning_ = false;  // Graphics3D::SKINNING_COMPUTE for the queue being drawn
    Buffer transfer_;  // upload of the target's pixels and read-back
    Rect viewport_, scissor_;
    bool scissorEmpty_ = false;
    float depthNear_ = 0.0f, depthFar_ = 1.0f;
    float projection_[16] = {};  // the queue's projection with the Vulkan fix-up, column major

    // Per-frame streaming data.
    std::vector<UniformChunk> chunks_;
    std::size_t chunk_ = 0;
    std::uint32_t chunkOffset_ = 0;
    std::uint32_t uniformStride_ = 0;
    VkDescriptorPool uniformPool_ = VK_NULL_HANDLE;
    Buffer quads_;
    std::vector<Buffer> retiredQuads_;
    VkDeviceSize quadOffset_ = 0;
    Buffer dummy_;

    // State last set on cmd_, to skip redundant commands.
    std::uint64_t boundPipeline_ = ~0ull;
    int cull_ = -1, frontFace_ = -1, depthTest_ = -1, depthWrite_ = -1;
    float biasFactor_ = 0.0f, biasUnits_ = 0.0f;
    int biasEnabled_ = -1;
    VkDescriptorSet boundTextures_ = VK_NULL_HANDLE;
    std::vector<float> pixelsScratch_;
};

}  // namespace m3g::vk
