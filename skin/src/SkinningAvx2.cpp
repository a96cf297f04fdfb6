// AVX2 + FMA skinning, chosen at run time (Isa::Avx2; Avx2.h says how the
// target attribute is applied).
//
// Positions + normals with 1..4 (or more) influences run in blocks of eight
// vertices (skinBlocks, described below); the zero-influence and
// positions-only jobs run vertex by vertex (skinT): a palette entry is three
// 256-bit rows, K entries blended with 3 FMAs each, and the dot products
// come out of horizontal adds, normals renormalised eight at a time.
#include "Kernels.h"

#ifdef M3G_SKIN_X86

#include "Avx2.h"

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

// ---------------------------------------------------------------------------
// Blocks of eight vertices (K = 1..4 or generic, with normals): the path
// a job's loose vertices (SkinningJob::vertices) take; shared-influence
// runs have their own kernel (skinRuns, below). Blocks are list positions
// 8b .. 8b+7 (aligned to the list, whatever the chunk). Each vertex's K
// entries are blended as three 256-bit rows (P0|P1), (P2|N0), (N1|N2) with
// FMAs (weights broadcast) and multiplied by (p|p), (p|n), (n|n), built from
// broadcast loads and blends with no shuffle (p = s * xyz + bias with w = 1,
// n with w = 0); the six dot products of four vertices come out of one
// unpack/shuffle/add reduction per row, giving x|y, z|nx, ny|nz for four
// vertices, and two such groups are joined into eight lanes.
//
// Then the normals are renormalised eight at a time (inverseLength) and the
// block is stored, transposed back to xyz triples with 256-bit stores when
// its vertices are consecutive and the strides are 3, else lane by lane. A
// block that runs past the list repeats its last vertex; a block cut by a
// chunk boundary is computed whole and stores only its lanes in the chunk.
// A listed vertex's result depends only on the vertex (the same arithmetic
// in every lane of either path; a vertex with a slot outside the palette is
// redone by the checked formula), so runParallel() is bit-identical to
// run() for any grain and thread count, and a vertex list may be cut
// anywhere (bone runs taken as one list, Skinning.cpp).

/// The zero entry slots outside the palette read instead (their vertices
/// are then redone by skinVertexChecked, which skips such slots).
alignas(32) const PaletteEntry kZeroEntry{};

struct BlockContext {
    const std::uint32_t* vertices;
    const float* inP;
    std::size_t inPs;
    std::size_t safeP;  // vertices below this can read 4 floats of position
    const float* inN;
    std::size_t inNs;
    std::size_t safeN;
    const std::int32_t* boneIndices;
    const float* boneWeights;
    std::size_t weightCount;  // floats in boneWeights
    std::size_t stride;
    int count;
    const PaletteEntry* palette;
    std::size_t bones;
    __m256 scale;  // s s s 0 | s s s 0
    __m256 bias;   // bx by bz 1 | bx by bz 1
    // Scale 1 and bias 0 (what the renderer passes, the palette having them
    // folded in, PaletteJob::positionScale): runs skip foldScaleBias.
    bool identity;
    // The inputs as planes (SkinningJob::inPositionPlanes), null when the
    // job has none or its arrays are not packed; `plane` floats apart.
    const float* planeP;
    const float* planeN;
    std::size_t plane;
};

/// Entry `bone` of the palette, or the zero entry (setting `bad`) outside it.
M3G_AVX2_INLINE const float* paletteRow(const BlockContext& c, std::int32_t bone, unsigned& bad) noexcept {
    const auto b = static_cast<std::uint32_t>(bone);
    const bool in = b < c.bones;
    bad |= static_cast<unsigned>(!in);
    return reinterpret_cast<const float*>(in ? c.palette + b : &kZeroEntry);
}

/// (x, y, z, w) of an xyz triple in both halves; w is whatever follows z
/// (the caller blends it away), read only when `wide` says it is there.
template <bool Wide>
M3G_AVX2_INLINE __m256 broadcastXyz(const float* p, bool wide) noexcept {
    if (Wide || wide) return _mm256_broadcast_ps(reinterpret_cast<const __m128*>(p));
    const __m128 x = loadXyz0(p);
    return pair(x, x);
}

struct Rows {
    __m256 m0, m1, m2;  // (P0|P1).(p|p), (P2|N0).(p|n), (N1|N2).(n|n), per element
};

/// The K palette entries of one vertex blended: (P0|P1), (P2|N0), (N1|N2).
/// Sets `bad` when a slot's bone is outside the palette.
template <int K>
M3G_AVX2_INLINE void blendRows(const BlockContext& c, const std::int32_t* bi, const float* bw, __m256& y0, __m256& y1,
                               __m256& y2, unsigned& bad) noexcept {
    const int count = K > 0 ? K : c.count;
    const float* e = paletteRow(c, bi[0], bad);
    const __m256 w0 = _mm256_broadcast_ss(bw);
    y0 = _mm256_mul_ps(w0, _mm256_loadu_ps(e));
    y1 = _mm256_mul_ps(w0, _mm256_loadu_ps(e + 8));
    y2 = _mm256_mul_ps(w0, _mm256_loadu_ps(e + 16));
#pragma GCC unroll 4
    for (int k = 1; k < count; ++k) {
        const float* f = paletteRow(c, bi[k], bad);
        const __m256 w = _mm256_broadcast_ss(bw + k);
        y0 = _mm256_fmadd_ps(w, _mm256_loadu_ps(f), y0);
        y1 = _mm256_fmadd_ps(w, _mm256_loadu_ps(f + 8), y1);
        y2 = _mm256_fmadd_ps(w, _mm256_loadu_ps(f + 16), y2);
    }
}

