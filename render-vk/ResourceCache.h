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
    /// SkinnedMesh or MorphingMesh. ISE on invalid vertex data.
    const VertexMirror& vertices(VertexBuffer& vb, const Mesh* mesh);
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
};

}  // namespace m3g::vk
