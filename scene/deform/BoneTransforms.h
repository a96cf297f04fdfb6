// The bone -> mesh transforms of a SkinnedMesh's bones, once per frame, with
// each node on the bones' paths to the mesh composed once (bones share their
// ancestors: a hand's path runs through the arm, the spine, the skeleton
// group), and only when it or a node above it changed since the last call.
//
// The paths are fixed while the mesh lives: a bone is in the mesh's skeleton
// (SkinnedMesh::addTransform checks it) and Group::removeChild refuses to
// detach a node that is or holds a bone of a SkinnedMesh above it, so the
// nodes between the bones and the mesh are listed once, parent first, and
// walked per call. A node's Object3D revision is bumped by every change of
// its transform (Transformable's setters, animate()), so a node whose
// revision and parent's transform are the ones of the last call keeps its
// transform, bit for bit, without composing it again; one whose own
// transform was the identity at its revision takes its parent's as it is.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <m3g/Transform.h>

namespace m3g {
class Node;
class SkinnedMesh;
}

namespace m3g::detail {

class BoneTransforms {
public:
    /// out[16 b .. 16 b + 16): bone b's transform to `mesh`, row-major, as
    /// Node::getTransformTo(mesh) gives it (up to float rounding: the
    /// products are associated top-down). A bone that is not a descendant of
    /// the mesh takes getTransformTo itself, every call. Resizes `out` to 16
    /// floats per bone. Returns false when no bone's transform can have
    /// changed since the last call for the same mesh (`out` then holds the
    /// same values); changedBones() tells which bones may have.
    bool compute(const SkinnedMesh& mesh, std::vector<float>& out);

    /// Per bone of the last compute(): 1 where its transform was composed
    /// again (it or a node above it changed, or the paths were rebuilt), else
    /// 0. A 1 is no promise that the value differs (a setter may write the
    /// same value).
    std::span<const std::uint8_t> changedBones() const noexcept { return changed_; }

private:
    /// Lists the nodes of every bone's path to `mesh`, parent first.
    void build(const SkinnedMesh& mesh);

    struct PathNode {
        const Node* node = nullptr;
        const Node* parent = nullptr;  // its parent when the paths were listed
        int parentIndex = -1;          // in nodes_, or -1 when the parent is the mesh
        std::uint32_t revision = 0;    // the node's revision at its last composition
        bool dirty = true;             // composed again by this call
        bool identity = false;         // its composite at that revision was the identity
    };
    std::vector<PathNode> nodes_;
    std::vector<Transform> toMesh_;   // per node of nodes_
    std::vector<int> boneNode_;       // per bone: index in nodes_, or -1 (not under the mesh)
    std::vector<std::uint8_t> changed_;
    std::uint64_t meshId_ = 0;
    bool built_ = false;
};

}  // namespace m3g::detail
