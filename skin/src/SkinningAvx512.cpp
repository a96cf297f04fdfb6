// AVX-512 kernels (Isa::Avx512): vertices sharing their influences (runs)
// or their bones (bone runs), sixteen at a time. The rest of a job (loose
// vertices, positions-only jobs, strided arrays) takes the AVX2 paths, which
// Avx512 CPUs also have.
//
// Why these: on real files most skinned vertices are in runs or bone runs
// (docs/skinning.md has the split per corpus file), and their work per
// vertex is vertical: FMAs on rows shared by the run, or blended per lane
// from the run's palette entries, which double in width with no extra
// shuffling. Sixteen packed xyz triples are three 512-bit loads and six
// two-source permutes (Avx512.h), or three loads where the job also gives
// its inputs as planes (SkinningJob::inPositionPlanes; the outputs are
// triples either way), and the last, partial block of a run is a
// masked load and store of exactly its vertices (no read past the arrays,
// no lane written outside the run).
#include "Kernels.h"

#ifdef M3G_SKIN_X86

#include "Avx512.h"

namespace m3g::skin::detail {

namespace {

/// Where the sixteen-lane blocks read their inputs: the packed xyz triples,
/// transposed per block (three loads and six permutes each for positions
/// and normals), or the job's planes (SkinningJob::inPositionPlanes: three
/// loads). The same values either way, so the same output bits.
template <bool Planes>
struct Inputs16 {
    const float* p;
    const float* n;
    std::size_t plane;  // floats from one plane to the next (vertexCount)

    explicit Inputs16(const SkinningJob& j) noexcept
        : p(Planes ? j.inPositionPlanes.data() : j.inPositions.data()),
          n(Planes ? j.inNormalPlanes.data() : j.inNormals.data()),
          plane(j.vertexCount) {}

