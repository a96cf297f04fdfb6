// MorphingMesh deformation end to end: MorphingMesh + MeshDeformer with the
// skin/ morph kernel (JSR-184 1.1, MorphingMesh). Expected values by hand.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include <m3g/AnimationController.h>
#include <m3g/AnimationTrack.h>
#include <m3g/KeyframeSequence.h>
#include <m3g/MorphingMesh.h>
#include <m3g/TriangleStripArray.h>

#include "MeshDeformer.h"

using namespace m3g;
using m3g::detail::MeshDeformer;
using Shorts = std::vector<std::int16_t>;
using Bytes = std::vector<std::int8_t>;

namespace {

Ref<IndexBuffer> makeIB(int n) {
    const int lengths[] = {n < 3 ? 3 : n};  // a strip needs 3 indices; validity is checked at render
    return new TriangleStripArray(0, lengths);
}

Ref<VertexArray> shorts(const Shorts& v, int comps) {
    const int n = static_cast<int>(v.size()) / comps;
    Ref<VertexArray> a = new VertexArray(n, comps, 2);
    a->set(0, n, v);
    return a;
}
Ref<VertexArray> bytes(const Bytes& v, int comps) {
    const int n = static_cast<int>(v.size()) / comps;
    Ref<VertexArray> a = new VertexArray(n, comps, 1);
    a->set(0, n, v);
    return a;
}

double unit(int c) { return (2.0 * c + 1.0) / 65535.0; }

/// Two vertices with positions, normals, colours (RGB bytes) and 2D texture
/// coordinates on unit 0.
Ref<VertexBuffer> makeVB(const Shorts& p, const Shorts& n, const Bytes& c, const Shorts& t, float scale = 1.0f,
                         std::array<float, 3> bias = {0, 0, 0}) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    vb->setPositions(shorts(p, 3), scale, bias);
    vb->setNormals(shorts(n, 3));
    vb->setColors(bytes(c, 3));
    vb->setTexCoords(0, shorts(t, 2), 1.0f, {});
    return vb;
}

struct Morph {
    Ref<VertexBuffer> base, t0, t1;
    Ref<MorphingMesh> mesh;
    Morph() {
        base = makeVB({0, 0, 0, 10, 0, 0}, {32767, 0, 0, 32767, 0, 0}, {100, 0, -56, 0, 0, 0}, {0, 0, 1, 1}, 0.5f,
                      {1, 0, 0});
        t0 = makeVB({4, 0, 0, 10, 8, 0}, {0, 32767, 0, 32767, 0, 0}, {-56, 0, 100, 0, 0, 0}, {10, 20, 1, 1});
        t1 = makeVB({0, 0, 8, 10, 0, 0}, {0, 0, 32767, 32767, 0, 0}, {100, -1, -56, 0, 0, 0}, {-4, 8, 1, 1});
        std::vector<Ref<VertexBuffer>> targets{t0, t1};
        mesh = new MorphingMesh(base, targets, makeIB(2), nullptr);
    }
    void weights(float a, float b) {
        const float w[] = {a, b};
        mesh->setWeights(w);
    }
};

}  // namespace

