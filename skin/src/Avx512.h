// Internal: what the AVX-512 kernels share: the target macros, the lane
// width as a type (Lanes<16>: 512-bit registers, Lanes<8>: 256-bit ones
// with the AVX-512VL forms of the same instructions), xyz triples to and
// from x, y, z lanes, the reciprocal length. Like Avx2.h, only functions
// carrying the target attribute use these instructions, so the library
// still runs on any x86-64 CPU. Include inside M3G_SKIN_X86.
//
// Why two widths: a run's last block, or a whole short run, often holds
// eight vertices or fewer (test.m3g's bone runs average ten), and cores
// that split 512-bit operations in two (Zen 4) spend on a 16-lane block
// twice what an 8-lane one costs. Every operation below is the same
// instruction at either width, so a lane's result does not depend on the
// width it was computed at (the reciprocal square root estimate included:
// VRSQRT14PS is specified bit for bit).
#pragma once

#include <immintrin.h>

#include <array>
#include <cstddef>
#include <cstdint>

#define M3G_AVX512 __attribute__((target("avx512f,avx512vl,avx2,fma")))
#define M3G_AVX512_INLINE __attribute__((target("avx512f,avx512vl,avx2,fma"), always_inline)) inline

namespace m3g::skin::detail {

template <int W>
struct Lanes;

/// Sixteen lanes: 512-bit registers.
template <>
struct Lanes<16> {
    using V = __m512;
    using I = __m512i;
    using M = __mmask16;
    static constexpr int kWidth = 16;
    M3G_AVX512_INLINE static V set1(float a) noexcept { return _mm512_set1_ps(a); }
    M3G_AVX512_INLINE static V zero() noexcept { return _mm512_setzero_ps(); }
    M3G_AVX512_INLINE static V fmadd(V a, V b, V c) noexcept { return _mm512_fmadd_ps(a, b, c); }
    M3G_AVX512_INLINE static V fnmadd(V a, V b, V c) noexcept { return _mm512_fnmadd_ps(a, b, c); }
    M3G_AVX512_INLINE static V mul(V a, V b) noexcept { return _mm512_mul_ps(a, b); }
    M3G_AVX512_INLINE static V load(const float* p) noexcept { return _mm512_loadu_ps(p); }
    M3G_AVX512_INLINE static V load(M m, const float* p) noexcept { return _mm512_maskz_loadu_ps(m, p); }
    M3G_AVX512_INLINE static void store(float* p, V v) noexcept { _mm512_storeu_ps(p, v); }
    M3G_AVX512_INLINE static void store(float* p, M m, V v) noexcept { _mm512_mask_storeu_ps(p, m, v); }
    M3G_AVX512_INLINE static I index(const std::int32_t* p) noexcept { return _mm512_loadu_si512(p); }
    M3G_AVX512_INLINE static V permute2(V a, I index, V b) noexcept { return _mm512_permutex2var_ps(a, index, b); }
    M3G_AVX512_INLINE static V blend(M m, V a, V b) noexcept { return _mm512_mask_blend_ps(m, a, b); }
    M3G_AVX512_INLINE static I add(I a, I b) noexcept { return _mm512_add_epi32(a, b); }
    M3G_AVX512_INLINE static I set1i(int a) noexcept { return _mm512_set1_epi32(a); }
    M3G_AVX512_INLINE static I mulloi(I a, I b) noexcept { return _mm512_mullo_epi32(a, b); }
    M3G_AVX512_INLINE static V gather(M m, I index, const float* base) noexcept {
        return _mm512_mask_i32gather_ps(_mm512_setzero_ps(), m, index, base, 4);
    }
    M3G_AVX512_INLINE static M greater(V a, V b) noexcept { return _mm512_cmp_ps_mask(a, b, _CMP_GT_OQ); }
    M3G_AVX512_INLINE static M less(M m, V a, V b) noexcept { return _mm512_mask_cmp_ps_mask(m, a, b, _CMP_LT_OQ); }
    // The zero-masked forms: the plain intrinsics start from an undefined
    // register, which GCC 12 reports as maybe uninitialised.
    M3G_AVX512_INLINE static V rsqrt14(V a) noexcept { return _mm512_maskz_rsqrt14_ps(0xFFFF, a); }
    M3G_AVX512_INLINE static V sqrt(M m, V a) noexcept { return _mm512_maskz_sqrt_ps(m, a); }
    M3G_AVX512_INLINE static V div(V src, M m, V a, V b) noexcept { return _mm512_mask_div_ps(src, m, a, b); }
};

/// Eight lanes: 256-bit registers, the AVX-512VL forms.
template <>
struct Lanes<8> {
    using V = __m256;
    using I = __m256i;
    using M = __mmask8;
    static constexpr int kWidth = 8;
    M3G_AVX512_INLINE static V set1(float a) noexcept { return _mm256_set1_ps(a); }
    M3G_AVX512_INLINE static V zero() noexcept { return _mm256_setzero_ps(); }
    M3G_AVX512_INLINE static V fmadd(V a, V b, V c) noexcept { return _mm256_fmadd_ps(a, b, c); }
    M3G_AVX512_INLINE static V fnmadd(V a, V b, V c) noexcept { return _mm256_fnmadd_ps(a, b, c); }
    M3G_AVX512_INLINE static V mul(V a, V b) noexcept { return _mm256_mul_ps(a, b); }
    M3G_AVX512_INLINE static V load(const float* p) noexcept { return _mm256_loadu_ps(p); }
    M3G_AVX512_INLINE static V load(M m, const float* p) noexcept { return _mm256_maskz_loadu_ps(m, p); }
    M3G_AVX512_INLINE static void store(float* p, V v) noexcept { _mm256_storeu_ps(p, v); }
    M3G_AVX512_INLINE static void store(float* p, M m, V v) noexcept { _mm256_mask_storeu_ps(p, m, v); }
    M3G_AVX512_INLINE static I index(const std::int32_t* p) noexcept {
        return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p));
    }
    M3G_AVX512_INLINE static V permute2(V a, I index, V b) noexcept { return _mm256_permutex2var_ps(a, index, b); }
    M3G_AVX512_INLINE static V blend(M m, V a, V b) noexcept { return _mm256_mask_blend_ps(m, a, b); }
    M3G_AVX512_INLINE static I add(I a, I b) noexcept { return _mm256_add_epi32(a, b); }
    M3G_AVX512_INLINE static I set1i(int a) noexcept { return _mm256_set1_epi32(a); }
    M3G_AVX512_INLINE static I mulloi(I a, I b) noexcept { return _mm256_mullo_epi32(a, b); }
    M3G_AVX512_INLINE static V gather(M m, I index, const float* base) noexcept {
        return _mm256_mmask_i32gather_ps(_mm256_setzero_ps(), m, index, base, 4);
    }
    M3G_AVX512_INLINE static M greater(V a, V b) noexcept { return _mm256_cmp_ps_mask(a, b, _CMP_GT_OQ); }
    M3G_AVX512_INLINE static M less(M m, V a, V b) noexcept { return _mm256_mask_cmp_ps_mask(m, a, b, _CMP_LT_OQ); }
    M3G_AVX512_INLINE static V rsqrt14(V a) noexcept { return _mm256_maskz_rsqrt14_ps(0xFF, a); }
    M3G_AVX512_INLINE static V sqrt(M m, V a) noexcept { return _mm256_maskz_sqrt_ps(m, a); }
    M3G_AVX512_INLINE static V div(V src, M m, V a, V b) noexcept { return _mm256_mask_div_ps(src, m, a, b); }
};

