// Shader invocation counting for one renderer's frames
// (m3g::vk::setShaderInvocationCounting): a pipeline-statistics query around
// the frame's command buffer, read after the frame's fence into the
// context's counters (RenderStats).
#pragma once

#include "Context.h"

namespace m3g::vk {

class ShaderCounter {
public:
    explicit ShaderCounter(Context& ctx) noexcept : ctx_(ctx) {}
    ~ShaderCounter();

    /// Before the frame's first command that can draw, outside any
    /// rendering: makes the query pool if needed (throws VulkanError) and
    /// decides whether this frame is counted (counting on and supported).
    void prepare();
    /// Records the query's reset and begin when this frame is counted.
    void begin(VkCommandBuffer cmd) noexcept;
    /// Records the query's end, after the frame's rendering has ended.
    void end(VkCommandBuffer cmd) noexcept;
    /// After the frame's fence: adds the frame's invocations to the
    /// context's counters.
    void collect();

    ShaderCounter(const ShaderCounter&) = delete;
    ShaderCounter& operator=(const ShaderCounter&) = delete;

private:
    Context& ctx_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    // The open frame is counted: decided at prepare(), its query recorded by
    // begin() (the renderer opens every frame it prepares before ending it),
    // cleared by collect().
    bool counting_ = false;
};

}  // namespace m3g::vk
