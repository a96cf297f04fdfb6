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

void normalizeSse2(float* xyz, std::size_t triples) noexcept {
    // Four triples per step: three loads, 8 shuffles to x, y, z, the math,
    // a transpose back, overlapping stores (the fourth triple's last store
    // must not reach past the block).
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
        // m0 = x0 y0 z0 x1, m1 = y1 z1 x2 y2, m2 = z2 x3 y3 z3
        const __m128 x = _mm_shuffle_ps(m0, _mm_shuffle_ps(m1, m2, _MM_SHUFFLE(1, 1, 2, 2)), _MM_SHUFFLE(2, 0, 3, 0));
        const __m128 y = _mm_shuffle_ps(_mm_shuffle_ps(m0, m1, _MM_SHUFFLE(0, 0, 1, 1)),
                                        _mm_shuffle_ps(m1, m2, _MM_SHUFFLE(2, 2, 3, 3)), _MM_SHUFFLE(2, 0, 2, 0));
        const __m128 z = _mm_shuffle_ps(_mm_shuffle_ps(m0, m1, _MM_SHUFFLE(1, 1, 2, 2)),
                                        _mm_shuffle_ps(m2, m2, _MM_SHUFFLE(3, 3, 0, 0)), _MM_SHUFFLE(2, 0, 2, 0));
        const __m128 len2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, x), _mm_mul_ps(y, y)), _mm_mul_ps(z, z));
        const __m128 positive = _mm_cmpgt_ps(len2, _mm_setzero_ps());
        const __m128 divisor =
            _mm_or_ps(_mm_and_ps(positive, _mm_sqrt_ps(len2)), _mm_andnot_ps(positive, _mm_set1_ps(1.0f)));
        __m128 r0 = _mm_div_ps(x, divisor), r1 = _mm_div_ps(y, divisor), r2 = _mm_div_ps(z, divisor);
        __m128 r3 = _mm_setzero_ps();
        _MM_TRANSPOSE4_PS(r0, r1, r2, r3);  // r_i = (x_i, y_i, z_i, 0)
        const __m128 v[4] = {r0, r1, r2, r3};
        for (std::size_t i = 0; i < n; ++i) {
            _mm_storel_pi(reinterpret_cast<__m64*>(p + i * 3), v[i]);
            _mm_store_ss(p + i * 3 + 2, _mm_movehl_ps(v[i], v[i]));
        }
    }
}

}  // namespace m3g::skin::detail

#endif  // M3G_SKIN_X86
