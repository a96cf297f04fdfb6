// MorphingMesh (JSR-184 1.1, MorphingMesh).
#include <gtest/gtest.h>

#include <vector>

#include <m3g/AnimationTrack.h>
#include <m3g/MorphingMesh.h>
#include <m3g/TriangleStripArray.h>

using namespace m3g;

namespace {
Ref<VertexBuffer> makeVB() {
    Ref<VertexBuffer> vb = new VertexBuffer();
    vb->setPositions(new VertexArray(3, 3, 2), 1.0f, {});
    return vb;
}
Ref<IndexBuffer> makeIB() {
    const int lengths[] = {3};
    return new TriangleStripArray(0, lengths);
}
using VBs = std::vector<Ref<VertexBuffer>>;
using Floats = std::vector<float>;
}  // namespace

TEST(MorphingMesh, ConstructionAndDefaults) {
    Ref<VertexBuffer> base = makeVB();
    VBs targets{makeVB(), makeVB(), makeVB()};
    Ref<IndexBuffer> ib = makeIB();
    Ref<MorphingMesh> m = new MorphingMesh(base, targets, ib, nullptr);
    EXPECT_STREQ(m->getClassName(), "MorphingMesh");
    EXPECT_EQ(m->getVertexBuffer(), base);
    EXPECT_EQ(m->getIndexBuffer(0), ib);
    ASSERT_EQ(m->getMorphTargetCount(), 3);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(m->getMorphTarget(i), targets[static_cast<std::size_t>(i)]);
    Floats w(3, 9.0f);
    m->getWeights(w);
    EXPECT_EQ(w, (Floats{0, 0, 0}));
}

TEST(MorphingMesh, SubmeshArrayConstructor) {
    VBs targets{makeVB()};
    std::vector<Ref<IndexBuffer>> ibs{makeIB(), makeIB()};
    Ref<MorphingMesh> m = new MorphingMesh(makeVB(), targets, ibs, {});
    EXPECT_EQ(m->getSubmeshCount(), 2);
    EXPECT_EQ(m->getMorphTargetCount(), 1);
}

TEST(MorphingMesh, ConstructorErrors) {
    Ref<VertexBuffer> base = makeVB();
    Ref<IndexBuffer> ib = makeIB();
    VBs targets{makeVB()};
    VBs withNull{makeVB(), nullptr};
    using Span = std::span<const Ref<VertexBuffer>>;
    EXPECT_THROW(MorphingMesh(nullptr, targets, ib, nullptr), NullPointerException);
    EXPECT_THROW(MorphingMesh(base, targets, static_cast<IndexBuffer*>(nullptr), nullptr), NullPointerException);
    EXPECT_THROW(MorphingMesh(base, Span(), ib, nullptr), NullPointerException);
    EXPECT_THROW(MorphingMesh(base, withNull, ib, nullptr), NullPointerException);
    EXPECT_THROW(MorphingMesh(base, Span(targets.data(), 0), ib, nullptr), IllegalArgumentException);
    std::vector<Ref<IndexBuffer>> ibs{ib};
    EXPECT_THROW(MorphingMesh(base, Span(), ibs, {}), NullPointerException);
    EXPECT_THROW(MorphingMesh(base, targets, std::span<const Ref<IndexBuffer>>(ibs.data(), 0), {}),
                 IllegalArgumentException);
}

TEST(MorphingMesh, WeightsRoundTrip) {
    VBs targets{makeVB(), makeVB()};
    Ref<MorphingMesh> m = new MorphingMesh(makeVB(), targets, makeIB(), nullptr);
    const auto r = m->getRevision();
    m->setWeights(Floats{-0.5f, 2.5f, 7.0f});  // any real value; extra entry ignored
    EXPECT_GT(m->getRevision(), r);
    Floats w(3, 9.0f);
    m->getWeights(w);
    EXPECT_EQ(w, (Floats{-0.5f, 2.5f, 9.0f}));
    auto engine = m->weights();
    EXPECT_EQ(Floats(engine.begin(), engine.end()), (Floats{-0.5f, 2.5f}));
}

