#include "BoneTransforms.h"

#include <algorithm>
#include <bit>
#include <functional>

#include <m3g/Node.h>
#include <m3g/SkinnedMesh.h>

namespace m3g::detail {

namespace {

/// Fibonacci hashing of the node's address (its low bits are alignment).
std::size_t slotOf(const Node* node, std::size_t mask) noexcept {
    return ((std::hash<const Node*>{}(node) * 0x9E3779B97F4A7C15ull) >> 20) & mask;
}

}  // namespace

int BoneTransforms::find(const Node* node) const noexcept {
    const std::size_t mask = table_.size() - 1;
    for (std::size_t i = slotOf(node, mask);; i = (i + 1) & mask) {
        if (table_[i].node == node) return static_cast<int>(table_[i].index);
        if (!table_[i].node) return -1;
    }
}

void BoneTransforms::insert(const Node* node, const Transform& toMesh) {
    if (2 * (toMesh_.size() + 1) > table_.size()) {
        // Grow and rehash (kept across frames: no allocation once the
        // skeleton's size is known).
        std::vector<Slot> previous(table_.size() * 2);
        previous.swap(table_);  // table_ is now the larger, empty one
        const std::size_t mask = table_.size() - 1;
        for (const Slot& s : previous) {
            if (!s.node) continue;
            std::size_t i = slotOf(s.node, mask);
            while (table_[i].node) i = (i + 1) & mask;
            table_[i] = s;
        }
    }
    const std::size_t mask = table_.size() - 1;
    std::size_t i = slotOf(node, mask);
    while (table_[i].node) i = (i + 1) & mask;
    table_[i] = {node, static_cast<std::uint32_t>(toMesh_.size())};
    toMesh_.push_back(toMesh);
}

void BoneTransforms::compute(const SkinnedMesh& mesh, std::vector<float>& out) {
    const int bones = mesh.boneCount();
    out.resize(static_cast<std::size_t>(bones) * 16);
    // Room for a few nodes per bone to start with (cleared every call, so
    // kept small for the common one-bone mesh); insert() grows it.
    const std::size_t start = std::bit_ceil(std::max<std::size_t>(16, 4 * static_cast<std::size_t>(bones)));
    if (table_.size() < start)
        table_.assign(start, Slot{});
    else
        std::fill(table_.begin(), table_.end(), Slot{});
    toMesh_.clear();
    for (int b = 0; b < bones; ++b) {
        const Node* bone = mesh.bone(b);
        // Up from the bone to the mesh, or to a node already composed.
        path_.clear();
        const Node* n = bone;
        int known = -1;
        while (n && n != &mesh && (known = find(n)) < 0) {
            path_.push_back(n);
            n = n->parentNode();
        }
        Transform m;
        if (!n) {
            // Not under the mesh (Group::removeChild refuses to detach a
            // bone, so only a future way of moving one would get here): the
            // general path, through the common ancestor with an inverse.
            bone->getTransformTo(&mesh, &m);
        } else {
            // Down again: (node -> mesh) = (parent -> mesh) x composite.
            bool identity = known < 0;
            if (!identity) m = toMesh_[static_cast<std::size_t>(known)];
            for (auto it = path_.rbegin(); it != path_.rend(); ++it) {
                const Transform c = (*it)->compositeTransform();
                m = identity ? c : m * c;
                identity = false;
                insert(*it, m);
            }
        }
        std::copy(m.rows().begin(), m.rows().end(), out.begin() + static_cast<std::ptrdiff_t>(b) * 16);
    }
}

}  // namespace m3g::detail