/// One vertex: its blended rows times its inputs (raw xyz broadcasts `p`,
/// `n`).
template <int K>
M3G_AVX2_INLINE Rows blendLane(const BlockContext& c, const std::int32_t* bi, const float* bw, __m256 p, __m256 n,
                               unsigned& bad) noexcept {
    __m256 y0, y1, y2;
    blendRows<K>(c, bi, bw, y0, y1, y2, bad);
    const __m256 zero = _mm256_setzero_ps();
    // (p|p) with w = 1: s * xyz + bias on xyz, 0 * 0 + 1 on w.
    const __m256 pp = _mm256_fmadd_ps(_mm256_blend_ps(p, zero, 0x88), c.scale, c.bias);
    const __m256 nn = _mm256_blend_ps(n, zero, 0x88);
    const __m256 pn = _mm256_blend_ps(pp, nn, 0xF0);
    return {_mm256_mul_ps(y0, pp), _mm256_mul_ps(y1, pn), _mm256_mul_ps(y2, nn)};
}

/// [a0+a2, b0+b2, a1+a3, b1+b3] per 128-bit half.
M3G_AVX2_INLINE __m256 pairSum(__m256 a, __m256 b) noexcept {
    return _mm256_add_ps(_mm256_unpacklo_ps(a, b), _mm256_unpackhi_ps(a, b));
}
/// Sums of the four elements of a, b, c, d per 128-bit half (from pairSum).
M3G_AVX2_INLINE __m256 quadSum(__m256 ab, __m256 cd) noexcept {
    return _mm256_add_ps(_mm256_shuffle_ps(ab, cd, _MM_SHUFFLE(1, 0, 1, 0)),
                         _mm256_shuffle_ps(ab, cd, _MM_SHUFFLE(3, 2, 3, 2)));
}

/// Lanes from .. from+lanes-1 of x, y, z (within 0..7): floats [3 from,
/// 3 (from + lanes)) of the 24 that storeSoa3(out) writes, and no others
/// (a run's last block: its other lanes belong to other vertices, which
/// must not be written).
M3G_AVX2_INLINE void storeSoa3Lanes(float* out, __m256 x, __m256 y, __m256 z, std::size_t from,
                                    std::size_t lanes) noexcept {
    alignas(32) float t[24];
    __m256 o0, o1, o2;
    soa3ToXyz(x, y, z, o0, o1, o2);
    _mm256_store_ps(t, o0);
    _mm256_store_ps(t + 8, o1);
    _mm256_store_ps(t + 16, o2);
    const std::size_t end = 3 * (from + lanes);
    std::size_t i = 3 * from;
    for (; i + 8 <= end; i += 8) _mm256_storeu_ps(out + i, _mm256_loadu_ps(t + i));
    if (i + 4 <= end) {
        _mm_storeu_ps(out + i, _mm_loadu_ps(t + i));
        i += 4;
    }
    for (; i < end; ++i) out[i] = t[i];
}

/// One block's results: eight lanes of position and unit normal.
struct Block {
    __m256 x, y, z, nx, ny, nz;
};

/// x|y, z|nx, ny|nz of lanes l0 .. l0+3 (the four vertices per half); bit
/// l of `bad` set for a lane l with a slot outside the palette.
template <int K, bool Wide, class Lane>
M3G_AVX2_INLINE void skinQuad(const BlockContext& c, Lane& lane, int l0, __m256& g0, __m256& g1, __m256& g2,
                              unsigned& bad) noexcept {
    Rows r[4];
#pragma GCC unroll 4
    for (int q = 0; q < 4; ++q) {
        const std::int32_t* bi;
        const float* bw;
        const float* p;
        const float* n;
        bool wide;
        lane(l0 + q, bi, bw, p, n, wide);
        unsigned laneBad = 0;
        r[q] = blendLane<K>(c, bi, bw, broadcastXyz<Wide>(p, wide), broadcastXyz<Wide>(n, wide), laneBad);
        bad |= laneBad << (l0 + q);
    }
    g0 = quadSum(pairSum(r[0].m0, r[1].m0), pairSum(r[2].m0, r[3].m0));
    g1 = quadSum(pairSum(r[0].m1, r[1].m1), pairSum(r[2].m1, r[3].m1));
    g2 = quadSum(pairSum(r[0].m2, r[1].m2), pairSum(r[2].m2, r[3].m2));
}

/// Skins the eight vertices whose inputs `lane(l, bi, bw, p, n, wide)`
/// supplies (l = 0..7); Wide: every lane may read 4 floats at p and n.
template <int K, bool Wide, class Lane>
M3G_AVX2_INLINE Block skinBlock(const BlockContext& c, Lane&& lane, unsigned& bad) noexcept {
    __m256 a0, a1, a2, b0, b1, b2;
    skinQuad<K, Wide>(c, lane, 0, a0, a1, a2, bad);
    skinQuad<K, Wide>(c, lane, 4, b0, b1, b2, bad);
    const __m256 g[2][3] = {{a0, a1, a2}, {b0, b1, b2}};
    Block o;
    o.x = _mm256_permute2f128_ps(g[0][0], g[1][0], 0x20);
    o.y = _mm256_permute2f128_ps(g[0][0], g[1][0], 0x31);
    o.z = _mm256_permute2f128_ps(g[0][1], g[1][1], 0x20);
    const __m256 nx = _mm256_permute2f128_ps(g[0][1], g[1][1], 0x31);
    const __m256 ny = _mm256_permute2f128_ps(g[0][2], g[1][2], 0x20);
    const __m256 nz = _mm256_permute2f128_ps(g[0][2], g[1][2], 0x31);
    const __m256 inv = inverseLength(nx, ny, nz);
    o.nx = _mm256_mul_ps(nx, inv);
    o.ny = _mm256_mul_ps(ny, inv);
    o.nz = _mm256_mul_ps(nz, inv);
    return o;
}

