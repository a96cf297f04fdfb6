// Object3D animation services (spec digest §4.1, §5.14): the track list and
// animate() on Node, Group, Camera and Light.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <m3g/AnimationController.h>
#include <m3g/AnimationTrack.h>
#include <m3g/Camera.h>
#include <m3g/Group.h>
#include <m3g/KeyframeSequence.h>
#include <m3g/Light.h>

using namespace m3g;

namespace {

struct Key {
    int time;
    std::vector<float> value;
};

Ref<KeyframeSequence> makeSeq(int interp, int duration, const std::vector<Key>& keys,
                              int repeat = KeyframeSequence::CONSTANT) {
    const int comps = static_cast<int>(keys[0].value.size());
    Ref<KeyframeSequence> s = make<KeyframeSequence>(static_cast<int>(keys.size()), comps, interp);
    for (std::size_t i = 0; i < keys.size(); ++i) s->setKeyframe(static_cast<int>(i), keys[i].time, keys[i].value);
    s->setDuration(duration);
    s->setRepeatMode(repeat);
    return s;
}

// A track with a fresh default controller (position == world time).
Ref<AnimationTrack> track(KeyframeSequence* s, int property, float weight = 1.0f) {
    Ref<AnimationTrack> t = make<AnimationTrack>(s, property);
    Ref<AnimationController> c = make<AnimationController>();
    c->setWeight(weight);
    t->setController(c);
    return t;
}

// A constant-valued 1-key sequence.
Ref<KeyframeSequence> constant(std::vector<float> value) {
    return makeSeq(KeyframeSequence::LINEAR, 10, {{0, std::move(value)}});
}

std::array<float, 3> translation(const Node& n) {
    std::array<float, 3> t;
    n.getTranslation(t);
    return t;
}

}  // namespace

TEST(Object3DAnimation, AddAnimationTrackChecks) {
    Ref<Group> g = make<Group>();
    EXPECT_THROW(g->addAnimationTrack(nullptr), NullPointerException);
    // Not animatable in the class.
    Ref<AnimationTrack> intensity = make<AnimationTrack>(constant({1}), AnimationTrack::INTENSITY);
    EXPECT_THROW(g->addAnimationTrack(intensity), IllegalArgumentException);
    Ref<Light> l = make<Light>();
    Ref<AnimationTrack> fov = make<AnimationTrack>(constant({60}), AnimationTrack::FIELD_OF_VIEW);
    EXPECT_THROW(l->addAnimationTrack(fov), IllegalArgumentException);
    Ref<AnimationController> ctl = make<AnimationController>();
    EXPECT_THROW(ctl->addAnimationTrack(intensity), IllegalArgumentException);
    // Already attached.
    Ref<AnimationTrack> alpha = make<AnimationTrack>(constant({1}), AnimationTrack::ALPHA);
    g->addAnimationTrack(alpha);
    EXPECT_THROW(g->addAnimationTrack(alpha), IllegalArgumentException);
    // Same property, different component count (SCALE 1 vs 3).
    Ref<AnimationTrack> scale1 = make<AnimationTrack>(constant({2}), AnimationTrack::SCALE);
    Ref<AnimationTrack> scale3 = make<AnimationTrack>(constant({1, 2, 3}), AnimationTrack::SCALE);
    g->addAnimationTrack(scale1);
    EXPECT_THROW(g->addAnimationTrack(scale3), IllegalArgumentException);
    Ref<AnimationTrack> scale1b = make<AnimationTrack>(constant({4}), AnimationTrack::SCALE);
    EXPECT_NO_THROW(g->addAnimationTrack(scale1b));
    EXPECT_EQ(g->getAnimationTrackCount(), 3);
    // The same track may animate another object too.
    Ref<Group> other = make<Group>();
    EXPECT_NO_THROW(other->addAnimationTrack(alpha));
}

