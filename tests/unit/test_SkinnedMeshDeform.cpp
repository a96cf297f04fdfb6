// SkinnedMesh deformation end to end: SkinnedMesh + MeshDeformer with the
// skin/ kernels (JSR-184 1.1, SkinnedMesh; a vertex without bones stays in
// mesh space, as Nokia's M3G implementation (reference) leaves it). Expected
// values are worked out by hand in the comments; a random rig is checked
// against the double-precision reference and the founding paper's baseline.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <m3g/AnimationController.h>
#include <m3g/AnimationTrack.h>
#include <m3g/Group.h>
#include <m3g/KeyframeSequence.h>
#include <m3g/Limits.h>
#include <m3g/SkinnedMesh.h>
#include <m3g/TriangleStripArray.h>
#include <m3g/skin/InfluenceTable.h>
#include <m3g/skin/Skinning.h>

#include "MeshDeformer.h"
#include "SkinReference.h"

using namespace m3g;
using m3g::detail::MeshDeformer;
using Shorts = std::vector<std::int16_t>;

namespace {

Ref<IndexBuffer> makeIB(int vertices) {
    const int lengths[] = {vertices < 3 ? 3 : vertices};  // a strip needs 3 indices; validity is checked at render
    return new TriangleStripArray(0, lengths);
}

Ref<VertexBuffer> makeVB(const Shorts& positions, float scale = 1.0f, std::array<float, 3> bias = {0, 0, 0},
                         const Shorts& normals = {}) {
    const int n = static_cast<int>(positions.size() / 3);
    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<VertexArray> p = new VertexArray(n, 3, 2);
    p->set(0, n, positions);
    vb->setPositions(p, scale, bias);
    if (!normals.empty()) {
        Ref<VertexArray> a = new VertexArray(n, 3, 2);
        a->set(0, n, normals);
        vb->setNormals(a);
    }
    return vb;
}

/// A short normal component as the renderer reads it: (2c + 1) / 65535.
double unit(int c) { return (2.0 * c + 1.0) / 65535.0; }
std::array<double, 3> normalised(double x, double y, double z) {
    const double l = std::sqrt(x * x + y * y + z * z);
    return {x / l, y / l, z / l};
}

struct Rig {
    Ref<Group> skeleton = new Group();
    std::vector<Ref<Group>> bones;
    Ref<SkinnedMesh> mesh;
    Rig(Ref<VertexBuffer> vb, int boneCount) {
        for (int i = 0; i < boneCount; ++i) {
            bones.push_back(new Group());
            skeleton->addChild(bones.back());
        }
        mesh = new SkinnedMesh(vb, makeIB(vb->getVertexCount()), nullptr, skeleton);
    }
};

// Mesh vertex v of the deformed output, wherever its slot is
// (DeformedVertices::order).
void expectPosition(const MeshDeformer& d, int v, double x, double y, double z, double tol = 1e-5) {
    const auto& p = d.vertices().positions;
    const std::size_t s = d.vertices().slotOf(static_cast<std::uint32_t>(v));
    ASSERT_GE(p.size(), s * 3 + 3);
    EXPECT_NEAR(p[s * 3], x, tol) << "vertex " << v << " x";
    EXPECT_NEAR(p[s * 3 + 1], y, tol) << "vertex " << v << " y";
    EXPECT_NEAR(p[s * 3 + 2], z, tol) << "vertex " << v << " z";
}
void expectNormal(const MeshDeformer& d, int v, std::array<double, 3> n, double tol = 1e-6) {
    const auto& a = d.vertices().normals;
    const std::size_t s = d.vertices().slotOf(static_cast<std::uint32_t>(v));
    ASSERT_GE(a.size(), s * 3 + 3);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[s * 3 + c], n[c], tol) << "vertex " << v << " normal " << c;
}
std::vector<float> positionsInMeshOrder(const MeshDeformer& d) {
    return d.vertices().inMeshOrder(d.vertices().positions, 3);
}
std::vector<float> normalsInMeshOrder(const MeshDeformer& d) { return d.vertices().inMeshOrder(d.vertices().normals, 3); }

}  // namespace

TEST(SkinnedMeshDeform, OneToFourInfluencesHandComputed) {
    // Bones at the origin at rest; posed T(4,0,0), T(0,8,0), T(0,0,2), T(-10,-10,-10).
    Rig r(makeVB({1, 0, 0, /**/ 0, 0, 0, /**/ 1, 1, 1, /**/ 1, 2, 3}), 4);
    auto& b = r.bones;
    r.mesh->addTransform(b[0], 1, 0, 4);  // every vertex: bone 0 weight 1
    r.mesh->addTransform(b[1], 3, 1, 1);  // v1: 1 : 3
    r.mesh->addTransform(b[1], 1, 2, 1);  // v2: 1 : 1 : 2
    r.mesh->addTransform(b[2], 2, 2, 1);
    r.mesh->addTransform(b[1], 2, 3, 1);  // v3: 1 : 2 : 3 : 4
    r.mesh->addTransform(b[2], 3, 3, 1);
    r.mesh->addTransform(b[3], 4, 3, 1);
    b[0]->setTranslation(4, 0, 0);
    b[1]->setTranslation(0, 8, 0);
    b[2]->setTranslation(0, 0, 2);
    b[3]->setTranslation(-10, -10, -10);
    MeshDeformer d;
    ASSERT_TRUE(d.update(*r.mesh));
    EXPECT_EQ(d.vertices().vertexCount, 4);
    expectPosition(d, 0, 5, 0, 0);  // (1,0,0) + (4,0,0)
    expectPosition(d, 1, 1, 6, 0);  // 0.25 (4,0,0) + 0.75 (0,8,0)
    expectPosition(d, 2, 2, 3, 2);  // (1,1,1) + 0.25 (4,0,0) + 0.25 (0,8,0) + 0.5 (0,0,2)
    // (1,2,3) + 0.1 (4,0,0) + 0.2 (0,8,0) + 0.3 (0,0,2) + 0.4 (-10,-10,-10)
    //   = (1 + 0.4 - 4, 2 + 1.6 - 4, 3 + 0.6 - 4) = (-2.6, -0.4, -0.4)
    expectPosition(d, 3, -2.6, -0.4, -0.4);
    EXPECT_TRUE(d.vertices().normals.empty());  // the VertexBuffer has none
    EXPECT_TRUE(d.vertices().colors.empty());
}

