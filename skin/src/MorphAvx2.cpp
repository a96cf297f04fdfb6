// AVX2 + FMA morphing (target attributes only, see Avx2.h): 32 floats per
// step, acc = fma(w, T - B, acc) per target; the tail uses the same fused
// operation on single lanes. Normals (MorphJob::normalize) are blended 24
// floats (eight triples) per step and renormalised before they are stored.
#include "Kernels.h"

#ifdef M3G_SKIN_X86

#include "Avx2.h"

namespace m3g::skin::detail {

namespace {
M3G_AVX2 inline __m256 clampPs(__m256 v, __m256 lo, __m256 hi) noexcept {
    return _mm256_max_ps(_mm256_min_ps(v, hi), lo);
}

/// One element's blend on a single lane: the vector lanes' operations, so
/// that a tail element gets the bits it would get in a vector.
M3G_AVX2_INLINE float blendOne(const MorphJob& j, std::size_t i, __m128 lo, __m128 hi) noexcept {
    const __m128 b = _mm_load_ss(j.base.data() + i);
    __m128 a = b;
    for (std::size_t t = 0; t < j.targets.size(); ++t)
        a = _mm_fmadd_ss(_mm_set_ss(j.weights[t]), _mm_sub_ss(_mm_load_ss(j.targets[t].data() + i), b), a);
    if (j.clamp) a = _mm_max_ss(_mm_min_ss(a, hi), lo);
    return _mm_cvtss_f32(a);
}

/// Elements [i, i + 8 N) blended (and clamped) into a[0 .. N).
template <int N>
M3G_AVX2_INLINE void blendBlock(const MorphJob& j, std::size_t i, __m256 lo, __m256 hi, __m256 (&a)[N]) noexcept {
    __m256 b[N];
#pragma GCC unroll 4
    for (int k = 0; k < N; ++k) a[k] = b[k] = _mm256_loadu_ps(j.base.data() + i + 8 * k);
    for (std::size_t t = 0; t < j.targets.size(); ++t) {
        const float* tp = j.targets[t].data() + i;
        const __m256 w = _mm256_set1_ps(j.weights[t]);
#pragma GCC unroll 4
        for (int k = 0; k < N; ++k) a[k] = _mm256_fmadd_ps(w, _mm256_sub_ps(_mm256_loadu_ps(tp + 8 * k), b[k]), a[k]);
    }
    if (j.clamp)
#pragma GCC unroll 4
        for (int k = 0; k < N; ++k) a[k] = clampPs(a[k], lo, hi);
}

/// Eight blended xyz triples (24 floats in three registers) renormalised
/// and stored at out: as x, y, z lanes, times inverseLength (the skinning
/// kernels' reciprocal square root and Newton step; 1 for a zero or NaN
/// length, which leaves the triple as it is).
M3G_AVX2_INLINE void storeNormalized(float* out, __m256 a0, __m256 a1, __m256 a2) noexcept {
    __m256 x, y, z;
    soa3FromRegisters(a0, a1, a2, x, y, z);
    const __m256 inv = inverseLength(x, y, z);
    storeSoa3(out, _mm256_mul_ps(x, inv), _mm256_mul_ps(y, inv), _mm256_mul_ps(z, inv));
}

}  // namespace

M3G_AVX2 void morphAvx2(const MorphJob& j, std::size_t begin, std::size_t end) noexcept {
    float* out = j.output.data();
    const __m256 lo = _mm256_set1_ps(j.clampMin), hi = _mm256_set1_ps(j.clampMax);
    const __m128 lo1 = _mm256_castps256_ps128(lo), hi1 = _mm256_castps256_ps128(hi);
    std::size_t i = begin;
    if (j.normalize) {
        // Blended and renormalised in one pass, eight triples per step (the
        // separate pass over the output with a square root and three
        // divisions per four triples was two thirds of a morph frame).
        for (; i + 24 <= end; i += 24) {
            __m256 a[3];
            blendBlock<3>(j, i, lo, hi, a);
            storeNormalized(out + i, a[0], a[1], a[2]);
        }
        if (i < end) {
            // The last triples (end - i < 24, a multiple of 3), blended one
            // lane at a time and renormalised in a block padded with
            // (1, 0, 0): the same lane operations as a full block.
            alignas(32) float block[24];
            for (std::size_t k = 0; k < 24; ++k) block[k] = k % 3 == 0 ? 1.0f : 0.0f;
            for (std::size_t k = 0; k < end - i; ++k) block[k] = blendOne(j, i + k, lo1, hi1);
            storeNormalized(block, _mm256_load_ps(block), _mm256_load_ps(block + 8), _mm256_load_ps(block + 16));
            for (std::size_t k = 0; k < end - i; ++k) out[i + k] = block[k];
        }
        return;
    }
    for (; i + 32 <= end; i += 32) {
        __m256 a[4];
        blendBlock<4>(j, i, lo, hi, a);
#pragma GCC unroll 4
        for (int k = 0; k < 4; ++k) _mm256_storeu_ps(out + i + 8 * k, a[k]);
    }
    for (; i < end; ++i) out[i] = blendOne(j, i, lo1, hi1);
}

}  // namespace m3g::skin::detail

#endif  // M3G_SKIN_X86
