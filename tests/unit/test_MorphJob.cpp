// skin::MorphJob: B + sum_i w_i (T_i - B) (JSR-184 1.1, MorphingMesh). Validity,
// hand-computed results on every ISA path, agreement with a double-precision
// evaluation on random data, and split/thread independence.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <span>
#include <vector>

#include <m3g/skin/Morph.h>
#include <m3g/skin/ThreadPool.h>

using namespace m3g::skin;

namespace {

const std::vector<Isa> kPaths{Isa::Scalar, Isa::Sse2, Isa::Avx2, Isa::Avx512};

#define SKIP_IF_UNSUPPORTED(isa) \
    if (!isaSupported(isa)) GTEST_SKIP() << isaName(isa) << " not supported by this CPU"

class MorphPaths : public ::testing::TestWithParam<Isa> {};

struct Morph {
    std::vector<float> base;
    std::vector<std::vector<float>> targets;
    std::vector<std::span<const float>> spans;
    std::vector<float> weights;
    std::vector<float> out;
    MorphJob job;
    Morph(std::vector<float> b, std::vector<std::vector<float>> t, std::vector<float> w)
        : base(std::move(b)), targets(std::move(t)), weights(std::move(w)), out(base.size(), -99.0f) {
        for (const auto& x : targets) spans.emplace_back(x);
        job.base = base;
        job.targets = spans;
        job.weights = weights;
        job.output = out;
    }
};

}  // namespace

TEST(MorphJob, ValidateChecksSizes) {
    Morph m({1, 2, 3}, {{4, 5, 6}, {7, 8, 9}}, {0.5f, 0.5f});
    EXPECT_TRUE(m.job.validate());
    MorphJob empty;
    EXPECT_TRUE(empty.validate());
    EXPECT_TRUE(empty.run());
    {
        Morph f({1, 2, 3}, {{4, 5, 6}, {7, 8, 9}}, {0.5f});  // one weight for two targets
        EXPECT_FALSE(f.job.validate());
        EXPECT_FALSE(f.job.run());
        EXPECT_EQ(f.out[0], -99.0f);
    }
    {
        Morph f({1, 2, 3}, {{4, 5, 6}, {7, 8}}, {0.5f, 0.5f});  // short target
        EXPECT_FALSE(f.job.validate());
    }
    {
        Morph f({1, 2, 3}, {{4, 5, 6}}, {0.5f});
        f.job.output = std::span<float>(f.out).first(2);
        EXPECT_FALSE(f.job.validate());
    }
    {
        Morph f({1, 2, 3}, {{4, 5, 6}}, {0.5f});
        f.job.clamp = true;
        f.job.clampMin = 1.0f;
        f.job.clampMax = 0.0f;
        EXPECT_FALSE(f.job.validate());
    }
    {
        Morph f({1, 2, 3, 4}, {{4, 5, 6, 7}}, {0.5f});
        f.job.normalize = true;  // 4 values are not xyz triples
        EXPECT_FALSE(f.job.validate());
    }
    {
        Morph f({1, 2, 3}, {{4, 5, 6}}, {0.5f});
        f.job.isa = Isa::Avx2;
        EXPECT_EQ(f.job.validate(), isaSupported(Isa::Avx2));
    }
}

TEST_P(MorphPaths, HandComputedBlend) {
    SKIP_IF_UNSUPPORTED(GetParam());
    // 37 elements, so every path runs its vector loop and its tail.
    // B = i, T0 = i + 10, T1 = 2i; w = (0.5, -0.25):
    //   out = i + 0.5 * 10 - 0.25 * (2i - i) = 0.75 i + 5.
    std::vector<float> b, t0, t1;
    for (int i = 0; i < 37; ++i) {
        b.push_back(float(i));
        t0.push_back(float(i + 10));
        t1.push_back(float(2 * i));
    }
    Morph m(b, {t0, t1}, {0.5f, -0.25f});
    m.job.isa = GetParam();
    ASSERT_TRUE(m.job.run());
    for (int i = 0; i < 37; ++i) EXPECT_FLOAT_EQ(m.out[i], 0.75f * i + 5.0f) << "element " << i;
}

TEST_P(MorphPaths, WeightsOutsideZeroOneAndNoTargets) {
    SKIP_IF_UNSUPPORTED(GetParam());
    // w = 2 extrapolates: 1 + 2 (3 - 1) = 5; w = -1: 1 - (3 - 1) = -1.
    Morph m({1, 1, 1}, {{3, 3, 3}}, {2.0f});
    m.job.isa = GetParam();
    ASSERT_TRUE(m.job.run());
    EXPECT_EQ(m.out, (std::vector<float>{5, 5, 5}));
    m.weights[0] = -1.0f;
    ASSERT_TRUE(m.job.run());
    EXPECT_EQ(m.out, (std::vector<float>{-1, -1, -1}));
    // No targets: the base.
    Morph none({4, 5, 6}, {}, {});
    none.job.isa = GetParam();
    ASSERT_TRUE(none.job.run());
    EXPECT_EQ(none.out, (std::vector<float>{4, 5, 6}));
}

