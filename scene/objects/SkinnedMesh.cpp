#include <m3g/SkinnedMesh.h>

#include <m3g/skin/InfluenceTable.h>

#include <algorithm>

#include <m3g/Limits.h>
#include <m3g/World.h>

#include "Check.h"

namespace m3g {

SkinnedMesh::SkinnedMesh(VertexBuffer* vertices, IndexBuffer* submesh, Appearance* appearance, Group* skeleton)
    : Mesh(vertices, submesh, appearance), table_(std::make_unique<skin::InfluenceTable>(getLimits().maxTransformsPerVertex)) {
    attachSkeleton(skeleton);
}

SkinnedMesh::SkinnedMesh(VertexBuffer* vertices, std::span<const Ref<IndexBuffer>> submeshes,
                         std::span<const Ref<Appearance>> appearances, Group* skeleton)
    : Mesh(vertices, submeshes, appearances), table_(std::make_unique<skin::InfluenceTable>(getLimits().maxTransformsPerVertex)) {
    attachSkeleton(skeleton);
}

void SkinnedMesh::attachSkeleton(Group* skeleton) {
    const char* where = "SkinnedMesh::SkinnedMesh";
    detail::requireNonNull(skeleton, where, "skeleton");
    if (dynamic_cast<World*>(skeleton)) detail::throwIAE(detail::str(where, ": the skeleton cannot be a World"));
    if (skeleton->parentNode())
        detail::throwIAE(detail::str(where, ": the skeleton already has a parent (remove it from that first)"));
    skeleton_ = skeleton;
    static_cast<Node*>(skeleton)->setParent(this);
}

SkinnedMesh::SkinnedMesh(const SkinnedMesh& other)
    : Mesh(other),
      bones_(other.bones_),
      atRest_(other.atRest_),
      boneIndex_(other.boneIndex_),
      table_(std::make_unique<skin::InfluenceTable>(*other.table_)),
      added_(other.added_) {}

SkinnedMesh::~SkinnedMesh() {
    for (const auto& b : bones_) b->removeBoneOwner(this);
    if (skeleton_) static_cast<Node*>(skeleton_.get())->setParent(nullptr);
}

Object3D* SkinnedMesh::duplicateImpl(DuplicateMap& map) const {
    auto* copy = new SkinnedMesh(*this);
    try {
        auto* skeleton = static_cast<Group*>(duplicateInto(skeleton_.get(), map));
        copy->skeleton_ = skeleton;
        static_cast<Node*>(skeleton)->setParent(copy);
    } catch (...) {
        delete copy;
        throw;
    }
    return copy;
}

void SkinnedMesh::remapReferences(const DuplicateMap& map) {
    Mesh::remapReferences(map);
    // The bones of a copy still point into the original skeleton: move them
    // to the copied nodes and register this mesh as their owner.
    boneIndex_.clear();
    for (std::size_t i = 0; i < bones_.size(); ++i) {
        if (auto it = map.find(bones_[i].get()); it != map.end()) bones_[i] = static_cast<Node*>(it->second);
        bones_[i]->addBoneOwner(this);
        boneIndex_[bones_[i].get()] = static_cast<int>(i);
    }
}

void SkinnedMesh::collectChildren(std::vector<Node*>& out) const {
    if (skeleton_) out.push_back(skeleton_.get());
}

void SkinnedMesh::collectReferences(std::vector<Object3D*>& out) const {
    Mesh::collectReferences(out);
    if (skeleton_) out.push_back(skeleton_.get());
}

int SkinnedMesh::boneIndex(const Node* node) const noexcept {
    auto it = boneIndex_.find(node);
    return it == boneIndex_.end() ? -1 : it->second;
}

void SkinnedMesh::requireInSkeleton(const Node* bone, const char* where) const {
    detail::requireNonNull(bone, where, "bone");
    if (!bone->isDescendantOf(skeleton_.get()))
        detail::throwIAE(detail::str(where, ": the ", bone->getClassName(),
                                     " is not the skeleton of this mesh or one of its descendants"));
}

void SkinnedMesh::addTransform(Node* bone, int weight, int firstVertex, int numVertices) {
    const char* where = "SkinnedMesh::addTransform";
    requireInSkeleton(bone, where);
    if (weight <= 0) detail::throwIAE(detail::str(where, ": weight ", weight, " must be positive"));
    if (numVertices <= 0) detail::throwIAE(detail::str(where, ": numVertices ", numVertices, " must be positive"));
    if (firstVertex < 0 || static_cast<long long>(firstVertex) + numVertices > 65535)
        throw IndexOutOfBoundsException(detail::str(where, ": vertices [", firstVertex, ", ",
                                                    static_cast<long long>(firstVertex) + numVertices,
                                                    ") out of range [0, 65535]"));
    int index = boneIndex(bone);
    if (index < 0) {
        // First use of this bone: capture the at-rest matrix (mesh -> bone)
        // before changing anything, so a singular matrix leaves no trace.
        Transform atRest;
        getTransformTo(bone, &atRest);
        index = static_cast<int>(bones_.size());
        bones_.emplace_back(bone);
        atRest_.push_back(atRest);
        boneIndex_[bone] = index;
        bone->addBoneOwner(this);
    }
    table_->add(index, weight, firstVertex, numVertices);
    added_.push_back({index, weight, firstVertex, numVertices});
    touch();
}

void SkinnedMesh::getBoneTransform(Node* bone, Transform* transform) const {
    const char* where = "SkinnedMesh::getBoneTransform";
    detail::requireNonNull(transform, where, "transform");
    requireInSkeleton(bone, where);
    const int index = boneIndex(bone);
    if (index >= 0) *transform = atRest_[index];
}

int SkinnedMesh::getBoneVertices(Node* bone, std::span<int> indices, std::span<float> weights) const {
    const char* where = "SkinnedMesh::getBoneVertices";
    requireInSkeleton(bone, where);
    const int index = boneIndex(bone);
    if (index < 0) return 0;
    std::vector<int> vertices;
    std::vector<float> w;
    const int count = table_->boneVertices(index, &vertices, &w);
    const auto n = static_cast<std::size_t>(count);
    if (indices.data() != nullptr) {
        if (indices.size() < n)
            detail::throwIAE(detail::str(where, ": indices has length ", indices.size(), ", needs at least ", n));
    }
    if (weights.data() != nullptr) {
        if (weights.size() < n)
            detail::throwIAE(detail::str(where, ": weights has length ", weights.size(), ", needs at least ", n));
    }
    if (indices.data() != nullptr) std::copy(vertices.begin(), vertices.end(), indices.begin());
    if (weights.data() != nullptr) std::copy(w.begin(), w.end(), weights.begin());
    return count;
}

}  // namespace m3g