TEST(SkinnedMeshDeform, AtRestPoseAndAncestorsBetweenBoneAndMesh) {
    // The bone sits at (0, 5, 0) when added: at rest = T(0, -5, 0). Turning it
    // 90 degrees about z moves vertex (1, 5, 0) (one unit along the bone's x)
    // to (0, 6, 0), and normal (1, 0, 0) to (0, 1, 0).
    Rig r(makeVB({1, 5, 0}, 1.0f, {0, 0, 0}, {32767, 0, 0}), 1);
    r.bones[0]->setTranslation(0, 5, 0);
    r.mesh->addTransform(r.bones[0], 1, 0, 1);
    MeshDeformer d;
    ASSERT_TRUE(d.update(*r.mesh));
    expectPosition(d, 0, 1, 5, 0);  // at rest: unchanged
    r.bones[0]->setOrientation(90, 0, 0, 1);
    ASSERT_TRUE(d.update(*r.mesh));
    expectPosition(d, 0, 0, 6, 0);
    // Normal: Rz(90) (x, y, z) = (-y, x, z) with the GL mapping of (32767, 0, 0).
    expectNormal(d, 0, normalised(-unit(0), unit(32767), unit(0)));
    // Moving the skeleton root (between bone and mesh) moves the vertex.
    r.skeleton->setTranslation(0, 0, 3);
    ASSERT_TRUE(d.update(*r.mesh));
    expectPosition(d, 0, 0, 6, 3);
}

TEST(SkinnedMeshDeform, OverlappingRangesWithDifferentWeights) {
    // Six vertices at the origin; A posed T(4,0,0), B posed T(0,4,0).
    Rig r(makeVB(Shorts(18, 0)), 2);
    Node* a = r.bones[0];
    Node* b = r.bones[1];
    r.mesh->addTransform(a, 1, 0, 4);  // v0..v3
    r.mesh->addTransform(b, 3, 2, 4);  // v2..v5
    r.mesh->addTransform(a, 2, 3, 2);  // v3..v4: A accumulates
    a->setTranslation(4, 0, 0);
    b->setTranslation(0, 4, 0);
    MeshDeformer d;
    ASSERT_TRUE(d.update(*r.mesh));
    expectPosition(d, 0, 4, 0, 0);        // A only
    expectPosition(d, 1, 4, 0, 0);        // A only
    expectPosition(d, 2, 1, 3, 0);        // A 1, B 3 -> 1/4, 3/4
    expectPosition(d, 3, 2, 2, 0);        // A 1 + 2, B 3 -> 1/2, 1/2
    expectPosition(d, 4, 1.6, 2.4, 0);    // A 2, B 3 -> 2/5, 3/5
    expectPosition(d, 5, 0, 4, 0);        // B only
}

TEST(SkinnedMeshDeform, TopNReplacementAndTieRule) {
    // N = 4 (the default limit). Five bones posed T(2^i, 0, 0), i = 0..4, so
    // that each kept subset gives a different x. All vertices at the origin.
    ASSERT_EQ(getLimits().maxTransformsPerVertex, 4);
    Rig r(makeVB(Shorts(12, 0)), 5);
    auto& b = r.bones;
    // v0: weights 5, 4, 3, 2, 1: bone 4 (the smallest) is left out:
    //     x = (5*1 + 4*2 + 3*4 + 2*8) / 14 = 41/14.
    for (int i = 0; i < 5; ++i) r.mesh->addTransform(b[i], 5 - i, 0, 1);
    // v1: all weights 3 (a tie for the last slot): the bones added first
    //     (lower bone index) win; called in reverse order to show that the
    //     call order on this vertex does not matter: x = (1+2+4+8)/4 = 3.75.
    for (int i = 4; i >= 0; --i) r.mesh->addTransform(b[i], 3, 1, 1);
    // v2: all weights 1 -> bone 4 out; one more unit for bone 4 (2 in all)
    //     brings it in and pushes out bone 3 (the last of the weight-1 tie):
    //     x = (2*16 + 1 + 2 + 4) / 5 = 39/5.
    for (int i = 0; i < 5; ++i) r.mesh->addTransform(b[i], 1, 2, 1);
    r.mesh->addTransform(b[4], 1, 2, 1);
    // v3: bone 0 weight 1, bone 4 weight 10: x = (1*1 + 10*16) / 11.
    r.mesh->addTransform(b[0], 1, 3, 1);
    r.mesh->addTransform(b[4], 10, 3, 1);
    for (int i = 0; i < 5; ++i) b[i]->setTranslation(static_cast<float>(1 << i), 0, 0);
    MeshDeformer d;
    ASSERT_TRUE(d.update(*r.mesh));
    expectPosition(d, 0, 41.0 / 14.0, 0, 0);
    expectPosition(d, 1, 3.75, 0, 0);
    expectPosition(d, 2, 39.0 / 5.0, 0, 0);
    expectPosition(d, 3, 161.0 / 11.0, 0, 0);
}

