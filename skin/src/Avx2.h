// Internal: what the AVX2 + FMA kernels (SkinningAvx2.cpp, PaletteAvx2.cpp,
// MorphAvx2.cpp) share. Only those functions carry the target attribute (no
// per-file -mavx2), so no inline library function is ever compiled for AVX2
// and shared with baseline code. Include inside M3G_SKIN_X86 only.
#pragma once

#include <immintrin.h>

#define M3G_AVX2 __attribute__((target("avx2,fma")))
// Inlined whatever the -O level: a call per vertex returning vectors through
// memory costs more than the work.
#define M3G_AVX2_INLINE __attribute__((target("avx2,fma"), always_inline)) inline

namespace m3g::skin::detail {

/// Four floats at `lo` | four at `hi`.
M3G_AVX2_INLINE __m256 halves(const float* lo, const float* hi) noexcept {
    return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(lo)), _mm_loadu_ps(hi), 1);
}

/// The sum of the four elements of each 128-bit half, in every element of
/// that half (a dot product per half after a multiply).
M3G_AVX2_INLINE __m256 sumPerHalf(__m256 v) noexcept {
    const __m256 pairs = _mm256_add_ps(v, _mm256_permute_ps(v, _MM_SHUFFLE(1, 0, 3, 2)));
    return _mm256_add_ps(pairs, _mm256_permute_ps(pairs, _MM_SHUFFLE(2, 3, 0, 1)));
}

}  // namespace m3g::skin::detail