/// The blended rows of a shared set of influences (blendRows' 24 floats:
/// P0 P1 P2 N0 N1 N2, four each) as eight-lane coefficients. Two sources:
/// - UniformRows: every coefficient broadcast once per run, so that the
///   block loop's FMAs take them as memory operands (pays for itself from
///   three blocks on);
/// - RowBroadcasts: a broadcast load per use from the 24 floats (no set-up:
///   short runs). Written as inline assembly with a memory operand: from
///   the intrinsic, GCC hoisted the 24 addresses out of the loop and
///   spilled them to the stack.
struct UniformRows {
    __m256 m[24];
    M3G_AVX2_INLINE __m256 operator[](int i) const noexcept { return m[i]; }
};

struct RowBroadcasts {
    const float* m;
    M3G_AVX2_INLINE __m256 operator[](int i) const noexcept {
        __m256 r;
        asm("vbroadcastss %1, %0" : "=x"(r) : "m"(m[i]));
        return r;
    }
};

M3G_AVX2_INLINE void broadcastRows(const float* rows, UniformRows& u) noexcept {
#pragma GCC unroll 24
    for (int i = 0; i < 24; ++i) u.m[i] = _mm256_broadcast_ss(rows + i);
}

/// Row `r` (coefficients 4r .. 4r+3) applied to lanes a, b, c (+ the
/// fourth coefficient).
template <bool Translate, class Rows>
M3G_AVX2_INLINE __m256 rowTimes(const Rows& m, int r, __m256 a, __m256 b, __m256 c) noexcept {
    const __m256 first = Translate ? _mm256_fmadd_ps(m[4 * r], a, m[4 * r + 3]) : _mm256_mul_ps(m[4 * r], a);
    return _mm256_fmadd_ps(m[4 * r + 2], c, _mm256_fmadd_ps(m[4 * r + 1], b, first));
}

/// The blended position rows (P0 | P1 in y0, P2 in y1's low half) with the
/// job's position scale and bias folded in, so that the block loop applies
/// them to the raw inputs: P (s p + b) = (P s) p + (P b), row by row
/// (r0 s, r1 s, r2 s, r0 b0 + r1 b1 + r2 b2 + r3). Once per shared set of
/// influences, not per block.
/// y * s, plus y . (b, 0) (per 128-bit half) in the elements of WMask.
template <int WMask>
M3G_AVX2_INLINE __m256 foldRows(__m256 y, __m256 s, __m256 bias) noexcept {
    const __m256 dot = sumPerHalf(_mm256_mul_ps(y, bias));
    return _mm256_add_ps(_mm256_mul_ps(y, s), _mm256_blend_ps(_mm256_setzero_ps(), dot, WMask));
}

M3G_AVX2_INLINE void foldScaleBias(const BlockContext& c, __m256& y0, __m256& y1) noexcept {
    const __m256 one = _mm256_set1_ps(1.0f);
    const __m256 scale = _mm256_blend_ps(c.scale, one, 0x88);                // s s s 1 | s s s 1
    const __m256 bias = _mm256_blend_ps(c.bias, _mm256_setzero_ps(), 0x88);  // bx by bz 0 | bx by bz 0
    y0 = foldRows<0x88>(y0, scale, bias);
    // y1: P2 | N0; the normal row keeps its values (scale 1, nothing added).
    y1 = foldRows<0x08>(y1, _mm256_blend_ps(scale, one, 0xF0), bias);
}

/// Eight vertices sharing one set of influences (the common case:
/// SkinnedMesh::addTransform gives runs of vertices the same bones and
/// weights), inputs as eight lanes of x, y, z: the rows, blended once and
/// with the scale and bias folded in (foldScaleBias), are applied with
/// FMAs (the result may differ from skinBlock's in the last bits; a
/// vertex's block or run, not the chunking, decides which runs).
template <class Rows>
M3G_AVX2_INLINE Block skinUniform(const Rows& m, __m256 px, __m256 py, __m256 pz, __m256 nx, __m256 ny,
                                  __m256 nz) noexcept {
    Block o;
    o.x = rowTimes<true>(m, 0, px, py, pz);
    o.y = rowTimes<true>(m, 1, px, py, pz);
    o.z = rowTimes<true>(m, 2, px, py, pz);
    const __m256 bx = rowTimes<false>(m, 3, nx, ny, nz);
    const __m256 by = rowTimes<false>(m, 4, nx, ny, nz);
    const __m256 bz = rowTimes<false>(m, 5, nx, ny, nz);
    const __m256 inv = inverseLength(bx, by, bz);
    o.nx = _mm256_mul_ps(bx, inv);
    o.ny = _mm256_mul_ps(by, inv);
    o.nz = _mm256_mul_ps(bz, inv);
    return o;
}

