// Internal: what the AVX2 + FMA kernels (SkinningAvx2.cpp, PaletteAvx2.cpp,
// MorphAvx2.cpp) share: the target macros, 128-bit halves, xyz triples to
// and from x, y, z lanes, the reciprocal length. Only those functions carry
// the target attribute (no per-file -mavx2), so no inline library function
// is ever compiled for AVX2 and shared with baseline code. Include inside
// M3G_SKIN_X86 only.
#pragma once

#include <immintrin.h>

#define M3G_AVX2 __attribute__((target("avx2,fma")))
// Inlined whatever the -O level: a call per vertex returning vectors through
// memory costs more than the work.
#define M3G_AVX2_INLINE __attribute__((target("avx2,fma"), always_inline)) inline

namespace m3g::skin::detail {

/// Four floats at `lo` | four at `hi`.
M3G_AVX2_INLINE __m256 halves(const float* lo, const float* hi) noexcept {
    return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(lo)), _mm_loadu_ps(hi), 1);
}

/// The sum of the four elements of each 128-bit half, in every element of
/// that half (a dot product per half after a multiply).
M3G_AVX2_INLINE __m256 sumPerHalf(__m256 v) noexcept {
    const __m256 pairs = _mm256_add_ps(v, _mm256_permute_ps(v, _MM_SHUFFLE(1, 0, 3, 2)));
    return _mm256_add_ps(pairs, _mm256_permute_ps(pairs, _MM_SHUFFLE(2, 3, 0, 1)));
}

/// Eight lanes of x, y, z as the 24 floats of their xyz triples, in three
/// registers (floats 0-7, 8-15, 16-23).
M3G_AVX2_INLINE void soa3ToXyz(__m256 x, __m256 y, __m256 z, __m256& o0, __m256& o1, __m256& o2) noexcept {
    // Per half (vertices 0-3 | 4-7): r0 = x0 y0 z0 x1, r1 = y1 z1 x2 y2, r2 = z2 x3 y3 z3.
    const __m256 xyLo = _mm256_unpacklo_ps(x, y);                            // x0 y0 x1 y1
    const __m256 xyHi = _mm256_unpackhi_ps(x, y);                            // x2 y2 x3 y3
    const __m256 zx = _mm256_shuffle_ps(z, x, _MM_SHUFFLE(3, 1, 2, 0));      // z0 z2 x1 x3
    const __m256 yz = _mm256_shuffle_ps(y, z, _MM_SHUFFLE(3, 1, 3, 1));      // y1 y3 z1 z3
    const __m256 r0 = _mm256_shuffle_ps(xyLo, zx, _MM_SHUFFLE(2, 0, 1, 0));  // x0 y0 z0 x1
    const __m256 r1 = _mm256_shuffle_ps(yz, xyHi, _MM_SHUFFLE(1, 0, 2, 0));  // y1 z1 x2 y2
    const __m256 r2 = _mm256_shuffle_ps(zx, yz, _MM_SHUFFLE(3, 1, 3, 1));    // z2 x3 y3 z3
    o0 = _mm256_permute2f128_ps(r0, r1, 0x20);
    o1 = _mm256_permute2f128_ps(r2, r0, 0x30);
    o2 = _mm256_permute2f128_ps(r1, r2, 0x31);
}

/// Eight lanes of x, y, z to 24 consecutive floats (xyz triples).
M3G_AVX2_INLINE void storeSoa3(float* out, __m256 x, __m256 y, __m256 z) noexcept {
    __m256 o0, o1, o2;
    soa3ToXyz(x, y, z, o0, o1, o2);
    _mm256_storeu_ps(out, o0);
    _mm256_storeu_ps(out + 8, o1);
    _mm256_storeu_ps(out + 16, o2);
}

/// 1 / |n| per lane, or 1 where |n|^2 is zero (or NaN). The reciprocal
/// square root estimate plus one Newton step (relative error about 2^-22)
/// keeps the square root and division latency (some 25 cycles, which the
/// block's long dependency chain cannot hide) out of the loop; a block with
/// a lane whose |n|^2 is below FLT_MIN, where the estimate is not usable,
/// takes the exact 1 / sqrt instead (decided per lane, so a vertex's result
/// never depends on its neighbours).
M3G_AVX2_INLINE __m256 inverseLength(__m256 nx, __m256 ny, __m256 nz) noexcept {
    const __m256 one = _mm256_set1_ps(1.0f);
    const __m256 len2 = _mm256_fmadd_ps(nz, nz, _mm256_fmadd_ps(ny, ny, _mm256_mul_ps(nx, nx)));
    const __m256 positive = _mm256_cmp_ps(len2, _mm256_setzero_ps(), _CMP_GT_OQ);
    const __m256 tiny = _mm256_and_ps(positive, _mm256_cmp_ps(len2, _mm256_set1_ps(1.17549435e-38f), _CMP_LT_OQ));
    const __m256 y = _mm256_rsqrt_ps(len2);
    // y' = y * (3 - len2 * y * y) / 2
    __m256 refined = _mm256_mul_ps(_mm256_mul_ps(_mm256_set1_ps(0.5f), y),
                                   _mm256_fnmadd_ps(_mm256_mul_ps(len2, y), y, _mm256_set1_ps(3.0f)));
    if (_mm256_movemask_ps(tiny) != 0) [[unlikely]]
        refined = _mm256_blendv_ps(refined, _mm256_div_ps(one, _mm256_sqrt_ps(len2)), tiny);
    return _mm256_blendv_ps(one, refined, positive);
}

/// x, y, z lanes of eight xyz triples given as the 128-bit pieces
/// m03 = floats 0-3 | 12-15, m14 = 4-7 | 16-19, m25 = 8-11 | 20-23.
M3G_AVX2_INLINE void soa3FromHalves(__m256 m03, __m256 m14, __m256 m25, __m256& x, __m256& y, __m256& z) noexcept {
    // Per half: m03 = x0 y0 z0 x1, m14 = y1 z1 x2 y2, m25 = z2 x3 y3 z3.
    const __m256 xy = _mm256_shuffle_ps(m14, m25, _MM_SHUFFLE(2, 1, 3, 2));  // x2 y2 x3 y3
    const __m256 yz = _mm256_shuffle_ps(m03, m14, _MM_SHUFFLE(1, 0, 2, 1));  // y0 z0 y1 z1
    x = _mm256_shuffle_ps(m03, xy, _MM_SHUFFLE(2, 0, 3, 0));
    y = _mm256_shuffle_ps(yz, xy, _MM_SHUFFLE(3, 1, 2, 0));
    z = _mm256_shuffle_ps(yz, m25, _MM_SHUFFLE(3, 0, 3, 1));
}

/// Eight consecutive xyz triples (24 floats) as x, y, z lanes.
M3G_AVX2_INLINE void loadSoa3(const float* p, __m256& x, __m256& y, __m256& z) noexcept {
    soa3FromHalves(halves(p, p + 12), halves(p + 4, p + 16), halves(p + 8, p + 20), x, y, z);
}

/// The same from the 24 floats in three registers (floats 0-7, 8-15, 16-23).
M3G_AVX2_INLINE void soa3FromRegisters(__m256 a0, __m256 a1, __m256 a2, __m256& x, __m256& y, __m256& z) noexcept {
    soa3FromHalves(_mm256_permute2f128_ps(a0, a1, 0x30), _mm256_permute2f128_ps(a0, a2, 0x21),
                   _mm256_permute2f128_ps(a1, a2, 0x30), x, y, z);
}

}  // namespace m3g::skin::detail