TEST(Object3DAnimation, TracksSortedByPropertyStable) {
    Ref<Group> g = make<Group>();
    Ref<AnimationTrack> trans = make<AnimationTrack>(constant({1, 2, 3}), AnimationTrack::TRANSLATION);
    Ref<AnimationTrack> alpha1 = make<AnimationTrack>(constant({1}), AnimationTrack::ALPHA);
    Ref<AnimationTrack> orient = make<AnimationTrack>(constant({0, 0, 0, 1}), AnimationTrack::ORIENTATION);
    Ref<AnimationTrack> alpha2 = make<AnimationTrack>(constant({0}), AnimationTrack::ALPHA);
    auto r = g->getRevision();
    g->addAnimationTrack(trans);
    EXPECT_GT(g->getRevision(), r);
    g->addAnimationTrack(alpha1);
    g->addAnimationTrack(orient);
    g->addAnimationTrack(alpha2);
    ASSERT_EQ(g->getAnimationTrackCount(), 4);
    EXPECT_EQ(g->getAnimationTrack(0), alpha1);
    EXPECT_EQ(g->getAnimationTrack(1), alpha2);
    EXPECT_EQ(g->getAnimationTrack(2), orient);
    EXPECT_EQ(g->getAnimationTrack(3), trans);
    EXPECT_THROW(g->getAnimationTrack(-1), IndexOutOfBoundsException);
    EXPECT_THROW(g->getAnimationTrack(4), IndexOutOfBoundsException);
    // getReferences lists the tracks first.
    Ref<Object3D> refs[4];
    EXPECT_EQ(g->getReferences(refs), 4);
    EXPECT_EQ(refs[0].get(), static_cast<Object3D*>(alpha1.get()));
    EXPECT_EQ(refs[3].get(), static_cast<Object3D*>(trans.get()));
}

TEST(Object3DAnimation, RemoveAnimationTrack) {
    Ref<Group> g = make<Group>();
    Ref<AnimationTrack> a = make<AnimationTrack>(constant({1}), AnimationTrack::ALPHA);
    Ref<AnimationTrack> b = make<AnimationTrack>(constant({1}), AnimationTrack::VISIBILITY);
    g->addAnimationTrack(a);
    g->addAnimationTrack(b);
    g->removeAnimationTrack(nullptr);  // ignored
    Ref<AnimationTrack> stranger = make<AnimationTrack>(constant({1}), AnimationTrack::ALPHA);
    g->removeAnimationTrack(stranger);  // ignored
    EXPECT_EQ(g->getAnimationTrackCount(), 2);
    auto r = g->getRevision();
    g->removeAnimationTrack(a);
    EXPECT_GT(g->getRevision(), r);
    ASSERT_EQ(g->getAnimationTrackCount(), 1);
    EXPECT_EQ(g->getAnimationTrack(0), b);
    g->addAnimationTrack(a);  // can be re-added
    EXPECT_EQ(g->getAnimationTrackCount(), 2);
}

TEST(Object3DAnimation, AnimateTranslationLinear) {
    Ref<Group> g = make<Group>();
    auto s = makeSeq(KeyframeSequence::LINEAR, 100, {{0, {0, 0, 0}}, {100, {10, 20, -30}}});
    g->addAnimationTrack(track(s, AnimationTrack::TRANSLATION));
    EXPECT_EQ(g->animate(25), 0);  // changes continuously
    auto t = translation(*g);
    EXPECT_FLOAT_EQ(t[0], 2.5f);
    EXPECT_FLOAT_EQ(t[1], 5);
    EXPECT_FLOAT_EQ(t[2], -7.5f);
    EXPECT_EQ(g->animate(200), 0x7FFFFFFF);  // past the last key: constant
    t = translation(*g);
    EXPECT_FLOAT_EQ(t[0], 10);
}

TEST(Object3DAnimation, ControllerMapsWorldTime) {
    Ref<Group> g = make<Group>();
    auto s = makeSeq(KeyframeSequence::LINEAR, 100, {{0, {0, 0, 0}}, {100, {100, 0, 0}}});
    Ref<AnimationTrack> t = track(s, AnimationTrack::TRANSLATION);
    t->getController()->setPosition(10, 1000);  // sequence 10 at world 1000
    t->getController()->setSpeed(2, 1000);
    g->addAnimationTrack(t);
    g->animate(1020);  // 10 + 2 * 20 = 50
    EXPECT_FLOAT_EQ(translation(*g)[0], 50);
}

TEST(Object3DAnimation, BlendsWeightedSumNotNormalised) {
    Ref<Group> g = make<Group>();
    g->addAnimationTrack(track(constant({1, 2, 3}), AnimationTrack::TRANSLATION, 2.0f));
    g->addAnimationTrack(track(constant({10, 0, 0}), AnimationTrack::TRANSLATION, 0.5f));
    g->animate(0);
    const auto t = translation(*g);
    EXPECT_FLOAT_EQ(t[0], 7);  // 2*1 + 0.5*10
    EXPECT_FLOAT_EQ(t[1], 4);
    EXPECT_FLOAT_EQ(t[2], 6);
}

