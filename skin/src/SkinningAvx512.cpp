// AVX-512 kernels (Isa::Avx512): vertices sharing their influences (runs)
// or their bones (bone runs), sixteen at a time (a run's last eight or
// fewer in 256-bit registers, Avx512.h says why). The rest of a job (loose
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

/// Where the blocks read their inputs: the packed xyz triples, transposed
/// per block (three loads and six permutes each for positions and
/// normals), or the job's planes (SkinningJob::inPositionPlanes: three
/// loads). The same values either way, so the same output bits.
template <bool Planes>
struct Inputs {
    const float* p;
    const float* n;
    std::size_t plane;  // floats from one plane to the next (vertexCount)

    explicit Inputs(const SkinningJob& j) noexcept
        : p(Planes ? j.inPositionPlanes.data() : j.inPositions.data()),
          n(Planes ? j.inNormalPlanes.data() : j.inNormals.data()),
          plane(j.vertexCount) {}

    /// Vertices v .. v + W - 1.
    template <int W, class V = typename Lanes<W>::V>
    M3G_AVX512_INLINE void load(std::size_t v, V& px, V& py, V& pz, V& nx, V& ny, V& nz) const noexcept {
        using L = Lanes<W>;
        if constexpr (Planes) {
            px = L::load(p + v);
            py = L::load(p + plane + v);
            pz = L::load(p + 2 * plane + v);
            nx = L::load(n + v);
            ny = L::load(n + plane + v);
            nz = L::load(n + 2 * plane + v);
        } else {
            loadSoa3<W>(p + 3 * v, px, py, pz);
            loadSoa3<W>(n + 3 * v, nx, ny, nz);
        }
    }
    /// Vertices v .. v + lanes - 1 (lanes < W); only they are read, the
    /// other lanes are 0.
    template <int W, class V = typename Lanes<W>::V>
    M3G_AVX512_INLINE void load(std::size_t v, std::size_t lanes, V& px, V& py, V& pz, V& nx, V& ny,
                                V& nz) const noexcept {
        using L = Lanes<W>;
        if constexpr (Planes) {
            const auto m = laneMask<W>(lanes);
            px = L::load(m, p + v);
            py = L::load(m, p + plane + v);
            pz = L::load(m, p + 2 * plane + v);
            nx = L::load(m, n + v);
            ny = L::load(m, n + plane + v);
            nz = L::load(m, n + 2 * plane + v);
        } else {
            loadSoa3<W>(p + 3 * v, lanes, px, py, pz);
            loadSoa3<W>(n + 3 * v, lanes, nx, ny, nz);
        }
    }
    /// Vertices v .. v + lanes - 1 (1..W), whole or masked.
    template <int W, class V = typename Lanes<W>::V>
    M3G_AVX512_INLINE void loadSome(std::size_t v, std::size_t lanes, V& px, V& py, V& pz, V& nx, V& ny,
                                    V& nz) const noexcept {
        if (lanes == W)
            load<W>(v, px, py, pz, nx, ny, nz);
        else
            load<W>(v, lanes, px, py, pz, nx, ny, nz);
    }
};

/// Lanes 0 .. lanes-1 (1..W) of positions and normals to the packed
/// output triples of vertices v ...
template <int W, class V = typename Lanes<W>::V>
M3G_AVX512_INLINE void storeOutputs(const SkinningJob& j, std::size_t v, std::size_t lanes, V x, V y, V z, V nx,
                                    V ny, V nz) noexcept {
    if (lanes == W) {
        storeSoa3<W>(j.outPositions.data() + 3 * v, x, y, z);
        storeSoa3<W>(j.outNormals.data() + 3 * v, nx, ny, nz);
    } else {
        storeSoa3<W>(j.outPositions.data() + 3 * v, lanes, x, y, z);
        storeSoa3<W>(j.outNormals.data() + 3 * v, lanes, nx, ny, nz);
    }
}

