// Internal: what the AVX-512 kernels share: the target macros, sixteen xyz
// triples to and from x, y, z lanes, the reciprocal length. Like Avx2.h,
// only functions carrying the target attribute use these instructions, so
// the library still runs on any x86-64 CPU. Include inside M3G_SKIN_X86.
#pragma once

#include <immintrin.h>

#include <array>
#include <cstddef>
#include <cstdint>

#define M3G_AVX512 __attribute__((target("avx512f,avx2,fma")))
#define M3G_AVX512_INLINE __attribute__((target("avx512f,avx2,fma"), always_inline)) inline

namespace m3g::skin::detail {

/// Permutation indices for sixteen xyz triples held in three registers
/// (floats 0-15, 16-31, 32-47): two two-source permutes per lane vector
/// each way (vpermt2ps), so a block costs six shuffles to load and six to
/// store, against 24 lane moves.
struct Soa3Indices {
    // Load: component c of vertex i is float 3i + c. The first permute takes
    // what lies in registers 0 and 1 (floats < 32), the second the rest from
    // register 2 (index 16 + float - 32 there; the first result at 0..15).
    std::array<std::array<std::int32_t, 16>, 3> gather01, gather2;
    // Store: float j of register o is component (16o + j) % 3 of vertex
    // (16o + j) / 3: x and y from the first permute (x: index vertex, y:
    // 16 + vertex), z from the second (16 + vertex; the rest pass through).
    std::array<std::array<std::int32_t, 16>, 3> scatterXy, scatterZ;
};

constexpr Soa3Indices makeSoa3Indices() noexcept {
    Soa3Indices s{};
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 16; ++i) {
            const int f = 3 * i + c;
            s.gather01[c][i] = f < 32 ? f : 0;
            s.gather2[c][i] = f < 32 ? i : 16 + (f - 32);
        }
    for (int o = 0; o < 3; ++o)
        for (int j = 0; j < 16; ++j) {
            const int f = 16 * o + j, vertex = f / 3, component = f % 3;
            // Vertices of register o: 16o/3 .. (16o + 15)/3, always < 16.
            s.scatterXy[o][j] = component == 0 ? vertex : component == 1 ? 16 + vertex : 0;
            s.scatterZ[o][j] = component == 2 ? 16 + vertex : j;
        }
    return s;
}

inline constexpr Soa3Indices kSoa3 = makeSoa3Indices();

M3G_AVX512_INLINE __m512i soa3Index(const std::array<std::int32_t, 16>& a) noexcept {
    return _mm512_loadu_si512(a.data());
}

/// The masks of the three registers holding the first `lanes` (0..16)
/// vertices' 3 * lanes floats.
M3G_AVX512_INLINE void soa3Masks(std::size_t lanes, __mmask16& m0, __mmask16& m1, __mmask16& m2) noexcept {
    const std::size_t floats = 3 * lanes;
    auto mask = [](std::size_t n) { return static_cast<__mmask16>(n >= 16 ? 0xFFFFu : (1u << n) - 1u); };
    m0 = mask(floats);
    m1 = mask(floats > 16 ? floats - 16 : 0);
    m2 = mask(floats > 32 ? floats - 32 : 0);
}

/// Three registers of sixteen xyz triples (floats 0-15, 16-31, 32-47) as x,
/// y, z lanes.
M3G_AVX512_INLINE void soa3FromXyz(__m512 a, __m512 b, __m512 c, __m512& x, __m512& y, __m512& z) noexcept {
    x = _mm512_permutex2var_ps(_mm512_permutex2var_ps(a, soa3Index(kSoa3.gather01[0]), b),
                               soa3Index(kSoa3.gather2[0]), c);
    y = _mm512_permutex2var_ps(_mm512_permutex2var_ps(a, soa3Index(kSoa3.gather01[1]), b),
                               soa3Index(kSoa3.gather2[1]), c);
    z = _mm512_permutex2var_ps(_mm512_permutex2var_ps(a, soa3Index(kSoa3.gather01[2]), b),
                               soa3Index(kSoa3.gather2[2]), c);
}

