// Per-vertex bone influences of a SkinnedMesh, built incrementally by
// SkinnedMesh::addTransform (the founding paper's idea: the per-vertex weight
// bookkeeping is done when a transform is added, never at render time).
//
// Storage is structure-of-arrays, N slots per vertex (N = maxTransformsPerVertex):
//   bone(v, k)   bone index (0-based, in order of first use) or -1 for an empty slot
//   weight(v, k) normalised weight: the slot's accumulated integer weight divided
//                by the sum over the vertex's N selected slots; slots 0..count(v)-1
//                are filled, sorted by descending weight (ties: lower bone index first)
// Memory is V*N for the table plus a sparse list only for vertices that ever had
// more than N distinct bones (needed to keep the top-N selection exact when
// later calls change the accumulated weights).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

namespace m3g::skin {

class InfluenceTable {
public:
    /// `maxInfluences` = N (>= 1).
    explicit InfluenceTable(int maxInfluences = 4);

    int maxInfluences() const noexcept { return n_; }
    /// Number of vertices with storage (grows on demand, up to 65535).
    int vertexCount() const noexcept { return vertexCount_; }
    /// Number of distinct bones registered.
    int boneCount() const noexcept { return boneCount_; }

    /// Adds `weight` (> 0) of bone `bone` (0 <= bone, a dense index) to every
    /// vertex in [first, first + count). Accumulates onto an existing slot of
    /// the same bone; otherwise keeps the N largest accumulated weights per
    /// vertex. Tie rule (deterministic): among equal accumulated weights the
    /// bone added first (lower bone index) wins. Renormalises only the touched
    /// vertices.
    void add(int bone, std::int32_t weight, int first, int count);

    /// Number of filled slots of vertex v (0 if v >= vertexCount()).
    int count(int v) const noexcept;
    int bone(int v, int k) const noexcept { return bones_[static_cast<std::size_t>(v) * n_ + k]; }
    float weight(int v, int k) const noexcept { return weights_[static_cast<std::size_t>(v) * n_ + k]; }

    /// Raw SoA arrays (size vertexCount() * maxInfluences()) for kernels and GPU upload.
    std::span<const std::int32_t> bones() const noexcept { return bones_; }
    std::span<const float> weights() const noexcept { return weights_; }

    /// Vertices influenced by `bone` (among the selected N slots) and their
    /// normalised weights, in vertex order. Returns the count.
    int boneVertices(int bone, std::vector<int>* vertices, std::vector<float>* weights) const;

    /// The one bone that every vertex in [0, vertices) follows, with weight
    /// 1 (one filled slot each, the same bone), or -1 (some vertex blends
    /// bones, follows another bone or none, or `vertices` is 0). Such a
    /// rigid binding deforms every vertex by one affine map. O(vertices).
    int rigidBone(std::size_t vertices) const noexcept;

    /// Incremented by every add(); lets a renderer know the table changed.
    std::uint32_t revision() const noexcept { return revision_; }

private:
    struct Influence { std::int32_t bone; std::int64_t weight; };
    void ensureVertices(int count);
    void rebuildVertex(int v);

    int n_;
    int vertexCount_ = 0;
    int boneCount_ = 0;
    std::uint32_t revision_ = 0;
    std::vector<std::int32_t> bones_;    // V*N, -1 = empty
    std::vector<float> weights_;          // V*N, normalised
    std::vector<std::int64_t> raw_;       // V*N, accumulated integer weights of the slots
    // Vertices that have ever had more than N distinct bones: every (bone, weight).
    std::unordered_map<int, std::vector<Influence>> overflow_;
};

}  // namespace m3g::skin
