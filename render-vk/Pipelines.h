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
    // Fragment-shader features, m3g.frag's specialization constants. A
    // feature a draw does not use is compiled out rather than skipped by a
    // uniform branch: llvmpipe runs both sides of a branch under a lane mask,
    // so a disabled texture unit or fog still cost their full work (measured:
    // ~40% of the rasteriser's CPU time on scene.m3g at 1280x960).
    /// 1: the discards stay (alpha threshold, Background BORDER). Without them
    /// a rasteriser can also test depth before shading (llvmpipe does).
    std::uint8_t discard = 0;
    std::uint8_t textures = 0;  ///< bit 0: unit 0 enabled, bit 1: unit 1
    std::uint8_t fog = 0;       ///< 1: fog applied
    /// Vertex-shader features (m3g.vert): bit 0 lighting, bit 1 two-sided.
    std::uint8_t lighting = 0;
    std::uint32_t packed() const noexcept {
        return blend | (writeMask << 4) | (samples << 8) | (static_cast<std::uint32_t>(wireframe) << 16) |
               (static_cast<std::uint32_t>(discard) << 17) | (static_cast<std::uint32_t>(textures) << 18) |
               (static_cast<std::uint32_t>(fog) << 20) | (static_cast<std::uint32_t>(lighting) << 21);
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
