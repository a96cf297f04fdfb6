// Linear blend skinning of positions and normals (JSR-184 1.1, SkinnedMesh):
//   p' = sum_k w_k * P[b_k] * (s * p + bias)        (P: PaletteEntry::position)
//   n' = normalise(sum_k w_k * N[b_k] * n)          (N: PaletteEntry::normal)
// over a list of vertices that all use the same number of influences, the
// way ozz-animation's SkinningJob works: a struct of spans and strides,
// validate(), run(), no memory of its own. InfluencePartition groups a
// mesh's vertices by influence count so that each group runs the kernel
// specialised for it (1, 2, 3, 4; a generic loop above 4; a copy for 0).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <m3g/skin/Isa.h>
#include <m3g/skin/Palette.h>

namespace m3g::skin {

class InfluenceTable;
class ThreadPool;

/// Consecutive vertices [firstVertex, firstVertex + vertexCount) that all have
/// the same influences (bone and weight bit patterns of every used slot):
/// what SkinnedMesh::addTransform ranges give. The kernels blend the run's
/// palette entries once and read no per-vertex influence data for it.
/// `start` is the run's first position in its job's run sequence: the sum of
/// the counts of the runs before it (SkinningJob::validate checks this), so
/// that a chunk of the sequence finds its run by binary search.
struct InfluenceRun {
    std::uint32_t firstVertex = 0;
    std::uint32_t vertexCount = 0;
    std::uint32_t start = 0;
};

struct SkinningJob {
    /// The vertices to process (indices into the per-vertex arrays below).
    /// Each index must be < vertexCount. Order and duplicates are allowed;
    /// every listed vertex's output is a function of its inputs only.
    std::span<const std::uint32_t> vertices;
    /// Number of vertices in the per-vertex arrays.
    std::size_t vertexCount = 0;
    /// More vertices to process, as runs sharing their influences (built by
    /// InfluencePartition). Every vertex of a run gets the influences of the
    /// run's first vertex: a run whose vertices differ is computed with the
    /// first one's slots for all (still never read or written out of bounds).
    std::span<const InfluenceRun> runs;
    /// More vertices, as runs sharing their bones but each with its own
    /// weights (InfluencePartition::compactBoneRuns): a vertex of a bone run
    /// is skinned with the bones of the run's first vertex and its own
    /// weights. The AVX-512 kernel blends sixteen such vertices' matrices at
    /// once from the run's palette entries; the other paths take them as a
    /// vertex list (each with its own slots, the same bones in a valid run).
    std::span<const InfluenceRun> boneRuns;
    /// Influences used per listed vertex: slots 0 .. influenceCount-1.
    /// 0 means "no bone": the vertex stays in mesh space (s * p + bias, the
    /// normal renormalised), as Nokia's M3G implementation (reference)
    /// leaves it.
    int influenceCount = 0;
    /// Slot k of vertex v is at [v * influenceStride + k] in boneIndices and
    /// boneWeights (InfluenceTable's layout: influenceStride = N).
    int influenceStride = 0;
    /// Bone (palette) index per slot. A used slot whose index is outside the
    /// palette (-1 = empty, or anything else out of range) contributes
    /// nothing: run() never reads outside the palette.
    std::span<const std::int32_t> boneIndices;
    /// Weight per slot, already normalised (the kernel does not divide).
    std::span<const float> boneWeights;
    std::span<const PaletteEntry> palette;
    /// The caller's word that the palette is conformal (PaletteJob::conformal:
    /// every bone a rotation times one common scale). The bone-run kernels
    /// (AVX-512, AVX2) then blend each lane's position rows only and take
    /// the normal through their 3x3, renormalised, so the common multiple
    /// cancels: half the per-lane blend, normals within kConformalTolerance
    /// of the normal rows' result, positions the same bits. Other paths
    /// ignore it. Set for a palette that is not conformal, normals come out
    /// wrong (finite, nothing read or written out of bounds).
    bool normalsFromPositions = false;

    /// Applied to the input positions before skinning (VertexBuffer's
    /// position scale and bias). Faster left at 1 and 0 with the palette
    /// made with them instead (PaletteJob::positionScale, as MeshDeformer
    /// does): the run kernel then folds nothing per run. Vertices without
    /// influence (influenceCount 0) still need them here.
    float positionScale = 1.0f;
    std::array<float, 3> positionBias{0.0f, 0.0f, 0.0f};

    /// xyz of vertex v at [v * stride]; strides in floats, >= 3.
    std::span<const float> inPositions;
    std::size_t inPositionStride = 3;
    /// Empty: no normals (outNormals must be empty too).
    std::span<const float> inNormals;
    std::size_t inNormalStride = 3;
    std::span<float> outPositions;
    std::size_t outPositionStride = 3;
    std::span<float> outNormals;
    std::size_t outNormalStride = 3;

