// Shared-influence runs (skin::InfluenceRun): how InfluencePartition finds
// them, what SkinningJob::validate accepts, and that skinning a mesh as runs
// gives what the vertex-list path and the double reference give, on every
// ISA, at any stride, chunking and thread count (JSR-184 1.1, SkinnedMesh; the
// founding paper's bookkeeping done when addTransform is called).
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <numeric>
#include <string>
#include <vector>

#include <sys/mman.h>
#include <unistd.h>

#include "SkinRandomMesh.h"
#include "SkinReference.h"

using namespace m3g::skin;

namespace {

std::vector<std::uint32_t> as(std::span<const std::uint32_t> s) { return {s.begin(), s.end()}; }

struct RunList {
    std::vector<InfluenceRun> runs;
    bool operator==(const std::vector<InfluenceRun>& o) const {
        if (o.size() != runs.size()) return false;
        for (std::size_t i = 0; i < runs.size(); ++i)
            if (runs[i].firstVertex != o[i].firstVertex || runs[i].vertexCount != o[i].vertexCount ||
                runs[i].start != o[i].start)
                return false;
        return true;
    }
};
RunList runsOf(std::span<const InfluenceRun> s) { return {{s.begin(), s.end()}}; }

std::string describe(std::span<const InfluenceRun> s) {
    std::string out;
    for (const InfluenceRun& r : s)
        out += "{" + std::to_string(r.firstVertex) + "," + std::to_string(r.vertexCount) + "," +
               std::to_string(r.start) + "} ";
    return out;
}

}  // namespace

// A hand-built table, stride 2:
//   v0..v9    bone 0, weight 1            (1 influence)  -> one run of 10
//   v10..v12  bone 1, weight 1            (1 influence)  -> 3 vertices: loose
//   v13       no bone                                     -> group 0
//   v14..v18  bones 0, 1, weights .5 .5   (2 influences) -> run of 5
//   v19..v22  bones 0, 1, weights .25 .75                -> run of 4 (weights differ)
//   v23, v24  beyond the table                            -> group 0
TEST(InfluencePartition, SplitsGroupsIntoRunsOfSharedInfluencesAndLooseVertices) {
    std::vector<std::int32_t> bones;
    std::vector<float> weights;
    auto add = [&](int count, std::int32_t b0, std::int32_t b1, float w0, float w1) {
        for (int i = 0; i < count; ++i) {
            bones.insert(bones.end(), {b0, b1});
            weights.insert(weights.end(), {w0, w1});
        }
    };
    add(10, 0, -1, 1.0f, 0.0f);
    add(3, 1, -1, 1.0f, 0.0f);
    add(1, -1, -1, 0.0f, 0.0f);
    add(5, 0, 1, 0.5f, 0.5f);
    add(4, 0, 1, 0.25f, 0.75f);
    InfluencePartition p;
    p.build(bones, weights, 2, 25);
    EXPECT_EQ(as(p.group(0)), (std::vector<std::uint32_t>{13, 23, 24}));
    EXPECT_EQ(as(p.loose(0)), (std::vector<std::uint32_t>{13, 23, 24}));
    EXPECT_TRUE(p.runs(0).empty());
    std::vector<std::uint32_t> g1(13);
    std::iota(g1.begin(), g1.end(), 0u);
    EXPECT_EQ(as(p.group(1)), g1);
    EXPECT_EQ(as(p.loose(1)), (std::vector<std::uint32_t>{10, 11, 12}));
    EXPECT_TRUE(runsOf(p.runs(1)) == (std::vector<InfluenceRun>{{0, 10, 0}})) << describe(p.runs(1));
    EXPECT_TRUE(p.loose(2).empty());
    EXPECT_TRUE(runsOf(p.runs(2)) == (std::vector<InfluenceRun>{{14, 5, 0}, {19, 4, 5}})) << describe(p.runs(2));
    EXPECT_TRUE(p.runs(3).empty());
    EXPECT_TRUE(p.loose(-1).empty());

    // A run is broken by a gap in the group (v5 moved to group 2 with its
    // own bones): v0..v4 (5) and v6..v9 (4) are runs.
    bones[5 * 2 + 1] = 3;
    weights[5 * 2] = 0.5f;
    weights[5 * 2 + 1] = 0.5f;
    p.build(bones, weights, 2, 25);
    EXPECT_TRUE(runsOf(p.runs(1)) == (std::vector<InfluenceRun>{{0, 5, 0}, {6, 4, 5}})) << describe(p.runs(1));
    EXPECT_EQ(as(p.loose(2)), (std::vector<std::uint32_t>{5}));

    // Without weights: no runs, every vertex loose.
    p.build(bones, 2, 25);
    for (int c = 0; c <= 2; ++c) {
        EXPECT_TRUE(p.runs(c).empty()) << c;
        EXPECT_EQ(as(p.loose(c)), as(p.group(c))) << c;
    }
}

