#include "ResourceCache.h"

#include "PropertyUtil.h"

#include <algorithm>
#include <cstring>

#include <m3g/Image2D.h>
#include <m3g/IndexBuffer.h>
#include <m3g/Mesh.h>
#include <m3g/MorphingMesh.h>
#include <m3g/SkinnedMesh.h>
#include <m3g/Texture2D.h>
#include <m3g/TriangleStripArray.h>
#include <m3g/VertexArray.h>
#include <m3g/VertexBuffer.h>

namespace m3g::vk {

namespace {

constexpr std::uint32_t kSetsPerPool = 256;
const std::uint32_t kComponents[5] = {3, 3, 4, 3, 3};

void rawStream(const VertexArray* a, int outComponents, std::vector<float>& out) {
    const int n = a->getVertexCount(), c = a->getComponentCount();
    out.assign(static_cast<std::size_t>(n) * outComponents, 0.0f);
    for (int v = 0; v < n; ++v)
        for (int k = 0; k < std::min(c, outComponents); ++k) out[v * outComponents + k] = static_cast<float>(a->value(v, k));
}

// OpenGL's signed-integer normal mapping (detail::normalComponent).
void normalStream(const VertexArray* a, std::vector<float>& out) {
    const int n = a->getVertexCount(), size = a->getComponentType();
    out.resize(static_cast<std::size_t>(n) * 3);
    for (int v = 0; v < n; ++v)
        for (int k = 0; k < 3; ++k) out[v * 3 + k] = detail::normalComponent(a->value(v, k), size);
}

// Colour bytes are unsigned; 3-component colours get alpha 1.
void colorStream(const VertexArray* a, std::vector<float>& out) {
    const int n = a->getVertexCount(), c = a->getComponentCount();
    out.resize(static_cast<std::size_t>(n) * 4);
    for (int v = 0; v < n; ++v)
        for (int k = 0; k < 4; ++k)
            out[v * 4 + k] = k < c ? static_cast<float>(a->value(v, k) & 0xFF) / 255.0f : 1.0f;
}

using Signature = std::array<std::uint64_t, 12>;

/// Identity and revision of the VertexBuffer and its arrays.
Signature signatureOf(const VertexBuffer& vb) {
    Signature sig{};
    const Object3D* parts[6] = {&vb, vb.positions(), vb.normals(), vb.colors(), vb.texCoords(0), vb.texCoords(1)};
    for (int i = 0; i < 6; ++i) {
        sig[i * 2] = parts[i] ? parts[i]->getObjectId() : 0;
        sig[i * 2 + 1] = parts[i] ? parts[i]->getRevision() : 0;
    }
    return sig;
}

}  // namespace

ResourceCache::ResourceCache(Context& ctx, VkDescriptorSetLayout textureSetLayout)
    : ctx_(ctx), setLayout_(textureSetLayout) {
    // The white texel that stands for an unused texture unit.
    Ref<Image2D> white(new Image2D(Image2D::RGBA, 1, 1));
    white_ = createTexture(*white, false);
}

ResourceCache::~ResourceCache() {
    ctx_.waitIdle();
    endFrame();
    for (auto& [id, e] : vertices_) {
        ctx_.destroy(e.mirror.buffer);
        if (compute_) compute_->release(e.gpu);
    }
    compute_.reset();  // frees what release() retired
    for (auto& [id, e] : indices_) ctx_.destroy(e.mirror.buffer);
    for (auto& [id, e] : textures_) ctx_.destroy(e.mirror.image);
    for (auto& [key, s] : samplers_) vkDestroySampler(ctx_.device(), s, nullptr);
    for (VkDescriptorPool p : pools_) vkDestroyDescriptorPool(ctx_.device(), p, nullptr);
    ctx_.destroy(white_.image);
}

void ResourceCache::retire(Buffer& buffer) {
    if (buffer.buffer) retiredBuffers_.push_back(buffer);
    buffer = Buffer{};
}

void ResourceCache::retire(Image& image) {
    if (image.image) retiredImages_.push_back(image);
    image = Image{};
}

bool ResourceCache::layoutMirror(VertexEntry& entry, const std::array<bool, 5>& present, int vertexCount) {
    VertexMirror& m = entry.mirror;
    VkDeviceSize size = 0;
    std::array<VkDeviceSize, 5> offsets{};
    for (int i = 0; i < 5; ++i) {
        offsets[i] = size;
        if (present[i]) size += static_cast<VkDeviceSize>(vertexCount) * kComponents[i] * sizeof(float);
    }
    size = std::max<VkDeviceSize>(size, 16);
    bool fresh = m.present != present || m.offsets != offsets || m.vertexCount != vertexCount;
    // Overwrite in place only if no recorded, unfinished frame reads it.
    if (!m.buffer.buffer || m.buffer.size < size || entry.lastFrame == frame_) {
        retire(m.buffer);
        // Storage too: the compute path writes deformed streams into it.
        m.buffer = ctx_.createHostBuffer(size, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        fresh = true;
    }
    m.present = present;
    m.offsets = offsets;
    m.vertexCount = vertexCount;
    return fresh;
}

void ResourceCache::writeStream(VertexEntry& entry, int stream, const std::vector<float>& values) {
    VertexMirror& m = entry.mirror;
    const std::size_t bytes = static_cast<std::size_t>(m.vertexCount) * kComponents[stream] * sizeof(float);
    std::memcpy(static_cast<char*>(m.buffer.mapped) + m.offsets[static_cast<std::size_t>(stream)], values.data(),
                std::min(bytes, values.size() * sizeof(float)));
}

void ResourceCache::upload(VertexEntry& entry, const std::array<const std::vector<float>*, 5>& streams, int vertexCount) {
    std::array<bool, 5> present{};
    for (int i = 0; i < 5; ++i) present[i] = streams[i] != nullptr;
    layoutMirror(entry, present, vertexCount);
    for (int i = 0; i < 5; ++i)
        if (streams[i]) writeStream(entry, i, *streams[i]);
    ++ctx_.bufferUploads;
}

void ResourceCache::deformOnGpu(VertexEntry& e, VertexBuffer& vb, const Mesh& mesh, bool staticsStale) {
    using D = detail::MeshDeformer;
    const D& d = *e.deformer;
    const int n = vb.getVertexCount();
    const bool skinned = dynamic_cast<const SkinnedMesh*>(&mesh) != nullptr;
    std::array<detail::MorphAttributeInputs, D::kMorphAttributes> morph{};
    if (!skinned)
        for (int a = 0; a < D::kMorphAttributes; ++a) morph[static_cast<std::size_t>(a)] = d.morphAttribute(a);
    const detail::SkinInputs skin = skinned ? d.skinInputs() : detail::SkinInputs{};

    // Streams: the deformed ones written by the shaders; a skinned mesh's
    // colours and texture coordinates are its VertexBuffer's, from the host.
    std::array<bool, 5> present{};
    present[0] = true;
    if (skinned) {
        present[1] = !skin.normals.empty();
        present[2] = vb.colors() != nullptr;
        for (int u = 0; u < 2; ++u) present[3 + u] = vb.texCoords(u) != nullptr;
    } else {
        present[1] = morph[D::kMorphNormals].components > 0;
        present[2] = morph[D::kMorphColors].components > 0;
        for (int u = 0; u < 2; ++u) present[3 + u] = morph[static_cast<std::size_t>(D::kMorphTexCoords + u)].components > 0;
    }
    const bool fresh = layoutMirror(e, present, n);
    if (skinned && (fresh || staticsStale)) {
        if (vb.colors()) {
            colorStream(vb.colors(), scratch_[2]);
            writeStream(e, 2, scratch_[2]);
        }
        for (int u = 0; u < 2; ++u)
            if (vb.texCoords(u)) {
                rawStream(vb.texCoords(u), 3, scratch_[3 + u]);
                writeStream(e, 3 + u, scratch_[3 + u]);
            }
        ++ctx_.bufferUploads;
    }

    if (!compute_) compute_ = std::make_unique<ComputeDeformer>(ctx_);
    const VertexMirror& m = e.mirror;
    ComputeDeformer::Streams streams;
    auto element = [&](int i) { return m.present[i] ? static_cast<std::uint32_t>(m.offsets[i] / sizeof(float)) : kNoStream; };
    streams.positions = element(0);
    streams.normals = element(1);
    streams.colors = element(2);
    streams.texCoords = {element(3), element(4)};
    VkCommandBuffer cmd = compute_->frameCommands();
    if (skinned)
        compute_->recordSkin(cmd, e.gpu, skin, d.inputStamp(), m.buffer, streams);
    else
        compute_->recordMorph(cmd, e.gpu, morph, d.morphWeights(), n, d.inputStamp(), m.buffer, streams);
    e.computed = true;
}

const VertexMirror& ResourceCache::vertices(VertexBuffer& vb, const Mesh* mesh, bool compute) {
    const bool deformable = mesh && (dynamic_cast<const SkinnedMesh*>(mesh) || dynamic_cast<const MorphingMesh*>(mesh));
    const Object3D* owner = deformable ? static_cast<const Object3D*>(mesh) : &vb;
    VertexEntry& e = vertices_[owner->getObjectId()];
    if (!e.owner.get()) e.owner = const_cast<Object3D*>(owner);

    const Signature sig = signatureOf(vb);
    if (!vb.positions())
        throw IllegalStateException("Graphics3D::render: the VertexBuffer has no positions (invalid vertex data)");
    const int n = vb.getVertexCount();

    if (deformable) {
        if (!e.deformer) e.deformer = std::make_unique<detail::MeshDeformer>();
        const bool changed = e.deformer->update(*mesh, compute ? detail::MeshDeformer::Output::InputsOnly
                                                               : detail::MeshDeformer::Output::Vertices);
        const bool stale = sig != e.signature || !e.mirror.buffer.buffer || e.computed != compute;
        if (compute && (changed || stale)) {
            deformOnGpu(e, vb, *mesh, stale);
            e.signature = sig;
        } else if (changed || stale) {
            const detail::DeformedVertices& d = e.deformer->vertices();
            std::array<const std::vector<float>*, 5> s{};
            s[0] = &d.positions;
            if (!d.normals.empty()) s[1] = &d.normals;
            if (!d.colors.empty()) {
                s[2] = &d.colors;
            } else if (vb.colors()) {
                colorStream(vb.colors(), scratch_[2]);
                s[2] = &scratch_[2];
            }
            for (int u = 0; u < 2; ++u) {
                if (!d.texCoords[u].empty()) {
                    const int c = d.texCoordComponents[u];
                    scratch_[3 + u].assign(static_cast<std::size_t>(n) * 3, 0.0f);
                    for (int v = 0; v < n; ++v)
                        for (int k = 0; k < std::min(c, 3); ++k) scratch_[3 + u][v * 3 + k] = d.texCoords[u][v * c + k];
                    s[3 + u] = &scratch_[3 + u];
                } else if (vb.texCoords(u)) {
                    rawStream(vb.texCoords(u), 3, scratch_[3 + u]);
                    s[3 + u] = &scratch_[3 + u];
                }
            }
            upload(e, s, n);
            e.signature = sig;
            e.computed = false;
        }
        e.mirror.deformed = true;
    } else if (sig != e.signature || !e.mirror.buffer.buffer) {
        std::array<const std::vector<float>*, 5> s{};
        rawStream(vb.positions(), 3, scratch_[0]);
        s[0] = &scratch_[0];
        if (vb.normals()) {
            normalStream(vb.normals(), scratch_[1]);
            s[1] = &scratch_[1];
        }
        if (vb.colors()) {
            colorStream(vb.colors(), scratch_[2]);
            s[2] = &scratch_[2];
        }
        for (int u = 0; u < 2; ++u)
            if (vb.texCoords(u)) {
                rawStream(vb.texCoords(u), 3, scratch_[3 + u]);
                s[3 + u] = &scratch_[3 + u];
            }
        upload(e, s, n);
        e.signature = sig;
        e.mirror.deformed = false;
    }
    e.lastFrame = frame_;
    return e.mirror;
}

const IndexMirror& ResourceCache::indices(IndexBuffer& ib) {
    IndexEntry& e = indices_[ib.getObjectId()];
    if (!e.owner.get()) e.owner = &ib;
    if (e.mirror.buffer.buffer && e.revision == ib.getRevision()) return e.mirror;
    std::vector<std::uint32_t> list;
    if (const auto* strips = dynamic_cast<const TriangleStripArray*>(&ib)) {
        // Strip triangle j is (s[j], s[j+1], s[j+2]) with alternating winding;
        // OpenGL's provoking vertex is s[j+2]. Rotations keep the winding.
        const auto idx = strips->stripIndices();
        std::size_t start = 0;
        for (int len : strips->stripLengths()) {
            const int* s = idx.data() + start;
            for (int j = 0; j + 2 < len; ++j) {
                const std::uint32_t a = static_cast<std::uint32_t>(s[j]), b = static_cast<std::uint32_t>(s[j + 1]),
                                    c = static_cast<std::uint32_t>(s[j + 2]);
                if (j % 2 == 0) list.insert(list.end(), {c, a, b});
                else list.insert(list.end(), {c, b, a});
            }
            start += static_cast<std::size_t>(len);
        }
    } else {
        // A generic triangle list: the third vertex provokes.
        const auto t = ib.triangleIndices();
        for (std::size_t i = 0; i + 2 < t.size(); i += 3)
            list.insert(list.end(), {static_cast<std::uint32_t>(t[i + 2]), static_cast<std::uint32_t>(t[i]),
                                     static_cast<std::uint32_t>(t[i + 1])});
    }
    const VkDeviceSize size = std::max<VkDeviceSize>(list.size() * sizeof(std::uint32_t), 16);
    retire(e.mirror.buffer);
    e.mirror.buffer = ctx_.createHostBuffer(size, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    if (!list.empty()) std::memcpy(e.mirror.buffer.mapped, list.data(), list.size() * sizeof(std::uint32_t));
    e.mirror.count = static_cast<std::uint32_t>(list.size());
    e.revision = ib.getRevision();
    ++ctx_.bufferUploads;
    return e.mirror;
}

TextureMirror ResourceCache::createTexture(Image2D& image, bool mipmaps) {
    TextureMirror t;
    const int format = image.getFormat();
    t.hasColor = format != Image2D::ALPHA;
    t.hasAlpha = format == Image2D::ALPHA || format == Image2D::LUMINANCE_ALPHA || format == Image2D::RGBA;
    const auto w = static_cast<std::uint32_t>(image.getWidth()), h = static_cast<std::uint32_t>(image.getHeight());
    std::uint32_t levels = 1;
    if (mipmaps)
        while ((std::max(w, h) >> levels) > 0) ++levels;
    std::vector<std::uint8_t> rgba;
    image.getPixelsRGBA8(rgba);
    t.image = ctx_.createImage(w, h, VK_FORMAT_R8G8B8A8_UNORM,
                               VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                   VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                               levels);
    Buffer staging = ctx_.createHostBuffer(rgba.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::memcpy(staging.mapped, rgba.data(), rgba.size());
    VkImage img = t.image.image;
    ctx_.submitNow([&](VkCommandBuffer cmd) {
        auto barrier = [&](std::uint32_t level, std::uint32_t count, VkImageLayout from, VkImageLayout to,
                           VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage,
                           VkAccessFlags2 dstAccess) {
            imageBarrier(cmd, img, VK_IMAGE_ASPECT_COLOR_BIT, level, count, from, to, srcStage, srcAccess, dstStage,
                         dstAccess);
        };
        barrier(0, levels, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, 0,
                VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        copyBufferToImage(cmd, staging.buffer, img, w, h);
        // The mip chain by successive linear blits (box filter), as glGenerateMipmap.
        for (std::uint32_t level = 1; level < levels; ++level) {
            barrier(level - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                    VK_ACCESS_2_TRANSFER_READ_BIT);
            VkImageBlit blit{};
            blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, 1};
            blit.srcOffsets[1] = {static_cast<std::int32_t>(std::max(w >> (level - 1), 1u)),
                                  static_cast<std::int32_t>(std::max(h >> (level - 1), 1u)), 1};
            blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
            blit.dstOffsets[1] = {static_cast<std::int32_t>(std::max(w >> level, 1u)),
                                  static_cast<std::int32_t>(std::max(h >> level, 1u)), 1};
            vkCmdBlitImage(cmd, img, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, img, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                           &blit, VK_FILTER_LINEAR);
            barrier(level - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                    VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                    VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        }
        barrier(levels - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    });
    ctx_.destroy(staging);
    ++ctx_.textureUploads;
    return t;
}

const TextureMirror& ResourceCache::texture(Image2D& image, bool mipmaps) {
    TextureEntry& e = textures_[image.getObjectId()];
    if (!e.owner.get()) e.owner = &image;
    if (e.mirror.image.image && e.revision == image.getRevision() && e.mipmaps == mipmaps) return e.mirror;
    retire(e.mirror.image);
    e.mirror = createTexture(image, mipmaps);
    e.revision = image.getRevision();
    e.mipmaps = mipmaps;
    return e.mirror;
}

VkSampler ResourceCache::sampler(int wrapS, int wrapT, int imageFilter, int levelFilter) {
    const std::uint32_t key = (wrapS == Texture2D::WRAP_CLAMP) | ((wrapT == Texture2D::WRAP_CLAMP) << 1) |
                              ((imageFilter == Texture2D::FILTER_LINEAR) << 2) |
                              (static_cast<std::uint32_t>(levelFilter == Texture2D::FILTER_BASE_LEVEL ? 0
                                                          : levelFilter == Texture2D::FILTER_NEAREST  ? 1
                                                                                                      : 2)
                               << 3);
    auto it = samplers_.find(key);
    if (it != samplers_.end()) return it->second;
    VkSamplerCreateInfo si{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    si.magFilter = si.minFilter = imageFilter == Texture2D::FILTER_LINEAR ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
    si.mipmapMode = levelFilter == Texture2D::FILTER_LINEAR ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
    si.addressModeU = wrapS == Texture2D::WRAP_CLAMP ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE : VK_SAMPLER_ADDRESS_MODE_REPEAT;
    si.addressModeV = wrapT == Texture2D::WRAP_CLAMP ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE : VK_SAMPLER_ADDRESS_MODE_REPEAT;
    si.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    si.minLod = 0.0f;
    si.maxLod = levelFilter == Texture2D::FILTER_BASE_LEVEL ? 0.0f : VK_LOD_CLAMP_NONE;
    VkSampler s;
    check(vkCreateSampler(ctx_.device(), &si, nullptr, &s), "vkCreateSampler");
    samplers_.emplace(key, s);
    return s;
}

VkDescriptorSet ResourceCache::textureSet(const TextureMirror* t0, VkSampler s0, const TextureMirror* t1, VkSampler s1) {
    if (!t0) { t0 = &white_; s0 = sampler(Texture2D::WRAP_REPEAT, Texture2D::WRAP_REPEAT, Texture2D::FILTER_NEAREST, Texture2D::FILTER_BASE_LEVEL); }
    if (!t1) { t1 = &white_; s1 = sampler(Texture2D::WRAP_REPEAT, Texture2D::WRAP_REPEAT, Texture2D::FILTER_NEAREST, Texture2D::FILTER_BASE_LEVEL); }
    const std::array<std::uint64_t, 4> key{reinterpret_cast<std::uint64_t>(t0->image.view), reinterpret_cast<std::uint64_t>(s0),
                                           reinterpret_cast<std::uint64_t>(t1->image.view), reinterpret_cast<std::uint64_t>(s1)};
    auto it = sets_.find(key);
    if (it != sets_.end()) return it->second;
    if (pools_.empty() || poolUsed_ == kSetsPerPool) {
        pools_.push_back(createDescriptorPool(ctx_.device(), VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kSetsPerPool, 2,
                                              "textures"));
        poolUsed_ = 0;
    }
    VkDescriptorSetLayout layout = setLayout_;
    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = pools_.back();
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &layout;
    VkDescriptorSet set;
    check(vkAllocateDescriptorSets(ctx_.device(), &ai, &set), "vkAllocateDescriptorSets");
    ++poolUsed_;
    VkDescriptorImageInfo infos[2] = {{s0, t0->image.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
                                      {s1, t1->image.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}};
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = 0;
    w.descriptorCount = 2;
    w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w.pImageInfo = infos;
    vkUpdateDescriptorSets(ctx_.device(), 1, &w, 0, nullptr);
    sets_.emplace(key, set);
    return set;
}

void ResourceCache::forgetTextureSets() {
    sets_.clear();
    for (VkDescriptorPool p : pools_) vkDestroyDescriptorPool(ctx_.device(), p, nullptr);
    pools_.clear();
    poolUsed_ = 0;
}

void ResourceCache::endFrame() {
    // Mirrors of objects that no longer exist.
    for (auto it = vertices_.begin(); it != vertices_.end();)
        if (!it->second.owner.get()) {
            retire(it->second.mirror.buffer);
            if (compute_) compute_->release(it->second.gpu);
            it = vertices_.erase(it);
        } else {
            ++it;
        }
    for (auto it = indices_.begin(); it != indices_.end();)
        if (!it->second.owner.get()) { retire(it->second.mirror.buffer); it = indices_.erase(it); } else ++it;
    for (auto it = textures_.begin(); it != textures_.end();)
        if (!it->second.owner.get()) { retire(it->second.mirror.image); it = textures_.erase(it); } else ++it;
    for (Buffer& b : retiredBuffers_) ctx_.destroy(b);
    retiredBuffers_.clear();
    if (compute_) compute_->endFrame();
    if (!retiredImages_.empty()) {
        // Descriptor sets may name the freed views: start the set cache afresh.
        forgetTextureSets();
        for (Image& i : retiredImages_) ctx_.destroy(i);
        retiredImages_.clear();
    }
}

}  // namespace m3g::vk
