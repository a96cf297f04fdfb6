// The inputs of a deformation kernel as plain spans: what scene's
// MeshDeformer hands to a back end that deforms on the GPU (render-vk's
// compute path) from the same influence table and palette as the CPU
// kernels (JSR-184 1.1, SkinnedMesh and MorphingMesh; docs/skinning.md).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <m3g/skin/Palette.h>

namespace m3g::frame {

/// The kernel inputs of a SkinnedMesh. The spans point into scene's
/// deformer and the mesh's influence table; they stay valid until the
/// mesh's next deformation or a change to the mesh.
struct SkinInputs {
    int vertexCount = 0;
    /// Raw xyz per vertex (zeros when the VertexBuffer has no positions).
    /// A vertex without influence takes positionScale * p + positionBias
    /// (the VertexBuffer's); the palette's position rows have them folded in
    /// (PaletteJob::positionScale), so an influenced vertex takes the
    /// blended rows times (p, 1).
    std::span<const float> positions;
    float positionScale = 1.0f;
    std::array<float, 3> positionBias{0.0f, 0.0f, 0.0f};
    /// xyz per vertex with the GL signed-normalised mapping; empty: no normals.
    std::span<const float> normals;
    /// The influence table (InfluenceTable's layout): `influenceStride` slots
    /// per vertex for tableVertices = bones.size() / influenceStride vertices
    /// (fewer or more than vertexCount); bone -1 = empty slot.
    int influenceStride = 0;
    std::span<const std::int32_t> bones;
    std::span<const float> weights;
    /// One entry per bone, as posed at the last deformation.
    std::span<const skin::PaletteEntry> palette;
};

/// Morph attribute indices: positions, normals, colours, then one per
/// texture unit (JSR-184 1.1 allows up to 4 units, Limits.h kMaxTextureUnits).
inline constexpr int kMorphPositions = 0, kMorphNormals = 1, kMorphColors = 2, kMorphTexCoords = 3;
inline constexpr int kMorphAttributes = 3 + 4;

/// One attribute of a MorphingMesh: base and target values as floats
/// (`components` per vertex; positions with the base's scale and bias
/// applied, normals GL-mapped, colours RGBA in [0, 1], texture coordinates
/// raw). components == 0: the attribute is absent.
struct MorphAttributeInputs {
    int components = 0;
    std::span<const float> base;
    std::span<const std::vector<float>> targets;
};

/// Everything a MorphingMesh's kernel reads.
struct MorphInputs {
    int vertexCount = 0;
    std::array<MorphAttributeInputs, kMorphAttributes> attributes{};
    std::span<const float> weights;  ///< one per target
};

}  // namespace m3g::frame
