#include "StreamBuffers.h"

#include <cstring>

namespace m3g::vk {

namespace {
constexpr std::uint32_t kDrawsPerChunk = 256;
constexpr VkDeviceSize kQuadBytes = 6 * 6 * sizeof(float);
}  // namespace

StreamBuffers::StreamBuffers(Context& ctx, VkDescriptorSetLayout uniformSetLayout)
    : ctx_(ctx), setLayout_(uniformSetLayout) {
    const auto align = static_cast<std::uint32_t>(ctx_.properties().limits.minUniformBufferOffsetAlignment);
    stride_ = static_cast<std::uint32_t>((sizeof(frame::DrawUniforms) + align - 1) / align * align);
    pool_ = createDescriptorPool(ctx_.device(), VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1024, 1, "uniforms");
    quads_ = ctx_.createHostBuffer(kQuadBytes * 1024, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    dummy_ = ctx_.createHostBuffer(64, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    std::memset(dummy_.mapped, 0, 64);
}

StreamBuffers::~StreamBuffers() {
    for (auto& c : chunks_) ctx_.destroy(c.buffer);
    vkDestroyDescriptorPool(ctx_.device(), pool_, nullptr);
    ctx_.destroy(quads_);
    for (Buffer& b : retiredQuads_) ctx_.destroy(b);
    ctx_.destroy(dummy_);
}

void StreamBuffers::beginFrame() noexcept {
    chunk_ = 0;
    chunkOffset_ = 0;
    quadOffset_ = 0;
}

void StreamBuffers::endFrame() noexcept {
    for (Buffer& b : retiredQuads_) ctx_.destroy(b);
    retiredQuads_.clear();
}

void StreamBuffers::uniforms(const frame::DrawUniforms& u, VkDescriptorSet& set, std::uint32_t& offset) {
    if (chunk_ < chunks_.size() && chunkOffset_ + stride_ > kDrawsPerChunk * stride_) {
        ++chunk_;
        chunkOffset_ = 0;
    }
    if (chunk_ == chunks_.size()) {
        UniformChunk c;
        c.buffer = ctx_.createHostBuffer(static_cast<VkDeviceSize>(kDrawsPerChunk) * stride_,
                                         VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
        VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        ai.descriptorPool = pool_;
        ai.descriptorSetCount = 1;
        ai.pSetLayouts = &setLayout_;
        check(vkAllocateDescriptorSets(ctx_.device(), &ai, &c.set), "vkAllocateDescriptorSets (uniforms)");
        VkDescriptorBufferInfo info{c.buffer.buffer, 0, sizeof(frame::DrawUniforms)};
        VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstSet = c.set;
        w.descriptorCount = 1;
        w.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
        w.pBufferInfo = &info;
        vkUpdateDescriptorSets(ctx_.device(), 1, &w, 0, nullptr);
        chunks_.push_back(c);
        chunkOffset_ = 0;
    }
    set = chunks_[chunk_].set;
    offset = chunkOffset_;
    chunkOffset_ += stride_;
    std::memcpy(static_cast<char*>(chunks_[chunk_].buffer.mapped) + offset, &u, sizeof(u));
}

VkBuffer StreamBuffers::quad(const frame::Quad& q, VkDeviceSize& offset) {
    if (quadOffset_ + kQuadBytes > quads_.size) {
        // A bigger ring; the full one stays alive until the frame is done.
        retiredQuads_.push_back(quads_);
        quads_ = ctx_.createHostBuffer(quads_.size * 2, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        quadOffset_ = 0;
    }
    // Two triangles, counter-clockwise; positions then texcoords per vertex.
    // The order is the triangle strip top-left, bottom-left, top-right,
    // bottom-right as GL splits it, which is how Nokia's engine draws
    // backgrounds and sprites: attributes are interpolated from each
    // triangle's first vertex, so a pixel centre exactly on a texel edge (a
    // 64-texel image over 240 rows has one every 15 rows) then rounds as in the
    // reference renders: to the texel after the edge, as exact arithmetic says
    // (VkTest.BackgroundNearestRowsAtExactTexelEdges).
    const float tl[6] = {q.x0, q.y1, q.z, q.s0, q.t0, 0}, bl[6] = {q.x0, q.y0, q.z, q.s0, q.t1, 0},
                tr[6] = {q.x1, q.y1, q.z, q.s1, q.t0, 0}, br[6] = {q.x1, q.y0, q.z, q.s1, q.t1, 0};
    const float* order[6] = {tl, bl, tr, tr, bl, br};
    float v[6][6];
    for (int i = 0; i < 6; ++i) std::memcpy(v[i], order[i], sizeof(v[i]));
    std::memcpy(static_cast<char*>(quads_.mapped) + quadOffset_, v, sizeof(v));
    offset = quadOffset_;
    quadOffset_ += kQuadBytes;
    return quads_.buffer;
}

}  // namespace m3g::vk
