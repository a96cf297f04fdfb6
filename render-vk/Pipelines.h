// The uber program's layouts and its pipelines, one per frame::PipelineKey
// (frame/PipelineKey.h: blending, write mask, sample count, and the shader
// features a draw uses, compiled in as specialization constants). All other
// fixed-function state is uniform data or Vulkan 1.3 dynamic state.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include <m3g/frame/PipelineKey.h>

#include "Context.h"

namespace m3g::vk {

using frame::PipelineKey;

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
    /// Creates those of `keys` that do not exist yet, several at once when
    /// more than one is missing (one thread each, up to the hardware
    /// threads): a first frame's states, or prewarm()'s, compile side by
    /// side instead of one after another. get() then finds them.
    void createMissing(std::span<const PipelineKey> keys);
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
    /// The pipeline for `key`, counted in the Context's statistics only:
    /// safe to call from several threads at once (the device and the
    /// pipeline cache are; nothing of this object changes).
    VkPipeline build(const PipelineKey& key) const;
    void destroy(VkPipeline pipeline) noexcept;
    /// Writes the VkPipelineCache to cachePath_ when pipelines were created
    /// since the last save (PipelineCacheFile.h).
    void saveCache() noexcept;

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
    /// The cache file (seeded from it at construction), "" for none.
    std::string cachePath_;
    /// The bytes the file holds (as read at construction or last written).
    std::vector<std::uint8_t> onDisk_;
    std::size_t unsaved_ = 0;
    std::chrono::steady_clock::time_point lastSave_{};
    std::unordered_map<std::uint64_t, Entry> pipelines_;
};

}  // namespace m3g::vk