TEST(SkinnedMeshDeform, SmallerLimitReplacesTheLowestWeight) {
    // N = 2 for a mesh created under that limit: three bones on one vertex,
    // weights 1, 2, 3 -> bones 1 and 2 kept: x = (2*2 + 3*4) / 5 = 16/5.
    struct Guard {
        Limits saved = getLimits();
        ~Guard() { setLimits(saved); }
    } guard;
    Limits two = getLimits();
    two.maxTransformsPerVertex = 2;
    setLimits(two);
    Rig r(makeVB(Shorts(3, 0)), 3);
    setLimits(guard.saved);
    for (int i = 0; i < 3; ++i) {
        r.mesh->addTransform(r.bones[i], i + 1, 0, 1);
        r.bones[i]->setTranslation(static_cast<float>(1 << i), 0, 0);
    }
    MeshDeformer d;
    ASSERT_TRUE(d.update(*r.mesh));
    expectPosition(d, 0, 16.0 / 5.0, 0, 0);
}

TEST(SkinnedMeshDeform, VertexWithNoBoneStaysInMeshSpace) {
    // Positions 0.5 * raw + (1, 1, 1). v0 has a bone (posed T(1,0,0)); v1 has
    // none (inside the table's range: v2 has one); v3 lies beyond every range.
    // Unskinned vertices keep scale * v + bias and get a unit normal.
    Rig r(makeVB({2, 4, 6, /**/ 2, 4, 6, /**/ 0, 0, 0, /**/ -2, 0, 2}, 0.5f, {1, 1, 1},
                 {0, 0, 32767, /**/ 32767, 32767, 0, /**/ 0, 32767, 0, /**/ 0, 0, -32768}),
          1);
    r.mesh->addTransform(r.bones[0], 1, 0, 1);
    r.mesh->addTransform(r.bones[0], 1, 2, 1);
    r.bones[0]->setTranslation(1, 0, 0);
    MeshDeformer d;
    ASSERT_TRUE(d.update(*r.mesh));
    expectPosition(d, 0, 3, 3, 4);  // 0.5 (2,4,6) + (1,1,1) = (2,3,4), then + (1,0,0)
    expectPosition(d, 1, 2, 3, 4);  // no bone: mesh space
    expectPosition(d, 2, 2, 1, 1);  // (1,1,1) + (1,0,0)
    expectPosition(d, 3, 0, 1, 2);  // beyond the table: mesh space
    expectNormal(d, 1, normalised(unit(32767), unit(32767), unit(0)));
    expectNormal(d, 3, normalised(unit(0), unit(0), unit(-32768)));
}

TEST(SkinnedMeshDeform, NonUniformBoneScaleUsesInverseTransposeForNormals) {
    // Bone scaled (2, 1, 1) after the rest pose. Position (1, 1, 0) -> (2, 1, 0).
    // Normal n -> diag(1/2, 1, 1) n, renormalised: for n ~ (1, 1, 0) that is
    // (1, 2, 0) / sqrt 5 (the matrix itself would tilt it the other way).
    Rig r(makeVB({1, 1, 0}, 1.0f, {0, 0, 0}, {32767, 32767, 0}), 1);
    r.mesh->addTransform(r.bones[0], 1, 0, 1);
    r.bones[0]->setScale(2, 1, 1);
    MeshDeformer d;
    ASSERT_TRUE(d.update(*r.mesh));
    expectPosition(d, 0, 2, 1, 0);
    expectNormal(d, 0, normalised(0.5 * unit(32767), unit(32767), unit(0)));
}