namespace {

/// A small valid job over `n` packed vertices, 1 influence of bone 0.
struct RunJob {
    std::vector<PaletteEntry> pal{PaletteEntry{{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}}};
    std::vector<std::int32_t> bones;
    std::vector<float> weights, in, nin, out, nout;
    std::vector<InfluenceRun> runs;
    SkinningJob job;
    explicit RunJob(std::size_t n)
        : bones(n, 0), weights(n, 1.0f), in(n * 3, 1.0f), nin(n * 3, 1.0f), out(n * 3), nout(n * 3),
          job(m3gtest::arraysJob({}, {}, n, 1, 1, bones, weights, pal, in, nin, out, nout, Isa::Auto)) {}
    bool validWith(std::vector<InfluenceRun> r) {
        runs = std::move(r);
        job.runs = runs;
        return job.validate();
    }
};

}  // namespace

TEST(SkinningJob, ValidateChecksRuns) {
    RunJob j(20);
    EXPECT_TRUE(j.validWith({}));
    EXPECT_TRUE(j.validWith({{0, 8, 0}, {8, 12, 8}}));
    EXPECT_TRUE(j.validWith({{0, 0, 0}, {3, 0, 0}, {0, 20, 0}}));  // empty runs share the next start
    EXPECT_FALSE(j.validWith({{0, 8, 1}})) << "start must be the sum of the counts before";
    EXPECT_FALSE(j.validWith({{0, 8, 0}, {8, 4, 7}}));
    EXPECT_FALSE(j.validWith({{13, 8, 0}})) << "past vertexCount";
    EXPECT_FALSE(j.validWith({{0xFFFFFFF0u, 0x20u, 0}})) << "first + count wraps";
    // Influence arrays shorter than the vertex arrays: runs must stay inside them.
    j.bones.resize(12);
    j.weights.resize(12);
    j.job.boneIndices = j.bones;
    j.job.boneWeights = j.weights;
    EXPECT_TRUE(j.validWith({{4, 8, 0}}));
    EXPECT_FALSE(j.validWith({{5, 8, 0}}));
    // No influence: only the vertex count bounds the runs.
    j.job.influenceCount = 0;
    EXPECT_TRUE(j.validWith({{5, 15, 0}}));
    EXPECT_FALSE(j.validWith({{5, 16, 0}}));
}

// Hand-computed: one run of 11 vertices (one full block and a 3-vertex
// tail) with bone 0 = translation (1, 2, 3) at weight 0.25 and bone 1 =
// rotation z 90 degrees at 0.75, scale 2 and bias (0, 0, 1):
// p = (x, 0, 0) -> s*p + b = (2x, 0, 1); translated (2x+1, 2, 4); rotated
// (0, 2x, 1); blend: (0.25 (2x+1), 0.5 + 1.5x, 1.75).
// Normal (1, 0, 0) -> 0.25 (1, 0, 0) + 0.75 (0, 1, 0), renormalised.
TEST(SkinningJob, RunOfTwoInfluencesHandComputedOnEveryPath) {
    const std::size_t n = 11;
    const std::vector<PaletteEntry> pal = m3gtest::paletteAtRestIdentity({{1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1},
                                                                         {0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}});
    std::vector<std::int32_t> bones;
    std::vector<float> weights;
    std::vector<float> in, nin;
    for (std::size_t v = 0; v < n; ++v) {
        bones.insert(bones.end(), {1, 0, -1, -1});
        weights.insert(weights.end(), {0.75f, 0.25f, 0.0f, 0.0f});
        in.insert(in.end(), {static_cast<float>(v), 0.0f, 0.0f});
        nin.insert(nin.end(), {1.0f, 0.0f, 0.0f});
    }
    const std::vector<InfluenceRun> runs{{0, static_cast<std::uint32_t>(n), 0}};
    const float len = std::sqrt(0.25f * 0.25f + 0.75f * 0.75f);
    for (Isa isa : {Isa::Scalar, Isa::Sse2, Isa::Avx2, Isa::Avx512}) {
        if (!isaSupported(isa)) continue;
        std::vector<float> out(n * 3, -9.0f), nout(n * 3, -9.0f);
        SkinningJob job = m3gtest::arraysJob({}, runs, n, 2, 4, bones, weights, pal, in, nin, out, nout, isa);
        job.positionScale = 2.0f;
        job.positionBias = {0.0f, 0.0f, 1.0f};
        ASSERT_TRUE(job.run()) << isaName(isa);
        for (std::size_t v = 0; v < n; ++v) {
            const float x = static_cast<float>(v);
            const std::string what = std::string(isaName(isa)) + " vertex " + std::to_string(v);
            EXPECT_NEAR(out[v * 3], 0.25f * (2 * x + 1), 1e-5f) << what;
            EXPECT_NEAR(out[v * 3 + 1], 0.5f + 1.5f * x, 1e-5f) << what;
            EXPECT_NEAR(out[v * 3 + 2], 1.75f, 1e-5f) << what;
            EXPECT_NEAR(nout[v * 3], 0.25f / len, 1e-6f) << what;
            EXPECT_NEAR(nout[v * 3 + 1], 0.75f / len, 1e-6f) << what;
            EXPECT_NEAR(nout[v * 3 + 2], 0.0f, 1e-6f) << what;
        }
    }
}

