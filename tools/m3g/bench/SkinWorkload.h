// Synthetic skinning and morphing workloads shared by tests/bench/bench_skin.cpp
// and `m3g bench skin` (tools/m3g/cmd_bench.cpp): plain arrays, no M3G objects
// (the large sizes exceed M3G's 65535 vertices per VertexArray).
//
// A skinned mesh is made the way an exporter writes M3G skins: vertices in
// runs of `runLength` consecutive vertices that share the same bones and
// weights, one addTransform record per (run, bone). Every vertex has exactly
// `influences` distinct bones with random integer weights 1..100.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <span>
#include <vector>

#include <m3g/skin/Morph.h>
#include <m3g/skin/Palette.h>
#include <m3g/skin/Skinning.h>
#include <m3g/skin/ThreadPool.h>

#include "SkinBaseline.h"
#include "SkinStreamRoof.h"

namespace m3gbench {

/// Kernel variants measured. Baseline = the paper's description of Nokia's
/// engine (SkinBaseline); the others are this library's palette + kernel.
enum class Variant { Baseline, Scalar, Sse2, Avx2, Parallel, Avx512 };

inline const char* variantName(Variant v) {
    switch (v) {
        case Variant::Baseline: return "baseline";
        case Variant::Scalar: return "scalar";
        case Variant::Sse2: return "sse2";
        case Variant::Avx2: return "avx2";
        case Variant::Parallel: return "avx2+mt";
        case Variant::Avx512: return "avx512";
    }
    return "?";
}

/// The kernels a variant runs (Parallel: the AVX2 ones on the pool).
inline m3g::skin::Isa isaOf(Variant v) {
    switch (v) {
        case Variant::Scalar: return m3g::skin::Isa::Scalar;
        case Variant::Sse2: return m3g::skin::Isa::Sse2;
        case Variant::Avx512: return m3g::skin::Isa::Avx512;
        default: return m3g::skin::Isa::Avx2;
    }
}

inline std::array<float, 16> benchAffine(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const float ax = u(rng), ay = u(rng), az = u(rng) + 0.01f;
    const float l = std::sqrt(ax * ax + ay * ay + az * az);
    const float x = ax / l, y = ay / l, z = az / l, a = 3.14159265f * u(rng);
    const float c = std::cos(a), s = std::sin(a), t = 1 - c;
    return {t * x * x + c,     t * x * y - s * z, t * x * z + s * y, u(rng),
            t * x * y + s * z, t * y * y + c,     t * y * z - s * x, u(rng),
            t * x * z - s * y, t * y * z + s * x, t * z * z + c,     u(rng),
            0,                 0,                 0,                 1};
}

struct SkinWorkload {
    static constexpr int kMaxInfluences = 4;  // N, the table stride
    std::size_t vertices = 0;
    int influences = 0;
    int bones = 0;
    int runLength = 0;
    std::vector<float> positions, normals;       // mesh space, xyz per vertex
    std::vector<std::int32_t> boneIndices;       // N per vertex, sorted by weight
    std::vector<float> boneWeights;              // N per vertex, normalised
    std::vector<WeightedTransform> records;      // the addTransform calls
    std::vector<float> boneToMesh, atRest;       // 16 per bone
    std::vector<std::uint32_t> all;              // 0 .. vertices - 1
    // Built once, as SkinnedMesh::addTransform's table is: the vertices of
    // `influences` slots split into shared-influence runs and loose ones.
    m3g::skin::InfluencePartition partition;
    // Per-frame outputs and scratch (allocated once).
    std::vector<m3g::skin::PaletteEntry> palette;
    std::vector<float> outPositions, outNormals;
    SkinBaseline baseline{kMaxInfluences};

