// The per-frame bone palette of a skinned mesh (JSR-184 1.1, SkinnedMesh): one
// entry per bone, computed once per bone per frame, consumed by SkinningJob
// (and, with the same layout, by the skinning compute shader).
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include <m3g/skin/Isa.h>

namespace m3g::skin {

/// One bone's matrices, std430-compatible: read it in GLSL as
///   struct PaletteEntry { vec4 position[3]; vec4 normal[3]; };
/// (96 bytes, 16-byte aligned, no padding inside).
struct alignas(16) PaletteEntry {
    /// Rows 0..2 of the affine matrix (bone -> mesh now) x (at rest:
    /// mesh -> bone) x (the job's position scale and bias), element
    /// [r * 4 + c]; the implied row 3 is (0, 0, 0, 1).
    float position[12];
    /// Rows 0..2 of the inverse transpose of the upper 3x3 of
    /// (bone -> mesh now) x (at rest) (the scale and bias left out: they
    /// apply to positions only),
    /// element [r * 4 + c], with [r * 4 + 3] = 0. For a singular 3x3 it holds
    /// the cofactor matrix instead (the inverse transpose times the
    /// determinant, which points the same way up to the sign), so that a
    /// bone scaled to a plane still gives usable normals after renormalisation.
    float normal[12];
};
static_assert(sizeof(PaletteEntry) == 96, "PaletteEntry must match the std430 layout");

/// Relative tolerance of PaletteJob::conformal: 2^-15, below the resolution
/// of a 16-bit normal component (1 / 32767), the finest a VertexArray holds.
inline constexpr float kConformalTolerance = 1.0f / 32768.0f;

/// Computes palette entries from per-bone matrices. Owns no memory.
///
/// Both inputs are 4x4 matrices in M3G's Transform order (row-major, element
/// index row * 4 + col), 16 floats per bone. Only their top three rows are
/// used: node transforms are affine (Node::setTransform rejects a W row other
/// than 0 0 0 1), so the products are too. The scalar path computes the
/// product and the inverse in double precision and rounds once; the SIMD
/// paths compute them in single precision (AVX2 with FMAs two bones at a
/// time, SSE2 one bone at a time), within a few units in the last place of
/// the double result for well-conditioned bones: the palette is most of a
/// small mesh's frame.
struct PaletteJob {
    /// Number of entries to compute.
    std::size_t boneCount = 0;
    /// bone -> mesh, as posed now (Node::getTransformTo(mesh)).
    std::span<const float> boneToMesh;
    /// at rest: mesh -> bone (SkinnedMesh::getBoneTransform).
    std::span<const float> atRest;
    /// At least boneCount entries.
    std::span<PaletteEntry> output;
    /// The vertex positions' scale and bias (VertexBuffer::setPositions),
    /// folded into the position rows: P (s p + b) = (P s) p + P b, so that
    /// the SkinningJob then takes the raw positions with scale 1 and bias 0.
    /// Once per bone per frame instead of once per shared-influence run (a
    /// run's fold was a fifth of a 16-vertex run's cost with 4 influences).
    float positionScale = 1.0f;
    std::array<float, 3> positionBias{0.0f, 0.0f, 0.0f};
    /// Which code path runs (Scalar, Sse2 or Avx2); an
    /// unsupported one makes validate() false.
    Isa isa = Isa::Auto;
    /// Optional output: when set, run() stores whether the palette is
    /// conformal: every bone's 3x3 (bone -> mesh now) x (at rest) a
    /// rotation, or a reflection, times one scale s common to all bones (rows
    /// orthogonal and of squared length s^2, to within kConformalTolerance
    /// of s^2), and the position scale positive. Each entry's normal 3x3 (the
    /// inverse transpose) is then its position 3x3 over s^2 times the
    /// position scale, one positive multiple for all entries, so that a
    /// blend of normal rows is that multiple of the same blend of position
    /// rows: renormalised, the normal comes out the same
    /// (SkinningJob::normalsFromPositions). What bones that only rotate and
    /// translate (the usual skeleton) give; a bone scaled non-uniformly, or
    /// unlike the others, does not; nor does a singular or non-finite one.
    /// A few operations per bone.
    bool* conformal = nullptr;

    /// True if the spans are large enough: 16 * boneCount floats each and
    /// boneCount entries, and the ISA is supported. (Non-finite elements are not rejected: they give
    /// non-finite entries, as the plain formula would.)
    bool validate() const noexcept;
    /// validate(), then writes output[0 .. boneCount). Returns validate().
    bool run() const noexcept;
};

}  // namespace m3g::skin
