// SkinnedMesh (JSR-184 1.1, SkinnedMesh) and the bone rule of Group::removeChild.
#include <gtest/gtest.h>

#include <vector>

#include <m3g/Group.h>
#include <m3g/Limits.h>
#include <m3g/SkinnedMesh.h>
#include <m3g/skin/InfluenceTable.h>
#include <m3g/TriangleStripArray.h>
#include <m3g/World.h>

using namespace m3g;
using Ints = std::vector<int>;
using Floats = std::vector<float>;

namespace {
Ref<VertexBuffer> makeVB() {
    Ref<VertexBuffer> vb = new VertexBuffer();
    vb->setPositions(new VertexArray(8, 3, 2), 1.0f, {});
    return vb;
}
Ref<IndexBuffer> makeIB() {
    const int lengths[] = {8};
    return new TriangleStripArray(0, lengths);
}

struct LimitsGuard {
    Limits saved = getLimits();
    ~LimitsGuard() { setLimits(saved); }
};

// skeleton -> upper -> lower, skeleton -> other.
struct Rig {
    Ref<VertexBuffer> vb = makeVB();
    Ref<IndexBuffer> ib = makeIB();
    Ref<Group> skeleton = new Group();
    Ref<Group> upper = new Group();
    Ref<Group> lower = new Group();
    Ref<Group> other = new Group();
    Ref<SkinnedMesh> mesh;
    Rig() {
        skeleton->addChild(upper);
        upper->addChild(lower);
        skeleton->addChild(other);
        mesh = new SkinnedMesh(vb, ib, nullptr, skeleton);
    }
};

void expectRows(const Transform& t, const std::array<float, 16>& rows) {
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(t.rows()[static_cast<std::size_t>(i)], rows[static_cast<std::size_t>(i)], 1e-5f) << "element " << i;
}
}  // namespace

TEST(SkinnedMesh, SkeletonBecomesChildOfTheMesh) {
    Rig r;
    EXPECT_STREQ(r.mesh->getClassName(), "SkinnedMesh");
    EXPECT_EQ(r.mesh->getSkeleton(), r.skeleton);
    EXPECT_EQ(r.skeleton->getParent().get(), r.mesh.get());
    EXPECT_TRUE(r.lower->isDescendantOf(r.mesh));
    EXPECT_EQ(r.mesh->getVertexBuffer(), r.vb);
    EXPECT_EQ(r.mesh->getIndexBuffer(0), r.ib);
    EXPECT_EQ(r.mesh->boneCount(), 0);
    EXPECT_EQ(r.mesh->influenceTable().maxInfluences(), getLimits().maxTransformsPerVertex);
    std::vector<Node*> kids;
    r.mesh->collectChildren(kids);
    ASSERT_EQ(kids.size(), 1u);
    EXPECT_EQ(kids[0], r.skeleton.get());
    // The skeleton cannot be given a second parent.
    Ref<Group> g = new Group();
    EXPECT_THROW(g->addChild(r.skeleton), IllegalArgumentException);
}

TEST(SkinnedMesh, SubmeshArrayConstructor) {
    std::vector<Ref<IndexBuffer>> ibs{makeIB(), makeIB()};
    Ref<Group> sk = new Group();
    Ref<SkinnedMesh> m = new SkinnedMesh(makeVB(), ibs, {}, sk);
    EXPECT_EQ(m->getSubmeshCount(), 2);
    EXPECT_EQ(sk->getParent().get(), m.get());
}

TEST(SkinnedMesh, ConstructorErrors) {
    Ref<VertexBuffer> vb = makeVB();
    Ref<IndexBuffer> ib = makeIB();
    EXPECT_THROW(SkinnedMesh(vb, ib, nullptr, nullptr), NullPointerException);
    Ref<Group> parent = new Group();
    Ref<Group> owned = new Group();
    parent->addChild(owned);
    EXPECT_THROW(SkinnedMesh(vb, ib, nullptr, owned), IllegalArgumentException);
    EXPECT_EQ(owned->getParent(), parent);
    Ref<World> world = new World();
    EXPECT_THROW(SkinnedMesh(vb, ib, nullptr, world), IllegalArgumentException);
    EXPECT_EQ(world->getParent(), nullptr);
    // Mesh checks apply too; a failed construction leaves the skeleton free.
    Ref<Group> free = new Group();
    EXPECT_THROW(SkinnedMesh(nullptr, ib, nullptr, free), NullPointerException);
    EXPECT_EQ(free->getParent(), nullptr);
    // A skeleton already used by another SkinnedMesh has a parent.
    Ref<SkinnedMesh> first = new SkinnedMesh(vb, ib, nullptr, free);
    EXPECT_THROW(SkinnedMesh(vb, ib, nullptr, free), IllegalArgumentException);
    EXPECT_EQ(free->getParent().get(), first.get());
}

