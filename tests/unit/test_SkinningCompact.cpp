// The partition's compact space (InfluencePartition::compactOrder, the
// compact runs and loose positions, skin::scatterXyz): loose vertices sorted
// by influence set when the table is built, so that what they share is
// blended once, and written back to their own mesh vertices (the output
// order stays the mesh's). Checked against the double reference and the
// list path on every ISA, with 1-4 influences, at any chunking.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "SkinRandomMesh.h"
#include "SkinReference.h"

using namespace m3g::skin;

namespace {

const Isa kIsas[] = {Isa::Scalar, Isa::Sse2, Isa::Avx2, Isa::Avx512};

/// What MeshDeformer does: each group's mesh-order runs (and group 0's
/// vertices) in place, the compact space's runs, bone runs and loose
/// positions in compact arrays, then every compact output written to its mesh vertex
/// (scatterXyz). Outputs start as a sentinel.
void skinCompact(const m3gtest::RandomMesh& m, const std::vector<PaletteEntry>& pal, Isa isa,
                 std::vector<float>& pos, std::vector<float>& nrm, ThreadPool* pool = nullptr,
                 std::size_t grain = 4096, std::size_t runBlock = 0) {
    InfluencePartition part;
    part.build(m.table.bones(), m.table.weights(), m.n, m.vertices, InfluencePartition::kMinRun, runBlock);
    pos.assign(m.vertices * 3, -999.0f);
    nrm.assign(m.vertices * 3, -999.0f);
    const auto order = part.compactOrder();
    std::vector<float> cp(order.size() * 3), cn(order.size() * 3), cop(order.size() * 3, -777.0f),
        con(order.size() * 3, -777.0f);
    for (std::size_t i = 0; i < order.size(); ++i)
        for (std::size_t e = 0; e < 3; ++e) {
            cp[i * 3 + e] = m.raw[order[i] * 3 + e];
            cn[i * 3 + e] = m.normals[order[i] * 3 + e];
        }
    for (int c = 0; c <= part.maxInfluences(); ++c) {
        SkinningJob job = m3gtest::meshJob(m, c == 0 ? part.loose(0) : std::span<const std::uint32_t>(), c, pal, isa,
                                           pos, nrm);
        job.runs = part.runs(c);
        ASSERT_TRUE(pool ? job.runParallel(*pool, grain) : job.run()) << "group " << c;
        if (c == 0) continue;
        SkinningJob cj = job;
        cj.vertices = part.compactLoose(c);
        cj.runs = part.compactRuns(c);
        cj.boneRuns = part.compactBoneRuns(c);
        cj.vertexCount = order.size();
        cj.boneIndices = part.compactBones();
        cj.boneWeights = part.compactWeights();
        cj.inPositions = cp;
        cj.inNormals = cn;
        cj.outPositions = cop;
        cj.outNormals = con;
        ASSERT_TRUE(pool ? cj.runParallel(*pool, grain) : cj.run()) << "compact group " << c;
    }
    scatterXyz(order, cop.data(), pos.data(), con.data(), nrm.data());
}

/// A mesh (stride 4) whose vertices come in stretches sharing bones, some
/// with the same weights, some each with their own (a blend along a limb),
/// some with every slot its own, with 1..4 influences, shuffled so that
/// the sharing vertices are not consecutive; with zeroWeights, about one
/// stretch in ten has all its weights 0 (zero total weight).
struct ShuffledMesh {
    int n = 4;
    std::size_t vertices;
    std::vector<std::int32_t> bones;
    std::vector<float> weights;
    ShuffledMesh(std::uint32_t seed, std::size_t count, int bonesInPalette, bool zeroWeights) : vertices(count) {
        std::mt19937 rng(seed);
        std::uniform_int_distribution<int> kind(0, 2), influences(1, 4), len(1, 30), bone(0, bonesInPalette - 1);
        std::uniform_real_distribution<float> w(0.0f, 1.0f);
        struct Slots {
            std::int32_t b[4];
            float w[4];
        };
        std::vector<Slots> slots;
        while (slots.size() < count) {
            const int k = influences(rng), stretch = len(rng), how = kind(rng);
            Slots s{{-1, -1, -1, -1}, {0, 0, 0, 0}};
            auto randomBones = [&](Slots& t) {
                std::set<int> used;
                for (int i = 0; i < k; ++i) {
                    int b;
                    do b = bone(rng);
                    while (!used.insert(b).second);
                    t.b[i] = b;
                }
            };
            auto randomWeights = [&](Slots& t) {
                float sum = 0;
                for (int i = 0; i < k; ++i) sum += t.w[i] = w(rng) + 0.01f;
                for (int i = 0; i < k; ++i) t.w[i] /= sum;
                if (zeroWeights && w(rng) < 0.1f)
                    for (int i = 0; i < k; ++i) t.w[i] = 0.0f;  // zero total weight
            };
            randomBones(s);
            randomWeights(s);
            for (int v = 0; v < stretch && slots.size() < count; ++v) {
                if (how >= 1) randomWeights(s);  // same bones, own weights
                if (how == 2) randomBones(s);    // everything its own
                slots.push_back(s);
            }
        }
        std::shuffle(slots.begin(), slots.end(), rng);
        for (const Slots& s : slots)
            for (int i = 0; i < 4; ++i) {
                bones.push_back(s.b[i]);
                weights.push_back(s.w[i]);
            }
    }
};

}  // namespace

