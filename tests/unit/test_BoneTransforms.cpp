// detail::BoneTransforms: every bone's transform to its SkinnedMesh in one
// pass, each shared ancestor composed once. Checked against hand-computed
// matrices and against Node::getTransformTo (the general path, tested in
// test_Node.cpp) on a branching skeleton in two poses.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <m3g/Group.h>
#include <m3g/SkinnedMesh.h>
#include <m3g/TriangleStripArray.h>
#include <m3g/VertexArray.h>
#include <m3g/VertexBuffer.h>

#include "BoneTransforms.h"

using namespace m3g;

namespace {

Ref<SkinnedMesh> meshWith(Group* skeleton) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<VertexArray> p = new VertexArray(3, 3, 2);
    const std::vector<std::int16_t> xyz{0, 0, 0, 1, 0, 0, 0, 1, 0};
    p->set(0, 3, xyz);
    vb->setPositions(p, 1.0f, std::array<float, 3>{0, 0, 0});
    const int lengths[] = {3};
    return new SkinnedMesh(vb, new TriangleStripArray(0, lengths), nullptr, skeleton);
}

/// Bone b's 16 floats against getTransformTo(mesh).
void expectLikeGetTransformTo(const SkinnedMesh& mesh, const std::vector<float>& out) {
    ASSERT_EQ(out.size(), static_cast<std::size_t>(mesh.boneCount()) * 16);
    for (int b = 0; b < mesh.boneCount(); ++b) {
        Transform t;
        mesh.bone(b)->getTransformTo(&mesh, &t);
        for (int i = 0; i < 16; ++i) {
            const float e = t.rows()[static_cast<std::size_t>(i)];
            EXPECT_NEAR(out[static_cast<std::size_t>(b) * 16 + static_cast<std::size_t>(i)], e,
                        2e-6f * std::max(1.0f, std::abs(e)))
                << "bone " << b << " element " << i;
        }
    }
}

}  // namespace

TEST(BoneTransforms, ChainHandComputed) {
    // skeleton T(0, 0, 3) -> upper T(1, 0, 0) Rz(90) -> lower T(2, 0, 0):
    // lower -> mesh = T(0,0,3) T(1,0,0) Rz(90) T(2,0,0), which maps the
    // origin to (1, 2, 3) and x to y. Bones added lower first, so upper is
    // found memoised.
    Ref<Group> skeleton = new Group(), upper = new Group(), lower = new Group();
    skeleton->addChild(upper);
    upper->addChild(lower);
    skeleton->setTranslation(0, 0, 3);
    upper->setTranslation(1, 0, 0);
    upper->setOrientation(90, 0, 0, 1);
    lower->setTranslation(2, 0, 0);
    Ref<SkinnedMesh> mesh = meshWith(skeleton);
    mesh->addTransform(lower, 1, 0, 1);
    mesh->addTransform(upper, 1, 1, 1);
    ASSERT_EQ(mesh->boneCount(), 2);
    ASSERT_EQ(mesh->bone(0), lower.get());
    std::vector<float> out;
    detail::BoneTransforms bt;
    bt.compute(*mesh, out);
    const std::array<float, 16> lowerExpected{0, -1, 0, 1, 1, 0, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1};
    const std::array<float, 16> upperExpected{0, -1, 0, 1, 1, 0, 0, 0, 0, 0, 1, 3, 0, 0, 0, 1};
    for (int i = 0; i < 16; ++i) {
        EXPECT_NEAR(out[static_cast<std::size_t>(i)], lowerExpected[static_cast<std::size_t>(i)], 1e-6f) << i;
        EXPECT_NEAR(out[16 + static_cast<std::size_t>(i)], upperExpected[static_cast<std::size_t>(i)], 1e-6f) << i;
    }
}

TEST(BoneTransforms, BranchingSkeletonAgreesWithGetTransformToAcrossPoses) {
    // skeleton -> spine -> chest -> {arm L -> hand L, arm R -> hand R, neck -> head},
    // with scales, rotations and a generic matrix; bones in an order where
    // some are ancestors of bones met before them.
    Ref<Group> skeleton = new Group();
    auto child = [](Group* parent, float tx, float angle) {
        Ref<Group> g = new Group();
        parent->addChild(g);
        g->setTranslation(tx, 0.5f * tx, 0.25f);
        g->setOrientation(angle, 0.3f, 1.0f, 0.2f);
        return g;
    };
    Ref<Group> spine = child(skeleton, 0.0f, 10), chest = child(spine, 1.0f, -20);
    Ref<Group> armL = child(chest, 0.7f, 35), handL = child(armL, 1.2f, -15);
    Ref<Group> armR = child(chest, -0.7f, -35), handR = child(armR, -1.2f, 15);
    Ref<Group> neck = child(chest, 0.1f, 5), head = child(neck, 0.3f, 50);
    chest->setScale(1.5f, 0.5f, 2.0f);
    Transform generic;
    generic.postRotate(30, 1, 0, 0);
    generic.postScale(1, 2, 1);
    armR->setTransform(&generic);
    skeleton->setTranslation(3, -2, 1);
    Ref<SkinnedMesh> mesh = meshWith(skeleton);
    mesh->setTranslation(5, 5, 5);  // the mesh's own transform is not part of bone -> mesh
    for (Group* bone : {handL.get(), armL.get(), head.get(), handR.get(), spine.get(), chest.get()})
        mesh->addTransform(bone, 1, 0, 3);
    detail::BoneTransforms bt;
    std::vector<float> out;
    bt.compute(*mesh, out);
    expectLikeGetTransformTo(*mesh, out);
    // A new pose: the memo of the previous call must not leak into this one.
    chest->setOrientation(70, 0, 0, 1);
    armL->setScale(2, 2, 2);
    skeleton->setTranslation(0, 0, 0);
    bt.compute(*mesh, out);
    expectLikeGetTransformTo(*mesh, out);
}

