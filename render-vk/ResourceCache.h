// GPU copies of the resources a DrawList names (vertex streams, triangle
// lists, textures), kept in side tables keyed by object id and refreshed
// when the draw names a newer version: the data comes through
// frame::FrameSources, never from scene objects (scene objects hold no
// Vulkan handles either). Used only while a frame is prepared: uploads of
// textures are recorded into the frame's upload commands (submitted with
// the frame, before its draws), deformations on the GPU into its compute
// commands. Replaced copies and those of released objects are freed once
// the frame that may read them has finished (endFrame).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include <m3g/frame/DrawList.h>
#include <m3g/frame/FrameSources.h>

#include "ComputeDeformer.h"
#include "Context.h"

namespace m3g::vk {

/// Five float streams (frame::Stream order): position (raw, or final for
/// deformed meshes), normal, colour RGBA, texcoord 0, texcoord 1 (raw).
struct VertexMirror {
    Buffer buffer;
    std::array<VkDeviceSize, frame::STREAM_COUNT> offsets{};
    std::array<bool, frame::STREAM_COUNT> present{};
    int vertexCount = 0;
};

struct IndexMirror {
    Buffer buffer;
    std::uint32_t count = 0;
};

class ResourceCache {
public:
    ResourceCache(Context& ctx, VkDescriptorSetLayout textureSetLayout);
    ~ResourceCache();

    /// The streams of `ref`: uploaded from `sources` when the copy is older
    /// than ref.version, or deformed by ComputeDeformer into the copy for
    /// GPU sources (recorded into the frame's compute commands).
    const VertexMirror& vertices(const frame::VertexRef& ref, frame::FrameSources& sources);
    /// The triangle list of `ref`.
    const IndexMirror& indices(const frame::IndexRef& ref, frame::FrameSources& sources);
    /// The RGBA8 image of `ref` (with its mip chain if asked), its upload
    /// recorded into the frame's upload commands when it is new.
    const Image& texture(const frame::TextureRef& ref, frame::FrameSources& sources);
    VkSampler sampler(frame::SamplerKey key);
    /// Descriptor set of two combined image samplers; a null image = white texel.
    VkDescriptorSet textureSet(const Image* t0, VkSampler s0, const Image* t1, VkSampler s1);

    /// The frame's upload and compute commands, ended, to submit before the
    /// draws; VK_NULL_HANDLE where the frame recorded none.
    VkCommandBuffer finishUploads();
    VkCommandBuffer finishCompute() { return compute_ ? compute_->finishFrame() : VK_NULL_HANDLE; }

    /// The objects of `ids` no longer exist: their copies go at endFrame.
    void release(std::span<const std::uint64_t> ids);
    /// Called when the GPU has finished all submitted work: frees replaced
    /// and released copies.
    void endFrame();
    /// Drops every cached texture descriptor set (the GPU must be idle).
    void forgetTextureSets();
    /// Called when a new frame starts.
    void beginFrame() noexcept { ++frame_; }

    ResourceCache(const ResourceCache&) = delete;
    ResourceCache& operator=(const ResourceCache&) = delete;

private:
    struct VertexEntry {
        VertexMirror mirror;
        std::uint64_t version = 0, inputVersion = 0;
        frame::VertexSource source = frame::VertexSource::Plain;
        std::uint64_t lastFrame = 0;
        GpuDeformState gpu;  ///< the compute path's inputs
    };
    struct IndexEntry {
        std::uint32_t revision = 0;
        std::uint64_t orderVersion = 0;
        IndexMirror mirror;
    };
    /// An IndexBuffer's triangles, in its VertexBuffer's order (second 0)
    /// or remapped to a deformed mesh's vertex order (second: that mesh).
    using IndexKey = std::pair<std::uint64_t, std::uint64_t>;
    struct IndexKeyHash {
        std::size_t operator()(const IndexKey& k) const noexcept {
            return std::hash<std::uint64_t>{}(k.first ^ (k.second * 0x9E3779B97F4A7C15ull));
        }
    };
    struct TextureEntry {
        std::uint32_t revision = 0;
        bool mipmaps = false;
        Image image;
    };

    /// Lays out `present` streams of `vertexCount` vertices in the entry's
    /// buffer, replacing it when too small or already used by this frame.
    /// Returns true when the buffer is new (its contents undefined).
    bool layoutMirror(VertexEntry& entry, const std::array<bool, frame::STREAM_COUNT>& present, int vertexCount);
    void writeStream(VertexEntry& entry, int stream, std::span<const float> values);
    /// The compute path of vertices().
    void deformOnGpu(VertexEntry& entry, const frame::VertexRef& ref, frame::FrameSources& sources, bool staticsStale);
    void retire(Buffer& buffer);
    void retire(Image& image);
    /// Creates the image and records its upload (and mip chain) into `cmd`.
    Image createTexture(VkCommandBuffer cmd, const std::vector<std::uint8_t>& rgba, int width, int height, bool mipmaps);
    VkCommandBuffer uploadCommands();
    /// The 1x1 white texture, created (and its upload recorded into this
    /// frame's uploads) at first use.
    const Image& white();

    Context& ctx_;
    VkDescriptorSetLayout setLayout_;
    std::uint64_t frame_ = 1;
    std::unordered_map<std::uint64_t, VertexEntry> vertices_;
    std::unordered_map<IndexKey, IndexEntry, IndexKeyHash> indices_;
    std::unordered_map<std::uint64_t, TextureEntry> textures_;
    std::unordered_map<std::uint32_t, VkSampler> samplers_;
    std::map<std::array<std::uint64_t, 4>, VkDescriptorSet> sets_;
    std::vector<VkDescriptorPool> pools_;
    std::uint32_t poolUsed_ = 0;
    Image white_;
    std::vector<Buffer> retiredBuffers_;
    std::vector<Image> retiredImages_;
    std::vector<std::uint32_t> triangles_;
    std::vector<std::uint8_t> texels_;
    std::unique_ptr<ComputeDeformer> compute_;
    VkCommandPool uploadPool_ = VK_NULL_HANDLE;
    VkCommandBuffer uploadCmd_ = VK_NULL_HANDLE;
    bool uploading_ = false;
};

}  // namespace m3g::vk
