#include "ComputeBench.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "ComputeRunner.h"
#include "MeshDeformer.h"

namespace m3gcli {

struct ComputeBench::State {
    m3gbench::ComputeRunner runner;
    std::uint64_t stamp = 1;

    explicit State(m3g::vk::Context& c) : runner(c, true) {}

    double difference(std::span<const float> cpu, std::size_t offset) const {
        const float* gpuOut = runner.floats() + offset;
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

std::string ComputeBench::deviceName() const { return s_->runner.ctx.info().name; }

double ComputeBench::lastDispatchSeconds() const { return s_->runner.lastDispatchSeconds(); }

void ComputeBench::reset() {
    s_->runner.deformer.release(s_->runner.state);
    s_->runner.deformer.endFrame();
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
    s_->runner.ensureOutput(w.vertices * 6);
    m3g::vk::ComputeDeformer::Streams streams;
    streams.positions = 0;
    streams.normals = n * 3;
    auto& r = s_->runner;
    r.run([&](VkCommandBuffer cmd) { r.deformer.recordSkin(cmd, r.state, in, s_->stamp, r.out, streams); });
}

void ComputeBench::morphFrame(m3gbench::MorphWorkload& w) {
    using D = m3g::detail::MeshDeformer;
    std::array<m3g::detail::MorphAttributeInputs, D::kMorphAttributes> attributes{};
    attributes[D::kMorphPositions] = {3, w.basePositions, w.targetPositions};
    attributes[D::kMorphNormals] = {3, w.baseNormals, w.targetNormals};
    const auto n = static_cast<std::uint32_t>(w.vertices);
    s_->runner.ensureOutput(w.vertices * 6);
    m3g::vk::ComputeDeformer::Streams streams;
    streams.positions = 0;
    streams.normals = n * 3;
    auto& r = s_->runner;
    r.run([&](VkCommandBuffer cmd) {
        r.deformer.recordMorph(cmd, r.state, attributes, w.weights, static_cast<int>(w.vertices), s_->stamp, r.out,
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
