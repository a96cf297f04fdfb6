// AVX2 + FMA skinning, chosen at run time (Isa::Avx2). Only the functions
// of this file carry the target attribute (no per-file -mavx2), so no inline
// library function is ever compiled for AVX2 and shared with baseline code.
//
// Per vertex: a palette entry is three 256-bit rows (P0|P1), (P2|N0),
// (N1|N2); K entries are blended with 3 FMAs each, the blend is multiplied by
// (p|p), (p|n), (n|n) and the six dot products come out of three horizontal
// adds. Blended normals wait in an 8-vertex buffer and are renormalised
// eight at a time (one sqrt and one division per eight vertices), so the
// long sqrt/division latency stays out of the per-vertex chain. Every lane
// runs the same operations: a vertex's result does not depend on its batch.
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
M3G_AVX2 inline __m256 pair(__m128 lo, __m128 hi) noexcept {
    return _mm256_insertf128_ps(_mm256_castps128_ps256(lo), hi, 1);
}

/// Normals waiting for renormalisation, eight at a time.
class NormalBatch {
public:
    M3G_AVX2 void add(__m128 n, float* destination) noexcept {
        _mm_store_ps(pending_[count_], n);
        destination_[count_] = destination;
        if (++count_ == 8) flush();
    }
    /// n / |n| per lane (a zero-length normal stays as it is), then stores.
    M3G_AVX2 void flush() noexcept {
        if (count_ == 0) return;
        // 8 x (x, y, z, -) -> x[8], y[8], z[8].
        const __m256 a0 = pair(_mm_load_ps(pending_[0]), _mm_load_ps(pending_[4]));
        const __m256 a1 = pair(_mm_load_ps(pending_[1]), _mm_load_ps(pending_[5]));
        const __m256 a2 = pair(_mm_load_ps(pending_[2]), _mm_load_ps(pending_[6]));
        const __m256 a3 = pair(_mm_load_ps(pending_[3]), _mm_load_ps(pending_[7]));
        const __m256 t0 = _mm256_unpacklo_ps(a0, a1), t1 = _mm256_unpackhi_ps(a0, a1);
        const __m256 t2 = _mm256_unpacklo_ps(a2, a3), t3 = _mm256_unpackhi_ps(a2, a3);
        const __m256 x = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0));
        const __m256 y = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
        const __m256 z = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0));
        // Lanes are vertices 0, 1, 2, 3 | 4, 5, 6, 7.
        const __m256 len2 = _mm256_fmadd_ps(z, z, _mm256_fmadd_ps(y, y, _mm256_mul_ps(x, x)));
        const __m256 positive = _mm256_cmp_ps(len2, _mm256_setzero_ps(), _CMP_GT_OQ);
        // Divide by the length, or by 1 where it is zero (or NaN).
        const __m256 divisor = _mm256_blendv_ps(_mm256_set1_ps(1.0f), _mm256_sqrt_ps(len2), positive);
        alignas(32) float out[3][8];
        _mm256_store_ps(out[0], _mm256_div_ps(x, divisor));
        _mm256_store_ps(out[1], _mm256_div_ps(y, divisor));
        _mm256_store_ps(out[2], _mm256_div_ps(z, divisor));
        for (int i = 0; i < count_; ++i) {
            destination_[i][0] = out[0][i];
            destination_[i][1] = out[1][i];
            destination_[i][2] = out[2][i];
        }
        count_ = 0;
    }

private:
    alignas(32) float pending_[8][4] = {};
    float* destination_[8] = {};
    int count_ = 0;
};

