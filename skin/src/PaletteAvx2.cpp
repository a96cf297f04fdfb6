// AVX2 + FMA palette (Isa::Avx2 CPUs): PaletteJob's formula in single
// precision, two bones per iteration (bone b in the low 128 bits, b + 1 in
// the high). The product's rows are three FMAs each on in-lane broadcasts,
// the cofactor rows (inverse transpose times the determinant) are cross
// products of pairs of rows, and 1/det is one division per pair, blended
// branch-free to 1 for a singular or non-finite bone. Some 40 instructions
// per bone instead of the double path's 60 and the plain loop's 200: with
// the paper's small meshes (100 vertices, 20 bones) the palette was a third
// of a frame. Float with FMAs differs from the double formula by a few
// units in the last place for well-conditioned bones (tested to 1e-6 of
// the larger of 1 and the element), far inside what a float vertex holds.
// PaletteJob::conformal is measured on the rows in registers (six dots per
// bone in two rounds of horizontal adds) rather than read back.
#include "Kernels.h"

#ifdef M3G_SKIN_X86

#include <cmath>

#include "Avx2.h"

namespace m3g::skin::detail {

namespace {

/// (y, z, x, w) and (z, x, y, w) of a row, per 128-bit half.
M3G_AVX2 inline __m256 yzx(__m256 v) noexcept { return _mm256_permute_ps(v, _MM_SHUFFLE(3, 0, 2, 1)); }
M3G_AVX2 inline __m256 zxy(__m256 v) noexcept { return _mm256_permute_ps(v, _MM_SHUFFLE(3, 1, 0, 2)); }

/// xyz of u x v per half (w: u.w v.w - u.w v.w, blended away by the caller).
M3G_AVX2 inline __m256 cross(__m256 u, __m256 v) noexcept {
    return _mm256_fmsub_ps(yzx(u), zxy(v), _mm256_mul_ps(zxy(u), yzx(v)));
}

/// The position rows m[0..2] of a pair of bones times the job's position
/// scale and bias: m (s, s, s, 1) + (0, 0, 0, m . (bx, by, bz, 0)) per half.
M3G_AVX2 inline void foldPositionScaleBias(const PaletteJob& job, __m256 (&m)[3]) noexcept {
    const __m256 zero = _mm256_setzero_ps();
    const float s = job.positionScale;
    const __m256 scale = _mm256_setr_ps(s, s, s, 1.0f, s, s, s, 1.0f);
    const __m256 bias = _mm256_setr_ps(job.positionBias[0], job.positionBias[1], job.positionBias[2], 0.0f,
                                       job.positionBias[0], job.positionBias[1], job.positionBias[2], 0.0f);
#pragma GCC unroll 3
    for (int i = 0; i < 3; ++i) {
        const __m256 dot = sumPerHalf(_mm256_mul_ps(m[i], bias));
        m[i] = _mm256_fmadd_ps(m[i], scale, _mm256_blend_ps(zero, dot, 0x88));
    }
}

/// GramBounds eight lanes wide: per half, the smallest and largest squared
/// row length and largest |dot of two rows| of the bones seen in it (set
/// by the caller: a constructor would be compiled without AVX).
struct GramLanes {
    __m256 minDiagonal, maxDiagonal, maxOff, sum;
};

/// Adds a pair of bones' 3x3s (rows m[0..2], w ignored) to `g`: the six
/// dots of each half summed by two rounds of horizontal adds.
M3G_AVX2 inline void addGram(const __m256 (&m)[3], GramLanes& g) noexcept {
    const __m256 zero = _mm256_setzero_ps();
    const __m256 r0 = _mm256_blend_ps(m[0], zero, 0x88), r1 = _mm256_blend_ps(m[1], zero, 0x88),
                 r2 = _mm256_blend_ps(m[2], zero, 0x88);
    const __m256 h0 = _mm256_hadd_ps(_mm256_mul_ps(r0, r0), _mm256_mul_ps(r1, r1));
    const __m256 h1 = _mm256_hadd_ps(_mm256_mul_ps(r2, r2), _mm256_mul_ps(r0, r1));
    const __m256 h2 = _mm256_hadd_ps(_mm256_mul_ps(r0, r2), _mm256_mul_ps(r1, r2));
    const __m256 d = _mm256_hadd_ps(h0, h1);  // g00 g11 g22 g01 per half
    const __m256 o = _mm256_hadd_ps(h2, h2);  // g02 g12 g02 g12 per half
    g.minDiagonal = _mm256_min_ps(g.minDiagonal, _mm256_blend_ps(d, _mm256_set1_ps(HUGE_VALF), 0x88));
    g.maxDiagonal = _mm256_max_ps(g.maxDiagonal, _mm256_blend_ps(d, zero, 0x88));
    const __m256 off = _mm256_blend_ps(o, d, 0x88);  // g02 g12 g02 g01 per half
    g.maxOff = _mm256_max_ps(g.maxOff, _mm256_andnot_ps(_mm256_set1_ps(-0.0f), off));
    g.sum = _mm256_add_ps(g.sum, _mm256_add_ps(d, o));
}

/// The eight lanes folded into one GramBounds.
M3G_AVX2 inline GramBounds gramBounds(const GramLanes& g) noexcept {
    alignas(32) float lo[8], hi[8], off[8], sum[8];
    _mm256_store_ps(lo, g.minDiagonal);
    _mm256_store_ps(hi, g.maxDiagonal);
    _mm256_store_ps(off, g.maxOff);
    _mm256_store_ps(sum, g.sum);
    GramBounds b;
    for (int i = 0; i < 8; ++i) {
        b.minDiagonal = std::min(b.minDiagonal, lo[i]);
        b.maxDiagonal = std::max(b.maxDiagonal, hi[i]);
        b.maxOff = std::max(b.maxOff, off[i]);
        b.sum += sum[i];
    }
    return b;
}

/// Entries of bones `b0` (low half) and `b1` (high half; equal to b0 for
/// the last bone of an odd count, then only `storeHigh` false); with
/// `gram`, their 3x3s added to it.
M3G_AVX2 inline void pairOfBones(const PaletteJob& job, std::size_t b0, std::size_t b1, bool storeHigh,
                                 bool foldScaleBias, GramLanes* gram) noexcept {
    const float* a0 = job.boneToMesh.data() + b0 * 16;
    const float* a1 = job.boneToMesh.data() + b1 * 16;
    const float* r0p = job.atRest.data() + b0 * 16;
    const float* r1p = job.atRest.data() + b1 * 16;
    const __m256 zero = _mm256_setzero_ps();
    const __m256 r0 = halves(r0p, r1p), r1 = halves(r0p + 4, r1p + 4), r2 = halves(r0p + 8, r1p + 8);
    // Row i of a * r (both affine): a[i][0..2] . r's rows, plus a[i][3] in w.
    __m256 m[3];
#pragma GCC unroll 3
    for (int i = 0; i < 3; ++i) {
        const __m256 ai = halves(a0 + 4 * i, a1 + 4 * i);
        const __m256 t = _mm256_blend_ps(zero, ai, 0x88);  // (0, 0, 0, a[i][3]) per half
        m[i] = _mm256_fmadd_ps(_mm256_permute_ps(ai, 0xAA), r2,
                               _mm256_fmadd_ps(_mm256_permute_ps(ai, 0x55), r1,
                                               _mm256_fmadd_ps(_mm256_permute_ps(ai, 0x00), r0, t)));
    }
    if (gram) addGram(m, *gram);
    // Cofactor rows: cof[i] = m[i+1] x m[i+2] (indices mod 3), w set to 0.
    const __m256 c0 = _mm256_blend_ps(cross(m[1], m[2]), zero, 0x88);
    const __m256 c1 = _mm256_blend_ps(cross(m[2], m[0]), zero, 0x88);
    const __m256 c2 = _mm256_blend_ps(cross(m[0], m[1]), zero, 0x88);
    // det = m0 . c0 in every element of each half (w out: a non-finite
    // translation must not make the 3x3's determinant unusable).
    const __m256 det = sumPerHalf(_mm256_blend_ps(_mm256_mul_ps(m[0], c0), zero, 0x88));
    // 1 / det, or 1 where det is 0 or not finite.
    const __m256 absDet = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), det);
    const __m256 usable = _mm256_and_ps(_mm256_cmp_ps(absDet, zero, _CMP_GT_OQ),
                                        _mm256_cmp_ps(absDet, _mm256_set1_ps(HUGE_VALF), _CMP_LT_OQ));
    const __m256 one = _mm256_set1_ps(1.0f);
    const __m256 inv = _mm256_blendv_ps(one, _mm256_div_ps(one, det), usable);
    const __m256 n0 = _mm256_mul_ps(c0, inv), n1 = _mm256_mul_ps(c1, inv), n2 = _mm256_mul_ps(c2, inv);
    // The position rows times the job's scale and bias: m[i] (s, s, s, 1)
    // plus m[i] . (bx, by, bz, 0) in w (skipped for 1 and 0, which leave a
    // non-finite row as it is rather than NaN).
    if (foldScaleBias) foldPositionScaleBias(job, m);
    // An entry as three 32-byte stores (P0|P1, P2|N0, N1|N2): the kernels
    // read each entry right after this with 32-byte loads (the AVX-512 run
    // kernel too), which a store can forward only if it holds the whole
    // load; from 16-byte row stores such a load waits for them to retire
    // (in perf's profile of otokka_jump2, one mesh after another, the
    // first read of each mesh's entry stood out; the frame gained about
    // 1 %, docs/skinning.md).
    float* e0 = reinterpret_cast<float*>(job.output.data() + b0);
    _mm256_storeu_ps(e0, _mm256_permute2f128_ps(m[0], m[1], 0x20));
    _mm256_storeu_ps(e0 + 8, _mm256_permute2f128_ps(m[2], n0, 0x20));
    _mm256_storeu_ps(e0 + 16, _mm256_permute2f128_ps(n1, n2, 0x20));
    if (!storeHigh) return;
    float* e1 = reinterpret_cast<float*>(job.output.data() + b1);
    _mm256_storeu_ps(e1, _mm256_permute2f128_ps(m[0], m[1], 0x31));
    _mm256_storeu_ps(e1 + 8, _mm256_permute2f128_ps(m[2], n0, 0x31));
    _mm256_storeu_ps(e1 + 16, _mm256_permute2f128_ps(n1, n2, 0x31));
}

}  // namespace

M3G_AVX2 void paletteAvx2(const PaletteJob& job) noexcept {
    const bool fold = !isIdentityScaleBias(job.positionScale, job.positionBias);
    GramLanes lanes{_mm256_set1_ps(HUGE_VALF), _mm256_setzero_ps(), _mm256_setzero_ps(), _mm256_setzero_ps()};
    GramLanes* gram = job.conformal ? &lanes : nullptr;
    std::size_t b = 0;
    for (; b + 2 <= job.boneCount; b += 2) pairOfBones(job, b, b + 1, true, fold, gram);
    if (b < job.boneCount) pairOfBones(job, b, b, false, fold, gram);
    // The position rows are these 3x3s times the position scale.
    if (gram) *job.conformal = gramBounds(lanes).conformal(job.positionScale);
}

}  // namespace m3g::skin::detail

#endif  // M3G_SKIN_X86
