#include <m3g/skin/Skinning.h>

#include <algorithm>
#include <cstring>
#include <iterator>

#include <m3g/skin/InfluenceTable.h>
#include <m3g/skin/ThreadPool.h>

#include "Kernels.h"

namespace m3g::skin {

namespace {

// A per-vertex array of `count` vertices at `stride` floats holds
// (count - 1) * stride + 3 floats at least. A product with an overflow
// check, not a quotient: every job of every mesh asks several times a
// frame, and a 64-bit division costs more than the rest of the check.
bool holds(std::span<const float> a, std::size_t count, std::size_t stride) noexcept {
    if (stride < 3) return false;
    if (count == 0) return true;
    std::size_t reach;
    return !__builtin_mul_overflow(count - 1, stride, &reach) && a.size() >= 3 && reach <= a.size() - 3;
}

void runRange(const SkinningJob& job, Isa isa, std::size_t begin, std::size_t end) noexcept {
    switch (isa) {
#ifdef M3G_SKIN_X86
        case Isa::Sse2: detail::skinSse2(job, begin, end); return;
        case Isa::Avx2:
        case Isa::Avx512: detail::skinAvx2(job, begin, end); return;  // the list: AVX2
#endif
        default: detail::skinScalar(job, begin, end); return;
    }
}

}  // namespace

namespace {

/// `start` the running sum and every run inside [0, bound) (O(runs), no
/// per-vertex reading); `total` receives the runs' vertex count.
bool checkRuns(std::span<const InfluenceRun> runs, std::uint64_t bound, std::size_t* total) noexcept {
    std::uint64_t sum = 0;
    for (const InfluenceRun& r : runs) {
        if (r.start != sum) return false;
        if (static_cast<std::uint64_t>(r.firstVertex) + r.vertexCount > bound) return false;
        sum += r.vertexCount;
    }
    if (sum > 0xFFFFFFFFu) return false;
    *total = static_cast<std::size_t>(sum);
    return true;
}

/// validate()'s checks; `runVertices` and `boneRunVertices` receive the
/// runs' and the bone runs' vertex counts.
bool check(const SkinningJob& j, std::size_t* runVertices, std::size_t* boneRunVertices) noexcept {
    *runVertices = 0;
    *boneRunVertices = 0;
    if (j.influenceCount < 0 || j.influenceStride < j.influenceCount) return false;
    if (!isaSupported(j.isa)) return false;
    if (!holds(j.inPositions, j.vertexCount, j.inPositionStride)) return false;
    if (!holds(std::span<const float>(j.outPositions), j.vertexCount, j.outPositionStride)) return false;
    if (j.inNormals.empty() != j.outNormals.empty()) return false;
    if (!j.inNormals.empty() && (!holds(j.inNormals, j.vertexCount, j.inNormalStride) ||
                                 !holds(std::span<const float>(j.outNormals), j.vertexCount, j.outNormalStride)))
        return false;
    // Planes given hold every vertex (the kernels read them up to
    // vertexCount, lanes of a block at once).
    const std::size_t planeFloats = 3 * j.vertexCount;
    if (!j.inPositionPlanes.empty() && j.inPositionPlanes.size() < planeFloats) return false;
    if (!j.inNormalPlanes.empty() && (j.inNormals.empty() || j.inNormalPlanes.size() < planeFloats)) return false;
    // Every vertex must be below `limit`: the vertex count, and the number
    // of vertices the influence arrays reach.
    std::size_t limit = j.vertexCount;
    if (j.influenceCount > 0) {
        const auto stride = static_cast<std::size_t>(j.influenceStride);
        const auto count = static_cast<std::size_t>(j.influenceCount);
        const std::size_t size = std::min(j.boneIndices.size(), j.boneWeights.size());
        // Vertex v's slots end at v * stride + count: every vertex below
        // the vertex count (the usual table, one row per vertex) or the
        // first that does not fit (the quotient only then).
        std::size_t end;
        const bool all = limit == 0 || (!__builtin_mul_overflow(limit - 1, stride, &end) && end <= size &&
                                        size - end >= count);
        if (!all) limit = size < count ? 0 : std::min(limit, (size - count) / stride + 1);
    }
    const std::uint64_t bound = limit;
    // Runs: inside the arrays, `start` the running sum.
    if (!checkRuns(j.runs, bound, runVertices)) return false;
    if (!checkRuns(j.boneRuns, bound, boneRunVertices)) return false;
    if (j.vertices.empty()) return true;
    // The list: one pass, branch-free.
    const std::uint32_t* v = j.vertices.data();
    const std::size_t n = j.vertices.size();
#ifdef M3G_SKIN_X86
    if (n >= 64 && isaSupported(Isa::Avx2)) return detail::maxIndexAvx2(v, n) < bound;
#endif
    bool bad0 = false, bad1 = false, bad2 = false, bad3 = false;
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4) {
        bad0 |= v[i] >= bound;
        bad1 |= v[i + 1] >= bound;
        bad2 |= v[i + 2] >= bound;
        bad3 |= v[i + 3] >= bound;
    }
    for (; i < n; ++i) bad0 |= v[i] >= bound;
    return !(bad0 | bad1 | bad2 | bad3);
}

/// Positions [begin, end) of `runs` (the job's runs or bone runs) as one
/// vertex list, a 256-index stack buffer at a time, on the list kernels: the
/// scalar path, and what the SIMD run kernels do not cover (each vertex of
/// a valid run has the run's slots, or for a bone run its bones, which these
/// paths read). The pieces are concatenated so that short runs fill whole
/// blocks of the list kernel; a vertex's result does not depend on its
/// place in the list (SkinningAvx2.cpp's blocks decide per lane).
void runsAsLists(const SkinningJob& job, std::span<const InfluenceRun> runs, Isa isa, std::size_t begin,
                 std::size_t end) noexcept {
    std::uint32_t list[256];
    std::size_t listed = 0;
    SkinningJob sub = job;
    sub.runs = {};
    sub.boneRuns = {};
    auto flush = [&] {
        sub.vertices = std::span<const std::uint32_t>(list, listed);
        runRange(sub, isa, 0, listed);
        listed = 0;
    };
    detail::RunPieces pieces(runs, begin, end);
    std::size_t runFirst, first, count;
    while (pieces.next(runFirst, first, count)) {
        for (std::size_t i = 0; i < count; ++i) {
            list[listed++] = static_cast<std::uint32_t>(first + i);
            if (listed == std::size(list)) flush();
        }
    }
    if (listed > 0) flush();
}

/// Positions [begin, end) of the job's run sequence.
void runRuns(const SkinningJob& job, Isa isa, std::size_t begin, std::size_t end) noexcept {
#ifdef M3G_SKIN_X86
    if (isa == Isa::Avx512 && detail::skinRunsAvx512(job, begin, end)) return;
    if ((isa == Isa::Avx2 || isa == Isa::Avx512) && detail::skinRunsAvx2(job, begin, end)) return;
    if (isa == Isa::Sse2 && detail::skinRunsSse2(job, begin, end)) return;
#endif
    runsAsLists(job, job.runs, isa, begin, end);
}

/// Positions [begin, end) of the job's bone-run sequence.
void runBoneRuns(const SkinningJob& job, Isa isa, std::size_t begin, std::size_t end) noexcept {
#ifdef M3G_SKIN_X86
    if (isa == Isa::Avx512 && detail::skinBoneRunsAvx512(job, begin, end)) return;
    if ((isa == Isa::Avx2 || isa == Isa::Avx512) && detail::skinBoneRunsAvx2(job, begin, end)) return;
#endif
    runsAsLists(job, job.boneRuns, isa, begin, end);
}

}  // namespace

