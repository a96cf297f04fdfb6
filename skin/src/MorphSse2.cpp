// SSE2 morphing: 16 floats per step (four accumulators), the targets looped
// inside so that each output element is read and written once. The tail uses
// the same single-lane operations, so any split gives identical results.
// Normals (MorphJob::normalize) are blended 12 floats (four triples) per
// step and renormalised before they are stored.
#include "Kernels.h"

#ifdef M3G_SKIN_X86

#include "Sse2.h"

namespace m3g::skin::detail {

namespace {
inline __m128 clampPs(__m128 v, __m128 lo, __m128 hi) noexcept { return _mm_max_ps(_mm_min_ps(v, hi), lo); }
inline __m128 clampSs(__m128 v, __m128 lo, __m128 hi) noexcept { return _mm_max_ss(_mm_min_ss(v, hi), lo); }
}  // namespace

namespace {

/// One element's blend on a single lane: the vector lanes' operations.
inline float blendOne(const MorphJob& j, std::size_t i, __m128 lo, __m128 hi) noexcept {
    const __m128 b = _mm_load_ss(j.base.data() + i);
    __m128 a = b;
    for (std::size_t t = 0; t < j.targets.size(); ++t)
        a = _mm_add_ss(a, _mm_mul_ss(_mm_set_ss(j.weights[t]), _mm_sub_ss(_mm_load_ss(j.targets[t].data() + i), b)));
    if (j.clamp) a = clampSs(a, lo, hi);
    return _mm_cvtss_f32(a);
}

/// Elements [i, i + 4 N) blended (and clamped) into a[0 .. N).
template <int N>
inline void blendBlock(const MorphJob& j, std::size_t i, __m128 lo, __m128 hi, __m128 (&a)[N]) noexcept {
    __m128 b[N];
#pragma GCC unroll 4
    for (int k = 0; k < N; ++k) a[k] = b[k] = _mm_loadu_ps(j.base.data() + i + 4 * k);
    for (std::size_t t = 0; t < j.targets.size(); ++t) {
        const float* tp = j.targets[t].data() + i;
        const __m128 w = _mm_set1_ps(j.weights[t]);
#pragma GCC unroll 4
        for (int k = 0; k < N; ++k) a[k] = _mm_add_ps(a[k], _mm_mul_ps(w, _mm_sub_ps(_mm_loadu_ps(tp + 4 * k), b[k])));
    }
    if (j.clamp)
#pragma GCC unroll 4
        for (int k = 0; k < N; ++k) a[k] = clampPs(a[k], lo, hi);
}

/// Four blended xyz triples (12 floats in three registers) renormalised and
/// stored at out (inverseLength: 1 for a zero or NaN length, which leaves
/// the triple as it is).
inline void storeNormalized(float* out, const __m128 (&a)[3]) noexcept {
    __m128 x, y, z;
    soa3FromRegisters(a[0], a[1], a[2], x, y, z);
    const __m128 inv = inverseLength(x, y, z);
    __m128 r0, r1, r2;
    soa3ToXyz(_mm_mul_ps(x, inv), _mm_mul_ps(y, inv), _mm_mul_ps(z, inv), r0, r1, r2);
    _mm_storeu_ps(out, r0);
    _mm_storeu_ps(out + 4, r1);
    _mm_storeu_ps(out + 8, r2);
}

}  // namespace

void morphSse2(const MorphJob& j, std::size_t begin, std::size_t end) noexcept {
    float* out = j.output.data();
    const __m128 lo = _mm_set1_ps(j.clampMin), hi = _mm_set1_ps(j.clampMax);
    std::size_t i = begin;
    if (j.normalize) {
        // Blended and renormalised in one pass, four triples per step.
        for (; i + 12 <= end; i += 12) {
            __m128 a[3];
            blendBlock<3>(j, i, lo, hi, a);
            storeNormalized(out + i, a);
        }
        if (i < end) {
            // The last triples (end - i < 12, a multiple of 3), blended one
            // lane at a time and renormalised in a block padded with (1, 0, 0).
            alignas(16) float block[12] = {1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0};
            for (std::size_t k = 0; k < end - i; ++k) block[k] = blendOne(j, i + k, lo, hi);
            const __m128 a[3] = {_mm_load_ps(block), _mm_load_ps(block + 4), _mm_load_ps(block + 8)};
            storeNormalized(block, a);
            for (std::size_t k = 0; k < end - i; ++k) out[i + k] = block[k];
        }
        return;
    }
    for (; i + 16 <= end; i += 16) {
        __m128 a[4];
        blendBlock<4>(j, i, lo, hi, a);
#pragma GCC unroll 4
        for (int k = 0; k < 4; ++k) _mm_storeu_ps(out + i + 4 * k, a[k]);
    }
    for (; i < end; ++i) out[i] = blendOne(j, i, lo, hi);
}

}  // namespace m3g::skin::detail

#endif  // M3G_SKIN_X86