TEST(SkinnedMesh, DestructorDetachesSkeleton) {
    Ref<Group> sk = new Group();
    {
        Ref<SkinnedMesh> m = new SkinnedMesh(makeVB(), makeIB(), nullptr, sk);
        EXPECT_EQ(sk->getParent().get(), m.get());
    }
    EXPECT_EQ(sk->getParent(), nullptr);
    EXPECT_EQ(sk->getRefCount(), 1);
}

TEST(SkinnedMesh, ReferencesMeshThenSkeleton) {
    Rig r;
    std::vector<Ref<Object3D>> refs(3);
    ASSERT_EQ(r.mesh->getReferences(refs), 3);
    EXPECT_EQ(refs[0].get(), r.vb.get());
    EXPECT_EQ(refs[1].get(), r.ib.get());
    EXPECT_EQ(refs[2].get(), r.skeleton.get());
    r.lower->setUserID(77);
    EXPECT_EQ(r.mesh->find(77).get(), r.lower.get());  // reachable through the skeleton
}

TEST(SkinnedMesh, AddTransformErrors) {
    Rig r;
    Ref<Group> stranger = new Group();
    EXPECT_THROW(r.mesh->addTransform(nullptr, 1, 0, 1), NullPointerException);
    EXPECT_THROW(r.mesh->addTransform(stranger, 1, 0, 1), IllegalArgumentException);
    EXPECT_THROW(r.mesh->addTransform(r.mesh, 1, 0, 1), IllegalArgumentException);  // the mesh is not a bone
    EXPECT_THROW(r.mesh->addTransform(r.lower, 0, 0, 1), IllegalArgumentException);
    EXPECT_THROW(r.mesh->addTransform(r.lower, -3, 0, 1), IllegalArgumentException);
    EXPECT_THROW(r.mesh->addTransform(r.lower, 1, 0, 0), IllegalArgumentException);
    EXPECT_THROW(r.mesh->addTransform(r.lower, 1, 0, -1), IllegalArgumentException);
    EXPECT_THROW(r.mesh->addTransform(r.lower, 1, -1, 1), IndexOutOfBoundsException);
    EXPECT_THROW(r.mesh->addTransform(r.lower, 1, 65535, 1), IndexOutOfBoundsException);
    EXPECT_THROW(r.mesh->addTransform(r.lower, 1, 65000, 536), IndexOutOfBoundsException);
    EXPECT_EQ(r.mesh->boneCount(), 0);
    EXPECT_EQ(r.lower->boneUseCount(), 0);
    EXPECT_NO_THROW(r.mesh->addTransform(r.lower, 1, 65000, 535));  // ends at 65535
    EXPECT_NO_THROW(r.mesh->addTransform(r.skeleton, 1, 0, 1));     // the skeleton root is a bone too
}

TEST(SkinnedMesh, SingularAtRestTransformLeavesNoTrace) {
    Rig r;
    r.lower->setScale(0, 1, 1);
    EXPECT_THROW(r.mesh->addTransform(r.lower, 1, 0, 1), ArithmeticException);
    EXPECT_EQ(r.mesh->boneCount(), 0);
    EXPECT_EQ(r.lower->boneUseCount(), 0);
    EXPECT_EQ(r.mesh->influenceTable().vertexCount(), 0);
}

TEST(SkinnedMesh, BonesGetDenseIndicesInOrderOfFirstUse) {
    Rig r;
    const auto rev = r.mesh->getRevision();
    r.mesh->addTransform(r.lower, 1, 0, 2);
    EXPECT_GT(r.mesh->getRevision(), rev);
    r.mesh->addTransform(r.upper, 1, 0, 2);
    r.mesh->addTransform(r.lower, 1, 4, 2);
    ASSERT_EQ(r.mesh->boneCount(), 2);
    EXPECT_EQ(r.mesh->bone(0), r.lower.get());
    EXPECT_EQ(r.mesh->bone(1), r.upper.get());
    EXPECT_EQ(r.mesh->boneIndex(r.lower), 0);
    EXPECT_EQ(r.mesh->boneIndex(r.upper), 1);
    EXPECT_EQ(r.mesh->boneIndex(r.other), -1);
    EXPECT_EQ(r.lower->boneUseCount(), 1);
    EXPECT_EQ(r.upper->boneUseCount(), 1);
    EXPECT_EQ(r.other->boneUseCount(), 0);
    ASSERT_EQ(r.lower->boneOwners().size(), 1u);
    EXPECT_EQ(r.lower->boneOwners()[0], r.mesh.get());
    EXPECT_EQ(r.mesh->influenceTable().boneCount(), 2);
}