/// The same from eight consecutive packed xyz triples at p and n.
template <class Rows>
M3G_AVX2_INLINE Block skinUniform(const Rows& m, const float* p, const float* n) noexcept {
    __m256 px, py, pz, nx, ny, nz;
    loadSoa3(p, px, py, pz);
    loadSoa3(n, nx, ny, nz);
    return skinUniform(m, px, py, pz, nx, ny, nz);
}

/// xyz of vertices first .. first+lanes-1 (lanes 1..8; the last repeated in
/// the lanes beyond) at `stride` floats as eight lanes of x, y, z. Vertices
/// below `safe` are read four floats at a time; `w` (if given) receives the
/// fourth floats, meaningful when every lane is below `safe`.
M3G_AVX2_INLINE void gatherSoa3(const float* base, std::size_t stride, std::size_t safe, std::size_t first,
                                std::size_t lanes, __m256& x, __m256& y, __m256& z, __m256* w = nullptr) noexcept {
    __m128 q[8];
#pragma GCC unroll 8
    for (std::size_t l = 0; l < 8; ++l) {
        const std::size_t v = first + (l < lanes ? l : lanes - 1);
        const float* p = base + v * stride;
        q[l] = v < safe ? _mm_loadu_ps(p) : loadXyz0(p);
    }
    const __m256 a0 = pair(q[0], q[4]), a1 = pair(q[1], q[5]), a2 = pair(q[2], q[6]), a3 = pair(q[3], q[7]);
    const __m256 t0 = _mm256_unpacklo_ps(a0, a1), t1 = _mm256_unpackhi_ps(a0, a1);
    const __m256 t2 = _mm256_unpacklo_ps(a2, a3), t3 = _mm256_unpackhi_ps(a2, a3);
    x = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0));
    y = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
    z = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0));
    if (w) *w = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2));  // the fourth floats (lanes below `safe`)
}

/// Lanes 0 .. lanes-1 of x, y, z to the xyz triples of vertices first ..
/// first+lanes-1 at `stride` floats (three floats written per vertex).
M3G_AVX2_INLINE void scatterSoa3(float* base, std::size_t stride, std::size_t first, std::size_t lanes, __m256 x,
                                 __m256 y, __m256 z) noexcept {
    const __m256 zero = _mm256_setzero_ps();
    const __m256 t0 = _mm256_unpacklo_ps(x, y), t1 = _mm256_unpackhi_ps(x, y);
    const __m256 t2 = _mm256_unpacklo_ps(z, zero), t3 = _mm256_unpackhi_ps(z, zero);
    const __m256 q[4] = {_mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0)),
                         _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2)),
                         _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0)),
                         _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2))};
    for (std::size_t l = 0; l < lanes; ++l) {
        const __m128 v = l < 4 ? _mm256_castps256_ps128(q[l]) : _mm256_extractf128_ps(q[l - 4], 1);
        storeXyz(base + (first + l) * stride, v);
    }
}

/// The block kernels' view of a job.
M3G_AVX2_INLINE BlockContext blockContext(const SkinningJob& j) noexcept {
    BlockContext c;
    c.vertices = j.vertices.data();
    c.inP = j.inPositions.data();
    c.inPs = j.inPositionStride;
    c.safeP = j.inPositions.size() >= 4 ? (j.inPositions.size() - 4) / c.inPs + 1 : 0;
    c.inN = j.inNormals.data();
    c.inNs = j.inNormalStride;
    c.safeN = j.inNormals.size() >= 4 ? (j.inNormals.size() - 4) / c.inNs + 1 : 0;
    c.boneIndices = j.boneIndices.data();
    c.boneWeights = j.boneWeights.data();
    c.weightCount = j.boneWeights.size();
    c.stride = static_cast<std::size_t>(j.influenceStride);
    c.count = j.influenceCount;
    c.palette = j.palette.data();
    c.bones = j.palette.size();
    const float s = j.positionScale;
    c.scale = _mm256_setr_ps(s, s, s, 0.0f, s, s, s, 0.0f);
    c.identity = isIdentityScaleBias(s, j.positionBias);
    c.bias = _mm256_setr_ps(j.positionBias[0], j.positionBias[1], j.positionBias[2], 1.0f, j.positionBias[0],
                            j.positionBias[1], j.positionBias[2], 1.0f);
    const bool planes = readsPlanes(j);
    c.planeP = planes ? j.inPositionPlanes.data() : nullptr;
    c.planeN = planes ? j.inNormalPlanes.data() : nullptr;
    c.plane = j.vertexCount;
    return c;
}

/// The eight vertices from v (inside the arrays) of a packed job as x, y,
/// z lanes: three loads each from the planes, or loadSoa3's transposition
/// of their triples. The same values either way.
template <bool Planes>
M3G_AVX2_INLINE void loadLanes8(const BlockContext& c, std::size_t v, __m256& px, __m256& py, __m256& pz, __m256& nx,
                                __m256& ny, __m256& nz) noexcept {
    if constexpr (Planes) {
        px = _mm256_loadu_ps(c.planeP + v);
        py = _mm256_loadu_ps(c.planeP + c.plane + v);
        pz = _mm256_loadu_ps(c.planeP + 2 * c.plane + v);
        nx = _mm256_loadu_ps(c.planeN + v);
        ny = _mm256_loadu_ps(c.planeN + c.plane + v);
        nz = _mm256_loadu_ps(c.planeN + 2 * c.plane + v);
    } else {
        loadSoa3(c.inP + 3 * v, px, py, pz);
        loadSoa3(c.inN + 3 * v, nx, ny, nz);
    }
}

