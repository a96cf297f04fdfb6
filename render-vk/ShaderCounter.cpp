#include "ShaderCounter.h"

#include <m3g/vk/Vulkan.h>

namespace m3g::vk {

namespace {
// Results come in the order of the flags' bits: vertex (bit 2), then fragment (bit 7).
constexpr VkQueryPipelineStatisticFlags kCounted = VK_QUERY_PIPELINE_STATISTIC_VERTEX_SHADER_INVOCATIONS_BIT |
                                                   VK_QUERY_PIPELINE_STATISTIC_FRAGMENT_SHADER_INVOCATIONS_BIT;
}  // namespace

ShaderCounter::~ShaderCounter() {
    if (pool_) vkDestroyQueryPool(ctx_.device(), pool_, nullptr);
}

void ShaderCounter::prepare() {
    counting_ = shaderInvocationCounting() && ctx_.pipelineStatisticsSupported();
    if (!counting_ || pool_) return;
    VkQueryPoolCreateInfo qi{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    qi.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
    qi.queryCount = 1;
    qi.pipelineStatistics = kCounted;
    check(vkCreateQueryPool(ctx_.device(), &qi, nullptr, &pool_), "vkCreateQueryPool");
}

void ShaderCounter::begin(VkCommandBuffer cmd) noexcept {
    if (!counting_) return;
    vkCmdResetQueryPool(cmd, pool_, 0, 1);
    vkCmdBeginQuery(cmd, pool_, 0, 0);
}

void ShaderCounter::end(VkCommandBuffer cmd) noexcept {
    if (counting_) vkCmdEndQuery(cmd, pool_, 0);
}

void ShaderCounter::collect() {
    if (!counting_) return;
    counting_ = false;
    std::uint64_t counts[2] = {0, 0};
    check(vkGetQueryPoolResults(ctx_.device(), pool_, 0, 1, sizeof(counts), counts, sizeof(counts),
                                VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
          "vkGetQueryPoolResults");
    ++ctx_.countedFrames;
    ctx_.vertexInvocations += counts[0];
    ctx_.fragmentInvocations += counts[1];
}

}  // namespace m3g::vk