TEST(SkinnedMesh, AtRestTransformIsCapturedAtFirstUse) {
    Rig r;
    Ref<Group> root = new Group();
    root->addChild(r.mesh);
    root->setTranslation(50, 0, 0);      // above the mesh: irrelevant
    r.mesh->setTranslation(100, 0, 0);   // the mesh's own transform: irrelevant (mesh space)
    r.skeleton->setTranslation(1, 2, 3);
    r.upper->setTranslation(0, 10, 0);
    r.mesh->addTransform(r.upper, 1, 0, 1);
    // upper -> mesh = T(1, 12, 3); at rest (mesh -> upper) = T(-1, -12, -3).
    Transform t;
    r.mesh->getBoneTransform(r.upper, &t);
    expectRows(t, {1, 0, 0, -1, 0, 1, 0, -12, 0, 0, 1, -3, 0, 0, 0, 1});
    expectRows(r.mesh->atRestTransform(0), {1, 0, 0, -1, 0, 1, 0, -12, 0, 0, 1, -3, 0, 0, 0, 1});
    // Moving the bone later does not change its at-rest matrix...
    r.upper->setTranslation(0, 20, 0);
    r.mesh->addTransform(r.upper, 1, 1, 1);
    r.mesh->getBoneTransform(r.upper, &t);
    expectRows(t, {1, 0, 0, -1, 0, 1, 0, -12, 0, 0, 1, -3, 0, 0, 0, 1});
    // ...but a bone added now sees the current pose: lower -> mesh = T(1, 22, 8).
    r.lower->setTranslation(0, 0, 5);
    r.mesh->addTransform(r.lower, 1, 0, 1);
    r.mesh->getBoneTransform(r.lower, &t);
    expectRows(t, {1, 0, 0, -1, 0, 1, 0, -22, 0, 0, 1, -8, 0, 0, 0, 1});
}

TEST(SkinnedMesh, AtRestTransformMapsMeshSpaceToBoneSpace) {
    Rig r;
    r.skeleton->setTranslation(5, 0, 0);
    r.skeleton->setOrientation(90, 0, 0, 1);  // bone -> mesh: p -> Rz(90) p + (5, 0, 0)
    r.mesh->addTransform(r.skeleton, 1, 0, 1);
    Transform t;
    r.mesh->getBoneTransform(r.skeleton, &t);
    float p[4] = {5, 1, 0, 1};  // mesh point = bone point (1, 0, 0)
    t.transform(p);
    EXPECT_NEAR(p[0], 1.0f, 1e-5f);
    EXPECT_NEAR(p[1], 0.0f, 1e-5f);
    EXPECT_NEAR(p[2], 0.0f, 1e-5f);
    EXPECT_NEAR(p[3], 1.0f, 1e-6f);
}

TEST(SkinnedMesh, GetBoneTransformErrorsAndUnusedBone) {
    Rig r;
    Transform t;
    Ref<Group> stranger = new Group();
    EXPECT_THROW(r.mesh->getBoneTransform(nullptr, &t), NullPointerException);
    EXPECT_THROW(r.mesh->getBoneTransform(r.lower, nullptr), NullPointerException);
    EXPECT_THROW(r.mesh->getBoneTransform(stranger, &t), IllegalArgumentException);
    EXPECT_THROW(r.mesh->getBoneTransform(r.mesh, &t), IllegalArgumentException);
    // In the skeleton but never added: the transform is left as it was.
    t.postTranslate(7, 8, 9);
    const Transform before = t;
    r.mesh->getBoneTransform(r.other, &t);
    EXPECT_EQ(t, before);
}