template <int K>
M3G_AVX2 void skinBlocks(const SkinningJob& j, std::size_t begin, std::size_t end) noexcept {
    const BlockContext c = blockContext(j);
    float* outP = j.outPositions.data();
    float* outN = j.outNormals.data();
    const std::size_t outPs = j.outPositionStride, outNs = j.outNormalStride;
    const std::size_t stride = c.stride;
    // Consecutive vertices, packed xyz arrays: lanes at fixed offsets from
    // the block's first vertex, 256-bit stores.
    const bool packed = isPacked(j);
    const std::size_t safe = c.safeP < c.safeN ? c.safeP : c.safeN;
    const __m256i ramp = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const std::size_t total = j.vertices.size();
    // Blocks are aligned to the list (list positions 8b .. 8b+7), not to
    // `begin`: which path a vertex takes (consecutive or any) depends
    // on its block only, so any chunking gives the same bits. A block cut
    // by [begin, end) is computed whole and only its lanes in range stored.
    for (std::size_t a = begin - begin % 8; a < end; a += 8) {
        const std::size_t n = total - a < 8 ? total - a : 8;  // lanes in the list
        const std::size_t lo = begin > a ? begin - a : 0;
        const std::size_t hi = end - a < 8 ? end - a : 8;  // lanes to store: [lo, hi)
        unsigned bad = 0;
        std::size_t v[8];
        Block o;
        const std::size_t v0 = c.vertices[a];
        bool consecutive = false;
        if (packed && n == 8 && v0 + 8 <= safe) {
            const __m256i listed = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(c.vertices + a));
            const __m256i expect = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(v0)), ramp);
            consecutive = _mm256_movemask_epi8(_mm256_cmpeq_epi32(listed, expect)) == -1;
        }
        if (consecutive) {
            const float* p0 = c.inP + v0 * 3;
            const float* n0 = c.inN + v0 * 3;
            const std::int32_t* b0 = c.boneIndices + v0 * stride;
            const float* w0 = c.boneWeights + v0 * stride;
            o = skinBlock<K, true>(
                c,
                [&](int l, const std::int32_t*& bi, const float*& bw, const float*& p, const float*& nrm, bool& wide) {
                    const auto ls = static_cast<std::size_t>(l);
                    bi = b0 + ls * stride;
                    bw = w0 + ls * stride;
                    p = p0 + 3 * ls;
                    nrm = n0 + 3 * ls;
                    wide = true;
                },
                bad);
            if (lo == 0 && hi == 8 && !bad) {
                storeSoa3(outP + v0 * 3, o.x, o.y, o.z);
                storeSoa3(outN + v0 * 3, o.nx, o.ny, o.nz);
                continue;
            }
            for (std::size_t l = 0; l < 8; ++l) v[l] = v0 + l;
        } else {
            // Any list: lanes by index; a short block repeats its last vertex.
            for (std::size_t l = 0; l < 8; ++l) v[l] = c.vertices[a + (l < n ? l : n - 1)];
            o = skinBlock<K, false>(
                c,
                [&](int l, const std::int32_t*& bi, const float*& bw, const float*& p, const float*& nrm,
                    bool& wide) {
                    const std::size_t vl = v[l];
                    bi = c.boneIndices + vl * stride;
                    bw = c.boneWeights + vl * stride;
                    p = c.inP + vl * c.inPs;
                    nrm = c.inN + vl * c.inNs;
                    wide = vl < safe;
                },
                bad);
        }
        alignas(32) float t[6][8];
        _mm256_store_ps(t[0], o.x);
        _mm256_store_ps(t[1], o.y);
        _mm256_store_ps(t[2], o.z);
        _mm256_store_ps(t[3], o.nx);
        _mm256_store_ps(t[4], o.ny);
        _mm256_store_ps(t[5], o.nz);
        for (std::size_t l = lo; l < hi; ++l) {
            float* op = outP + v[l] * outPs;
            float* on = outN + v[l] * outNs;
            op[0] = t[0][l], op[1] = t[1][l], op[2] = t[2][l];
            on[0] = t[3][l], on[1] = t[4][l], on[2] = t[5][l];
        }
        // A vertex with a slot outside the palette: by the checked formula.
        // Each lane's result depends on its own vertex only (the arithmetic
        // is the same in every lane and either path), so neither the block
        // a vertex lands in nor the chunking changes its bits.
        if (bad)
            for (std::size_t l = lo; l < hi; ++l)
                if ((bad >> l) & 1u) skinVertexChecked(j, v[l]);
    }
}

