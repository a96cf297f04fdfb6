// One ComputeDeformer on the shared device, driven by one-shot submits, with
// an output buffer the host reads back: the compute path's harness, shared by
// the agreement tests (tests/vk/test_ComputeSkinning.cpp) and `m3g bench
// skin|morph` (tools/m3g/ComputeBench.cpp). Reaches into render-vk's internals,
// so its users add render-vk to their include path and link volk_static.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ComputeDeformer.h"
#include "Context.h"

namespace m3gbench {

class ComputeRunner {
public:
    /// `timed`: also measure the device time of each run() with timestamp
    /// queries, when the queue supports them (lastDispatchSeconds()).
    explicit ComputeRunner(m3g::vk::Context& context, bool timed = false) : ctx(context), deformer(context) {
        if (!timed) return;
        std::uint32_t families = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice(), &families, nullptr);
        std::vector<VkQueueFamilyProperties> props(families);
        vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice(), &families, props.data());
        if (ctx.properties().limits.timestampPeriod > 0 && props[ctx.queueFamily()].timestampValidBits > 0) {
            VkQueryPoolCreateInfo qi{};
            qi.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
            qi.queryType = VK_QUERY_TYPE_TIMESTAMP;
            qi.queryCount = 2;
            m3g::vk::check(vkCreateQueryPool(ctx.device(), &qi, nullptr, &timestamps_), "vkCreateQueryPool");
        }
    }
    ~ComputeRunner() {
        vkDeviceWaitIdle(ctx.device());
        deformer.release(state);
        deformer.endFrame();
        ctx.destroy(out);
        if (timestamps_) vkDestroyQueryPool(ctx.device(), timestamps_, nullptr);
    }
    ComputeRunner(const ComputeRunner&) = delete;
    ComputeRunner& operator=(const ComputeRunner&) = delete;

    /// `out` holds at least `floats` floats (host-visible storage buffer).
    void ensureOutput(std::size_t floats) {
        if (out.buffer && out.size >= floats * sizeof(float)) return;
        ctx.destroy(out);
        out = ctx.createHostBuffer(floats * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    }

    /// Records `record(cmd)` with a barrier making the output host-readable,
    /// submits, waits, and ends the deformer's frame.
    template <class Record>
    void run(Record&& record) {
        ctx.submitNow([&](VkCommandBuffer cmd) {
            if (timestamps_) {
                vkCmdResetQueryPool(cmd, timestamps_, 0, 2);
                vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, timestamps_, 0);
            }
            record(cmd);
            if (timestamps_) vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, timestamps_, 1);
            m3g::vk::ComputeDeformer::barrier(cmd, VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        });
        deformer.endFrame();
        lastDispatchSeconds_ = -1.0;
        std::uint64_t ticks[2];
        if (timestamps_ && vkGetQueryPoolResults(ctx.device(), timestamps_, 0, 2, sizeof(ticks), ticks,
                                                 sizeof(std::uint64_t),
                                                 VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS)
            lastDispatchSeconds_ =
                static_cast<double>(ticks[1] - ticks[0]) * ctx.properties().limits.timestampPeriod * 1e-9;
    }

    const float* floats() const { return static_cast<const float*>(out.mapped); }
    /// Device time of the last run()'s commands, or -1 when not timed.
    double lastDispatchSeconds() const { return lastDispatchSeconds_; }

    m3g::vk::Context& ctx;
    m3g::vk::ComputeDeformer deformer;
    m3g::vk::GpuDeformState state;
    m3g::vk::Buffer out;

private:
    VkQueryPool timestamps_ = VK_NULL_HANDLE;
    double lastDispatchSeconds_ = -1.0;
};

}  // namespace m3gbench
