// The deformed vertices of a SkinnedMesh or MorphingMesh, as float arrays,
// for the renderer and for picking (JSR-184 1.1, MorphingMesh and
// SkinnedMesh). Deformed data never goes back into the quantised
// VertexArrays.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <m3g/Limits.h>
#include <m3g/skin/Palette.h>
#include <m3g/skin/Skinning.h>
#include <m3g/frame/DeformInputs.h>

#include "BoneTransforms.h"

namespace m3g {
class Mesh;
class MorphingMesh;
class SkinnedMesh;
class VertexArray;
class VertexBuffer;
}

namespace m3g::detail {

struct DeformedVertices {
    int vertexCount = 0;
    /// The order of every stream below: slot i holds mesh vertex order[i].
    /// Empty: the mesh's order (a MorphingMesh always; a SkinnedMesh whose
    /// vertices already come in the order below). A SkinnedMesh's vertices
    /// are kept grouped by influence set, as the kernels skin them
    /// (docs/skinning.md, "Compact space"), so that nothing is copied back
    /// to the mesh's order each frame: a consumer draws them through
    /// `location` (the renderer remaps its index copy once per order).
    std::span<const std::uint32_t> order;
    /// The inverse of `order`: mesh vertex v is at slot location[v] (empty: v).
    std::span<const std::uint32_t> location;
    /// The slot of mesh vertex `v`.
    std::uint32_t slotOf(std::uint32_t v) const noexcept { return location.empty() ? v : location[v]; }
    /// `values` (a stream of this struct, `components` floats per slot)
    /// rearranged into the mesh's order.
    std::vector<float> inMeshOrder(std::span<const float> values, int components) const;
    /// The other way: `values` in the mesh's order (`components` floats per
    /// vertex) into `out` in this struct's order (a copy when `order` is
    /// empty). For inputs and streams the deformation leaves alone.
    void inSlotOrder(std::span<const float> values, int components, std::vector<float>& out) const;
    /// xyz per vertex in the mesh's local space, position scale and bias
    /// already applied (so a consumer uses scale 1, bias 0).
    std::vector<float> positions;
    /// xyz per vertex, unit length; empty when the VertexBuffer has no normals.
    std::vector<float> normals;
    /// RGBA in [0, 1] per vertex; empty unless the mesh is a MorphingMesh
    /// (skinning leaves colours alone: read the VertexBuffer's).
    std::vector<float> colors;
    /// MorphingMesh only: morphed raw texture coordinates per unit (the base
    /// VertexBuffer's scale and bias still apply), texCoordComponents[u]
    /// values per vertex; empty for units without coordinates.
    std::array<std::vector<float>, kMaxTextureUnits> texCoords;
    std::array<int, kMaxTextureUnits> texCoordComponents{};
    /// Set by update() with Rigid::AsTransform for a SkinnedMesh bound
    /// rigidly: every vertex follows one and the same bone, with weight 1
    /// (Superscape Swerve exports each part of a character this way:
    /// otokka_jump2's fifteen meshes). Deforming such a mesh is one affine
    /// map of all its vertices, so it is left to the consumer's own
    /// transform: `rigidTransform` is that bone's palette entry (its position
    /// rows take the VertexBuffer's raw positions, scale and bias folded in;
    /// its normal rows the raw normals), and positions and normals above are
    /// not written (what they hold is meaningless while `rigid` is set).
    bool rigid = false;
    skin::PaletteEntry rigidTransform{};
};

/// The kernel inputs (plain spans, shared with back ends that deform on the
/// GPU: frame/DeformInputs.h).
using frame::MorphAttributeInputs;
using frame::SkinInputs;

/// Per-mesh deformation state. A renderer or picker keeps one per mesh (in
/// its own side table) and calls update() before using vertices().
class MeshDeformer {
public:
    MeshDeformer() = default;
    // Its plans hold spans into its own arrays: a copy would read and write
    // the original's. A move keeps them valid (the buffers move along).
    MeshDeformer(const MeshDeformer&) = delete;
    MeshDeformer& operator=(const MeshDeformer&) = delete;
    MeshDeformer(MeshDeformer&&) noexcept = default;
    MeshDeformer& operator=(MeshDeformer&&) noexcept = default;