bool SkinningJob::validate() const noexcept {
    std::size_t runVertices, boneRunVertices;
    return check(*this, &runVertices, &boneRunVertices);
}

bool SkinningJob::run() const noexcept {
    std::size_t runVertices, boneRunVertices;
    if (!check(*this, &runVertices, &boneRunVertices)) return false;
    const Isa resolved = resolveIsa(isa);
    if (!vertices.empty()) runRange(*this, resolved, 0, vertices.size());
    if (runVertices > 0) runRuns(*this, resolved, 0, runVertices);
    if (boneRunVertices > 0) runBoneRuns(*this, resolved, 0, boneRunVertices);
    return true;
}

bool SkinningJob::runParallel(ThreadPool& pool, std::size_t grain) const noexcept {
    std::size_t runVertices, boneRunVertices;
    if (!check(*this, &runVertices, &boneRunVertices)) return false;
    if (grain == 0) grain = 1;
    // Chunks of the list, then of the runs, then of the bone runs: a chunk
    // never mixes two of them.
    struct Context {
        const SkinningJob* job;
        Isa isa;
        std::size_t grain;
        std::size_t total[3];   // list, runs, bone runs
        std::size_t chunks[3];  // chunks of each
    } context{this, resolveIsa(isa), grain, {vertices.size(), runVertices, boneRunVertices}, {}};
    std::size_t chunks = 0;
    for (int part = 0; part < 3; ++part) {
        context.chunks[part] = (context.total[part] + grain - 1) / grain;
        chunks += context.chunks[part];
    }
    pool.run(
        chunks,
        [](void* c, std::size_t chunk) {
            const auto& ctx = *static_cast<const Context*>(c);
            int part = 0;
            while (chunk >= ctx.chunks[part]) chunk -= ctx.chunks[part++];
            const std::size_t begin = chunk * ctx.grain;
            const std::size_t end = std::min(begin + ctx.grain, ctx.total[part]);
            if (part == 0)
                runRange(*ctx.job, ctx.isa, begin, end);
            else if (part == 1)
                runRuns(*ctx.job, ctx.isa, begin, end);
            else
                runBoneRuns(*ctx.job, ctx.isa, begin, end);
        },
        &context);
    return true;
}

