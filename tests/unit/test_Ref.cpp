// Ref / WeakRef ownership rules (api/m3g/Ref.h).
#include <gtest/gtest.h>

#include <m3g/Group.h>

using namespace m3g;

TEST(Ref, NewObjectIsOwnedByFirstRef) {
    Group* raw = new Group();
    EXPECT_EQ(raw->getRefCount(), 0);
    {
        Ref<Group> a = raw;
        EXPECT_EQ(raw->getRefCount(), 1);
        Ref<Group> b = a;
        EXPECT_EQ(raw->getRefCount(), 2);
        Ref<Node> asNode = b;
        EXPECT_EQ(raw->getRefCount(), 3);
        EXPECT_EQ(asNode.get(), static_cast<Node*>(raw));
    }
}

TEST(Ref, SelfAssignmentKeepsObject) {
    Ref<Group> a = make<Group>();
    Ref<Group>& alias = a;
    a = alias;
    EXPECT_EQ(a->getRefCount(), 1);
}

TEST(Ref, AssigningChildReachableOnlyThroughOldValueIsSafe) {
    // `r = r->getChild(0)` must take the child before the parent is released.
    Ref<Group> parent = make<Group>();
    parent->addChild(make<Group>());
    Ref<Node> r = parent;
    parent = nullptr;
    r = static_cast<Group*>(r.get())->getChild(0);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->getParent(), nullptr);  // the old parent died and detached it
    EXPECT_EQ(r->getRefCount(), 1);
}

TEST(WeakRef, BecomesNullWhenObjectDies) {
    WeakRef<Group> w;
    EXPECT_EQ(w.get(), nullptr);
    EXPECT_FALSE(w.expired());
    {
        Ref<Group> g = make<Group>();
        w = g.get();
        EXPECT_EQ(w.get(), g.get());
    }
    EXPECT_EQ(w.get(), nullptr);
    EXPECT_TRUE(w.expired());
}
