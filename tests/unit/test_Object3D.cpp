// Object3D services (JSR-184 1.1, Object3D): user ID/object, find,
// getReferences and duplicate, on the node classes of the core.
#include <gtest/gtest.h>

#include <memory>

#include <m3g/World.h>

using namespace m3g;

TEST(Object3D, UserIdAndUserObject) {
    Ref<Group> g = make<Group>();
    EXPECT_EQ(g->getUserID(), 0);
    EXPECT_FALSE(g->getUserObject().has_value());
    g->setUserID(42);
    auto params = std::make_shared<const UserParameters>(UserParameters{{7, {1, 2, 3}}});
    g->setUserObject(params);
    EXPECT_EQ(g->getUserID(), 42);
    auto back = std::any_cast<std::shared_ptr<const UserParameters>>(g->getUserObject());
    EXPECT_EQ(back->at(7), (std::vector<std::uint8_t>{1, 2, 3}));
}

TEST(Object3D, GetUserParametersReadsEveryParameterHolder) {
    Ref<Group> g = make<Group>();
    EXPECT_EQ(g->getUserParameters(), nullptr);
    g->setUserObject(std::make_shared<const UserParameters>(UserParameters{{1, {9}}}));
    ASSERT_NE(g->getUserParameters(), nullptr);
    EXPECT_EQ(g->getUserParameters()->at(1), std::vector<std::uint8_t>{9});
    g->setUserObject(std::make_shared<UserParameters>(UserParameters{{2, {8}}}));
    EXPECT_EQ(g->getUserParameters()->at(2), std::vector<std::uint8_t>{8});
    g->setUserObject(UserParameters{{3, {7}}});
    EXPECT_EQ(g->getUserParameters()->at(3), std::vector<std::uint8_t>{7});
    g->setUserObject(std::string("not parameters"));
    EXPECT_EQ(g->getUserParameters(), nullptr);
}

TEST(Object3D, ObjectIdsAreUniqueAndRevisionsGrow) {
    Ref<Group> a = make<Group>(), b = make<Group>();
    EXPECT_NE(a->getObjectId(), b->getObjectId());
    const auto r0 = a->getRevision();
    a->setTranslation(1, 2, 3);
    EXPECT_GT(a->getRevision(), r0);
}

TEST(Object3D, FindSearchesThisThenReferencesDepthFirst) {
    Ref<World> w = make<World>();
    Ref<Group> a = make<Group>(), b = make<Group>(), deep = make<Group>();
    w->addChild(a);
    w->addChild(b);
    a->addChild(deep);
    w->setUserID(1);
    a->setUserID(2);
    b->setUserID(5);
    deep->setUserID(5);
    EXPECT_EQ(w->find(1), w);
    // Depth first in reference order: a's subtree (deep) comes before b.
    EXPECT_EQ(w->find(5), deep);
    EXPECT_EQ(w->find(99), nullptr);
    // find(0) finds objects with the default ID: this object first.
    Ref<Group> fresh = make<Group>();
    EXPECT_EQ(fresh->find(0), fresh);
    EXPECT_EQ(w->find(0), nullptr);
}

TEST(Object3D, AlignmentReferencesAreNotTraversed) {
    // Alignment references point up or across the graph: find() and
    // getReferences() only go down.
    Ref<Group> root = make<Group>(), a = make<Group>();
    root->addChild(a);
    root->setUserID(7);
    a->setAlignment(root, Node::ORIGIN, nullptr, Node::NONE);
    EXPECT_EQ(a->getReferences(), 0);
    EXPECT_EQ(a->find(7), nullptr);
    EXPECT_EQ(root->find(7), root);
}