// Random meshes written in runs (lengths 16, 13, 5 and 4, so runs start
// anywhere in an eight-lane block and end in tails of every length), 1..4
// influences: runs + loose vertices agree with the double reference and
// with the list path, and the parallel run is bit-identical to run() for
// any grain (grains that cut runs) and thread count.
TEST(SkinningJob, RunsAgreeWithReferenceAndListPathAndAreBitIdenticalAcrossChunks) {
    for (int k = 1; k <= 4; ++k) {
        for (int run : {16, 13, 5, 4}) {
            m3gtest::RandomMesh m(200u + static_cast<std::uint32_t>(k * 10 + run), 2003, 30, k, run);
            const auto pal = m3gtest::paletteOf(m);
            const std::vector<double> mesh = m.meshSpace();
            const std::vector<double> a(m.boneToMesh.begin(), m.boneToMesh.end()), r(m.atRest.begin(), m.atRest.end());
            const std::vector<double> n(m.normals.begin(), m.normals.end());
            const auto ref = m3gtest::referenceSkin(m.records, m.n, a, r, m.vertices, mesh, n);
            InfluencePartition part;
            part.build(m.table.bones(), m.table.weights(), m.n, m.vertices);
            ASSERT_FALSE(part.runs(k).empty()) << k << " influences, run " << run;
            for (Isa isa : {Isa::Scalar, Isa::Sse2, Isa::Avx2, Isa::Avx512}) {
                if (!isaSupported(isa)) continue;
                const std::string what =
                    std::string(isaName(isa)) + ", " + std::to_string(k) + " influences, run " + std::to_string(run);
                std::vector<float> pos, nrm, listPos, listNrm;
                m3gtest::skinAll(m, pal, isa, pos, nrm, nullptr, 4096, true);
                m3gtest::skinAll(m, pal, isa, listPos, listNrm, nullptr, 4096, false);
                EXPECT_TRUE(m3gtest::closeXyz(pos, ref.positions)) << what << " positions";
                EXPECT_TRUE(m3gtest::closeXyz(nrm, ref.normals)) << what << " normals";
                for (std::size_t i = 0; i < pos.size(); ++i) {
                    ASSERT_NEAR(pos[i], listPos[i], 2e-5f * std::max(1.0f, std::abs(listPos[i]))) << what << " " << i;
                    ASSERT_NEAR(nrm[i], listNrm[i], 2e-6f) << what << " normal " << i;
                }
                for (int threads : {1, 2, 3}) {
                    ThreadPool pool(threads);
                    for (std::size_t grain : {1u, 5u, 7u, 12u, 256u}) {
                        std::vector<float> p2, n2;
                        m3gtest::skinAll(m, pal, isa, p2, n2, &pool, grain, true);
                        EXPECT_EQ(0, std::memcmp(pos.data(), p2.data(), pos.size() * sizeof(float)))
                            << what << ", " << threads << " threads, grain " << grain;
                        EXPECT_EQ(0, std::memcmp(nrm.data(), n2.data(), nrm.size() * sizeof(float)))
                            << what << ", " << threads << " threads, grain " << grain;
                    }
                }
            }
        }
    }
}

// Packed arrays: a run's last, partial block is loaded as a whole block
// (from the run's vertex, or the arrays' last eight at their end) and must
// store only the run's lanes. Runs of 5 (tail at the block start), 11 (a
// block and a 3-vertex tail) and 5 at the very end of 40 vertices, a run
// in arrays of 6 vertices (shorter than an AVX2 block) and one of 2 at the
// end of 3 vertices (shorter than an SSE2 block); for the sixteen-lane
// AVX-512 blocks, in 64 vertices a run of exactly 16, one of 35 (two blocks
// and a 3-vertex tail) and 4 at the end: every run vertex is translated by
// (1, 2, 3), every other output keeps its sentinel bits.
TEST(SkinningJob, PartialRunBlocksWriteOnlyTheirVertices) {
    const std::vector<PaletteEntry> pal =
        m3gtest::paletteAtRestIdentity({{1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1}});
    for (std::size_t n : {40u, 6u, 3u, 64u}) {
        const std::vector<InfluenceRun> runs = n == 40  ? std::vector<InfluenceRun>{{3, 5, 0}, {20, 11, 5}, {35, 5, 16}}
                                               : n == 6 ? std::vector<InfluenceRun>{{1, 4, 0}}
                                               : n == 3 ? std::vector<InfluenceRun>{{1, 2, 0}}
                                                        : std::vector<InfluenceRun>{{0, 16, 0}, {17, 35, 16}, {60, 4, 51}};
        std::vector<bool> inRun(n, false);
        for (const InfluenceRun& r : runs)
            for (std::uint32_t v = r.firstVertex; v < r.firstVertex + r.vertexCount; ++v) inRun[v] = true;
        std::vector<std::int32_t> bones;
        std::vector<float> weights, in, nin;
        for (std::size_t v = 0; v < n; ++v) {
            bones.insert(bones.end(), {0, -1, -1, -1});
            weights.insert(weights.end(), {1.0f, 0.0f, 0.0f, 0.0f});
            const float x = static_cast<float>(v);
            in.insert(in.end(), {x, -x, 0.5f * x});
            nin.insert(nin.end(), {0.0f, 0.0f, 2.0f});
        }
        for (Isa isa : {Isa::Scalar, Isa::Sse2, Isa::Avx2, Isa::Avx512}) {
            if (!isaSupported(isa)) continue;
            const float sentinel = -7.25f;
            std::vector<float> out(n * 3, sentinel), nout(n * 3, sentinel);
            SkinningJob job = m3gtest::arraysJob({}, runs, n, 1, 4, bones, weights, pal, in, nin, out, nout, isa);
            ASSERT_TRUE(job.run()) << isaName(isa);
            for (std::size_t v = 0; v < n; ++v) {
                const std::string what = std::string(isaName(isa)) + ", " + std::to_string(n) + " vertices, vertex " +
                                         std::to_string(v);
                const float x = static_cast<float>(v);
                if (inRun[v]) {
                    EXPECT_NEAR(out[v * 3], x + 1, 1e-5f) << what;
                    EXPECT_NEAR(out[v * 3 + 1], 2 - x, 1e-5f) << what;
                    EXPECT_NEAR(out[v * 3 + 2], 0.5f * x + 3, 1e-5f) << what;
                    EXPECT_NEAR(nout[v * 3 + 2], 1.0f, 1e-6f) << what;
                } else {
                    for (int c = 0; c < 3; ++c) {
                        EXPECT_EQ(out[v * 3 + c], sentinel) << what << " written";
                        EXPECT_EQ(nout[v * 3 + c], sentinel) << what << " normal written";
                    }
                }
            }
        }
    }
}