    /// What update() produces.
    enum class Output {
        /// Runs the CPU kernels: vertices() holds the deformed vertices.
        Vertices,
        /// Refreshes the kernel inputs (skinInputs(), morphAttribute(),
        /// morphWeights()) and detects changes, but runs no kernel:
        /// vertices() holds only vertexCount and texCoordComponents. For a
        /// GPU that deforms from the same inputs (render-vk's compute path).
        InputsOnly,
    };
    /// What update() does with a rigidly bound SkinnedMesh
    /// (DeformedVertices::rigid).
    enum class Rigid {
        /// Deforms it like any other (`output` decides how).
        Deform,
        /// Computes its palette only and reports the one transform; the
        /// caller draws the undeformed vertices through it (the renderer,
        /// whose model-view then carries the bone: no vertex is skinned or
        /// uploaded per frame, on the CPU path or the compute path).
        AsTransform,
    };

    /// Recomputes the deformed vertices of `mesh` (a SkinnedMesh with its
    /// bones as posed now, or a MorphingMesh with its current weights).
    /// Returns true when the deformed vertices changed since the previous
    /// call (always true on the first call and when `output` or `rigid`
    /// differs from the previous call's). Returns false and leaves vertices()
    /// empty for a plain Mesh. Throws IllegalStateException when a
    /// MorphingMesh's targets do not have the base's set of arrays (JSR-184
    /// 1.1, MorphingMesh). With Rigid::AsTransform, a rigidly bound
    /// SkinnedMesh gets vertices().rigid and its transform instead of
    /// deformed vertices (true is then returned when that transform changed).
    bool update(const Mesh& mesh, Output output = Output::Vertices, Rigid rigid = Rigid::Deform);

    const DeformedVertices& vertices() const noexcept { return out_; }

    /// Increments each time update() returns true: a key for GPU mirrors.
    std::uint64_t stamp() const noexcept { return stamp_; }
    /// Increments each time update() rebuilt vertices().order (the
    /// influence table or the inputs changed): a key for copies made
    /// through it, such as remapped indices.
    std::uint64_t orderStamp() const noexcept { return orderStamp_; }
    /// Increments each time update() rebuilt the static inputs (vertex
    /// arrays, influence table, morph targets), as opposed to only the
    /// palette or the weights: a key for GPU copies of those inputs.
    std::uint64_t inputStamp() const noexcept { return inputStamp_; }

    /// Inputs of the last update() of a SkinnedMesh (empty otherwise).
    SkinInputs skinInputs() const noexcept;

    /// Morph attribute indices: positions, normals, colours, then one per
    /// texture unit.
    static constexpr int kMorphPositions = frame::kMorphPositions, kMorphNormals = frame::kMorphNormals,
                         kMorphColors = frame::kMorphColors, kMorphTexCoords = frame::kMorphTexCoords;
    static constexpr int kMorphAttributes = frame::kMorphAttributes;
    static_assert(kMorphAttributes == 3 + kMaxTextureUnits);
    /// Attribute `index` of the last update() of a MorphingMesh
    /// (components 0 when absent or not a MorphingMesh).
    MorphAttributeInputs morphAttribute(int index) const noexcept;
    /// The weights of the last update() of a MorphingMesh, one per target.
    std::span<const float> morphWeights() const noexcept { return weights_; }

private:
    /// An object read by the last computation: (object id, revision); id 0
    /// stands for "no object".
    struct Source {
        std::uint64_t id = 0;
        std::uint32_t revision = 0;
        friend bool operator==(const Source&, const Source&) = default;
    };
    enum class Kind { None, Skinned, Morphing };

    /// A skinned mesh's three sources: its VertexBuffer, positions, normals.
    using SkinnedSources = std::array<Source, 3>;
    /// The skinning jobs of one influence count, as the partition gives them
    /// (listed once per change of the table or the inputs, not per frame).
    /// Everything in output slots (the compact space's, then the vertices
    /// without bones).
    struct GroupPlan {
        bool parallel = false;  // large enough for the thread pool
        // Every run and bone run of the group (the job's own lists are
        // these, or in a partial frame those that moved).
        std::span<const skin::InfluenceRun> runs, boneRuns;
        // Its job as planned: the loose vertices (count 0: every vertex
        // without bones), arrays, influence count and stride; each frame
        // sets the runs, palette and normal method.
        skin::SkinningJob job;
    };