// The compact space holds exactly the loose vertices with influences, each
// with its own slots; its runs share every slot; runs and loose positions
// cover it once; sorting brings vertices with the same set together.
// With a run block (InfluencePartition::runBlock), a compact run shorter
// than it is the whole of its set of bones in its group.
TEST(InfluencePartition, CompactSpaceSortsLooseVerticesByInfluenceSet) {
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        for (std::size_t runBlock : {std::size_t{0}, std::size_t{8}, std::size_t{16}}) {
            SCOPED_TRACE("seed " + std::to_string(seed) + ", run block " + std::to_string(runBlock));
            ShuffledMesh m(seed, 3001, 23, false);
            InfluencePartition part;
            part.build(m.bones, m.weights, m.n, m.vertices, InfluencePartition::kMinRun, runBlock);
            const auto order = part.compactOrder();
            std::vector<std::uint32_t> loose;
            for (int c = 1; c <= part.maxInfluences(); ++c)
                loose.insert(loose.end(), part.loose(c).begin(), part.loose(c).end());
            std::vector<std::uint32_t> sortedOrder(order.begin(), order.end());
            std::sort(sortedOrder.begin(), sortedOrder.end());
            std::sort(loose.begin(), loose.end());
            ASSERT_EQ(loose, sortedOrder) << "seed " << seed;
            ASSERT_EQ(part.compactBones().size(), order.size() * 4);
            ASSERT_EQ(part.compactWeights().size(), order.size() * 4);
            for (std::size_t i = 0; i < order.size(); ++i) {
                // The vertex's own slots, as the table has them.
                ASSERT_EQ(0, std::memcmp(&part.compactBones()[i * 4], &m.bones[order[i] * 4], 16)) << "compact " << i;
                ASSERT_EQ(0, std::memcmp(&part.compactWeights()[i * 4], &m.weights[order[i] * 4], 16)) << "compact " << i;
            }
            // Loose vertices of a group never share every slot with kMinRun - 1
            // others (those are runs).
            std::vector<int> covered(order.size(), 0);
            std::size_t inRuns = 0, inBoneRuns = 0;
            for (int c = 1; c <= part.maxInfluences(); ++c) {
                std::uint32_t start = 0;
                for (const InfluenceRun& r : part.compactRuns(c)) {
                    ASSERT_EQ(r.start, start);
                    ASSERT_GE(r.vertexCount, InfluencePartition::kMinRun);
                    start += r.vertexCount;
                    inRuns += r.vertexCount;
                    for (std::uint32_t v = r.firstVertex; v < r.firstVertex + r.vertexCount; ++v) {
                        ++covered[v];
                        ASSERT_EQ(0, std::memcmp(&part.compactBones()[v * 4], &part.compactBones()[r.firstVertex * 4], 16));
                        ASSERT_EQ(0, std::memcmp(&part.compactWeights()[v * 4],
                                                 &part.compactWeights()[r.firstVertex * 4], 16));
                    }
                }
                // Bone runs: consecutive, every vertex with the first one's bones
                // (its own weights); sets of fewer than kMinRun such vertices
                // stay loose, so no loose vertex shares its bones with
                // kMinRun - 1 other loose ones of its group.
                std::uint32_t boneStart = 0;
                for (const InfluenceRun& r : part.compactBoneRuns(c)) {
                    ASSERT_EQ(r.start, boneStart);
                    ASSERT_GE(r.vertexCount, InfluencePartition::kMinRun);
                    boneStart += r.vertexCount;
                    inBoneRuns += r.vertexCount;
                    for (std::uint32_t v = r.firstVertex; v < r.firstVertex + r.vertexCount; ++v) {
                        ++covered[v];
                        ASSERT_EQ(0, std::memcmp(&part.compactBones()[v * 4], &part.compactBones()[r.firstVertex * 4],
                                                 4 * static_cast<std::size_t>(c)));
                    }
                }
                std::map<std::vector<std::int32_t>, int> looseSets;
                for (std::uint32_t v : part.compactLoose(c)) {
                    ++covered[v];
                    const std::int32_t* b = &part.compactBones()[v * 4];
                    ASSERT_LT(++looseSets[std::vector<std::int32_t>(b, b + c)], static_cast<int>(InfluencePartition::kMinRun))
                        << "compact " << v;
                }
                // A run shorter than the block: no other vertex of the group
                // has its bones.
                auto bonesOf = [&](std::uint32_t v) {
                    const std::int32_t* b = &part.compactBones()[v * 4];
                    return std::vector<std::int32_t>(b, b + c);
                };
                std::map<std::vector<std::int32_t>, std::size_t> setSizes;
                for (const InfluenceRun& r : part.compactRuns(c)) setSizes[bonesOf(r.firstVertex)] += r.vertexCount;
                for (const InfluenceRun& r : part.compactBoneRuns(c)) setSizes[bonesOf(r.firstVertex)] += r.vertexCount;
                for (std::uint32_t v : part.compactLoose(c)) ++setSizes[bonesOf(v)];
                for (const InfluenceRun& r : part.compactRuns(c)) {
                    if (r.vertexCount < runBlock) {
                        ASSERT_EQ(setSizes[bonesOf(r.firstVertex)], r.vertexCount) << "run at " << r.firstVertex;
                    }
                }
            }
            for (std::size_t i = 0; i < covered.size(); ++i) ASSERT_EQ(1, covered[i]) << "compact " << i;
            EXPECT_GT(inRuns, 0u);
            EXPECT_GT(inBoneRuns, 0u);
        }
    }
    // Without weights there is no compact space.
    ShuffledMesh m(9, 100, 5, false);
    InfluencePartition part;
    part.build(m.bones, m.n, m.vertices);
    EXPECT_TRUE(part.compactOrder().empty());
    EXPECT_TRUE(part.compactRuns(1).empty());
    EXPECT_TRUE(part.compactLoose(1).empty());
    EXPECT_TRUE(part.compactBoneRuns(1).empty());
}