TEST(SkinnedMeshDeform, RecomputesOnlyWhenAnInputChanged) {
    Ref<Group> world = new Group();
    Ref<Group> joint = new Group();  // between the skeleton root and the bone
    Rig r(makeVB({1, 0, 0, /**/ 0, 1, 0}, 1.0f, {0, 0, 0}, {32767, 0, 0, /**/ 0, 32767, 0}), 0);
    Ref<Group> bone = new Group();
    r.skeleton->addChild(joint);
    joint->addChild(bone);
    world->addChild(r.mesh);
    r.mesh->addTransform(bone, 1, 0, 1);

    MeshDeformer d;
    EXPECT_TRUE(d.update(*r.mesh));  // first call
    EXPECT_EQ(d.stamp(), 1u);
    EXPECT_FALSE(d.update(*r.mesh));  // nothing changed
    EXPECT_EQ(d.stamp(), 1u);
    expectPosition(d, 0, 1, 0, 0);

    bone->setTranslation(0, 0, 1);  // the bone moves
    EXPECT_TRUE(d.update(*r.mesh));
    expectPosition(d, 0, 1, 0, 1);
    bone->setTranslation(0, 0, 1);  // same pose again: same palette
    EXPECT_FALSE(d.update(*r.mesh));

    joint->setTranslation(0, 2, 0);  // an ancestor between bone and mesh
    EXPECT_TRUE(d.update(*r.mesh));
    expectPosition(d, 0, 1, 2, 1);

    // The mesh's own transform and its parents do not change mesh-space vertices.
    r.mesh->setTranslation(100, 0, 0);
    world->setScale(3, 3, 3);
    EXPECT_FALSE(d.update(*r.mesh));
    EXPECT_EQ(d.stamp(), 3u);

    // animate() on the joint: a translation track.
    Ref<KeyframeSequence> seq = new KeyframeSequence(1, 3, KeyframeSequence::LINEAR);
    const float key[] = {0, 5, 0};
    seq->setKeyframe(0, 0, key);
    seq->setDuration(1000);
    Ref<AnimationTrack> track = new AnimationTrack(seq, AnimationTrack::TRANSLATION);
    track->setController(new AnimationController());
    joint->addAnimationTrack(track);
    world->animate(0);
    EXPECT_TRUE(d.update(*r.mesh));
    expectPosition(d, 0, 1, 5, 1);
    world->animate(10);  // same value: same palette
    EXPECT_FALSE(d.update(*r.mesh));

    r.mesh->addTransform(bone, 1, 1, 1);  // the influence table changes
    EXPECT_TRUE(d.update(*r.mesh));
    expectPosition(d, 1, 0, 6, 1);
    EXPECT_FALSE(d.update(*r.mesh));

    // Vertex data: a VertexArray edited in place, then replaced, then scale/bias.
    const std::int16_t moved[] = {2, 0, 0};
    r.mesh->getVertexBuffer()->getPositions()->set(0, 1, moved);
    EXPECT_TRUE(d.update(*r.mesh));
    expectPosition(d, 0, 2, 5, 1);
    const std::int16_t turned[] = {0, 0, 32767};
    r.mesh->getVertexBuffer()->getNormals()->set(0, 1, turned);
    EXPECT_TRUE(d.update(*r.mesh));
    expectNormal(d, 0, normalised(unit(0), unit(0), unit(32767)));
    EXPECT_FALSE(d.update(*r.mesh));
    const float bias[] = {0, 0, 10};
    r.mesh->getVertexBuffer()->setPositions(r.mesh->getVertexBuffer()->getPositions(), 1.0f, bias);
    EXPECT_TRUE(d.update(*r.mesh));
    expectPosition(d, 0, 2, 5, 11);
    Ref<VertexArray> other = new VertexArray(2, 3, 2);
    const std::int16_t values[] = {3, 0, 0, 0, 3, 0};
    other->set(0, 2, values);
    r.mesh->getVertexBuffer()->setPositions(other, 1.0f, bias);
    EXPECT_TRUE(d.update(*r.mesh));
    expectPosition(d, 0, 3, 5, 11);
    EXPECT_FALSE(d.update(*r.mesh));

    // Another mesh through the same deformer, then a plain Mesh.
    Rig second(makeVB({7, 7, 7}), 1);
    EXPECT_TRUE(d.update(*second.mesh));
    expectPosition(d, 0, 7, 7, 7);
    EXPECT_FALSE(d.update(*second.mesh));
    Ref<Mesh> plain = new Mesh(makeVB({1, 1, 1}), makeIB(1), nullptr);
    const auto stamp = d.stamp();
    EXPECT_FALSE(d.update(*plain));
    EXPECT_TRUE(d.vertices().positions.empty());
    EXPECT_EQ(d.stamp(), stamp);
    EXPECT_TRUE(d.update(*second.mesh));  // back to a deformed mesh
}

