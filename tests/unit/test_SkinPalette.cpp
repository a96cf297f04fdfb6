// skin::PaletteJob: the per-frame bone palette (JSR-184 1.1, SkinnedMesh). Every
// expected matrix is worked out by hand in the comments.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <random>
#include <vector>

#include <m3g/skin/Isa.h>
#include <m3g/skin/Palette.h>

#include "SkinReference.h"

using m3g::skin::Isa;
using m3g::skin::isaSupported;
using m3g::skin::PaletteEntry;
using m3g::skin::PaletteJob;
using Mat = std::array<float, 16>;

namespace {

constexpr Mat kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Mat translation(float x, float y, float z) { return {1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, z, 0, 0, 0, 1}; }

/// A job over `boneCount` bones of the two matrix arrays into `output`.
PaletteJob paletteJob(std::size_t boneCount, std::span<const float> boneToMesh, std::span<const float> atRest,
                      std::span<PaletteEntry> output) {
    PaletteJob job;
    job.boneCount = boneCount;
    job.boneToMesh = boneToMesh;
    job.atRest = atRest;
    job.output = output;
    return job;
}

PaletteEntry compute(const Mat& boneToMesh, const Mat& atRest) {
    PaletteEntry e{};
    const PaletteJob job = paletteJob(1, boneToMesh, atRest, std::span<PaletteEntry>(&e, 1));
    EXPECT_TRUE(job.run());
    return e;
}

void expectRows(const float* actual, const std::array<float, 12>& expected, const char* what) {
    for (int i = 0; i < 12; ++i) EXPECT_NEAR(actual[i], expected[static_cast<std::size_t>(i)], 1e-6f) << what << " element " << i;
}

}  // namespace

TEST(SkinPalette, LayoutIsStd430Compatible) {
    // GLSL: struct { vec4 position[3]; vec4 normal[3]; } has offsets 0 and 48,
    // size 96, alignment 16 under std430.
    EXPECT_EQ(sizeof(PaletteEntry), 96u);
    EXPECT_EQ(alignof(PaletteEntry), 16u);
    EXPECT_EQ(offsetof(PaletteEntry, position), 0u);
    EXPECT_EQ(offsetof(PaletteEntry, normal), 48u);
}

TEST(SkinPalette, ValidateChecksSizes) {
    std::vector<float> m(32, 0.0f);
    std::vector<PaletteEntry> out(2);
    PaletteJob job = paletteJob(2, m, m, out);
    EXPECT_TRUE(job.validate());
    job.boneToMesh = std::span<const float>(m).first(31);
    EXPECT_FALSE(job.validate());
    EXPECT_FALSE(job.run());
    job.boneToMesh = m;
    job.atRest = std::span<const float>(m).first(16);
    EXPECT_FALSE(job.validate());
    job.atRest = m;
    job.output = std::span<PaletteEntry>(out).first(1);
    EXPECT_FALSE(job.validate());
    // No bones: nothing to do, valid with empty spans.
    PaletteJob empty;
    EXPECT_TRUE(empty.validate());
    EXPECT_TRUE(empty.run());
}

TEST(SkinPalette, TranslationsCompose) {
    // T(1, 2, 3) x T(-1, 0, 0) = T(0, 2, 3); normals untouched.
    const PaletteEntry e = compute(translation(1, 2, 3), translation(-1, 0, 0));
    expectRows(e.position, {1, 0, 0, 0, 0, 1, 0, 2, 0, 0, 1, 3}, "position");
    expectRows(e.normal, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}, "normal");
}

