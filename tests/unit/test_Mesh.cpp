// Mesh (JSR-184 1.1, Mesh). Appearance objects are not constructed here (their
// implementation lives elsewhere); null appearances exercise the same paths.
#include <gtest/gtest.h>

#include <vector>

#include <m3g/Group.h>
#include <m3g/Mesh.h>
#include <m3g/TriangleStripArray.h>

using namespace m3g;

namespace {
Ref<VertexBuffer> makeVB() {
    Ref<VertexBuffer> vb = new VertexBuffer();
    vb->setPositions(new VertexArray(4, 3, 2), 1.0f, {});
    return vb;
}
Ref<IndexBuffer> makeIB() {
    const int lengths[] = {4};
    return new TriangleStripArray(0, lengths);
}
}  // namespace

TEST(Mesh, SingleSubmesh) {
    Ref<VertexBuffer> vb = makeVB();
    Ref<IndexBuffer> ib = makeIB();
    Ref<Mesh> m = new Mesh(vb, ib, nullptr);
    EXPECT_EQ(m->getVertexBuffer(), vb);
    EXPECT_EQ(m->getSubmeshCount(), 1);
    EXPECT_EQ(m->getIndexBuffer(0), ib);
    EXPECT_EQ(m->getAppearance(0), nullptr);
    EXPECT_STREQ(m->getClassName(), "Mesh");
    // Node defaults.
    EXPECT_EQ(m->getParent(), nullptr);
    EXPECT_TRUE(m->isRenderingEnabled());
    EXPECT_TRUE(m->isPickingEnabled());
    EXPECT_EQ(m->getAlphaFactor(), 1.0f);
    EXPECT_EQ(m->getScope(), -1);
}

TEST(Mesh, SingleSubmeshNulls) {
    EXPECT_THROW(Mesh(nullptr, makeIB(), nullptr), NullPointerException);
    EXPECT_THROW(Mesh(makeVB(), static_cast<IndexBuffer*>(nullptr), nullptr), NullPointerException);
}

TEST(Mesh, SubmeshArrays) {
    Ref<VertexBuffer> vb = makeVB();
    std::vector<Ref<IndexBuffer>> ibs{makeIB(), makeIB(), makeIB()};
    Ref<Mesh> m = new Mesh(vb, ibs, {});  // null appearances: none for any submesh
    ASSERT_EQ(m->getSubmeshCount(), 3);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(m->getIndexBuffer(i), ibs[static_cast<std::size_t>(i)]);
        EXPECT_EQ(m->getAppearance(i), nullptr);
    }
    // Appearances longer than the submeshes: extra entries ignored.
    std::vector<Ref<Appearance>> apps(5);
    Ref<Mesh> m2 = new Mesh(vb, ibs, apps);
    EXPECT_EQ(m2->getSubmeshCount(), 3);
}

TEST(Mesh, SubmeshArrayErrors) {
    Ref<VertexBuffer> vb = makeVB();
    std::vector<Ref<IndexBuffer>> ibs{makeIB(), makeIB()};
    std::vector<Ref<IndexBuffer>> withNull{makeIB(), nullptr};
    std::vector<Ref<Appearance>> oneApp(1);
    using IBs = std::span<const Ref<IndexBuffer>>;
    EXPECT_THROW(Mesh(nullptr, ibs, {}), NullPointerException);
    EXPECT_THROW(Mesh(vb, IBs(), {}), NullPointerException);
    EXPECT_THROW(Mesh(vb, withNull, {}), NullPointerException);
    EXPECT_THROW(Mesh(vb, IBs(ibs.data(), 0), {}), IllegalArgumentException);
    EXPECT_THROW(Mesh(vb, ibs, oneApp), IllegalArgumentException);
}

TEST(Mesh, IndexChecks) {
    std::vector<Ref<IndexBuffer>> ibs{makeIB(), makeIB()};
    Ref<Mesh> m = new Mesh(makeVB(), ibs, {});
    EXPECT_THROW(m->getIndexBuffer(-1), IndexOutOfBoundsException);
    EXPECT_THROW(m->getIndexBuffer(2), IndexOutOfBoundsException);
    EXPECT_THROW(m->getAppearance(-1), IndexOutOfBoundsException);
    EXPECT_THROW(m->getAppearance(2), IndexOutOfBoundsException);
    EXPECT_THROW(m->setAppearance(-1, nullptr), IndexOutOfBoundsException);
    EXPECT_THROW(m->setAppearance(2, nullptr), IndexOutOfBoundsException);
}

TEST(Mesh, SetAppearanceTouches) {
    Ref<Mesh> m = new Mesh(makeVB(), makeIB(), nullptr);
    const auto r = m->getRevision();
    m->setAppearance(0, nullptr);
    EXPECT_GT(m->getRevision(), r);
    EXPECT_EQ(m->getAppearance(0), nullptr);
}

TEST(Mesh, ReferencesVertexBufferThenIndexBuffers) {
    Ref<VertexBuffer> vb = makeVB();
    std::vector<Ref<IndexBuffer>> ibs{makeIB(), makeIB()};
    Ref<Mesh> m = new Mesh(vb, ibs, {});
    std::vector<Ref<Object3D>> refs(3);
    ASSERT_EQ(m->getReferences(refs), 3);  // null appearances omitted
    EXPECT_EQ(refs[0].get(), vb.get());
    EXPECT_EQ(refs[1].get(), ibs[0].get());
    EXPECT_EQ(refs[2].get(), ibs[1].get());
}

TEST(Mesh, DuplicateSharesComponents) {
    Ref<VertexBuffer> vb = makeVB();
    std::vector<Ref<IndexBuffer>> ibs{makeIB(), makeIB()};
    Ref<Group> parent = new Group();
    Ref<Mesh> m = new Mesh(vb, ibs, {});
    parent->addChild(m);
    m->setUserID(5);
    m->setScope(3);
    m->setTranslation(1, 2, 3);
    Ref<Mesh> d = dynamicCast<Mesh>(m->duplicate());
    ASSERT_TRUE(d);
    EXPECT_NE(d.get(), m.get());
    EXPECT_STREQ(d->getClassName(), "Mesh");
    EXPECT_EQ(d->getParent(), nullptr);
    EXPECT_EQ(d->getUserID(), 5);
    EXPECT_EQ(d->getScope(), 3);
    float t[3];
    d->getTranslation(t);
    EXPECT_EQ(t[2], 3.0f);
    EXPECT_EQ(d->getVertexBuffer().get(), vb.get());
    ASSERT_EQ(d->getSubmeshCount(), 2);
    EXPECT_EQ(d->getIndexBuffer(0).get(), ibs[0].get());
    EXPECT_EQ(d->getIndexBuffer(1).get(), ibs[1].get());
    EXPECT_EQ(d->getAppearance(1), nullptr);
}

TEST(Mesh, EngineAccessors) {
    Ref<VertexBuffer> vb = makeVB();
    Ref<IndexBuffer> ib = makeIB();
    Ref<Mesh> m = new Mesh(vb, ib, nullptr);
    EXPECT_EQ(m->vertexBuffer(), vb.get());
    EXPECT_EQ(m->indexBuffer(0), ib.get());
    EXPECT_EQ(m->appearance(0), nullptr);
}