void InfluencePartition::build(std::span<const std::int32_t> boneIndices, int stride, std::size_t vertexCount) {
    build(boneIndices, {}, stride, vertexCount);
}

void InfluencePartition::build(std::span<const std::int32_t> boneIndices, std::span<const float> boneWeights,
                               int stride, std::size_t vertexCount, std::size_t minRun, std::size_t runBlock) {
    minRun = std::max(minRun, kMinRun);
    const int n = stride < 0 ? 0 : stride;
    const auto ns = static_cast<std::size_t>(n);
    const std::size_t tableVertices = ns == 0 ? 0 : boneIndices.size() / ns;
    auto countOf = [&](std::size_t v) {
        if (v >= tableVertices) return 0;
        int c = 0;
        while (c < n && boneIndices[v * ns + static_cast<std::size_t>(c)] >= 0) ++c;
        return c;
    };
    offsets_.assign(ns + 2, 0);
    for (std::size_t v = 0; v < vertexCount; ++v) ++offsets_[static_cast<std::size_t>(countOf(v)) + 1];
    for (std::size_t c = 1; c < offsets_.size(); ++c) offsets_[c] += offsets_[c - 1];
    vertices_.resize(vertexCount);
    // Counting sort: a cursor per group, vertices visited in ascending order.
    std::vector<std::size_t>& cursor = cursor_;
    cursor.assign(offsets_.begin(), offsets_.end() - 1);
    for (std::size_t v = 0; v < vertexCount; ++v)
        vertices_[cursor[static_cast<std::size_t>(countOf(v))]++] = static_cast<std::uint32_t>(v);

    // Runs: consecutive vertices of a group whose used slots (bones and
    // weight bit patterns) equal those of the run's first vertex.
    const bool weights = boneWeights.size() >= tableVertices * ns && tableVertices > 0;
    loose_.clear();
    runs_.clear();
    looseOffsets_.assign(offsets_.size(), 0);
    runOffsets_.assign(offsets_.size(), 0);
    for (std::size_t c = 0; c + 1 < offsets_.size(); ++c) {
        const std::uint32_t* g = vertices_.data() + offsets_[c];
        const std::size_t size = offsets_[c + 1] - offsets_[c];
        std::uint32_t start = 0;
        auto same = [&](std::size_t a, std::size_t b) {
            return std::memcmp(&boneIndices[a * ns], &boneIndices[b * ns], c * sizeof(std::int32_t)) == 0 &&
                   std::memcmp(&boneWeights[a * ns], &boneWeights[b * ns], c * sizeof(float)) == 0;
        };
        for (std::size_t i = 0; i < size;) {
            std::size_t e = i + 1;
            if (weights && c > 0)
                while (e < size && g[e] == g[e - 1] + 1 && same(g[i], g[e])) ++e;
            if (e - i >= minRun) {
                runs_.push_back({g[i], static_cast<std::uint32_t>(e - i), start});
                start += static_cast<std::uint32_t>(e - i);
            } else {
                loose_.insert(loose_.end(), g + i, g + e);
            }
            i = e;
        }
        looseOffsets_[c + 1] = loose_.size();
        runOffsets_[c + 1] = runs_.size();
    }
    buildCompact(boneIndices, boneWeights, weights, runBlock);
}