TEST(SkinnedMesh, BoneVerticesWithNormalisedWeights) {
    Rig r;
    r.mesh->addTransform(r.upper, 1, 0, 4);  // vertices 0..3
    r.mesh->addTransform(r.lower, 3, 2, 4);  // vertices 2..5
    // Vertices 2 and 3: upper 1/(1+3) = 0.25, lower 3/4 = 0.75.
    EXPECT_EQ(r.mesh->getBoneVertices(r.upper), 4);
    Ints idx(4);
    Floats w(4);
    ASSERT_EQ(r.mesh->getBoneVertices(r.upper, idx, w), 4);
    EXPECT_EQ(idx, (Ints{0, 1, 2, 3}));
    EXPECT_FLOAT_EQ(w[0], 1.0f);
    EXPECT_FLOAT_EQ(w[1], 1.0f);
    EXPECT_FLOAT_EQ(w[2], 0.25f);
    EXPECT_FLOAT_EQ(w[3], 0.25f);
    ASSERT_EQ(r.mesh->getBoneVertices(r.lower, idx, w), 4);
    EXPECT_EQ(idx, (Ints{2, 3, 4, 5}));
    EXPECT_FLOAT_EQ(w[0], 0.75f);
    EXPECT_FLOAT_EQ(w[1], 0.75f);
    EXPECT_FLOAT_EQ(w[2], 1.0f);
    EXPECT_FLOAT_EQ(w[3], 1.0f);
    // The same bone added twice accumulates: vertex 0 gets upper 1 + 2 = 3.
    r.mesh->addTransform(r.upper, 2, 0, 1);
    r.mesh->addTransform(r.lower, 1, 0, 1);  // vertex 0: upper 3/4, lower 1/4
    idx.resize(5);
    w.resize(5);
    ASSERT_EQ(r.mesh->getBoneVertices(r.lower, idx, w), 5);
    EXPECT_EQ(idx[0], 0);
    EXPECT_FLOAT_EQ(w[0], 0.25f);
    ASSERT_EQ(r.mesh->getBoneVertices(r.upper, idx, w), 4);
    EXPECT_FLOAT_EQ(w[0], 0.75f);
}

TEST(SkinnedMesh, BoneVerticesErrors) {
    Rig r;
    r.mesh->addTransform(r.upper, 1, 0, 3);
    Ints shortIdx(2), idx(3);
    Floats shortW(2), w(3);
    Ref<Group> stranger = new Group();
    EXPECT_THROW(r.mesh->getBoneVertices(nullptr), NullPointerException);
    EXPECT_THROW(r.mesh->getBoneVertices(stranger), IllegalArgumentException);
    EXPECT_THROW(r.mesh->getBoneVertices(r.upper, shortIdx, w), IllegalArgumentException);
    EXPECT_THROW(r.mesh->getBoneVertices(r.upper, idx, shortW), IllegalArgumentException);
    EXPECT_EQ(r.mesh->getBoneVertices(r.other, idx, w), 0);  // in the skeleton, never added
    EXPECT_EQ(r.mesh->getBoneVertices(r.upper, idx, {}), 3);  // only indices wanted
    EXPECT_EQ(idx, (Ints{0, 1, 2}));
}

TEST(SkinnedMesh, TransformsPerVertexFromLimitsAtConstruction) {
    LimitsGuard guard;
    Limits l = getLimits();
    l.maxTransformsPerVertex = 2;
    setLimits(l);
    Rig r;
    l.maxTransformsPerVertex = 4;
    setLimits(l);
    EXPECT_EQ(r.mesh->influenceTable().maxInfluences(), 2);
    r.mesh->addTransform(r.upper, 1, 0, 1);
    r.mesh->addTransform(r.lower, 2, 0, 1);
    r.mesh->addTransform(r.other, 3, 0, 1);  // upper (1) drops out of vertex 0
    EXPECT_EQ(r.mesh->getBoneVertices(r.upper), 0);
    Ints idx(1);
    Floats w(1);
    ASSERT_EQ(r.mesh->getBoneVertices(r.other, idx, w), 1);
    EXPECT_FLOAT_EQ(w[0], 0.6f);  // 3 / (3 + 2)
}

TEST(SkinnedMesh, RemoveChildRefusesToCutABone) {
    Rig r;
    r.mesh->addTransform(r.lower, 1, 0, 1);
    EXPECT_THROW(r.upper->removeChild(r.lower), IllegalArgumentException);
    EXPECT_THROW(r.skeleton->removeChild(r.upper), IllegalArgumentException);  // contains the bone
    EXPECT_EQ(r.lower->getParent(), r.upper);
    EXPECT_EQ(r.upper->getParent(), r.skeleton);
    r.skeleton->removeChild(r.other);  // not a bone
    EXPECT_EQ(r.other->getParent(), nullptr);
    // Removing the whole mesh (bones and owner together) is fine.
    Ref<Group> root = new Group();
    root->addChild(r.mesh);
    root->removeChild(r.mesh);
    EXPECT_EQ(r.mesh->getParent(), nullptr);
    // Once the mesh is gone the bone is an ordinary node again.
    r.mesh = nullptr;
    EXPECT_EQ(r.lower->boneUseCount(), 0);
    EXPECT_EQ(r.skeleton->getParent(), nullptr);
    r.upper->removeChild(r.lower);
    EXPECT_EQ(r.lower->getParent(), nullptr);
}