    /// Optional: the same input positions and normals once more as planes,
    /// x of vertices 0 .. vertexCount-1, then their y, then their z
    /// (3 * vertexCount floats each). Inputs are static while a mesh's
    /// vertices are (MeshDeformer makes the planes when they change), so the
    /// lane kernels of runs and bone runs (Isa::Avx2 eight lanes,
    /// Isa::Avx512 sixteen) then read a block's x, y and z with three loads
    /// instead of transposing its xyz triples each frame; outputs are the
    /// same bits. Used only when both are given (normals present) and the
    /// arrays are packed (strides 3); every other path (the vertex lists,
    /// Scalar, SSE2) reads inPositions and inNormals. The contents must be
    /// theirs: validate() checks sizes, not values.
    std::span<const float> inPositionPlanes;
    std::span<const float> inNormalPlanes;

    /// Which code path runs; an unsupported one makes validate() false.
    Isa isa = Isa::Auto;

    /// Checks sizes and strides: every per-vertex array holds vertexCount
    /// vertices at its stride (strides >= 3), normals are both present or
    /// both absent, influenceCount <= influenceStride, the influence arrays
    /// reach the listed vertices, every listed vertex is < vertexCount (one
    /// max reduction over the list), every run lies inside the arrays with
    /// consistent `start` values (runs and boneRuns each counted from 0),
    /// planes given hold 3 * vertexCount floats (normal planes only with
    /// normals), and the ISA is supported. The bone
    /// indices are not scanned (see boneIndices). Like ozz-animation, cheap
    /// enough to run on every call.
    bool validate() const noexcept;
    /// validate(), then skins every listed vertex. Returns validate().
    bool run() const noexcept;
    /// validate() once, then runs the list, the runs and the bone runs, in chunks of
    /// `grain` vertices on `pool`. The chunks do not depend on the pool's
    /// size and each vertex is computed the same way in any chunk, so the
    /// output is bit-identical to run() for any thread count.
    bool runParallel(ThreadPool& pool, std::size_t grain = 4096) const noexcept;
};

/// A mesh's vertices grouped by influence count (number of filled slots of
/// an InfluenceTable-layout bone array: slots are filled from 0, -1 = empty),
/// ascending vertex order within a group. Vertices beyond the table have no
/// influence. With weights, each group (count >= 1) is further split into
/// runs of at least kMinRun consecutive vertices with the same slots
/// (InfluenceRun) and the loose vertices left over, which is what a
/// SkinningJob takes. Rebuilt only when the table changes (the paper's
/// bookkeeping at addTransform time, not per frame); reuses its storage.
class InfluencePartition {
public:
    /// Shortest run kept as a run: half an eight-lane block of the AVX2
    /// kernel (from four vertices on, one blend per run costs no more than
    /// the loose path's blend per vertex; BM_SkinRunLength).
    static constexpr std::size_t kMinRun = 4;
    /// build()'s `minRun` for a caller that skins only the compact space
    /// (MeshDeformer): no run of the mesh's order is kept in place, so every
    /// vertex with influences is in the compact space, where the vertices
    /// of one influence set form one run however the mesh interleaves them
    /// (docs/skinning.md).
    static constexpr std::size_t kNoInPlaceRuns = static_cast<std::size_t>(-1);

    /// Groups vertices [0, vertexCount). `boneIndices` holds
    /// tableVertexCount * stride slots (tableVertexCount may be smaller or
    /// larger than vertexCount). No runs: loose(c) is group(c).
    void build(std::span<const std::int32_t> boneIndices, int stride, std::size_t vertexCount);
    /// The same, and runs of `minRun` or more (>= kMinRun) found by
    /// comparing the bones and `boneWeights` (same layout and size as
    /// boneIndices) of neighbouring vertices. In the compact space, a run
    /// shorter than `runBlock` vertices is kept as a run only where it is
    /// the whole of its set of bones; otherwise its vertices join the set's
    /// bone run (runBlock(isa) says why; 0, the default, keeps every run of
    /// kMinRun or more).
    void build(std::span<const std::int32_t> boneIndices, std::span<const float> boneWeights, int stride,
               std::size_t vertexCount, std::size_t minRun = kMinRun, std::size_t runBlock = 0);

    /// build()'s `runBlock` for the kernels of `isa` (resolved; Auto is
    /// resolved here): the vertices of one block of its run kernel (16 for
    /// Avx512, 8 for Avx2), 0 where it has no bone-run kernel (Sse2,
    /// Scalar, which take bone runs as vertex lists). A run shorter than a
    /// block costs its blend and a whole block however few its vertices;
    /// beside a bone run of the same bones, the bone run takes them in the
    /// lanes its own blocks leave over (test.m3g's two- and three-bone
    /// sets: runs of 4-7 vertices beside bone runs; docs/skinning.md).
    static std::size_t runBlock(Isa isa) noexcept;

