// M3G transforms as glTF node transforms. An M3G Transformable composes
// T R S M (JSR-184 1.1, Transformable) where M is any 4x4 matrix; a glTF node has
// either TRS or a `matrix` that must decompose into TRS (glTF 2.0 §3.5.2).
// Part of the `m3g export` tool.
#pragma once

#include <array>
#include <vector>

namespace m3g {
class Transform;
}

namespace m3gcli::gltf {

/// One glTF node's translation, rotation (unit quaternion x, y, z, w) and
/// scale; composes T * R * S.
struct Trs {
    std::array<float, 3> t{0.0f, 0.0f, 0.0f};
    std::array<float, 4> r{0.0f, 0.0f, 0.0f, 1.0f};
    std::array<float, 3> s{1.0f, 1.0f, 1.0f};
};

/// How a general M3G matrix becomes glTF nodes.
struct MatrixNodes {
    /// The matrix decomposes into T * R * S (its 3x3 columns are orthogonal):
    /// one node with `matrix` (column-major) is enough.
    bool asMatrix = false;
    std::array<float, 16> columnMajor{};
    /// Otherwise (shear): a chain of nodes, parent first, whose TRS compose
    /// to the matrix exactly: [T * R(U)], [S(Σ)], [R(Vᵀ)] from the singular
    /// value decomposition U Σ Vᵀ of the 3x3 part.
    std::vector<Trs> chain;
    /// The bottom row was not (0, 0, 0, 1): glTF nodes are affine, so it was
    /// dropped (an approximation the caller reports).
    bool projectiveDropped = false;
};

/// True when `m` is exactly the identity.
bool isIdentity(const m3g::Transform& m);

/// Splits `m` as described for MatrixNodes.
MatrixNodes matrixNodes(const m3g::Transform& m);

/// Unit quaternion (x, y, z, w) of a 3x3 rotation given row-major.
std::array<float, 4> quaternionFromRotation(const std::array<double, 9>& rowMajor);

/// Normalises a quaternion; (0, 0, 0, 1) for a zero or non-finite one.
std::array<float, 4> normalizedQuaternion(const std::array<float, 4>& q);

}  // namespace m3gcli::gltf