// Three sets of two bones, laid out by hand: {0, 1} with five vertices of
// equal weights and three of their own, {2, 3} with five of equal weights
// only, {4, 5} with nine of equal weights and four of their own. Without a
// run block every equal stretch of kMinRun or more is a run; with one,
// {0, 1}'s five join its bone run (the three alone would stay loose), {2, 3}'s
// five stay a run (the whole set), and {4, 5}'s nine stay a run at a block
// of eight but join the bone run at sixteen.
TEST(InfluencePartition, ShortRunsJoinTheBoneRunOfTheirSetWithARunBlock) {
    std::vector<std::int32_t> bones;
    std::vector<float> weights;
    auto add = [&](int b0, int b1, float w0, int count) {
        for (int i = 0; i < count; ++i) {
            bones.insert(bones.end(), {b0, b1});
            weights.insert(weights.end(), {w0, 1.0f - w0});
        }
    };
    add(0, 1, 0.5f, 5);
    add(0, 1, 0.1f, 1);
    add(0, 1, 0.2f, 1);
    add(0, 1, 0.3f, 1);
    add(2, 3, 0.25f, 5);
    add(4, 5, 0.75f, 9);
    for (float w : {0.15f, 0.35f, 0.45f, 0.55f}) add(4, 5, w, 1);
    const std::size_t vertices = bones.size() / 2;
    struct Layout {
        std::vector<std::uint32_t> runs, boneRuns;
        std::size_t loose;
    };
    auto layout = [&](std::size_t runBlock) {
        InfluencePartition part;
        part.build(bones, weights, 2, vertices, InfluencePartition::kNoInPlaceRuns, runBlock);
        Layout l;
        for (const InfluenceRun& r : part.compactRuns(2)) l.runs.push_back(r.vertexCount);
        for (const InfluenceRun& r : part.compactBoneRuns(2)) l.boneRuns.push_back(r.vertexCount);
        l.loose = part.compactLoose(2).size();
        EXPECT_TRUE(part.compactRuns(1).empty());
        return l;
    };
    using V = std::vector<std::uint32_t>;
    const Layout none = layout(0);
    EXPECT_EQ(none.runs, (V{5, 5, 9}));
    EXPECT_EQ(none.boneRuns, (V{4}));
    EXPECT_EQ(none.loose, 3u);
    const Layout eight = layout(8);
    EXPECT_EQ(eight.runs, (V{5, 9}));
    EXPECT_EQ(eight.boneRuns, (V{8, 4}));
    EXPECT_EQ(eight.loose, 0u);
    const Layout sixteen = layout(16);
    EXPECT_EQ(sixteen.runs, (V{5}));
    EXPECT_EQ(sixteen.boneRuns, (V{8, 13}));
    EXPECT_EQ(sixteen.loose, 0u);
    EXPECT_EQ(InfluencePartition::runBlock(Isa::Scalar), 0u);
    if (isaSupported(Isa::Sse2)) {
        EXPECT_EQ(InfluencePartition::runBlock(Isa::Sse2), 0u);
    }
    if (isaSupported(Isa::Avx2)) {
        EXPECT_EQ(InfluencePartition::runBlock(Isa::Avx2), 8u);
    }
    if (isaSupported(Isa::Avx512)) {
        EXPECT_EQ(InfluencePartition::runBlock(Isa::Avx512), 16u);
    }
}

