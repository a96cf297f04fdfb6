// The deformed vertices of a SkinnedMesh or MorphingMesh, as float arrays,
// for the renderer and for picking (spec digest §4.9, §5.11). Deformed data
// never goes back into the quantised VertexArrays (architecture guide §6).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <m3g/Limits.h>

namespace m3g {
class Mesh;
}

namespace m3g::detail {

struct DeformedVertices {
    int vertexCount = 0;
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
};

/// Per-mesh deformation state. A renderer or picker keeps one per mesh (in
/// its own side table) and calls update() before using vertices().
class MeshDeformer {
public:
    /// Recomputes the deformed vertices of `mesh` (a SkinnedMesh with its
    /// bones as posed now, or a MorphingMesh with its current weights).
    /// Returns true when vertices() changed since the previous call (always
    /// true on the first call). Returns false and leaves vertices() empty for
    /// a plain Mesh. Throws IllegalStateException when a MorphingMesh's
    /// targets do not have the base's set of arrays (§4.9).
    bool update(const Mesh& mesh);

    const DeformedVertices& vertices() const noexcept { return out_; }

    /// Increments each time update() returns true: a key for GPU mirrors.
    std::uint64_t stamp() const noexcept { return stamp_; }

private:
    DeformedVertices out_;
    std::uint64_t stamp_ = 0;
};

}  // namespace m3g::detail