void InfluencePartition::buildForKernels(const InfluenceTable& table, std::size_t vertexCount, Isa isa) {
    build(table.bones(), table.weights(), table.maxInfluences(), vertexCount, kNoInPlaceRuns, runBlock(isa));
}

std::size_t InfluencePartition::runBlock(Isa isa) noexcept {
    switch (resolveIsa(isa)) {
        case Isa::Avx512: return 16;
        case Isa::Avx2: return 8;
        default: return 0;
    }
}

void InfluencePartition::buildCompact(std::span<const std::int32_t> boneIndices, std::span<const float> boneWeights,
                                      bool weights, std::size_t runBlock) {
    const std::size_t ns = offsets_.size() - 2;
    compactOrder_.clear();
    compactBones_.clear();
    compactWeights_.clear();
    compactRuns_.clear();
    compactBoneRuns_.clear();
    compactLoose_.clear();
    compactRunOffsets_.assign(offsets_.size(), 0);
    compactBoneRunOffsets_.assign(offsets_.size(), 0);
    compactLooseOffsets_.assign(offsets_.size(), 0);
    std::vector<std::uint32_t>& sorted = cursorScratch_;
    for (std::size_t c = 1; c + 1 < offsets_.size(); ++c) {
        compactRunOffsets_[c] = compactRuns_.size();
        compactBoneRunOffsets_[c] = compactBoneRuns_.size();
        compactLooseOffsets_[c] = compactLoose_.size();
        if (!weights) continue;
        const std::span<const std::uint32_t> group = loose(static_cast<int>(c));
        // The used slots compared as they are in the table (bones, then
        // weight bit patterns, then the vertex: a total order, so the
        // compact space does not depend on the sort's implementation).
        auto slots = [&](std::uint32_t v, std::size_t k, bool weight) {
            if (!weight) return static_cast<std::uint32_t>(boneIndices[v * ns + k]);
            std::uint32_t bits;
            std::memcpy(&bits, &boneWeights[v * ns + k], sizeof bits);
            return bits;
        };
        sorted.assign(group.begin(), group.end());
        std::sort(sorted.begin(), sorted.end(), [&](std::uint32_t a, std::uint32_t b) {
            for (int weight = 0; weight < 2; ++weight)
                for (std::size_t k = 0; k < c; ++k) {
                    const std::uint32_t x = slots(a, k, weight != 0), y = slots(b, k, weight != 0);
                    if (x != y) return x < y;
                }
            return a < b;
        });
        auto sameBones = [&](std::uint32_t a, std::uint32_t b) {
            return std::memcmp(&boneIndices[a * ns], &boneIndices[b * ns], c * sizeof(std::int32_t)) == 0;
        };
        auto same = [&](std::uint32_t a, std::uint32_t b) {
            return sameBones(a, b) &&
                   std::memcmp(&boneWeights[a * ns], &boneWeights[b * ns], c * sizeof(float)) == 0;
        };
        auto append = [&](std::uint32_t v) {
            compactOrder_.push_back(v);
            compactBones_.insert(compactBones_.end(), boneIndices.begin() + static_cast<std::ptrdiff_t>(v * ns),
                                 boneIndices.begin() + static_cast<std::ptrdiff_t>(v * ns + ns));
            compactWeights_.insert(compactWeights_.end(), boneWeights.begin() + static_cast<std::ptrdiff_t>(v * ns),
                                   boneWeights.begin() + static_cast<std::ptrdiff_t>(v * ns + ns));
            return static_cast<std::uint32_t>(compactOrder_.size() - 1);
        };
        // One set of bones at a time: equal slots are neighbours; runs of
        // kMinRun or more are runs (of runBlock or more, or the whole set:
        // a shorter one goes with the set's other vertices); the set's
        // other vertices form a bone run when there are kMinRun or more,
        // else they are loose. The group's
        // runs are laid out first, then its bone runs, then its loose
        // vertices, so that each kind is consecutive in the compact arrays
        // (the list kernel, which takes bone runs on CPUs without a bone-run
        // kernel, stores whole blocks of consecutive vertices at once).
        std::vector<std::uint32_t>& runVertices = runScratch_;
        std::vector<std::uint32_t>& boneRunVertices = boneRunScratch_;
        std::vector<std::uint32_t>& looseVertices = looseScratch_;
        std::vector<std::uint32_t>& runLengths = runLengthScratch_;
        std::vector<std::uint32_t>& boneRunLengths = boneRunLengthScratch_;
        runVertices.clear();
        boneRunVertices.clear();
        looseVertices.clear();
        runLengths.clear();
        boneRunLengths.clear();
        for (std::size_t i = 0; i < sorted.size();) {
            std::size_t setEnd = i + 1;
            while (setEnd < sorted.size() && sameBones(sorted[i], sorted[setEnd])) ++setEnd;
            const std::size_t setLooseFrom = looseVertices.size();
            for (std::size_t q = i; q < setEnd;) {
                std::size_t e = q + 1;
                while (e < setEnd && same(sorted[q], sorted[e])) ++e;
                auto from = sorted.begin() + static_cast<std::ptrdiff_t>(q);
                auto to = sorted.begin() + static_cast<std::ptrdiff_t>(e);
                const std::size_t length = e - q;
                if (length >= kMinRun && (length >= runBlock || length == setEnd - i)) {
                    runVertices.insert(runVertices.end(), from, to);
                    runLengths.push_back(static_cast<std::uint32_t>(length));
                } else {
                    looseVertices.insert(looseVertices.end(), from, to);
                }
                q = e;
            }
            const std::size_t setLoose = looseVertices.size() - setLooseFrom;
            if (setLoose >= kMinRun) {
                auto from = looseVertices.begin() + static_cast<std::ptrdiff_t>(setLooseFrom);
                boneRunVertices.insert(boneRunVertices.end(), from, looseVertices.end());
                boneRunLengths.push_back(static_cast<std::uint32_t>(setLoose));
                looseVertices.erase(from, looseVertices.end());
            }
            i = setEnd;
        }
        auto appendRuns = [&](const std::vector<std::uint32_t>& vertices, const std::vector<std::uint32_t>& lengths,
                              std::vector<InfluenceRun>& out) {
            std::size_t at = 0;
            std::uint32_t start = 0;
            for (std::uint32_t length : lengths) {
                const std::uint32_t first = append(vertices[at]);
                for (std::size_t r = 1; r < length; ++r) append(vertices[at + r]);
                out.push_back({first, length, start});
                start += length;
                at += length;
            }
        };
        appendRuns(runVertices, runLengths, compactRuns_);
        appendRuns(boneRunVertices, boneRunLengths, compactBoneRuns_);
        for (std::uint32_t v : looseVertices) compactLoose_.push_back(append(v));
    }
    compactRunOffsets_.back() = compactRuns_.size();
    compactBoneRunOffsets_.back() = compactBoneRuns_.size();
    compactLooseOffsets_.back() = compactLoose_.size();
}

