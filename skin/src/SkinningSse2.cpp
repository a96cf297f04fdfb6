// SSE2 skinning (the x86-64 baseline: no target attribute needed).
//
// Per vertex: the K palette rows are blended with 128-bit multiply-adds
// (3 position rows + 3 normal rows) and applied as row dot products reduced
// by a 4x4 transpose. The blended normals wait in a 4-vertex buffer and are
// renormalised four at a time (one sqrt and one division for four vertices),
// which keeps the long sqrt/division latency out of the per-vertex chain.
// Every lane runs the same operations, so the result of a vertex does not
// depend on which other vertices share its batch.
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

/// Normals waiting for renormalisation, four at a time.
class NormalBatch {
public:
    void add(__m128 n, float* destination) noexcept {
        _mm_store_ps(pending_[count_], n);
        destination_[count_] = destination;
        if (++count_ == 4) flush();
    }
    /// n / |n| per lane (a zero-length normal stays as it is), then stores.
    void flush() noexcept {
        if (count_ == 0) return;
        __m128 x = _mm_load_ps(pending_[0]), y = _mm_load_ps(pending_[1]);
        __m128 z = _mm_load_ps(pending_[2]), w = _mm_load_ps(pending_[3]);
        _MM_TRANSPOSE4_PS(x, y, z, w);
        const __m128 len2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, x), _mm_mul_ps(y, y)), _mm_mul_ps(z, z));
        const __m128 positive = _mm_cmpgt_ps(len2, _mm_setzero_ps());
        const __m128 len = _mm_sqrt_ps(len2);
        // 1 where the length is zero (or NaN): divides by 1, leaving n.
        const __m128 divisor = _mm_or_ps(_mm_and_ps(positive, len), _mm_andnot_ps(positive, _mm_set1_ps(1.0f)));
        alignas(16) float out[3][4];
        _mm_store_ps(out[0], _mm_div_ps(x, divisor));
        _mm_store_ps(out[1], _mm_div_ps(y, divisor));
        _mm_store_ps(out[2], _mm_div_ps(z, divisor));
        for (int i = 0; i < count_; ++i) {
            destination_[i][0] = out[0][i];
            destination_[i][1] = out[1][i];
            destination_[i][2] = out[2][i];
        }
        count_ = 0;
    }

private:
    alignas(16) float pending_[4][4] = {};
    float* destination_[4] = {};
    int count_ = 0;
};

template <int K, bool Normals>
void skinT(const SkinningJob& j, std::size_t begin, std::size_t end) noexcept {
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
        const __m128 p = _mm_add_ps(_mm_mul_ps(loadXyz1(inP + v * inPs), scale), bias);
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
            __m128 r0, r1, r2, n0 = _mm_setzero_ps(), n1 = _mm_setzero_ps(), n2 = _mm_setzero_ps();
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
                const __m128 n = loadXyz0(inN + v * inNs);
                const __m128 u2 = _mm_mul_ps(n2, n);
                batch.add(hsum4(_mm_mul_ps(n0, n), _mm_mul_ps(n1, n), u2, u2), outN + v * outNs);
            }
        }
    }
    if constexpr (Normals) batch.flush();
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