TEST(MorphingMeshDeform, HandComputedAttributes) {
    Morph m;
    m.weights(0.5f, 0.25f);
    MeshDeformer d;
    ASSERT_TRUE(d.update(*m.mesh));
    const auto& out = d.vertices();
    ASSERT_EQ(out.vertexCount, 2);
    // Positions: raw B + 0.5 (T0 - B) + 0.25 (T1 - B), then the base's
    // scale 0.5 and bias (1, 0, 0):
    //   v0: (0,0,0) + 0.5 (4,0,0) + 0.25 (0,0,8) = (2, 0, 2) -> (2, 0, 1)
    //   v1: (10,0,0) + 0.5 (0,8,0) + 0 = (10, 4, 0) -> (6, 2, 0)
    const std::vector<float> p{2, 0, 1, 6, 2, 0};
    ASSERT_EQ(out.positions.size(), 6u);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(out.positions[i], p[i], 1e-6f) << i;
    // Normals: morphed with the GL mapping, renormalised. v0:
    //   (1, u, u) + 0.5 ((u, 1, u) - (1, u, u)) + 0.25 ((u, u, 1) - (1, u, u))
    //   with u = unit(0) = 1/65535.
    const double one = unit(32767), u = unit(0);
    std::array<double, 3> n{one + 0.5 * (u - one) + 0.25 * (u - one), u + 0.5 * (one - u), u + 0.25 * (one - u)};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(out.normals[c], n[c] / len, 1e-6) << c;
    // v1: all three (1, u, u): unchanged, renormalised.
    const double l1 = std::sqrt(one * one + 2 * u * u);
    EXPECT_NEAR(out.normals[3], one / l1, 1e-6);
    // Colours (bytes read unsigned: -56 = 200, -1 = 255), RGB arrays: alpha 1.
    //   R = 100 + 0.5 (200 - 100) + 0.25 (100 - 100) = 150
    //   G = 0 + 0 + 0.25 (255 - 0) = 63.75
    //   B = 200 + 0.5 (100 - 200) + 0.25 (200 - 200) = 150
    ASSERT_EQ(out.colors.size(), 8u);
    EXPECT_NEAR(out.colors[0], 150.0 / 255, 1e-6);
    EXPECT_NEAR(out.colors[1], 63.75 / 255, 1e-6);
    EXPECT_NEAR(out.colors[2], 150.0 / 255, 1e-6);
    EXPECT_NEAR(out.colors[3], 1.0, 1e-6);
    // Texture coordinates (raw; the base's scale and bias still apply):
    //   0.5 (10, 20) + 0.25 (-4, 8) = (4, 12).
    ASSERT_EQ(out.texCoordComponents[0], 2);
    EXPECT_EQ(out.texCoordComponents[1], 0);
    EXPECT_TRUE(out.texCoords[1].empty());
    EXPECT_NEAR(out.texCoords[0][0], 4, 1e-6);
    EXPECT_NEAR(out.texCoords[0][1], 12, 1e-6);
    EXPECT_NEAR(out.texCoords[0][2], 1, 1e-6);
}

TEST(MorphingMeshDeform, ColoursAreClamped) {
    // w = (2, -1): R = 100 + 2 (100) - 0 = 300 -> 255; G = 0 - (255) -> 0;
    // B = 200 + 2 (-100) - 0 = 0.
    Morph m;
    m.weights(2.0f, -1.0f);
    MeshDeformer d;
    ASSERT_TRUE(d.update(*m.mesh));
    EXPECT_FLOAT_EQ(d.vertices().colors[0], 1.0f);
    EXPECT_FLOAT_EQ(d.vertices().colors[1], 0.0f);
    EXPECT_NEAR(d.vertices().colors[2], 0.0f, 1e-6f);
}

TEST(MorphingMeshDeform, DefaultColourIsMorphedWithoutColourArrays) {
    // Base default 0xFF804020, target 0x00FFFFFF, w = 0.5:
    //   A = 255 - 127.5, R = 128 + 63.5, G = 64 + 95.5, B = 32 + 111.5.
    auto vb = [](int argb) {
        Ref<VertexBuffer> v = new VertexBuffer();
        v->setPositions(shorts({0, 0, 0}, 3), 1.0f, {});
        v->setDefaultColor(argb);
        return v;
    };
    std::vector<Ref<VertexBuffer>> targets{vb(0x00FFFFFF)};
    Ref<MorphingMesh> mesh = new MorphingMesh(vb(static_cast<int>(0xFF804020u)), targets, makeIB(1), nullptr);
    const float w[] = {0.5f};
    mesh->setWeights(w);
    MeshDeformer d;
    ASSERT_TRUE(d.update(*mesh));
    const auto& c = d.vertices().colors;
    ASSERT_EQ(c.size(), 4u);
    EXPECT_NEAR(c[0], 191.5 / 255, 1e-6);
    EXPECT_NEAR(c[1], 159.5 / 255, 1e-6);
    EXPECT_NEAR(c[2], 143.5 / 255, 1e-6);
    EXPECT_NEAR(c[3], 127.5 / 255, 1e-6);
    EXPECT_TRUE(d.vertices().normals.empty());
}

