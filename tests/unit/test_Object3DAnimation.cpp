// Object3D animation services (JSR-184 1.1, Object3D.animate): the track list
// and animate() on Node, Group, Camera and Light.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <m3g/AnimationController.h>
#include <m3g/AnimationTrack.h>
#include <m3g/Camera.h>
#include <m3g/Group.h>
#include <m3g/KeyframeSequence.h>
#include <m3g/Light.h>
#include <m3g/m3g.h>

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

// ---- Audit: controller timing, blending, every animatable property ----

namespace {

/// LINEAR from `from` at 0 to `to` at 100 (CONSTANT): animate(50) gives the midpoint.
Ref<KeyframeSequence> ramp(std::vector<float> from, std::vector<float> to) {
    return makeSeq(KeyframeSequence::LINEAR, 100, {{0, std::move(from)}, {100, std::move(to)}});
}

void animateWith(Object3D& o, int property, Ref<KeyframeSequence> s) { o.addAnimationTrack(track(s, property)); }

}  // namespace

TEST(Object3DAnimation, ControllerActiveIntervalEdges) {
    // Interval [100, 200): active at 100 and 199, not at 200 or 99.
    Ref<Group> g = make<Group>();
    Ref<AnimationTrack> t = track(ramp({0, 0, 0}, {100, 0, 0}), AnimationTrack::TRANSLATION);
    t->getController()->setActiveInterval(100, 200);
    t->getController()->setPosition(0, 100);  // sequence 0 at world 100
    g->addAnimationTrack(t);
    g->setTranslation(-1, 0, 0);
    EXPECT_EQ(g->animate(99), 1);  // becomes active in 1 ms
    EXPECT_EQ(translation(*g)[0], -1.0f);
    g->animate(100);
    EXPECT_FLOAT_EQ(translation(*g)[0], 0.0f);
    g->animate(199);
    EXPECT_FLOAT_EQ(translation(*g)[0], 99.0f);
    g->setTranslation(-1, 0, 0);
    EXPECT_EQ(g->animate(200), 0x7FFFFFFF);  // never active again
    EXPECT_EQ(translation(*g)[0], -1.0f);
    // start == end: active at every time, even far before.
    t->getController()->setActiveInterval(50, 50);
    g->animate(-1000);
    EXPECT_FLOAT_EQ(translation(*g)[0], 0.0f);  // position -1100: before the first key
    g->animate(150);
    EXPECT_FLOAT_EQ(translation(*g)[0], 50.0f);
}

TEST(Object3DAnimation, ControllerSpeedAndPositionEdges) {
    Ref<Group> g = make<Group>();
    Ref<AnimationTrack> t = track(ramp({0, 0, 0}, {100, 0, 0}), AnimationTrack::TRANSLATION);
    g->addAnimationTrack(t);
    AnimationController& c = *t->getController();
    // Backwards: sequence 100 at world 0, speed -1: at 30 the position is 70.
    c.setPosition(100, 0);
    c.setSpeed(-1, 0);
    g->animate(30);
    EXPECT_FLOAT_EQ(translation(*g)[0], 70.0f);
    g->animate(-20);  // position 120: past the last key, clamped (CONSTANT)
    EXPECT_FLOAT_EQ(translation(*g)[0], 100.0f);
    // Speed changed at world 30 keeps the position continuous (70 there).
    c.setSpeed(0.5f, 30);
    g->animate(50);  // 70 + 0.5 * 20
    EXPECT_FLOAT_EQ(translation(*g)[0], 80.0f);
    // Speed 0: frozen.
    c.setSpeed(0, 50);
    g->animate(100000);
    EXPECT_FLOAT_EQ(translation(*g)[0], 80.0f);
    // Fractional positions interpolate (speed 0.25 from 10 at world 0).
    c.setPosition(10, 0);
    c.setSpeed(0.25f, 0);
    g->animate(3);  // 10.75
    EXPECT_FLOAT_EQ(translation(*g)[0], 10.75f);
}

