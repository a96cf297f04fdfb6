// SSE2 palette (the x86-64 baseline, used where the CPU has no AVX2 + FMA):
// PaletteJob's formula in single precision, one bone per iteration, each
// row one 128-bit register. The product's rows are multiply-adds on
// broadcast elements, the cofactor rows (inverse transpose times the
// determinant) cross products of pairs of rows, and 1/det one division,
// selected branch-free to 1 for a singular or non-finite bone: the same
// steps as the AVX2 path without FMAs, some 90 instructions per bone where
// the double loop took about 400 (at 100 vertices and 20 bones the double
// palette was most of the SSE2 frame). Agrees with the double formula to
// float rounding (tested to 1e-6 of the larger of 1 and the element).
#include "Kernels.h"

#ifdef M3G_SKIN_X86

#include <cmath>

#include "Sse2.h"

namespace m3g::skin::detail {

namespace {

/// Element I of v in all four lanes.
template <int I>
inline __m128 splat(__m128 v) noexcept {
    return _mm_shuffle_ps(v, v, _MM_SHUFFLE(I, I, I, I));
}
/// (y, z, x, w) and (z, x, y, w).
inline __m128 yzx(__m128 v) noexcept { return _mm_shuffle_ps(v, v, _MM_SHUFFLE(3, 0, 2, 1)); }
inline __m128 zxy(__m128 v) noexcept { return _mm_shuffle_ps(v, v, _MM_SHUFFLE(3, 1, 0, 2)); }

/// xyz of u x v (w: u.w v.w - u.w v.w, masked away by the caller).
inline __m128 cross(__m128 u, __m128 v) noexcept {
    return _mm_sub_ps(_mm_mul_ps(yzx(u), zxy(v)), _mm_mul_ps(zxy(u), yzx(v)));
}

}  // namespace

void paletteSse2(const PaletteJob& job) noexcept {
    const __m128 wOnly = _mm_castsi128_ps(_mm_setr_epi32(0, 0, 0, -1));
    const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
    const __m128 signBit = _mm_set1_ps(-0.0f), infinity = _mm_set1_ps(HUGE_VALF);
    const bool fold = !isIdentityScaleBias(job.positionScale, job.positionBias);
    const float s = job.positionScale;
    const __m128 scale = _mm_setr_ps(s, s, s, 1.0f);
    const __m128 bias = _mm_setr_ps(job.positionBias[0], job.positionBias[1], job.positionBias[2], 0.0f);
    for (std::size_t b = 0; b < job.boneCount; ++b) {
        const float* a = job.boneToMesh.data() + b * 16;
        const float* r = job.atRest.data() + b * 16;
        const __m128 r0 = _mm_loadu_ps(r), r1 = _mm_loadu_ps(r + 4), r2 = _mm_loadu_ps(r + 8);
        // Row i of a * r (both affine): a[i][0..2] . r's rows, plus a[i][3] in w.
        __m128 m[3];
        for (int i = 0; i < 3; ++i) {
            const __m128 ai = _mm_loadu_ps(a + 4 * i);
            m[i] = _mm_add_ps(_mm_add_ps(_mm_mul_ps(splat<0>(ai), r0), _mm_mul_ps(splat<1>(ai), r1)),
                              _mm_add_ps(_mm_mul_ps(splat<2>(ai), r2), _mm_and_ps(ai, wOnly)));
        }
        // Cofactor rows: cof[i] = m[i+1] x m[i+2] (indices mod 3), w set to 0.
        const __m128 c0 = _mm_andnot_ps(wOnly, cross(m[1], m[2]));
        const __m128 c1 = _mm_andnot_ps(wOnly, cross(m[2], m[0]));
        const __m128 c2 = _mm_andnot_ps(wOnly, cross(m[0], m[1]));
        // det = m0 . c0 (w out: a non-finite translation must not make the
        // 3x3's determinant unusable); 1 / det, or 1 where det is 0 or not
        // finite.
        const __m128 det = sumAll(_mm_andnot_ps(wOnly, _mm_mul_ps(m[0], c0)));
        const __m128 absDet = _mm_andnot_ps(signBit, det);
        const __m128 usable = _mm_and_ps(_mm_cmpgt_ps(absDet, zero), _mm_cmplt_ps(absDet, infinity));
        const __m128 inv = select(usable, _mm_div_ps(one, det), one);
        // The position rows times the job's scale and bias: m[i] (s, s, s, 1)
        // plus m[i] . (bx, by, bz, 0) in w (skipped for 1 and 0, which leave
        // a non-finite row as it is rather than NaN).
        if (fold)
            for (__m128& row : m) row = foldScaleBias(row, scale, bias);
        PaletteEntry& e = job.output[b];
        _mm_storeu_ps(e.position, m[0]);
        _mm_storeu_ps(e.position + 4, m[1]);
        _mm_storeu_ps(e.position + 8, m[2]);
        _mm_storeu_ps(e.normal, _mm_mul_ps(c0, inv));
        _mm_storeu_ps(e.normal + 4, _mm_mul_ps(c1, inv));
        _mm_storeu_ps(e.normal + 8, _mm_mul_ps(c2, inv));
    }
}

}  // namespace m3g::skin::detail

#endif  // M3G_SKIN_X86