/// The mask of the first `n` lanes (all of them from W on).
template <int W>
M3G_AVX512_INLINE typename Lanes<W>::M laneMask(std::size_t n) noexcept {
    using M = typename Lanes<W>::M;
    return n >= static_cast<std::size_t>(W) ? static_cast<M>((1u << W) - 1u) : static_cast<M>((1u << n) - 1u);
}

/// Permutation indices for W xyz triples held in three registers (floats
/// 0..W-1, W..2W-1, 2W..3W-1): two two-source permutes per lane vector
/// each way (vpermt2ps), so a block costs six shuffles to load and six to
/// store, against 3W lane moves.
template <int W>
struct Soa3Indices {
    // Load: component c of vertex i is float 3i + c. The first permute takes
    // what lies in registers 0 and 1 (floats < 2W), the second the rest from
    // register 2 (index W + float - 2W there; the first result at 0..W-1).
    std::array<std::array<std::int32_t, W>, 3> gather01, gather2;
    // Store: float j of register o is component (Wo + j) % 3 of vertex
    // (Wo + j) / 3: x and y from the first permute (x: index vertex, y:
    // W + vertex), z from the second (W + vertex; the rest pass through).
    std::array<std::array<std::int32_t, W>, 3> scatterXy, scatterZ;
};

template <int W>
constexpr Soa3Indices<W> makeSoa3Indices() noexcept {
    Soa3Indices<W> s{};
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < W; ++i) {
            const int f = 3 * i + c;
            s.gather01[c][i] = f < 2 * W ? f : 0;
            s.gather2[c][i] = f < 2 * W ? i : W + (f - 2 * W);
        }
    for (int o = 0; o < 3; ++o)
        for (int j = 0; j < W; ++j) {
            const int f = W * o + j, vertex = f / 3, component = f % 3;
            // Vertices of register o: Wo/3 .. (Wo + W-1)/3, always < W.
            s.scatterXy[o][j] = component == 0 ? vertex : component == 1 ? W + vertex : 0;
            s.scatterZ[o][j] = component == 2 ? W + vertex : j;
        }
    return s;
}

template <int W>
inline constexpr Soa3Indices<W> kSoa3 = makeSoa3Indices<W>();

/// The masks of the three registers holding the first `lanes` (0..W)
/// vertices' 3 * lanes floats.
template <int W>
M3G_AVX512_INLINE void soa3Masks(std::size_t lanes, typename Lanes<W>::M& m0, typename Lanes<W>::M& m1,
                                 typename Lanes<W>::M& m2) noexcept {
    const std::size_t floats = 3 * lanes;
    m0 = laneMask<W>(floats);
    m1 = laneMask<W>(floats > W ? floats - W : 0);
    m2 = laneMask<W>(floats > 2 * W ? floats - 2 * W : 0);
}