namespace {

/// A random rig deformed by MeshDeformer against the double-precision
/// reference and the founding paper's baseline. `rigid`: the skeleton's
/// nodes rotate and translate only (PaletteJob::conformal holds, and the
/// bone runs turn normals with the position rows); else every node is
/// scaled non-uniformly too.
void checkRandomRig(std::uint32_t seed, bool rigid) {
    std::mt19937 rng(seed);
    const int n = 600;
    // Skeleton: a random tree of 24 groups with random transforms (rotation,
    // non-uniform scale, translation) at rest.
    Shorts pos, nrm;
    std::uniform_int_distribution<int> coord(-3000, 3000), comp(-32768, 32767);
    for (int i = 0; i < n * 3; ++i) {
        pos.push_back(static_cast<std::int16_t>(coord(rng)));
        nrm.push_back(static_cast<std::int16_t>(comp(rng)));
    }
    const float scale = 0.003f;
    const std::array<float, 3> bias{0.25f, -0.5f, 1.0f};
    Ref<VertexBuffer> vb = makeVB(pos, scale, bias, nrm);
    Ref<Group> skeleton = new Group();
    std::vector<Ref<Group>> nodes{skeleton};
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), s(0.6f, 1.6f);
    auto randomPose = [&](Group* g) {
        g->setTranslation(2 * u(rng), 2 * u(rng), 2 * u(rng));
        g->setOrientation(180 * u(rng), u(rng), u(rng), u(rng) + 0.01f);
        if (!rigid) g->setScale(s(rng), s(rng), s(rng));
    };
    for (int i = 0; i < 24; ++i) {
        Ref<Group> g = new Group();
        std::uniform_int_distribution<std::size_t> parent(0, nodes.size() - 1);
        nodes[parent(rng)]->addChild(g);
        randomPose(g);
        nodes.push_back(g);
    }
    Ref<SkinnedMesh> mesh = new SkinnedMesh(vb, makeIB(n), nullptr, skeleton);
    // 250 records over the first 400 vertices, weights 1..5, ranges up to 30
    // vertices: 0 to ~10 bones a vertex.
    std::vector<m3gtest::WeightedTransform> records;
    std::uniform_int_distribution<int> node(1, 24), weight(1, 5), first(0, n - 201), len(1, 30);
    for (int i = 0; i < 250; ++i) {
        Group* bone = nodes[static_cast<std::size_t>(node(rng))];
        const int f = first(rng), c = std::min(len(rng), n - 200 - f), w = weight(rng);
        mesh->addTransform(bone, w, f, c);
        records.push_back({mesh->boneIndex(bone), w, f, c});
    }
    // And the last 200 vertices in stretches of 20 that share two or three
    // bones, each vertex with weights of its own (a blend along a limb:
    // the compact space's bone runs).
    std::uniform_int_distribution<int> three(2, 3);
    for (int f = n - 200; f < n; f += 20) {
        Group* stretch[3];
        for (Group*& g : stretch) g = nodes[static_cast<std::size_t>(node(rng))];
        const int k = three(rng);
        for (int v = f; v < f + 20; ++v)
            for (int b = 0; b < k; ++b) {
                // Two records of one bone add up; a repeated bone is fine.
                const int w = weight(rng);
                mesh->addTransform(stretch[b], w, v, 1);
                records.push_back({mesh->boneIndex(stretch[b]), w, v, 1});
            }
    }
    for (std::size_t i = 1; i < nodes.size(); ++i) randomPose(nodes[i]);  // a new pose
    // Vertices sharing their bones with their own weights (bone runs), the
    // kernels normalsFromPositions changes.
    skin::InfluencePartition part;
    part.buildForKernels(mesh->influenceTable(), static_cast<std::size_t>(n));
    std::size_t boneRunVertices = 0;
    for (int c = 1; c <= part.maxInfluences(); ++c)
        for (const auto& run : part.compactBoneRuns(c)) boneRunVertices += run.vertexCount;
    EXPECT_GT(boneRunVertices, 100u);
    MeshDeformer d;
    ASSERT_TRUE(d.update(*mesh));

    // Inputs for the reference and the baseline, through the public API.
    std::vector<float> toMesh, rest;
    for (int b = 0; b < mesh->boneCount(); ++b) {
        Transform t;
        mesh->bone(b)->getTransformTo(mesh, &t);
        toMesh.insert(toMesh.end(), t.rows().begin(), t.rows().end());
        mesh->getBoneTransform(mesh->bone(b), &t);
        rest.insert(rest.end(), t.rows().begin(), t.rows().end());
    }
    std::vector<double> meshPos, meshNrm;
    for (int i = 0; i < n * 3; ++i) {
        meshPos.push_back(double(scale) * pos[i] + bias[i % 3]);
        meshNrm.push_back(unit(nrm[i]));
    }
    const std::vector<double> a(toMesh.begin(), toMesh.end()), r(rest.begin(), rest.end());
    const auto ref = m3gtest::referenceSkin(records, 4, a, r, n, meshPos, meshNrm);
    EXPECT_TRUE(m3gtest::closeXyz(positionsInMeshOrder(d), ref.positions));
    EXPECT_TRUE(m3gtest::closeXyz(normalsInMeshOrder(d), ref.normals));

    std::vector<float> pf(meshPos.begin(), meshPos.end()), nf(meshNrm.begin(), meshNrm.end()), bp(pf.size()),
        bn(nf.size());
    m3gbench::SkinBaseline baseline(4);
    baseline.deform(records, static_cast<std::size_t>(mesh->boneCount()), toMesh, rest, n, pf, nf, bp, bn);
    EXPECT_TRUE(m3gtest::closeXyz(positionsInMeshOrder(d), bp));
    EXPECT_TRUE(m3gtest::closeXyz(normalsInMeshOrder(d), bn));
}

}  // namespace

TEST(SkinnedMeshDeform, RandomRigAgreesWithReferenceAndPaperBaseline) { checkRandomRig(2024, false); }

// Bones that only rotate and translate: the palette is conformal and the
// bone runs' normals come from the position rows, still the reference's.
TEST(SkinnedMeshDeform, RigidRigAgreesWithReferenceAndPaperBaseline) {
    checkRandomRig(2024, true);
    checkRandomRig(7, true);
}

TEST(SkinnedMeshDeform, LargeMeshTakesTheParallelPath) {
    // 40000 vertices (above MeshDeformer's threshold for the thread pool):
    // bone A on [0, 30000) weight 1, bone B on [10000, 40000) weight 3.
    // Posed A = T(4, 0, 0), B = T(0, 4, 0): x-range only A -> +(4,0,0);
    // both -> +(1, 3, 0); only B -> +(0, 4, 0).
    const int n = 40000;
    Shorts pos(static_cast<std::size_t>(n) * 3);
    for (int v = 0; v < n; ++v) pos[static_cast<std::size_t>(v) * 3] = static_cast<std::int16_t>(v % 1000);
    Rig r(makeVB(pos), 2);
    r.mesh->addTransform(r.bones[0], 1, 0, 30000);
    r.mesh->addTransform(r.bones[1], 3, 10000, 30000);
    r.bones[0]->setTranslation(4, 0, 0);
    r.bones[1]->setTranslation(0, 4, 0);
    MeshDeformer d;
    ASSERT_TRUE(d.update(*r.mesh));
    for (int v : {0, 9999, 10000, 25000, 29999, 30000, 39999}) {
        const double x = v % 1000;
        if (v < 10000)
            expectPosition(d, v, x + 4, 0, 0);
        else if (v < 30000)
            expectPosition(d, v, x + 1, 3, 0);
        else
            expectPosition(d, v, x, 4, 0);
    }
    EXPECT_FALSE(d.update(*r.mesh));
}