/// Vertices [v, v + count) of a run, eight at a time by skinUniform with
/// the run's rows: inputs loaded straight from packed arrays (the last,
/// partial block too, storing only its lanes), or gathered and scattered
/// lane by lane at other strides and in arrays shorter than a block.
template <bool Planes, class Rows>
M3G_AVX2_INLINE void skinRunRows(const SkinningJob& j, const BlockContext& c, bool packed, const Rows& rows,
                                 std::size_t v, std::size_t count) noexcept {
    const std::size_t end = v + count;
    float* outP = j.outPositions.data();
    float* outN = j.outNormals.data();
    if (packed) {
        // loadSoa3 reads exactly the eight vertices' 24 floats (a validated
        // run ends inside the arrays).
        for (; v + 8 <= end; v += 8) {
            __m256 px, py, pz, nx, ny, nz;
            loadLanes8<Planes>(c, v, px, py, pz, nx, ny, nz);
            const Block o = skinUniform(rows, px, py, pz, nx, ny, nz);
            storeSoa3(outP + v * 3, o.x, o.y, o.z);
            storeSoa3(outN + v * 3, o.nx, o.ny, o.nz);
        }
    }
    if (packed && v < end && j.vertexCount >= 8) {
        // The last (partial) block: loaded as the whole block of the eight
        // vertices from v, or, at the end of the arrays, of the last eight
        // (the ones outside the run are read, not written), and only the
        // run's lanes stored.
        const std::size_t base = v + 8 <= j.vertexCount ? v : j.vertexCount - 8;
        __m256 px, py, pz, nx, ny, nz;
        loadLanes8<Planes>(c, base, px, py, pz, nx, ny, nz);
        const Block o = skinUniform(rows, px, py, pz, nx, ny, nz);
        storeSoa3Lanes(outP + base * 3, o.x, o.y, o.z, v - base, end - v);
        storeSoa3Lanes(outN + base * 3, o.nx, o.ny, o.nz, v - base, end - v);
        return;
    }
    while (v < end) {
        const std::size_t lanes = end - v < 8 ? end - v : 8;
        __m256 px, py, pz, nx, ny, nz;
        gatherSoa3(c.inP, c.inPs, c.safeP, v, lanes, px, py, pz);
        gatherSoa3(c.inN, c.inNs, c.safeN, v, lanes, nx, ny, nz);
        const Block o = skinUniform(rows, px, py, pz, nx, ny, nz);
        scatterSoa3(outP, j.outPositionStride, v, lanes, o.x, o.y, o.z);
        scatterSoa3(outN, j.outNormalStride, v, lanes, o.nx, o.ny, o.nz);
        v += lanes;
    }
}

template <int K, bool Planes>
M3G_AVX2_INLINE void skinRun(const SkinningJob& j, const BlockContext& c, bool packed, std::size_t runFirst,
                             std::size_t v, std::size_t count) noexcept {
    const std::int32_t* bi = c.boneIndices + runFirst * c.stride;
    const float* bw = c.boneWeights + runFirst * c.stride;
    unsigned bad = 0;
    __m256 y0, y1, y2;
    blendRows<K>(c, bi, bw, y0, y1, y2, bad);
    if (bad) {
        // A slot outside the palette: the checked formula, vertex by vertex.
        for (std::size_t i = 0; i < count; ++i) skinVertexChecked(j, v + i);
        return;
    }
    if (!c.identity) foldScaleBias(c, y0, y1);
    // The rows are applied from this copy (reading a one-bone run's rows in
    // place from its palette entry, with no blend and no fold, measured
    // slower: 2.13 against 1.94 ns a vertex at 100k in runs of 16).
    alignas(32) float rows[24];
    _mm256_store_ps(rows, y0);
    _mm256_store_ps(rows + 8, y1);
    _mm256_store_ps(rows + 16, y2);
    if (count >= 24) {
        UniformRows uniform;
        broadcastRows(rows, uniform);
        skinRunRows<Planes>(j, c, packed, uniform, v, count);
    } else {
        skinRunRows<Planes>(j, c, packed, RowBroadcasts{rows}, v, count);
    }
}

/// Positions [begin, end) of the job's run sequence.
template <int K>
M3G_AVX2 void skinRuns(const SkinningJob& j, std::size_t begin, std::size_t end) noexcept {
    const BlockContext c = blockContext(j);
    const bool packed = isPacked(j);
    RunPieces pieces(j.runs, begin, end);
    std::size_t runFirst, first, count;
    if (c.planeP) {
        while (pieces.next(runFirst, first, count)) skinRun<K, true>(j, c, packed, runFirst, first, count);
    } else {
        while (pieces.next(runFirst, first, count)) skinRun<K, false>(j, c, packed, runFirst, first, count);
    }
}

// ---------------------------------------------------------------------------
// Bone runs (SkinningJob::boneRuns): vertices sharing their bones, each with
// its own weights, eight lanes a step (SkinningAvx512.cpp has the sixteen-
// lane form and why): each lane's weights times the run's palette entries,
// broadcast, give the lanes' blended matrix a row at a time, applied at
// once, with no horizontal reduction. Packed arrays only. The blocks are the
// run's whole eights counted from its first vertex (a block cut by a chunk
// is computed whole and stores only its lanes in the chunk); the run's last
// vertices (fewer than eight) take one more whole block, loaded from the
// eight vertices at the tail's first or, where the inputs or the weights
// end sooner, the run's last eight (the lanes outside the run are read,
// weighed with the run's entries and not stored), so they cost a block
// load and not a lane-by-lane gather (measured slower) nor the list kernel
// (test.m3g 7.75 -> 6.96 us held to AVX2: its bone runs average ten
// vertices). Only a run ending before vertex 8, or in a weight table's
// partial last row, sends its tail to the list kernel. Which kernel a
// vertex takes depends only on its run, so chunking does not change its
// bits.