// Interleaved arrays (positions at stride 4, normals at 5, outputs at 6 and
// 7, with padding that must stay untouched) and arrays that end right after
// the last vertex: the run path gathers and scatters lane by lane and agrees
// with the list path.
TEST(SkinningJob, RunsAtOtherStridesTouchOnlyTheirVertices) {
    m3gtest::RandomMesh m(77, 203, 12, 3, 29);
    const auto pal = m3gtest::paletteOf(m);
    InfluencePartition part;
    part.build(m.table.bones(), m.table.weights(), m.n, m.vertices);
    const std::size_t n = m.vertices;
    std::vector<float> in((n - 1) * 4 + 3), nin((n - 1) * 5 + 3);
    for (std::size_t v = 0; v < n; ++v)
        for (int c = 0; c < 3; ++c) {
            in[v * 4 + c] = m.raw[v * 3 + c];
            nin[v * 5 + c] = m.normals[v * 3 + c];
        }
    for (Isa isa : {Isa::Scalar, Isa::Sse2, Isa::Avx2, Isa::Avx512}) {
        if (!isaSupported(isa)) continue;
        std::vector<float> listPos, listNrm;
        m3gtest::skinAll(m, pal, isa, listPos, listNrm, nullptr, 4096, false);
        std::vector<float> out((n - 1) * 6 + 3, -7.0f), nout((n - 1) * 7 + 3, -7.0f);
        for (int c = 0; c <= 4; ++c) {
            SkinningJob job = m3gtest::meshJob(m, part.loose(c), c, pal, isa, out, nout);
            job.runs = part.runs(c);
            job.inPositions = in;
            job.inPositionStride = 4;
            job.inNormals = nin;
            job.inNormalStride = 5;
            job.outPositionStride = 6;
            job.outNormalStride = 7;
            ASSERT_TRUE(job.run()) << isaName(isa) << " group " << c;
        }
        for (std::size_t v = 0; v < n; ++v)
            for (std::size_t c = 0; c < 7; ++c) {
                const std::string what = std::string(isaName(isa)) + " vertex " + std::to_string(v);
                if (c < 3) {
                    ASSERT_NEAR(out[v * 6 + c], listPos[v * 3 + c], 2e-5f * std::max(1.0f, std::abs(listPos[v * 3 + c])))
                        << what;
                    ASSERT_NEAR(nout[v * 7 + c], listNrm[v * 3 + c], 2e-6f) << what;
                } else {
                    if (v * 6 + c < out.size() && c < 6) {
                        ASSERT_EQ(out[v * 6 + c], -7.0f) << what << " padding";
                    }
                    if (v * 7 + c < nout.size()) {
                        ASSERT_EQ(nout[v * 7 + c], -7.0f) << what << " normal padding";
                    }
                }
            }
    }
}

