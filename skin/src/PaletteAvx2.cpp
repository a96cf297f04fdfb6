// AVX2 + FMA palette (Isa::Avx2 CPUs): PaletteJob's formula with one bone's
// rows as four doubles per register. The product's rows are three FMAs
// each, the cofactor rows (inverse transpose times the determinant) are
// cross products of pairs of rows, so a bone costs some 60 instructions
// instead of the plain loop's 200 or so, which matters for the paper's
// small meshes (100 vertices, 20 bones: the palette is most of a frame).
// Still double precision, rounded once to float; FMAs may round the double
// intermediate differently from the plain loop (far below float precision).
#include "Kernels.h"

#ifdef M3G_SKIN_X86

#include <cmath>

#include <immintrin.h>

#define M3G_AVX2 __attribute__((target("avx2,fma")))

namespace m3g::skin::detail {

namespace {

/// (y, z, x, w) and (z, x, y, w) of a row.
M3G_AVX2 inline __m256d yzx(__m256d v) noexcept { return _mm256_permute4x64_pd(v, _MM_SHUFFLE(3, 0, 2, 1)); }
M3G_AVX2 inline __m256d zxy(__m256d v) noexcept { return _mm256_permute4x64_pd(v, _MM_SHUFFLE(3, 1, 0, 2)); }

/// xyz of u x v (w: 0 for finite rows, blended to 0 by the caller anyway).
M3G_AVX2 inline __m256d cross(__m256d u, __m256d v) noexcept {
    return _mm256_fmsub_pd(yzx(u), zxy(v), _mm256_mul_pd(zxy(u), yzx(v)));
}

}  // namespace

M3G_AVX2 void paletteAvx2(const PaletteJob& job) noexcept {
    const __m256d zero = _mm256_setzero_pd();
    for (std::size_t b = 0; b < job.boneCount; ++b) {
        const float* a = job.boneToMesh.data() + b * 16;
        const float* r = job.atRest.data() + b * 16;
        const __m256d r0 = _mm256_cvtps_pd(_mm_loadu_ps(r));
        const __m256d r1 = _mm256_cvtps_pd(_mm_loadu_ps(r + 4));
        const __m256d r2 = _mm256_cvtps_pd(_mm_loadu_ps(r + 8));
        // Row i of a * r (both affine): a[i][0..2] . r's rows, plus a[i][3] in w.
        __m256d m[3];
#pragma GCC unroll 3
        for (int i = 0; i < 3; ++i) {
            const __m256d ai = _mm256_cvtps_pd(_mm_loadu_ps(a + 4 * i));
            const __m256d t = _mm256_blend_pd(zero, ai, 0x8);  // (0, 0, 0, a[i][3])
            m[i] = _mm256_fmadd_pd(_mm256_permute4x64_pd(ai, _MM_SHUFFLE(2, 2, 2, 2)), r2,
                                   _mm256_fmadd_pd(_mm256_permute4x64_pd(ai, _MM_SHUFFLE(1, 1, 1, 1)), r1,
                                                   _mm256_fmadd_pd(_mm256_permute4x64_pd(ai, 0), r0, t)));
        }
        // Cofactor rows: cof[i] = m[i+1] x m[i+2] (indices mod 3).
        const __m256d c0 = cross(m[1], m[2]), c1 = cross(m[2], m[0]), c2 = cross(m[0], m[1]);
        const __m256d d = _mm256_mul_pd(m[0], c0);
        const __m128d dlo = _mm256_castpd256_pd128(d);
        const __m128d det = _mm_add_sd(_mm_add_sd(dlo, _mm_unpackhi_pd(dlo, dlo)), _mm256_extractf128_pd(d, 1));
        // 1 / det, or 1 where det is 0 or not finite (branch-free: the
        // division's latency overlaps the next bone's work).
        const __m128d absDet = _mm_andnot_pd(_mm_set_sd(-0.0), det);
        const __m128d usable = _mm_and_pd(_mm_cmpgt_sd(absDet, _mm_setzero_pd()),
                                          _mm_cmplt_sd(absDet, _mm_set_sd(HUGE_VAL)));
        const __m128d inv = _mm_blendv_pd(_mm_set_sd(1.0), _mm_div_sd(_mm_set_sd(1.0), det), usable);
        const __m256d scale = _mm256_broadcastsd_pd(inv);
        PaletteEntry& e = job.output[b];
        _mm_storeu_ps(e.position, _mm256_cvtpd_ps(m[0]));
        _mm_storeu_ps(e.position + 4, _mm256_cvtpd_ps(m[1]));
        _mm_storeu_ps(e.position + 8, _mm256_cvtpd_ps(m[2]));
        _mm_storeu_ps(e.normal, _mm256_cvtpd_ps(_mm256_blend_pd(_mm256_mul_pd(c0, scale), zero, 0x8)));
        _mm_storeu_ps(e.normal + 4, _mm256_cvtpd_ps(_mm256_blend_pd(_mm256_mul_pd(c1, scale), zero, 0x8)));
        _mm_storeu_ps(e.normal + 8, _mm256_cvtpd_ps(_mm256_blend_pd(_mm256_mul_pd(c2, scale), zero, 0x8)));
    }
}

}  // namespace m3g::skin::detail

#endif  // M3G_SKIN_X86
