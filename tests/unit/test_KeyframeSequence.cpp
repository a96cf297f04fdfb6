// KeyframeSequence (JSR-184 1.1, KeyframeSequence): construction, keyframes, ranges,
// duration, repeat mode, lazy validation.
#include <gtest/gtest.h>

#include <vector>

#include <m3g/KeyframeSequence.h>

using namespace m3g;

TEST(KeyframeSequence, Constants) {
    EXPECT_EQ(KeyframeSequence::LINEAR, 176);
    EXPECT_EQ(KeyframeSequence::SLERP, 177);
    EXPECT_EQ(KeyframeSequence::SPLINE, 178);
    EXPECT_EQ(KeyframeSequence::SQUAD, 179);
    EXPECT_EQ(KeyframeSequence::STEP, 180);
    EXPECT_EQ(KeyframeSequence::CONSTANT, 192);
    EXPECT_EQ(KeyframeSequence::LOOP, 193);
}

TEST(KeyframeSequence, ConstructorChecks) {
    EXPECT_THROW(KeyframeSequence(0, 1, KeyframeSequence::LINEAR), IllegalArgumentException);
    EXPECT_THROW(KeyframeSequence(1, 0, KeyframeSequence::LINEAR), IllegalArgumentException);
    EXPECT_THROW(KeyframeSequence(1, 1, 175), IllegalArgumentException);
    EXPECT_THROW(KeyframeSequence(1, 1, 181), IllegalArgumentException);
    EXPECT_THROW(KeyframeSequence(1, 1, KeyframeSequence::CONSTANT), IllegalArgumentException);
    EXPECT_THROW(KeyframeSequence(2, 3, KeyframeSequence::SLERP), IllegalArgumentException);
    EXPECT_THROW(KeyframeSequence(2, 5, KeyframeSequence::SQUAD), IllegalArgumentException);
    EXPECT_NO_THROW(KeyframeSequence(2, 4, KeyframeSequence::SLERP));
    EXPECT_NO_THROW(KeyframeSequence(2, 4, KeyframeSequence::SQUAD));
    EXPECT_NO_THROW(KeyframeSequence(1, 7, KeyframeSequence::SPLINE));
    EXPECT_NO_THROW(KeyframeSequence(3, 2, KeyframeSequence::STEP));
}

TEST(KeyframeSequence, Defaults) {
    Ref<KeyframeSequence> s = make<KeyframeSequence>(3, 2, KeyframeSequence::SPLINE);
    EXPECT_EQ(s->getKeyframeCount(), 3);
    EXPECT_EQ(s->getComponentCount(), 2);
    EXPECT_EQ(s->getInterpolationType(), KeyframeSequence::SPLINE);
    EXPECT_EQ(s->getDuration(), 0);
    EXPECT_EQ(s->getRepeatMode(), KeyframeSequence::CONSTANT);
    EXPECT_EQ(s->getValidRangeFirst(), 0);
    EXPECT_EQ(s->getValidRangeLast(), 2);
    for (int i = 0; i < 3; ++i) {
        float v[2] = {9, 9};
        EXPECT_EQ(s->getKeyframe(i, v), 0);
        EXPECT_EQ(v[0], 0.0f);
        EXPECT_EQ(v[1], 0.0f);
    }
    EXPECT_STREQ(s->getClassName(), "KeyframeSequence");
}

TEST(KeyframeSequence, KeyframeRoundTrip) {
    Ref<KeyframeSequence> s = make<KeyframeSequence>(2, 3, KeyframeSequence::LINEAR);
    const float a[3] = {1, 2, 3};
    const float b[4] = {4, 5, 6, 99};  // longer than needed is fine
    s->setKeyframe(0, 10, a);
    s->setKeyframe(1, 20, b);
    float out[3];
    EXPECT_EQ(s->getKeyframe(0, out), 10);
    EXPECT_EQ(out[0], 1.0f);
    EXPECT_EQ(out[2], 3.0f);
    EXPECT_EQ(s->getKeyframe(1, out), 20);
    EXPECT_EQ(out[0], 4.0f);
    EXPECT_EQ(out[2], 6.0f);
    EXPECT_EQ(s->getKeyframe(1, std::span<float>()), 20);  // null value array
    // LINEAR keys are not normalised.
    const float big[3] = {3, 4, 0};
    s->setKeyframe(0, 0, big);
    s->getKeyframe(0, out);
    EXPECT_EQ(out[0], 3.0f);
    EXPECT_EQ(out[1], 4.0f);
}

