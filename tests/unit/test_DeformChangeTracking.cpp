// Change tracking of SkinnedMesh deformation across frames: BoneTransforms
// composes only the nodes that changed (Object3D revisions along the bones'
// paths), and MeshDeformer skins again only the runs whose bones' palette
// entries changed. The expectations are independent of that tracking: each
// frame's result must equal, bit for bit, what a fresh BoneTransforms or
// MeshDeformer computes from scratch, and Node::getTransformTo within float
// rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <m3g/Group.h>
#include <m3g/SkinnedMesh.h>
#include <m3g/TriangleStripArray.h>
#include <m3g/VertexArray.h>
#include <m3g/VertexBuffer.h>

#include "BoneTransforms.h"
#include "MeshDeformer.h"

using namespace m3g;
using m3g::detail::BoneTransforms;
using m3g::detail::MeshDeformer;

namespace {

// A random skeleton (a tree of groups under one root, random poses) and a
// SkinnedMesh over it whose vertices are in mesh-order runs (ranges of one
// bone), loose with several bones (overlapping ranges), and without bones.
struct RandomRig {
    std::mt19937 rng;
    Ref<Group> skeleton = new Group();
    std::vector<Ref<Group>> nodes;  // [0] the skeleton root
    Ref<SkinnedMesh> mesh;
    std::uniform_real_distribution<float> u{-1.0f, 1.0f}, s{0.6f, 1.6f};

    void pose(Group* g) {
        g->setTranslation(2 * u(rng), 2 * u(rng), 2 * u(rng));
        g->setOrientation(180 * u(rng), u(rng), u(rng), u(rng) + 0.01f);
        g->setScale(s(rng), s(rng), s(rng));
    }

    RandomRig(unsigned seed, int groups, int vertices) : rng(seed) {
        nodes.push_back(skeleton);
        for (int i = 0; i < groups; ++i) {
            Ref<Group> g = new Group();
            std::uniform_int_distribution<std::size_t> parent(0, nodes.size() - 1);
            nodes[parent(rng)]->addChild(g);
            pose(g);
            nodes.push_back(g);
        }
        std::vector<std::int16_t> pos, nrm;
        std::uniform_int_distribution<int> coord(-3000, 3000), comp(-32768, 32767);
        for (int i = 0; i < vertices * 3; ++i) {
            pos.push_back(static_cast<std::int16_t>(coord(rng)));
            nrm.push_back(static_cast<std::int16_t>(comp(rng)));
        }
        Ref<VertexBuffer> vb = new VertexBuffer();
        Ref<VertexArray> p = new VertexArray(vertices, 3, 2), n = new VertexArray(vertices, 3, 2);
        p->set(0, vertices, pos);
        n->set(0, vertices, nrm);
        const float bias[] = {0.25f, -0.5f, 1.0f};
        vb->setPositions(p, 0.003f, bias);
        vb->setNormals(n);
        const int lengths[] = {vertices};
        mesh = new SkinnedMesh(vb, new TriangleStripArray(0, lengths), nullptr, skeleton);
        // The first tenth without bones; then one-bone ranges of 4..40
        // vertices (runs); then overlapping ranges (loose vertices and
        // compact runs).
        std::uniform_int_distribution<std::size_t> node(1, nodes.size() - 1);
        std::uniform_int_distribution<int> weight(1, 5), len(4, 40);
        int v = vertices / 10;
        const int runsEnd = vertices * 6 / 10;
        while (v < runsEnd) {
            const int c = std::min(len(rng), runsEnd - v);
            mesh->addTransform(nodes[node(rng)], 1, v, c);
            v += c;
        }
        std::uniform_int_distribution<int> first(runsEnd, vertices - 1), shortLen(1, 12);
        for (int i = 0; i < vertices / 3; ++i) {
            const int f = first(rng);
            mesh->addTransform(nodes[node(rng)], weight(rng), f, std::min(shortLen(rng), vertices - f));
        }
    }
};

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

}  // namespace

TEST(BoneTransforms, ComposesOnlyWhatMovedAndMatchesAFreshComputation) {
    RandomRig rig(7, 30, 400);
    BoneTransforms kept;
    std::vector<float> keptOut;
    ASSERT_TRUE(kept.compute(*rig.mesh, keptOut));
    const int bones = rig.mesh->boneCount();
    ASSERT_GT(bones, 10);
    EXPECT_FALSE(kept.compute(*rig.mesh, keptOut));  // nothing moved
    for (std::uint8_t c : kept.changedBones()) EXPECT_EQ(c, 0);

    std::uniform_int_distribution<std::size_t> pick(0, rig.nodes.size() - 1);
    for (int frame = 0; frame < 40; ++frame) {
        // Move one to three nodes (the skeleton root too, sometimes).
        std::vector<const Node*> moved;
        const int count = 1 + frame % 3;
        for (int i = 0; i < count; ++i) {
            Group* g = rig.nodes[pick(rig.rng)];
            rig.pose(g);
            moved.push_back(g);
        }
        ASSERT_TRUE(kept.compute(*rig.mesh, keptOut));
        BoneTransforms fresh;
        std::vector<float> freshOut;
        fresh.compute(*rig.mesh, freshOut);
        EXPECT_TRUE(sameBits(keptOut, freshOut)) << "frame " << frame;
        for (int b = 0; b < bones; ++b) {
            // Composed again exactly when a moved node is the bone or above it.
            bool below = false;
            for (const Node* n = rig.mesh->bone(b); n && n != rig.mesh.get(); n = n->parentNode())
                for (const Node* m : moved) below = below || n == m;
            EXPECT_EQ(kept.changedBones()[static_cast<std::size_t>(b)] != 0, below) << "frame " << frame << " bone " << b;
            Transform t;
            ASSERT_TRUE(rig.mesh->bone(b)->getTransformTo(rig.mesh.get(), &t));
            for (int e = 0; e < 16; ++e)
                EXPECT_NEAR(keptOut[static_cast<std::size_t>(b) * 16 + e], t.rows()[e],
                            2e-4 * std::max(1.0f, std::fabs(t.rows()[e])));
        }
    }
}