/// Row r (coefficients 4r .. 4r+3) of the lanes' blended matrices.
template <int K>
M3G_AVX2_INLINE void blendRow8(const float* const (&e)[4], const __m256 (&w)[4], int r, __m256& c0, __m256& c1,
                               __m256& c2, __m256& c3) noexcept {
    c0 = _mm256_mul_ps(w[0], _mm256_broadcast_ss(e[0] + 4 * r));
    c1 = _mm256_mul_ps(w[0], _mm256_broadcast_ss(e[0] + 4 * r + 1));
    c2 = _mm256_mul_ps(w[0], _mm256_broadcast_ss(e[0] + 4 * r + 2));
    c3 = _mm256_mul_ps(w[0], _mm256_broadcast_ss(e[0] + 4 * r + 3));
#pragma GCC unroll 4
    for (int k = 1; k < K; ++k) {
        c0 = _mm256_fmadd_ps(w[k], _mm256_broadcast_ss(e[k] + 4 * r), c0);
        c1 = _mm256_fmadd_ps(w[k], _mm256_broadcast_ss(e[k] + 4 * r + 1), c1);
        c2 = _mm256_fmadd_ps(w[k], _mm256_broadcast_ss(e[k] + 4 * r + 2), c2);
        c3 = _mm256_fmadd_ps(w[k], _mm256_broadcast_ss(e[k] + 4 * r + 3), c3);
    }
}

/// The eight vertices from b of a bone run whose K entries are `e`; lanes
/// [lo, hi) stored.
template <int K, bool NormalsFromPositions, bool Planes>
M3G_AVX2_INLINE void skinBoneBlock(const SkinningJob& j, const BlockContext& c, const float* const (&e)[4],
                                   std::size_t b, std::size_t lo, std::size_t hi) noexcept {
    __m256 px, py, pz, nx, ny, nz;
    loadLanes8<Planes>(c, b, px, py, pz, nx, ny, nz);
    if (!c.identity) {
        const __m256 s = _mm256_set1_ps(j.positionScale);
        px = _mm256_fmadd_ps(px, s, _mm256_set1_ps(j.positionBias[0]));
        py = _mm256_fmadd_ps(py, s, _mm256_set1_ps(j.positionBias[1]));
        pz = _mm256_fmadd_ps(pz, s, _mm256_set1_ps(j.positionBias[2]));
    }
    // Slot k of lane l at weights[(b + l) * stride + k]: with four slots or
    // more (and the arrays holding four floats from every lane's first) the
    // lanes' first four transposed as gatherSoa3 does xyz, else element by
    // element.
    __m256 w[4];
    const float* weights = c.boneWeights + b * c.stride;
    if (c.stride >= 4 && (b + 8) * c.stride <= c.weightCount) {
        gatherSoa3(weights, c.stride, 8, 0, 8, w[0], w[1], w[2], &w[3]);
    } else {
#pragma GCC unroll 4
        for (int k = 0; k < K; ++k) {
            const float* s = weights + k;
            const std::size_t t = c.stride;
            w[k] = _mm256_setr_ps(s[0], s[t], s[2 * t], s[3 * t], s[4 * t], s[5 * t], s[6 * t], s[7 * t]);
        }
    }
    // With a conformal palette (SkinningJob::normalsFromPositions) the
    // position rows' 3x3 also turns the normal: three rows blended, not six.
    __m256 c0, c1, c2, c3;
    __m256 x, y, z, bx, by, bz;
    blendRow8<K>(e, w, 0, c0, c1, c2, c3);
    x = _mm256_fmadd_ps(c2, pz, _mm256_fmadd_ps(c1, py, _mm256_fmadd_ps(c0, px, c3)));
    if constexpr (NormalsFromPositions) bx = _mm256_fmadd_ps(c2, nz, _mm256_fmadd_ps(c1, ny, _mm256_mul_ps(c0, nx)));
    blendRow8<K>(e, w, 1, c0, c1, c2, c3);
    y = _mm256_fmadd_ps(c2, pz, _mm256_fmadd_ps(c1, py, _mm256_fmadd_ps(c0, px, c3)));
    if constexpr (NormalsFromPositions) by = _mm256_fmadd_ps(c2, nz, _mm256_fmadd_ps(c1, ny, _mm256_mul_ps(c0, nx)));
    blendRow8<K>(e, w, 2, c0, c1, c2, c3);
    z = _mm256_fmadd_ps(c2, pz, _mm256_fmadd_ps(c1, py, _mm256_fmadd_ps(c0, px, c3)));
    if constexpr (NormalsFromPositions) {
        bz = _mm256_fmadd_ps(c2, nz, _mm256_fmadd_ps(c1, ny, _mm256_mul_ps(c0, nx)));
    } else {
        blendRow8<K>(e, w, 3, c0, c1, c2, c3);
        bx = _mm256_fmadd_ps(c2, nz, _mm256_fmadd_ps(c1, ny, _mm256_mul_ps(c0, nx)));
        blendRow8<K>(e, w, 4, c0, c1, c2, c3);
        by = _mm256_fmadd_ps(c2, nz, _mm256_fmadd_ps(c1, ny, _mm256_mul_ps(c0, nx)));
        blendRow8<K>(e, w, 5, c0, c1, c2, c3);
        bz = _mm256_fmadd_ps(c2, nz, _mm256_fmadd_ps(c1, ny, _mm256_mul_ps(c0, nx)));
    }
    const __m256 inv = inverseLength(bx, by, bz);
    const __m256 ox = _mm256_mul_ps(bx, inv), oy = _mm256_mul_ps(by, inv), oz = _mm256_mul_ps(bz, inv);
    float* outP = j.outPositions.data() + 3 * b;
    float* outN = j.outNormals.data() + 3 * b;
    if (lo == 0 && hi == 8) {
        storeSoa3(outP, x, y, z);
        storeSoa3(outN, ox, oy, oz);
    } else {
        storeSoa3Lanes(outP, x, y, z, lo, hi - lo);
        storeSoa3Lanes(outN, ox, oy, oz, lo, hi - lo);
    }
}

