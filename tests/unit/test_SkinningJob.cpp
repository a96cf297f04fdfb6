// skin::SkinningJob, skin::InfluencePartition and skin::ThreadPool
// (JSR-184 1.1, SkinnedMesh). Three parts, as in ozz-animation's job tests:
// validity, exact hand-computed results (every ISA path forced), and
// agreement of every path with a double-precision reference and with the
// founding paper's baseline on random meshes. (The benchmark is
// tests/bench/bench_skin.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <m3g/skin/InfluenceTable.h>
#include <m3g/skin/Palette.h>
#include <m3g/skin/Skinning.h>
#include <m3g/skin/ThreadPool.h>

#include "SkinRandomMesh.h"
#include "SkinReference.h"

using namespace m3g::skin;
using Mat = std::array<float, 16>;

namespace {

constexpr Mat kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
Mat translation(float x, float y, float z) { return {1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, z, 0, 0, 0, 1}; }
const Mat kRz90{0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // x -> y, y -> -x

std::vector<PaletteEntry> palette(const std::vector<Mat>& boneToMesh) { return m3gtest::paletteAtRestIdentity(boneToMesh); }

const std::vector<Isa> kPaths{Isa::Scalar, Isa::Sse2, Isa::Avx2, Isa::Avx512};

/// A one-vertex job: influences (bone, weight) on vertex 0, stride `stride`.
struct OneVertex {
    std::vector<PaletteEntry> pal;
    std::vector<std::int32_t> bones;
    std::vector<float> weights;
    std::vector<float> in{0, 0, 0}, nin{0, 0, 1}, out{9, 9, 9}, nout{9, 9, 9};
    std::vector<std::uint32_t> list{0};
    SkinningJob job;
    OneVertex(const std::vector<Mat>& mats, const std::vector<std::pair<int, float>>& infl, int stride = 4)
        : pal(palette(mats)) {
        bones.assign(static_cast<std::size_t>(stride), -1);
        weights.assign(static_cast<std::size_t>(stride), 0.0f);
        for (std::size_t k = 0; k < infl.size(); ++k) {
            bones[k] = infl[k].first;
            weights[k] = infl[k].second;
        }
        job = m3gtest::arraysJob(list, {}, 1, static_cast<int>(infl.size()), stride, bones, weights, pal, in, nin, out,
                                 nout, Isa::Auto);
    }
    bool run(Isa isa, std::array<float, 3> p, std::array<float, 3> n) {
        std::copy(p.begin(), p.end(), in.begin());
        std::copy(n.begin(), n.end(), nin.begin());
        job.isa = isa;
        return job.run();
    }
};

#define SKIP_IF_UNSUPPORTED(isa) \
    if (!isaSupported(isa)) GTEST_SKIP() << isaName(isa) << " not supported by this CPU"

class SkinningPaths : public ::testing::TestWithParam<Isa> {};

void expectXyz(const std::vector<float>& v, float x, float y, float z, const char* what) {
    EXPECT_NEAR(v[0], x, 1e-6f) << what << " x";
    EXPECT_NEAR(v[1], y, 1e-6f) << what << " y";
    EXPECT_NEAR(v[2], z, 1e-6f) << what << " z";
}

}  // namespace

// ---------------------------------------------------------------- validity

TEST(SkinningJob, ValidateAcceptsAWellFormedJob) {
    OneVertex f({translation(1, 2, 3)}, {{0, 1.0f}});
    EXPECT_TRUE(f.job.validate());
    SkinningJob empty;
    EXPECT_TRUE(empty.validate());  // no vertices
    EXPECT_TRUE(empty.run());
}

TEST(SkinningJob, ValidateRejectsBadCountsAndIndices) {
    {
        OneVertex f({translation(1, 2, 3)}, {{0, 1.0f}});
        f.job.influenceCount = -1;
        EXPECT_FALSE(f.job.validate());
        EXPECT_FALSE(f.job.run());
        expectXyz(f.out, 9, 9, 9, "untouched after a failed run");
    }
    {
        OneVertex f({translation(1, 2, 3)}, {{0, 1.0f}});
        f.job.influenceCount = 5;  // above the stride (4)
        EXPECT_FALSE(f.job.validate());
    }
    {
        OneVertex f({translation(1, 2, 3)}, {{0, 1.0f}});
        f.list[0] = 1;  // vertex beyond vertexCount
        EXPECT_FALSE(f.job.validate());
    }
    {
        // Influence arrays that do not reach the listed vertex 1 (stride 4:
        // vertex 1 needs 4 + 1 values).
        OneVertex f({translation(1, 2, 3)}, {{0, 1.0f}});
        f.in.resize(6);
        f.out.resize(6);
        f.nin.resize(6);
        f.nout.resize(6);
        f.list = {0, 1};
        f.job.vertices = f.list;
        f.job.vertexCount = 2;
        f.job.inPositions = f.in;
        f.job.outPositions = f.out;
        f.job.inNormals = f.nin;
        f.job.outNormals = f.nout;
        EXPECT_FALSE(f.job.validate());
        f.bones.resize(5, 0);
        f.weights.resize(5, 1.0f);
        f.job.boneIndices = f.bones;
        f.job.boneWeights = f.weights;
        EXPECT_TRUE(f.job.validate());
    }
    {
        OneVertex f({translation(1, 2, 3)}, {{0, 1.0f}});
        f.job.boneWeights = std::span<const float>(f.weights).first(0);  // too short
        EXPECT_FALSE(f.job.validate());
    }
    {
        OneVertex f({translation(1, 2, 3)}, {{0, 1.0f}});
        f.job.boneIndices = {};
        EXPECT_FALSE(f.job.validate());
    }
}

TEST(SkinningJob, ValidateRejectsShortArraysAndBadStrides) {
    auto check = [](auto mutate) {
        OneVertex f({translation(1, 2, 3)}, {{0, 1.0f}});
        mutate(f);
        return f.job.validate();
    };
    EXPECT_FALSE(check([](OneVertex& f) { f.job.inPositions = std::span<const float>(f.in).first(2); }));
    EXPECT_FALSE(check([](OneVertex& f) { f.job.outPositions = std::span<float>(f.out).first(2); }));
    EXPECT_FALSE(check([](OneVertex& f) { f.job.inNormals = std::span<const float>(f.nin).first(2); }));
    EXPECT_FALSE(check([](OneVertex& f) { f.job.outNormals = std::span<float>(f.nout).first(2); }));
    EXPECT_FALSE(check([](OneVertex& f) { f.job.inPositionStride = 2; }));
    EXPECT_FALSE(check([](OneVertex& f) { f.job.outNormalStride = 1; }));
    // Normals in without normals out (or the reverse).
    EXPECT_FALSE(check([](OneVertex& f) { f.job.outNormals = {}; }));
    EXPECT_FALSE(check([](OneVertex& f) { f.job.inNormals = {}; }));
    EXPECT_TRUE(check([](OneVertex& f) {
        f.job.inNormals = {};
        f.job.outNormals = {};
    }));
    // Two vertices need (2 - 1) * stride + 3 floats.
    EXPECT_FALSE(check([](OneVertex& f) { f.job.vertexCount = 2; }));
    // Three vertices with every array long enough; then an input stride
    // whose reach, 2 * 2^63, overflows size_t: rejected, not wrapped to a
    // reach of 0 that three floats would seem to hold.
    const auto threeVertices = [](OneVertex& f) {
        for (auto* a : {&f.in, &f.nin, &f.out, &f.nout}) a->resize(9);
        f.bones.resize(12, -1);
        f.weights.resize(12, 0.0f);
        f.job.vertexCount = 3;
        f.job.inPositions = f.in;
        f.job.inNormals = f.nin;
        f.job.outPositions = f.out;
        f.job.outNormals = f.nout;
        f.job.boneIndices = f.bones;
        f.job.boneWeights = f.weights;
    };
    EXPECT_TRUE(check(threeVertices));
    EXPECT_FALSE(check([&](OneVertex& f) {
        threeVertices(f);
        f.job.inPositionStride = (std::numeric_limits<std::size_t>::max() >> 1) + 1;
    }));
    // An ISA the CPU lacks is rejected, a supported one accepted.
    EXPECT_EQ(check([](OneVertex& f) { f.job.isa = Isa::Avx2; }), isaSupported(Isa::Avx2));
    EXPECT_EQ(check([](OneVertex& f) { f.job.isa = Isa::Avx512; }), isaSupported(Isa::Avx512));
}

TEST(SkinningJob, IsaHelpers) {
    EXPECT_TRUE(isaSupported(Isa::Scalar));
    EXPECT_TRUE(isaSupported(Isa::Auto));
    EXPECT_NE(resolveIsa(Isa::Auto), Isa::Auto);
    EXPECT_TRUE(isaSupported(resolveIsa(Isa::Auto)));
    EXPECT_EQ(resolveIsa(Isa::Sse2), Isa::Sse2);
    EXPECT_STREQ(isaName(Isa::Avx2), "avx2");
    EXPECT_STREQ(isaName(Isa::Avx512), "avx512");
    // AVX-512 kernels need AVX2 and FMA beside them (the list path).
    if (isaSupported(Isa::Avx512)) {
        EXPECT_TRUE(isaSupported(Isa::Avx2));
    }
    EXPECT_STREQ(isaName(Isa::Sse2), "sse2");
    EXPECT_STREQ(isaName(Isa::Scalar), "scalar");
#if defined(__x86_64__)
    EXPECT_TRUE(isaSupported(Isa::Sse2));  // the x86-64 baseline
#endif
}

// ---------------------------------------------------- hand-computed results

TEST_P(SkinningPaths, NoInfluenceAppliesScaleBiasAndRenormalises) {
    SKIP_IF_UNSUPPORTED(GetParam());
    OneVertex f({translation(1, 2, 3)}, {});
    f.job.positionScale = 2.0f;
    f.job.positionBias = {1, 2, 3};
    // 2 * (1, 1, 1) + (1, 2, 3) = (3, 4, 5); (0, 3, 4) / 5.
    ASSERT_TRUE(f.run(GetParam(), {1, 1, 1}, {0, 3, 4}));
    expectXyz(f.out, 3, 4, 5, "position");
    expectXyz(f.nout, 0, 0.6f, 0.8f, "normal");
}

TEST_P(SkinningPaths, OneInfluence) {
    SKIP_IF_UNSUPPORTED(GetParam());
    OneVertex f({translation(1, 2, 3), kRz90}, {{0, 1.0f}});
    ASSERT_TRUE(f.run(GetParam(), {1, 0, 0}, {1, 0, 0}));
    expectXyz(f.out, 2, 2, 3, "translated");
    expectXyz(f.nout, 1, 0, 0, "translation leaves normals");
    f.bones[0] = 1;  // Rz(90): (1, 0, 0) -> (0, 1, 0) for both
    ASSERT_TRUE(f.run(GetParam(), {1, 0, 0}, {1, 0, 0}));
    expectXyz(f.out, 0, 1, 0, "rotated");
    expectXyz(f.nout, 0, 1, 0, "rotated normal");
    // Scale and bias come first: Rz90 (0.5 * (2, 0, 0) + (0, 0, 1)) = (0, 1, 1).
    f.job.positionScale = 0.5f;
    f.job.positionBias = {0, 0, 1};
    ASSERT_TRUE(f.run(GetParam(), {2, 0, 0}, {0, 0, 1}));
    expectXyz(f.out, 0, 1, 1, "scale, bias, then bone");
}

TEST_P(SkinningPaths, TwoInfluences) {
    SKIP_IF_UNSUPPORTED(GetParam());
    // 0.25 T(4, 0, 0) + 0.75 T(0, 8, 0) on the origin = (1, 6, 0).
    OneVertex f({translation(4, 0, 0), translation(0, 8, 0)}, {{0, 0.25f}, {1, 0.75f}});
    ASSERT_TRUE(f.run(GetParam(), {0, 0, 0}, {0, 0, 1}));
    expectXyz(f.out, 1, 6, 0, "position");
    expectXyz(f.nout, 0, 0, 1, "normal");
    // Half identity, half Rz(90): n = (1, 0, 0) -> (0.5, 0.5, 0) -> (1, 1, 0) / sqrt 2;
    // p = (2, 0, 0) -> 0.5 (2, 0, 0) + 0.5 (0, 2, 0) = (1, 1, 0).
    OneVertex g({kIdentity, kRz90}, {{0, 0.5f}, {1, 0.5f}});
    ASSERT_TRUE(g.run(GetParam(), {2, 0, 0}, {1, 0, 0}));
    expectXyz(g.out, 1, 1, 0, "blended rotation");
    const float h = std::sqrt(0.5f);
    expectXyz(g.nout, h, h, 0, "blended normal, renormalised");
}

TEST_P(SkinningPaths, ThreeInfluences) {
    SKIP_IF_UNSUPPORTED(GetParam());
    // (1, 1, 1) + 0.25 (4, 0, 0) + 0.25 (0, 8, 0) + 0.5 (0, 0, 2) = (2, 3, 2).
    OneVertex f({translation(4, 0, 0), translation(0, 8, 0), translation(0, 0, 2)},
                {{0, 0.25f}, {1, 0.25f}, {2, 0.5f}});
    ASSERT_TRUE(f.run(GetParam(), {1, 1, 1}, {0, 1, 0}));
    expectXyz(f.out, 2, 3, 2, "position");
    expectXyz(f.nout, 0, 1, 0, "normal");
}

TEST_P(SkinningPaths, FourInfluences) {
    SKIP_IF_UNSUPPORTED(GetParam());
    // (1, 2, 3) + 0.1 (10, 0, 0) + 0.2 (0, 10, 0) + 0.3 (0, 0, 10) + 0.4 (-10, -10, -10)
    //   = (1 + 1 - 4, 2 + 2 - 4, 3 + 3 - 4) = (-2, 0, 2).
    OneVertex f({translation(10, 0, 0), translation(0, 10, 0), translation(0, 0, 10), translation(-10, -10, -10)},
                {{0, 0.1f}, {1, 0.2f}, {2, 0.3f}, {3, 0.4f}});
    ASSERT_TRUE(f.run(GetParam(), {1, 2, 3}, {0, 0, -1}));
    expectXyz(f.out, -2, 0, 2, "position");
    expectXyz(f.nout, 0, 0, -1, "normal");
}

TEST_P(SkinningPaths, MoreThanFourInfluencesUseTheGenericLoop) {
    SKIP_IF_UNSUPPORTED(GetParam());
    // Five bones at 0.2 each: 0.2 ((5,0,0) + (0,5,0) + (0,0,5) + (-5,0,0) + 0) = (0, 1, 1).
    OneVertex f({translation(5, 0, 0), translation(0, 5, 0), translation(0, 0, 5), translation(-5, 0, 0), kIdentity},
                {{0, 0.2f}, {1, 0.2f}, {2, 0.2f}, {3, 0.2f}, {4, 0.2f}}, 6);
    ASSERT_TRUE(f.run(GetParam(), {0, 0, 0}, {1, 0, 0}));
    expectXyz(f.out, 0, 1, 1, "position");
    expectXyz(f.nout, 1, 0, 0, "normal");
}

TEST_P(SkinningPaths, NonUniformScaleTransformsNormalsByTheInverseTranspose) {
    SKIP_IF_UNSUPPORTED(GetParam());
    // Bone scales x by 2. p = (1, 1, 0) -> (2, 1, 0). The surface with normal
    // (1, 1, 0) becomes steeper in x: n -> diag(1/2, 1, 1) n = (0.5, 1, 0),
    // i.e. (1, 2, 0) / sqrt 5 (the plain matrix would give (2, 1, 0)).
    const Mat s{2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    OneVertex f({s}, {{0, 1.0f}});
    const float r = std::sqrt(0.5f);
    ASSERT_TRUE(f.run(GetParam(), {1, 1, 0}, {r, r, 0}));
    expectXyz(f.out, 2, 1, 0, "position");
    const float k = 1.0f / std::sqrt(5.0f);
    expectXyz(f.nout, k, 2 * k, 0, "normal");
}

TEST_P(SkinningPaths, ZeroNormalStaysZeroAndNormalsAreOptional) {
    SKIP_IF_UNSUPPORTED(GetParam());
    OneVertex f({kRz90}, {{0, 1.0f}});
    ASSERT_TRUE(f.run(GetParam(), {1, 0, 0}, {0, 0, 0}));
    expectXyz(f.nout, 0, 0, 0, "zero normal");
    f.job.inNormals = {};
    f.job.outNormals = {};
    f.nout = {7, 7, 7};
    ASSERT_TRUE(f.run(GetParam(), {0, 1, 0}, {0, 0, 0}));
    expectXyz(f.out, -1, 0, 0, "position without normals");
}

TEST_P(SkinningPaths, OutOfRangeBoneIndicesContributeNothing) {
    SKIP_IF_UNSUPPORTED(GetParam());
    // Three vertices with two slots each (stride 2), all at (1, 0, 0) with
    // normal (0, 0, 1). Palette: T(1, 0, 0), T(0, 2, 0).
    //  v0: (0, 0.5) (1, 0.5)       -> (1,0,0) + 0.5 (1,0,0) + 0.5 (0,2,0) = (1.5, 1, 0)
    //  v1: (0, 0.5) (-1, 0.5)      -> only bone 0 counts: 0.5 (2, 0, 0) = (1, 0, 0)
    //  v2: (7, 0.25) (1, 0.75)     -> only bone 1 counts: 0.75 (1, 2, 0) = (0.75, 1.5, 0)
    // The SIMD paths take a checked fallback for v1 and v2; v0 shares their
    // normal batch and is unaffected.
    const auto pal = palette({translation(1, 0, 0), translation(0, 2, 0)});
    std::vector<float> pin{1, 0, 0, 1, 0, 0, 1, 0, 0}, nin{0, 0, 1, 0, 0, 1, 0, 0, 1};
    std::vector<float> pout(9, 9.0f), nout(9, 9.0f);
    std::vector<std::int32_t> bones{0, 1, 0, -1, 7, 1};
    std::vector<float> weights{0.5f, 0.5f, 0.5f, 0.5f, 0.25f, 0.75f};
    std::vector<std::uint32_t> list{0, 1, 2};
    SkinningJob job;
    job.vertices = list;
    job.vertexCount = 3;
    job.influenceCount = 2;
    job.influenceStride = 2;
    job.boneIndices = bones;
    job.boneWeights = weights;
    job.palette = pal;
    job.inPositions = pin;
    job.inNormals = nin;
    job.outPositions = pout;
    job.outNormals = nout;
    job.isa = GetParam();
    ASSERT_TRUE(job.validate());
    ASSERT_TRUE(job.run());
    const std::vector<float> expected{1.5f, 1, 0, 1, 0, 0, 0.75f, 1.5f, 0};
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(pout[i], expected[i], 1e-6f) << "position float " << i;
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(nout[i], i % 3 == 2 ? 1.0f : 0.0f, 1e-6f) << "normal float " << i;
    // A palette with no entries: no slot counts, the positions collapse to 0.
    job.palette = {};
    ASSERT_TRUE(job.run());
    for (int i = 0; i < 9; ++i) EXPECT_EQ(pout[i], 0.0f) << "empty palette, float " << i;
}

TEST_P(SkinningPaths, StridesListedVerticesOnlyAndPaddingUntouched) {
    SKIP_IF_UNSUPPORTED(GetParam());
    // Three vertices, positions at stride 5, normals at stride 4, outputs at
    // stride 6 and 4; only vertices 2 and 0 are listed (in that order).
    const auto pal = palette({translation(1, 0, 0), translation(0, 0, -1)});
    std::vector<float> pin{1, 1, 1, -1, -1, /**/ 5, 5, 5, -1, -1, /**/ 2, 2, 2};
    std::vector<float> nin{3, 0, 0, -1, /**/ 0, 5, 0, -1, /**/ 0, 0, 2};
    std::vector<float> pout(6 * 2 + 3, 9.0f), nout(4 * 2 + 3, 9.0f);
    std::vector<std::int32_t> bones{0, 1, 1, 0, 1, 0};  // stride 2
    std::vector<float> weights{0.5f, 0.5f, 1, 0, 1, 0};
    std::vector<std::uint32_t> list{2, 0};
    SkinningJob job;
    job.vertices = list;
    job.vertexCount = 3;
    job.influenceCount = 1;
    job.influenceStride = 2;
    job.boneIndices = bones;
    job.boneWeights = weights;
    job.palette = pal;
    job.inPositions = pin;
    job.inPositionStride = 5;
    job.inNormals = nin;
    job.inNormalStride = 4;
    job.outPositions = pout;
    job.outPositionStride = 6;
    job.outNormals = nout;
    job.outNormalStride = 4;
    job.isa = GetParam();
    ASSERT_TRUE(job.run());
    // Vertex 0 uses only slot 0 (influenceCount 1): bone 0, weight 0.5 ->
    // 0.5 * ((1, 1, 1) + (1, 0, 0)) = (1, 0.5, 0.5).
    const std::vector<float> expectedP{1, 0.5f, 0.5f, 9, 9, 9, 9, 9, 9, 9, 9, 9, 2, 2, 1};
    const std::vector<float> expectedN{1, 0, 0, 9, 9, 9, 9, 9, 0, 0, 1};
    for (std::size_t i = 0; i < pout.size(); ++i) EXPECT_NEAR(pout[i], expectedP[i], 1e-6f) << "position float " << i;
    for (std::size_t i = 0; i < nout.size(); ++i) EXPECT_NEAR(nout[i], expectedN[i], 1e-6f) << "normal float " << i;
}

INSTANTIATE_TEST_SUITE_P(Isa, SkinningPaths, ::testing::ValuesIn(kPaths),
                         [](const auto& p) { return std::string(isaName(p.param)); });

// --------------------------------------------------------------- partition

TEST(InfluencePartition, GroupsVerticesByFilledSlots) {
    // Stride 3: v0 two bones, v1 none, v2 three, v3 one, v4 two.
    const std::vector<std::int32_t> bones{4, 1, -1, -1, -1, -1, 0, 1, 2, 7, -1, -1, 2, 3, -1};
    InfluencePartition p;
    p.build(bones, 3, 7);  // vertices 5 and 6 lie beyond the table: no influence
    EXPECT_EQ(p.maxInfluences(), 3);
    auto as = [](std::span<const std::uint32_t> s) { return std::vector<std::uint32_t>(s.begin(), s.end()); };
    EXPECT_EQ(as(p.group(0)), (std::vector<std::uint32_t>{1, 5, 6}));
    EXPECT_EQ(as(p.group(1)), (std::vector<std::uint32_t>{3}));
    EXPECT_EQ(as(p.group(2)), (std::vector<std::uint32_t>{0, 4}));
    EXPECT_EQ(as(p.group(3)), (std::vector<std::uint32_t>{2}));
    EXPECT_TRUE(p.group(4).empty());
    EXPECT_TRUE(p.group(-1).empty());
    // Fewer vertices than the table: the rest is ignored.
    p.build(bones, 3, 2);
    EXPECT_EQ(as(p.group(0)), (std::vector<std::uint32_t>{1}));
    EXPECT_EQ(as(p.group(2)), (std::vector<std::uint32_t>{0}));
    EXPECT_TRUE(p.group(3).empty());
    InfluencePartition none;
    EXPECT_TRUE(none.group(0).empty());
}

// ------------------------------------------------------------- thread pool

TEST(ThreadPool, RunsEveryTaskOnceWithAnyThreadCount) {
    for (int threads : {1, 2, 3, 8}) {
        ThreadPool pool(threads);
        EXPECT_EQ(pool.threadCount(), threads);
        for (std::size_t tasks : {0u, 1u, 5u, 1000u}) {
            std::vector<std::atomic<int>> hits(tasks);
            auto f = [&](std::size_t i) { hits[i].fetch_add(1); };
            pool.parallelFor(tasks, f);
            for (std::size_t i = 0; i < tasks; ++i) ASSERT_EQ(hits[i].load(), 1) << threads << " threads, task " << i;
        }
    }
}

TEST(ThreadPool, ConcurrentCallersAreSafe) {
    ThreadPool pool(3);
    std::atomic<long> total{0};
    auto caller = [&] {
        for (int round = 0; round < 50; ++round) {
            auto f = [&](std::size_t i) { total.fetch_add(static_cast<long>(i)); };
            pool.parallelFor(100, f);
        }
    };
    std::thread a(caller), b(caller);
    a.join();
    b.join();
    EXPECT_EQ(total.load(), 2L * 50 * (99 * 100 / 2));
}

// ------------------------------------- random meshes: every path agrees

using m3gtest::meshJob;
using m3gtest::paletteOf;
using m3gtest::RandomMesh;
using m3gtest::skinAll;

TEST(SkinningJob, EveryPathAgreesWithDoubleReferenceAndPaperBaseline) {
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        // 1500 vertices, 30 bones, 400 overlapping records with small integer
        // weights: vertices get 0 .. 10+ bones, so top-N selection and its tie
        // rule are exercised, as are all four specialised kernels.
        RandomMesh m(seed, 1500, 30, 400);
        InfluencePartition part;
        part.build(m.table.bones(), m.n, m.vertices);
        for (int c = 0; c <= 4; ++c) EXPECT_FALSE(part.group(c).empty()) << "seed " << seed << " count " << c;

        const std::vector<double> mesh = m.meshSpace();
        const std::vector<double> a(m.boneToMesh.begin(), m.boneToMesh.end()), r(m.atRest.begin(), m.atRest.end());
        const std::vector<double> n(m.normals.begin(), m.normals.end());
        const auto ref = m3gtest::referenceSkin(m.records, m.n, a, r, m.vertices, mesh, n);

        // The paper's baseline (float, list searched per vertex).
        std::vector<float> meshF(mesh.begin(), mesh.end()), bp(m.vertices * 3), bn(m.vertices * 3);
        m3gbench::SkinBaseline baseline(m.n);
        baseline.deform(m.records, m.boneToMesh.size() / 16, m.boneToMesh, m.atRest, m.vertices, meshF, m.normals,
                        bp, bn);
        EXPECT_TRUE(m3gtest::closeXyz(bp, ref.positions)) << "baseline positions, seed " << seed;
        EXPECT_TRUE(m3gtest::closeXyz(bn, ref.normals)) << "baseline normals, seed " << seed;

        const auto pal = paletteOf(m);
        for (Isa isa : kPaths) {
            if (!isaSupported(isa)) continue;
            for (bool runs : {false, true}) {
                const std::string what = std::string(isaName(isa)) + (runs ? " runs" : " lists");
                std::vector<float> pos, nrm;
                skinAll(m, pal, isa, pos, nrm, nullptr, 4096, runs);
                EXPECT_TRUE(m3gtest::closeXyz(pos, ref.positions)) << what << " positions, seed " << seed;
                EXPECT_TRUE(m3gtest::closeXyz(nrm, ref.normals)) << what << " normals, seed " << seed;
                EXPECT_TRUE(m3gtest::closeXyz(pos, bp)) << what << " vs baseline, seed " << seed;
            }
        }
    }
}

TEST(SkinningJob, ParallelRunIsBitIdenticalForAnyThreadCount) {
    RandomMesh m(7, 5000, 40, 1200);
    const auto pal = paletteOf(m);
    for (Isa isa : kPaths) {
        if (!isaSupported(isa)) continue;
        for (bool runs : {false, true}) {
            std::vector<float> pos, nrm;
            skinAll(m, pal, isa, pos, nrm, nullptr, 4096, runs);
            for (int threads : {1, 2, 3, 5}) {
                ThreadPool pool(threads);
                for (std::size_t grain : {1u, 7u, 256u}) {
                    std::vector<float> p2, n2;
                    skinAll(m, pal, isa, p2, n2, &pool, grain, runs);
                    const std::string what = std::string(isaName(isa)) + (runs ? " runs, " : " lists, ") +
                                             std::to_string(threads) + " threads, grain " + std::to_string(grain);
                    EXPECT_EQ(0, std::memcmp(pos.data(), p2.data(), pos.size() * sizeof(float))) << what;
                    EXPECT_EQ(0, std::memcmp(nrm.data(), n2.data(), nrm.size() * sizeof(float))) << what;
                }
            }
        }
    }
}

// Runs of vertices sharing their bones and weights (what addTransform ranges
// give), passed as plain vertex lists (the list kernel, not InfluenceRun),
// runs not aligned to its 8-vertex blocks (13 vertices), a list that is the whole
// mesh (consecutive) or every other vertex, and chunk grains that cut blocks:
// every path agrees with the double reference, and the parallel runs are
// bit-identical to run().
TEST(SkinningJob, SharedInfluenceRunsAgreeAndAreBitIdenticalAcrossChunks) {
    for (int k = 1; k <= 4; ++k) {
        for (int run : {16, 13}) {
            RandomMesh m(100u + static_cast<std::uint32_t>(k), 3001, 30, k, run);
            const auto pal = paletteOf(m);
            const std::vector<double> mesh = m.meshSpace();
            const std::vector<double> a(m.boneToMesh.begin(), m.boneToMesh.end()), r(m.atRest.begin(), m.atRest.end());
            const std::vector<double> n(m.normals.begin(), m.normals.end());
            const auto ref = m3gtest::referenceSkin(m.records, m.n, a, r, m.vertices, mesh, n);
            std::vector<std::uint32_t> all(m.vertices), odd;
            std::iota(all.begin(), all.end(), 0u);
            for (std::uint32_t v = 1; v < m.vertices; v += 2) odd.push_back(v);
            for (Isa isa : kPaths) {
                if (!isaSupported(isa)) continue;
                for (const auto* list : {&all, &odd}) {
                    const std::string what = std::string(isaName(isa)) + ", " + std::to_string(k) + " influences, run " +
                                             std::to_string(run) + (list == &odd ? ", odd vertices" : ", all vertices");
                    auto skin = [&](std::vector<float>& pos, std::vector<float>& nrm, ThreadPool* pool,
                                    std::size_t grain) {
                        pos.assign(m.vertices * 3, -999.0f);
                        nrm.assign(m.vertices * 3, -999.0f);
                        SkinningJob job = meshJob(m, *list, k, pal, isa, pos, nrm);
                        return pool ? job.runParallel(*pool, grain) : job.run();
                    };
                    std::vector<float> pos, nrm;
                    ASSERT_TRUE(skin(pos, nrm, nullptr, 0)) << what;
                    std::vector<double> refP(m.vertices * 3, -999.0), refN(m.vertices * 3, -999.0);
                    for (std::uint32_t v : *list)
                        for (int c = 0; c < 3; ++c) {
                            refP[v * 3 + c] = ref.positions[v * 3 + c];
                            refN[v * 3 + c] = ref.normals[v * 3 + c];
                        }
                    EXPECT_TRUE(m3gtest::closeXyz(pos, refP)) << what << " positions";
                    EXPECT_TRUE(m3gtest::closeXyz(nrm, refN)) << what << " normals";
                    for (int threads : {1, 2, 3}) {
                        ThreadPool pool(threads);
                        for (std::size_t grain : {1u, 5u, 7u, 12u, 256u}) {
                            std::vector<float> p2, n2;
                            ASSERT_TRUE(skin(p2, n2, &pool, grain)) << what;
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
}

// Influence arrays that end right after the last vertex's used slots (stride
// 4, 2 influences: the last vertex's slots 2 and 3 are not there): valid, and
// every path gives the same results (no path may read the missing slots).
TEST(SkinningJob, ShortInfluenceArraysAreReadOnlyWhereValid) {
    const std::vector<PaletteEntry> pal = palette({translation(1, 2, 3), kRz90});
    const std::size_t n = 16;
    std::vector<std::int32_t> bones;
    std::vector<float> weights;
    for (std::size_t v = 0; v < n; ++v) {
        bones.insert(bones.end(), {0, 1, -1, -1});
        weights.insert(weights.end(), {0.25f, 0.75f, 0.0f, 0.0f});
    }
    bones.resize((n - 1) * 4 + 2);
    weights.resize((n - 1) * 4 + 2);
    std::vector<float> in(n * 3), nin(n * 3);
    for (std::size_t i = 0; i < n * 3; ++i) {
        in[i] = static_cast<float>(i % 7) - 3.0f;
        nin[i] = static_cast<float>(i % 5) - 1.5f;
    }
    std::vector<std::uint32_t> list(n);
    std::iota(list.begin(), list.end(), 0u);
    std::vector<float> expectP, expectN;
    for (Isa isa : kPaths) {
        if (!isaSupported(isa)) continue;
        std::vector<float> out(n * 3, -9.0f), nout(n * 3, -9.0f);
        SkinningJob job = m3gtest::arraysJob(list, {}, n, 2, 4, bones, weights, pal, in, nin, out, nout, isa);
        ASSERT_TRUE(job.run()) << isaName(isa);
        if (expectP.empty()) {
            expectP = out;
            expectN = nout;
            continue;
        }
        for (std::size_t i = 0; i < n * 3; ++i) {
            EXPECT_NEAR(out[i], expectP[i], 1e-5f) << isaName(isa) << " position " << i;
            EXPECT_NEAR(nout[i], expectN[i], 1e-5f) << isaName(isa) << " normal " << i;
        }
    }
}