    /// Vertices v .. v + 15.
    M3G_AVX512_INLINE void load(std::size_t v, __m512& px, __m512& py, __m512& pz, __m512& nx, __m512& ny,
                                __m512& nz) const noexcept {
        if constexpr (Planes) {
            px = _mm512_loadu_ps(p + v);
            py = _mm512_loadu_ps(p + plane + v);
            pz = _mm512_loadu_ps(p + 2 * plane + v);
            nx = _mm512_loadu_ps(n + v);
            ny = _mm512_loadu_ps(n + plane + v);
            nz = _mm512_loadu_ps(n + 2 * plane + v);
        } else {
            loadSoa3x16(p + 3 * v, px, py, pz);
            loadSoa3x16(n + 3 * v, nx, ny, nz);
        }
    }
    /// Vertices v .. v + lanes - 1 (lanes < 16); only they are read, the
    /// other lanes are 0.
    M3G_AVX512_INLINE void load(std::size_t v, std::size_t lanes, __m512& px, __m512& py, __m512& pz, __m512& nx,
                                __m512& ny, __m512& nz) const noexcept {
        if constexpr (Planes) {
            const auto m = static_cast<__mmask16>((1u << lanes) - 1u);
            px = _mm512_maskz_loadu_ps(m, p + v);
            py = _mm512_maskz_loadu_ps(m, p + plane + v);
            pz = _mm512_maskz_loadu_ps(m, p + 2 * plane + v);
            nx = _mm512_maskz_loadu_ps(m, n + v);
            ny = _mm512_maskz_loadu_ps(m, n + plane + v);
            nz = _mm512_maskz_loadu_ps(m, n + 2 * plane + v);
        } else {
            loadSoa3x16(p + 3 * v, lanes, px, py, pz);
            loadSoa3x16(n + 3 * v, lanes, nx, ny, nz);
        }
    }
};

/// Rows of a run: its K palette entries blended (P0 P1 P2 N0 N1 N2, four
/// floats each, as PaletteEntry), the job's position scale and bias folded
/// into the position rows. False (rows unset) when a slot's bone is
/// outside the palette.
template <int K>
M3G_AVX512_INLINE bool runRows(const SkinningJob& j, const std::int32_t* bi, const float* bw,
                               float (&rows)[24]) noexcept {
    const int count = K > 0 ? K : j.influenceCount;
    const std::size_t bones = j.palette.size();
    __m512 a = _mm512_setzero_ps();  // floats 0-15
    __m256 b = _mm256_setzero_ps();  // floats 16-23
#pragma GCC unroll 4
    for (int k = 0; k < count; ++k) {
        const auto bone = static_cast<std::uint32_t>(bi[k]);
        if (bone >= bones) return false;
        const float* e = reinterpret_cast<const float*>(j.palette.data() + bone);
        a = _mm512_fmadd_ps(_mm512_set1_ps(bw[k]), _mm512_loadu_ps(e), a);
        b = _mm256_fmadd_ps(_mm256_set1_ps(bw[k]), _mm256_loadu_ps(e + 16), b);
    }
    _mm512_storeu_ps(rows, a);
    _mm256_storeu_ps(rows + 16, b);
    if (!isIdentityScaleBias(j.positionScale, j.positionBias)) {
        // P (s p + b) = (P s) p + (P b), row by row, once per run.
        const float s = j.positionScale;
        for (int r = 0; r < 3; ++r) {
            float* row = rows + 4 * r;
            row[3] += row[0] * j.positionBias[0] + row[1] * j.positionBias[1] + row[2] * j.positionBias[2];
            row[0] *= s;
            row[1] *= s;
            row[2] *= s;
        }
    }
    return true;
}

/// Sixteen lanes of positions and normals through a run's rows (`m`, the
/// 24 floats broadcast).
struct Skinned16 {
    __m512 x, y, z, nx, ny, nz;
};
template <class Rows>
M3G_AVX512_INLINE Skinned16 applyRows16(const Rows& m, __m512 px, __m512 py, __m512 pz, __m512 nx,
                                        __m512 ny, __m512 nz) noexcept {
    Skinned16 o;
    o.x = _mm512_fmadd_ps(m[2], pz, _mm512_fmadd_ps(m[1], py, _mm512_fmadd_ps(m[0], px, m[3])));
    o.y = _mm512_fmadd_ps(m[6], pz, _mm512_fmadd_ps(m[5], py, _mm512_fmadd_ps(m[4], px, m[7])));
    o.z = _mm512_fmadd_ps(m[10], pz, _mm512_fmadd_ps(m[9], py, _mm512_fmadd_ps(m[8], px, m[11])));
    const __m512 bx = _mm512_fmadd_ps(m[14], nz, _mm512_fmadd_ps(m[13], ny, _mm512_mul_ps(m[12], nx)));
    const __m512 by = _mm512_fmadd_ps(m[18], nz, _mm512_fmadd_ps(m[17], ny, _mm512_mul_ps(m[16], nx)));
    const __m512 bz = _mm512_fmadd_ps(m[22], nz, _mm512_fmadd_ps(m[21], ny, _mm512_mul_ps(m[20], nx)));
    const __m512 inv = inverseLength16(bx, by, bz);
    o.nx = _mm512_mul_ps(bx, inv);
    o.ny = _mm512_mul_ps(by, inv);
    o.nz = _mm512_mul_ps(bz, inv);
    return o;
}

/// Vertices [v, v + count) of a run with packed arrays: whole blocks of
/// sixteen with plain loads and stores, the rest with masked ones.
template <bool Planes>
M3G_AVX512_INLINE void applyRows(const SkinningJob& j, const float (&rows)[24], std::size_t v,
                                 std::size_t count) noexcept {
    // Coefficients as broadcast memory operands, read again each block:
    // kept in registers, the 21 of them and the 12 permute indices do not
    // fit in 32 and the indices were reloaded instead.
    struct {
        const float* r;
        M3G_AVX512_INLINE __m512 operator[](int i) const noexcept { return _mm512_set1_ps(r[i]); }
    } m{rows};
    const Inputs16<Planes> in(j);
    float* outP = j.outPositions.data();
    float* outN = j.outNormals.data();
    const std::size_t end = v + count;
    for (; v + 16 <= end; v += 16) {
        __m512 px, py, pz, nx, ny, nz;
        in.load(v, px, py, pz, nx, ny, nz);
        const Skinned16 o = applyRows16(m, px, py, pz, nx, ny, nz);
        storeSoa3x16(outP + 3 * v, o.x, o.y, o.z);
        storeSoa3x16(outN + 3 * v, o.nx, o.ny, o.nz);
    }
    if (v < end) {
        const std::size_t lanes = end - v;
        __m512 px, py, pz, nx, ny, nz;
        in.load(v, lanes, px, py, pz, nx, ny, nz);
        const Skinned16 o = applyRows16(m, px, py, pz, nx, ny, nz);
        storeSoa3x16(outP + 3 * v, lanes, o.x, o.y, o.z);
        storeSoa3x16(outN + 3 * v, lanes, o.nx, o.ny, o.nz);
    }
}

template <int K, bool Planes>
M3G_AVX512 void skinRuns16(const SkinningJob& j, std::size_t begin, std::size_t end) noexcept {
    const std::size_t stride = static_cast<std::size_t>(j.influenceStride);
    RunPieces pieces(j.runs, begin, end);
    std::size_t runFirst, first, count;
    while (pieces.next(runFirst, first, count)) {
        float rows[24];
        if (!runRows<K>(j, j.boneIndices.data() + runFirst * stride, j.boneWeights.data() + runFirst * stride,
                        rows)) {
            // A slot outside the palette: the checked formula, vertex by vertex.
            for (std::size_t i = 0; i < count; ++i) skinVertexChecked(j, first + i);
            continue;
        }
        applyRows<Planes>(j, rows, first, count);
    }
}

// ---------------------------------------------------------------------------
// Bone runs: vertices sharing their bones, each with its own weights (what
// the compact space's loose vertices mostly are: a strip between two bones
// blends them in varying proportions). Sixteen lanes a step: each lane's
// weights (gathered at the influence stride) times the run's palette
// entries, broadcast, give the lane's blended matrix row by row, which is
// applied at once (a row's four coefficients live only while it is used);
// then the normal is renormalised. The per-vertex list kernel blends each
// vertex's entries as three 256-bit rows and needs a horizontal reduction
// per vertex; here the work is all vertical. With a conformal palette
// (SkinningJob::normalsFromPositions) the normal goes through the blended
// position rows: 12 coefficients blended per slot instead of 21.

/// 4l for lanes 0-7 and 4(l - 8) for lanes 8-15: slot 0 of each lane in a
/// pair of registers of four-slot weights (skinBoneBlock adds the slot).
M3G_AVX512_INLINE __m512i slotIndex() noexcept {
    return _mm512_setr_epi32(0, 4, 8, 12, 16, 20, 24, 28, 0, 4, 8, 12, 16, 20, 24, 28);
}

/// Row r (coefficients 4r .. 4r+3) of the lanes' blended matrices.
template <int K>
M3G_AVX512_INLINE void blendRow16(const float* const (&e)[4], const __m512 (&w)[4], int count, int r, __m512& c0,
                                  __m512& c1, __m512& c2, __m512& c3) noexcept {
    const int n = K > 0 ? K : count;
    c0 = _mm512_mul_ps(w[0], _mm512_set1_ps(e[0][4 * r]));
    c1 = _mm512_mul_ps(w[0], _mm512_set1_ps(e[0][4 * r + 1]));
    c2 = _mm512_mul_ps(w[0], _mm512_set1_ps(e[0][4 * r + 2]));
    c3 = _mm512_mul_ps(w[0], _mm512_set1_ps(e[0][4 * r + 3]));
#pragma GCC unroll 4
    for (int k = 1; k < n; ++k) {
        c0 = _mm512_fmadd_ps(w[k], _mm512_set1_ps(e[k][4 * r]), c0);
        c1 = _mm512_fmadd_ps(w[k], _mm512_set1_ps(e[k][4 * r + 1]), c1);
        c2 = _mm512_fmadd_ps(w[k], _mm512_set1_ps(e[k][4 * r + 2]), c2);
        c3 = _mm512_fmadd_ps(w[k], _mm512_set1_ps(e[k][4 * r + 3]), c3);
    }
}

/// Vertices [v, v + lanes) of a bone run (lanes 1..16) whose K entries are
/// `e` (K <= 4 here; the generic count goes vertex by vertex).
template <int K, bool NormalsFromPositions, bool Planes>
M3G_AVX512_INLINE void skinBoneBlock(const SkinningJob& j, const Inputs16<Planes>& in, const float* const (&e)[4],
                                     std::size_t v, std::size_t lanes) noexcept {
    const auto stride = static_cast<std::size_t>(j.influenceStride);
    const __mmask16 mask = lanes >= 16 ? __mmask16(0xFFFF) : static_cast<__mmask16>((1u << lanes) - 1u);
    __m512 px, py, pz, nx, ny, nz;
    if (lanes == 16)
        in.load(v, px, py, pz, nx, ny, nz);
    else
        in.load(v, lanes, px, py, pz, nx, ny, nz);
    if (!isIdentityScaleBias(j.positionScale, j.positionBias)) {
        const __m512 s = _mm512_set1_ps(j.positionScale);
        px = _mm512_fmadd_ps(px, s, _mm512_set1_ps(j.positionBias[0]));
        py = _mm512_fmadd_ps(py, s, _mm512_set1_ps(j.positionBias[1]));
        pz = _mm512_fmadd_ps(pz, s, _mm512_set1_ps(j.positionBias[2]));
    }
    // Slot k of lane l at weights[(v + l) * stride + k]; lanes outside the
    // run are not read (masked loads or gather) and weigh 0.
    const float* weights = j.boneWeights.data() + v * stride;
    __m512 w[4];
    if (stride == 4) {
        // The common table (four slots): the 64 floats in four registers,
        // slot k picked by two permutes and a blend (a gather costs several
        // times that on current cores).
        __m512 q[4];
#pragma GCC unroll 4
        for (int i = 0; i < 4; ++i) {
            const std::size_t floats = 4 * lanes;
            const std::size_t from = 16 * static_cast<std::size_t>(i);
            const __mmask16 m = floats >= from + 16 ? __mmask16(0xFFFF)
                                : floats > from     ? static_cast<__mmask16>((1u << (floats - from)) - 1u)
                                                    : __mmask16(0);
            q[i] = _mm512_maskz_loadu_ps(m, weights + from);
        }
#pragma GCC unroll 4
        for (int k = 0; k < K; ++k) {
            // Lanes 0-7 from q0:q1 (floats 4l + k), lanes 8-15 from q2:q3
            // (float 4(l - 8) + k of that pair).
            const __m512i index = _mm512_add_epi32(slotIndex(), _mm512_set1_epi32(k));
            w[k] = _mm512_mask_blend_ps(0xFF00, _mm512_permutex2var_ps(q[0], index, q[1]),
                                        _mm512_permutex2var_ps(q[2], index, q[3]));
        }
    } else {
        const __m512i lane = _mm512_mullo_epi32(
            _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15),
            _mm512_set1_epi32(static_cast<int>(stride)));
#pragma GCC unroll 4
        for (int k = 0; k < K; ++k)
            w[k] = _mm512_mask_i32gather_ps(_mm512_setzero_ps(), mask, _mm512_add_epi32(lane, _mm512_set1_epi32(k)),
                                            weights, 4);
    }
    // With a conformal palette (SkinningJob::normalsFromPositions) the
    // position rows' 3x3 also turns the normal: three rows blended, not six.
    __m512 c0, c1, c2, c3;
    __m512 x, y, z, bx, by, bz;
    blendRow16<K>(e, w, K, 0, c0, c1, c2, c3);
    x = _mm512_fmadd_ps(c2, pz, _mm512_fmadd_ps(c1, py, _mm512_fmadd_ps(c0, px, c3)));
    if constexpr (NormalsFromPositions) bx = _mm512_fmadd_ps(c2, nz, _mm512_fmadd_ps(c1, ny, _mm512_mul_ps(c0, nx)));
    blendRow16<K>(e, w, K, 1, c0, c1, c2, c3);
    y = _mm512_fmadd_ps(c2, pz, _mm512_fmadd_ps(c1, py, _mm512_fmadd_ps(c0, px, c3)));
    if constexpr (NormalsFromPositions) by = _mm512_fmadd_ps(c2, nz, _mm512_fmadd_ps(c1, ny, _mm512_mul_ps(c0, nx)));
    blendRow16<K>(e, w, K, 2, c0, c1, c2, c3);
    z = _mm512_fmadd_ps(c2, pz, _mm512_fmadd_ps(c1, py, _mm512_fmadd_ps(c0, px, c3)));
    if constexpr (NormalsFromPositions) {
        bz = _mm512_fmadd_ps(c2, nz, _mm512_fmadd_ps(c1, ny, _mm512_mul_ps(c0, nx)));
    } else {
        blendRow16<K>(e, w, K, 3, c0, c1, c2, c3);
        bx = _mm512_fmadd_ps(c2, nz, _mm512_fmadd_ps(c1, ny, _mm512_mul_ps(c0, nx)));
        blendRow16<K>(e, w, K, 4, c0, c1, c2, c3);
        by = _mm512_fmadd_ps(c2, nz, _mm512_fmadd_ps(c1, ny, _mm512_mul_ps(c0, nx)));
        blendRow16<K>(e, w, K, 5, c0, c1, c2, c3);
        bz = _mm512_fmadd_ps(c2, nz, _mm512_fmadd_ps(c1, ny, _mm512_mul_ps(c0, nx)));
    }
    const __m512 inv = inverseLength16(bx, by, bz);
    const __m512 ox = _mm512_mul_ps(bx, inv), oy = _mm512_mul_ps(by, inv), oz = _mm512_mul_ps(bz, inv);
    if (lanes == 16) {
        storeSoa3x16(j.outPositions.data() + 3 * v, x, y, z);
        storeSoa3x16(j.outNormals.data() + 3 * v, ox, oy, oz);
    } else {
        storeSoa3x16(j.outPositions.data() + 3 * v, lanes, x, y, z);
        storeSoa3x16(j.outNormals.data() + 3 * v, lanes, ox, oy, oz);
    }
}

template <int K, bool NormalsFromPositions, bool Planes>
M3G_AVX512 void skinBoneRuns16(const SkinningJob& j, std::size_t begin, std::size_t end) noexcept {
    const auto stride = static_cast<std::size_t>(j.influenceStride);
    const Inputs16<Planes> in(j);
    RunPieces pieces(j.boneRuns, begin, end);
    std::size_t runFirst, first, count;
    while (pieces.next(runFirst, first, count)) {
        const std::int32_t* bi = j.boneIndices.data() + runFirst * stride;
        const float* e[4] = {};
        if (!boneRunEntries<K>(j, bi, e)) {
            // A slot outside the palette: the checked formula, vertex by vertex.
            for (std::size_t i = 0; i < count; ++i) skinVertexChecked(j, first + i);
            continue;
        }
        for (std::size_t v = first, stop = first + count; v < stop; v += 16)
            skinBoneBlock<K, NormalsFromPositions>(j, in, e, v, stop - v < 16 ? stop - v : 16);
    }
}

template <int K>
M3G_AVX512_INLINE void boneRuns16(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept {
    withBoneRunChoices(job, [&](auto normalsFromPositions, auto planes) {
        skinBoneRuns16<K, decltype(normalsFromPositions)::value, decltype(planes)::value>(job, begin, end);
    });
}

template <int K>
M3G_AVX512_INLINE void runs16(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept {
    if (readsPlanes(job))
        skinRuns16<K, true>(job, begin, end);
    else
        skinRuns16<K, false>(job, begin, end);
}

}  // namespace

M3G_AVX512 bool skinBoneRunsAvx512(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept {
    if (job.inNormals.empty()) return false;
    if (!isPacked(job)) return false;
    switch (job.influenceCount) {
        case 1: boneRuns16<1>(job, begin, end); return true;
        case 2: boneRuns16<2>(job, begin, end); return true;
        case 3: boneRuns16<3>(job, begin, end); return true;
        case 4: boneRuns16<4>(job, begin, end); return true;
        default: return false;  // 0, or more than four slots: the list path
    }
}

M3G_AVX512 bool skinRunsAvx512(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept {
    if (job.inNormals.empty()) return false;
    if (!isPacked(job)) return false;
    switch (job.influenceCount) {
        case 0: return false;
        case 1: runs16<1>(job, begin, end); return true;
        case 2: runs16<2>(job, begin, end); return true;
        case 3: runs16<3>(job, begin, end); return true;
        case 4: runs16<4>(job, begin, end); return true;
        default: runs16<-1>(job, begin, end); return true;
    }
}

}  // namespace m3g::skin::detail

#endif  // M3G_SKIN_X86