TEST(MorphingMeshDeform, MismatchedTargetThrowsOnEveryCallUntilFixed) {
    Ref<VertexBuffer> base = new VertexBuffer(), target = new VertexBuffer();
    base->setPositions(shorts({0, 0, 0}, 3), 1.0f, {});
    base->setNormals(shorts({0, 0, 32767}, 3));
    target->setPositions(shorts({1, 0, 0}, 3), 1.0f, {});
    std::vector<Ref<VertexBuffer>> targets{target};
    Ref<MorphingMesh> mesh = new MorphingMesh(base, targets, makeIB(1), nullptr);
    MeshDeformer d;
    EXPECT_THROW(d.update(*mesh), IllegalStateException);
    EXPECT_THROW(d.update(*mesh), IllegalStateException);  // not cached as valid
    target->setNormals(shorts({0, 32767, 0}, 3));
    EXPECT_TRUE(d.update(*mesh));
    EXPECT_FALSE(d.update(*mesh));
}

TEST(MorphingMeshDeform, RecomputesOnlyWhenAnInputChanged) {
    Morph m;
    MeshDeformer d;
    EXPECT_TRUE(d.update(*m.mesh));
    EXPECT_FALSE(d.update(*m.mesh));
    EXPECT_NEAR(d.vertices().positions[0], 1.0f, 1e-6f);  // weights 0: the base
    m.weights(0, 0);  // same weights (the mesh's revision changes, not its result)
    EXPECT_FALSE(d.update(*m.mesh));
    m.mesh->setTranslation(5, 5, 5);  // the node transform: not a vertex input
    EXPECT_FALSE(d.update(*m.mesh));
    m.weights(0.5f, 0);  // a weight
    EXPECT_TRUE(d.update(*m.mesh));
    EXPECT_NEAR(d.vertices().positions[0], 2.0f, 1e-6f);  // 0.5 (0.5 * 4) + 1
    EXPECT_FALSE(d.update(*m.mesh));
    // A target's array edited in place: T0 v0 x = 8 -> 0.5 (0.5 * 8) + 1 = 3.
    const std::int16_t moved[] = {8, 0, 0};
    m.t0->getPositions()->set(0, 1, moved);
    EXPECT_TRUE(d.update(*m.mesh));
    EXPECT_NEAR(d.vertices().positions[0], 3.0f, 1e-6f);
    // The base VertexBuffer's scale and bias.
    const float bias[] = {2, 0, 0};
    m.base->setPositions(m.base->getPositions(), 0.5f, bias);
    EXPECT_TRUE(d.update(*m.mesh));
    EXPECT_NEAR(d.vertices().positions[0], 4.0f, 1e-6f);
    EXPECT_FALSE(d.update(*m.mesh));
    // A target's default colour is not used when colour arrays exist, but any
    // change to a VertexBuffer is taken as an input change.
    m.t1->setDefaultColor(0x12345678);
    EXPECT_TRUE(d.update(*m.mesh));
    // MORPH_WEIGHTS animated: weight 1 on target 1 -> v0 z = 0.5 * 8 = 4.
    Ref<KeyframeSequence> seq = new KeyframeSequence(1, 2, KeyframeSequence::LINEAR);
    const float key[] = {0, 1};
    seq->setKeyframe(0, 0, key);
    seq->setDuration(100);
    Ref<AnimationTrack> track = new AnimationTrack(seq, AnimationTrack::MORPH_WEIGHTS);
    track->setController(new AnimationController());
    m.mesh->addAnimationTrack(track);
    m.mesh->animate(0);
    EXPECT_TRUE(d.update(*m.mesh));
    EXPECT_NEAR(d.vertices().positions[2], 4.0f, 1e-6f);
    m.mesh->animate(50);  // same value
    EXPECT_FALSE(d.update(*m.mesh));
}