// A run whose shared slot names a bone outside the palette: that slot
// contributes nothing (the checked formula), as on the list path.
TEST(SkinningJob, RunWithABoneOutsideThePaletteSkipsThatSlot) {
    const std::size_t n = 12;
    const std::vector<PaletteEntry> pal = m3gtest::paletteAtRestIdentity({{1, 0, 0, 5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}});
    std::vector<std::int32_t> bones;
    std::vector<float> weights, in, nin;
    for (std::size_t v = 0; v < n; ++v) {
        bones.insert(bones.end(), {0, 9});
        weights.insert(weights.end(), {0.5f, 0.5f});
        in.insert(in.end(), {1.0f, static_cast<float>(v), 0.0f});
        nin.insert(nin.end(), {0.0f, 0.0f, 2.0f});
    }
    const std::vector<InfluenceRun> runs{{0, static_cast<std::uint32_t>(n), 0}};
    for (Isa isa : {Isa::Scalar, Isa::Sse2, Isa::Avx2, Isa::Avx512}) {
        if (!isaSupported(isa)) continue;
        std::vector<float> out(n * 3, -9.0f), nout(n * 3, -9.0f);
        SkinningJob job = m3gtest::arraysJob({}, runs, n, 2, 2, bones, weights, pal, in, nin, out, nout, isa);
        ASSERT_TRUE(job.run()) << isaName(isa);
        for (std::size_t v = 0; v < n; ++v) {
            // 0.5 * ((1, v, 0) + (5, 0, 0)); the normal 0.5 (0, 0, 2) renormalised.
            EXPECT_NEAR(out[v * 3], 3.0f, 1e-6f) << isaName(isa) << " vertex " << v;
            EXPECT_NEAR(out[v * 3 + 1], 0.5f * static_cast<float>(v), 1e-6f) << isaName(isa) << " vertex " << v;
            EXPECT_NEAR(out[v * 3 + 2], 0.0f, 1e-6f);
            EXPECT_NEAR(nout[v * 3 + 2], 1.0f, 1e-6f) << isaName(isa) << " vertex " << v;
        }
    }
}

// The renderer folds the position scale and bias into the palette
// (PaletteJob::positionScale) and skins influenced vertices with scale 1
// and bias 0: the same results as the unfolded palette with the job's
// scale and bias, on every path (runs with 1..4 influences, loose
// vertices).
TEST(SkinningJob, PaletteWithFoldedScaleAndBiasGivesTheSameVertices) {
    for (int k = 1; k <= 4; ++k) {
        m3gtest::RandomMesh m(900u + static_cast<std::uint32_t>(k), 1203, 25, k, 13);
        const auto pal = m3gtest::paletteOf(m);
        std::vector<PaletteEntry> folded(pal.size());
        PaletteJob pj;
        pj.boneCount = folded.size();
        pj.boneToMesh = m.boneToMesh;
        pj.atRest = m.atRest;
        pj.output = folded;
        pj.positionScale = m.scale;
        pj.positionBias = m.bias;
        ASSERT_TRUE(pj.run());
        InfluencePartition part;
        part.build(m.table.bones(), m.table.weights(), m.n, m.vertices);
        for (Isa isa : {Isa::Scalar, Isa::Sse2, Isa::Avx2, Isa::Avx512}) {
            if (!isaSupported(isa)) continue;
            for (bool runs : {true, false}) {
                const std::string what = std::string(isaName(isa)) + ", " + std::to_string(k) + " influences, " +
                                         (runs ? "runs" : "lists");
                std::vector<float> pos, nrm, fpos(m.vertices * 3, -9.0f), fnrm(m.vertices * 3, -9.0f);
                m3gtest::skinAll(m, pal, isa, pos, nrm, nullptr, 4096, runs);
                for (int c = 0; c <= part.maxInfluences(); ++c) {
                    SkinningJob job = m3gtest::meshJob(m, runs ? part.loose(c) : part.group(c), c, folded, isa, fpos, fnrm);
                    if (runs) job.runs = part.runs(c);
                    if (c > 0) {
                        job.positionScale = 1.0f;
                        job.positionBias = {0.0f, 0.0f, 0.0f};
                    }
                    ASSERT_TRUE(job.run()) << what;
                }
                for (std::size_t i = 0; i < pos.size(); ++i) {
                    ASSERT_NEAR(fpos[i], pos[i], 2e-5f * std::max(1.0f, std::abs(pos[i]))) << what << " " << i;
                    ASSERT_NEAR(fnrm[i], nrm[i], 2e-6f) << what << " normal " << i;
                }
            }
        }
    }
}