TEST(SkinPalette, RotationNormalMatrixIsTheRotation) {
    // Rz(90): x -> y, y -> -x. Its inverse transpose is itself.
    const Mat rz{0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const PaletteEntry e = compute(rz, kIdentity);
    expectRows(e.position, {0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0}, "position");
    expectRows(e.normal, {0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0}, "normal");
}

TEST(SkinPalette, NonUniformScaleUsesInverseTranspose) {
    // A = diag(2, 4, 0.5) with translation (1, 0, 0); at rest T(0, -1, 0).
    // A x R = [2 0 0 1; 0 4 0 -4; 0 0 0.5 0]; normal = diag(1/2, 1/4, 2).
    const Mat a{2, 0, 0, 1, 0, 4, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 1};
    const PaletteEntry e = compute(a, translation(0, -1, 0));
    expectRows(e.position, {2, 0, 0, 1, 0, 4, 0, -4, 0, 0, 0.5f, 0}, "position");
    expectRows(e.normal, {0.5f, 0, 0, 0, 0, 0.25f, 0, 0, 0, 0, 2, 0}, "normal");
}

TEST(SkinPalette, ShearInverseTranspose) {
    // S = [1 1 0; 0 1 0; 0 0 1]; S^-1 = [1 -1 0; 0 1 0; 0 0 1];
    // (S^-1)^T = [1 0 0; -1 1 0; 0 0 1].
    const Mat s{1, 1, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const PaletteEntry e = compute(s, kIdentity);
    expectRows(e.normal, {1, 0, 0, 0, -1, 1, 0, 0, 0, 0, 1, 0}, "normal");
}

TEST(SkinPalette, AtRestAppliesFirst) {
    // boneToMesh x atRest: T(5, 0, 0) x Rz(90) = [Rz(90) | (5, 0, 0)]; the
    // other order would give the translation Rz(90) (5, 0, 0) = (0, 5, 0).
    const Mat rz{0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const PaletteEntry f = compute(translation(5, 0, 0), rz);
    expectRows(f.position, {0, -1, 0, 5, 1, 0, 0, 0, 0, 0, 1, 0}, "T x R");
}

TEST(SkinPalette, SingularMatrixGivesCofactors) {
    // diag(2, 3, 0) flattens z: cofactors = diag(3*0, 2*0, 2*3) = diag(0, 0, 6),
    // so every normal maps to +z (the flattened plane's normal).
    const Mat flat{2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
    const PaletteEntry e = compute(flat, kIdentity);
    expectRows(e.normal, {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 6, 0}, "normal");
}

TEST(SkinPalette, SeveralBonesAndTheBottomRowIsIgnored) {
    // Bone 1's bottom row is not (0 0 0 1): only the top three rows count.
    std::vector<float> a, r;
    const Mat t1 = translation(1, 0, 0);
    Mat t2 = translation(0, 7, 0);
    t2[12] = 9.0f;
    a.insert(a.end(), t1.begin(), t1.end());
    a.insert(a.end(), t2.begin(), t2.end());
    r.insert(r.end(), kIdentity.begin(), kIdentity.end());
    r.insert(r.end(), kIdentity.begin(), kIdentity.end());
    std::vector<PaletteEntry> out(2);
    const PaletteJob job = paletteJob(2, a, r, out);
    ASSERT_TRUE(job.run());
    expectRows(out[0].position, {1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0}, "bone 0");
    expectRows(out[1].position, {1, 0, 0, 0, 0, 1, 0, 7, 0, 0, 1, 0}, "bone 1");
}

// The SIMD paths (single precision, rows as vectors: AVX2 with FMAs two
// bones at a time, SSE2 one at a time) against the plain double loop:
// random affine bones, a singular one (scaled to a plane) and a translation
// only, an odd count (AVX2's last bone alone); the entries agree to float
// rounding.
TEST(SkinPalette, SimdPathsAgreeWithPlainLoop) {
    std::mt19937 rng(11);
    std::vector<float> a, r;
    for (int b = 0; b < 41; ++b) {
        const auto x = m3gtest::randomAffine(rng), y = m3gtest::randomAffine(rng);
        a.insert(a.end(), x.begin(), x.end());
        r.insert(r.end(), y.begin(), y.end());
    }
    const float flat[16] = {1, 0, 0, 2, 0, 1, 0, 3, 0, 0, 0, 4, 0, 0, 0, 1};  // z scaled to 0
    const float moved[16] = {1, 0, 0, -5, 0, 1, 0, 6, 0, 0, 1, 7, 0, 0, 0, 1};
    a.insert(a.end(), std::begin(flat), std::end(flat));
    r.insert(r.end(), std::begin(moved), std::end(moved));
    a.insert(a.end(), std::begin(moved), std::end(moved));
    r.insert(r.end(), std::begin(flat), std::end(flat));
    const std::size_t bones = a.size() / 16;
    ASSERT_EQ(bones % 2, 1u);
    std::vector<PaletteEntry> plain(bones);
    PaletteJob job = paletteJob(bones, a, r, plain);
    job.isa = Isa::Scalar;
    ASSERT_TRUE(job.run());
    for (Isa isa : {Isa::Sse2, Isa::Avx2, Isa::Avx512}) {
        if (!isaSupported(isa)) continue;
        SCOPED_TRACE(m3g::skin::isaName(isa));
        std::vector<PaletteEntry> simd(bones);
        job.output = simd;
        job.isa = isa;
        ASSERT_TRUE(job.run());
        for (std::size_t b = 0; b < bones; ++b)
            for (int i = 0; i < 12; ++i) {
                const float p = plain[b].position[i], q = simd[b].position[i];
                EXPECT_NEAR(q, p, 1e-6f * std::max(1.0f, std::abs(p))) << "bone " << b << " position " << i;
                const float n = plain[b].normal[i], m = simd[b].normal[i];
                EXPECT_NEAR(m, n, 1e-6f * std::max(1.0f, std::abs(n))) << "bone " << b << " normal " << i;
            }
    }
}

// The vertex positions' scale and bias folded into the position rows:
// P (s p + b) = (P s) p + P b; the normal rows stay those of P. Rz(90)
// (x -> y, y -> -x) then T(1, 2, 3), at rest T(0, 0, 1): P = [0 -1 0 1;
// 1 0 0 2; 0 0 1 4]. With s = 2 and b = (1, 0, -1): P b = (0, 1, -1), so
// the rows are [0 -2 0 1; 2 0 0 3; 0 0 2 3]; normals Rz(90). Every code
// path, and 1 / 0 leave the rows as they are.
TEST(SkinPalette, PositionScaleAndBiasFoldIntoThePositionRows) {
    const Mat a{0, -1, 0, 1, 1, 0, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1};
    const Mat r = translation(0, 0, 1);
    for (Isa isa : {Isa::Scalar, Isa::Sse2, Isa::Avx2, Isa::Avx512}) {
        if (!isaSupported(isa)) continue;
        SCOPED_TRACE(m3g::skin::isaName(isa));
        // Two bones (the AVX2 path's pair): m, then the identity.
        auto thenIdentity = [](const Mat& m) {
            std::vector<float> v(m.begin(), m.end());
            v.insert(v.end(), kIdentity.begin(), kIdentity.end());
            return v;
        };
        const std::vector<float> boneToMesh = thenIdentity(a), atRest = thenIdentity(r);
        std::vector<PaletteEntry> out(2);
        PaletteJob job = paletteJob(2, boneToMesh, atRest, out);
        job.isa = isa;
        ASSERT_TRUE(job.run());
        expectRows(out[0].position, {0, -1, 0, 1, 1, 0, 0, 2, 0, 0, 1, 4}, "unfolded position");
        job.positionScale = 2.0f;
        job.positionBias = {1.0f, 0.0f, -1.0f};
        ASSERT_TRUE(job.run());
        expectRows(out[0].position, {0, -2, 0, 1, 2, 0, 0, 3, 0, 0, 2, 3}, "position");
        expectRows(out[0].normal, {0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0}, "normal");
        // The identity bone: rows (2 I | b), normal I.
        expectRows(out[1].position, {2, 0, 0, 1, 0, 2, 0, 0, 0, 0, 2, -1}, "second position");
        expectRows(out[1].normal, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}, "second normal");
    }
}

namespace {

/// PaletteJob::conformal for `boneToMesh` (at rest: `atRest`, the same
/// matrix for every bone) on `isa`, with the given position scale.
bool conformalOn(Isa isa, const std::vector<Mat>& boneToMesh, const Mat& atRest, float positionScale) {
    std::vector<float> a, r;
    for (const Mat& m : boneToMesh) {
        a.insert(a.end(), m.begin(), m.end());
        r.insert(r.end(), atRest.begin(), atRest.end());
    }
    std::vector<PaletteEntry> out(boneToMesh.size());
    PaletteJob job = paletteJob(out.size(), a, r, out);
    job.isa = isa;
    job.positionScale = positionScale;
    job.positionBias = {0.5f, -1.0f, 2.0f};
    // Run from either starting value: run() writes the answer both ways.
    bool fromTrue = true, fromFalse = false;
    job.conformal = &fromTrue;
    EXPECT_TRUE(job.run());
    job.conformal = &fromFalse;
    EXPECT_TRUE(job.run());
    EXPECT_EQ(fromTrue, fromFalse);
    return fromFalse;
}

}  // namespace

// PaletteJob::conformal on every code path: bones that rotate (or reflect)
// and translate with one common scale, at rest a scaled rotation too, are
// conformal with any positive position scale; a bone scaled non-uniformly
// by 0.1 %, one scaled unlike the others by 0.1 %, a negative position
// scale, a bone flattened to a plane or holding a NaN are not; 1e-6 of
// non-uniformity (below the 2^-15 tolerance on s^2) still is. 37 bones, an
// odd count: the AVX2 path's last bone alone must count.
TEST(SkinPalette, ConformalReportsRotationsWithOneCommonScale) {
    for (Isa isa : {Isa::Scalar, Isa::Sse2, Isa::Avx2, Isa::Avx512}) {
        if (!isaSupported(isa)) continue;
        SCOPED_TRACE(m3g::skin::isaName(isa));
        std::mt19937 rng(5);
        std::vector<Mat> bones;
        for (int b = 0; b < 37; ++b) bones.push_back(m3gtest::randomScaledRotation(rng, 1.5f));
        // A reflection with the same scale: the inverse transpose is still
        // the matrix over s^2.
        for (int c = 0; c < 4; ++c) bones[3][static_cast<std::size_t>(4 + c)] *= -1.0f;
        const Mat atRest = m3gtest::randomScaledRotation(rng, 0.8f);
        EXPECT_TRUE(conformalOn(isa, bones, atRest, 1.0f));
        EXPECT_TRUE(conformalOn(isa, bones, atRest, 0.25f));
        EXPECT_TRUE(conformalOn(isa, bones, kIdentity, 1.0f));
        EXPECT_FALSE(conformalOn(isa, bones, atRest, -0.25f)) << "negative position scale";

        // Bone `b` changed by `edit`: the first, one inside, and the last
        // (alone in the AVX2 path's last pair).
        for (std::size_t b : {std::size_t{0}, std::size_t{20}, std::size_t{36}}) {
            SCOPED_TRACE(::testing::Message() << "bone " << b);
            auto with = [&](auto edit) {
                std::vector<Mat> v = bones;
                edit(v[b]);
                return conformalOn(isa, v, atRest, 0.25f);
            };
            auto scaleColumn = [](Mat& m, int c, float k) {
                for (int r = 0; r < 3; ++r) m[static_cast<std::size_t>(r * 4 + c)] *= k;
            };
            EXPECT_FALSE(with([&](Mat& m) { scaleColumn(m, 1, 1.001f); })) << "non-uniform scale";
            EXPECT_TRUE(with([&](Mat& m) { scaleColumn(m, 1, 1.000001f); })) << "below the tolerance";
            EXPECT_FALSE(with([&](Mat& m) {
                for (int c = 0; c < 3; ++c) scaleColumn(m, c, 1.001f);
            })) << "a scale unlike the others'";
            EXPECT_FALSE(with([&](Mat& m) { scaleColumn(m, 2, 0.0f); })) << "flattened";
            EXPECT_FALSE(with([&](Mat& m) { m[5] = std::nanf(""); })) << "NaN";
        }
    }
}