TEST(MorphingMeshDeform, LargeMeshTakesTheParallelPath) {
    // 30000 vertices: x = v % 1000 in the base, x + 100 in the target;
    // w = 0.25 -> x + 25 everywhere.
    const int n = 30000;
    Shorts b(static_cast<std::size_t>(n) * 3, 0), t(static_cast<std::size_t>(n) * 3, 0);
    for (int v = 0; v < n; ++v) {
        b[static_cast<std::size_t>(v) * 3] = static_cast<std::int16_t>(v % 1000);
        t[static_cast<std::size_t>(v) * 3] = static_cast<std::int16_t>(v % 1000 + 100);
    }
    Ref<VertexBuffer> base = new VertexBuffer(), target = new VertexBuffer();
    base->setPositions(shorts(b, 3), 1.0f, {});
    target->setPositions(shorts(t, 3), 1.0f, {});
    std::vector<Ref<VertexBuffer>> targets{target};
    Ref<MorphingMesh> mesh = new MorphingMesh(base, targets, makeIB(n), nullptr);
    const float w[] = {0.25f};
    mesh->setWeights(w);
    MeshDeformer d;
    ASSERT_TRUE(d.update(*mesh));
    for (int v = 0; v < n; v += 997) EXPECT_FLOAT_EQ(d.vertices().positions[static_cast<std::size_t>(v) * 3], float(v % 1000 + 25)) << v;
}

TEST(MorphingMeshDeform, InputsOnlyExposesBaseTargetsAndWeights) {
    Morph m;
    m.weights(0.5f, 0.0f);
    MeshDeformer d;
    using Output = MeshDeformer::Output;
    EXPECT_TRUE(d.update(*m.mesh, Output::InputsOnly));
    EXPECT_TRUE(d.vertices().positions.empty());
    EXPECT_EQ(d.vertices().texCoordComponents[0], 2);
    const auto positions = d.morphAttribute(MeshDeformer::kMorphPositions);
    EXPECT_EQ(positions.components, 3);
    ASSERT_EQ(positions.targets.size(), 2u);
    // Base and targets with the base's scale 0.5 and bias (1, 0, 0) applied.
    EXPECT_FLOAT_EQ(positions.base[3], 0.5f * 10 + 1);
    EXPECT_FLOAT_EQ(positions.targets[0][0], 0.5f * 4 + 1);
    EXPECT_EQ(d.morphAttribute(MeshDeformer::kMorphColors).components, 4);
    EXPECT_EQ(d.morphAttribute(MeshDeformer::kMorphTexCoords + 1).components, 0);  // no unit 1
    EXPECT_EQ(d.morphAttribute(99).components, 0);
    ASSERT_EQ(d.morphWeights().size(), 2u);
    EXPECT_EQ(d.morphWeights()[0], 0.5f);
    const auto stamp = d.inputStamp();
    EXPECT_FALSE(d.update(*m.mesh, Output::InputsOnly));
    m.weights(0.25f, 1.0f);  // the weights only
    EXPECT_TRUE(d.update(*m.mesh, Output::InputsOnly));
    EXPECT_EQ(d.inputStamp(), stamp);
    EXPECT_EQ(d.morphWeights()[1], 1.0f);
    const std::int16_t moved[] = {1, 2, 3};
    m.t1->getPositions()->set(0, 1, moved);  // a target's data: static inputs rebuilt
    EXPECT_TRUE(d.update(*m.mesh, Output::InputsOnly));
    EXPECT_GT(d.inputStamp(), stamp);
}
