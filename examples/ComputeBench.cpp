#include "ComputeBench.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "ComputeDeformer.h"
#include "Context.h"
#include "MeshDeformer.h"

namespace m3gcli {

struct ComputeBench::State {
    m3g::vk::Context& ctx;
    m3g::vk::ComputeDeformer deformer;
    m3g::vk::GpuDeformState gpu;
    m3g::vk::Buffer out;
    std::uint64_t stamp = 1;
    // Device time of the last frame's dispatches (timestamps around them),
    // when the queue has timestamps.
    VkQueryPool timestamps = VK_NULL_HANDLE;
    double lastDispatchSeconds = -1.0;

    explicit State(m3g::vk::Context& c) : ctx(c), deformer(c) {
        const auto& limits = ctx.properties().limits;
        std::uint32_t families = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice(), &families, nullptr);
        std::vector<VkQueueFamilyProperties> props(families);
        vkGetPhysicalDeviceQueueFamilyProperties(ctx.physicalDevice(), &families, props.data());
        if (limits.timestampPeriod > 0 && props[ctx.queueFamily()].timestampValidBits > 0) {
            VkQueryPoolCreateInfo qi{};
            qi.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
            qi.queryType = VK_QUERY_TYPE_TIMESTAMP;
            qi.queryCount = 2;
            m3g::vk::check(vkCreateQueryPool(ctx.device(), &qi, nullptr, &timestamps), "vkCreateQueryPool");
        }
    }
    ~State() {
        vkDeviceWaitIdle(ctx.device());
        deformer.release(gpu);
        deformer.endFrame();
        ctx.destroy(out);
        if (timestamps) vkDestroyQueryPool(ctx.device(), timestamps, nullptr);
    }
    void ensureOutput(std::size_t floats) {
        if (out.buffer && out.size >= floats * sizeof(float)) return;
        ctx.destroy(out);
        out = ctx.createHostBuffer(floats * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    }
    template <class Record>
    void run(Record&& record) {
        ctx.submitNow([&](VkCommandBuffer cmd) {
            if (timestamps) {
                vkCmdResetQueryPool(cmd, timestamps, 0, 2);
                vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, timestamps, 0);
            }
            record(cmd);
            if (timestamps) vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, timestamps, 1);
            m3g::vk::ComputeDeformer::barrier(cmd, VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        });
        deformer.endFrame();
        lastDispatchSeconds = -1.0;
        std::uint64_t ticks[2];
        if (timestamps && vkGetQueryPoolResults(ctx.device(), timestamps, 0, 2, sizeof(ticks), ticks, sizeof(std::uint64_t),
                                                VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS)
            lastDispatchSeconds =
                static_cast<double>(ticks[1] - ticks[0]) * ctx.properties().limits.timestampPeriod * 1e-9;
    }
    double difference(std::span<const float> cpu, std::size_t offset) const {
        const auto* gpuOut = static_cast<const float*>(out.mapped) + offset;
        double worst = 0.0;
        for (std::size_t i = 0; i < cpu.size(); ++i)
            worst = std::max(worst, std::abs(double(gpuOut[i]) - cpu[i]) / std::max(1.0, std::abs(double(cpu[i]))));
        return worst;
    }
};

std::unique_ptr<ComputeBench> ComputeBench::create(std::string& why) {
    try {
        return std::unique_ptr<ComputeBench>(new ComputeBench(std::make_unique<State>(m3g::vk::Context::get())));
    } catch (const std::exception& e) {
        why = e.what();
        return nullptr;
    }
}

ComputeBench::ComputeBench(std::unique_ptr<State> state) : s_(std::move(state)) {}
ComputeBench::~ComputeBench() = default;

std::string ComputeBench::deviceName() const { return s_->ctx.info().name; }

double ComputeBench::lastDispatchSeconds() const { return s_->lastDispatchSeconds; }

void ComputeBench::reset() {
    s_->deformer.release(s_->gpu);
    s_->deformer.endFrame();
    ++s_->stamp;
}

void ComputeBench::skinFrame(m3gbench::SkinWorkload& w) {
    // The palette on the CPU, once per bone, as the renderer computes it.
    m3g::skin::PaletteJob pj;
    pj.boneCount = static_cast<std::size_t>(w.bones);
    pj.boneToMesh = w.boneToMesh;
    pj.atRest = w.atRest;
    pj.output = w.palette;
    pj.run();
    m3g::detail::SkinInputs in;
    in.vertexCount = static_cast<int>(w.vertices);
    in.positions = w.positions;
    in.normals = w.normals;
    in.influenceStride = m3gbench::SkinWorkload::kMaxInfluences;
    in.bones = w.boneIndices;
    in.weights = w.boneWeights;
    in.palette = w.palette;
    const auto n = static_cast<std::uint32_t>(w.vertices);
    s_->ensureOutput(w.vertices * 6);
    m3g::vk::ComputeDeformer::Streams streams;
    streams.positions = 0;
    streams.normals = n * 3;
    s_->run([&](VkCommandBuffer cmd) { s_->deformer.recordSkin(cmd, s_->gpu, in, s_->stamp, s_->out, streams); });
}

void ComputeBench::morphFrame(m3gbench::MorphWorkload& w) {
    using D = m3g::detail::MeshDeformer;
    std::array<m3g::detail::MorphAttributeInputs, D::kMorphAttributes> attributes{};
    attributes[D::kMorphPositions] = {3, w.basePositions, w.targetPositions};
    attributes[D::kMorphNormals] = {3, w.baseNormals, w.targetNormals};
    const auto n = static_cast<std::uint32_t>(w.vertices);
    s_->ensureOutput(w.vertices * 6);
    m3g::vk::ComputeDeformer::Streams streams;
    streams.positions = 0;
    streams.normals = n * 3;
    s_->run([&](VkCommandBuffer cmd) {
        s_->deformer.recordMorph(cmd, s_->gpu, attributes, w.weights, static_cast<int>(w.vertices), s_->stamp, s_->out,
                                 streams);
    });
}

double ComputeBench::skinDifference(const m3gbench::SkinWorkload& w) const {
    return std::max(s_->difference(w.outPositions, 0), s_->difference(w.outNormals, w.vertices * 3));
}

double ComputeBench::morphDifference(const m3gbench::MorphWorkload& w) const {
    return std::max(s_->difference(w.outPositions, 0), s_->difference(w.outNormals, w.vertices * 3));
}

}  // namespace m3gcli