// A run of one bone at scale 1 and bias 0 (no fold): its weight is used as
// given, 1 or 0.5, on every path. Bone 0 = T(1, 2, 3); p = (x, 1, 0).
TEST(SkinningJob, OneBoneRunAppliesItsWeight) {
    const std::vector<PaletteEntry> pal =
        m3gtest::paletteAtRestIdentity({{1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1}});
    const std::size_t n = 11;
    for (float w : {1.0f, 0.5f}) {
        std::vector<std::int32_t> bones;
        std::vector<float> weights, in, nin;
        for (std::size_t v = 0; v < n; ++v) {
            bones.insert(bones.end(), {0, -1, -1, -1});
            weights.insert(weights.end(), {w, 0.0f, 0.0f, 0.0f});
            in.insert(in.end(), {static_cast<float>(v), 1.0f, 0.0f});
            nin.insert(nin.end(), {0.0f, 3.0f, 0.0f});
        }
        const std::vector<InfluenceRun> runs{{0, static_cast<std::uint32_t>(n), 0}};
        for (Isa isa : {Isa::Scalar, Isa::Sse2, Isa::Avx2, Isa::Avx512}) {
            if (!isaSupported(isa)) continue;
            std::vector<float> out(n * 3), nout(n * 3);
            SkinningJob job = m3gtest::arraysJob({}, runs, n, 1, 4, bones, weights, pal, in, nin, out, nout, isa);
            ASSERT_TRUE(job.run());
            for (std::size_t v = 0; v < n; ++v) {
                const std::string what = std::string(isaName(isa)) + ", weight " + std::to_string(w) + ", vertex " +
                                         std::to_string(v);
                EXPECT_NEAR(out[v * 3], w * (static_cast<float>(v) + 1), 1e-5f) << what;
                EXPECT_NEAR(out[v * 3 + 1], w * 3, 1e-5f) << what;
                EXPECT_NEAR(out[v * 3 + 2], w * 3, 1e-5f) << what;
                EXPECT_NEAR(nout[v * 3 + 1], 1.0f, 1e-6f) << what;
            }
        }
    }
}

