// Records prepared draws into a frame's command buffer, skipping state that
// is already set (pipeline, cull mode, front face, depth test, write and
// bias, texture descriptor set). Only vkCmd* calls: recording cannot fail,
// allocate GPU objects or wait.
#pragma once

#include <cstdint>

#include "Context.h"
#include "PreparedDraw.h"

namespace m3g::vk {

class Recorder {
public:
    /// A new command buffer (or a new frame in it): no state known.
    void reset(VkCommandBuffer cmd, VkPipelineLayout layout, bool hasDepth) noexcept;
    /// Records `draw`; a quad (no index buffer) draws without culling.
    void record(const PreparedDraw& draw) noexcept;
    /// Viewport (with depth range) and scissor.
    void setViewport(const VkViewport& viewport, const VkRect2D& scissor) noexcept;
    VkCommandBuffer commandBuffer() const noexcept { return cmd_; }

private:
    void setDepthState(bool test, bool write, float factor, float units) noexcept;

    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    bool hasDepth_ = true;
    std::uint64_t boundPipeline_ = ~0ull;
    int cull_ = -1, frontFace_ = -1, depthTest_ = -1, depthWrite_ = -1, biasEnabled_ = -1;
    float biasFactor_ = 0.0f, biasUnits_ = 0.0f;
    VkDescriptorSet boundTextures_ = VK_NULL_HANDLE;
};

}  // namespace m3g::vk
