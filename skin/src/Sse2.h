// Internal: what the SSE2 kernels (SkinningSse2.cpp, MorphSse2.cpp,
// PaletteSse2.cpp) share: xyz triples to and from x, y, z lanes, a per-lane
// select, the sum of four elements, the position scale and bias fold, the
// reciprocal length. The AVX2 versions are in Avx2.h. Include inside
// M3G_SKIN_X86 only.
#pragma once

#include <emmintrin.h>

namespace m3g::skin::detail {

/// x, y, z lanes of four xyz triples given as the 12 floats in three
/// registers: m0 = x0 y0 z0 x1, m1 = y1 z1 x2 y2, m2 = z2 x3 y3 z3.
inline void soa3FromRegisters(__m128 m0, __m128 m1, __m128 m2, __m128& x, __m128& y, __m128& z) noexcept {
    const __m128 xy = _mm_shuffle_ps(m1, m2, _MM_SHUFFLE(2, 1, 3, 2));  // x2 y2 x3 y3
    const __m128 yz = _mm_shuffle_ps(m0, m1, _MM_SHUFFLE(1, 0, 2, 1));  // y0 z0 y1 z1
    x = _mm_shuffle_ps(m0, xy, _MM_SHUFFLE(2, 0, 3, 0));
    y = _mm_shuffle_ps(yz, xy, _MM_SHUFFLE(3, 1, 2, 0));
    z = _mm_shuffle_ps(yz, m2, _MM_SHUFFLE(3, 0, 3, 1));
}

/// Four consecutive xyz triples (12 floats) as x, y, z lanes.
inline void loadSoa3(const float* p, __m128& x, __m128& y, __m128& z) noexcept {
    soa3FromRegisters(_mm_loadu_ps(p), _mm_loadu_ps(p + 4), _mm_loadu_ps(p + 8), x, y, z);
}

/// Four lanes of x, y, z as the 12 floats of their xyz triples.
inline void soa3ToXyz(__m128 x, __m128 y, __m128 z, __m128& r0, __m128& r1, __m128& r2) noexcept {
    const __m128 xyLo = _mm_unpacklo_ps(x, y);                        // x0 y0 x1 y1
    const __m128 xyHi = _mm_unpackhi_ps(x, y);                        // x2 y2 x3 y3
    const __m128 zx = _mm_shuffle_ps(z, x, _MM_SHUFFLE(3, 1, 2, 0));  // z0 z2 x1 x3
    const __m128 yz = _mm_shuffle_ps(y, z, _MM_SHUFFLE(3, 1, 3, 1));  // y1 y3 z1 z3
    r0 = _mm_shuffle_ps(xyLo, zx, _MM_SHUFFLE(2, 0, 1, 0));           // x0 y0 z0 x1
    r1 = _mm_shuffle_ps(yz, xyHi, _MM_SHUFFLE(1, 0, 2, 0));           // y1 z1 x2 y2
    r2 = _mm_shuffle_ps(zx, yz, _MM_SHUFFLE(3, 1, 3, 1));             // z2 x3 y3 z3
}

/// The sum of v's four elements, in every element.
inline __m128 sumAll(__m128 v) noexcept {
    const __m128 pairs = _mm_add_ps(v, _mm_shuffle_ps(v, v, _MM_SHUFFLE(1, 0, 3, 2)));
    return _mm_add_ps(pairs, _mm_shuffle_ps(pairs, pairs, _MM_SHUFFLE(2, 3, 0, 1)));
}

/// A position row (r0 r1 r2 r3) of P with a position scale s and bias b
/// folded in, P (s p + b) = (P s) p + P b: (r0 s, r1 s, r2 s,
/// r0 b0 + r1 b1 + r2 b2 + r3), given scale = (s, s, s, 1) and
/// bias = (b0, b1, b2, 0). The palette folds its rows so; the run kernel a
/// job's own scale and bias.
inline __m128 foldScaleBias(__m128 row, __m128 scale, __m128 bias) noexcept {
    const __m128 wOnly = _mm_castsi128_ps(_mm_setr_epi32(0, 0, 0, -1));
    return _mm_add_ps(_mm_mul_ps(row, scale), _mm_and_ps(sumAll(_mm_mul_ps(row, bias)), wOnly));
}

/// mask ? a : b per element.
inline __m128 select(__m128 mask, __m128 a, __m128 b) noexcept {
    return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b));
}

/// 1 / |n| per lane, or 1 where |n|^2 is zero (or NaN): the reciprocal
/// square root estimate and one Newton step (relative error about 2^-22),
/// the exact 1 / sqrt for a lane whose |n|^2 is below FLT_MIN, where the
/// estimate is not usable (per lane: a vertex's result never depends on its
/// neighbours).
inline __m128 inverseLength(__m128 nx, __m128 ny, __m128 nz) noexcept {
    const __m128 one = _mm_set1_ps(1.0f);
    const __m128 len2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx, nx), _mm_mul_ps(ny, ny)), _mm_mul_ps(nz, nz));
    const __m128 positive = _mm_cmpgt_ps(len2, _mm_setzero_ps());
    const __m128 tiny = _mm_and_ps(positive, _mm_cmplt_ps(len2, _mm_set1_ps(1.17549435e-38f)));
    const __m128 y = _mm_rsqrt_ps(len2);
    // y' = y * (3 - len2 * y * y) / 2
    __m128 refined = _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(0.5f), y),
                                _mm_sub_ps(_mm_set1_ps(3.0f), _mm_mul_ps(_mm_mul_ps(len2, y), y)));
    if (_mm_movemask_ps(tiny) != 0) [[unlikely]]
        refined = select(tiny, _mm_div_ps(one, _mm_sqrt_ps(len2)), refined);
    return select(positive, refined, one);
}

}  // namespace m3g::skin::detail
