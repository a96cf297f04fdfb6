// AVX2 + FMA skinning, chosen at run time (Isa::Avx2). Only the functions
// of this file carry the target attribute (no per-file -mavx2), so no inline
// library function is ever compiled for AVX2 and shared with baseline code.
//
// One vertex at a time: a palette entry is three 256-bit rows
// (P0|P1), (P2|N0), (N1|N2); K entries are blended with 3 FMAs each, the
// blend is multiplied by (p|p), (p|n), (n|n) and the six dot products come
// out of three horizontal adds.
#include "Kernels.h"

#ifdef M3G_SKIN_X86

#include <immintrin.h>

#define M3G_AVX2 __attribute__((target("avx2,fma")))

namespace m3g::skin::detail {

namespace {

M3G_AVX2 inline __m128 loadXyz1(const float* p) noexcept {
    const __m128 xy = _mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(p));
    const __m128 z1 = _mm_unpacklo_ps(_mm_load_ss(p + 2), _mm_set_ss(1.0f));
    return _mm_movelh_ps(xy, z1);
}
M3G_AVX2 inline __m128 loadXyz0(const float* p) noexcept {
    const __m128 xy = _mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(p));
    return _mm_movelh_ps(xy, _mm_load_ss(p + 2));
}
M3G_AVX2 inline void storeXyz(float* p, __m128 v) noexcept {
    _mm_storel_pi(reinterpret_cast<__m64*>(p), v);
    _mm_store_ss(p + 2, _mm_movehl_ps(v, v));
}
M3G_AVX2 inline __m128 hsum4(__m128 t0, __m128 t1, __m128 t2, __m128 t3) noexcept {
    const __m128 ab = _mm_add_ps(_mm_unpacklo_ps(t0, t1), _mm_unpackhi_ps(t0, t1));
    const __m128 cd = _mm_add_ps(_mm_unpacklo_ps(t2, t3), _mm_unpackhi_ps(t2, t3));
    return _mm_add_ps(_mm_movelh_ps(ab, cd), _mm_movehl_ps(cd, ab));
}
M3G_AVX2 inline __m128 normalize(__m128 n) noexcept {
    const __m128 len2 = _mm_dp_ps(n, n, 0x71);  // lanes 0..2 squared, summed into lane 0
    if (!(_mm_cvtss_f32(len2) > 0.0f)) return n;
    const __m128 len = _mm_sqrt_ss(len2);
    return _mm_div_ps(n, _mm_shuffle_ps(len, len, _MM_SHUFFLE(0, 0, 0, 0)));
}
M3G_AVX2 inline __m256 pair(__m128 lo, __m128 hi) noexcept {
    return _mm256_insertf128_ps(_mm256_castps128_ps256(lo), hi, 1);
}