    /// The partition as MeshDeformer skins `table`'s first `vertexCount`
    /// vertices on the kernels of `isa`: every vertex with influences in
    /// the compact space (kNoInPlaceRuns), short runs placed by
    /// runBlock(isa). What `m3g info` and the benchmarks report too.
    void buildForKernels(const InfluenceTable& table, std::size_t vertexCount, Isa isa = Isa::Auto);

    /// Largest group index (= stride after build()).
    int maxInfluences() const noexcept { return static_cast<int>(offsets_.size()) - 2; }
    /// Vertices with exactly `count` influences (empty for count out of range).
    std::span<const std::uint32_t> group(int count) const noexcept;
    /// The vertices of group(count) that are in no run, ascending.
    std::span<const std::uint32_t> loose(int count) const noexcept;
    /// The runs of group(count), ascending, `start` counted from 0.
    std::span<const InfluenceRun> runs(int count) const noexcept;

    // ---- Compact space (built with weights only) ----
    // The loose vertices of every group with at least one influence, in a
    // space of their own where they are sorted by influence set (bones,
    // then weight bit patterns, slot by slot), so that vertices with the
    // same slots that are not neighbours in the mesh (exporters interleave
    // the vertices of different bones) become runs there and are blended
    // once; vertices sharing only their bones become bone runs; the rest
    // stay loose but consecutive, which the list kernel takes in packed
    // blocks. Slots keep the table's order. Built with the groups,
    // when the table changes (never per frame). A caller gathers the inputs
    // into compact order when they change (compactOrder()[i] is the mesh
    // vertex at compact position i) and skins the compact arrays; the
    // outputs are in compact order (MeshDeformer keeps them so and its
    // consumers draw through the permutation), or written back to their
    // mesh vertices with scatterXyz.

    /// Mesh vertex of each compact position (each loose vertex once).
    std::span<const std::uint32_t> compactOrder() const noexcept { return compactOrder_; }
    /// The compact influence table, stride as the table's:
    /// compactOrder().size() * stride slots.
    std::span<const std::int32_t> compactBones() const noexcept { return compactBones_; }
    std::span<const float> compactWeights() const noexcept { return compactWeights_; }
    /// Runs, bone runs and loose positions (compact indices) of the compact
    /// vertices with `count` influences, which they cover once: runs share
    /// every slot; bone runs (kMinRun vertices or more) share their bones,
    /// each vertex with its own weights (SkinningJob::boneRuns); the rest
    /// are loose. Per group the runs come first, then the bone runs, then
    /// the loose vertices, each kind consecutive. Runs and bone runs
    /// ascending, `start` counted from 0 in each.
    std::span<const InfluenceRun> compactRuns(int count) const noexcept;
    std::span<const InfluenceRun> compactBoneRuns(int count) const noexcept;
    std::span<const std::uint32_t> compactLoose(int count) const noexcept;

private:
    void buildCompact(std::span<const std::int32_t> boneIndices, std::span<const float> boneWeights, bool weights,
                      std::size_t runBlock);

    std::vector<std::uint32_t> vertices_;
    std::vector<std::size_t> offsets_;  // group c = [offsets_[c], offsets_[c + 1])
    std::vector<std::size_t> cursor_;   // build() scratch
    std::vector<std::uint32_t> loose_;
    std::vector<std::size_t> looseOffsets_;
    std::vector<InfluenceRun> runs_;
    std::vector<std::size_t> runOffsets_;
    std::vector<std::uint32_t> compactOrder_;
    std::vector<std::int32_t> compactBones_;
    std::vector<float> compactWeights_;
    std::vector<InfluenceRun> compactRuns_;
    std::vector<std::uint32_t> compactLoose_;
    std::vector<InfluenceRun> compactBoneRuns_;
    std::vector<std::size_t> compactRunOffsets_, compactLooseOffsets_, compactBoneRunOffsets_;
    // buildCompact() scratch: a group's run, bone-run and loose vertices
    // before they are laid out, and the lengths of its runs and bone runs.
    std::vector<std::uint32_t> cursorScratch_, runScratch_, boneRunScratch_, looseScratch_;
    std::vector<std::uint32_t> runLengthScratch_, boneRunLengthScratch_;
};

/// out[order[i]] = in[i] for xyz triples (packed, 3 floats a vertex):
/// compact outputs written back to their mesh vertices. Three floats
/// written per vertex, none other.
void scatterXyz(std::span<const std::uint32_t> order, const float* in, float* out) noexcept;
/// The same for two pairs of arrays in one pass (positions and normals:
/// each index read once).
void scatterXyz(std::span<const std::uint32_t> order, const float* in, float* out, const float* in2,
                float* out2) noexcept;

}  // namespace m3g::skin