    SkinWorkload(std::size_t vertexCount, int influenceCount, int boneCount, int run = 16, std::uint32_t seed = 1)
        : vertices(vertexCount), influences(influenceCount), bones(boneCount), runLength(run) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> u(-1.0f, 1.0f);
        positions.resize(vertices * 3);
        normals.resize(vertices * 3);
        for (auto& p : positions) p = u(rng);
        for (std::size_t v = 0; v < vertices; ++v) {
            float* n = &normals[v * 3];
            n[0] = u(rng), n[1] = u(rng), n[2] = u(rng) + 0.01f;
            const float l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (int c = 0; c < 3; ++c) n[c] /= l;
        }
        boneIndices.assign(vertices * kMaxInfluences, -1);
        boneWeights.assign(vertices * kMaxInfluences, 0.0f);
        std::vector<int> pool(static_cast<std::size_t>(bones));
        std::iota(pool.begin(), pool.end(), 0);
        std::uniform_int_distribution<int> weight(1, 100);
        for (std::size_t first = 0; first < vertices; first += static_cast<std::size_t>(runLength)) {
            const int count = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(runLength), vertices - first));
            std::shuffle(pool.begin(), pool.end(), rng);
            std::vector<std::pair<int, int>> infl;  // (weight, bone)
            for (int k = 0; k < influences; ++k) {
                infl.push_back({weight(rng), pool[static_cast<std::size_t>(k)]});
                records.push_back({pool[static_cast<std::size_t>(k)], infl.back().first, static_cast<int>(first), count});
            }
            // InfluenceTable's order: larger weight first, ties to the lower bone.
            std::sort(infl.begin(), infl.end(),
                      [](auto& a, auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
            int sum = 0;
            for (auto& [w, b] : infl) sum += w;
            for (std::size_t v = first; v < first + static_cast<std::size_t>(count); ++v)
                for (int k = 0; k < influences; ++k) {
                    boneIndices[v * kMaxInfluences + k] = infl[static_cast<std::size_t>(k)].second;
                    boneWeights[v * kMaxInfluences + k] =
                        static_cast<float>(static_cast<double>(infl[static_cast<std::size_t>(k)].first) / sum);
                }
        }
        for (int b = 0; b < bones; ++b) {
            const auto a = benchAffine(rng), r = benchAffine(rng);
            boneToMesh.insert(boneToMesh.end(), a.begin(), a.end());
            atRest.insert(atRest.end(), r.begin(), r.end());
        }
        all.resize(vertices);
        std::iota(all.begin(), all.end(), 0u);
        partition.build(boneIndices, boneWeights, kMaxInfluences, vertices);
        palette.resize(static_cast<std::size_t>(bones));
        outPositions.resize(vertices * 3);
        outNormals.resize(vertices * 3);
    }

    /// The memory-bandwidth reference over this workload's arrays (meant for
    /// influences == kMaxInfluences, whose bytes it moves); without `tables`,
    /// the bytes of a vertex in a shared-influence run.
    SkinStreamRoof streamRoof(bool tables = true) {
        SkinStreamRoof r;
        r.tables = tables;
        r.vertices = all;
        r.positions = positions;
        r.normals = normals;
        r.boneIndices = boneIndices;
        r.boneWeights = boneWeights;
        r.outPositions = outPositions;
        r.outNormals = outNormals;
        return r;
    }

    /// One frame's deformation with `variant`: what a renderer pays per frame
    /// (the palette or PT/NT per bone, then every vertex). False if the
    /// variant cannot run on this CPU.
    bool frame(Variant variant, m3g::skin::ThreadPool* pool = nullptr) {
        if (variant == Variant::Baseline) {
            baseline.deform(records, static_cast<std::size_t>(bones), boneToMesh, atRest, vertices, positions, normals,
                            outPositions, outNormals);
            return true;
        }
        m3g::skin::PaletteJob pj;
        pj.boneCount = static_cast<std::size_t>(bones);
        pj.boneToMesh = boneToMesh;
        pj.atRest = atRest;
        pj.output = palette;
        if (!pj.run()) return false;
        m3g::skin::SkinningJob job;
        job.vertices = partition.loose(influences);
        job.runs = partition.runs(influences);
        job.vertexCount = vertices;
        job.influenceCount = influences;
        job.influenceStride = kMaxInfluences;
        job.boneIndices = boneIndices;
        job.boneWeights = boneWeights;
        job.palette = palette;
        job.inPositions = positions;
        job.inNormals = normals;
        job.outPositions = outPositions;
        job.outNormals = outNormals;
        job.isa = isaOf(variant);
        if (!m3g::skin::isaSupported(job.isa)) return false;
        if (variant == Variant::Parallel) return job.runParallel(pool ? *pool : m3g::skin::ThreadPool::shared());
        return job.run();
    }
};