TEST(KeyframeSequence, KeyframeChecks) {
    Ref<KeyframeSequence> s = make<KeyframeSequence>(2, 3, KeyframeSequence::LINEAR);
    const float v[3] = {1, 2, 3};
    const float shortV[2] = {1, 2};
    EXPECT_THROW(s->setKeyframe(0, 0, std::span<const float>()), NullPointerException);
    EXPECT_THROW(s->setKeyframe(-1, 0, v), IndexOutOfBoundsException);
    EXPECT_THROW(s->setKeyframe(2, 0, v), IndexOutOfBoundsException);
    EXPECT_THROW(s->setKeyframe(0, -1, v), IllegalArgumentException);
    EXPECT_THROW(s->setKeyframe(0, 0, shortV), IllegalArgumentException);
    float out[3];
    float shortOut[2];
    EXPECT_THROW(s->getKeyframe(-1, out), IndexOutOfBoundsException);
    EXPECT_THROW(s->getKeyframe(2, out), IndexOutOfBoundsException);
    EXPECT_THROW(s->getKeyframe(0, shortOut), IllegalArgumentException);
}

TEST(KeyframeSequence, QuaternionKeysAreNormalised) {
    for (int interp : {KeyframeSequence::SLERP, KeyframeSequence::SQUAD}) {
        Ref<KeyframeSequence> s = make<KeyframeSequence>(2, 4, interp);
        const float q[4] = {0, 0, 3, 4};
        s->setKeyframe(0, 0, q);
        float out[4];
        s->getKeyframe(0, out);
        EXPECT_FLOAT_EQ(out[0], 0.0f);
        EXPECT_FLOAT_EQ(out[1], 0.0f);
        EXPECT_FLOAT_EQ(out[2], 0.6f);
        EXPECT_FLOAT_EQ(out[3], 0.8f);
        const float zero[4] = {0, 0, 0, 0};
        s->setKeyframe(1, 5, zero);  // becomes the identity
        s->getKeyframe(1, out);
        EXPECT_EQ(out[2], 0.0f);
        EXPECT_EQ(out[3], 1.0f);
    }
}

TEST(KeyframeSequence, ValidRange) {
    Ref<KeyframeSequence> s = make<KeyframeSequence>(4, 1, KeyframeSequence::LINEAR);
    s->setValidRange(1, 2);
    EXPECT_EQ(s->getValidRangeFirst(), 1);
    EXPECT_EQ(s->getValidRangeLast(), 2);
    s->setValidRange(3, 0);  // wraps
    EXPECT_EQ(s->getValidRangeFirst(), 3);
    EXPECT_EQ(s->getValidRangeLast(), 0);
    EXPECT_THROW(s->setValidRange(-1, 2), IndexOutOfBoundsException);
    EXPECT_THROW(s->setValidRange(0, 4), IndexOutOfBoundsException);
    EXPECT_THROW(s->setValidRange(4, 0), IndexOutOfBoundsException);
    EXPECT_EQ(s->getValidRangeFirst(), 3);
}

TEST(KeyframeSequence, DurationAndRepeatMode) {
    Ref<KeyframeSequence> s = make<KeyframeSequence>(1, 1, KeyframeSequence::STEP);
    s->setDuration(1000);
    EXPECT_EQ(s->getDuration(), 1000);
    EXPECT_THROW(s->setDuration(0), IllegalArgumentException);
    EXPECT_THROW(s->setDuration(-5), IllegalArgumentException);
    EXPECT_EQ(s->getDuration(), 1000);
    s->setRepeatMode(KeyframeSequence::LOOP);
    EXPECT_EQ(s->getRepeatMode(), KeyframeSequence::LOOP);
    s->setRepeatMode(KeyframeSequence::CONSTANT);
    EXPECT_EQ(s->getRepeatMode(), KeyframeSequence::CONSTANT);
    EXPECT_THROW(s->setRepeatMode(KeyframeSequence::LINEAR), IllegalArgumentException);
    EXPECT_THROW(s->setRepeatMode(194), IllegalArgumentException);
}