template <int K, bool Normals>
M3G_AVX2 void skinT(const SkinningJob& j, std::size_t begin, std::size_t end) noexcept {
    const int count = K >= 0 ? K : j.influenceCount;
    const auto stride = static_cast<std::size_t>(j.influenceStride);
    const __m128 scale = _mm_setr_ps(j.positionScale, j.positionScale, j.positionScale, 1.0f);
    const __m128 bias = _mm_setr_ps(j.positionBias[0], j.positionBias[1], j.positionBias[2], 0.0f);
    const PaletteEntry* palette = j.palette.data();
    for (std::size_t i = begin; i < end; ++i) {
        const std::size_t v = j.vertices[i];
        const __m128 p = _mm_fmadd_ps(loadXyz1(j.inPositions.data() + v * j.inPositionStride), scale, bias);
        float* op = j.outPositions.data() + v * j.outPositionStride;
        if constexpr (K == 0) {
            storeXyz(op, p);
            if constexpr (Normals)
                storeXyz(j.outNormals.data() + v * j.outNormalStride,
                         normalize(loadXyz0(j.inNormals.data() + v * j.inNormalStride)));
            continue;
        } else {
            const std::int32_t* bi = j.boneIndices.data() + v * stride;
            const float* bw = j.boneWeights.data() + v * stride;
            if constexpr (Normals) {
                __m256 y0, y1, y2;
                {
                    const float* e = reinterpret_cast<const float*>(palette + bi[0]);
                    const __m256 w = _mm256_broadcast_ss(bw);
                    // Entries are 16-byte aligned only: unaligned 256-bit loads.
                    y0 = _mm256_mul_ps(w, _mm256_loadu_ps(e));       // P0 | P1
                    y1 = _mm256_mul_ps(w, _mm256_loadu_ps(e + 8));   // P2 | N0
                    y2 = _mm256_mul_ps(w, _mm256_loadu_ps(e + 16));  // N1 | N2
                }
                for (int k = 1; k < count; ++k) {
                    const float* e = reinterpret_cast<const float*>(palette + bi[k]);
                    const __m256 w = _mm256_broadcast_ss(bw + k);
                    y0 = _mm256_fmadd_ps(w, _mm256_loadu_ps(e), y0);
                    y1 = _mm256_fmadd_ps(w, _mm256_loadu_ps(e + 8), y1);
                    y2 = _mm256_fmadd_ps(w, _mm256_loadu_ps(e + 16), y2);
                }
                const __m128 n = loadXyz0(j.inNormals.data() + v * j.inNormalStride);
                const __m256 m0 = _mm256_mul_ps(y0, pair(p, p));
                const __m256 m1 = _mm256_mul_ps(y1, pair(p, n));
                const __m256 m2 = _mm256_mul_ps(y2, pair(n, n));
                // Per 128-bit half: low = [px, pz, ny, ny], high = [py, nx, nz, nz].
                const __m256 h = _mm256_hadd_ps(_mm256_hadd_ps(m0, m1), _mm256_hadd_ps(m2, m2));
                const __m128 lo = _mm256_castps256_ps128(h);
                const __m128 hi = _mm256_extractf128_ps(h, 1);
                const __m128 pos = _mm_unpacklo_ps(lo, hi);  // px py pz nx
                const __m128 q = _mm_unpackhi_ps(lo, hi);    // ny nz ny nz
                const __m128 nrm = _mm_shuffle_ps(pos, q, _MM_SHUFFLE(1, 0, 3, 3));  // nx nx ny nz
                storeXyz(op, pos);
                storeXyz(j.outNormals.data() + v * j.outNormalStride,
                         normalize(_mm_shuffle_ps(nrm, nrm, _MM_SHUFFLE(0, 3, 2, 1))));
            } else {
                __m256 y0;
                __m128 x2;
                {
                    const float* e = reinterpret_cast<const float*>(palette + bi[0]);
                    const __m256 w = _mm256_broadcast_ss(bw);
                    y0 = _mm256_mul_ps(w, _mm256_loadu_ps(e));
                    x2 = _mm_mul_ps(_mm256_castps256_ps128(w), _mm_load_ps(e + 8));
                }
                for (int k = 1; k < count; ++k) {
                    const float* e = reinterpret_cast<const float*>(palette + bi[k]);
                    const __m256 w = _mm256_broadcast_ss(bw + k);
                    y0 = _mm256_fmadd_ps(w, _mm256_loadu_ps(e), y0);
                    x2 = _mm_fmadd_ps(_mm256_castps256_ps128(w), _mm_load_ps(e + 8), x2);
                }
                const __m256 m0 = _mm256_mul_ps(y0, pair(p, p));
                const __m128 t2 = _mm_mul_ps(x2, p);
                storeXyz(op, hsum4(_mm256_castps256_ps128(m0), _mm256_extractf128_ps(m0, 1), t2, t2));
            }
        }
    }
}

template <bool Normals>
M3G_AVX2 void skinN(const SkinningJob& j, std::size_t begin, std::size_t end) noexcept {
    switch (j.influenceCount) {
        case 0: skinT<0, Normals>(j, begin, end); return;
        case 1: skinT<1, Normals>(j, begin, end); return;
        case 2: skinT<2, Normals>(j, begin, end); return;
        case 3: skinT<3, Normals>(j, begin, end); return;
        case 4: skinT<4, Normals>(j, begin, end); return;
        default: skinT<-1, Normals>(j, begin, end); return;
    }
}

}  // namespace

M3G_AVX2 void skinAvx2(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept {
    if (job.inNormals.empty())
        skinN<false>(job, begin, end);
    else
        skinN<true>(job, begin, end);
}

}  // namespace m3g::skin::detail

#endif  // M3G_SKIN_X86
