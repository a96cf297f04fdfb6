// The bone -> mesh transforms of a SkinnedMesh's bones, once per frame, with
// each node on the bones' paths to the mesh composed once (bones share their
// ancestors: a hand's path runs through the arm, the spine, the skeleton
// group). Node::getTransformTo per bone recomposed every ancestor for every
// bone, and walked the common-ancestor search in O(depth^2).
#pragma once

#include <cstddef>
#include <cstdint>
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
    /// the mesh would take getTransformTo itself. Resizes `out` to 16 floats
    /// per bone; allocates only when the number of nodes grows.
    void compute(const SkinnedMesh& mesh, std::vector<float>& out);

private:
    /// Index of `node`'s memoised transform, or -1.
    int find(const Node* node) const noexcept;
    void insert(const Node* node, const Transform& toMesh);

    struct Slot {
        const Node* node = nullptr;
        std::uint32_t index = 0;
    };
    std::vector<Slot> table_;        // open addressing, power-of-two size, under half full
    std::vector<Transform> toMesh_;  // per memoised node, this frame
    std::vector<const Node*> path_;  // a bone's nodes not yet memoised, bottom up
};

}  // namespace m3g::detail