TEST(SkinnedMesh, DuplicateCopiesSkeletonAndRemapsBones) {
    Rig r;
    r.skeleton->setTranslation(1, 2, 3);
    r.mesh->addTransform(r.upper, 1, 0, 4);
    r.mesh->addTransform(r.lower, 3, 2, 4);
    r.mesh->setUserID(9);
    Ref<SkinnedMesh> d = dynamicCast<SkinnedMesh>(r.mesh->duplicate());
    ASSERT_TRUE(d);
    EXPECT_EQ(d->getUserID(), 9);
    EXPECT_EQ(d->getParent(), nullptr);
    // Components shared.
    EXPECT_EQ(d->getVertexBuffer().get(), r.vb.get());
    EXPECT_EQ(d->getIndexBuffer(0).get(), r.ib.get());
    // Skeleton copied, parented to the copy.
    Ref<Group> sk = d->getSkeleton();
    ASSERT_TRUE(sk);
    EXPECT_NE(sk.get(), r.skeleton.get());
    EXPECT_EQ(sk->getParent().get(), d.get());
    ASSERT_EQ(sk->getChildCount(), 2);
    Ref<Group> upper = dynamicCast<Group>(sk->getChild(0));
    ASSERT_TRUE(upper);
    Ref<Group> lower = dynamicCast<Group>(upper->getChild(0));
    ASSERT_TRUE(lower);
    EXPECT_NE(upper.get(), r.upper.get());
    EXPECT_NE(lower.get(), r.lower.get());
    // Bones remapped to the copies, owners registered.
    ASSERT_EQ(d->boneCount(), 2);
    EXPECT_EQ(d->bone(0), upper.get());
    EXPECT_EQ(d->bone(1), lower.get());
    EXPECT_EQ(d->boneIndex(lower), 1);
    EXPECT_EQ(d->boneIndex(r.lower), -1);
    EXPECT_EQ(lower->boneUseCount(), 1);
    EXPECT_EQ(lower->boneOwners()[0], d.get());
    EXPECT_EQ(r.lower->boneUseCount(), 1);
    EXPECT_EQ(r.lower->boneOwners()[0], r.mesh.get());
    // Bookkeeping copied.
    Transform t;
    d->getBoneTransform(upper, &t);
    expectRows(t, {1, 0, 0, -1, 0, 1, 0, -2, 0, 0, 1, -3, 0, 0, 0, 1});
    Ints idx(4);
    Floats w(4);
    ASSERT_EQ(d->getBoneVertices(lower, idx, w), 4);
    EXPECT_EQ(idx, (Ints{2, 3, 4, 5}));
    EXPECT_FLOAT_EQ(w[0], 0.75f);
    EXPECT_FLOAT_EQ(w[3], 1.0f);
    // The original bones are not in the copy's skeleton.
    EXPECT_THROW(d->getBoneVertices(r.lower), IllegalArgumentException);
    EXPECT_THROW(d->addTransform(r.lower, 1, 0, 1), IllegalArgumentException);
    // References: vb, ib, copied skeleton.
    std::vector<Ref<Object3D>> refs(3);
    ASSERT_EQ(d->getReferences(refs), 3);
    EXPECT_EQ(refs[2].get(), sk.get());
    // The copy's bones are protected by removeChild too.
    EXPECT_THROW(upper->removeChild(lower), IllegalArgumentException);
    // The copy outlives the original and vice versa.
    r.mesh = nullptr;
    EXPECT_EQ(r.lower->boneUseCount(), 0);
    EXPECT_EQ(d->getBoneVertices(upper), 4);
    d = nullptr;
    EXPECT_EQ(lower->boneUseCount(), 0);
    EXPECT_EQ(sk->getParent(), nullptr);
}

TEST(SkinnedMesh, DuplicateInsideAGroupKeepsTheSkin) {
    Rig r;
    r.mesh->addTransform(r.lower, 1, 0, 1);
    Ref<Group> root = new Group();
    root->addChild(r.mesh);
    Ref<Group> copy = dynamicCast<Group>(root->duplicate());
    ASSERT_TRUE(copy);
    Ref<SkinnedMesh> m = dynamicCast<SkinnedMesh>(copy->getChild(0));
    ASSERT_TRUE(m);
    EXPECT_EQ(m->getParent().get(), copy.get());
    Node* bone = m->bone(0);
    EXPECT_NE(bone, r.lower.get());
    EXPECT_TRUE(bone->isDescendantOf(m->getSkeleton()));
    EXPECT_EQ(bone->boneUseCount(), 1);
}