TEST(SkinnedMeshDeform, InputsOnlyKeepsTheChangeDetectionWithoutRunningTheKernel) {
    // Output::InputsOnly (the compute path): the same answers from update(),
    // the kernel inputs exposed, vertices() left empty; inputStamp() moves
    // only when the static inputs were rebuilt, not with the pose.
    Rig r(makeVB({1, 0, 0, /**/ 0, 1, 0, /**/ 0, 0, 1}, 2.0f, {0, 0, 5}, {32767, 0, 0, 0, 32767, 0, 0, 0, 32767}), 2);
    r.mesh->addTransform(r.bones[0], 1, 0, 2);
    r.mesh->addTransform(r.bones[1], 3, 1, 1);
    MeshDeformer d;
    using Output = MeshDeformer::Output;
    EXPECT_TRUE(d.update(*r.mesh, Output::InputsOnly));
    EXPECT_TRUE(d.vertices().positions.empty());
    EXPECT_TRUE(d.vertices().normals.empty());
    EXPECT_EQ(d.vertices().vertexCount, 3);
    const detail::SkinInputs in = d.skinInputs();
    EXPECT_EQ(in.vertexCount, 3);
    EXPECT_EQ(in.positionScale, 2.0f);
    EXPECT_EQ(in.positionBias[2], 5.0f);
    ASSERT_EQ(in.positions.size(), 9u);
    EXPECT_EQ(in.positions[0], 1.0f);  // raw: the kernel applies scale and bias
    EXPECT_EQ(in.normals.size(), 9u);
    EXPECT_EQ(in.influenceStride, 4);
    EXPECT_EQ(in.palette.size(), 2u);
    EXPECT_EQ(in.bones.size(), 2u * 4u);  // the table covers vertices 0 and 1 only
    EXPECT_EQ(in.bones[4], 1);            // vertex 1: bone 1 (weight 3) before bone 0 (weight 1)
    EXPECT_FLOAT_EQ(in.weights[4], 0.75f);
    const auto stamp = d.inputStamp();

    EXPECT_FALSE(d.update(*r.mesh, Output::InputsOnly));  // nothing changed
    r.bones[1]->setTranslation(0, 1, 0);                    // the pose: the palette only
    EXPECT_TRUE(d.update(*r.mesh, Output::InputsOnly));
    EXPECT_EQ(d.inputStamp(), stamp);
    r.mesh->addTransform(r.bones[1], 1, 2, 1);  // the table: static inputs rebuilt
    EXPECT_TRUE(d.update(*r.mesh, Output::InputsOnly));
    EXPECT_GT(d.inputStamp(), stamp);
    EXPECT_EQ(d.skinInputs().bones.size(), 3u * 4u);

    // Switching the output recomputes, with the same result as a fresh deformer.
    EXPECT_TRUE(d.update(*r.mesh, Output::Vertices));
    MeshDeformer fresh;
    ASSERT_TRUE(fresh.update(*r.mesh));
    EXPECT_EQ(d.vertices().positions, fresh.vertices().positions);
    EXPECT_EQ(d.vertices().normals, fresh.vertices().normals);
    EXPECT_FALSE(d.update(*r.mesh, Output::Vertices));
    EXPECT_TRUE(d.update(*r.mesh, Output::InputsOnly));
}

TEST(SkinnedMeshDeform, BoneAddedAfterAnUpdateUsesItsAtRestMatrix) {
    // Bone 0 at the origin first; bone 1, at (0, 5, 0) when added after an
    // update, has at rest T(0, -5, 0): at rest vertex 1 stays where it is,
    // and moving bone 1 by (1, 0, 0) moves it by that much.
    Rig r(makeVB({1, 0, 0, 2, 5, 0}), 2);
    r.mesh->addTransform(r.bones[0], 1, 0, 1);
    MeshDeformer d;
    ASSERT_TRUE(d.update(*r.mesh));
    r.bones[1]->setTranslation(0, 5, 0);
    r.mesh->addTransform(r.bones[1], 1, 1, 1);
    ASSERT_TRUE(d.update(*r.mesh));
    expectPosition(d, 0, 1, 0, 0);
    expectPosition(d, 1, 2, 5, 0);
    r.bones[1]->setTranslation(1, 5, 0);
    ASSERT_TRUE(d.update(*r.mesh));
    expectPosition(d, 1, 3, 5, 0);
}