/// Morphing: positions and normals (renormalised) of `vertices` vertices
/// with `targets` targets, all weights non-zero.
struct MorphWorkload {
    std::size_t vertices = 0;
    std::vector<float> basePositions, baseNormals, outPositions, outNormals, weights;
    std::vector<std::vector<float>> targetPositions, targetNormals;
    std::vector<std::span<const float>> positionSpans, normalSpans;

    MorphWorkload(std::size_t vertexCount, int targets, std::uint32_t seed = 1) : vertices(vertexCount) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> u(-1.0f, 1.0f);
        auto fill = [&](std::vector<float>& v) {
            v.resize(vertices * 3);
            for (auto& x : v) x = u(rng);
        };
        fill(basePositions);
        fill(baseNormals);
        targetPositions.resize(static_cast<std::size_t>(targets));
        targetNormals.resize(static_cast<std::size_t>(targets));
        for (int t = 0; t < targets; ++t) {
            fill(targetPositions[static_cast<std::size_t>(t)]);
            fill(targetNormals[static_cast<std::size_t>(t)]);
            positionSpans.emplace_back(targetPositions[static_cast<std::size_t>(t)]);
            normalSpans.emplace_back(targetNormals[static_cast<std::size_t>(t)]);
            weights.push_back(0.1f + 0.2f * static_cast<float>(t));
        }
        outPositions.resize(vertices * 3);
        outNormals.resize(vertices * 3);
    }

    /// Baseline: the plain loop the reference MeshDeformer used (out = B,
    /// then one pass over the array per target), then renormalisation.
    void naive() {
        outPositions = basePositions;
        outNormals = baseNormals;
        for (std::size_t t = 0; t < weights.size(); ++t) {
            const float w = weights[t];
            for (std::size_t i = 0; i < outPositions.size(); ++i)
                outPositions[i] += w * (targetPositions[t][i] - basePositions[i]);
            for (std::size_t i = 0; i < outNormals.size(); ++i)
                outNormals[i] += w * (targetNormals[t][i] - baseNormals[i]);
        }
        for (std::size_t v = 0; v < vertices; ++v) {
            float* n = &outNormals[v * 3];
            const float l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            if (l > 0)
                for (int c = 0; c < 3; ++c) n[c] /= l;
        }
    }

    bool frame(Variant variant, m3g::skin::ThreadPool* pool = nullptr) {
        if (variant == Variant::Baseline) {
            naive();
            return true;
        }
        const m3g::skin::Isa isa = isaOf(variant);
        if (!m3g::skin::isaSupported(isa)) return false;
        m3g::skin::MorphJob p;
        p.base = basePositions;
        p.targets = positionSpans;
        p.weights = weights;
        p.output = outPositions;
        p.isa = isa;
        m3g::skin::MorphJob n = p;
        n.base = baseNormals;
        n.targets = normalSpans;
        n.output = outNormals;
        n.normalize = true;
        if (variant == Variant::Parallel) {
            m3g::skin::ThreadPool& tp = pool ? *pool : m3g::skin::ThreadPool::shared();
            return p.runParallel(tp) && n.runParallel(tp);
        }
        return p.run() && n.run();
    }
};

}  // namespace m3gbench