TEST(BoneTransforms, DeepChainGrowsTheMemo) {
    // One bone 50 levels below the skeleton (and one halfway): many more
    // nodes than the memo starts with room for, met in one call.
    Ref<Group> skeleton = new Group();
    std::vector<Ref<Group>> chain;
    Group* parent = skeleton.get();
    for (int i = 0; i < 50; ++i) {
        chain.push_back(new Group());
        parent->addChild(chain.back());
        chain.back()->setTranslation(0.1f, 0.0f, 0.02f * static_cast<float>(i % 3));
        chain.back()->setOrientation(3.0f, 0.0f, 0.0f, 1.0f);
        parent = chain.back().get();
    }
    Ref<SkinnedMesh> mesh = meshWith(skeleton);
    mesh->addTransform(chain.back(), 1, 0, 2);
    mesh->addTransform(chain[24], 1, 2, 1);
    detail::BoneTransforms bt;
    std::vector<float> out;
    bt.compute(*mesh, out);
    expectLikeGetTransformTo(*mesh, out);
    // 50 turns of 3 degrees about z: the deepest bone's x axis at 150 degrees.
    EXPECT_NEAR(out[0], std::cos(150.0 * 3.14159265358979 / 180.0), 1e-5);
    EXPECT_NEAR(out[4], std::sin(150.0 * 3.14159265358979 / 180.0), 1e-5);
    bt.compute(*mesh, out);  // again, with the grown table
    expectLikeGetTransformTo(*mesh, out);
}

TEST(BoneTransforms, IdentityBonePassesItsParentsTransformOnUntilItMoves) {
    // skeleton -> joint (animated) -> bone (identity, the way exporters write
    // a bone under its joint), and a second identity node under that bone.
    // The identity nodes take their parent's transform while only the
    // parent moves; once the bone gets a transform of its own (and when it
    // returns to the identity) it is composed again, and the tip follows it.
    Ref<Group> skeleton = new Group(), joint = new Group(), bone = new Group(), tip = new Group();
    skeleton->addChild(joint);
    joint->addChild(bone);
    bone->addChild(tip);
    skeleton->setTranslation(1, 2, 3);
    Ref<SkinnedMesh> mesh = meshWith(skeleton);
    mesh->addTransform(bone, 1, 0, 2);
    mesh->addTransform(tip, 1, 2, 1);
    detail::BoneTransforms bt;
    std::vector<float> out;
    auto pose = [&](float angle) {
        joint->setOrientation(angle, 0.2f, 1.0f, 0.4f);
        joint->setTranslation(0.5f, -1.0f, 0.25f * angle);
        EXPECT_TRUE(bt.compute(*mesh, out));
        expectLikeGetTransformTo(*mesh, out);
    };
    pose(10);
    pose(35);
    // joint -> mesh: T(1, 2, 3) T(0.5, -1, 8.75) R; both bones carry it, their translation the sum.
    EXPECT_NEAR(out[3], 1.5f, 1e-5f);
    EXPECT_NEAR(out[7], 1.0f, 1e-5f);
    EXPECT_NEAR(out[11], 3.0f + 0.25f * 35.0f, 1e-5f);
    for (int i = 0; i < 16; ++i) EXPECT_EQ(out[static_cast<std::size_t>(i)], out[16 + static_cast<std::size_t>(i)]) << i;
    const std::vector<float> before = out;
    bone->setTranslation(0, 2, 0);  // the bone moves on its own
    EXPECT_TRUE(bt.compute(*mesh, out));
    expectLikeGetTransformTo(*mesh, out);
    EXPECT_NE(out[7], before[7]) << "the bone kept the joint's transform";
    for (int i = 0; i < 16; ++i) EXPECT_EQ(out[static_cast<std::size_t>(i)], out[16 + static_cast<std::size_t>(i)]) << i;
    pose(60);
    bone->setTranslation(0, 0, 0);  // back to the identity
    pose(80);
    for (int i = 0; i < 16; ++i) EXPECT_EQ(out[static_cast<std::size_t>(i)], out[16 + static_cast<std::size_t>(i)]) << i;
    EXPECT_FALSE(bt.compute(*mesh, out)) << "nothing moved";
}