TEST(Object3D, GetReferencesCountsAndFills) {
    Ref<World> w = make<World>();
    Ref<Group> a = make<Group>(), b = make<Group>();
    w->addChild(a);
    w->addChild(b);
    EXPECT_EQ(w->getReferences(), 2);
    std::vector<Ref<Object3D>> refs(3);
    EXPECT_EQ(w->getReferences(refs), 2);
    EXPECT_EQ(refs[0], a);
    EXPECT_EQ(refs[1], b);
    EXPECT_EQ(refs[2], nullptr);
    std::vector<Ref<Object3D>> shortArray(1);
    EXPECT_THROW(w->getReferences(shortArray), IllegalArgumentException);
}

TEST(Object3D, DuplicateCopiesSubtreeAndProperties) {
    Ref<Group> g = make<Group>();
    Ref<Group> child = make<Group>();
    g->addChild(child);
    g->setUserID(9);
    g->setTranslation(1, 2, 3);
    g->setAlphaFactor(0.5f);
    g->setScope(6);
    child->setUserID(10);
    Ref<Group> copy = dynamicCast<Group>(g->duplicate());
    ASSERT_TRUE(copy);
    EXPECT_NE(copy, g);
    EXPECT_EQ(copy->getUserID(), 9);
    EXPECT_EQ(copy->getAlphaFactor(), 0.5f);
    EXPECT_EQ(copy->getScope(), 6);
    float t[3];
    copy->getTranslation(t);
    EXPECT_EQ(t[1], 2);
    ASSERT_EQ(copy->getChildCount(), 1);
    EXPECT_NE(copy->getChild(0), child);  // children are copied, not shared
    EXPECT_EQ(copy->getChild(0)->getUserID(), 10);
    EXPECT_EQ(copy->getChild(0)->getParent(), copy);
    EXPECT_EQ(copy->getParent(), nullptr);
    EXPECT_EQ(child->getParent(), g);
}

TEST(Object3D, DuplicateOfChildIsARoot) {
    Ref<Group> root = make<Group>(), child = make<Group>();
    root->addChild(child);
    Ref<Object3D> copy = child->duplicate();
    EXPECT_EQ(static_cast<Node*>(copy.get())->getParent(), nullptr);
    EXPECT_EQ(root->getChildCount(), 1);
}

TEST(Object3D, DuplicateRemapsAlignmentInsideSubtreeOnly) {
    Ref<Group> outside = make<Group>(), root = make<Group>();
    Ref<Group> g = make<Group>(), a = make<Group>(), b = make<Group>();
    root->addChild(outside);
    root->addChild(g);
    g->addChild(a);
    g->addChild(b);
    a->setAlignment(b, Node::ORIGIN, outside, Node::Y_AXIS);
    Ref<Group> copy = dynamicCast<Group>(g->duplicate());
    Ref<Node> a2 = copy->getChild(0), b2 = copy->getChild(1);
    EXPECT_EQ(a2->getAlignmentReference(Node::Z_AXIS), b2);       // inside: remapped
    EXPECT_EQ(a2->getAlignmentReference(Node::Y_AXIS), outside);  // outside: kept
}

TEST(Object3D, DuplicateWorldRemapsActiveCamera) {
    // The camera class lives elsewhere; a World referencing no camera still
    // copies its children and keeps a null camera.
    Ref<World> w = make<World>();
    w->addChild(make<Group>());
    Ref<World> w2 = dynamicCast<World>(w->duplicate());
    ASSERT_TRUE(w2);
    EXPECT_EQ(w2->getChildCount(), 1);
    EXPECT_EQ(w2->getActiveCamera(), nullptr);
}

TEST(Object3D, DroppingSharedGraphsFreesEverything) {
    WeakRef<Group> wa, wb;
    {
        Ref<Group> a = make<Group>(), b = make<Group>();
        wa = a.get();
        wb = b.get();
        a->addChild(b);
        Ref<Object3D> dup = a->duplicate();
        a->setAlignment(nullptr, Node::NONE, nullptr, Node::NONE);
        b->setAlignment(a, Node::ORIGIN, nullptr, Node::NONE);  // child aligned to parent: weak, no cycle
    }
    EXPECT_TRUE(wa.expired());
    EXPECT_TRUE(wb.expired());
}
