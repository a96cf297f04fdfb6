// AVX2 + FMA morphing (target attributes only, see SkinningAvx2.cpp):
// 32 floats per step, acc = fma(w, T - B, acc) per target; the tail uses the
// same fused operation on single lanes.
#include "Kernels.h"

#ifdef M3G_SKIN_X86


#include "Avx2.h"

namespace m3g::skin::detail {

namespace {
M3G_AVX2 inline __m256 clampPs(__m256 v, __m256 lo, __m256 hi) noexcept {
    return _mm256_max_ps(_mm256_min_ps(v, hi), lo);
}
}  // namespace

M3G_AVX2 void morphAvx2(const MorphJob& j, std::size_t begin, std::size_t end) noexcept {
    const std::size_t targets = j.targets.size();
    const float* base = j.base.data();
    float* out = j.output.data();
    const __m256 lo = _mm256_set1_ps(j.clampMin), hi = _mm256_set1_ps(j.clampMax);
    std::size_t i = begin;
    for (; i + 32 <= end; i += 32) {
        const __m256 b0 = _mm256_loadu_ps(base + i), b1 = _mm256_loadu_ps(base + i + 8);
        const __m256 b2 = _mm256_loadu_ps(base + i + 16), b3 = _mm256_loadu_ps(base + i + 24);
        __m256 a0 = b0, a1 = b1, a2 = b2, a3 = b3;
        for (std::size_t t = 0; t < targets; ++t) {
            const float* tp = j.targets[t].data() + i;
            const __m256 w = _mm256_set1_ps(j.weights[t]);
            a0 = _mm256_fmadd_ps(w, _mm256_sub_ps(_mm256_loadu_ps(tp), b0), a0);
            a1 = _mm256_fmadd_ps(w, _mm256_sub_ps(_mm256_loadu_ps(tp + 8), b1), a1);
            a2 = _mm256_fmadd_ps(w, _mm256_sub_ps(_mm256_loadu_ps(tp + 16), b2), a2);
            a3 = _mm256_fmadd_ps(w, _mm256_sub_ps(_mm256_loadu_ps(tp + 24), b3), a3);
        }
        if (j.clamp) {
            a0 = clampPs(a0, lo, hi);
            a1 = clampPs(a1, lo, hi);
            a2 = clampPs(a2, lo, hi);
            a3 = clampPs(a3, lo, hi);
        }
        _mm256_storeu_ps(out + i, a0);
        _mm256_storeu_ps(out + i + 8, a1);
        _mm256_storeu_ps(out + i + 16, a2);
        _mm256_storeu_ps(out + i + 24, a3);
    }
    const __m128 lo1 = _mm256_castps256_ps128(lo), hi1 = _mm256_castps256_ps128(hi);
    for (; i < end; ++i) {
        const __m128 b = _mm_load_ss(base + i);
        __m128 a = b;
        for (std::size_t t = 0; t < targets; ++t)
            a = _mm_fmadd_ss(_mm_set_ss(j.weights[t]), _mm_sub_ss(_mm_load_ss(j.targets[t].data() + i), b), a);
        if (j.clamp) a = _mm_max_ss(_mm_min_ss(a, hi1), lo1);
        _mm_store_ss(out + i, a);
    }
}

M3G_AVX2 void normalizeAvx2(float* xyz, std::size_t triples) noexcept {
    // As normalizeSse2 (four triples per step, shuffled to x, y, z in
    // registers), with a fused len^2.
    for (std::size_t first = 0; first < triples; first += 4) {
        const std::size_t n = triples - first < 4 ? triples - first : 4;
        float* p = xyz + first * 3;
        alignas(16) float partial[12] = {1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0};  // padding: (1, 0, 0)
        const float* src = p;
        if (n < 4) {
            for (std::size_t i = 0; i < n * 3; ++i) partial[i] = p[i];
            src = partial;
        }
        const __m128 m0 = _mm_loadu_ps(src), m1 = _mm_loadu_ps(src + 4), m2 = _mm_loadu_ps(src + 8);
        const __m128 x = _mm_shuffle_ps(m0, _mm_shuffle_ps(m1, m2, _MM_SHUFFLE(1, 1, 2, 2)), _MM_SHUFFLE(2, 0, 3, 0));
        const __m128 y = _mm_shuffle_ps(_mm_shuffle_ps(m0, m1, _MM_SHUFFLE(0, 0, 1, 1)),
                                        _mm_shuffle_ps(m1, m2, _MM_SHUFFLE(2, 2, 3, 3)), _MM_SHUFFLE(2, 0, 2, 0));
        const __m128 z = _mm_shuffle_ps(_mm_shuffle_ps(m0, m1, _MM_SHUFFLE(1, 1, 2, 2)),
                                        _mm_shuffle_ps(m2, m2, _MM_SHUFFLE(3, 3, 0, 0)), _MM_SHUFFLE(2, 0, 2, 0));
        const __m128 len2 = _mm_fmadd_ps(z, z, _mm_fmadd_ps(y, y, _mm_mul_ps(x, x)));
        const __m128 positive = _mm_cmp_ps(len2, _mm_setzero_ps(), _CMP_GT_OQ);
        const __m128 divisor = _mm_blendv_ps(_mm_set1_ps(1.0f), _mm_sqrt_ps(len2), positive);
        __m128 r0 = _mm_div_ps(x, divisor), r1 = _mm_div_ps(y, divisor), r2 = _mm_div_ps(z, divisor);
        __m128 r3 = _mm_setzero_ps();
        _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
        const __m128 v[4] = {r0, r1, r2, r3};
        for (std::size_t i = 0; i < n; ++i) {
            _mm_storel_pi(reinterpret_cast<__m64*>(p + i * 3), v[i]);
            _mm_store_ss(p + i * 3 + 2, _mm_movehl_ps(v[i], v[i]));
        }
    }
}

}  // namespace m3g::skin::detail

#endif  // M3G_SKIN_X86