std::span<const InfluenceRun> InfluencePartition::compactRuns(int count) const noexcept {
    if (count < 0 || static_cast<std::size_t>(count) + 1 >= compactRunOffsets_.size()) return {};
    const auto c = static_cast<std::size_t>(count);
    return std::span<const InfluenceRun>(compactRuns_)
        .subspan(compactRunOffsets_[c], compactRunOffsets_[c + 1] - compactRunOffsets_[c]);
}

std::span<const InfluenceRun> InfluencePartition::compactBoneRuns(int count) const noexcept {
    if (count < 0 || static_cast<std::size_t>(count) + 1 >= compactBoneRunOffsets_.size()) return {};
    const auto c = static_cast<std::size_t>(count);
    return std::span<const InfluenceRun>(compactBoneRuns_)
        .subspan(compactBoneRunOffsets_[c], compactBoneRunOffsets_[c + 1] - compactBoneRunOffsets_[c]);
}

std::span<const std::uint32_t> InfluencePartition::compactLoose(int count) const noexcept {
    if (count < 0 || static_cast<std::size_t>(count) + 1 >= compactLooseOffsets_.size()) return {};
    const auto c = static_cast<std::size_t>(count);
    return std::span<const std::uint32_t>(compactLoose_)
        .subspan(compactLooseOffsets_[c], compactLooseOffsets_[c + 1] - compactLooseOffsets_[c]);
}