TEST_P(MorphPaths, ClampForColours) {
    SKIP_IF_UNSUPPORTED(GetParam());
    // Colours in [0, 1]: B = 0.5, T = 1; w = 2 -> 1.5 -> 1; w = -2 -> -0.5 -> 0;
    // w = 0.5 -> 0.75 (inside).
    std::vector<float> b(20, 0.5f), t(20, 1.0f);
    for (float w : {2.0f, -2.0f, 0.5f}) {
        Morph m(b, {t}, {w});
        m.job.clamp = true;
        m.job.isa = GetParam();
        ASSERT_TRUE(m.job.run());
        const float expected = w == 2.0f ? 1.0f : (w < 0 ? 0.0f : 0.75f);
        for (float v : m.out) EXPECT_FLOAT_EQ(v, expected) << "w " << w;
    }
}

TEST_P(MorphPaths, NormalizeRenormalisesTriples) {
    SKIP_IF_UNSUPPORTED(GetParam());
    // B = (1, 0, 0), T = (0, 1, 0), w = 0.5 -> (0.5, 0.5, 0) -> (1, 1, 0) / sqrt 2.
    // Second vertex: B = (0, 0, 2), T = (0, 0, -2), w = 0.5 -> (0, 0, 0) stays zero.
    Morph m({1, 0, 0, 0, 0, 2}, {{0, 1, 0, 0, 0, -2}}, {0.5f});
    m.job.normalize = true;
    m.job.isa = GetParam();
    ASSERT_TRUE(m.job.run());
    const float h = std::sqrt(0.5f);
    EXPECT_NEAR(m.out[0], h, 1e-7f);
    EXPECT_NEAR(m.out[1], h, 1e-7f);
    EXPECT_EQ(m.out[2], 0.0f);
    EXPECT_EQ(m.out[3], 0.0f);
    EXPECT_EQ(m.out[4], 0.0f);
    EXPECT_EQ(m.out[5], 0.0f);
}

INSTANTIATE_TEST_SUITE_P(Isa, MorphPaths, ::testing::ValuesIn(kPaths),
                         [](const auto& p) { return std::string(isaName(p.param)); });

TEST(MorphJob, EveryPathAgreesWithDoublePrecision) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-100.0f, 100.0f), w(-1.5f, 1.5f);
    const std::size_t n = 3 * 1001;
    std::vector<float> b(n);
    for (float& x : b) x = u(rng);
    std::vector<std::vector<float>> t(5, std::vector<float>(n));
    for (auto& tt : t)
        for (float& x : tt) x = u(rng);
    std::vector<float> weights(5);
    for (float& x : weights) x = w(rng);
    std::vector<double> ref(n);
    for (std::size_t i = 0; i < n; ++i) {
        double acc = b[i];
        for (std::size_t k = 0; k < t.size(); ++k) acc += double(weights[k]) * (double(t[k][i]) - double(b[i]));
        ref[i] = acc;
    }
    // The same blend renormalised per xyz triple (1001 triples: full blocks
    // and a partial one on every path).
    std::vector<double> unit(ref);
    for (std::size_t v = 0; v < n; v += 3) {
        const double len = std::sqrt(ref[v] * ref[v] + ref[v + 1] * ref[v + 1] + ref[v + 2] * ref[v + 2]);
        for (int c = 0; c < 3; ++c) unit[v + c] = ref[v + c] / len;
    }
    for (Isa isa : kPaths) {
        if (!isaSupported(isa)) continue;
        Morph m(b, t, weights);
        m.job.isa = isa;
        ASSERT_TRUE(m.job.run());
        for (std::size_t i = 0; i < n; ++i)
            ASSERT_NEAR(m.out[i], ref[i], 1e-5 * std::max(100.0, std::abs(ref[i]))) << isaName(isa) << " element " << i;
        m.job.normalize = true;
        ASSERT_TRUE(m.job.run());
        for (std::size_t i = 0; i < n; ++i)
            ASSERT_NEAR(m.out[i], unit[i], 1e-5) << isaName(isa) << " normalised element " << i;
    }
}

TEST(MorphJob, ParallelRunIsBitIdenticalForAnyThreadCount) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const std::size_t n = 3 * 20011;
    std::vector<float> b(n);
    for (float& x : b) x = u(rng);
    std::vector<std::vector<float>> t(3, std::vector<float>(n));
    for (auto& tt : t)
        for (float& x : tt) x = u(rng);
    for (Isa isa : kPaths) {
        if (!isaSupported(isa)) continue;
        Morph serial(b, t, {0.3f, -0.7f, 1.1f});
        serial.job.isa = isa;
        serial.job.normalize = true;
        ASSERT_TRUE(serial.job.run());
        for (int threads : {1, 2, 3}) {
            ThreadPool pool(threads);
            for (std::size_t grain : {1u, 5u, 1000u}) {
                Morph par(b, t, {0.3f, -0.7f, 1.1f});
                par.job.isa = isa;
                par.job.normalize = true;
                ASSERT_TRUE(par.job.runParallel(pool, grain));
                EXPECT_EQ(0, std::memcmp(serial.out.data(), par.out.data(), n * sizeof(float)))
                    << isaName(isa) << ", " << threads << " threads, grain " << grain;
            }
        }
    }
}
