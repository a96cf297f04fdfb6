// AnimationTrack (JSR-184 1.1, AnimationTrack): construction checks, component counts,
// controller, references, duplication.
#include <gtest/gtest.h>

#include <m3g/AnimationController.h>
#include <m3g/AnimationTrack.h>
#include <m3g/KeyframeSequence.h>

using namespace m3g;

namespace {
Ref<KeyframeSequence> seq(int components) {
    return make<KeyframeSequence>(2, components, KeyframeSequence::LINEAR);
}
bool accepts(int components, int property) {
    try {
        AnimationTrack t(seq(components), property);
        return true;
    } catch (const IllegalArgumentException&) {
        return false;
    }
}
}  // namespace

TEST(AnimationTrack, Constants) {
    EXPECT_EQ(AnimationTrack::ALPHA, 256);
    EXPECT_EQ(AnimationTrack::COLOR, 258);
    EXPECT_EQ(AnimationTrack::FIELD_OF_VIEW, 264);
    EXPECT_EQ(AnimationTrack::SPOT_EXPONENT, 274);
    EXPECT_EQ(AnimationTrack::VISIBILITY, 276);
}

TEST(AnimationTrack, ConstructorChecks) {
    EXPECT_THROW(AnimationTrack(nullptr, AnimationTrack::ALPHA), NullPointerException);
    EXPECT_THROW(AnimationTrack(seq(1), 255), IllegalArgumentException);
    EXPECT_THROW(AnimationTrack(seq(1), 277), IllegalArgumentException);
}

TEST(AnimationTrack, ComponentCountRules) {
    for (int p : {AnimationTrack::ALPHA, AnimationTrack::DENSITY, AnimationTrack::FAR_DISTANCE,
                  AnimationTrack::FIELD_OF_VIEW, AnimationTrack::INTENSITY, AnimationTrack::NEAR_DISTANCE,
                  AnimationTrack::PICKABILITY, AnimationTrack::SHININESS, AnimationTrack::SPOT_ANGLE,
                  AnimationTrack::SPOT_EXPONENT, AnimationTrack::VISIBILITY}) {
        EXPECT_TRUE(accepts(1, p)) << p;
        EXPECT_FALSE(accepts(2, p)) << p;
        EXPECT_FALSE(accepts(3, p)) << p;
    }
    EXPECT_FALSE(accepts(1, AnimationTrack::CROP));
    EXPECT_TRUE(accepts(2, AnimationTrack::CROP));
    EXPECT_FALSE(accepts(3, AnimationTrack::CROP));
    EXPECT_TRUE(accepts(4, AnimationTrack::CROP));
    for (int p : {AnimationTrack::COLOR, AnimationTrack::AMBIENT_COLOR, AnimationTrack::DIFFUSE_COLOR,
                  AnimationTrack::EMISSIVE_COLOR, AnimationTrack::SPECULAR_COLOR, AnimationTrack::TRANSLATION}) {
        EXPECT_TRUE(accepts(3, p)) << p;
        EXPECT_FALSE(accepts(1, p)) << p;
        EXPECT_FALSE(accepts(4, p)) << p;
    }
    EXPECT_TRUE(accepts(4, AnimationTrack::ORIENTATION));
    EXPECT_FALSE(accepts(3, AnimationTrack::ORIENTATION));
    EXPECT_TRUE(accepts(1, AnimationTrack::SCALE));
    EXPECT_FALSE(accepts(2, AnimationTrack::SCALE));
    EXPECT_TRUE(accepts(3, AnimationTrack::SCALE));
    EXPECT_FALSE(accepts(4, AnimationTrack::SCALE));
    EXPECT_TRUE(accepts(1, AnimationTrack::MORPH_WEIGHTS));
    EXPECT_TRUE(accepts(7, AnimationTrack::MORPH_WEIGHTS));
}

TEST(AnimationTrack, GettersAndController) {
    Ref<KeyframeSequence> s = seq(3);
    Ref<AnimationTrack> t = make<AnimationTrack>(s, AnimationTrack::TRANSLATION);
    EXPECT_EQ(t->getKeyframeSequence(), s);
    EXPECT_EQ(t->getTargetProperty(), AnimationTrack::TRANSLATION);
    EXPECT_FALSE(t->getController());
    Ref<AnimationController> c = make<AnimationController>();
    auto r = t->getRevision();
    t->setController(c);
    EXPECT_GT(t->getRevision(), r);
    EXPECT_EQ(t->getController(), c);
    t->setController(nullptr);
    EXPECT_FALSE(t->getController());
    EXPECT_STREQ(t->getClassName(), "AnimationTrack");
}

TEST(AnimationTrack, ReferencesAreSequenceThenController) {
    Ref<KeyframeSequence> s = seq(1);
    Ref<AnimationTrack> t = make<AnimationTrack>(s, AnimationTrack::ALPHA);
    EXPECT_EQ(t->getReferences(), 1);
    Ref<AnimationController> c = make<AnimationController>();
    t->setController(c);
    Ref<Object3D> refs[2];
    EXPECT_EQ(t->getReferences(refs), 2);
    EXPECT_EQ(refs[0].get(), static_cast<Object3D*>(s.get()));
    EXPECT_EQ(refs[1].get(), static_cast<Object3D*>(c.get()));
}

TEST(AnimationTrack, DuplicateSharesSequenceAndController) {
    Ref<KeyframeSequence> s = seq(1);
    Ref<AnimationTrack> t = make<AnimationTrack>(s, AnimationTrack::ALPHA);
    Ref<AnimationController> c = make<AnimationController>();
    t->setController(c);
    Ref<AnimationTrack> d = dynamicCast<AnimationTrack>(t->duplicate());
    ASSERT_TRUE(d);
    EXPECT_NE(d.get(), t.get());
    EXPECT_EQ(d->getKeyframeSequence(), s);
    EXPECT_EQ(d->getController(), c);
    EXPECT_EQ(d->getTargetProperty(), AnimationTrack::ALPHA);
}