// Vertices that share their influences without being neighbours (bones
// interleaved vertex by vertex, as some exporters write them) go through
// the partition's compact space, sorted by influence set, and come back to
// their own vertices: the output order is the mesh's. 24 vertices, with
// normals: v % 3 == 0 bone 0 alone (a compact run), v % 3 == 1 bones 0 and
// 1 with weights that change from vertex to vertex (compact, loose), v % 3
// == 2 bone 1 alone (a compact run); bone 0 posed T(10, 0, 0), bone 1
// T(0, 20, 0).
TEST(SkinnedMeshDeform, InterleavedInfluencesComeOutInInfluenceOrder) {
    const int n = 24;
    Shorts pos, nrm;
    for (int v = 0; v < n; ++v) {
        const auto c = static_cast<std::int16_t>(v);
        pos.insert(pos.end(), {c, static_cast<std::int16_t>(2 * v), static_cast<std::int16_t>(-v)});
        nrm.insert(nrm.end(), {0, 0, 1000});
    }
    Rig r(makeVB(pos, 1.0f, {0, 0, 0}, nrm), 2);
    for (int v = 0; v < n; ++v) {
        if (v % 3 != 2) r.mesh->addTransform(r.bones[0], v % 3 == 0 ? 1 : 1 + v, v, 1);
        if (v % 3 != 0) r.mesh->addTransform(r.bones[1], v % 3 == 2 ? 1 : 30 - v, v, 1);
    }
    r.bones[0]->setTranslation(10, 0, 0);
    r.bones[1]->setTranslation(0, 20, 0);
    skin::InfluencePartition part;
    const skin::InfluenceTable& table = r.mesh->influenceTable();
    part.build(table.bones(), table.weights(), table.maxInfluences(), n);
    EXPECT_EQ(part.compactOrder().size(), static_cast<std::size_t>(n));  // nothing in mesh-order runs
    EXPECT_EQ(part.compactRuns(1).size(), 2u);                           // bone 0 alone, bone 1 alone
    // The eight two-bone vertices, each with its own weights: the table
    // puts the heavier bone first, bone 1 in v = 1, 4, 7, 10, 13 (a bone
    // run of five), bone 0 in v = 16, 19, 22 (fewer than kMinRun: loose).
    EXPECT_EQ(part.compactLoose(2).size(), 3u);
    ASSERT_EQ(part.compactBoneRuns(2).size(), 1u);
    EXPECT_EQ(part.compactBoneRuns(2)[0].vertexCount, 5u);
    MeshDeformer d;
    ASSERT_TRUE(d.update(*r.mesh));
    // The outputs stay in the compact space's order (nothing is copied back
    // to the mesh's): the eight bone-0 vertices, the eight bone-1 ones, then
    // the two-bone vertices; location inverts it.
    const auto& out = d.vertices();
    ASSERT_EQ(out.order.size(), static_cast<std::size_t>(n));
    ASSERT_EQ(out.location.size(), static_cast<std::size_t>(n));
    for (std::uint32_t i = 0; i < 8; ++i) {
        EXPECT_EQ(out.order[i], 3 * i) << i;
        EXPECT_EQ(out.order[8 + i], 3 * i + 2) << i;
    }
    for (std::uint32_t v = 0; v < static_cast<std::uint32_t>(n); ++v) EXPECT_EQ(out.order[out.location[v]], v);
    for (int v = 0; v < n; ++v) {
        double w0 = v % 3 == 0 ? 1.0 : v % 3 == 2 ? 0.0 : (1.0 + v) / ((1.0 + v) + (30.0 - v));
        expectPosition(d, v, v + 10.0 * w0, 2.0 * v + 20.0 * (1.0 - w0), -v);
        expectNormal(d, v, normalised(unit(0), unit(0), unit(1000)));
    }
}