// Random meshes with 1-4 influences whose vertices share bones and weights
// without being neighbours: skinned through the compact space, every mesh
// vertex gets its own result (the reference's, at its own index: the
// output order is the mesh's), the same as the plain vertex-list path on
// that ISA, bit-identical for any grain and thread count.
TEST(SkinningJob, CompactSpaceKeepsTheMeshOrderAndAgreesWithTheReference) {
    for (std::uint32_t seed : {11u, 12u, 13u, 14u}) {
        // Records over random ranges: overlapping ranges give 1-4 influences.
        m3gtest::RandomMesh m(seed, 1501, 17, 60);
        // And vertices that share their influences without being neighbours.
        for (int i = 0; i < 40; ++i) {
            const int first = static_cast<int>((seed * 131 + static_cast<std::uint32_t>(i) * 37) % 1400);
            m.records.push_back({i % 17, 3, first, 1});
            m.table.add(i % 17, 3, first, 1);
            m.records.push_back({i % 17, 3, first + 50, 1});
            m.table.add(i % 17, 3, first + 50, 1);
        }
        const auto pal = m3gtest::paletteOf(m);
        const std::vector<double> mesh = m.meshSpace();
        const std::vector<double> a(m.boneToMesh.begin(), m.boneToMesh.end()), r(m.atRest.begin(), m.atRest.end());
        const std::vector<double> nd(m.normals.begin(), m.normals.end());
        const auto ref = m3gtest::referenceSkin(m.records, m.n, a, r, m.vertices, mesh, nd);
        InfluencePartition part;
        part.build(m.table.bones(), m.table.weights(), m.n, m.vertices);
        std::size_t compactRuns = 0;
        for (int c = 1; c <= part.maxInfluences(); ++c) compactRuns += part.compactRuns(c).size();
        EXPECT_GT(compactRuns, 0u) << "seed " << seed;
        for (Isa isa : kIsas) {
            if (!isaSupported(isa)) continue;
            const std::string what = std::string(isaName(isa)) + ", seed " + std::to_string(seed);
            // Without a run block, and with the ISA's (short runs in bone runs).
            for (std::size_t runBlock : {std::size_t{0}, InfluencePartition::runBlock(isa)}) {
                const std::string at = what + ", run block " + std::to_string(runBlock);
                std::vector<float> pos, nrm, listPos, listNrm;
                skinCompact(m, pal, isa, pos, nrm, nullptr, 4096, runBlock);
                m3gtest::skinAll(m, pal, isa, listPos, listNrm);
                EXPECT_TRUE(m3gtest::closeXyz(pos, ref.positions)) << at << " positions";
                EXPECT_TRUE(m3gtest::closeXyz(nrm, ref.normals)) << at << " normals";
                for (std::size_t i = 0; i < pos.size(); ++i) {
                    ASSERT_NEAR(pos[i], listPos[i], 2e-5f * std::max(1.0f, std::abs(listPos[i]))) << at << " " << i;
                    ASSERT_NEAR(nrm[i], listNrm[i], 2e-6f) << at << " normal " << i;
                }
                for (int threads : {1, 2}) {
                    ThreadPool pool(threads);
                    for (std::size_t grain : {1u, 5u, 12u, 256u}) {
                        std::vector<float> p2, n2;
                        skinCompact(m, pal, isa, p2, n2, &pool, grain, runBlock);
                        EXPECT_EQ(0, std::memcmp(pos.data(), p2.data(), pos.size() * sizeof(float))) << at;
                        EXPECT_EQ(0, std::memcmp(nrm.data(), n2.data(), nrm.size() * sizeof(float))) << at;
                    }
                }
            }
        }
    }
}

