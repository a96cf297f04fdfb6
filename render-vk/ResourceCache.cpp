#include "ResourceCache.h"

#include <algorithm>
#include <cstring>

namespace m3g::vk {

namespace {

constexpr std::uint32_t kSetsPerPool = 256;

bool isGpu(frame::VertexSource s) {
    return s == frame::VertexSource::GpuSkinned || s == frame::VertexSource::GpuMorphed;
}

VkSamplerCreateInfo samplerInfo(frame::SamplerKey key) {
    const frame::LevelFilter level = frame::samplerLevel(key);
    VkSamplerCreateInfo si{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    si.magFilter = si.minFilter = frame::samplerLinear(key) ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
    si.mipmapMode = level == frame::LevelFilter::Linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
    si.addressModeU = frame::samplerClampsS(key) ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE : VK_SAMPLER_ADDRESS_MODE_REPEAT;
    si.addressModeV = frame::samplerClampsT(key) ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE : VK_SAMPLER_ADDRESS_MODE_REPEAT;
    si.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    si.minLod = 0.0f;
    si.maxLod = level == frame::LevelFilter::Base ? 0.0f : VK_LOD_CLAMP_NONE;
    return si;
}

}  // namespace

ResourceCache::ResourceCache(Context& ctx, VkDescriptorSetLayout textureSetLayout)
    : ctx_(ctx), setLayout_(textureSetLayout) {
    uploadPool_ = ctx_.createCommandPool();
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = uploadPool_;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(ctx_.device(), &ai, &uploadCmd_), "vkAllocateCommandBuffers (uploads)");
}

const Image& ResourceCache::white() {
    // The white texel that stands for an unused texture unit: made by the
    // first frame that names one, its upload recorded with that frame's
    // uploads. A submit of its own at construction cost every renderer (and
    // every `m3g render` process) one more round trip through lavapipe's
    // queue thread before the first frame.
    if (!white_.image) {
        const std::vector<std::uint8_t> texel{255, 255, 255, 255};
        white_ = createTexture(uploadCommands(), texel, 1, 1, false);
    }
    return white_;
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
    for (auto& [id, e] : textures_) ctx_.destroy(e.image);
    for (auto& [key, s] : samplers_) vkDestroySampler(ctx_.device(), s, nullptr);
    for (VkDescriptorPool p : pools_) vkDestroyDescriptorPool(ctx_.device(), p, nullptr);
    ctx_.destroy(white_);
    vkDestroyCommandPool(ctx_.device(), uploadPool_, nullptr);
}

void ResourceCache::retire(Buffer& buffer) {
    if (buffer.buffer) retiredBuffers_.push_back(buffer);
    buffer = Buffer{};
}

void ResourceCache::retire(Image& image) {
    if (image.image) retiredImages_.push_back(image);
    image = Image{};
}

bool ResourceCache::layoutMirror(VertexEntry& entry, const std::array<bool, frame::STREAM_COUNT>& present,
                                 int vertexCount) {
    VertexMirror& m = entry.mirror;
    VkDeviceSize size = 0;
    std::array<VkDeviceSize, frame::STREAM_COUNT> offsets{};
    for (int i = 0; i < frame::STREAM_COUNT; ++i) {
        offsets[static_cast<std::size_t>(i)] = size;
        if (present[static_cast<std::size_t>(i)])
            size += static_cast<VkDeviceSize>(vertexCount) * static_cast<VkDeviceSize>(frame::kStreamComponents[static_cast<std::size_t>(i)]) *
                    sizeof(float);
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

void ResourceCache::writeStream(VertexEntry& entry, int stream, std::span<const float> values) {
    VertexMirror& m = entry.mirror;
    const std::size_t bytes = static_cast<std::size_t>(m.vertexCount) *
                              static_cast<std::size_t>(frame::kStreamComponents[static_cast<std::size_t>(stream)]) *
                              sizeof(float);
    if (values.empty()) return;
    std::memcpy(static_cast<char*>(m.buffer.mapped) + m.offsets[static_cast<std::size_t>(stream)], values.data(),
                std::min(bytes, values.size() * sizeof(float)));
}

void ResourceCache::deformOnGpu(VertexEntry& e, const frame::VertexRef& ref, frame::FrameSources& sources,
                                bool staticsStale) {
    const bool skinned = ref.source == frame::VertexSource::GpuSkinned;
    const bool fresh = layoutMirror(e, ref.present, ref.vertexCount);
    // A skinned mesh's colours and texture coordinates are its
    // VertexBuffer's, written from the host; the kernel writes the rest.
    if (skinned && (fresh || staticsStale)) {
        const frame::VertexStreams s = sources.vertexStreams(ref);
        for (int i = frame::COLORS; i < frame::STREAM_COUNT; ++i)
            if (ref.present[static_cast<std::size_t>(i)]) writeStream(e, i, s.streams[static_cast<std::size_t>(i)]);
        ++ctx_.bufferUploads;
    }
    if (!compute_) compute_ = std::make_unique<ComputeDeformer>(ctx_);
    const VertexMirror& m = e.mirror;
    ComputeDeformer::Streams streams;
    auto element = [&](int i) {
        return m.present[static_cast<std::size_t>(i)]
                   ? static_cast<std::uint32_t>(m.offsets[static_cast<std::size_t>(i)] / sizeof(float))
                   : kNoStream;
    };
    streams.positions = element(frame::POSITIONS);
    streams.normals = element(frame::NORMALS);
    streams.colors = element(frame::COLORS);
    streams.texCoords = {element(frame::TEXCOORDS0), element(frame::TEXCOORDS1)};
    VkCommandBuffer cmd = compute_->frameCommands();
    if (skinned) {
        compute_->recordSkin(cmd, e.gpu, sources.skinInputs(ref), ref.inputVersion, m.buffer, streams);
    } else {
        const frame::MorphInputs in = sources.morphInputs(ref);
        compute_->recordMorph(cmd, e.gpu, in.attributes, in.weights, ref.vertexCount, ref.inputVersion, m.buffer,
                              streams);
    }
}

const VertexMirror& ResourceCache::vertices(const frame::VertexRef& ref, frame::FrameSources& sources) {
    VertexEntry& e = vertices_[ref.owner];
    const bool stale = !e.mirror.buffer.buffer || e.version != ref.version || e.source != ref.source;
    if (stale) {
        if (isGpu(ref.source)) {
            deformOnGpu(e, ref, sources, e.inputVersion != ref.inputVersion || e.source != ref.source);
        } else {
            const frame::VertexStreams s = sources.vertexStreams(ref);
            layoutMirror(e, ref.present, ref.vertexCount);
            for (int i = 0; i < frame::STREAM_COUNT; ++i)
                if (ref.present[static_cast<std::size_t>(i)]) writeStream(e, i, s.streams[static_cast<std::size_t>(i)]);
            ++ctx_.bufferUploads;
        }
        e.version = ref.version;
        e.inputVersion = ref.inputVersion;
        e.source = ref.source;
    }
    e.lastFrame = frame_;
    return e.mirror;
}

const IndexMirror& ResourceCache::indices(const frame::IndexRef& ref, frame::FrameSources& sources) {
    IndexEntry& e = indices_[{ref.id, ref.vertexOrder}];
    if (e.mirror.buffer.buffer && e.revision == ref.revision && e.orderVersion == ref.orderVersion) return e.mirror;
    sources.triangles(ref, triangles_);
    const VkDeviceSize size = std::max<VkDeviceSize>(triangles_.size() * sizeof(std::uint32_t), 16);
    retire(e.mirror.buffer);
    e.mirror.buffer = ctx_.createHostBuffer(size, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    if (!triangles_.empty())
        std::memcpy(e.mirror.buffer.mapped, triangles_.data(), triangles_.size() * sizeof(std::uint32_t));
    e.mirror.count = static_cast<std::uint32_t>(triangles_.size());
    e.revision = ref.revision;
    e.orderVersion = ref.orderVersion;
    ++ctx_.bufferUploads;
    return e.mirror;
}

VkCommandBuffer ResourceCache::uploadCommands() {
    if (!uploading_) {
        vkResetCommandBuffer(uploadCmd_, 0);
        VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        check(vkBeginCommandBuffer(uploadCmd_, &bi), "vkBeginCommandBuffer (uploads)");
        uploading_ = true;
    }
    return uploadCmd_;
}

VkCommandBuffer ResourceCache::finishUploads() {
    if (!uploading_) return VK_NULL_HANDLE;
    uploading_ = false;
    check(vkEndCommandBuffer(uploadCmd_), "vkEndCommandBuffer (uploads)");
    return uploadCmd_;
}

Image ResourceCache::createTexture(VkCommandBuffer cmd, const std::vector<std::uint8_t>& rgba, int width, int height,
                                   bool mipmaps) {
    const auto w = static_cast<std::uint32_t>(std::max(width, 1)), h = static_cast<std::uint32_t>(std::max(height, 1));
    std::uint32_t levels = 1;
    if (mipmaps)
        while ((std::max(w, h) >> levels) > 0) ++levels;
    Image t = ctx_.createImage(w, h, VK_FORMAT_R8G8B8A8_UNORM,
                               VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                   VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                               levels);
    Buffer staging = ctx_.createHostBuffer(std::max<VkDeviceSize>(rgba.size(), 4), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::memcpy(staging.mapped, rgba.data(), std::min<std::size_t>(rgba.size(), static_cast<std::size_t>(w) * h * 4));
    retiredBuffers_.push_back(staging);  // freed once the frame has finished
    VkImage img = t.image;
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
                VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    }
    barrier(levels - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
            VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
            VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    ++ctx_.textureUploads;
    return t;
}

const Image& ResourceCache::texture(const frame::TextureRef& ref, frame::FrameSources& sources) {
    if (!ref.id) return white();
    TextureEntry& e = textures_[ref.id];
    if (e.image.image && e.revision == ref.revision && e.mipmaps == ref.mipmaps) return e.image;
    int w = 0, h = 0;
    sources.texels(ref, texels_, w, h);
    retire(e.image);
    e.image = createTexture(uploadCommands(), texels_, w, h, ref.mipmaps);
    e.revision = ref.revision;
    e.mipmaps = ref.mipmaps;
    return e.image;
}

VkSampler ResourceCache::sampler(frame::SamplerKey key) {
    auto it = samplers_.find(key);
    if (it != samplers_.end()) return it->second;
    const VkSamplerCreateInfo si = samplerInfo(key);
    VkSampler s;
    check(vkCreateSampler(ctx_.device(), &si, nullptr, &s), "vkCreateSampler");
    samplers_.emplace(key, s);
    return s;
}

VkDescriptorSet ResourceCache::textureSet(const Image* t0, VkSampler s0, const Image* t1, VkSampler s1) {
    // The white texel: repeat, nearest, base level (the key 0).
    constexpr frame::SamplerKey kWhite = frame::makeSampler(false, false, false, frame::LevelFilter::Base);
    if (!t0) {
        t0 = &white();
        s0 = sampler(kWhite);
    }
    if (!t1) {
        t1 = &white();
        s1 = sampler(kWhite);
    }
    const std::array<std::uint64_t, 4> key{reinterpret_cast<std::uint64_t>(t0->view), reinterpret_cast<std::uint64_t>(s0),
                                           reinterpret_cast<std::uint64_t>(t1->view), reinterpret_cast<std::uint64_t>(s1)};
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
    VkDescriptorImageInfo infos[2] = {{s0, t0->view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
                                      {s1, t1->view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}};
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

void ResourceCache::release(std::span<const std::uint64_t> ids) {
    for (std::uint64_t id : ids) {
        if (auto it = vertices_.find(id); it != vertices_.end()) {
            retire(it->second.mirror.buffer);
            if (compute_) compute_->release(it->second.gpu);
            vertices_.erase(it);
        }
        if (auto it = textures_.find(id); it != textures_.end()) {
            retire(it->second.image);
            textures_.erase(it);
        }
    }
    // Index copies go with their IndexBuffer and with the mesh whose vertex
    // order they follow: one pass over them.
    if (ids.empty() || indices_.empty()) return;
    std::vector<std::uint64_t> released(ids.begin(), ids.end());
    std::sort(released.begin(), released.end());
    auto gone = [&](std::uint64_t id) { return id && std::binary_search(released.begin(), released.end(), id); };
    for (auto it = indices_.begin(); it != indices_.end();) {
        if (gone(it->first.first) || gone(it->first.second)) {
            retire(it->second.mirror.buffer);
            it = indices_.erase(it);
        } else {
            ++it;
        }
    }
}

void ResourceCache::endFrame() {
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