/// x, y, z lanes as the three registers of their xyz triples.
M3G_AVX512_INLINE void soa3ToXyz16(__m512 x, __m512 y, __m512 z, __m512& o0, __m512& o1, __m512& o2) noexcept {
    o0 = _mm512_permutex2var_ps(_mm512_permutex2var_ps(x, soa3Index(kSoa3.scatterXy[0]), y),
                                soa3Index(kSoa3.scatterZ[0]), z);
    o1 = _mm512_permutex2var_ps(_mm512_permutex2var_ps(x, soa3Index(kSoa3.scatterXy[1]), y),
                                soa3Index(kSoa3.scatterZ[1]), z);
    o2 = _mm512_permutex2var_ps(_mm512_permutex2var_ps(x, soa3Index(kSoa3.scatterXy[2]), y),
                                soa3Index(kSoa3.scatterZ[2]), z);
}

/// Sixteen packed xyz triples at `p` as x, y, z lanes.
M3G_AVX512_INLINE void loadSoa3x16(const float* p, __m512& x, __m512& y, __m512& z) noexcept {
    soa3FromXyz(_mm512_loadu_ps(p), _mm512_loadu_ps(p + 16), _mm512_loadu_ps(p + 32), x, y, z);
}

/// The first `lanes` (< 16) xyz triples at `p`: only their 3 * lanes floats
/// are read (masked loads; the other lanes are 0).
M3G_AVX512_INLINE void loadSoa3x16(const float* p, std::size_t lanes, __m512& x, __m512& y, __m512& z) noexcept {
    __mmask16 m0, m1, m2;
    soa3Masks(lanes, m0, m1, m2);
    soa3FromXyz(_mm512_maskz_loadu_ps(m0, p), _mm512_maskz_loadu_ps(m1, p + 16), _mm512_maskz_loadu_ps(m2, p + 32),
                x, y, z);
}

/// Sixteen lanes of x, y, z to the packed xyz triples at `out`.
M3G_AVX512_INLINE void storeSoa3x16(float* out, __m512 x, __m512 y, __m512 z) noexcept {
    __m512 o0, o1, o2;
    soa3ToXyz16(x, y, z, o0, o1, o2);
    _mm512_storeu_ps(out, o0);
    _mm512_storeu_ps(out + 16, o1);
    _mm512_storeu_ps(out + 32, o2);
}

/// Lanes 0 .. lanes-1 (lanes < 16): only their 3 * lanes floats are
/// written (masked stores).
M3G_AVX512_INLINE void storeSoa3x16(float* out, std::size_t lanes, __m512 x, __m512 y, __m512 z) noexcept {
    __mmask16 m0, m1, m2;
    soa3Masks(lanes, m0, m1, m2);
    __m512 o0, o1, o2;
    soa3ToXyz16(x, y, z, o0, o1, o2);
    _mm512_mask_storeu_ps(out, m0, o0);
    _mm512_mask_storeu_ps(out + 16, m1, o1);
    _mm512_mask_storeu_ps(out + 32, m2, o2);
}

/// 1 / |n| per lane, or 1 where |n|^2 is zero (or NaN): the 14-bit
/// reciprocal square root estimate plus one Newton step (relative error
/// about 2^-24, below the AVX2 path's), the exact 1 / sqrt for lanes whose
/// |n|^2 is below FLT_MIN, where the estimate is not usable.
M3G_AVX512_INLINE __m512 inverseLength16(__m512 nx, __m512 ny, __m512 nz) noexcept {
    const __m512 one = _mm512_set1_ps(1.0f);
    const __m512 len2 = _mm512_fmadd_ps(nz, nz, _mm512_fmadd_ps(ny, ny, _mm512_mul_ps(nx, nx)));
    const __mmask16 positive = _mm512_cmp_ps_mask(len2, _mm512_setzero_ps(), _CMP_GT_OQ);
    const __mmask16 tiny =
        _mm512_mask_cmp_ps_mask(positive, len2, _mm512_set1_ps(1.17549435e-38f), _CMP_LT_OQ);
    // The zero-masked forms: the plain intrinsics start from an undefined
    // register, which GCC 12 reports as maybe uninitialised.
    const __m512 y = _mm512_maskz_rsqrt14_ps(0xFFFF, len2);
    // y' = y * (3 - len2 * y * y) / 2
    __m512 refined = _mm512_mul_ps(_mm512_mul_ps(_mm512_set1_ps(0.5f), y),
                                   _mm512_fnmadd_ps(_mm512_mul_ps(len2, y), y, _mm512_set1_ps(3.0f)));
    if (tiny != 0) [[unlikely]]
        refined = _mm512_mask_div_ps(refined, tiny, one, _mm512_maskz_sqrt_ps(tiny, len2));
    return _mm512_mask_blend_ps(positive, one, refined);
}

}  // namespace m3g::skin::detail