// Shuffled meshes with 1-4 influences, some vertices of zero total weight
// (they go to the origin, their normal stays zero), positions and normals
// at random: through the compact space on every ISA, each mesh vertex gets
// what the scalar path gives it as a plain vertex list.
TEST(SkinningJob, CompactSpaceAgreesWithTheScalarListPathIncludingZeroWeights) {
    std::mt19937 rng(31);
    std::vector<std::array<float, 16>> bonesToMesh;
    for (int b = 0; b < 23; ++b) bonesToMesh.push_back(m3gtest::randomAffine(rng));
    const std::vector<PaletteEntry> pal = m3gtest::paletteAtRestIdentity(bonesToMesh);
    std::uniform_real_distribution<float> u(-5.0f, 5.0f);
    for (std::uint32_t seed : {4u, 5u, 6u}) {
        ShuffledMesh m(seed, 2000 + seed, 23, true);
        std::vector<float> in(m.vertices * 3), nin(m.vertices * 3);
        for (auto& x : in) x = u(rng);
        for (auto& x : nin) x = u(rng);
        InfluencePartition part;
        part.build(m.bones, m.weights, m.n, m.vertices);
        // The reference: every group as one vertex list, scalar.
        std::vector<float> ref(m.vertices * 3, -999.0f), nref(m.vertices * 3, -999.0f);
        for (int c = 0; c <= part.maxInfluences(); ++c) {
            SkinningJob job = m3gtest::arraysJob(part.group(c), {}, m.vertices, c, m.n, m.bones, m.weights, pal, in,
                                                 nin, ref, nref, Isa::Scalar);
            ASSERT_TRUE(job.run());
        }
        const auto order = part.compactOrder();
        ASSERT_EQ(order.size(), m.vertices - [&] {
            std::size_t r = 0;
            for (int c = 1; c <= part.maxInfluences(); ++c)
                for (const InfluenceRun& run : part.runs(c)) r += run.vertexCount;
            return r;
        }());
        std::vector<float> cp(order.size() * 3), cn(order.size() * 3);
        for (std::size_t i = 0; i < order.size(); ++i)
            for (std::size_t e = 0; e < 3; ++e) {
                cp[i * 3 + e] = in[order[i] * 3 + e];
                cn[i * 3 + e] = nin[order[i] * 3 + e];
            }
        for (Isa isa : kIsas) {
            if (!isaSupported(isa)) continue;
            const std::string what = std::string(isaName(isa)) + ", seed " + std::to_string(seed);
            std::vector<float> pos(m.vertices * 3, -999.0f), nrm(m.vertices * 3, -999.0f);
            std::vector<float> cop(order.size() * 3, -777.0f), con(order.size() * 3, -777.0f);
            for (int c = 1; c <= part.maxInfluences(); ++c) {
                SkinningJob job = m3gtest::arraysJob({}, part.runs(c), m.vertices, c, m.n, m.bones, m.weights, pal,
                                                     in, nin, pos, nrm, isa);
                ASSERT_TRUE(job.run()) << what;
                SkinningJob cj = m3gtest::arraysJob(part.compactLoose(c), part.compactRuns(c), order.size(), c, m.n,
                                                    std::vector<std::int32_t>(part.compactBones().begin(),
                                                                              part.compactBones().end()),
                                                    std::vector<float>(part.compactWeights().begin(),
                                                                       part.compactWeights().end()),
                                                    pal, cp, cn, cop, con, isa);
                // arraysJob keeps spans of its arguments: point at the partition's own arrays.
                cj.boneIndices = part.compactBones();
                cj.boneWeights = part.compactWeights();
                cj.boneRuns = part.compactBoneRuns(c);
                ASSERT_TRUE(cj.run()) << what;
            }
            scatterXyz(order, cop.data(), pos.data());
            scatterXyz(order, con.data(), nrm.data());
            for (std::size_t i = 0; i < pos.size(); ++i) {
                ASSERT_NEAR(pos[i], ref[i], 2e-5f * std::max(1.0f, std::abs(ref[i]))) << what << " " << i;
                ASSERT_NEAR(nrm[i], nref[i], 2e-6f) << what << " normal " << i;
            }
        }
    }
}