std::span<const std::uint32_t> InfluencePartition::group(int count) const noexcept {
    if (count < 0 || static_cast<std::size_t>(count) + 1 >= offsets_.size()) return {};
    const auto c = static_cast<std::size_t>(count);
    return std::span<const std::uint32_t>(vertices_).subspan(offsets_[c], offsets_[c + 1] - offsets_[c]);
}

std::span<const std::uint32_t> InfluencePartition::loose(int count) const noexcept {
    if (count < 0 || static_cast<std::size_t>(count) + 1 >= looseOffsets_.size()) return {};
    const auto c = static_cast<std::size_t>(count);
    return std::span<const std::uint32_t>(loose_).subspan(looseOffsets_[c], looseOffsets_[c + 1] - looseOffsets_[c]);
}

std::span<const InfluenceRun> InfluencePartition::runs(int count) const noexcept {
    if (count < 0 || static_cast<std::size_t>(count) + 1 >= runOffsets_.size()) return {};
    const auto c = static_cast<std::size_t>(count);
    return std::span<const InfluenceRun>(runs_).subspan(runOffsets_[c], runOffsets_[c + 1] - runOffsets_[c]);
}

// ---------------------------------------------------------------------------
// Scalar path: the formula, one vertex at a time.

namespace detail {

namespace {

/// One vertex by the formula. Slots whose bone index is outside the palette
/// (-1 = empty, or garbage) contribute nothing.
template <bool Normals>
inline void skinOne(const SkinningJob& j, std::size_t v, int count) noexcept {
    const float* ip = j.inPositions.data() + v * j.inPositionStride;
    float* op = j.outPositions.data() + v * j.outPositionStride;
    const float s = j.positionScale;
    const float px = s * ip[0] + j.positionBias[0], py = s * ip[1] + j.positionBias[1],
                pz = s * ip[2] + j.positionBias[2];
    const float* in = Normals ? j.inNormals.data() + v * j.inNormalStride : nullptr;
    float* on = Normals ? j.outNormals.data() + v * j.outNormalStride : nullptr;
    if (count == 0) {
        op[0] = px;
        op[1] = py;
        op[2] = pz;
        if constexpr (Normals) {
            float n[3] = {in[0], in[1], in[2]};
            normalize3(n);
            on[0] = n[0];
            on[1] = n[1];
            on[2] = n[2];
        }
        return;
    }
    const std::size_t base = v * static_cast<std::size_t>(j.influenceStride);
    const std::int32_t* bi = j.boneIndices.data() + base;
    const float* bw = j.boneWeights.data() + base;
    const std::size_t bones = j.palette.size();
    // Blend the matrices, then apply the blend once.
    float m[12] = {}, nm[12] = {};
    for (int k = 0; k < count; ++k) {
        const auto b = static_cast<std::uint32_t>(bi[k]);
        if (b >= bones) continue;
        const PaletteEntry& e = j.palette[b];
        const float w = bw[k];
        for (int r = 0; r < 12; ++r) m[r] += w * e.position[r];
        if constexpr (Normals)
            for (int r = 0; r < 12; ++r) nm[r] += w * e.normal[r];
    }
    for (int r = 0; r < 3; ++r) op[r] = m[r * 4] * px + m[r * 4 + 1] * py + m[r * 4 + 2] * pz + m[r * 4 + 3];
    if constexpr (Normals) {
        float n[3];
        for (int r = 0; r < 3; ++r) n[r] = nm[r * 4] * in[0] + nm[r * 4 + 1] * in[1] + nm[r * 4 + 2] * in[2];
        normalize3(n);
        on[0] = n[0];
        on[1] = n[1];
        on[2] = n[2];
    }
}

template <int K, bool Normals>
void skinScalarT(const SkinningJob& j, std::size_t begin, std::size_t end) noexcept {
    const int count = K >= 0 ? K : j.influenceCount;
    for (std::size_t i = begin; i < end; ++i) skinOne<Normals>(j, j.vertices[i], count);
}

}  // namespace

void skinVertexChecked(const SkinningJob& job, std::size_t v) noexcept {
    if (job.inNormals.empty())
        skinOne<false>(job, v, job.influenceCount);
    else
        skinOne<true>(job, v, job.influenceCount);
}

namespace {

template <bool Normals>
void skinScalarN(const SkinningJob& j, std::size_t begin, std::size_t end) noexcept {
    switch (j.influenceCount) {
        case 0: skinScalarT<0, Normals>(j, begin, end); return;
        case 1: skinScalarT<1, Normals>(j, begin, end); return;
        case 2: skinScalarT<2, Normals>(j, begin, end); return;
        case 3: skinScalarT<3, Normals>(j, begin, end); return;
        case 4: skinScalarT<4, Normals>(j, begin, end); return;
        default: skinScalarT<-1, Normals>(j, begin, end); return;
    }
}

}  // namespace

void skinScalar(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept {
    if (job.inNormals.empty())
        skinScalarN<false>(job, begin, end);
    else
        skinScalarN<true>(job, begin, end);
}

}  // namespace detail

}  // namespace m3g::skin