    bool updateSkinned(const SkinnedMesh& mesh);
    /// The output order (order_, location_) of a partition of `n`
    /// vertices, and the inputs gathered into it (as packed triples, and as
    /// planes where the kernels read them).
    void planOrder(std::size_t n);
    /// Lists groups_ from partition_ (after a change of the table or
    /// inputs) with their jobs for `n` vertices at influence stride `stride`.
    void planGroups(std::size_t n, int stride);
    bool updateMorphing(const MorphingMesh& mesh);
    /// Records `mesh`'s kind and id; true when either differs from the last
    /// call's.
    bool meshChanged(Kind kind, const Mesh& mesh);
    /// meshChanged, and whether newSources_ equal the stored sources_ (then
    /// swaps them in). True when anything differs.
    bool sourcesChanged(Kind kind, const Mesh& mesh);
    void addSource(const VertexBuffer* vb);
    void addSource(const VertexArray* array);
    void finish();

    DeformedVertices out_;
    std::uint64_t stamp_ = 0;
    std::uint64_t inputStamp_ = 0;
    std::uint64_t orderStamp_ = 0;
    Output output_ = Output::Vertices;  // of the last update()
    Rigid rigidMode_ = Rigid::Deform;   // of the last update()

    // ---- Change detection: out_ is valid for exactly these inputs ----
    Kind kind_ = Kind::None;
    std::uint64_t meshId_ = 0;
    bool valid_ = false;
    std::vector<Source> sources_;      // VertexBuffers and VertexArrays, fixed order
    std::vector<Source> newSources_;   // scratch of update()
    SkinnedSources skinnedSources_{};  // SkinnedMesh: its sources (sources_ is the MorphingMesh's)

    // ---- SkinnedMesh: inputs as floats (rebuilt when a source changes) ----
    std::vector<float> rawPositions_;  // unscaled; scale and bias go to the kernel
    std::vector<float> baseNormals_;   // GL signed-normalised mapping
    std::uint32_t tableRevision_ = 0;
    SkinInputs skinInputs_;
    skin::InfluencePartition partition_;
    // The output order: the partition's compact space (every vertex with
    // influences, sorted by influence set), then the vertices without bones.
    // Empty when that is the mesh's order; the inputs are then used as they
    // are, else gathered into it when the inputs or the table change.
    std::vector<std::uint32_t> order_, location_;
    std::vector<std::uint32_t> unboned_;  // output slots of the vertices without bones
    bool ordered_ = false;
    std::vector<float> orderedPositions_, orderedNormals_;
    // The inputs in output order again as planes (x, y, z), for the lane
    // kernels (SkinningJob::inPositionPlanes): made with the order, only
    // where those kernels run (AVX2, AVX-512) and the mesh has normals.
    std::vector<float> positionPlanes_, normalPlanes_;
    std::vector<GroupPlan> groups_;    // the non-empty groups, ascending count
    BoneTransforms boneTransforms_;
    std::vector<float> boneMatrices_;  // 16 per bone: bone -> mesh now
    std::vector<float> atRest_;        // 16 per bone
    std::vector<skin::PaletteEntry> palette_, newPalette_;
    bool conformal_ = false;  // PaletteJob::conformal of palette_ (bone runs only)
    // The one bone of every vertex when the table binds the mesh rigidly
    // (DeformedVertices::rigid), else -1; found once per change of the table.
    int rigidBone_ = -1;
    // Per bone, whether its palette entry differs from the last call's (a
    // frame that keeps out_ recomputes only the runs of changed bones).
    std::vector<std::uint8_t> entryChanged_;
    std::vector<skin::InfluenceRun> movedRuns_, movedBoneRuns_;  // scratch: those runs

    // ---- MorphingMesh: base then targets, per attribute, as floats ----
    struct MorphAttribute {
        std::vector<std::vector<float>> values;  // [0] = base, [1 + t] = target t
        int components = 0;                      // 0: attribute absent
    };
    std::array<MorphAttribute, kMorphAttributes> morph_;
    std::vector<float> weights_;                 // the weights out_ was made with
    std::vector<float> activeWeights_;           // scratch: non-zero weights
    std::vector<std::span<const float>> activeTargets_;
};

}  // namespace m3g::detail