// SkinningJob::normalsFromPositions: with a conformal palette (bones that
// rotate and translate with one common scale, PaletteJob::conformal), the
// bone-run kernels (AVX-512, AVX2) turn normals with the blended position
// rows: positions the same bits as without, normals within 1e-5 of the
// normal rows' result and of unit length. Control: with a palette that is
// not conformal (non-uniform scales) the flag changes normals by far more,
// so the kernels do read it.
TEST(SkinningJob, BoneRunsTurnNormalsWithThePositionRowsOfAConformalPalette) {
    std::mt19937 rng(41);
    std::vector<float> a, r;
    for (int b = 0; b < 23; ++b) {
        const auto m = m3gtest::randomScaledRotation(rng, 1.3f), rest = m3gtest::randomScaledRotation(rng, 0.7f);
        a.insert(a.end(), m.begin(), m.end());
        r.insert(r.end(), rest.begin(), rest.end());
    }
    std::vector<PaletteEntry> conformalPalette(23);
    PaletteJob pj;
    pj.boneCount = 23;
    pj.boneToMesh = a;
    pj.atRest = r;
    pj.output = conformalPalette;
    pj.positionScale = 0.5f;
    bool conformal = false;
    pj.conformal = &conformal;
    ASSERT_TRUE(pj.run());
    ASSERT_TRUE(conformal);
    std::vector<std::array<float, 16>> skewed;
    for (int b = 0; b < 23; ++b) skewed.push_back(m3gtest::randomAffine(rng));
    const std::vector<PaletteEntry> skewedPalette = m3gtest::paletteAtRestIdentity(skewed);

    ShuffledMesh m(7, 3000, 23, false);
    InfluencePartition part;
    part.build(m.bones, m.weights, m.n, m.vertices, InfluencePartition::kNoInPlaceRuns);
    const auto order = part.compactOrder();
    std::uniform_real_distribution<float> u(-5.0f, 5.0f);
    std::vector<float> cp(order.size() * 3), cn(order.size() * 3);
    for (auto& x : cp) x = u(rng);
    for (auto& x : cn) x = u(rng);
    std::size_t boneRunVertices = 0;
    for (int c = 1; c <= part.maxInfluences(); ++c)
        for (const InfluenceRun& run : part.compactBoneRuns(c)) boneRunVertices += run.vertexCount;
    ASSERT_GT(boneRunVertices, 500u);

    // Every group's bone runs with and without the flag; outputs start as a
    // sentinel, so a vertex left out shows.
    auto skin = [&](const std::vector<PaletteEntry>& pal, Isa isa, bool flag, std::vector<float>& pos,
                    std::vector<float>& nrm) {
        pos.assign(order.size() * 3, -777.0f);
        nrm.assign(order.size() * 3, -777.0f);
        for (int c = 1; c <= part.maxInfluences(); ++c) {
            SkinningJob job = m3gtest::arraysJob({}, {}, order.size(), c, m.n, m.bones, m.weights, pal, cp, cn, pos,
                                                 nrm, isa);
            // The compact arrays in place of the mesh's, and only the bone runs.
            job.boneIndices = part.compactBones();
            job.boneWeights = part.compactWeights();
            job.boneRuns = part.compactBoneRuns(c);
            job.normalsFromPositions = flag;
            ASSERT_TRUE(job.run());
        }
    };
    for (Isa isa : {Isa::Avx2, Isa::Avx512}) {
        if (!isaSupported(isa)) continue;
        SCOPED_TRACE(isaName(isa));
        std::vector<float> pos, nrm, fromPositions, fromPositionsNrm;
        skin(conformalPalette, isa, false, pos, nrm);
        skin(conformalPalette, isa, true, fromPositions, fromPositionsNrm);
        std::size_t skinned = 0;
        for (int c = 1; c <= part.maxInfluences(); ++c)
            for (const InfluenceRun& run : part.compactBoneRuns(c))
                for (std::size_t v = run.firstVertex; v < run.firstVertex + run.vertexCount; ++v, ++skinned) {
                    ASSERT_EQ(0, std::memcmp(&pos[v * 3], &fromPositions[v * 3], 3 * sizeof(float))) << "vertex " << v;
                    float len2 = 0.0f;
                    for (std::size_t e = 0; e < 3; ++e) {
                        ASSERT_NEAR(fromPositionsNrm[v * 3 + e], nrm[v * 3 + e], 1e-5f) << "vertex " << v;
                        len2 += fromPositionsNrm[v * 3 + e] * fromPositionsNrm[v * 3 + e];
                    }
                    ASSERT_NEAR(len2, 1.0f, 1e-5f) << "vertex " << v;
                }
        EXPECT_EQ(skinned, boneRunVertices);

        skin(skewedPalette, isa, false, pos, nrm);
        skin(skewedPalette, isa, true, fromPositions, fromPositionsNrm);
        float worst = 0.0f;
        for (std::size_t i = 0; i < nrm.size(); ++i)
            if (nrm[i] != -777.0f) worst = std::max(worst, std::abs(fromPositionsNrm[i] - nrm[i]));
        EXPECT_GT(worst, 1e-2f) << "the flag made no difference with a non-conformal palette";
    }
}

