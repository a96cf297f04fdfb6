// Random skinned meshes for the skinning tests (test_SkinningJob.cpp,
// test_SkinningRuns.cpp): addTransform records in a real InfluenceTable,
// random affine bones, and helpers that run every influence group of a
// mesh through SkinningJob, as vertex lists or as shared-influence runs.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <random>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include <m3g/skin/InfluenceTable.h>
#include <m3g/skin/Palette.h>
#include <m3g/skin/Skinning.h>
#include <m3g/skin/ThreadPool.h>

#include "SkinReference.h"

namespace m3gtest {

using namespace m3g::skin;


struct RandomMesh {
    int n = 4;
    std::size_t vertices = 0;
    std::vector<m3gtest::WeightedTransform> records;
    InfluenceTable table{4};
    std::vector<float> boneToMesh, atRest;  // 16 per bone
    std::vector<float> raw, normals;        // kernel inputs
    float scale = 0.75f;
    std::array<float, 3> bias{0.5f, -1.0f, 2.0f};

    /// recordCount random addTransform records; or, with runLength > 0,
    /// records in runs the way exporters write skins: every run of
    /// runLength vertices gets `recordCount` distinct bones (1..4) with
    /// random weights, so neighbours share their influences.
    RandomMesh(std::uint32_t seed, std::size_t vertexCount, int bones, int recordCount, int runLength = 0)
        : vertices(vertexCount) {
        std::mt19937 rng(seed);
        std::uniform_int_distribution<int> bone(0, bones - 1), weight(1, 6), len(1, 40);
        std::uniform_int_distribution<int> first(0, static_cast<int>(vertexCount) - 1);
        if (runLength > 0) {
            std::vector<int> pool(static_cast<std::size_t>(bones));
            std::iota(pool.begin(), pool.end(), 0);
            for (int f = 0; f < static_cast<int>(vertexCount); f += runLength) {
                const int c = std::min(runLength, static_cast<int>(vertexCount) - f);
                std::shuffle(pool.begin(), pool.end(), rng);
                for (int k = 0; k < recordCount; ++k) {
                    records.push_back({pool[static_cast<std::size_t>(k)], weight(rng), f, c});
                    table.add(records.back().bone, records.back().weight, f, c);
                }
            }
        }
        for (int i = 0; runLength == 0 && i < recordCount; ++i) {
            const int f = first(rng);
            const int c = std::min(len(rng), static_cast<int>(vertexCount) - f);
            records.push_back({bone(rng), weight(rng), f, c});
            table.add(records.back().bone, records.back().weight, f, c);
        }
        for (int b = 0; b < bones; ++b) {
            const auto a = m3gtest::randomAffine(rng), r = m3gtest::randomAffine(rng);
            boneToMesh.insert(boneToMesh.end(), a.begin(), a.end());
            atRest.insert(atRest.end(), r.begin(), r.end());
        }
        std::uniform_real_distribution<float> u(-10.0f, 10.0f);
        for (std::size_t i = 0; i < vertexCount * 3; ++i) raw.push_back(u(rng));
        for (std::size_t v = 0; v < vertexCount; ++v) {
            float x = u(rng), y = u(rng), z = u(rng);
            if (v % 97 == 0) x = y = z = 0.0f;  // some zero normals
            normals.insert(normals.end(), {x, y, z});
        }
    }
    std::vector<double> meshSpace() const {
        std::vector<double> p(raw.size());
        for (std::size_t i = 0; i < raw.size(); ++i) p[i] = double(scale) * raw[i] + bias[i % 3];
        return p;
    }
};

/// A job skinning `vertices` of `m` (all with `influences` influences) into pos/nrm.
inline SkinningJob meshJob(const RandomMesh& m, std::span<const std::uint32_t> vertices, int influences,
                    const std::vector<PaletteEntry>& pal, Isa isa, std::vector<float>& pos, std::vector<float>& nrm) {
    SkinningJob job;
    job.vertices = vertices;
    job.vertexCount = m.vertices;
    job.influenceCount = influences;
    job.influenceStride = m.n;
    job.boneIndices = m.table.bones();
    job.boneWeights = m.table.weights();
    job.palette = pal;
    job.positionScale = m.scale;
    job.positionBias = m.bias;
    job.inPositions = m.raw;
    job.inNormals = m.normals;
    job.outPositions = pos;
    job.outNormals = nrm;
    job.isa = isa;
    return job;
}

/// Runs every group of the partition with `isa`; parallel on `pool` if
/// given. With `runs`, each group as its shared-influence runs plus its
/// loose vertices (what the renderer does); otherwise as one vertex list.
inline void skinAll(const RandomMesh& m, const std::vector<PaletteEntry>& pal, Isa isa, std::vector<float>& pos,
                    std::vector<float>& nrm, ThreadPool* pool = nullptr, std::size_t grain = 4096,
                    bool runs = false) {
    InfluencePartition part;
    part.build(m.table.bones(), m.table.weights(), m.n, m.vertices);
    pos.assign(m.vertices * 3, -999.0f);
    nrm.assign(m.vertices * 3, -999.0f);
    for (int c = 0; c <= part.maxInfluences(); ++c) {
        SkinningJob job = meshJob(m, runs ? part.loose(c) : part.group(c), c, pal, isa, pos, nrm);
        if (runs) job.runs = part.runs(c);
        ASSERT_TRUE(pool ? job.runParallel(*pool, grain) : job.run()) << "group " << c;
    }
}

/// The palette of bones given as bone -> mesh matrices (row-major 4x4),
/// at rest the identity.
inline std::vector<PaletteEntry> paletteAtRestIdentity(const std::vector<std::array<float, 16>>& boneToMesh) {
    std::vector<float> a, r;
    const std::array<float, 16> id{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    for (const auto& m : boneToMesh) {
        a.insert(a.end(), m.begin(), m.end());
        r.insert(r.end(), id.begin(), id.end());
    }
    std::vector<PaletteEntry> out(boneToMesh.size());
    PaletteJob job;
    job.boneCount = out.size();
    job.boneToMesh = a;
    job.atRest = r;
    job.output = out;
    EXPECT_TRUE(job.run());
    return out;
}

/// A job over listed `vertices` and `runs` of `n` vertices in packed
/// arrays (stride 3), `influences` used slots of `stride`.
inline SkinningJob arraysJob(std::span<const std::uint32_t> vertices, std::span<const InfluenceRun> runs,
                             std::size_t n, int influences, int stride, const std::vector<std::int32_t>& bones,
                             const std::vector<float>& weights, const std::vector<PaletteEntry>& pal,
                             const std::vector<float>& in, const std::vector<float>& nin, std::vector<float>& out,
                             std::vector<float>& nout, Isa isa) {
    SkinningJob job;
    job.vertices = vertices;
    job.runs = runs;
    job.vertexCount = n;
    job.influenceCount = influences;
    job.influenceStride = stride;
    job.boneIndices = bones;
    job.boneWeights = weights;
    job.palette = pal;
    job.inPositions = in;
    job.inNormals = nin;
    job.outPositions = out;
    job.outNormals = nout;
    job.isa = isa;
    return job;
}

inline std::vector<PaletteEntry> paletteOf(const RandomMesh& m) {
    std::vector<PaletteEntry> pal(m.boneToMesh.size() / 16);
    PaletteJob job;
    job.boneCount = pal.size();
    job.boneToMesh = m.boneToMesh;
    job.atRest = m.atRest;
    job.output = pal;
    EXPECT_TRUE(job.run());
    return pal;
}

}  // namespace m3gtest
