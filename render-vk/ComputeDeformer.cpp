#include "ComputeDeformer.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "m3g_morph_comp.h"  // generated from shaders/ by glslangValidator at build time
#include "m3g_skin_comp.h"

namespace m3g::vk {

namespace {

constexpr std::uint32_t kSetsPerPool = 64;
constexpr std::uint32_t kBindings = 4;  // frame data, inputs as floats, inputs as ints, output
constexpr std::uint32_t kPushBytes = 64;
static_assert(sizeof(SkinParams) <= kPushBytes && sizeof(MorphParams) <= kPushBytes);

/// Internal errors: inputs that MeshDeformer never builds.
[[noreturn]] void fail(const std::string& what) {
    throw IllegalStateException("ComputeDeformer: " + what);
}

std::uint32_t elements(std::size_t n, const char* what) {
    if (n > 0xFFFFFFF0u) fail(std::string(what) + " exceeds 2^32 elements");
    return static_cast<std::uint32_t>(n);
}

/// Copies `count` 4-byte elements. A zero count copies nothing: an empty
/// span's data() may be null, which memcpy must not receive even for 0 bytes.
void copyElements(void* dst, const void* src, std::size_t count) noexcept {
    if (count != 0) std::memcpy(dst, src, count * 4);
}

/// The output buffer holds `count` floats at `offset` (elements).
void requireRoom(const Buffer& out, std::uint32_t offset, std::size_t count, const char* stream) {
    if (offset == kNoStream) return;
    if ((static_cast<std::size_t>(offset) + count) * sizeof(float) > out.size)
        fail(std::string("the output buffer is too small for the ") + stream + " stream");
}

VkPipeline createComputePipeline(VkDevice device, VkPipelineLayout layout, const std::uint32_t* code, std::size_t bytes) {
    VkShaderModule module = createShaderModule(device, code, bytes);
    VkComputePipelineCreateInfo ci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    ci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    ci.stage.module = module;
    ci.stage.pName = "main";
    ci.layout = layout;
    VkPipeline pipeline;
    const VkResult r = vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &ci, nullptr, &pipeline);
    vkDestroyShaderModule(device, module, nullptr);
    check(r, "vkCreateComputePipelines");
    return pipeline;
}

}  // namespace

