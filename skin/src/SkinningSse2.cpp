// SSE2 skinning (the x86-64 baseline: no target attribute needed).
//
// Per vertex: the K palette rows are blended with 128-bit multiply-adds
// (3 position rows + 3 normal rows) and applied as row dot products reduced
// by a 4x4 transpose. The blended normals wait in a 4-vertex buffer and are
// renormalised four at a time (the reciprocal square root estimate and one
// Newton step, as in the run kernel), which keeps that latency out of the
// per-vertex chain.
// Every lane runs the same operations, so the result of a vertex does not
// depend on which other vertices share its batch.
#include "Kernels.h"

#ifdef M3G_SKIN_X86

#include "Sse2.h"

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
        // The run kernel's reciprocal square root and Newton step (Sse2.h).
        const __m128 inv = inverseLength(x, y, z);
        alignas(16) float out[3][4];
        _mm_store_ps(out[0], _mm_mul_ps(x, inv));
        _mm_store_ps(out[1], _mm_mul_ps(y, inv));
        _mm_store_ps(out[2], _mm_mul_ps(z, inv));
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

// Shared-influence runs (InfluenceRun), four lanes at a time: a run's
// entries are blended once (from its first vertex's slots) and its 24
// coefficients broadcast once (the block loop's multiplies take them as
// memory operands); each block of four consecutive vertices is transposed
// to x, y, z lanes, multiplied and added (no FMA in SSE2), renormalised
// with the reciprocal square root estimate plus one Newton step, and
// transposed back. The AVX2 run kernel's structure at half the width.

/// Lanes from .. from+lanes-1 of x, y, z (within 0..3) to floats
/// [3 from, 3 (from + lanes)) of out, and no others (the block's other
/// lanes belong to other vertices).
inline void storeSoa3Lanes(float* out, __m128 x, __m128 y, __m128 z, std::size_t from, std::size_t lanes) noexcept {
    alignas(16) float t[12];
    __m128 r0, r1, r2;
    soa3ToXyz(x, y, z, r0, r1, r2);
    if (from == 0 && lanes == 4) {
        _mm_storeu_ps(out, r0);
        _mm_storeu_ps(out + 4, r1);
        _mm_storeu_ps(out + 8, r2);
        return;
    }
    _mm_store_ps(t, r0);
    _mm_store_ps(t + 4, r1);
    _mm_store_ps(t + 8, r2);
    const std::size_t end = 3 * (from + lanes);
    std::size_t i = 3 * from;
    if (i + 4 <= end) {
        _mm_storeu_ps(out + i, _mm_loadu_ps(t + i));
        i += 4;
    }
    for (; i < end; ++i) out[i] = t[i];
}

/// A run's coefficients, each in all four lanes: P0 P1 P2 N0 N1 N2, four
/// per row (the normal rows' fourth unused), so that the block loop's
/// multiplies take them as memory operands.
struct RunRows {
    __m128 m[24];
};

/// Row r of m (coefficients 4r .. 4r+3) applied to lanes a, b, c, plus the
/// fourth coefficient when Translate.
template <bool Translate>
inline __m128 rowTimes(const RunRows& m, int r, __m128 a, __m128 b, __m128 c) noexcept {
    const __m128 ab = _mm_add_ps(_mm_mul_ps(m.m[4 * r], a), _mm_mul_ps(m.m[4 * r + 1], b));
    const __m128 ct = Translate ? _mm_add_ps(_mm_mul_ps(m.m[4 * r + 2], c), m.m[4 * r + 3]) : _mm_mul_ps(m.m[4 * r + 2], c);
    return _mm_add_ps(ab, ct);
}

/// Four vertices' positions and unit normals from their x, y, z lanes.
struct Block4 {
    __m128 x, y, z, nx, ny, nz;
};
inline Block4 skinBlock4(const RunRows& m, __m128 px, __m128 py, __m128 pz, __m128 nx, __m128 ny, __m128 nz) noexcept {
    Block4 o;
    o.x = rowTimes<true>(m, 0, px, py, pz);
    o.y = rowTimes<true>(m, 1, px, py, pz);
    o.z = rowTimes<true>(m, 2, px, py, pz);
    const __m128 bx = rowTimes<false>(m, 3, nx, ny, nz);
    const __m128 by = rowTimes<false>(m, 4, nx, ny, nz);
    const __m128 bz = rowTimes<false>(m, 5, nx, ny, nz);
    const __m128 inv = inverseLength(bx, by, bz);
    o.nx = _mm_mul_ps(bx, inv);
    o.ny = _mm_mul_ps(by, inv);
    o.nz = _mm_mul_ps(bz, inv);
    return o;
}

/// x, y, z lanes of vertices first .. first+lanes-1 (1..4, the last
/// repeated beyond) at `stride` floats, reading three floats per vertex.
inline void gatherSoa3(const float* base, std::size_t stride, std::size_t first, std::size_t lanes, __m128& x,
                       __m128& y, __m128& z) noexcept {
    __m128 q[4];
    for (std::size_t l = 0; l < 4; ++l) q[l] = loadXyz0(base + (first + (l < lanes ? l : lanes - 1)) * stride);
    _MM_TRANSPOSE4_PS(q[0], q[1], q[2], q[3]);
    x = q[0], y = q[1], z = q[2];
}

/// Lanes 0 .. lanes-1 of x, y, z to the xyz triples of vertices first ..
/// first+lanes-1 at `stride` floats (three floats written per vertex).
inline void scatterSoa3(float* base, std::size_t stride, std::size_t first, std::size_t lanes, __m128 x, __m128 y,
                        __m128 z) noexcept {
    __m128 w = _mm_setzero_ps();
    _MM_TRANSPOSE4_PS(x, y, z, w);
    const __m128 q[4] = {x, y, z, w};
    for (std::size_t l = 0; l < lanes; ++l) storeXyz(base + (first + l) * stride, q[l]);
}

