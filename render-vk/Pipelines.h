// The uber program's layouts and its pipelines. A pipeline is identified by
// a small key (guide §5: blend mode, colour write mask, sample count); all
// other fixed-function state is uniform data or Vulkan 1.3 dynamic state.
#pragma once

#include <cstddef>
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
    /// Per texture unit: its function (DrawUniforms.h TexFunc, 0 = off) and
    /// its image's channels (bit 0 colour, bit 1 alpha).
    std::uint8_t texFunc[2] = {0, 0};
    std::uint8_t texFormat[2] = {0, 0};
    /// Per texture unit, 1: the texture matrix is projective (bottom row not
    /// 0, 0, 0, 1), so the fragment shader divides s and t by q.
    std::uint8_t texProjective[2] = {0, 0};
    std::uint8_t fog = 0;   ///< 1: fog applied
    std::uint8_t flat = 0;  ///< 1: SHADE_FLAT
    /// Bit 0 lighting, bit 1 two-sided lighting (m3g.vert, and m3g.frag's
    /// choice of back-face colours).
    std::uint8_t lighting = 0;
    /// With lighting, m3g.vert's lights: how many (0..8), each one's mode
    /// (light i in bits 2i..2i+1: 0 ambient, 1 directional, 2 omni, 3 spot)
    /// and whether the material's specular colour is not black. A light's
    /// mode is compiled in instead of branched on (llvmpipe ran every mode's
    /// code for every light: the vertex stage of midpath robot.m3g).
    std::uint8_t lightCount = 0;
    std::uint16_t lightModes = 0;
    std::uint8_t specular = 0;
    std::uint64_t packed() const noexcept {
        auto at = [](std::uint64_t v, int bit) { return v << bit; };
        return at(blend, 0) | at(writeMask, 4) | at(samples, 8) | at(wireframe, 16) | at(discard, 17) |
               at(texFunc[0], 18) | at(texFunc[1], 21) | at(texFormat[0], 24) | at(texFormat[1], 26) | at(fog, 28) |
               at(flat, 29) | at(lighting, 30) | at(lightCount, 32) | at(lightModes, 36) | at(specular, 52) |
               at(texProjective[0], 53) | at(texProjective[1], 54);
    }
};

/// A renderer's pipelines, created on first use and kept while they are
/// among the `capacity` most recently used. The key space is large (blend x
/// write mask x texture units x fog x up to 8 lights' modes): a long-lived
/// viewer that opens many files would otherwise keep every combination it
/// ever drew. Real scenes use a few dozen keys (prewarm makes 40).
class Pipelines {
public:
    static constexpr std::size_t kDefaultCapacity = 256;

    /// `capacity` >= 1: pipelines kept between frames (a single frame may
    /// use more; none of those is destroyed before the frame has ended).
    explicit Pipelines(Context& ctx, std::size_t capacity = kDefaultCapacity);
    ~Pipelines();

    VkPipelineLayout layout() const noexcept { return layout_; }
    VkDescriptorSetLayout uniformSetLayout() const noexcept { return uniformSet_; }
    VkDescriptorSetLayout textureSetLayout() const noexcept { return textureSet_; }

    /// The pipeline for `key`, created on first use; marked used by the
    /// current frame. Valid until endFrame() of a later frame.
    VkPipeline get(const PipelineKey& key);
    /// Creates the pipelines of the common keys ahead of the first frame.
    void prewarm(std::uint8_t samples);
    /// Called once the GPU has finished the frame (its fence waited): when
    /// more than capacity() pipelines exist, destroys the least recently
    /// used ones that this frame did not use, down to capacity(). Then a new
    /// frame begins.
    void endFrame();
    std::size_t size() const noexcept { return pipelines_.size(); }
    std::size_t capacity() const noexcept { return capacity_; }
    /// How many times endFrame() has replaced the VkPipelineCache.
    std::size_t cacheResets() const noexcept { return cacheResets_; }

    Pipelines(const Pipelines&) = delete;
    Pipelines& operator=(const Pipelines&) = delete;

private:
    struct Entry {
        VkPipeline pipeline = VK_NULL_HANDLE;
        std::uint64_t lastFrame = 0;
    };
    VkPipeline create(const PipelineKey& key);
    void destroy(VkPipeline pipeline) noexcept;

    Context& ctx_;
    std::size_t capacity_;
    std::uint64_t frame_ = 1;
    /// Pipelines created through cache_ since it was (re)created: the
    /// VkPipelineCache keeps every shader variant it has seen, so it is
    /// replaced after evictions once it has seen several capacities' worth.
    std::size_t createdThroughCache_ = 0;
    std::size_t cacheResets_ = 0;
    VkDescriptorSetLayout uniformSet_ = VK_NULL_HANDLE, textureSet_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkShaderModule vert_ = VK_NULL_HANDLE, frag_ = VK_NULL_HANDLE;
    VkPipelineCache cache_ = VK_NULL_HANDLE;
    std::unordered_map<std::uint64_t, Entry> pipelines_;
};

}  // namespace m3g::vk
