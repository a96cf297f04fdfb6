#include <m3g/skin/Skinning.h>

#include <algorithm>

#include <m3g/skin/ThreadPool.h>

#include "Kernels.h"

namespace m3g::skin {

namespace {

// A per-vertex array of `count` vertices at `stride` floats holds
// (count - 1) * stride + 3 floats at least.
bool holds(std::span<const float> a, std::size_t count, std::size_t stride) noexcept {
    return stride >= 3 && (count == 0 || (a.size() >= 3 && (a.size() - 3) / stride >= count - 1));
}

void runRange(const SkinningJob& job, Isa isa, std::size_t begin, std::size_t end) noexcept {
    switch (isa) {
#ifdef M3G_SKIN_X86
        case Isa::Sse2: detail::skinSse2(job, begin, end); return;
        case Isa::Avx2: detail::skinAvx2(job, begin, end); return;
#endif
        default: detail::skinScalar(job, begin, end); return;
    }
}

}  // namespace

bool SkinningJob::validate() const noexcept {
    if (influenceCount < 0 || influenceStride < influenceCount) return false;
    if (!isaSupported(isa)) return false;
    if (!holds(inPositions, vertexCount, inPositionStride)) return false;
    if (!holds(std::span<const float>(outPositions), vertexCount, outPositionStride)) return false;
    if (inNormals.empty() != outNormals.empty()) return false;
    if (!inNormals.empty() && (!holds(inNormals, vertexCount, inNormalStride) ||
                               !holds(std::span<const float>(outNormals), vertexCount, outNormalStride)))
        return false;
    if (vertices.empty()) return true;
    // Every listed vertex must be below `limit`: the vertex count, and the
    // number of vertices the influence arrays reach. One pass, branch-free.
    std::size_t limit = vertexCount;
    if (influenceCount > 0) {
        const auto stride = static_cast<std::size_t>(influenceStride);
        const auto count = static_cast<std::size_t>(influenceCount);
        const std::size_t size = std::min(boneIndices.size(), boneWeights.size());
        limit = size < count ? 0 : std::min(limit, (size - count) / stride + 1);
    }
    const std::uint64_t bound = limit;
    const std::uint32_t* v = vertices.data();
    const std::size_t n = vertices.size();
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

bool SkinningJob::run() const noexcept {
    if (!validate()) return false;
    runRange(*this, resolveIsa(isa), 0, vertices.size());
    return true;
}

bool SkinningJob::runParallel(ThreadPool& pool, std::size_t grain) const noexcept {
    if (!validate()) return false;
    if (grain == 0) grain = 1;
    struct Context {
        const SkinningJob* job;
        Isa isa;
        std::size_t grain;
        std::size_t total;
    } context{this, resolveIsa(isa), grain, vertices.size()};
    const std::size_t chunks = (vertices.size() + grain - 1) / grain;
    pool.run(
        chunks,
        [](void* c, std::size_t chunk) {
            const auto& ctx = *static_cast<const Context*>(c);
            const std::size_t begin = chunk * ctx.grain;
            const std::size_t end = begin + ctx.grain < ctx.total ? begin + ctx.grain : ctx.total;
            runRange(*ctx.job, ctx.isa, begin, end);
        },
        &context);
    return true;
}

void InfluencePartition::build(std::span<const std::int32_t> boneIndices, int stride, std::size_t vertexCount) {
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
}

std::span<const std::uint32_t> InfluencePartition::group(int count) const noexcept {
    if (count < 0 || static_cast<std::size_t>(count) + 1 >= offsets_.size()) return {};
    const auto c = static_cast<std::size_t>(count);
    return std::span<const std::uint32_t>(vertices_).subspan(offsets_[c], offsets_[c + 1] - offsets_[c]);
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