/// Vertices [v, v + count) of a run whose first vertex is runFirst.
template <int K>
void skinRun(const SkinningJob& j, bool packed, std::size_t runFirst, std::size_t v, std::size_t count) noexcept {
    const int slots = K > 0 ? K : j.influenceCount;
    const auto stride = static_cast<std::size_t>(j.influenceStride);
    const std::int32_t* bi = j.boneIndices.data() + runFirst * stride;
    const float* bw = j.boneWeights.data() + runFirst * stride;
    for (int k = 0; k < slots; ++k)
        if (static_cast<std::uint32_t>(bi[k]) >= j.palette.size()) {
            // A slot outside the palette: the checked formula, vertex by vertex.
            for (std::size_t i = 0; i < count; ++i) skinVertexChecked(j, v + i);
            return;
        }
    // The blended rows P0 P1 P2 N0 N1 N2 (one register each).
    __m128 y[6];
    {
        const float* e = reinterpret_cast<const float*>(j.palette.data() + bi[0]);
        const __m128 w = _mm_set1_ps(bw[0]);
        for (int r = 0; r < 6; ++r) y[r] = _mm_mul_ps(w, _mm_load_ps(e + 4 * r));
    }
    for (int k = 1; k < slots; ++k) {
        const float* e = reinterpret_cast<const float*>(j.palette.data() + bi[k]);
        const __m128 w = _mm_set1_ps(bw[k]);
        for (int r = 0; r < 6; ++r) y[r] = _mm_add_ps(y[r], _mm_mul_ps(w, _mm_load_ps(e + 4 * r)));
    }
    if (!isIdentityScaleBias(j.positionScale, j.positionBias)) {
        const float s = j.positionScale;
        const __m128 scale = _mm_setr_ps(s, s, s, 1.0f);
        const __m128 bias = _mm_setr_ps(j.positionBias[0], j.positionBias[1], j.positionBias[2], 0.0f);
        for (int r = 0; r < 3; ++r) y[r] = foldScaleBias(y[r], scale, bias);
    }
    alignas(16) float flat[24];
    for (int r = 0; r < 6; ++r) _mm_store_ps(flat + 4 * r, y[r]);
    RunRows rows;
    for (int i = 0; i < 24; ++i) rows.m[i] = _mm_set1_ps(flat[i]);

    const std::size_t end = v + count;
    float* outP = j.outPositions.data();
    float* outN = j.outNormals.data();
    if (packed && j.vertexCount >= 4) {
        const float* inP = j.inPositions.data();
        const float* inN = j.inNormals.data();
        __m128 px, py, pz, nx, ny, nz;
        for (; v + 4 <= end; v += 4) {
            loadSoa3(inP + v * 3, px, py, pz);
            loadSoa3(inN + v * 3, nx, ny, nz);
            const Block4 o = skinBlock4(rows, px, py, pz, nx, ny, nz);
            storeSoa3Lanes(outP + v * 3, o.x, o.y, o.z, 0, 4);
            storeSoa3Lanes(outN + v * 3, o.nx, o.ny, o.nz, 0, 4);
        }
        if (v < end) {
            // The last, partial block: the four vertices from v, or the
            // arrays' last four (a validated run ends inside the arrays),
            // only the run's lanes stored.
            const std::size_t base = v + 4 <= j.vertexCount ? v : j.vertexCount - 4;
            loadSoa3(inP + base * 3, px, py, pz);
            loadSoa3(inN + base * 3, nx, ny, nz);
            const Block4 o = skinBlock4(rows, px, py, pz, nx, ny, nz);
            storeSoa3Lanes(outP + base * 3, o.x, o.y, o.z, v - base, end - v);
            storeSoa3Lanes(outN + base * 3, o.nx, o.ny, o.nz, v - base, end - v);
        }
        return;
    }
    // Other strides, or arrays shorter than a block: lane by lane.
    while (v < end) {
        const std::size_t lanes = end - v < 4 ? end - v : 4;
        __m128 px, py, pz, nx, ny, nz;
        gatherSoa3(j.inPositions.data(), j.inPositionStride, v, lanes, px, py, pz);
        gatherSoa3(j.inNormals.data(), j.inNormalStride, v, lanes, nx, ny, nz);
        const Block4 o = skinBlock4(rows, px, py, pz, nx, ny, nz);
        scatterSoa3(outP, j.outPositionStride, v, lanes, o.x, o.y, o.z);
        scatterSoa3(outN, j.outNormalStride, v, lanes, o.nx, o.ny, o.nz);
        v += lanes;
    }
}

template <int K>
void skinRuns(const SkinningJob& j, std::size_t begin, std::size_t end) noexcept {
    const bool packed = isPacked(j);
    RunPieces pieces(j.runs, begin, end);
    std::size_t runFirst, first, count;
    while (pieces.next(runFirst, first, count)) skinRun<K>(j, packed, runFirst, first, count);
}

}  // namespace

void skinSse2(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept {
    if (job.inNormals.empty())
        skinN<false>(job, begin, end);
    else
        skinN<true>(job, begin, end);
}

bool skinRunsSse2(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept {
    if (job.inNormals.empty()) return false;
    switch (job.influenceCount) {
        case 0: return false;
        case 1: skinRuns<1>(job, begin, end); return true;
        case 2: skinRuns<2>(job, begin, end); return true;
        case 3: skinRuns<3>(job, begin, end); return true;
        case 4: skinRuns<4>(job, begin, end); return true;
        default: skinRuns<-1>(job, begin, end); return true;
    }
}

}  // namespace m3g::skin::detail

#endif  // M3G_SKIN_X86