ComputeDeformer::ComputeDeformer(Context& ctx) : ctx_(ctx) {
    VkDevice device = ctx.device();
    std::array<VkDescriptorSetLayoutBinding, kBindings> bindings{};
    for (std::uint32_t i = 0; i < kBindings; ++i)
        bindings[i] = {i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo li{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    li.bindingCount = kBindings;
    li.pBindings = bindings.data();
    check(vkCreateDescriptorSetLayout(device, &li, nullptr, &setLayout_), "vkCreateDescriptorSetLayout");
    VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, kPushBytes};
    VkPipelineLayoutCreateInfo pl{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pl.setLayoutCount = 1;
    pl.pSetLayouts = &setLayout_;
    pl.pushConstantRangeCount = 1;
    pl.pPushConstantRanges = &range;
    check(vkCreatePipelineLayout(device, &pl, nullptr, &layout_), "vkCreatePipelineLayout");
    skin_ = createComputePipeline(device, layout_, m3g_skin_comp, sizeof(m3g_skin_comp));
    morph_ = createComputePipeline(device, layout_, m3g_morph_comp, sizeof(m3g_morph_comp));
}

ComputeDeformer::~ComputeDeformer() {
    VkDevice device = ctx_.device();
    for (Buffer& b : retired_) ctx_.destroy(b);
    for (VkDescriptorPool p : pools_) vkDestroyDescriptorPool(device, p, nullptr);
    vkDestroyPipeline(device, skin_, nullptr);
    vkDestroyPipeline(device, morph_, nullptr);
    vkDestroyPipelineLayout(device, layout_, nullptr);
    vkDestroyDescriptorSetLayout(device, setLayout_, nullptr);
    if (cmd_) {
        std::lock_guard lock(ctx_.poolMutex());
        vkFreeCommandBuffers(device, ctx_.commandPool(), 1, &cmd_);
    }
}

void ComputeDeformer::retire(Buffer& buffer) {
    if (buffer.buffer) retired_.push_back(buffer);
    buffer = Buffer{};
}

void ComputeDeformer::release(GpuDeformState& state) {
    retire(state.inputs);
    retire(state.frameData);
    state.hasInputs = false;
}

void* ComputeDeformer::frameData(GpuDeformState& state, std::size_t bytes) {
    bytes = std::max<std::size_t>(bytes, 16);
    if (!state.frameData.buffer || state.frameData.size < bytes || state.frameDataUsed == frame_) {
        retire(state.frameData);
        state.frameData = ctx_.createHostBuffer(bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    }
    state.frameDataUsed = frame_;
    return state.frameData.mapped;
}

VkDescriptorSet ComputeDeformer::descriptorSet(const Buffer& frameData, const Buffer& inputs, const Buffer& out) {
    if (pool_ < pools_.size() && poolUsed_ == kSetsPerPool) {
        ++pool_;
        poolUsed_ = 0;
    }
    if (pool_ == pools_.size()) {
        pools_.push_back(
            createDescriptorPool(ctx_.device(), VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kSetsPerPool, kBindings, "compute"));
        poolUsed_ = 0;
    }
    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = pools_[pool_];
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &setLayout_;
    VkDescriptorSet set;
    check(vkAllocateDescriptorSets(ctx_.device(), &ai, &set), "vkAllocateDescriptorSets (compute)");
    ++poolUsed_;
    const VkDescriptorBufferInfo infos[kBindings] = {{frameData.buffer, 0, VK_WHOLE_SIZE},
                                                     {inputs.buffer, 0, VK_WHOLE_SIZE},
                                                     {inputs.buffer, 0, VK_WHOLE_SIZE},
                                                     {out.buffer, 0, VK_WHOLE_SIZE}};
    std::array<VkWriteDescriptorSet, kBindings> writes{};
    for (std::uint32_t i = 0; i < kBindings; ++i) {
        writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = set;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        writes[i].pBufferInfo = &infos[i];
    }
    vkUpdateDescriptorSets(ctx_.device(), kBindings, writes.data(), 0, nullptr);
    return set;
}

void ComputeDeformer::dispatch(VkCommandBuffer cmd, VkPipeline pipeline, VkDescriptorSet set, const void* params,
                               std::uint32_t paramBytes, std::uint32_t vertexCount) {
    if (vertexCount == 0) return;
    const std::uint32_t groups = (vertexCount + kDeformGroupSize - 1) / kDeformGroupSize;
    if (groups > ctx_.properties().limits.maxComputeWorkGroupCount[0])
        fail(std::to_string(vertexCount) + " vertices exceed one dispatch (" +
             std::to_string(ctx_.properties().limits.maxComputeWorkGroupCount[0]) + " groups of " +
             std::to_string(kDeformGroupSize) + ")");
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, paramBytes, params);
    vkCmdDispatch(cmd, groups, 1, 1);
    ++ctx_.computeDispatches;
}

void ComputeDeformer::recordSkin(VkCommandBuffer cmd, GpuDeformState& state, const frame::SkinInputs& in,
                                 std::uint64_t inputStamp, const Buffer& out, const Streams& streams) {
    const auto n = static_cast<std::size_t>(std::max(in.vertexCount, 0));
    const bool normals = !in.normals.empty();
    const auto stride = static_cast<std::size_t>(in.influenceStride);
    if (in.positions.size() < n * 3 || (normals && in.normals.size() < n * 3))
        fail("skinning inputs hold fewer vertices than vertexCount");
    if (!in.bones.empty() && (stride == 0 || in.weights.size() < in.bones.size()))
        fail("the influence table's weights do not cover its bone indices");
    requireRoom(out, streams.positions, n * 3, "position");
    if (normals) requireRoom(out, streams.normals, n * 3, "normal");

    if (!state.hasInputs || state.inputStamp != inputStamp) {
        // Static inputs: bone indices, weights, positions, normals (elements).
        const std::size_t slots = stride == 0 ? 0 : in.bones.size() / stride * stride;
        const std::size_t total = slots * 2 + n * 3 + (normals ? n * 3 : 0);
        retire(state.inputs);
        state.inputs = ctx_.createHostBuffer(std::max<std::size_t>(total * 4, 16), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        auto* base = static_cast<std::uint32_t*>(state.inputs.mapped);
        state.bonesIn = 0;
        state.weightsIn = elements(slots, "the influence table");
        state.positionsIn = elements(slots * 2, "the skinning inputs");
        state.normalsIn = normals ? elements(slots * 2 + n * 3, "the skinning inputs") : kNoStream;
        state.tableVertices = elements(stride == 0 ? 0 : slots / stride, "the influence table");
        copyElements(base + state.bonesIn, in.bones.data(), slots);
        copyElements(base + state.weightsIn, in.weights.data(), slots);
        copyElements(base + state.positionsIn, in.positions.data(), n * 3);
        if (normals) copyElements(base + state.normalsIn, in.normals.data(), n * 3);
        state.inputStamp = inputStamp;
        state.hasInputs = true;
    }

    const std::size_t paletteBytes = in.palette.size() * sizeof(skin::PaletteEntry);
    void* palette = frameData(state, paletteBytes);
    copyElements(palette, in.palette.data(), paletteBytes / 4);

    SkinParams p{};
    p.positionBias[0] = in.positionBias[0];
    p.positionBias[1] = in.positionBias[1];
    p.positionBias[2] = in.positionBias[2];
    p.positionScale = in.positionScale;
    p.vertexCount = elements(n, "the vertex count");
    p.tableVertices = state.tableVertices;
    p.stride = static_cast<std::uint32_t>(stride);
    p.boneCount = elements(in.palette.size(), "the palette");
    p.bonesIn = state.bonesIn;
    p.weightsIn = state.weightsIn;
    p.positionsIn = state.positionsIn;
    p.normalsIn = normals ? state.normalsIn : kNoStream;
    p.positionsOut = streams.positions;
    p.normalsOut = streams.normals;
    if (p.positionsOut == kNoStream || (normals && p.normalsOut == kNoStream))
        fail("skinning needs an output stream for positions (and normals when the mesh has them)");
    dispatch(cmd, skin_, descriptorSet(state.frameData, state.inputs, out), &p, sizeof(p), p.vertexCount);
}

void ComputeDeformer::recordMorph(VkCommandBuffer cmd, GpuDeformState& state,
                                  std::span<const frame::MorphAttributeInputs> attributes,
                                  std::span<const float> weights, int vertexCount, std::uint64_t inputStamp,
                                  const Buffer& out, const Streams& streams) {
    namespace D = m3g::frame;
    const auto n = static_cast<std::size_t>(std::max(vertexCount, 0));
    if (attributes.size() != static_cast<std::size_t>(D::kMorphAttributes))
        fail("recordMorph needs one entry per morph attribute");
    auto outStream = [&](int a) {
        return a == D::kMorphPositions ? streams.positions
               : a == D::kMorphNormals ? streams.normals
               : a == D::kMorphColors  ? streams.colors
                                       : streams.texCoords[static_cast<std::size_t>(a - D::kMorphTexCoords)];
    };
    auto outStride = [&](int a) { return a == D::kMorphColors ? 4u : 3u; };
    std::size_t total = 0;
    for (int a = 0; a < D::kMorphAttributes; ++a) {
        const auto& attr = attributes[static_cast<std::size_t>(a)];
        if (attr.components == 0) continue;
        if (attr.components < 0 || static_cast<std::uint32_t>(attr.components) > outStride(a))
            fail("morph attribute " + std::to_string(a) + " has " + std::to_string(attr.components) + " components");
        const auto size = n * static_cast<std::size_t>(attr.components);
        if (attr.base.size() < size || attr.targets.size() != weights.size())
            fail("morph attribute " + std::to_string(a) + " does not match the vertex or target count");
        for (const auto& t : attr.targets)
            if (t.size() < size) fail("a morph target of attribute " + std::to_string(a) + " is too short");
        if (outStream(a) == kNoStream) fail("morph attribute " + std::to_string(a) + " has no output stream");
        requireRoom(out, outStream(a), n * outStride(a), "morph");
        total += size * (weights.size() + 1);
    }

    if (!state.hasInputs || state.inputStamp != inputStamp) {
        retire(state.inputs);
        state.inputs = ctx_.createHostBuffer(std::max<std::size_t>(total * 4, 16), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        auto* base = static_cast<float*>(state.inputs.mapped);
        std::size_t at = 0;
        for (int a = 0; a < D::kMorphAttributes; ++a) {
            const auto& attr = attributes[static_cast<std::size_t>(a)];
            state.valuesIn[static_cast<std::size_t>(a)] = kNoStream;
            if (attr.components == 0) continue;
            const auto size = n * static_cast<std::size_t>(attr.components);
            state.valuesIn[static_cast<std::size_t>(a)] = elements(at, "the morph inputs");
            copyElements(base + at, attr.base.data(), size);
            at += size;
            for (const auto& t : attr.targets) {
                copyElements(base + at, t.data(), size);
                at += size;
            }
        }
        state.inputStamp = inputStamp;
        state.hasInputs = true;
    }

    void* w = frameData(state, weights.size() * sizeof(float));
    copyElements(w, weights.data(), weights.size());
    VkDescriptorSet set = VK_NULL_HANDLE;
    for (int a = 0; a < D::kMorphAttributes; ++a) {
        const auto& attr = attributes[static_cast<std::size_t>(a)];
        if (attr.components == 0) continue;
        if (!set) set = descriptorSet(state.frameData, state.inputs, out);
        MorphParams p{};
        p.vertexCount = elements(n, "the vertex count");
        p.components = static_cast<std::uint32_t>(attr.components);
        p.targetCount = elements(weights.size(), "the target count");
        p.valuesIn = state.valuesIn[static_cast<std::size_t>(a)];
        p.valuesOut = outStream(a);
        p.outStride = outStride(a);
        p.flags = (a == D::kMorphColors ? MORPH_CLAMP : 0u) | (a == D::kMorphNormals ? MORPH_NORMALIZE : 0u);
        dispatch(cmd, morph_, set, &p, sizeof(p), p.vertexCount);
    }
}

void ComputeDeformer::barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    VkMemoryBarrier2 b{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    b.srcStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    b.srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
    b.dstStageMask = VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT | dstStage;
    b.dstAccessMask = VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT | dstAccess;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);
}

VkCommandBuffer ComputeDeformer::frameCommands() {
    if (recording_) return cmd_;
    if (!cmd_) {
        std::lock_guard lock(ctx_.poolMutex());
        VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        ai.commandPool = ctx_.commandPool();
        ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        ai.commandBufferCount = 1;
        check(vkAllocateCommandBuffers(ctx_.device(), &ai, &cmd_), "vkAllocateCommandBuffers (compute)");
    }
    vkResetCommandBuffer(cmd_, 0);
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cmd_, &bi), "vkBeginCommandBuffer (compute)");
    recording_ = true;
    return cmd_;
}

VkCommandBuffer ComputeDeformer::finishFrame() {
    if (!recording_) return VK_NULL_HANDLE;
    recording_ = false;
    barrier(cmd_);
    check(vkEndCommandBuffer(cmd_), "vkEndCommandBuffer (compute)");
    return cmd_;
}

void ComputeDeformer::endFrame() {
    for (Buffer& b : retired_) ctx_.destroy(b);
    retired_.clear();
    for (std::size_t i = 0; i < pools_.size() && i <= pool_; ++i) vkResetDescriptorPool(ctx_.device(), pools_[i], 0);
    pool_ = 0;
    poolUsed_ = 0;
    ++frame_;
}

}  // namespace m3g::vk