namespace m3g::skin {

void scatterXyz(std::span<const std::uint32_t> order, const float* in, float* out) noexcept {
    // Two moves a triple (8 + 4 bytes) rather than three.
    const std::uint32_t* o = order.data();
    const std::size_t n = order.size();
    for (std::size_t i = 0; i < n; ++i) {
        std::uint64_t xy;
        float z;
        std::memcpy(&xy, in + i * 3, sizeof xy);
        std::memcpy(&z, in + i * 3 + 2, sizeof z);
        float* d = out + std::size_t{o[i]} * 3;
        std::memcpy(d, &xy, sizeof xy);
        std::memcpy(d + 2, &z, sizeof z);
    }
}

void scatterXyz(std::span<const std::uint32_t> order, const float* in, float* out, const float* in2,
                float* out2) noexcept {
    const std::uint32_t* o = order.data();
    const std::size_t n = order.size();
    for (std::size_t i = 0; i < n; ++i) {
        std::uint64_t xy, xy2;
        float z, z2;
        std::memcpy(&xy, in + i * 3, sizeof xy);
        std::memcpy(&z, in + i * 3 + 2, sizeof z);
        std::memcpy(&xy2, in2 + i * 3, sizeof xy2);
        std::memcpy(&z2, in2 + i * 3 + 2, sizeof z2);
        const std::size_t d = std::size_t{o[i]} * 3;
        std::memcpy(out + d, &xy, sizeof xy);
        std::memcpy(out + d + 2, &z, sizeof z);
        std::memcpy(out2 + d, &xy2, sizeof xy2);
        std::memcpy(out2 + d + 2, &z2, sizeof z2);
    }
}

}  // namespace m3g::skin