/// Three registers of W xyz triples as x, y, z lanes.
template <int W, class V = typename Lanes<W>::V>
M3G_AVX512_INLINE void soa3FromXyz(V a, V b, V c, V& x, V& y, V& z) noexcept {
    using L = Lanes<W>;
    const auto& k = kSoa3<W>;
    x = L::permute2(L::permute2(a, L::index(k.gather01[0].data()), b), L::index(k.gather2[0].data()), c);
    y = L::permute2(L::permute2(a, L::index(k.gather01[1].data()), b), L::index(k.gather2[1].data()), c);
    z = L::permute2(L::permute2(a, L::index(k.gather01[2].data()), b), L::index(k.gather2[2].data()), c);
}

/// x, y, z lanes as the three registers of their xyz triples.
template <int W, class V = typename Lanes<W>::V>
M3G_AVX512_INLINE void soa3ToXyz(V x, V y, V z, V& o0, V& o1, V& o2) noexcept {
    using L = Lanes<W>;
    const auto& k = kSoa3<W>;
    o0 = L::permute2(L::permute2(x, L::index(k.scatterXy[0].data()), y), L::index(k.scatterZ[0].data()), z);
    o1 = L::permute2(L::permute2(x, L::index(k.scatterXy[1].data()), y), L::index(k.scatterZ[1].data()), z);
    o2 = L::permute2(L::permute2(x, L::index(k.scatterXy[2].data()), y), L::index(k.scatterZ[2].data()), z);
}

/// W packed xyz triples at `p` as x, y, z lanes.
template <int W, class V = typename Lanes<W>::V>
M3G_AVX512_INLINE void loadSoa3(const float* p, V& x, V& y, V& z) noexcept {
    using L = Lanes<W>;
    soa3FromXyz<W>(L::load(p), L::load(p + W), L::load(p + 2 * W), x, y, z);
}

/// The first `lanes` (< W) xyz triples at `p`: only their 3 * lanes floats
/// are read (masked loads; the other lanes are 0).
template <int W, class V = typename Lanes<W>::V>
M3G_AVX512_INLINE void loadSoa3(const float* p, std::size_t lanes, V& x, V& y, V& z) noexcept {
    using L = Lanes<W>;
    typename L::M m0, m1, m2;
    soa3Masks<W>(lanes, m0, m1, m2);
    soa3FromXyz<W>(L::load(m0, p), L::load(m1, p + W), L::load(m2, p + 2 * W), x, y, z);
}

/// W lanes of x, y, z to the packed xyz triples at `out`.
template <int W, class V = typename Lanes<W>::V>
M3G_AVX512_INLINE void storeSoa3(float* out, V x, V y, V z) noexcept {
    using L = Lanes<W>;
    V o0, o1, o2;
    soa3ToXyz<W>(x, y, z, o0, o1, o2);
    L::store(out, o0);
    L::store(out + W, o1);
    L::store(out + 2 * W, o2);
}

/// Lanes 0 .. lanes-1 (lanes < W): only their 3 * lanes floats are
/// written (masked stores).
template <int W, class V = typename Lanes<W>::V>
M3G_AVX512_INLINE void storeSoa3(float* out, std::size_t lanes, V x, V y, V z) noexcept {
    using L = Lanes<W>;
    typename L::M m0, m1, m2;
    soa3Masks<W>(lanes, m0, m1, m2);
    V o0, o1, o2;
    soa3ToXyz<W>(x, y, z, o0, o1, o2);
    L::store(out, m0, o0);
    L::store(out + W, m1, o1);
    L::store(out + 2 * W, m2, o2);
}

/// 1 / |n| per lane, or 1 where |n|^2 is zero (or NaN): the 14-bit
/// reciprocal square root estimate plus one Newton step (relative error
/// about 2^-24, below the AVX2 path's), the exact 1 / sqrt for lanes whose
/// |n|^2 is below FLT_MIN, where the estimate is not usable.
template <int W, class V = typename Lanes<W>::V>
M3G_AVX512_INLINE V inverseLength(V nx, V ny, V nz) noexcept {
    using L = Lanes<W>;
    const V one = L::set1(1.0f);
    const V len2 = L::fmadd(nz, nz, L::fmadd(ny, ny, L::mul(nx, nx)));
    const typename L::M positive = L::greater(len2, L::zero());
    const typename L::M tiny = L::less(positive, len2, L::set1(1.17549435e-38f));
    const V y = L::rsqrt14(len2);
    // y' = y * (3 - len2 * y * y) / 2
    V refined = L::mul(L::mul(L::set1(0.5f), y), L::fnmadd(L::mul(len2, y), y, L::set1(3.0f)));
    if (tiny != 0) [[unlikely]]
        refined = L::div(refined, tiny, one, L::sqrt(tiny, len2));
    return L::blend(positive, one, refined);
}

}  // namespace m3g::skin::detail
