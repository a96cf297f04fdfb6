#include "Recorder.h"

namespace m3g::vk {

void Recorder::reset(VkCommandBuffer cmd, VkPipelineLayout layout, bool hasDepth) noexcept {
    cmd_ = cmd;
    layout_ = layout;
    hasDepth_ = hasDepth;
    boundPipeline_ = ~0ull;
    cull_ = frontFace_ = depthTest_ = depthWrite_ = biasEnabled_ = -1;
    biasFactor_ = biasUnits_ = 0.0f;
    boundTextures_ = VK_NULL_HANDLE;
}

void Recorder::setViewport(const VkViewport& viewport, const VkRect2D& scissor) noexcept {
    vkCmdSetViewport(cmd_, 0, 1, &viewport);
    vkCmdSetScissor(cmd_, 0, 1, &scissor);
}

void Recorder::setDepthState(bool test, bool write, float factor, float units) noexcept {
    // A disabled depth test is ALWAYS, so depth is still written (as Nokia's
    // M3G implementation does; docs/rendering.md).
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

void Recorder::record(const PreparedDraw& d) noexcept {
    if (boundPipeline_ != d.pipelineKey) {
        vkCmdBindPipeline(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, d.pipeline);
        boundPipeline_ = d.pipelineKey;
    }
    const frame::RasterState& r = d.raster;
    const bool quad = d.indexBuffer == VK_NULL_HANDLE;
    setDepthState(r.depthTest != 0, r.depthWrite != 0, r.depthOffsetFactor, r.depthOffsetUnits);
    if (r.cull != cull_) {
        vkCmdSetCullMode(cmd_, r.cull == 0 ? VK_CULL_MODE_NONE : r.cull == 1 ? VK_CULL_MODE_FRONT_BIT : VK_CULL_MODE_BACK_BIT);
        cull_ = r.cull;
    }
    // A quad is not culled, so its winding only needs to be defined.
    if (quad ? frontFace_ == -1 : r.clockwise != frontFace_) {
        const int front = quad ? 0 : r.clockwise;
        vkCmdSetFrontFace(cmd_, front ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE);
        frontFace_ = front;
    }
    vkCmdBindDescriptorSets(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &d.uniforms, 1, &d.uniformOffset);
    if (d.textures != boundTextures_) {
        vkCmdBindDescriptorSets(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 1, 1, &d.textures, 0, nullptr);
        boundTextures_ = d.textures;
    }
    vkCmdBindVertexBuffers2(cmd_, 0, frame::STREAM_COUNT, d.buffers.data(), d.offsets.data(), nullptr, d.strides.data());
    if (quad) {
        vkCmdDraw(cmd_, d.count, 1, 0, 0);
    } else {
        vkCmdBindIndexBuffer(cmd_, d.indexBuffer, 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexed(cmd_, d.count, 1, 0, 0, 0);
    }
}

}  // namespace m3g::vk