TEST(Object3DAnimation, LoopWithNegativeSequenceTime) {
    // LOOP, duration 100, keys 0 -> 0 at 0 and 80 at 80, wrap 80 -> 0 over 20.
    Ref<Group> g = make<Group>();
    auto s = makeSeq(KeyframeSequence::LINEAR, 100, {{0, {0, 0, 0}}, {80, {80, 0, 0}}}, KeyframeSequence::LOOP);
    Ref<AnimationTrack> t = track(s, AnimationTrack::TRANSLATION);
    g->addAnimationTrack(t);
    t->getController()->setPosition(-10, 0);  // -10 -> 90: wrap segment, u = 0.5
    g->animate(0);
    EXPECT_FLOAT_EQ(translation(*g)[0], 40.0f);
    g->animate(-250);  // -260 -> 40
    EXPECT_FLOAT_EQ(translation(*g)[0], 40.0f);
    g->animate(315);  // 305 -> 5
    EXPECT_FLOAT_EQ(translation(*g)[0], 5.0f);
}

TEST(Object3DAnimation, TwoControllersBlendTheirOwnSamples) {
    // One sequence 0 -> 100 over 100 ms. Controller A: weight 0.25, position
    // = world time. Controller B: weight 0.75, sequence 80 at world 0, speed
    // 0.5. At world 40: A samples 40, B samples 100 (clamped at 100 from
    // position 100): 0.25 * 40 + 0.75 * 100 = 85.
    Ref<Group> g = make<Group>();
    Ref<KeyframeSequence> s = ramp({0, 0, 0}, {100, 0, 0});
    Ref<AnimationTrack> a = track(s, AnimationTrack::TRANSLATION, 0.25f);
    Ref<AnimationTrack> b = track(s, AnimationTrack::TRANSLATION, 0.75f);
    b->getController()->setPosition(80, 0);
    b->getController()->setSpeed(0.5f, 0);
    g->addAnimationTrack(a);
    g->addAnimationTrack(b);
    g->animate(40);
    EXPECT_FLOAT_EQ(translation(*g)[0], 85.0f);
    // At world 20: A 20, B 90: 5 + 67.5.
    g->animate(20);
    EXPECT_FLOAT_EQ(translation(*g)[0], 72.5f);
    // B outside its interval: A alone, not renormalised: 0.25 * 20.
    b->getController()->setActiveInterval(1000, 2000);
    g->animate(20);
    EXPECT_FLOAT_EQ(translation(*g)[0], 5.0f);
}

TEST(Object3DAnimation, BlendedOrientationsAreRenormalised) {
    // 0.5 * identity + 0.5 * (90 degrees about Z) = (0, 0, 0.3536, 0.8536),
    // renormalised: 45 degrees about Z.
    Ref<Group> g = make<Group>();
    const float h = float(std::sqrt(0.5));
    g->addAnimationTrack(
        track(makeSeq(KeyframeSequence::SLERP, 10, {{0, {0, 0, 0, 1}}}), AnimationTrack::ORIENTATION, 0.5f));
    g->addAnimationTrack(
        track(makeSeq(KeyframeSequence::SLERP, 10, {{0, {0, 0, h, h}}}), AnimationTrack::ORIENTATION, 0.5f));
    g->animate(0);
    float aa[4];
    g->getOrientation(aa);
    EXPECT_NEAR(aa[0], 45.0f, 1e-3f);
    EXPECT_NEAR(aa[3], 1.0f, 1e-5f);
}

