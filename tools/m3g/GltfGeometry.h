// Vertex and index data of M3G meshes in the form glTF wants (float arrays,
// triangle lists), as plain functions so the unit tests can check them
// against hand-computed values. Part of the `m3g export` tool.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace m3g {
class IndexBuffer;
class SkinnedMesh;
class Transform;
class VertexArray;
class VertexBuffer;
}  // namespace m3g

namespace m3gcli::gltf {

/// Triangle list of `indices` (its triangleIndices(): strips already
/// unrolled with alternating winding, JSR-184 1.1, IndexBuffer.getIndices).
/// With `flip`, the
/// second and third index of each triangle are swapped (WINDING_CW, or
/// CULL_FRONT expressed as back-face culling of the flipped triangles).
std::vector<std::uint32_t> triangleList(const m3g::IndexBuffer& indices, bool flip);

/// xyz per vertex: scale * raw + bias (the VertexBuffer's position scale and
/// bias, JSR-184 1.1, VertexBuffer.setPositions); 2-component arrays get
/// z = 0 plus bias.
std::vector<float> positions(const m3g::VertexBuffer& vb);
/// Morph target displacement (target - base), both with the base's scale and
/// bias (JSR-184 1.1, MorphingMesh: targets use the base buffer's scale and
/// bias).
std::vector<float> positionDeltas(const m3g::VertexBuffer& base, const m3g::VertexBuffer& target);

/// Unit normals with OpenGL's signed integer mapping (2c + 1) / (2^b - 1).
/// A normal of (nearly) zero length becomes (0, 0, 1) and is counted in
/// `degenerate`.
std::vector<float> normals(const m3g::VertexArray& normals, int& degenerate);
/// Normal displacements (target - base) of the unnormalised GL-mapped normals.
std::vector<float> normalDeltas(const m3g::VertexArray& base, const m3g::VertexArray& target);

/// RGBA8 per vertex: the colour array's bytes read as unsigned (RGB arrays
/// get alpha 255).
std::vector<std::uint8_t> colors(const m3g::VertexArray& colors);

/// Texture coordinates of `unit` for glTF: s, t per vertex with the
/// VertexBuffer's scale and bias, then the texture's transform (a 4x4 on
/// (s, t, r, 1) with r = 0 for 2-component arrays, divided by q when q is
/// not 1).
std::vector<float> texCoords(const m3g::VertexBuffer& vb, int unit, const m3g::Transform& textureMatrix);

/// Per-vertex skin data in sets of four influences (glTF JOINTS_n/WEIGHTS_n).
struct SkinAttributes {
    int sets = 1;                        ///< number of JOINTS_n/WEIGHTS_n pairs
    std::vector<std::uint16_t> joints;   ///< vertexCount * 4 * sets joint indices
    std::vector<float> weights;          ///< same layout, each vertex sums to 1
    bool usesRestJoint = false;          ///< some vertex has no bone: uses joint `restJoint`
};

/// Joints and weights of `mesh`'s influence table for `vertexCount`
/// vertices. Joint j < boneCount() is bone j; a vertex without influences
/// gets joint `restJoint` (an extra joint that stays at the mesh node, as
/// Nokia's engine leaves such vertices in mesh space) with weight 1. Unused
/// slots are joint 0 with weight 0.
SkinAttributes skinAttributes(const m3g::SkinnedMesh& mesh, int vertexCount, int restJoint);

}  // namespace m3gcli::gltf