// Bone runs: vertices sharing their bones, each with its own weights. Two
// bones translate by (10, 0, 0) and (0, 20, 0); vertex v of a bone run
// weighs them w = (v + 1) / 70 and 1 - w, so it moves by (10 w, 20 (1 - w),
// 0) and keeps its normal's direction. In 64 vertices, bone runs of exactly
// sixteen, of 35 (two sixteen-lane blocks and a 3-vertex tail) and of 4 at
// the very end, at influence strides 4 (the AVX-512 kernel's permuted
// weights), 3 and 2 (its gathered weights); every other output keeps its
// sentinel bits. A run of 5 whose second slot names a bone outside the
// palette contributes its first slot only (w (p + (10, 0, 0))).
TEST(SkinningJob, BoneRunsBlendEachVertexsOwnWeights) {
    const std::vector<PaletteEntry> pal = m3gtest::paletteAtRestIdentity(
        {{1, 0, 0, 10, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, {1, 0, 0, 0, 0, 1, 0, 20, 0, 0, 1, 0, 0, 0, 0, 1}});
    const std::size_t n = 64;
    const std::vector<InfluenceRun> boneRuns{{0, 16, 0}, {17, 35, 16}, {60, 4, 51}};
    const InfluenceRun badRun{54, 5, 0};
    for (int stride : {4, 3, 2}) {
        std::vector<std::int32_t> bones(n * static_cast<std::size_t>(stride), -1);
        std::vector<float> weights(bones.size(), 0.0f), in, nin;
        std::vector<int> kind(n, 0);  // 0: none, 1: bone run, 2: the run with a bad bone
        for (const InfluenceRun& r : boneRuns)
            for (std::uint32_t v = r.firstVertex; v < r.firstVertex + r.vertexCount; ++v) kind[v] = 1;
        for (std::uint32_t v = badRun.firstVertex; v < badRun.firstVertex + badRun.vertexCount; ++v) kind[v] = 2;
        for (std::size_t v = 0; v < n; ++v) {
            const std::size_t s = v * static_cast<std::size_t>(stride);
            const float w = static_cast<float>(v + 1) / 70.0f;
            bones[s] = 0;
            bones[s + 1] = kind[v] == 2 ? 7 : 1;
            weights[s] = w;
            weights[s + 1] = 1.0f - w;
            const float x = static_cast<float>(v);
            in.insert(in.end(), {x, -x, 0.5f * x});
            nin.insert(nin.end(), {0.0f, 3.0f, 4.0f});
        }
        for (Isa isa : {Isa::Scalar, Isa::Sse2, Isa::Avx2, Isa::Avx512}) {
            if (!isaSupported(isa)) continue;
            for (bool bad : {false, true}) {
                const float sentinel = -7.25f;
                std::vector<float> out(n * 3, sentinel), nout(n * 3, sentinel);
                SkinningJob job = m3gtest::arraysJob({}, {}, n, 2, stride, bones, weights, pal, in, nin, out, nout, isa);
                job.boneRuns = bad ? std::span<const InfluenceRun>(&badRun, 1) : std::span<const InfluenceRun>(boneRuns);
                ASSERT_TRUE(job.run()) << isaName(isa);
                for (std::size_t v = 0; v < n; ++v) {
                    const std::string what = std::string(isaName(isa)) + ", stride " + std::to_string(stride) +
                                             ", vertex " + std::to_string(v);
                    const float x = static_cast<float>(v), w = static_cast<float>(v + 1) / 70.0f;
                    if (kind[v] == (bad ? 2 : 1)) {
                        const float keep = bad ? w : 1.0f;  // the bad slot adds nothing
                        EXPECT_NEAR(out[v * 3], keep * x + 10 * w, 1e-4f) << what;
                        EXPECT_NEAR(out[v * 3 + 1], -keep * x + (bad ? 0.0f : 20 * (1 - w)), 1e-4f) << what;
                        EXPECT_NEAR(out[v * 3 + 2], keep * 0.5f * x, 1e-4f) << what;
                        EXPECT_NEAR(nout[v * 3], 0.0f, 1e-6f) << what;
                        EXPECT_NEAR(nout[v * 3 + 1], 0.6f, 1e-6f) << what;
                        EXPECT_NEAR(nout[v * 3 + 2], 0.8f, 1e-6f) << what;
                    } else {
                        for (int c = 0; c < 3; ++c) {
                            EXPECT_EQ(out[v * 3 + c], sentinel) << what << " written";
                            EXPECT_EQ(nout[v * 3 + c], sentinel) << what << " normal written";
                        }
                    }
                }
            }
        }
    }
}

/// `count` floats that end where an inaccessible page begins: a read past
/// the last one faults, so a kernel reading weights the table does not
/// have fails the test whatever the build (not only under ASan).
class GuardedFloats {
public:
    explicit GuardedFloats(std::size_t count) : count_(count) {
        const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
        const std::size_t bytes = (count * sizeof(float) + page - 1) / page * page;
        size_ = bytes + page;
        base_ = mmap(nullptr, size_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (base_ == MAP_FAILED || mprotect(static_cast<char*>(base_) + bytes, page, PROT_NONE) != 0) {
            ADD_FAILURE() << "mmap/mprotect for the guarded weights failed";
            base_ = nullptr;
            return;
        }
        data_ = reinterpret_cast<float*>(static_cast<char*>(base_) + bytes) - count;
    }
    ~GuardedFloats() {
        if (base_) munmap(base_, size_);
    }
    GuardedFloats(const GuardedFloats&) = delete;
    GuardedFloats& operator=(const GuardedFloats&) = delete;
    bool ok() const { return base_ != nullptr; }
    std::span<float> span() { return {data_, count_}; }

private:
    void* base_ = nullptr;
    std::size_t size_ = 0;
    float* data_ = nullptr;
    std::size_t count_;
};

// A bone run at the end of the weight table, with more vertices after it
// than the table has rows (the compact space's unboned vertices follow
// its influenced ones and have no weights): the run's last block reads no
// weights past the table, on every ISA, with whole rows and with a last
// row that holds only the used slots; the vertices after the run are not
// written. (The AVX2 kernel once loaded the tail's block from the tail's
// first vertex whenever the inputs held eight more, reading four rows past
// the table here: the guard page turns that into a fault.)
TEST(SkinningJob, BoneRunTailsReadNoWeightsPastTheTable) {
    const std::vector<PaletteEntry> pal = m3gtest::paletteAtRestIdentity(
        {{1, 0, 0, 10, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, {1, 0, 0, 0, 0, 1, 0, 20, 0, 0, 1, 0, 0, 0, 0, 1}});
    const std::size_t n = 24, rows = 12;
    const std::vector<InfluenceRun> boneRun{{0, static_cast<std::uint32_t>(rows), 0}};
    std::vector<float> in, nin;
    for (std::size_t v = 0; v < n; ++v) {
        const float x = static_cast<float>(v);
        in.insert(in.end(), {x, -x, 0.5f * x});
        nin.insert(nin.end(), {0.0f, 3.0f, 4.0f});
    }
    for (int stride : {4, 3, 2}) {
        for (bool partialLastRow : {false, true}) {
            const auto s = static_cast<std::size_t>(stride);
            const std::size_t floats = partialLastRow ? (rows - 1) * s + 2 : rows * s;
            std::vector<std::int32_t> bones(floats, -1);
            GuardedFloats weights(floats);
            ASSERT_TRUE(weights.ok());
            const std::span<float> w = weights.span();
            std::fill(w.begin(), w.end(), 0.0f);
            for (std::size_t v = 0; v < rows; ++v) {
                bones[v * s] = 0;
                bones[v * s + 1] = 1;
                w[v * s] = static_cast<float>(v + 1) / 70.0f;
                w[v * s + 1] = 1.0f - w[v * s];
            }
            for (Isa isa : {Isa::Scalar, Isa::Sse2, Isa::Avx2, Isa::Avx512}) {
                if (!isaSupported(isa)) continue;
                const float sentinel = -7.25f;
                std::vector<float> out(n * 3, sentinel), nout(n * 3, sentinel);
                SkinningJob job = m3gtest::arraysJob({}, {}, n, 2, stride, bones, {}, pal, in, nin, out, nout, isa);
                job.boneWeights = w;
                job.boneRuns = boneRun;
                ASSERT_TRUE(job.run()) << isaName(isa);
                for (std::size_t v = 0; v < n; ++v) {
                    const std::string what = std::string(isaName(isa)) + ", stride " + std::to_string(stride) +
                                             (partialLastRow ? ", partial last row" : "") + ", vertex " +
                                             std::to_string(v);
                    if (v >= rows) {
                        EXPECT_EQ(out[v * 3], sentinel) << what << " written";
                        EXPECT_EQ(nout[v * 3], sentinel) << what << " normal written";
                        continue;
                    }
                    const float x = static_cast<float>(v), wv = static_cast<float>(v + 1) / 70.0f;
                    EXPECT_NEAR(out[v * 3], x + 10 * wv, 1e-4f) << what;
                    EXPECT_NEAR(out[v * 3 + 1], -x + 20 * (1 - wv), 1e-4f) << what;
                    EXPECT_NEAR(out[v * 3 + 2], 0.5f * x, 1e-4f) << what;
                    EXPECT_NEAR(nout[v * 3 + 1], 0.6f, 1e-6f) << what;
                    EXPECT_NEAR(nout[v * 3 + 2], 0.8f, 1e-6f) << what;
                }
            }
        }
    }
}

// Bone runs through runParallel: each vertex is computed alike in any chunk
// (the sixteen lanes are independent), so any grain and thread count gives
// run()'s bits; validate() checks bone runs as it checks runs.
TEST(SkinningJob, BoneRunsAreBitIdenticalAcrossChunksAndValidated) {
    // Three of four bones per vertex, random weights: bone sets repeat, weights mostly differ.
    m3gtest::RandomMesh m(77, 901, 4, 3, 1);
    const auto pal = m3gtest::paletteOf(m);
    InfluencePartition part;
    part.build(m.table.bones(), m.table.weights(), m.n, m.vertices);
    std::size_t inBoneRuns = 0;
    for (Isa isa : {Isa::Scalar, Isa::Sse2, Isa::Avx2, Isa::Avx512}) {
        if (!isaSupported(isa)) continue;
        // The compact space of the three-influence group, skinned in place.
        const auto order = part.compactOrder();
        std::vector<float> cp(order.size() * 3), cn(order.size() * 3);
        for (std::size_t i = 0; i < order.size(); ++i)
            for (std::size_t e = 0; e < 3; ++e) {
                cp[i * 3 + e] = m.raw[order[i] * 3 + e];
                cn[i * 3 + e] = m.normals[order[i] * 3 + e];
            }
        std::vector<float> out(cp.size(), -1.0f), nout(cp.size(), -1.0f);
        SkinningJob job;
        job.vertexCount = order.size();
        job.influenceCount = 3;
        job.influenceStride = m.n;
        job.boneIndices = part.compactBones();
        job.boneWeights = part.compactWeights();
        job.palette = pal;
        job.inPositions = cp;
        job.inNormals = cn;
        job.outPositions = out;
        job.outNormals = nout;
        job.boneRuns = part.compactBoneRuns(3);
        job.positionScale = m.scale;  // applied to the inputs, not folded into rows
        job.positionBias = m.bias;
        job.isa = isa;
        inBoneRuns = 0;
        for (const InfluenceRun& r : job.boneRuns) inBoneRuns += r.vertexCount;
        ASSERT_TRUE(job.run()) << isaName(isa);
        // The same vertices as a scalar vertex list (each with its own slots).
        {
            std::vector<std::uint32_t> list;
            for (const InfluenceRun& r : job.boneRuns)
                for (std::uint32_t v = r.firstVertex; v < r.firstVertex + r.vertexCount; ++v) list.push_back(v);
            std::vector<float> lp(cp.size(), -1.0f), ln(cp.size(), -1.0f);
            SkinningJob lj = job;
            lj.boneRuns = {};
            lj.vertices = list;
            lj.outPositions = lp;
            lj.outNormals = ln;
            lj.isa = Isa::Scalar;
            ASSERT_TRUE(lj.run());
            for (std::size_t i = 0; i < lp.size(); ++i) {
                ASSERT_NEAR(out[i], lp[i], 2e-5f * std::max(1.0f, std::abs(lp[i]))) << isaName(isa) << " " << i;
                ASSERT_NEAR(nout[i], ln[i], 2e-6f) << isaName(isa) << " normal " << i;
            }
        }
        for (int threads : {1, 3}) {
            ThreadPool pool(threads);
            for (std::size_t grain : {1u, 7u, 16u, 100u}) {
                std::vector<float> p2(cp.size(), -1.0f), n2(cp.size(), -1.0f);
                SkinningJob j2 = job;
                j2.outPositions = p2;
                j2.outNormals = n2;
                ASSERT_TRUE(j2.runParallel(pool, grain));
                EXPECT_EQ(0, std::memcmp(out.data(), p2.data(), out.size() * sizeof(float)))
                    << isaName(isa) << ", " << threads << " threads, grain " << grain;
                EXPECT_EQ(0, std::memcmp(nout.data(), n2.data(), nout.size() * sizeof(float)))
                    << isaName(isa) << ", " << threads << " threads, grain " << grain;
            }
        }
        // A bone run reaching past the arrays, or with a wrong start, is refused.
        std::vector<InfluenceRun> bad(job.boneRuns.begin(), job.boneRuns.end());
        ASSERT_FALSE(bad.empty());
        bad.back().vertexCount += static_cast<std::uint32_t>(order.size());
        job.boneRuns = bad;
        EXPECT_FALSE(job.validate());
        bad = {{0, 4, 1}};
        job.boneRuns = bad;
        EXPECT_FALSE(job.validate());
    }
    EXPECT_GT(inBoneRuns, 0u);
}