TEST(Object3DAnimation, EveryAnimatablePropertyThroughAWorld) {
    // Every animatable property of JSR-184 1.1 (AnimationTrack's property
    // table) on its class, reached from a
    // World through children, the background, appearances and vertex
    // buffers; LINEAR ramps sampled halfway (animate(50)). Colors (0.2, 0.4,
    // 0.6) pack to 0x336699; alpha 0.4 to 0x66, 0.2 to 0x33.
    const std::vector<float> c0{0.0f, 0.2f, 0.4f}, c1{0.4f, 0.6f, 0.8f};
    Ref<World> w = make<World>();

    Ref<Group> g = make<Group>();
    w->addChild(g);
    animateWith(*g, AnimationTrack::ALPHA, ramp({0}, {0.5f}));
    animateWith(*g, AnimationTrack::PICKABILITY, ramp({0}, {0.8f}));  // 0.4
    animateWith(*g, AnimationTrack::VISIBILITY, ramp({0.4f}, {0.8f}));  // 0.6
    animateWith(*g, AnimationTrack::TRANSLATION, ramp({0, 0, 0}, {2, 4, 6}));
    animateWith(*g, AnimationTrack::SCALE, ramp({1, 1, 1}, {3, 5, 7}));
    animateWith(*g, AnimationTrack::ORIENTATION,
                makeSeq(KeyframeSequence::SLERP, 100, {{0, {0, 0, 0, 1}}, {100, {1, 0, 0, 0}}}));

    Ref<Camera> cam = make<Camera>();
    cam->setPerspective(60, 1, 1, 100);
    w->addChild(cam);
    animateWith(*cam, AnimationTrack::FIELD_OF_VIEW, ramp({40}, {60}));
    animateWith(*cam, AnimationTrack::NEAR_DISTANCE, ramp({1}, {3}));
    animateWith(*cam, AnimationTrack::FAR_DISTANCE, ramp({100}, {300}));

    Ref<Light> light = make<Light>();
    w->addChild(light);
    animateWith(*light, AnimationTrack::COLOR, ramp(c0, c1));
    animateWith(*light, AnimationTrack::INTENSITY, ramp({1}, {4}));
    animateWith(*light, AnimationTrack::SPOT_ANGLE, ramp({20}, {40}));
    animateWith(*light, AnimationTrack::SPOT_EXPONENT, ramp({4}, {20}));

    Ref<Material> mat = make<Material>();
    for (int p : {AnimationTrack::AMBIENT_COLOR, AnimationTrack::DIFFUSE_COLOR, AnimationTrack::EMISSIVE_COLOR,
                  AnimationTrack::SPECULAR_COLOR})
        animateWith(*mat, p, ramp(c0, c1));
    animateWith(*mat, AnimationTrack::ALPHA, ramp({0}, {0.8f}));
    animateWith(*mat, AnimationTrack::SHININESS, ramp({0}, {128}));
    Ref<Fog> fog = make<Fog>();
    animateWith(*fog, AnimationTrack::COLOR, ramp(c0, c1));
    animateWith(*fog, AnimationTrack::DENSITY, ramp({0}, {1}));
    animateWith(*fog, AnimationTrack::NEAR_DISTANCE, ramp({0}, {6}));
    animateWith(*fog, AnimationTrack::FAR_DISTANCE, ramp({20}, {40}));
    Ref<Texture2D> tex = make<Texture2D>(make<Image2D>(Image2D::RGB, 4, 4));
    animateWith(*tex, AnimationTrack::COLOR, ramp(c0, c1));
    animateWith(*tex, AnimationTrack::TRANSLATION, ramp({0, 0, 0}, {2, 0, 0}));
    Ref<Appearance> app = make<Appearance>();
    app->setMaterial(mat);
    app->setFog(fog);
    app->setTexture(0, tex);
    Ref<VertexBuffer> vb = make<VertexBuffer>();
    vb->setPositions(make<VertexArray>(3, 3, 2), 1.0f, {});
    animateWith(*vb, AnimationTrack::COLOR, ramp(c0, c1));
    animateWith(*vb, AnimationTrack::ALPHA, ramp({0}, {0.8f}));
    const int lengths[] = {3};
    Ref<IndexBuffer> ib = make<TriangleStripArray>(0, lengths);
    std::vector<Ref<VertexBuffer>> targets{make<VertexBuffer>(), make<VertexBuffer>()};
    for (auto& t : targets) t->setPositions(make<VertexArray>(3, 3, 2), 1.0f, {});
    Ref<MorphingMesh> morph = make<MorphingMesh>(vb, targets, ib, app);
    animateWith(*morph, AnimationTrack::MORPH_WEIGHTS, ramp({0, 0}, {0.5f, 1.5f}));
    w->addChild(morph);

    Ref<Background> bg = make<Background>();
    animateWith(*bg, AnimationTrack::COLOR, ramp(c0, c1));
    animateWith(*bg, AnimationTrack::ALPHA, ramp({0}, {0.4f}));
    animateWith(*bg, AnimationTrack::CROP, ramp({0, 0, 0, 0}, {2, 4, 6, 8}));
    w->setBackground(bg);

    Ref<Sprite3D> s2 = make<Sprite3D>(true, make<Image2D>(Image2D::RGB, 8, 8), app);
    animateWith(*s2, AnimationTrack::CROP, ramp({0, 0}, {10, 20}));
    Ref<Sprite3D> s4 = make<Sprite3D>(false, make<Image2D>(Image2D::RGB, 8, 8), nullptr);
    animateWith(*s4, AnimationTrack::CROP, ramp({0, 0, 0, 0}, {2, 4, -6, 8}));
    w->addChild(s2);
    w->addChild(s4);

    EXPECT_EQ(w->animate(50), 0);

    EXPECT_FLOAT_EQ(g->getAlphaFactor(), 0.25f);
    EXPECT_FALSE(g->isPickingEnabled());
    EXPECT_TRUE(g->isRenderingEnabled());
    const auto t = translation(*g);
    EXPECT_FLOAT_EQ(t[0], 1);
    EXPECT_FLOAT_EQ(t[1], 2);
    EXPECT_FLOAT_EQ(t[2], 3);
    float sc[3];
    g->getScale(sc);
    EXPECT_FLOAT_EQ(sc[0], 2);
    EXPECT_FLOAT_EQ(sc[1], 3);
    EXPECT_FLOAT_EQ(sc[2], 4);
    float aa[4];
    g->getOrientation(aa);  // halfway from identity to 180 about X
    EXPECT_NEAR(aa[0], 90, 1e-3);
    EXPECT_NEAR(aa[1], 1, 1e-5);

    float p[4];
    cam->getProjection(std::span<float>(p));
    EXPECT_FLOAT_EQ(p[0], 50);
    EXPECT_FLOAT_EQ(p[2], 2);
    EXPECT_FLOAT_EQ(p[3], 200);

    EXPECT_EQ(light->getColor(), 0x336699);
    EXPECT_FLOAT_EQ(light->getIntensity(), 2.5f);
    EXPECT_FLOAT_EQ(light->getSpotAngle(), 30);
    EXPECT_FLOAT_EQ(light->getSpotExponent(), 12);

    EXPECT_EQ(mat->getColor(Material::AMBIENT) & 0xFFFFFF, 0x336699);
    EXPECT_EQ(static_cast<std::uint32_t>(mat->getColor(Material::DIFFUSE)), 0x66336699u);
    EXPECT_EQ(mat->getColor(Material::EMISSIVE) & 0xFFFFFF, 0x336699);
    EXPECT_EQ(mat->getColor(Material::SPECULAR) & 0xFFFFFF, 0x336699);
    EXPECT_FLOAT_EQ(mat->getShininess(), 64);
    EXPECT_EQ(fog->getColor(), 0x336699);
    EXPECT_FLOAT_EQ(fog->getDensity(), 0.5f);
    EXPECT_FLOAT_EQ(fog->getNearDistance(), 3);
    EXPECT_FLOAT_EQ(fog->getFarDistance(), 30);
    EXPECT_EQ(tex->getBlendColor(), 0x336699);
    float tt[3];
    tex->getTranslation(tt);
    EXPECT_FLOAT_EQ(tt[0], 1);
    EXPECT_EQ(static_cast<std::uint32_t>(vb->getDefaultColor()), 0x66336699u);
    float mw[2];
    morph->getWeights(mw);
    EXPECT_FLOAT_EQ(mw[0], 0.25f);
    EXPECT_FLOAT_EQ(mw[1], 0.75f);

    EXPECT_EQ(static_cast<std::uint32_t>(bg->getColor()), 0x33336699u);
    EXPECT_EQ(bg->getCropX(), 1);
    EXPECT_EQ(bg->getCropY(), 2);
    EXPECT_EQ(bg->getCropWidth(), 3);
    EXPECT_EQ(bg->getCropHeight(), 4);

    EXPECT_EQ(s2->getCropX(), 5);
    EXPECT_EQ(s2->getCropY(), 10);
    EXPECT_EQ(s2->getCropWidth(), 8);  // 2 components: x and y only
    EXPECT_EQ(s2->getCropHeight(), 8);
    EXPECT_EQ(s4->getCropX(), 1);
    EXPECT_EQ(s4->getCropY(), 2);
    EXPECT_EQ(s4->getCropWidth(), -3);
    EXPECT_EQ(s4->getCropHeight(), 4);
}
