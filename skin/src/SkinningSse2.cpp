// SSE2 skinning (the x86-64 baseline: no target attribute needed). One
// vertex at a time: the K palette rows are blended with 128-bit
// multiply-adds (3 position rows + 3 normal rows), then applied with row
// dot products reduced by a 4x4 transpose.
#include "Kernels.h"

#ifdef M3G_SKIN_X86

#include <emmintrin.h>

namespace m3g::skin::detail {

namespace {

/// (x, y, z, 1) from three floats (reads exactly three).
inline __m128 loadXyz1(const float* p) noexcept {
    const __m128 xy = _mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(p));
    const __m128 z1 = _mm_unpacklo_ps(_mm_load_ss(p + 2), _mm_set_ss(1.0f));
    return _mm_movelh_ps(xy, z1);
}
/// (x, y, z, 0) from three floats.
inline __m128 loadXyz0(const float* p) noexcept {
    const __m128 xy = _mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(p));
    return _mm_movelh_ps(xy, _mm_load_ss(p + 2));
}
/// Writes lanes 0..2.
inline void storeXyz(float* p, __m128 v) noexcept {
    _mm_storel_pi(reinterpret_cast<__m64*>(p), v);
    _mm_store_ss(p + 2, _mm_movehl_ps(v, v));
}
/// (sum t0, sum t1, sum t2, sum t3): four horizontal sums at once.
inline __m128 hsum4(__m128 t0, __m128 t1, __m128 t2, __m128 t3) noexcept {
    const __m128 ab = _mm_add_ps(_mm_unpacklo_ps(t0, t1), _mm_unpackhi_ps(t0, t1));
    const __m128 cd = _mm_add_ps(_mm_unpacklo_ps(t2, t3), _mm_unpackhi_ps(t2, t3));
    return _mm_add_ps(_mm_movelh_ps(ab, cd), _mm_movehl_ps(cd, ab));
}
/// n / |n| on lanes 0..2 (lane 3 ignored); zero length stays as it is.
inline __m128 normalize(__m128 n) noexcept {
    const __m128 sq = _mm_mul_ps(n, n);
    const __m128 len2 = _mm_add_ss(_mm_add_ss(sq, _mm_shuffle_ps(sq, sq, _MM_SHUFFLE(1, 1, 1, 1))),
                                   _mm_shuffle_ps(sq, sq, _MM_SHUFFLE(2, 2, 2, 2)));
    if (!(_mm_cvtss_f32(len2) > 0.0f)) return n;
    const __m128 len = _mm_sqrt_ss(len2);
    return _mm_div_ps(n, _mm_shuffle_ps(len, len, _MM_SHUFFLE(0, 0, 0, 0)));
}

template <int K, bool Normals>
void skinT(const SkinningJob& j, std::size_t begin, std::size_t end) noexcept {
    const int count = K >= 0 ? K : j.influenceCount;
    const auto stride = static_cast<std::size_t>(j.influenceStride);
    const __m128 scale = _mm_setr_ps(j.positionScale, j.positionScale, j.positionScale, 1.0f);
    const __m128 bias = _mm_setr_ps(j.positionBias[0], j.positionBias[1], j.positionBias[2], 0.0f);
    const PaletteEntry* palette = j.palette.data();
    for (std::size_t i = begin; i < end; ++i) {
        const std::size_t v = j.vertices[i];
        const __m128 p = _mm_add_ps(_mm_mul_ps(loadXyz1(j.inPositions.data() + v * j.inPositionStride), scale), bias);
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
            __m128 r0, r1, r2, n0, n1, n2;
            {
                const float* e = reinterpret_cast<const float*>(palette + bi[0]);
                const __m128 w = _mm_set1_ps(bw[0]);
                r0 = _mm_mul_ps(w, _mm_load_ps(e));
                r1 = _mm_mul_ps(w, _mm_load_ps(e + 4));
                r2 = _mm_mul_ps(w, _mm_load_ps(e + 8));
                if constexpr (Normals) {
                    n0 = _mm_mul_ps(w, _mm_load_ps(e + 12));
                    n1 = _mm_mul_ps(w, _mm_load_ps(e + 16));
                    n2 = _mm_mul_ps(w, _mm_load_ps(e + 20));
                }
            }
            for (int k = 1; k < count; ++k) {
                const float* e = reinterpret_cast<const float*>(palette + bi[k]);
                const __m128 w = _mm_set1_ps(bw[k]);
                r0 = _mm_add_ps(r0, _mm_mul_ps(w, _mm_load_ps(e)));
                r1 = _mm_add_ps(r1, _mm_mul_ps(w, _mm_load_ps(e + 4)));
                r2 = _mm_add_ps(r2, _mm_mul_ps(w, _mm_load_ps(e + 8)));
                if constexpr (Normals) {
                    n0 = _mm_add_ps(n0, _mm_mul_ps(w, _mm_load_ps(e + 12)));
                    n1 = _mm_add_ps(n1, _mm_mul_ps(w, _mm_load_ps(e + 16)));
                    n2 = _mm_add_ps(n2, _mm_mul_ps(w, _mm_load_ps(e + 20)));
                }
            }
            const __m128 t2 = _mm_mul_ps(r2, p);
            storeXyz(op, hsum4(_mm_mul_ps(r0, p), _mm_mul_ps(r1, p), t2, t2));
            if constexpr (Normals) {
                const __m128 n = loadXyz0(j.inNormals.data() + v * j.inNormalStride);
                const __m128 u2 = _mm_mul_ps(n2, n);
                storeXyz(j.outNormals.data() + v * j.outNormalStride,
                         normalize(hsum4(_mm_mul_ps(n0, n), _mm_mul_ps(n1, n), u2, u2)));
            }
        }
    }
}

template <bool Normals>
void skinN(const SkinningJob& j, std::size_t begin, std::size_t end) noexcept {
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

void skinSse2(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept {
    if (job.inNormals.empty())
        skinN<false>(job, begin, end);
    else
        skinN<true>(job, begin, end);
}

}  // namespace m3g::skin::detail

#endif  // M3G_SKIN_X86
