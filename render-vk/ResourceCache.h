// GPU mirrors of VertexBuffer, IndexBuffer and Image2D, kept in side tables
// keyed by object id and refreshed when the object's revision changes
// (architecture guide §4: scene objects never hold Vulkan handles). Mirrors
// of dead objects and replaced mirrors are freed only after the frame that
// may use them has finished (endFrame).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <unordered_map>
#include <vector>

#include <m3g/Object3D.h>
#include <m3g/Ref.h>

#include "ComputeDeformer.h"
#include "Context.h"
#include "MeshDeformer.h"

namespace m3g {
class Image2D;
class IndexBuffer;
class Mesh;
class VertexBuffer;
}  // namespace m3g

namespace m3g::vk {

/// Five float streams: position (raw, or final for deformed meshes),
/// normal, colour RGBA, texcoord 0, texcoord 1 (raw).
struct VertexMirror {
    Buffer buffer;
    std::array<VkDeviceSize, 5> offsets{};
    std::array<bool, 5> present{};
    int vertexCount = 0;
    bool deformed = false;  ///< positions already scaled and biased
};

struct IndexMirror {
    Buffer buffer;
    std::uint32_t count = 0;
};

struct TextureMirror {
    Image image;
    bool hasColor = true, hasAlpha = true;
};

class ResourceCache {
public:
    ResourceCache(Context& ctx, VkDescriptorSetLayout textureSetLayout);
    ~ResourceCache();

    /// Streams of `vb`, or of `mesh`'s deformed vertices when it is a
    /// SkinnedMesh or MorphingMesh: deformed on the CPU and uploaded, or,
    /// with `compute`, by ComputeDeformer into the mirror (recorded into the
    /// frame's compute commands, see finishCompute). Either way only when an
    /// input changed. ISE on invalid vertex data.
    const VertexMirror& vertices(VertexBuffer& vb, const Mesh* mesh, bool compute = false);
    /// The frame's compute commands, ended with their barrier, to submit
    /// before the draws; VK_NULL_HANDLE when the frame deformed nothing on
    /// the GPU.
    VkCommandBuffer finishCompute() { return compute_ ? compute_->finishFrame() : VK_NULL_HANDLE; }

    /// A triangle list with each triangle's OpenGL provoking vertex (the
    /// strip's last) first, because Vulkan's flat shading uses the first.
    const IndexMirror& indices(IndexBuffer& ib);
    /// RGBA8 image of `image` (expanded per format), with a mip chain if asked.
    const TextureMirror& texture(Image2D& image, bool mipmaps);
    VkSampler sampler(int wrapS, int wrapT, int imageFilter, int levelFilter);
    /// Descriptor set of two combined image samplers; null = white texel.
    VkDescriptorSet textureSet(const TextureMirror* t0, VkSampler s0, const TextureMirror* t1, VkSampler s1);

    /// Called when the GPU has finished all submitted work: frees replaced
    /// mirrors and those of objects that no longer exist.
    void endFrame();
    /// Drops every cached texture descriptor set (the GPU must be idle).
    void forgetTextureSets();
    /// Called when a new frame starts recording.
    void beginFrame() noexcept { ++frame_; }

    ResourceCache(const ResourceCache&) = delete;
    ResourceCache& operator=(const ResourceCache&) = delete;

private:
    struct VertexEntry {
        WeakRef<Object3D> owner;
        std::array<std::uint64_t, 12> signature{};
        VertexMirror mirror;
        std::unique_ptr<detail::MeshDeformer> deformer;
        std::uint64_t lastFrame = 0;
        /// The compute path's inputs; `computed`: the mirror was last
        /// written by it (its static streams are in place).
        GpuDeformState gpu;
        bool computed = false;
    };
    struct IndexEntry {
        WeakRef<Object3D> owner;
        std::uint32_t revision = 0;
        IndexMirror mirror;
    };
    struct TextureEntry {
        WeakRef<Object3D> owner;
        std::uint32_t revision = 0;
        bool mipmaps = false;
        TextureMirror mirror;
    };

    void upload(VertexEntry& entry, const std::array<const std::vector<float>*, 5>& streams, int vertexCount);
    /// Lays out `present` streams of `vertexCount` vertices in the entry's
    /// buffer, replacing it when too small or already used by this frame.
    /// Returns true when the buffer is new (its contents undefined).
    bool layoutMirror(VertexEntry& entry, const std::array<bool, 5>& present, int vertexCount);
    void writeStream(VertexEntry& entry, int stream, const std::vector<float>& values);
    /// The compute path of vertices().
    void deformOnGpu(VertexEntry& entry, VertexBuffer& vb, const Mesh& mesh, bool staticsStale);
    void retire(Buffer& buffer);
    void retire(Image& image);
    TextureMirror createTexture(Image2D& image, bool mipmaps);

    Context& ctx_;
    VkDescriptorSetLayout setLayout_;
    std::uint64_t frame_ = 1;
    std::unordered_map<std::uint64_t, VertexEntry> vertices_;
    std::unordered_map<std::uint64_t, IndexEntry> indices_;
    std::unordered_map<std::uint64_t, TextureEntry> textures_;
    std::unordered_map<std::uint32_t, VkSampler> samplers_;
    std::map<std::array<std::uint64_t, 4>, VkDescriptorSet> sets_;
    std::vector<VkDescriptorPool> pools_;
    std::uint32_t poolUsed_ = 0;
    TextureMirror white_;
    std::vector<Buffer> retiredBuffers_;
    std::vector<Image> retiredImages_;
    std::vector<float> scratch_[5];
    std::unique_ptr<ComputeDeformer> compute_;
};

}  // namespace m3g::vk