TEST(Object3DAnimation, ZeroTotalWeightLeavesValueUnchanged) {
    Ref<Group> g = make<Group>();
    g->setTranslation(5, 5, 5);
    Ref<AnimationTrack> zero = track(constant({1, 2, 3}), AnimationTrack::TRANSLATION, 0.0f);
    Ref<AnimationTrack> noController = make<AnimationTrack>(constant({7, 7, 7}), AnimationTrack::TRANSLATION);
    Ref<AnimationTrack> inactive = track(constant({9, 9, 9}), AnimationTrack::TRANSLATION);
    inactive->getController()->setActiveInterval(100, 200);
    g->addAnimationTrack(zero);
    g->addAnimationTrack(noController);
    g->addAnimationTrack(inactive);
    const auto rev = g->getRevision();
    EXPECT_EQ(g->animate(50), 50);  // the inactive one starts at 100
    auto t = translation(*g);
    EXPECT_EQ(t[0], 5.0f);
    EXPECT_EQ(t[1], 5.0f);
    EXPECT_EQ(t[2], 5.0f);
    EXPECT_EQ(g->getRevision(), rev);
    // Inside the interval the third track applies.
    EXPECT_EQ(g->animate(150), 50);  // constant sample, but deactivates at 200
    t = translation(*g);
    EXPECT_EQ(t[0], 9.0f);
    // After the interval nothing changes any more.
    g->setTranslation(1, 1, 1);
    EXPECT_EQ(g->animate(250), 0x7FFFFFFF);
    EXPECT_EQ(translation(*g)[0], 1.0f);
}

TEST(Object3DAnimation, NothingAnimatedIsValidForever) {
    Ref<Group> g = make<Group>();
    g->addChild(make<Camera>());
    EXPECT_EQ(g->animate(0), 0x7FFFFFFF);
}

TEST(Object3DAnimation, AnimateReachesDescendants) {
    Ref<Group> root = make<Group>();
    Ref<Group> mid = make<Group>();
    Ref<Camera> cam = make<Camera>();
    Ref<Light> light = make<Light>();
    root->addChild(mid);
    mid->addChild(cam);
    root->addChild(light);
    cam->setPerspective(60, 1, 1, 100);

    auto fovSeq = makeSeq(KeyframeSequence::LINEAR, 100, {{0, {40}}, {100, {80}}});
    cam->addAnimationTrack(track(fovSeq, AnimationTrack::FIELD_OF_VIEW));
    auto farSeq = makeSeq(KeyframeSequence::STEP, 100, {{0, {50}}, {100, {500}}});
    cam->addAnimationTrack(track(farSeq, AnimationTrack::FAR_DISTANCE));
    auto intensitySeq = makeSeq(KeyframeSequence::LINEAR, 100, {{0, {0}}, {100, {2}}});
    light->addAnimationTrack(track(intensitySeq, AnimationTrack::INTENSITY));
    auto colorSeq = constant({0, 1, 0});
    light->addAnimationTrack(track(colorSeq, AnimationTrack::COLOR));
    auto alphaSeq = constant({0.5f});
    mid->addAnimationTrack(track(alphaSeq, AnimationTrack::ALPHA));

    EXPECT_EQ(root->animate(50), 0);
    float p[4];
    cam->getProjection(std::span<float>(p));
    EXPECT_FLOAT_EQ(p[0], 60);
    EXPECT_FLOAT_EQ(p[3], 50);
    EXPECT_FLOAT_EQ(light->getIntensity(), 1);
    EXPECT_EQ(light->getColor(), 0x00FF00);
    EXPECT_FLOAT_EQ(mid->getAlphaFactor(), 0.5f);

    // Animating a subtree leaves the rest alone.
    light->setIntensity(-1);
    mid->animate(75);
    EXPECT_FLOAT_EQ(light->getIntensity(), -1);
    cam->getProjection(std::span<float>(p));
    EXPECT_FLOAT_EQ(p[0], 70);
}

TEST(Object3DAnimation, PropertiesAreClampedOnApply) {
    Ref<Group> root = make<Group>();
    Ref<Light> light = make<Light>();
    Ref<Camera> cam = make<Camera>();
    root->addChild(light);
    root->addChild(cam);
    cam->setPerspective(60, 1, 1, 100);
    root->addAnimationTrack(track(constant({1.5f}), AnimationTrack::ALPHA));
    light->addAnimationTrack(track(constant({120}), AnimationTrack::SPOT_ANGLE));
    light->addAnimationTrack(track(constant({-3}), AnimationTrack::SPOT_EXPONENT));
    cam->addAnimationTrack(track(constant({100}), AnimationTrack::FIELD_OF_VIEW, 2.0f));  // 200
    root->animate(0);
    EXPECT_EQ(root->getAlphaFactor(), 1.0f);
    EXPECT_EQ(light->getSpotAngle(), 90.0f);
    EXPECT_EQ(light->getSpotExponent(), 0.0f);
    float p[4];
    cam->getProjection(std::span<float>(p));
    EXPECT_EQ(p[0], 180.0f);
}