template <int K, bool Normals>
M3G_AVX2 void skinT(const SkinningJob& j, std::size_t begin, std::size_t end) noexcept {
    const int count = K >= 0 ? K : j.influenceCount;
    const auto stride = static_cast<std::size_t>(j.influenceStride);
    const std::uint32_t* vertices = j.vertices.data();
    const float* inP = j.inPositions.data();
    const std::size_t inPs = j.inPositionStride;
    float* outP = j.outPositions.data();
    const std::size_t outPs = j.outPositionStride;
    const float* inN = j.inNormals.data();
    const std::size_t inNs = j.inNormalStride;
    float* outN = j.outNormals.data();
    const std::size_t outNs = j.outNormalStride;
    const std::int32_t* boneIndices = j.boneIndices.data();
    const float* boneWeights = j.boneWeights.data();
    const PaletteEntry* palette = j.palette.data();
    const std::size_t bones = j.palette.size();
    const __m128 scale = _mm_setr_ps(j.positionScale, j.positionScale, j.positionScale, 1.0f);
    const __m128 bias = _mm_setr_ps(j.positionBias[0], j.positionBias[1], j.positionBias[2], 0.0f);
    NormalBatch batch;
    for (std::size_t i = begin; i < end; ++i) {
        const std::size_t v = vertices[i];
        const __m128 p = _mm_fmadd_ps(loadXyz1(inP + v * inPs), scale, bias);
        float* op = outP + v * outPs;
        if constexpr (K == 0) {
            storeXyz(op, p);
            if constexpr (Normals) batch.add(loadXyz0(inN + v * inNs), outN + v * outNs);
        } else {
            const std::int32_t* bi = boneIndices + v * stride;
            const float* bw = boneWeights + v * stride;
            bool valid = true;
            for (int k = 0; k < count; ++k) valid &= static_cast<std::uint32_t>(bi[k]) < bones;
            if (!valid) {
                skinVertexChecked(j, v);
                continue;
            }
            if constexpr (Normals) {
                // Entries are 16-byte aligned only: unaligned 256-bit loads.
                const float* e = reinterpret_cast<const float*>(palette + bi[0]);
                const __m256 w0 = _mm256_broadcast_ss(bw);
                __m256 y0 = _mm256_mul_ps(w0, _mm256_loadu_ps(e));       // P0 | P1
                __m256 y1 = _mm256_mul_ps(w0, _mm256_loadu_ps(e + 8));   // P2 | N0
                __m256 y2 = _mm256_mul_ps(w0, _mm256_loadu_ps(e + 16));  // N1 | N2
                for (int k = 1; k < count; ++k) {
                    const float* f = reinterpret_cast<const float*>(palette + bi[k]);
                    const __m256 w = _mm256_broadcast_ss(bw + k);
                    y0 = _mm256_fmadd_ps(w, _mm256_loadu_ps(f), y0);
                    y1 = _mm256_fmadd_ps(w, _mm256_loadu_ps(f + 8), y1);
                    y2 = _mm256_fmadd_ps(w, _mm256_loadu_ps(f + 16), y2);
                }
                const __m128 n = loadXyz0(inN + v * inNs);
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
                batch.add(_mm_shuffle_ps(nrm, nrm, _MM_SHUFFLE(0, 3, 2, 1)), outN + v * outNs);
            } else {
                const float* e = reinterpret_cast<const float*>(palette + bi[0]);
                const __m256 w0 = _mm256_broadcast_ss(bw);
                __m256 y0 = _mm256_mul_ps(w0, _mm256_loadu_ps(e));
                __m128 x2 = _mm_mul_ps(_mm256_castps256_ps128(w0), _mm_load_ps(e + 8));
                for (int k = 1; k < count; ++k) {
                    const float* f = reinterpret_cast<const float*>(palette + bi[k]);
                    const __m256 w = _mm256_broadcast_ss(bw + k);
                    y0 = _mm256_fmadd_ps(w, _mm256_loadu_ps(f), y0);
                    x2 = _mm_fmadd_ps(_mm256_castps256_ps128(w), _mm_load_ps(f + 8), x2);
                }
                const __m256 m0 = _mm256_mul_ps(y0, pair(p, p));
                const __m128 t2 = _mm_mul_ps(x2, p);
                storeXyz(op, hsum4(_mm256_castps256_ps128(m0), _mm256_extractf128_ps(m0, 1), t2, t2));
            }
        }
    }
    if constexpr (Normals) batch.flush();
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