TEST(KeyframeSequence, MutatorsTouch) {
    Ref<KeyframeSequence> s = make<KeyframeSequence>(2, 1, KeyframeSequence::LINEAR);
    const float v[1] = {1};
    auto r = s->getRevision();
    s->setKeyframe(0, 0, v);
    EXPECT_GT(s->getRevision(), r);
    r = s->getRevision();
    s->setDuration(5);
    EXPECT_GT(s->getRevision(), r);
    r = s->getRevision();
    s->setValidRange(0, 0);
    EXPECT_GT(s->getRevision(), r);
    r = s->getRevision();
    s->setRepeatMode(KeyframeSequence::LOOP);
    EXPECT_GT(s->getRevision(), r);
}

TEST(KeyframeSequence, ValidationDurationNotSet) {
    Ref<KeyframeSequence> s = make<KeyframeSequence>(1, 1, KeyframeSequence::LINEAR);
    EXPECT_THROW(s->validate(), IllegalStateException);
    s->setDuration(1);
    EXPECT_NO_THROW(s->validate());
}

TEST(KeyframeSequence, ValidationDecreasingTimes) {
    Ref<KeyframeSequence> s = make<KeyframeSequence>(3, 1, KeyframeSequence::LINEAR);
    const float v[1] = {0};
    s->setKeyframe(0, 10, v);
    s->setKeyframe(1, 5, v);
    s->setKeyframe(2, 20, v);
    s->setDuration(100);
    EXPECT_THROW(s->validate(), IllegalStateException);
    s->setValidRange(1, 2);  // 5, 20: fine
    EXPECT_NO_THROW(s->validate());
    s->setValidRange(2, 1);  // wraps: 20, 10, 5: decreasing
    EXPECT_THROW(s->validate(), IllegalStateException);
    s->setValidRange(2, 0);  // 20, 10: decreasing
    EXPECT_THROW(s->validate(), IllegalStateException);
    s->setKeyframe(0, 30, v);  // 20, 30
    EXPECT_NO_THROW(s->validate());
}

TEST(KeyframeSequence, ValidationLastTimeAfterDuration) {
    Ref<KeyframeSequence> s = make<KeyframeSequence>(2, 1, KeyframeSequence::LINEAR);
    const float v[1] = {0};
    s->setKeyframe(0, 0, v);
    s->setKeyframe(1, 50, v);
    s->setDuration(40);
    EXPECT_THROW(s->validate(), IllegalStateException);
    s->setDuration(50);  // last == duration is allowed
    EXPECT_NO_THROW(s->validate());
}

TEST(KeyframeSequence, DuplicateCopiesKeys) {
    Ref<KeyframeSequence> s = make<KeyframeSequence>(2, 2, KeyframeSequence::STEP);
    const float a[2] = {1, 2};
    s->setKeyframe(1, 7, a);
    s->setDuration(9);
    s->setRepeatMode(KeyframeSequence::LOOP);
    s->setValidRange(1, 0);
    Ref<KeyframeSequence> d = dynamicCast<KeyframeSequence>(s->duplicate());
    ASSERT_TRUE(d);
    EXPECT_NE(d.get(), s.get());
    float out[2];
    EXPECT_EQ(d->getKeyframe(1, out), 7);
    EXPECT_EQ(out[1], 2.0f);
    EXPECT_EQ(d->getDuration(), 9);
    EXPECT_EQ(d->getRepeatMode(), KeyframeSequence::LOOP);
    EXPECT_EQ(d->getValidRangeFirst(), 1);
    EXPECT_EQ(d->getValidRangeLast(), 0);
    EXPECT_EQ(d->getInterpolationType(), KeyframeSequence::STEP);
    // Independent storage.
    const float b[2] = {5, 5};
    d->setKeyframe(1, 8, b);
    EXPECT_EQ(s->getKeyframe(1, out), 7);
}