TEST(Object3DAnimation, VisibilityAndPickabilityThreshold) {
    Ref<Group> g = make<Group>();
    g->addAnimationTrack(track(makeSeq(KeyframeSequence::LINEAR, 10, {{0, {0}}, {10, {1}}}),
                               AnimationTrack::VISIBILITY));
    g->addAnimationTrack(track(makeSeq(KeyframeSequence::LINEAR, 10, {{0, {1}}, {10, {0}}}),
                               AnimationTrack::PICKABILITY));
    g->animate(4);  // visibility 0.4, pickability 0.6
    EXPECT_FALSE(g->isRenderingEnabled());
    EXPECT_TRUE(g->isPickingEnabled());
    g->animate(6);  // 0.6, 0.4
    EXPECT_TRUE(g->isRenderingEnabled());
    EXPECT_FALSE(g->isPickingEnabled());
}

TEST(Object3DAnimation, OrientationSlerp) {
    Ref<Group> g = make<Group>();
    const float h = float(std::sqrt(0.5));
    auto s = makeSeq(KeyframeSequence::SLERP, 10, {{0, {0, 0, 0, 1}}, {10, {0, 0, h, h}}});
    g->addAnimationTrack(track(s, AnimationTrack::ORIENTATION));
    g->animate(5);
    float aa[4];
    g->getOrientation(aa);
    EXPECT_NEAR(aa[0], 45.0f, 1e-3f);
    EXPECT_NEAR(aa[1], 0.0f, 1e-5f);
    EXPECT_NEAR(aa[2], 0.0f, 1e-5f);
    EXPECT_NEAR(aa[3], 1.0f, 1e-5f);
}

TEST(Object3DAnimation, UniformScaleTrack) {
    Ref<Group> g = make<Group>();
    g->addAnimationTrack(track(constant({3}), AnimationTrack::SCALE));
    g->animate(0);
    float s[3];
    g->getScale(s);
    EXPECT_EQ(s[0], 3.0f);
    EXPECT_EQ(s[1], 3.0f);
    EXPECT_EQ(s[2], 3.0f);
}

TEST(Object3DAnimation, LoopingTrack) {
    Ref<Group> g = make<Group>();
    auto s = makeSeq(KeyframeSequence::LINEAR, 40, {{0, {0, 0, 0}}, {10, {10, 0, 0}}, {30, {50, 0, 0}}},
                     KeyframeSequence::LOOP);
    g->addAnimationTrack(track(s, AnimationTrack::TRANSLATION));
    g->animate(75);  // 35 in the loop: wrap segment 50 -> 0, u = 0.5
    EXPECT_FLOAT_EQ(translation(*g)[0], 25);
}

TEST(Object3DAnimation, ValidityIntervals) {
    // Before the first key (CONSTANT): valid until the first key time.
    {
        Ref<Group> g = make<Group>();
        g->addAnimationTrack(track(makeSeq(KeyframeSequence::LINEAR, 200, {{100, {0}}, {200, {1}}}),
                                   AnimationTrack::ALPHA));
        EXPECT_EQ(g->animate(40), 60);
    }
    // STEP: valid until the next key; at speed 2 half as long in world time.
    {
        Ref<Group> g = make<Group>();
        Ref<AnimationTrack> t =
            track(makeSeq(KeyframeSequence::STEP, 200, {{0, {0}}, {100, {1}}}), AnimationTrack::ALPHA);
        g->addAnimationTrack(t);
        EXPECT_EQ(g->animate(30), 70);
        t->getController()->setSpeed(2, 30);  // position 30 at world 30
        EXPECT_EQ(g->animate(30), 35);
        t->getController()->setSpeed(0, 30);  // frozen
        EXPECT_EQ(g->animate(30), 0x7FFFFFFF);
        t->getController()->setSpeed(-1, 50);  // STEP key 0 holds back to sequence time 0 (position 30 at 50)
        EXPECT_EQ(g->animate(50), 30);
    }
    // The smallest interval over all objects wins.
    {
        Ref<Group> root = make<Group>();
        Ref<Light> l = make<Light>();
        root->addChild(l);
        root->addAnimationTrack(track(makeSeq(KeyframeSequence::STEP, 200, {{0, {0}}, {100, {1}}}),
                                      AnimationTrack::ALPHA));
        l->addAnimationTrack(track(makeSeq(KeyframeSequence::STEP, 200, {{0, {0}}, {50, {1}}}),
                                   AnimationTrack::INTENSITY));
        EXPECT_EQ(root->animate(20), 30);
    }
}

