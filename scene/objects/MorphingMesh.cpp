#include <m3g/MorphingMesh.h>

#include <algorithm>

#include <m3g/AnimationTrack.h>

#include "Check.h"

namespace m3g {

MorphingMesh::MorphingMesh(VertexBuffer* base, std::span<const Ref<VertexBuffer>> targets, IndexBuffer* submesh,
                           Appearance* appearance)
    : Mesh(base, submesh, appearance) {
    initTargets(targets);
}

MorphingMesh::MorphingMesh(VertexBuffer* base, std::span<const Ref<VertexBuffer>> targets,
                           std::span<const Ref<IndexBuffer>> submeshes, std::span<const Ref<Appearance>> appearances)
    : Mesh(base, submeshes, appearances) {
    initTargets(targets);
}

void MorphingMesh::initTargets(std::span<const Ref<VertexBuffer>> targets) {
    const char* where = "MorphingMesh::MorphingMesh";
    if (targets.data() == nullptr) detail::throwNull(where, "targets");
    for (std::size_t i = 0; i < targets.size(); ++i)
        if (!targets[i]) throw NullPointerException(detail::str(where, ": targets[", i, "] is null"));
    if (targets.empty()) detail::throwIAE(detail::str(where, ": targets is empty"));
    targets_.assign(targets.begin(), targets.end());
    weights_.assign(targets_.size(), 0.0f);
}

MorphingMesh::MorphingMesh(const MorphingMesh& other) = default;

MorphingMesh::~MorphingMesh() = default;

Object3D* MorphingMesh::duplicateImpl(DuplicateMap&) const { return new MorphingMesh(*this); }

Ref<VertexBuffer> MorphingMesh::getMorphTarget(int index) const {
    detail::requireIndex(index, getMorphTargetCount(), "MorphingMesh::getMorphTarget", "index");
    return targets_[index];
}

void MorphingMesh::setWeights(std::span<const float> weights) {
    detail::requireArray(weights, weights_.size(), "MorphingMesh::setWeights", "weights");
    std::copy_n(weights.begin(), weights_.size(), weights_.begin());
    touch();
}

void MorphingMesh::getWeights(std::span<float> weights) const {
    detail::requireArray(weights, weights_.size(), "MorphingMesh::getWeights", "weights");
    std::copy(weights_.begin(), weights_.end(), weights.begin());
}

bool MorphingMesh::isAnimatable(int property) const noexcept {
    return property == AnimationTrack::MORPH_WEIGHTS || Mesh::isAnimatable(property);
}

void MorphingMesh::updateProperty(int property, std::span<const float> value) {
    if (property != AnimationTrack::MORPH_WEIGHTS) {
        Mesh::updateProperty(property, value);
        return;
    }
    for (std::size_t i = 0; i < weights_.size(); ++i) weights_[i] = i < value.size() ? value[i] : 0.0f;
    touch();
}

void MorphingMesh::collectReferences(std::vector<Object3D*>& out) const {
    Mesh::collectReferences(out);
    for (const auto& t : targets_) out.push_back(t.get());
}

}  // namespace m3g