// SkinningJob::inPositionPlanes / inNormalPlanes: the same inputs as x, y
// and z planes. The lane kernels of runs and bone runs (AVX2, AVX-512)
// read them instead of transposing triples; every path gives the same
// bits with them as without (runs, bone runs with either normal method,
// loose vertices, partial blocks, a position scale and bias applied per
// block). Control: planes that differ from the triples in one run vertex
// change that vertex on AVX2 and AVX-512 only, so their kernels do read
// them and the others do not.
TEST(SkinningJob, InputPlanesGiveTheSameBitsAsTriples) {
    std::mt19937 rng(43);
    std::vector<std::array<float, 16>> bonesToMesh;
    for (int b = 0; b < 23; ++b) bonesToMesh.push_back(m3gtest::randomAffine(rng));
    const std::vector<PaletteEntry> pal = m3gtest::paletteAtRestIdentity(bonesToMesh);
    ShuffledMesh m(11, 2501, 23, false);  // an odd count: partial blocks at the arrays' end
    InfluencePartition part;
    part.build(m.bones, m.weights, m.n, m.vertices, InfluencePartition::kNoInPlaceRuns);
    const std::size_t n = part.compactOrder().size();
    std::uniform_real_distribution<float> u(-5.0f, 5.0f);
    std::vector<float> cp(n * 3), cn(n * 3);
    for (auto& x : cp) x = u(rng);
    for (auto& x : cn) x = u(rng);
    auto planesOf = [n](const std::vector<float>& xyz) {
        std::vector<float> planes(3 * n);
        for (std::size_t v = 0; v < n; ++v)
            for (std::size_t c = 0; c < 3; ++c) planes[c * n + v] = xyz[3 * v + c];
        return planes;
    };
    const std::vector<float> pp = planesOf(cp), np = planesOf(cn);
    std::size_t runVertices = 0, boneRunVertices = 0;
    for (int c = 1; c <= part.maxInfluences(); ++c) {
        for (const InfluenceRun& r : part.compactRuns(c)) runVertices += r.vertexCount;
        for (const InfluenceRun& r : part.compactBoneRuns(c)) boneRunVertices += r.vertexCount;
    }
    ASSERT_GT(runVertices, 500u);
    ASSERT_GT(boneRunVertices, 300u);

    // Every group's runs, bone runs and loose vertices; outputs start as a
    // sentinel, so a vertex left out shows.
    auto skin = [&](Isa isa, bool flag, bool scaled, std::span<const float> positionPlanes,
                    std::span<const float> normalPlanes, std::vector<float>& pos, std::vector<float>& nrm) {
        pos.assign(n * 3, -777.0f);
        nrm.assign(n * 3, -777.0f);
        for (int c = 1; c <= part.maxInfluences(); ++c) {
            SkinningJob job = m3gtest::arraysJob(part.compactLoose(c), part.compactRuns(c), n, c, m.n, m.bones,
                                                 m.weights, pal, cp, cn, pos, nrm, isa);
            job.boneIndices = part.compactBones();
            job.boneWeights = part.compactWeights();
            job.boneRuns = part.compactBoneRuns(c);
            job.normalsFromPositions = flag;
            if (scaled) {
                job.positionScale = 0.75f;
                job.positionBias = {0.5f, -1.0f, 2.0f};
            }
            job.inPositionPlanes = positionPlanes;
            job.inNormalPlanes = normalPlanes;
            ASSERT_TRUE(job.run());
        }
    };
    std::vector<float> altered = pp;
    const std::size_t probe = part.compactRuns(1).empty() ? part.compactRuns(2)[0].firstVertex + 1
                                                          : part.compactRuns(1)[0].firstVertex + 1;
    altered[probe] += 1.0f;  // x of one run vertex
    for (Isa isa : kIsas) {
        if (!isaSupported(isa)) continue;
        for (bool flag : {false, true})
            for (bool scaled : {false, true}) {
                SCOPED_TRACE(std::string(isaName(isa)) + (flag ? ", normals from positions" : "") +
                             (scaled ? ", scale and bias" : ""));
                std::vector<float> pos, nrm, ppos, pnrm;
                skin(isa, flag, scaled, {}, {}, pos, nrm);
                skin(isa, flag, scaled, pp, np, ppos, pnrm);
                for (std::size_t i = 0; i < pos.size(); ++i) {
                    ASSERT_NE(pos[i], -777.0f) << "float " << i;
                    ASSERT_EQ(0, std::memcmp(&pos[i], &ppos[i], sizeof(float))) << "position float " << i;
                    ASSERT_EQ(0, std::memcmp(&nrm[i], &pnrm[i], sizeof(float))) << "normal float " << i;
                }
                skin(isa, flag, scaled, altered, np, ppos, pnrm);
                const bool read = std::memcmp(&pos[probe * 3], &ppos[probe * 3], 3 * sizeof(float)) != 0;
                EXPECT_EQ(read, isa == Isa::Avx2 || isa == Isa::Avx512) << "vertex " << probe;
                for (std::size_t v = 0; v < n; ++v) {
                    if (v == probe) continue;
                    ASSERT_EQ(0, std::memcmp(&pos[v * 3], &ppos[v * 3], 3 * sizeof(float))) << v;
                }
            }
    }

    // validate(): planes hold every vertex; normal planes only with normals.
    std::vector<float> pos(n * 3), nrm(n * 3);
    SkinningJob job = m3gtest::arraysJob(part.compactLoose(1), part.compactRuns(1), n, 1, m.n, m.bones, m.weights,
                                         pal, cp, cn, pos, nrm, Isa::Auto);
    job.boneIndices = part.compactBones();
    job.boneWeights = part.compactWeights();
    job.inPositionPlanes = pp;
    job.inNormalPlanes = np;
    EXPECT_TRUE(job.validate());
    job.inPositionPlanes = std::span<const float>(pp).first(3 * n - 1);
    EXPECT_FALSE(job.validate()) << "position planes one float short";
    job.inPositionPlanes = pp;
    job.inNormalPlanes = std::span<const float>(np).first(3 * n - 1);
    EXPECT_FALSE(job.validate()) << "normal planes one float short";
    job.inNormalPlanes = np;
    job.inNormals = {};
    job.outNormals = {};
    EXPECT_FALSE(job.validate()) << "normal planes without normals";
    job.inNormalPlanes = {};
    EXPECT_TRUE(job.validate()) << "position planes alone (not read: no normals)";
}

// scatterXyz writes three floats per listed vertex and nothing else.
TEST(SkinningJob, ScatterXyzWritesOnlyTheListedTriples) {
    const std::vector<std::uint32_t> order{4, 0, 2};
    const std::vector<float> in{1, 2, 3, 4, 5, 6, 7, 8, 9};
    std::vector<float> out(16, -1.0f);
    scatterXyz(order, in.data(), out.data());
    const std::vector<float> expect{4, 5, 6, -1, -1, -1, 7, 8, 9, -1, -1, -1, 1, 2, 3, -1};
    EXPECT_EQ(out, expect);
    std::vector<float> a(16, -1.0f), b(16, -1.0f);
    const std::vector<float> in2{10, 20, 30, 40, 50, 60, 70, 80, 90};
    scatterXyz(order, in.data(), a.data(), in2.data(), b.data());
    EXPECT_EQ(a, expect);
    const std::vector<float> expect2{40, 50, 60, -1, -1, -1, 70, 80, 90, -1, -1, -1, 10, 20, 30, -1};
    EXPECT_EQ(b, expect2);
}
