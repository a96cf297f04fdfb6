// Objects made without `new` are never freed by their count
// (api/m3g/Ref.h, RefCounted): the trap of `Graphics g(320, 240);
// g3d.bindTarget(&g); g3d.releaseTarget();`, which freed a stack object,
// is closed, and objects made with `new` are still freed by their last Ref,
// nested `new` in constructor arguments and failed constructions included.
// Under AddressSanitizer (scripts/test's second stage) a wrong delete would
// be reported as a bad free, and a missed one as a leak.
#include <gtest/gtest.h>

#include <memory>
#include <span>
#include <vector>

#include <m3g/m3g.h>

using namespace m3g;

namespace {

std::vector<std::uint8_t> grey(int n) { return std::vector<std::uint8_t>(static_cast<std::size_t>(n), 128); }

}  // namespace

TEST(Ownership, StackGraphicsSurvivesBindAndRelease) {
    Graphics g(32, 24);
    EXPECT_FALSE(g.isHeapAllocated());
    Graphics3D* g3d = Graphics3D::getInstance();
    g3d->bindTarget(&g);
    g3d->releaseTarget();  // the Graphics3D's Ref to the target goes: count 1 -> 0
    EXPECT_EQ(g.getRefCount(), 0);
    EXPECT_EQ(g.getWidth(), 32) << "still alive and usable";
    g3d->bindTarget(&g);   // and can be bound again
    g3d->releaseTarget();
}

TEST(Ownership, StackAndMemberObjectsOutliveTheirLastRef) {
    Group stackGroup;
    WeakRef<Group> watch(&stackGroup);
    {
        Ref<Group> r(&stackGroup);
        Ref<Group> parent(new Group());
        parent->addChild(&stackGroup);
        parent->removeChild(&stackGroup);
    }
    EXPECT_EQ(stackGroup.getRefCount(), 0);
    EXPECT_EQ(watch.get(), &stackGroup) << "not deleted by its count";

    struct Holder {
        Material material;
        Image2D image{Image2D::RGB, 2, 2, std::span<const std::uint8_t>(grey(12))};
    };
    auto holder = std::make_unique<Holder>();  // a member of a heap object made by the global new
    EXPECT_FALSE(holder->material.isHeapAllocated());
    EXPECT_FALSE(holder->image.isHeapAllocated());
    { Ref<Material> r(&holder->material); }
    { Ref<Image2D> r(&holder->image); }
    EXPECT_EQ(holder->image.getWidth(), 2);
    holder.reset();  // the owner destroys them, once

    std::vector<Camera> cameras(3);  // elements of a container
    for (Camera& c : cameras) {
        Ref<Camera> r(&c);
    }
    EXPECT_EQ(cameras[2].getProjection(static_cast<Transform*>(nullptr)), Camera::GENERIC);
}

TEST(Ownership, HeapObjectsAreFreedByTheirLastRef) {
    WeakRef<Group> watch;
    {
        Ref<Group> g(new Group());
        EXPECT_TRUE(g->isHeapAllocated());
        watch = g.get();
        EXPECT_EQ(watch.get(), g.get());
    }
    EXPECT_TRUE(watch.expired());
    EXPECT_EQ(RefCounted::pendingAllocations(), 0u);
}

TEST(Ownership, NestedNewInConstructorArgumentsIsFreedToo) {
    // The Mesh's block is allocated before its arguments' objects are made,
    // so several blocks are pending at once; each must be claimed by its own
    // object (the innermost first).
    WeakRef<VertexBuffer> vb;
    WeakRef<TriangleStripArray> ib;
    WeakRef<Appearance> ap;
    WeakRef<Mesh> mesh;
    {
        const int strip[] = {3};
        Ref<Mesh> m(new Mesh(new VertexBuffer(), new TriangleStripArray(0, strip), new Appearance()));
        EXPECT_TRUE(m->isHeapAllocated());
        EXPECT_TRUE(m->getVertexBuffer()->isHeapAllocated());
        EXPECT_TRUE(m->getIndexBuffer(0)->isHeapAllocated());
        EXPECT_TRUE(m->getAppearance(0)->isHeapAllocated());
        vb = m->getVertexBuffer().get();
        ib = static_cast<TriangleStripArray*>(m->getIndexBuffer(0).get());
        ap = m->getAppearance(0).get();
        mesh = m.get();
        EXPECT_EQ(RefCounted::pendingAllocations(), 0u);
    }
    EXPECT_TRUE(mesh.expired());
    EXPECT_TRUE(vb.expired());
    EXPECT_TRUE(ib.expired());
    EXPECT_TRUE(ap.expired());
}

TEST(Ownership, FailedConstructionLeavesNothingPending) {
    EXPECT_THROW((void)new Image2D(Image2D::RGB, -1, 4), IllegalArgumentException);
    EXPECT_EQ(RefCounted::pendingAllocations(), 0u) << "operator delete took the block back";
    // A stack object made next is not taken for a heap one.
    Image2D after(Image2D::RGB, 4, 4);
    EXPECT_FALSE(after.isHeapAllocated());
}

TEST(Ownership, DuplicatesAreHeapObjects) {
    Group stackGroup;
    Ref<Object3D> copy = stackGroup.duplicate();
    EXPECT_TRUE(copy->isHeapAllocated());
    EXPECT_FALSE(stackGroup.isHeapAllocated());
}