TEST(BoneTransforms, AnotherMeshOrANewBoneListsThePathsAgain) {
    RandomRig a(11, 12, 100), b(12, 12, 100);
    BoneTransforms t;
    std::vector<float> out, fresh;
    t.compute(*a.mesh, out);
    ASSERT_TRUE(t.compute(*b.mesh, out));  // another mesh: all composed
    BoneTransforms().compute(*b.mesh, fresh);
    EXPECT_TRUE(sameBits(out, fresh));
    // A bone not used before (a group added under the skeleton).
    Ref<Group> extra = new Group();
    b.nodes[3]->addChild(extra);
    extra->setTranslation(1, 2, 3);
    b.mesh->addTransform(extra, 1, 0, 4);
    ASSERT_TRUE(t.compute(*b.mesh, out));
    BoneTransforms().compute(*b.mesh, fresh);
    EXPECT_TRUE(sameBits(out, fresh));
    EXPECT_EQ(out.size(), static_cast<std::size_t>(b.mesh->boneCount()) * 16);
}

TEST(SkinnedMeshDeform, PartialFramesEqualFullRecomputation) {
    // Frame after frame, a few nodes move; the kept deformer skins only the
    // runs of changed bones (and every loose vertex) and must give the same
    // bits as a deformer computing everything.
    RandomRig rig(2024, 24, 900);
    MeshDeformer kept;
    ASSERT_TRUE(kept.update(*rig.mesh));
    std::uniform_int_distribution<std::size_t> pick(1, rig.nodes.size() - 1);
    int updated = 0;
    for (int frame = 0; frame < 60; ++frame) {
        const int count = frame % 4;  // frame 0, 4, 8...: nothing moves
        for (int i = 0; i < count; ++i) rig.pose(rig.nodes[pick(rig.rng)]);
        const bool changed = kept.update(*rig.mesh);
        if (count == 0) {
            EXPECT_FALSE(changed) << "frame " << frame;
        }
        updated += changed;
        MeshDeformer fresh;
        ASSERT_TRUE(fresh.update(*rig.mesh));
        EXPECT_TRUE(sameBits(kept.vertices().positions, fresh.vertices().positions)) << "frame " << frame;
        EXPECT_TRUE(sameBits(kept.vertices().normals, fresh.vertices().normals)) << "frame " << frame;
    }
    EXPECT_GT(updated, 30);  // most moves reach a bone
}

TEST(SkinnedMeshDeform, MovingASharedAncestorMovesEveryBoneBelowIt) {
    // joint -> {boneA, boneB}; vertices 0-7 on A (a run), 8-15 on B.
    Ref<Group> skeleton = new Group(), joint = new Group(), boneA = new Group(), boneB = new Group();
    skeleton->addChild(joint);
    joint->addChild(boneA);
    joint->addChild(boneB);
    std::vector<std::int16_t> pos;
    for (int v = 0; v < 16; ++v) pos.insert(pos.end(), {static_cast<std::int16_t>(v), 0, 0});
    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<VertexArray> p = new VertexArray(16, 3, 2);
    p->set(0, 16, pos);
    vb->setPositions(p, 1.0f, {});  // no bias
    const int lengths[] = {16};
    Ref<SkinnedMesh> mesh = new SkinnedMesh(vb, new TriangleStripArray(0, lengths), nullptr, skeleton);
    mesh->addTransform(boneA, 1, 0, 8);
    mesh->addTransform(boneB, 1, 8, 8);
    MeshDeformer d;
    ASSERT_TRUE(d.update(*mesh));
    boneA->setTranslation(0, 1, 0);  // only A's vertices move
    ASSERT_TRUE(d.update(*mesh));
    const auto& out = d.vertices().positions;
    for (int v = 0; v < 16; ++v) {
        EXPECT_FLOAT_EQ(out[v * 3], static_cast<float>(v));
        EXPECT_FLOAT_EQ(out[v * 3 + 1], v < 8 ? 1.0f : 0.0f) << "vertex " << v;
    }
    joint->setTranslation(0, 0, 5);  // both bones' vertices move
    ASSERT_TRUE(d.update(*mesh));
    for (int v = 0; v < 16; ++v) {
        EXPECT_FLOAT_EQ(d.vertices().positions[v * 3 + 1], v < 8 ? 1.0f : 0.0f) << "vertex " << v;
        EXPECT_FLOAT_EQ(d.vertices().positions[v * 3 + 2], 5.0f) << "vertex " << v;
    }
    joint->setTranslation(0, 0, 5);  // the same value again: a new revision, the same palette
    EXPECT_FALSE(d.update(*mesh));
}
