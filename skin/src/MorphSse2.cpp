// SSE2 morphing: 16 floats per step (four accumulators), the targets looped
// inside so that each output element is read and written once. The tail uses
// the same single-lane operations, so any split gives identical results.
#include "Kernels.h"

#ifdef M3G_SKIN_X86

#include <emmintrin.h>

namespace m3g::skin::detail {

namespace {
inline __m128 clampPs(__m128 v, __m128 lo, __m128 hi) noexcept { return _mm_max_ps(_mm_min_ps(v, hi), lo); }
inline __m128 clampSs(__m128 v, __m128 lo, __m128 hi) noexcept { return _mm_max_ss(_mm_min_ss(v, hi), lo); }
}  // namespace

void morphSse2(const MorphJob& j, std::size_t begin, std::size_t end) noexcept {
    const std::size_t targets = j.targets.size();
    const float* base = j.base.data();
    float* out = j.output.data();
    const __m128 lo = _mm_set1_ps(j.clampMin), hi = _mm_set1_ps(j.clampMax);
    std::size_t i = begin;
    for (; i + 16 <= end; i += 16) {
        const __m128 b0 = _mm_loadu_ps(base + i), b1 = _mm_loadu_ps(base + i + 4);
        const __m128 b2 = _mm_loadu_ps(base + i + 8), b3 = _mm_loadu_ps(base + i + 12);
        __m128 a0 = b0, a1 = b1, a2 = b2, a3 = b3;
        for (std::size_t t = 0; t < targets; ++t) {
            const float* tp = j.targets[t].data() + i;
            const __m128 w = _mm_set1_ps(j.weights[t]);
            a0 = _mm_add_ps(a0, _mm_mul_ps(w, _mm_sub_ps(_mm_loadu_ps(tp), b0)));
            a1 = _mm_add_ps(a1, _mm_mul_ps(w, _mm_sub_ps(_mm_loadu_ps(tp + 4), b1)));
            a2 = _mm_add_ps(a2, _mm_mul_ps(w, _mm_sub_ps(_mm_loadu_ps(tp + 8), b2)));
            a3 = _mm_add_ps(a3, _mm_mul_ps(w, _mm_sub_ps(_mm_loadu_ps(tp + 12), b3)));
        }
        if (j.clamp) {
            a0 = clampPs(a0, lo, hi);
            a1 = clampPs(a1, lo, hi);
            a2 = clampPs(a2, lo, hi);
            a3 = clampPs(a3, lo, hi);
        }
        _mm_storeu_ps(out + i, a0);
        _mm_storeu_ps(out + i + 4, a1);
        _mm_storeu_ps(out + i + 8, a2);
        _mm_storeu_ps(out + i + 12, a3);
    }
    for (; i < end; ++i) {
        const __m128 b = _mm_load_ss(base + i);
        __m128 a = b;
        for (std::size_t t = 0; t < targets; ++t)
            a = _mm_add_ss(a, _mm_mul_ss(_mm_set_ss(j.weights[t]), _mm_sub_ss(_mm_load_ss(j.targets[t].data() + i), b)));
        if (j.clamp) a = clampSs(a, lo, hi);
        _mm_store_ss(out + i, a);
    }
}

}  // namespace m3g::skin::detail

#endif  // M3G_SKIN_X86
