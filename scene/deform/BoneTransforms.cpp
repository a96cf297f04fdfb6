#include "BoneTransforms.h"

#include <algorithm>
#include <cstring>
#include <unordered_map>

#include <m3g/Node.h>
#include <m3g/SkinnedMesh.h>

namespace m3g::detail {

namespace {

constexpr int kNotUnderMesh = -1;  // boneNode_: the general path
constexpr int kIsMesh = -2;        // boneNode_: the identity

}  // namespace

void BoneTransforms::build(const SkinnedMesh& mesh) {
    nodes_.clear();
    const auto bones = static_cast<std::size_t>(mesh.boneCount());
    boneNode_.assign(bones, kNotUnderMesh);
    std::unordered_map<const Node*, int> index;  // only here: paths change with the mesh or its bones
    std::vector<const Node*> path;
    for (std::size_t b = 0; b < bones; ++b) {
        const Node* bone = mesh.bone(static_cast<int>(b));
        // Up from the bone to the mesh, or to a node already listed.
        path.clear();
        const Node* n = bone;
        int known = -1;
        while (n && n != &mesh) {
            if (auto it = index.find(n); it != index.end()) {
                known = it->second;
                break;
            }
            path.push_back(n);
            n = n->parentNode();
        }
        if (!n) continue;  // not under the mesh: getTransformTo each call
        if (path.empty() && known < 0) {
            boneNode_[b] = kIsMesh;
            continue;
        }
        // Down again, parent first.
        int parent = known;
        for (auto it = path.rbegin(); it != path.rend(); ++it) {
            PathNode p;
            p.node = *it;
            p.parent = (*it)->parentNode();
            p.parentIndex = parent;
            parent = static_cast<int>(nodes_.size());
            index.emplace(*it, parent);
            nodes_.push_back(p);
        }
        boneNode_[b] = parent;
    }
    toMesh_.resize(nodes_.size());
    meshId_ = mesh.getObjectId();
    built_ = true;
}

bool BoneTransforms::compute(const SkinnedMesh& mesh, std::vector<float>& out) {
    const auto bones = static_cast<std::size_t>(mesh.boneCount());
    // The paths are listed again for another mesh or a new bone
    // (addTransform), and, should a node on them ever have been moved, when
    // a parent differs from the listed one (checked on the walk).
    bool force = !built_ || mesh.getObjectId() != meshId_ || boneNode_.size() != bones || out.size() != bones * 16;
    if (force) build(mesh);
    out.resize(bones * 16);
    changed_.resize(bones);
    bool any = false;
    for (bool walked = false; !walked;) {
        walked = true;
        for (PathNode& p : nodes_) {
            if (p.node->parentNode() != p.parent) {
                build(mesh);
                force = true;
                walked = false;
                break;
            }
            const std::uint32_t revision = p.node->getRevision();
            const bool parentDirty = p.parentIndex >= 0 && nodes_[static_cast<std::size_t>(p.parentIndex)].dirty;
            const bool own = force || revision != p.revision;
            p.dirty = own || parentDirty;
            if (!p.dirty) continue;
            p.revision = revision;
            // (node -> mesh) = (parent -> mesh) x composite, the same
            // association as composing the path top-down. A node whose own
            // transform is the identity (exporters' bone nodes under an
            // animated joint often are) passes its parent's on: the product
            // with the identity is that matrix.
            const auto i = static_cast<std::size_t>(&p - nodes_.data());
            if (!own && p.identity) {  // dirty through its parent only, so it has one in nodes_
                toMesh_[i] = toMesh_[static_cast<std::size_t>(p.parentIndex)];
                continue;
            }
            const Transform composite = p.node->compositeTransform();
            if (own) p.identity = composite == Transform();
            toMesh_[i] = p.parentIndex < 0 ? composite : toMesh_[static_cast<std::size_t>(p.parentIndex)] * composite;
        }
    }
    Transform general;  // outside the loop: a Transform's constructor writes the identity
    for (std::size_t b = 0; b < bones; ++b) {
        const int node = boneNode_[b];
        const Transform* m = nullptr;
        if (node >= 0) {
            if (!nodes_[static_cast<std::size_t>(node)].dirty) {
                changed_[b] = 0;
                continue;
            }
            m = &toMesh_[static_cast<std::size_t>(node)];
        } else if (node == kNotUnderMesh) {
            // Not under the mesh (Group::removeChild refuses to detach a
            // bone, so only a future way of moving one would get here): the
            // general path, through the common ancestor with an inverse.
            mesh.bone(static_cast<int>(b))->getTransformTo(&mesh, &general);
            m = &general;
        } else {
            if (!force) {
                changed_[b] = 0;
                continue;
            }
            general = Transform();  // the mesh itself: the identity
            m = &general;
        }
        changed_[b] = 1;
        any = true;
        // A fixed 64 bytes: inlined, where std::copy called memmove.
        std::memcpy(out.data() + b * 16, m->rows().data(), sizeof(float) * 16);
    }
    return any;
}

}  // namespace m3g::detail