TEST(MorphingMesh, WeightAndTargetErrors) {
    VBs targets{makeVB(), makeVB()};
    Ref<MorphingMesh> m = new MorphingMesh(makeVB(), targets, makeIB(), nullptr);
    Floats one(1);
    EXPECT_THROW(m->setWeights(std::span<const float>()), NullPointerException);
    EXPECT_THROW(m->getWeights(std::span<float>()), NullPointerException);
    EXPECT_THROW(m->setWeights(one), IllegalArgumentException);
    EXPECT_THROW(m->getWeights(one), IllegalArgumentException);
    EXPECT_THROW(m->getMorphTarget(-1), IndexOutOfBoundsException);
    EXPECT_THROW(m->getMorphTarget(2), IndexOutOfBoundsException);
}

TEST(MorphingMesh, AnimatesMorphWeights) {
    VBs targets{makeVB(), makeVB(), makeVB()};
    Ref<MorphingMesh> m = new MorphingMesh(makeVB(), targets, makeIB(), nullptr);
    EXPECT_TRUE(m->isAnimatable(AnimationTrack::MORPH_WEIGHTS));
    EXPECT_TRUE(m->isAnimatable(AnimationTrack::ALPHA));        // Node
    EXPECT_TRUE(m->isAnimatable(AnimationTrack::TRANSLATION));  // Transformable
    EXPECT_FALSE(m->isAnimatable(AnimationTrack::COLOR));
    m->setWeights(Floats{1, 1, 1});
    const float fewer[] = {0.25f};  // remaining weights become 0
    m->updateProperty(AnimationTrack::MORPH_WEIGHTS, fewer);
    Floats w(3);
    m->getWeights(w);
    EXPECT_EQ(w, (Floats{0.25f, 0, 0}));
    const float more[] = {1, 2, 3, 4, 5};  // extra ignored
    m->updateProperty(AnimationTrack::MORPH_WEIGHTS, more);
    m->getWeights(w);
    EXPECT_EQ(w, (Floats{1, 2, 3}));
    const float alpha[] = {0.5f};
    m->updateProperty(AnimationTrack::ALPHA, alpha);  // falls through to Node
    EXPECT_EQ(m->getAlphaFactor(), 0.5f);
    // A plain Mesh does not take morph weights.
    Ref<Mesh> plain = new Mesh(makeVB(), makeIB(), nullptr);
    EXPECT_FALSE(plain->isAnimatable(AnimationTrack::MORPH_WEIGHTS));
}

TEST(MorphingMesh, ReferencesMeshThenTargets) {
    Ref<VertexBuffer> base = makeVB();
    Ref<IndexBuffer> ib = makeIB();
    VBs targets{makeVB(), makeVB()};
    Ref<MorphingMesh> m = new MorphingMesh(base, targets, ib, nullptr);
    std::vector<Ref<Object3D>> refs(4);
    ASSERT_EQ(m->getReferences(refs), 4);
    EXPECT_EQ(refs[0].get(), base.get());
    EXPECT_EQ(refs[1].get(), ib.get());
    EXPECT_EQ(refs[2].get(), targets[0].get());
    EXPECT_EQ(refs[3].get(), targets[1].get());
}

TEST(MorphingMesh, DuplicateSharesTargetsAndCopiesWeights) {
    Ref<VertexBuffer> base = makeVB();
    VBs targets{makeVB(), makeVB()};
    Ref<MorphingMesh> m = new MorphingMesh(base, targets, makeIB(), nullptr);
    m->setWeights(Floats{0.25f, 0.75f});
    Ref<MorphingMesh> d = dynamicCast<MorphingMesh>(m->duplicate());
    ASSERT_TRUE(d);
    EXPECT_NE(d.get(), m.get());
    EXPECT_EQ(d->getVertexBuffer().get(), base.get());
    ASSERT_EQ(d->getMorphTargetCount(), 2);
    EXPECT_EQ(d->getMorphTarget(0).get(), targets[0].get());
    EXPECT_EQ(d->getMorphTarget(1).get(), targets[1].get());
    Floats w(2);
    d->getWeights(w);
    EXPECT_EQ(w, (Floats{0.25f, 0.75f}));
    d->setWeights(Floats{1, 1});
    m->getWeights(w);
    EXPECT_EQ(w, (Floats{0.25f, 0.75f}));
}