template <int K, bool NormalsFromPositions, bool Planes>
M3G_AVX2 void skinBoneRuns(const SkinningJob& j, std::size_t begin, std::size_t end) noexcept {
    const BlockContext c = blockContext(j);
    std::uint32_t tail[256];
    std::size_t tailCount = 0;
    auto flushTail = [&] {
        if (tailCount == 0) return;
        SkinningJob list = j;
        list.runs = {};
        list.boneRuns = {};
        list.vertices = std::span<const std::uint32_t>(tail, tailCount);
        skinBlocks<K>(list, 0, tailCount);
        tailCount = 0;
    };
    RunPieces pieces(j.boneRuns, begin, end);
    std::size_t runFirst, first, count;
    while (pieces.next(runFirst, first, count)) {
        const std::size_t stop = first + count;
        const std::size_t wholeEnd = runFirst + pieces.runLength() / 8 * 8;
        const std::int32_t* bi = c.boneIndices + runFirst * c.stride;
        const float* e[4] = {};
        if (!boneRunEntries<K>(j, bi, e)) {
            // A slot outside the palette: the checked formula, vertex by vertex.
            for (std::size_t v = first; v < stop; ++v) skinVertexChecked(j, v);
            continue;
        }
        for (std::size_t b = runFirst + (first - runFirst) / 8 * 8; b < stop && b < wholeEnd; b += 8) {
            const std::size_t lo = first > b ? first - b : 0;
            const std::size_t hi = stop - b < 8 ? stop - b : 8;
            skinBoneBlock<K, NormalsFromPositions, Planes>(j, c, e, b, lo, hi);
        }
        // The tail (see above): one block, only its lanes stored, whether it
        // does decided by the run alone (so not by the chunking). Its eight
        // lanes must have inputs and whole weight rows (the weights may end
        // before the inputs: the compact space's unboned vertices have none):
        // from the tail's first vertex when those eight do, else the run's
        // last eight, which lie before its end.
        const std::size_t tailFirst = first > wholeEnd ? first : wholeEnd;
        const std::size_t runEnd = runFirst + pieces.runLength();
        if (tailFirst < stop && runEnd >= 8 && runEnd * c.stride <= c.weightCount) {
            const bool fromTail = tailFirst + 8 <= j.vertexCount && (tailFirst + 8) * c.stride <= c.weightCount;
            const std::size_t base = fromTail ? tailFirst : runEnd - 8;
            skinBoneBlock<K, NormalsFromPositions, Planes>(j, c, e, base, tailFirst - base, stop - base);
            continue;
        }
        for (std::size_t v = tailFirst; v < stop; ++v) {
            tail[tailCount++] = static_cast<std::uint32_t>(v);
            if (tailCount == std::size(tail)) flushTail();
        }
    }
    flushTail();
}

template <int K>
M3G_AVX2_INLINE void boneRuns(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept {
    withBoneRunChoices(job, [&](auto normalsFromPositions, auto planes) {
        skinBoneRuns<K, decltype(normalsFromPositions)::value, decltype(planes)::value>(job, begin, end);
    });
}

template <bool Normals>
M3G_AVX2 void skinN(const SkinningJob& j, std::size_t begin, std::size_t end) noexcept {
    if constexpr (Normals) {
        switch (j.influenceCount) {
            case 0: break;
            case 1: skinBlocks<1>(j, begin, end); return;
            case 2: skinBlocks<2>(j, begin, end); return;
            case 3: skinBlocks<3>(j, begin, end); return;
            case 4: skinBlocks<4>(j, begin, end); return;
            default: skinBlocks<-1>(j, begin, end); return;
        }
    }
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

M3G_AVX2 std::uint32_t maxIndexAvx2(const std::uint32_t* indices, std::size_t count) noexcept {
    __m256i m0 = _mm256_setzero_si256(), m1 = m0;
    std::size_t i = 0;
    for (; i + 16 <= count; i += 16) {
        m0 = _mm256_max_epu32(m0, _mm256_loadu_si256(reinterpret_cast<const __m256i*>(indices + i)));
        m1 = _mm256_max_epu32(m1, _mm256_loadu_si256(reinterpret_cast<const __m256i*>(indices + i + 8)));
    }
    alignas(32) std::uint32_t lanes[8];
    _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), _mm256_max_epu32(m0, m1));
    std::uint32_t m = 0;
    for (std::uint32_t x : lanes) m = x > m ? x : m;
    for (; i < count; ++i) m = indices[i] > m ? indices[i] : m;
    return m;
}

M3G_AVX2 bool skinRunsAvx2(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept {
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

M3G_AVX2 bool skinBoneRunsAvx2(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept {
    if (job.inNormals.empty()) return false;
    if (!isPacked(job)) return false;
    switch (job.influenceCount) {
        case 1: boneRuns<1>(job, begin, end); return true;
        case 2: boneRuns<2>(job, begin, end); return true;
        case 3: boneRuns<3>(job, begin, end); return true;
        case 4: boneRuns<4>(job, begin, end); return true;
        default: return false;  // 0, or more than four slots: the list path
    }
}

M3G_AVX2 void skinAvx2(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept {
    if (job.inNormals.empty())
        skinN<false>(job, begin, end);
    else
        skinN<true>(job, begin, end);
}

}  // namespace m3g::skin::detail

#endif  // M3G_SKIN_X86