TEST(Object3DAnimation, InvalidSequenceThrowsOnlyWhenSampled) {
    Ref<Group> g = make<Group>();
    Ref<KeyframeSequence> noDuration = make<KeyframeSequence>(2, 1, KeyframeSequence::LINEAR);
    Ref<AnimationTrack> t = make<AnimationTrack>(noDuration, AnimationTrack::ALPHA);
    g->addAnimationTrack(t);
    EXPECT_NO_THROW(g->animate(0));  // no controller: never sampled
    t->setController(make<AnimationController>());
    EXPECT_THROW(g->animate(0), IllegalStateException);
    noDuration->setDuration(10);
    EXPECT_NO_THROW(g->animate(0));
    const float v[1] = {0};
    noDuration->setKeyframe(1, 20, v);  // last key after the duration
    EXPECT_THROW(g->animate(0), IllegalStateException);
}

TEST(Object3DAnimation, InvalidSequenceInChildThrows) {
    Ref<Group> root = make<Group>();
    Ref<Camera> cam = make<Camera>();
    root->addChild(cam);
    Ref<KeyframeSequence> s = make<KeyframeSequence>(2, 1, KeyframeSequence::LINEAR);
    const float v[1] = {0};
    s->setKeyframe(0, 10, v);
    s->setKeyframe(1, 5, v);  // decreasing
    s->setDuration(20);
    cam->addAnimationTrack(track(s, AnimationTrack::NEAR_DISTANCE));
    EXPECT_THROW(root->animate(0), IllegalStateException);
}

TEST(Object3DAnimation, AlignmentReferenceIsNotFollowed) {
    // The child's alignment reference is its parent. animate() goes down the
    // graph only, so animating the child leaves the parent alone.
    Ref<Group> parent = make<Group>();
    Ref<Group> child = make<Group>();
    parent->addChild(child);
    child->setAlignment(parent, Node::ORIGIN, nullptr, Node::NONE);
    parent->addAnimationTrack(track(constant({1, 2, 3}), AnimationTrack::TRANSLATION));
    child->addAnimationTrack(track(constant({4, 5, 6}), AnimationTrack::TRANSLATION));
    child->animate(0);
    EXPECT_EQ(translation(*child)[0], 4.0f);
    EXPECT_EQ(translation(*parent)[0], 0.0f);
    parent->animate(0);  // and the parent reaches its child once
    EXPECT_EQ(translation(*parent)[0], 1.0f);
    EXPECT_EQ(translation(*child)[0], 4.0f);
}

TEST(Object3DAnimation, SharedSequenceAndControllerAcrossObjects) {
    Ref<Group> root = make<Group>();
    Ref<Group> a = make<Group>();
    Ref<Group> b = make<Group>();
    root->addChild(a);
    root->addChild(b);
    auto s = makeSeq(KeyframeSequence::LINEAR, 10, {{0, {0, 0, 0}}, {10, {10, 10, 10}}});
    Ref<AnimationTrack> t = track(s, AnimationTrack::TRANSLATION);
    a->addAnimationTrack(t);
    b->addAnimationTrack(t);
    root->animate(3);
    EXPECT_FLOAT_EQ(translation(*a)[0], 3);
    EXPECT_FLOAT_EQ(translation(*b)[0], 3);
}

TEST(Object3DAnimation, DuplicateSharesTracks) {
    Ref<Group> g = make<Group>();
    Ref<AnimationTrack> t = track(constant({1, 2, 3}), AnimationTrack::TRANSLATION);
    g->addAnimationTrack(t);
    Ref<Group> d = dynamicCast<Group>(g->duplicate());
    ASSERT_TRUE(d);
    ASSERT_EQ(d->getAnimationTrackCount(), 1);
    EXPECT_EQ(d->getAnimationTrack(0), t);
    d->animate(0);
    EXPECT_EQ(translation(*d)[1], 2.0f);
}