/// Rows of a run: its K palette entries blended (P0 P1 P2 N0 N1 N2, four
/// floats each, as PaletteEntry), the job's position scale and bias folded
/// into the position rows. False (rows unset) when a slot's bone is
/// outside the palette.
template <int K>
M3G_AVX512_INLINE bool runRows(const SkinningJob& j, const std::int32_t* bi, const float* bw,
                               float (&rows)[24]) noexcept {
    const int count = K > 0 ? K : j.influenceCount;
    const std::size_t bones = j.palette.size();
    // 32-byte loads, as the palette kernel stores an entry (PaletteAvx2.cpp):
    // a 64-byte load of an entry just written could not be forwarded.
    __m256 a = _mm256_setzero_ps();  // floats 0-7
    __m256 b = _mm256_setzero_ps();  // floats 8-15
    __m256 c = _mm256_setzero_ps();  // floats 16-23
#pragma GCC unroll 4
    for (int k = 0; k < count; ++k) {
        const auto bone = static_cast<std::uint32_t>(bi[k]);
        if (bone >= bones) return false;
        const float* e = reinterpret_cast<const float*>(j.palette.data() + bone);
        const __m256 w = _mm256_set1_ps(bw[k]);
        a = _mm256_fmadd_ps(w, _mm256_loadu_ps(e), a);
        b = _mm256_fmadd_ps(w, _mm256_loadu_ps(e + 8), b);
        c = _mm256_fmadd_ps(w, _mm256_loadu_ps(e + 16), c);
    }
    _mm256_storeu_ps(rows, a);
    _mm256_storeu_ps(rows + 8, b);
    _mm256_storeu_ps(rows + 16, c);
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

/// W lanes of positions and normals through a run's rows (the 24 floats,
/// broadcast as memory operands where used: kept in registers, the 21 of
/// them and the 12 permute indices do not fit in 32 and the indices were
/// reloaded instead), stored for lanes 0 .. lanes-1.
template <int W, bool Planes>
M3G_AVX512_INLINE void applyRowsBlock(const SkinningJob& j, const Inputs<Planes>& in, const float (&r)[24],
                                      std::size_t v, std::size_t lanes) noexcept {
    using L = Lanes<W>;
    using V = typename L::V;
    V px, py, pz, nx, ny, nz;
    in.template loadSome<W>(v, lanes, px, py, pz, nx, ny, nz);
    struct {
        const float* r;
        M3G_AVX512_INLINE V operator()(int i) const noexcept { return L::set1(r[i]); }
    } m{r};
    const V x = L::fmadd(m(2), pz, L::fmadd(m(1), py, L::fmadd(m(0), px, m(3))));
    const V y = L::fmadd(m(6), pz, L::fmadd(m(5), py, L::fmadd(m(4), px, m(7))));
    const V z = L::fmadd(m(10), pz, L::fmadd(m(9), py, L::fmadd(m(8), px, m(11))));
    const V bx = L::fmadd(m(14), nz, L::fmadd(m(13), ny, L::mul(m(12), nx)));
    const V by = L::fmadd(m(18), nz, L::fmadd(m(17), ny, L::mul(m(16), nx)));
    const V bz = L::fmadd(m(22), nz, L::fmadd(m(21), ny, L::mul(m(20), nx)));
    const V inv = inverseLength<W>(bx, by, bz);
    storeOutputs<W>(j, v, lanes, x, y, z, L::mul(bx, inv), L::mul(by, inv), L::mul(bz, inv));
}

/// Vertices [v, v + count) of a run with packed arrays: whole blocks of
/// sixteen, the rest (masked) in sixteen lanes or, eight or fewer, in eight.
template <bool Planes>
M3G_AVX512_INLINE void applyRows(const SkinningJob& j, const float (&rows)[24], std::size_t v,
                                 std::size_t count) noexcept {
    const Inputs<Planes> in(j);
    const std::size_t end = v + count;
    for (; v + 16 <= end; v += 16) applyRowsBlock<16>(j, in, rows, v, 16);
    if (v + 8 < end)
        applyRowsBlock<16>(j, in, rows, v, end - v);
    else if (v < end)
        applyRowsBlock<8>(j, in, rows, v, end - v);
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
// blends them in varying proportions). Sixteen lanes a step (eight for a
// run's last eight or fewer): each lane's weights (gathered at the
// influence stride) times the run's palette entries, broadcast, give the
// lane's blended matrix row by row, which is applied at once (a row's four
// coefficients live only while it is used); then the normal is
// renormalised. The per-vertex list kernel blends each vertex's entries as
// three 256-bit rows and needs a horizontal reduction per vertex; here the
// work is all vertical. With a conformal palette
// (SkinningJob::normalsFromPositions) the normal goes through the blended
// position rows: 12 coefficients blended per slot instead of 21.

/// 4l for the first half of the lanes and 4(l - W/2) for the second: slot
/// 0 of each lane in a pair of registers of four-slot weights
/// (skinBoneBlock adds the slot).
template <int W>
M3G_AVX512_INLINE typename Lanes<W>::I slotIndex() noexcept {
    static constexpr std::int32_t k[16] = {0, 4, 8, 12, 16, 20, 24, 28, 0, 4, 8, 12, 16, 20, 24, 28};
    static constexpr std::int32_t k8[8] = {0, 4, 8, 12, 0, 4, 8, 12};
    return Lanes<W>::index(W == 16 ? k : k8);
}

/// Row r (coefficients 4r .. 4r+3) of the lanes' blended matrices.
template <int W, int K, class V = typename Lanes<W>::V>
M3G_AVX512_INLINE void blendRow(const float* const (&e)[4], const V (&w)[4], int r, V& c0, V& c1, V& c2,
                                V& c3) noexcept {
    using L = Lanes<W>;
    c0 = L::mul(w[0], L::set1(e[0][4 * r]));
    c1 = L::mul(w[0], L::set1(e[0][4 * r + 1]));
    c2 = L::mul(w[0], L::set1(e[0][4 * r + 2]));
    c3 = L::mul(w[0], L::set1(e[0][4 * r + 3]));
#pragma GCC unroll 4
    for (int k = 1; k < K; ++k) {
        c0 = L::fmadd(w[k], L::set1(e[k][4 * r]), c0);
        c1 = L::fmadd(w[k], L::set1(e[k][4 * r + 1]), c1);
        c2 = L::fmadd(w[k], L::set1(e[k][4 * r + 2]), c2);
        c3 = L::fmadd(w[k], L::set1(e[k][4 * r + 3]), c3);
    }
}

/// Vertices [v, v + lanes) of a bone run (lanes 1..W) whose K entries are
/// `e` (K <= 4 here; the generic count goes vertex by vertex).
template <int W, int K, bool NormalsFromPositions, bool Planes>
M3G_AVX512_INLINE void skinBoneBlock(const SkinningJob& j, const Inputs<Planes>& in, const float* const (&e)[4],
                                     std::size_t v, std::size_t lanes) noexcept {
    using L = Lanes<W>;
    using V = typename L::V;
    const auto stride = static_cast<std::size_t>(j.influenceStride);
    V px, py, pz, nx, ny, nz;
    in.template loadSome<W>(v, lanes, px, py, pz, nx, ny, nz);
    if (!isIdentityScaleBias(j.positionScale, j.positionBias)) {
        const V s = L::set1(j.positionScale);
        px = L::fmadd(px, s, L::set1(j.positionBias[0]));
        py = L::fmadd(py, s, L::set1(j.positionBias[1]));
        pz = L::fmadd(pz, s, L::set1(j.positionBias[2]));
    }
    // Slot k of lane l at weights[(v + l) * stride + k]; lanes outside the
    // run are not read (masked loads or gather) and weigh 0.
    const float* weights = j.boneWeights.data() + v * stride;
    V w[4];
    if (stride == 4) {
        // The common table (four slots): the 4W floats in four registers,
        // slot k picked by two permutes and a blend (a gather costs several
        // times that on current cores). Only the table's floats are read: its
        // last row may hold just the used slots (SkinningJob::validate).
        V q[4];
        const std::size_t have = j.boneWeights.size() - v * stride;
        const std::size_t floats = 4 * lanes < have ? 4 * lanes : have;
#pragma GCC unroll 4
        for (int i = 0; i < 4; ++i) {
            const std::size_t from = static_cast<std::size_t>(W) * static_cast<std::size_t>(i);
            q[i] = L::load(laneMask<W>(floats > from ? floats - from : 0), weights + from);
        }
        constexpr auto upperHalf = static_cast<typename L::M>(((1u << W) - 1u) & ~((1u << (W / 2)) - 1u));
#pragma GCC unroll 4
        for (int k = 0; k < K; ++k) {
            // The first half of the lanes from q0:q1 (floats 4l + k), the
            // second from q2:q3 (float 4(l - W/2) + k of that pair).
            const typename L::I index = L::add(slotIndex<W>(), L::set1i(k));
            w[k] = L::blend(upperHalf, L::permute2(q[0], index, q[1]), L::permute2(q[2], index, q[3]));
        }
    } else {
        static constexpr std::int32_t kLane[16] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
        const typename L::I lane = L::mulloi(L::index(kLane), L::set1i(static_cast<int>(stride)));
        const auto mask = laneMask<W>(lanes);
#pragma GCC unroll 4
        for (int k = 0; k < K; ++k) w[k] = L::gather(mask, L::add(lane, L::set1i(k)), weights);
    }
    // With a conformal palette (SkinningJob::normalsFromPositions) the
    // position rows' 3x3 also turns the normal: three rows blended, not six.
    V c0, c1, c2, c3;
    V x, y, z, bx, by, bz;
    blendRow<W, K>(e, w, 0, c0, c1, c2, c3);
    x = L::fmadd(c2, pz, L::fmadd(c1, py, L::fmadd(c0, px, c3)));
    if constexpr (NormalsFromPositions) bx = L::fmadd(c2, nz, L::fmadd(c1, ny, L::mul(c0, nx)));
    blendRow<W, K>(e, w, 1, c0, c1, c2, c3);
    y = L::fmadd(c2, pz, L::fmadd(c1, py, L::fmadd(c0, px, c3)));
    if constexpr (NormalsFromPositions) by = L::fmadd(c2, nz, L::fmadd(c1, ny, L::mul(c0, nx)));
    blendRow<W, K>(e, w, 2, c0, c1, c2, c3);
    z = L::fmadd(c2, pz, L::fmadd(c1, py, L::fmadd(c0, px, c3)));
    if constexpr (NormalsFromPositions) {
        bz = L::fmadd(c2, nz, L::fmadd(c1, ny, L::mul(c0, nx)));
    } else {
        blendRow<W, K>(e, w, 3, c0, c1, c2, c3);
        bx = L::fmadd(c2, nz, L::fmadd(c1, ny, L::mul(c0, nx)));
        blendRow<W, K>(e, w, 4, c0, c1, c2, c3);
        by = L::fmadd(c2, nz, L::fmadd(c1, ny, L::mul(c0, nx)));
        blendRow<W, K>(e, w, 5, c0, c1, c2, c3);
        bz = L::fmadd(c2, nz, L::fmadd(c1, ny, L::mul(c0, nx)));
    }
    const V inv = inverseLength<W>(bx, by, bz);
    storeOutputs<W>(j, v, lanes, x, y, z, L::mul(bx, inv), L::mul(by, inv), L::mul(bz, inv));
}

template <int K, bool NormalsFromPositions, bool Planes>
M3G_AVX512 void skinBoneRuns16(const SkinningJob& j, std::size_t begin, std::size_t end) noexcept {
    const auto stride = static_cast<std::size_t>(j.influenceStride);
    const Inputs<Planes> in(j);
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
        for (std::size_t v = first, stop = first + count; v < stop; v += 16) {
            const std::size_t lanes = stop - v < 16 ? stop - v : 16;
            if (lanes > 8)
                skinBoneBlock<16, K, NormalsFromPositions>(j, in, e, v, lanes);
            else
                skinBoneBlock<8, K, NormalsFromPositions>(j, in, e, v, lanes);
        }
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