// Rigid binding (Rigid::AsTransform): every vertex on one bone, weight 1.
// The bone is posed away from its rest pose with a rotation, a non-uniform
// scale and a translation, and the VertexBuffer has a scale and bias: the
// reported transform maps each raw position to the position the kernels
// give in Rigid::Deform (hand-computed for vertex 0), and its normal rows
// are the inverse transpose of the bone's 3x3.
TEST(SkinnedMeshDeform, RigidBindingReportsTheBoneInsteadOfDeforming) {
    Rig r(makeVB({10, 0, 0, /**/ 0, 10, 0, /**/ 3, -4, 7, /**/ -6, 2, 9}, 0.5f, {1, 2, 3},
                 {32767, 0, 0, /**/ 0, 32767, 0, /**/ 0, 0, 32767, /**/ 1000, -2000, 3000}),
          2);
    r.mesh->addTransform(r.bones[1], 1, 0, 2);
    r.mesh->addTransform(r.bones[1], 3, 2, 2);  // another weight, the same bone: still weight 1
    r.bones[1]->setTranslation(0, 0, 5);
    r.bones[1]->setScale(2, 1, 1);
    r.bones[1]->setOrientation(90, 0, 0, 1);
    using Output = MeshDeformer::Output;
    using Rigid = MeshDeformer::Rigid;
    MeshDeformer rigid, deformed;
    ASSERT_TRUE(rigid.update(*r.mesh, Output::Vertices, Rigid::AsTransform));
    ASSERT_TRUE(deformed.update(*r.mesh, Output::Vertices, Rigid::Deform));
    ASSERT_TRUE(rigid.vertices().rigid);
    EXPECT_FALSE(deformed.vertices().rigid);
    const skin::PaletteEntry& e = rigid.vertices().rigidTransform;
    auto apply = [](const float* rows, double x, double y, double z, int row, bool translate) {
        return rows[row * 4] * x + rows[row * 4 + 1] * y + rows[row * 4 + 2] * z + (translate ? rows[row * 4 + 3] : 0.0);
    };
    // Vertex 0: 0.5 (10, 0, 0) + (1, 2, 3) = (6, 2, 3); the bone's transform
    // T(0, 0, 5) R(90 about z) S(2, 1, 1): S -> (12, 2, 3), R -> (-2, 12, 3),
    // T -> (-2, 12, 8).
    EXPECT_NEAR(apply(e.position, 10, 0, 0, 0, true), -2.0, 1e-5);
    EXPECT_NEAR(apply(e.position, 10, 0, 0, 1, true), 12.0, 1e-5);
    EXPECT_NEAR(apply(e.position, 10, 0, 0, 2, true), 8.0, 1e-5);
    expectPosition(deformed, 0, -2, 12, 8);
    const Shorts raw = {10, 0, 0, 0, 10, 0, 3, -4, 7, -6, 2, 9};
    const Shorts rawNormals = {32767, 0, 0, 0, 32767, 0, 0, 0, 32767, 1000, -2000, 3000};
    for (int v = 0; v < 4; ++v) {
        double p[3], n[3];
        for (int c = 0; c < 3; ++c) {
            p[c] = apply(e.position, raw[v * 3], raw[v * 3 + 1], raw[v * 3 + 2], c, true);
            n[c] = apply(e.normal, unit(rawNormals[v * 3]), unit(rawNormals[v * 3 + 1]), unit(rawNormals[v * 3 + 2]),
                         c, false);
        }
        expectPosition(deformed, v, p[0], p[1], p[2]);
        expectNormal(deformed, v, normalised(n[0], n[1], n[2]), 1e-5);
    }
    // Normal x (1, 0, 0) after S(2, 1, 1)'s inverse transpose and R: (0, 1/2, 0), that is +y.
    const auto nx = normalised(apply(e.normal, 1, 0, 0, 0, false), apply(e.normal, 1, 0, 0, 1, false),
                               apply(e.normal, 1, 0, 0, 2, false));
    EXPECT_NEAR(nx[1], 1.0, 1e-6);

    // The pose moves: the transform follows and update() says so; it does
    // not move: nothing changed.
    EXPECT_FALSE(rigid.update(*r.mesh, Output::Vertices, Rigid::AsTransform));
    r.bones[1]->setTranslation(0, 0, 6);
    EXPECT_TRUE(rigid.update(*r.mesh, Output::Vertices, Rigid::AsTransform));
    EXPECT_NEAR(rigid.vertices().rigidTransform.position[11], 6.0 + 3.0, 1e-5);  // bias z 3, then + 6
    // Asked to deform after all: the vertices, as a fresh deformer makes them.
    EXPECT_TRUE(rigid.update(*r.mesh, Output::Vertices, Rigid::Deform));
    EXPECT_FALSE(rigid.vertices().rigid);
    MeshDeformer fresh;
    ASSERT_TRUE(fresh.update(*r.mesh));
    EXPECT_EQ(rigid.vertices().positions, fresh.vertices().positions);
    EXPECT_EQ(rigid.vertices().normals, fresh.vertices().normals);
    // The compute path's output mode reports it too.
    EXPECT_TRUE(rigid.update(*r.mesh, Output::InputsOnly, Rigid::AsTransform));
    EXPECT_TRUE(rigid.vertices().rigid);
}

TEST(SkinnedMeshDeform, RigidBindingNeedsOneBoneOnEveryVertex) {
    using Output = MeshDeformer::Output;
    using Rigid = MeshDeformer::Rigid;
    auto rigid = [](Rig& r) {
        MeshDeformer d;
        d.update(*r.mesh, Output::Vertices, Rigid::AsTransform);
        return d.vertices().rigid;
    };
    const Shorts three = {1, 0, 0, /**/ 0, 1, 0, /**/ 0, 0, 1};
    {
        Rig r(makeVB(three), 2);  // two bones, one per part
        r.mesh->addTransform(r.bones[0], 1, 0, 2);
        r.mesh->addTransform(r.bones[1], 1, 2, 1);
        EXPECT_FALSE(rigid(r));
    }
    {
        Rig r(makeVB(three), 2);  // vertex 1 blends two bones
        r.mesh->addTransform(r.bones[0], 1, 0, 3);
        r.mesh->addTransform(r.bones[1], 1, 1, 1);
        EXPECT_FALSE(rigid(r));
    }
    {
        Rig r(makeVB(three), 1);  // vertex 2 has no bone (beyond the table)
        r.mesh->addTransform(r.bones[0], 1, 0, 2);
        EXPECT_FALSE(rigid(r));
    }
    {
        Rig r(makeVB(three), 1);  // no bone at all
        EXPECT_FALSE(rigid(r));
    }
    {
        Rig r(makeVB(three), 1);  // the binding becomes rigid, then stops being
        r.mesh->addTransform(r.bones[0], 1, 0, 2);
        MeshDeformer d;
        d.update(*r.mesh, Output::Vertices, Rigid::AsTransform);
        EXPECT_FALSE(d.vertices().rigid);
        r.mesh->addTransform(r.bones[0], 1, 2, 1);
        EXPECT_TRUE(d.update(*r.mesh, Output::Vertices, Rigid::AsTransform));
        EXPECT_TRUE(d.vertices().rigid);
        Ref<Group> other = new Group();
        r.skeleton->addChild(other);
        r.mesh->addTransform(other, 1, 2, 1);
        other->setTranslation(0, 0, 4);  // moved from its rest pose
        EXPECT_TRUE(d.update(*r.mesh, Output::Vertices, Rigid::AsTransform));
        EXPECT_FALSE(d.vertices().rigid);
        expectPosition(d, 0, 1, 0, 0);
        expectPosition(d, 2, 0, 0, 3);  // half at rest, half moved by (0, 0, 4)
    }
}
