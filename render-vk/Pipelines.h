// The uber program's layouts and its pipelines. A pipeline is identified by
// a small key (guide §5: blend mode, colour write mask, sample count); all
// other fixed-function state is uniform data or Vulkan 1.3 dynamic state.
#pragma once

#include <cstdint>
#include <unordered_map>

#include "Context.h"

namespace m3g::vk {

struct PipelineKey {
    std::uint8_t blend = 0;      ///< 0 REPLACE, 1 ALPHA, 2 ALPHA_ADD, 3 MODULATE, 4 MODULATE_X2
    std::uint8_t writeMask = 0xF;  ///< VkColorComponentFlags
    std::uint8_t samples = 1;
    std::uint8_t wireframe = 0;  ///< 1: polygon mode LINE (DebugView)
    /// 1: the fragment shader keeps its discards (alpha threshold, Background
    /// BORDER). Without them a rasteriser can test depth before shading
    /// (llvmpipe does), so only draws that need them pay for late depth.
    std::uint8_t discard = 0;
    std::uint32_t packed() const noexcept {
        return blend | (writeMask << 4) | (samples << 8) | (static_cast<std::uint32_t>(wireframe) << 16) |
               (static_cast<std::uint32_t>(discard) << 17);
    }
};

class Pipelines {
public:
    explicit Pipelines(Context& ctx);
    ~Pipelines();

    VkPipelineLayout layout() const noexcept { return layout_; }
    VkDescriptorSetLayout uniformSetLayout() const noexcept { return uniformSet_; }
    VkDescriptorSetLayout textureSetLayout() const noexcept { return textureSet_; }

    /// The pipeline for `key`, created on first use.
    VkPipeline get(const PipelineKey& key);
    /// Creates the pipelines of the common keys ahead of the first frame.
    void prewarm(std::uint8_t samples);
    std::size_t size() const noexcept { return pipelines_.size(); }

    Pipelines(const Pipelines&) = delete;
    Pipelines& operator=(const Pipelines&) = delete;

private:
    VkPipeline create(const PipelineKey& key);

    Context& ctx_;
    VkDescriptorSetLayout uniformSet_ = VK_NULL_HANDLE, textureSet_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkShaderModule vert_ = VK_NULL_HANDLE, frag_ = VK_NULL_HANDLE;
    VkPipelineCache cache_ = VK_NULL_HANDLE;
    std::unordered_map<std::uint32_t, VkPipeline> pipelines_;
};

}  // namespace m3g::vk
