// Keyframe sampling (JSR-184 1.1, KeyframeSequence), every interpolation and repeat mode
// at hand-computed points.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <m3g/KeyframeSequence.h>

#include "KeyframeSampler.h"

using namespace m3g;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

struct Key {
    int time;
    std::vector<float> value;
};

Ref<KeyframeSequence> makeSeq(int interp, int repeat, int duration, const std::vector<Key>& keys) {
    const int comps = static_cast<int>(keys[0].value.size());
    Ref<KeyframeSequence> s = make<KeyframeSequence>(static_cast<int>(keys.size()), comps, interp);
    for (std::size_t i = 0; i < keys.size(); ++i) s->setKeyframe(static_cast<int>(i), keys[i].time, keys[i].value);
    s->setDuration(duration);
    s->setRepeatMode(repeat);
    return s;
}

float sample1(const KeyframeSequence& s, double t) {
    float out[1];
    s.validate();
    detail::sampleKeyframes(detail::viewOf(s), t, out);
    return out[0];
}

std::vector<float> sampleN(const KeyframeSequence& s, double t) {
    std::vector<float> out(static_cast<std::size_t>(s.getComponentCount()));
    s.validate();
    detail::sampleKeyframes(detail::viewOf(s), t, out);
    return out;
}

// Quaternion for a rotation whose half-angle is `halfDeg` about +Z.
std::vector<float> zQuat(double halfDeg) {
    return {0.0f, 0.0f, float(std::sin(halfDeg * kDeg)), float(std::cos(halfDeg * kDeg))};
}

void expectQuat(const std::vector<float>& q, const std::vector<float>& expected, float eps = 1e-5f) {
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(q[i], expected[i], eps) << "component " << i;
}

}  // namespace

TEST(KeyframeSampler, LinearConstant) {
    auto s = makeSeq(KeyframeSequence::LINEAR, KeyframeSequence::CONSTANT, 40, {{0, {0}}, {10, {10}}, {30, {50}}});
    EXPECT_FLOAT_EQ(sample1(*s, -5), 0);
    EXPECT_FLOAT_EQ(sample1(*s, 0), 0);
    EXPECT_FLOAT_EQ(sample1(*s, 5), 5);
    EXPECT_FLOAT_EQ(sample1(*s, 10), 10);
    EXPECT_FLOAT_EQ(sample1(*s, 20), 30);  // halfway 10 -> 50
    EXPECT_FLOAT_EQ(sample1(*s, 30), 50);
    EXPECT_FLOAT_EQ(sample1(*s, 35), 50);
    EXPECT_FLOAT_EQ(sample1(*s, 1000), 50);
}

TEST(KeyframeSampler, LinearLoopWrapsThroughDuration) {
    auto s = makeSeq(KeyframeSequence::LINEAR, KeyframeSequence::LOOP, 40, {{0, {0}}, {10, {10}}, {30, {50}}});
    // Wrap segment 30 -> 40 (key 0 again), 50 -> 0.
    EXPECT_FLOAT_EQ(sample1(*s, 35), 25);
    EXPECT_FLOAT_EQ(sample1(*s, 45), 5);
    EXPECT_FLOAT_EQ(sample1(*s, -5), 25);
    EXPECT_FLOAT_EQ(sample1(*s, 70), 50);
    EXPECT_FLOAT_EQ(sample1(*s, 80), 0);
}

TEST(KeyframeSampler, LoopWithFirstKeyAfterZero) {
    // Keys at 10 and 20, duration 30: the wrap segment 20 -> 40 has length 20.
    auto s = makeSeq(KeyframeSequence::LINEAR, KeyframeSequence::LOOP, 30, {{10, {0}}, {20, {10}}});
    EXPECT_FLOAT_EQ(sample1(*s, 5), 2.5f);   // 35 on the wrap: u = 0.75
    EXPECT_FLOAT_EQ(sample1(*s, 25), 7.5f);  // u = 0.25
    EXPECT_FLOAT_EQ(sample1(*s, 15), 5);
}

TEST(KeyframeSampler, Step) {
    auto s = makeSeq(KeyframeSequence::STEP, KeyframeSequence::CONSTANT, 20, {{0, {1}}, {10, {2}}, {20, {3}}});
    EXPECT_FLOAT_EQ(sample1(*s, 9.9), 1);
    EXPECT_FLOAT_EQ(sample1(*s, 10), 2);
    EXPECT_FLOAT_EQ(sample1(*s, 15), 2);
    EXPECT_FLOAT_EQ(sample1(*s, 19.99), 2);
    EXPECT_FLOAT_EQ(sample1(*s, 25), 3);
    float out[1];
    const auto v = detail::sampleKeyframes(detail::viewOf(*s), 15, out);
    EXPECT_DOUBLE_EQ(v.forward, 5);
    EXPECT_DOUBLE_EQ(v.backward, 5);
}

TEST(KeyframeSampler, StepLoop) {
    auto s = makeSeq(KeyframeSequence::STEP, KeyframeSequence::LOOP, 30, {{0, {1}}, {10, {2}}, {20, {3}}});
    EXPECT_FLOAT_EQ(sample1(*s, 25), 3);
    EXPECT_FLOAT_EQ(sample1(*s, 31), 1);
    EXPECT_FLOAT_EQ(sample1(*s, 42), 2);
}

TEST(KeyframeSampler, CoincidentKeysTakeTheLaterOne) {
    auto s = makeSeq(KeyframeSequence::LINEAR, KeyframeSequence::CONSTANT, 20,
                     {{0, {0}}, {10, {5}}, {10, {20}}, {20, {30}}});
    EXPECT_FLOAT_EQ(sample1(*s, 5), 2.5f);
    EXPECT_FLOAT_EQ(sample1(*s, 10), 20);
    EXPECT_FLOAT_EQ(sample1(*s, 15), 25);
}

TEST(KeyframeSampler, SingleKeyIsConstant) {
    auto s = makeSeq(KeyframeSequence::SPLINE, KeyframeSequence::LOOP, 10, {{3, {7}}});
    EXPECT_FLOAT_EQ(sample1(*s, -100), 7);
    EXPECT_FLOAT_EQ(sample1(*s, 5), 7);
    float out[1];
    const auto v = detail::sampleKeyframes(detail::viewOf(*s), 5, out);
    EXPECT_TRUE(std::isinf(v.forward));
    EXPECT_TRUE(std::isinf(v.backward));
}

TEST(KeyframeSampler, ValidityOfConstantEnds) {
    auto s = makeSeq(KeyframeSequence::LINEAR, KeyframeSequence::CONSTANT, 40, {{10, {0}}, {30, {1}}});
    float out[1];
    auto v = detail::sampleKeyframes(detail::viewOf(*s), 4, out);
    EXPECT_DOUBLE_EQ(v.forward, 6);
    EXPECT_TRUE(std::isinf(v.backward));
    v = detail::sampleKeyframes(detail::viewOf(*s), 35, out);
    EXPECT_TRUE(std::isinf(v.forward));
    EXPECT_DOUBLE_EQ(v.backward, 5);
    v = detail::sampleKeyframes(detail::viewOf(*s), 20, out);
    EXPECT_DOUBLE_EQ(v.forward, 0);
}

TEST(KeyframeSampler, SplineNonUniformSpacingReproducesLinearData) {
    // P = t at t = 0, 10, 30, 40. Segment 10 -> 30: central difference 15,
    // outgoing scale at key 1 = 2*20/(10+20) = 4/3 and incoming scale at key 2
    // = 2*20/(20+10) = 4/3, so both tangents are 20 and the curve is exactly
    // linear: at u = 0.25 (t = 15) Hermite gives
    // 0.84375*10 + 0.15625*30 + 0.140625*20 - 0.046875*20 = 15.
    // (Unscaled tangents of 15 would give 14.53.)
    auto s = makeSeq(KeyframeSequence::SPLINE, KeyframeSequence::CONSTANT, 40,
                     {{0, {0}}, {10, {10}}, {30, {30}}, {40, {40}}});
    EXPECT_NEAR(sample1(*s, 15), 15.0f, 1e-5f);
    EXPECT_NEAR(sample1(*s, 20), 20.0f, 1e-5f);
    EXPECT_NEAR(sample1(*s, 25), 25.0f, 1e-5f);
    // First segment: the first key has a zero tangent (CONSTANT end), key 1's
    // incoming tangent is 15 * 2*10/(10+20) = 10. At u = 0.5:
    // 0.5*0 + 0.5*10 + 0.125*0 - 0.125*10 = 3.75.
    EXPECT_NEAR(sample1(*s, 5), 3.75f, 1e-5f);
    EXPECT_FLOAT_EQ(sample1(*s, 10), 10);
    EXPECT_FLOAT_EQ(sample1(*s, 50), 40);
}

TEST(KeyframeSampler, SplineLoopUsesWrappedNeighbours) {
    // Keys t = 0, 10, 30 with P = 0, 10, 30; duration 40 (wrap segment 10).
    // Key 0: T = (P1 - P2)/2 = -10, scales 1 (10 | 10).
    // Key 1: T = (P2 - P0)/2 = 15, in 2*10/30, out 2*20/30.
    // Key 2: T = (P0 - P1)/2 = -5, in 2*20/30, out 2*10/30.
    auto s = makeSeq(KeyframeSequence::SPLINE, KeyframeSequence::LOOP, 40, {{0, {0}}, {10, {10}}, {30, {30}}});
    // t = 5, u = 0.5: 0.5*0 + 0.5*10 + 0.125*(-10) - 0.125*(15*2/3) = 2.5
    EXPECT_NEAR(sample1(*s, 5), 2.5f, 1e-5f);
    // t = 35, wrap segment u = 0.5: 0.5*30 + 0.5*0 + 0.125*(-5*2/3) - 0.125*(-10) = 15.8333333
    EXPECT_NEAR(sample1(*s, 35), 15.833333f, 1e-4f);
    EXPECT_NEAR(sample1(*s, 75), 15.833333f, 1e-4f);
}

TEST(KeyframeSampler, SplineVectorComponentsIndependent) {
    auto s = makeSeq(KeyframeSequence::SPLINE, KeyframeSequence::CONSTANT, 40,
                     {{0, {0, 0}}, {10, {10, -10}}, {30, {30, -30}}, {40, {40, -40}}});
    const auto v = sampleN(*s, 15);
    EXPECT_NEAR(v[0], 15.0f, 1e-5f);
    EXPECT_NEAR(v[1], -15.0f, 1e-5f);
}

TEST(KeyframeSampler, Slerp) {
    // Identity to 90 degrees about Z; halfway is 45 degrees (half-angle 22.5).
    auto s = makeSeq(KeyframeSequence::SLERP, KeyframeSequence::CONSTANT, 10, {{0, zQuat(0)}, {10, zQuat(45)}});
    expectQuat(sampleN(*s, 5), zQuat(22.5));
    expectQuat(sampleN(*s, 2.5), zQuat(11.25));
    expectQuat(sampleN(*s, 10), zQuat(45));
}

TEST(KeyframeSampler, SlerpDoesNotTakeTheShortestArc) {
    // q1 = -(rotation of 45 degrees about Z): dot(q0, q1) = -cos 22.5 < 0.
    // Without the sign flip the path is the 157.5 degree arc of the 4D sphere;
    // halfway lies 78.75 degrees from q0 towards q1: (0, 0, -sin 78.75, cos 78.75).
    const std::vector<float> q1{0.0f, 0.0f, -float(std::sin(22.5 * kDeg)), -float(std::cos(22.5 * kDeg))};
    auto s = makeSeq(KeyframeSequence::SLERP, KeyframeSequence::CONSTANT, 10, {{0, zQuat(0)}, {10, q1}});
    expectQuat(sampleN(*s, 5), {0.0f, 0.0f, -0.98078528f, 0.19509032f});
}

TEST(KeyframeSampler, SlerpOppositeQuaternionsStaysUnit) {
    auto s = makeSeq(KeyframeSequence::SLERP, KeyframeSequence::CONSTANT, 10,
                     {{0, {0, 0, 0, 1}}, {10, {0, 0, 0, -1}}});
    const auto q = sampleN(*s, 5);
    const double len = std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] + double(q[2]) * q[2] + double(q[3]) * q[3]);
    EXPECT_NEAR(len, 1.0, 1e-6);
    EXPECT_NEAR(q[3], 0.0f, 1e-6f);  // a quarter of the way round the 4D circle
    expectQuat(sampleN(*s, 10), {0, 0, 0, -1});
}

TEST(KeyframeSampler, SquadNonUniformSpacing) {
    // Rotations about Z only (everything commutes, logs are (0, 0, half-angle)).
    // Half-angles 0, 10, 30, 40 degrees at t = 0, 10, 30, 40: linear in time.
    // Key 1: logs prev 10, next 20, centred difference 15, out scale 4/3 -> 20,
    //   A1 = q1 exp((20 - 20)/2) = q1. Key 2: in scale 4/3 -> 20, B2 = q2.
    // So segment 1 is a plain slerp: at t = 15 the half-angle is 15.
    auto s = makeSeq(KeyframeSequence::SQUAD, KeyframeSequence::CONSTANT, 40,
                     {{0, zQuat(0)}, {10, zQuat(10)}, {30, zQuat(30)}, {40, zQuat(40)}});
    expectQuat(sampleN(*s, 15), zQuat(15));
    expectQuat(sampleN(*s, 25), zQuat(25));
    // Segment 0: key 0 is a CONSTANT end, its tangent is 0:
    //   A0 = q0 exp((0 - 10)/2) -> half-angle -5.
    // Key 1 incoming: 15 * 2*10/30 = 10, B1 = q1 exp((10 - 10)/2) = q1 -> 10.
    // u = 0.5: slerp(q0, q1) -> 5, slerp(A0, B1) -> 2.5, blended with
    // 2u(1-u) = 0.5 -> 3.75.
    expectQuat(sampleN(*s, 5), zQuat(3.75));
}

TEST(KeyframeSampler, SquadUniformMatchesSlerpForConstantRate) {
    auto s = makeSeq(KeyframeSequence::SQUAD, KeyframeSequence::LOOP, 40,
                     {{0, zQuat(0)}, {10, zQuat(10)}, {20, zQuat(20)}, {30, zQuat(30)}});
    expectQuat(sampleN(*s, 12), zQuat(12));
}

TEST(KeyframeSampler, ValidRangeWrap) {
    // Valid keys 2, 3, 0 (range first = 2 > last = 0); key 1 is ignored even
    // though its time would break the order.
    Ref<KeyframeSequence> s = make<KeyframeSequence>(4, 1, KeyframeSequence::LINEAR);
    const float v0[1] = {40}, v1[1] = {999}, v2[1] = {0}, v3[1] = {10};
    s->setKeyframe(0, 20, v0);
    s->setKeyframe(1, 5, v1);
    s->setKeyframe(2, 0, v2);
    s->setKeyframe(3, 10, v3);
    s->setDuration(30);
    EXPECT_THROW(s->validate(), IllegalStateException);  // full range 20, 5, 0, 10
    s->setValidRange(2, 0);
    EXPECT_NO_THROW(s->validate());
    EXPECT_FLOAT_EQ(sample1(*s, 5), 5);
    EXPECT_FLOAT_EQ(sample1(*s, 15), 25);
    EXPECT_FLOAT_EQ(sample1(*s, 25), 40);
    s->setRepeatMode(KeyframeSequence::LOOP);
    // Wrap segment key 0 (t 20, 40) -> key 2 (t 0 + 30, 0): at 25 u = 0.5.
    EXPECT_FLOAT_EQ(sample1(*s, 25), 20);
    EXPECT_FLOAT_EQ(sample1(*s, 35), 5);
}

TEST(KeyframeSampler, ValidRangeSubset) {
    auto s = makeSeq(KeyframeSequence::LINEAR, KeyframeSequence::CONSTANT, 100,
                     {{0, {100}}, {10, {0}}, {20, {10}}, {30, {500}}});
    s->setValidRange(1, 2);
    EXPECT_FLOAT_EQ(sample1(*s, 0), 0);  // before key 1: its value
    EXPECT_FLOAT_EQ(sample1(*s, 15), 5);
    EXPECT_FLOAT_EQ(sample1(*s, 90), 10);
}

TEST(KeyframeSampler, SplineNonUniformSpacingCurvedData) {
    // P = 0, 20, 10, 40 at t = 0, 10, 30, 40 (spacings 10, 20, 10), CONSTANT.
    // Key 1: central difference (10 - 0)/2 = 5; in scale 2*10/30, out 2*20/30
    //   -> T1in = 10/3, T1out = 20/3.
    // Key 2: central difference (40 - 20)/2 = 10; in scale 2*20/30, out
    //   2*10/30 -> T2in = 40/3, T2out = 20/3. Key 3 (CONSTANT end): 0.
    auto s = makeSeq(KeyframeSequence::SPLINE, KeyframeSequence::CONSTANT, 40,
                     {{0, {0}}, {10, {20}}, {30, {10}}, {40, {40}}});
    // t = 20, u = 0.5: 0.5*20 + 0.5*10 + 0.125*(20/3) - 0.125*(40/3) = 14.1666...
    EXPECT_NEAR(sample1(*s, 20), 15.0f - 2.5f / 3.0f, 1e-4f);
    // t = 15, u = 0.25: 0.84375*20 + 0.15625*10 + 0.140625*(20/3) - 0.046875*(40/3) = 18.75
    EXPECT_NEAR(sample1(*s, 15), 18.75f, 1e-4f);
    // t = 35, u = 0.5: 0.5*10 + 0.5*40 + 0.125*(20/3) - 0.125*0 = 25.8333...
    EXPECT_NEAR(sample1(*s, 35), 25.0f + 2.5f / 3.0f, 1e-4f);
    // t = 5, u = 0.5 (key 0 is the CONSTANT start: tangent 0):
    // 0.5*0 + 0.5*20 + 0 - 0.125*(10/3) = 9.5833...
    EXPECT_NEAR(sample1(*s, 5), 10.0f - 1.25f / 3.0f, 1e-4f);
}

TEST(KeyframeSampler, SquadLoopFourKeysNonConstantRate) {
    // Rotations about Z only, so everything commutes and a quaternion is
    // fixed by its half-angle; slerp and exp/log then act on half-angles.
    // Half-angles 0, 10, 40, 30 at t = 0, 10, 20, 30; LOOP, duration 40, so
    // every spacing is 10 (tangent scales 1) and the wrap goes 30 -> 0.
    // Differences to the next key: d0 = 10, d1 = 30, d2 = -10, d3 = -30.
    // Tangents T_i = (d_{i-1} + d_i)/2: T0 = -10, T1 = 20, T2 = 10, T3 = -20.
    // A_i = a_i + (T_i - d_i)/2, B_i = a_i + (d_{i-1} - T_i)/2:
    //   A1 = 5, B2 = 50, A3 = 35, B0 = -10.
    // squad = L + 2u(1-u)(M - L) with L = lerp(a_i, a_i+1), M = lerp(A_i, B_i+1).
    auto s = makeSeq(KeyframeSequence::SQUAD, KeyframeSequence::LOOP, 40,
                     {{0, zQuat(0)}, {10, zQuat(10)}, {20, zQuat(40)}, {30, zQuat(30)}});
    // t = 15 (u 0.5): L = 25, M = 27.5 -> 25 + 0.5 * 2.5 = 26.25.
    expectQuat(sampleN(*s, 15), zQuat(26.25));
    // t = 12 (u 0.2): L = 16, M = 5 + 0.2 * 45 = 14 -> 16 + 0.32 * (-2) = 15.36.
    expectQuat(sampleN(*s, 12), zQuat(15.36));
    // Wrap segment, t = 35 (u 0.5): L = 15, M = (35 - 10)/2 = 12.5 -> 13.75.
    expectQuat(sampleN(*s, 35), zQuat(13.75));
    // The same point one loop later and one loop earlier.
    expectQuat(sampleN(*s, 75), zQuat(13.75));
    expectQuat(sampleN(*s, -5), zQuat(13.75));
    // The keys themselves.
    expectQuat(sampleN(*s, 20), zQuat(40));
    expectQuat(sampleN(*s, 40), zQuat(0));
}

// SQUAD control quaternions and arcs computed once per change of the sequence
// (KeyframeSequence::squadControls and quaternionArcs, as animate() samples)
// give the same bits as computing them per sample; every kind of change
// refreshes them.
TEST(KeyframeSampler, SquadControlsCachedGiveTheSameBitsAndFollowChanges) {
    auto s = makeSeq(KeyframeSequence::SQUAD, KeyframeSequence::LOOP, 100,
                     {{0, {0, 0, 0, 1}},
                      {15, {0.3f, 0.1f, 0, 0.9f}},
                      {40, {0, 0.7f, 0.2f, 0.6f}},
                      {70, {-0.5f, 0, 0.5f, 0.5f}},
                      {90, {0.1f, -0.2f, 0.9f, 0.3f}}});
    auto expectSameBits = [&](const char* what) {
        s->validate();
        detail::KeyframeView perSample = detail::viewOf(*s);
        detail::KeyframeView cached = perSample;
        cached.squad = s->squadControls();
        ASSERT_FALSE(cached.squad.empty()) << what;
        detail::KeyframeView withArcs = cached;  // as animate() samples
        withArcs.arcs = s->quaternionArcs();
        ASSERT_FALSE(withArcs.arcs.empty()) << what;
        for (double t = -30.0; t <= 230.0; t += 1.7) {
            float a[4], b[4], c[4];
            detail::sampleKeyframes(perSample, t, a);
            detail::sampleKeyframes(cached, t, b);
            detail::sampleKeyframes(withArcs, t, c);
            for (int i = 0; i < 4; ++i) {
                ASSERT_EQ(a[i], b[i]) << what << ", time " << t << ", component " << i;
                ASSERT_EQ(a[i], c[i]) << what << ", arcs, time " << t << ", component " << i;
            }
        }
    };
    expectSameBits("loop");
    const float q[4] = {0.6f, 0, 0, 0.8f};
    s->setKeyframe(2, 45, q);
    expectSameBits("after setKeyframe");
    // A wrapping valid range (keys 3, 4, 0, 1), with times rising along it.
    const float k0[4] = {0, 0, 0, 1}, k1[4] = {0.3f, 0.1f, 0, 0.9f};
    const float k3[4] = {-0.5f, 0, 0.5f, 0.5f}, k4[4] = {0.1f, -0.2f, 0.9f, 0.3f};
    s->setKeyframe(3, 0, k3);
    s->setKeyframe(4, 10, k4);
    s->setKeyframe(0, 20, k0);
    s->setKeyframe(1, 50, k1);
    s->setValidRange(3, 1);
    expectSameBits("after a wrapping setValidRange");
    s->setValidRange(3, 4);
    s->setRepeatMode(KeyframeSequence::CONSTANT);
    expectSameBits("after setRepeatMode");
    s->setDuration(95);
    expectSameBits("after setDuration");
    auto linear = makeSeq(KeyframeSequence::LINEAR, KeyframeSequence::LOOP, 10, {{0, {1}}, {5, {2}}});
    EXPECT_TRUE(linear->squadControls().empty());
    EXPECT_TRUE(linear->quaternionArcs().empty());
}

// A segment guess (what animate() passes: the last sample's segment) never
// changes the result: right, stale, out-of-range and negative guesses give
// the same bits and validity as no guess, and the segment handed back is
// the one the binary search finds. Coincident key times, a wrapping valid
// range and both repeat modes included.
TEST(KeyframeSampler, SegmentGuessGivesTheSameResultAsTheSearch) {
    auto s = makeSeq(KeyframeSequence::SQUAD, KeyframeSequence::LOOP, 100,
                     {{0, {0, 0, 0, 1}},
                      {15, {0.3f, 0.1f, 0, 0.9f}},
                      {15, {0, 0.7f, 0.2f, 0.6f}},
                      {70, {-0.5f, 0, 0.5f, 0.5f}},
                      {90, {0.1f, -0.2f, 0.9f, 0.3f}}});
    auto l = makeSeq(KeyframeSequence::LINEAR, KeyframeSequence::CONSTANT, 60,
                     {{5, {1}}, {10, {2}}, {10, {3}}, {30, {4}}, {31, {5}}, {50, {6}}});
    auto compare = [](const KeyframeSequence& seq, const char* what) {
        seq.validate();
        detail::KeyframeView view = detail::viewOf(seq);
        view.squad = seq.squadControls();
        int carried = 0;  // as animate() carries it from sample to sample
        for (double t = -130.0; t <= 260.0; t += 0.75) {
            std::vector<float> plain(4), guessed(4), carriedOut(4);
            const auto v0 = detail::sampleKeyframes(view, t, plain);
            for (int guess : {-3, 0, 1, 2, 3, 4, 5, 6, 99}) {
                int g = guess;
                const auto v1 = detail::sampleKeyframes(view, t, guessed, &g);
                ASSERT_EQ(plain, guessed) << what << ", time " << t << ", guess " << guess;
                ASSERT_EQ(v0.forward, v1.forward);
                ASSERT_EQ(v0.backward, v1.backward);
            }
            detail::sampleKeyframes(view, t, carriedOut, &carried);
            ASSERT_EQ(plain, carriedOut) << what << ", time " << t;
        }
    };
    compare(*s, "squad loop");
    compare(*l, "linear constant");
    s->setValidRange(3, 1);  // keys 3, 4, 0, 1: times 70, 90, 0, 15 do not rise: fix them
    const float k3[4] = {-0.5f, 0, 0.5f, 0.5f}, k4[4] = {0.1f, -0.2f, 0.9f, 0.3f};
    const float k0[4] = {0, 0, 0, 1}, k1[4] = {0.3f, 0.1f, 0, 0.9f};
    s->setKeyframe(3, 0, k3);
    s->setKeyframe(4, 10, k4);
    s->setKeyframe(0, 20, k0);
    s->setKeyframe(1, 50, k1);
    compare(*s, "wrapping valid range");
    s->setRepeatMode(KeyframeSequence::CONSTANT);
    compare(*s, "wrapping valid range, constant");
}

// The same for SLERP: arcs kept per segment, nearly equal and exactly
// opposite neighbours (the two special arcs) included.
TEST(KeyframeSampler, SlerpArcsCachedGiveTheSameBitsAndFollowChanges) {
    auto s = makeSeq(KeyframeSequence::SLERP, KeyframeSequence::LOOP, 100,
                     {{0, {0, 0, 0, 1}},
                      {15, {0, 0, 0, -1}},
                      {40, {0, 0.7f, 0.2f, 0.6f}},
                      {70, {0, 0.7f, 0.2f, 0.6f}},
                      {90, {-0.5f, 0, 0.5f, 0.5f}}});
    auto expectSameBits = [&](const char* what) {
        s->validate();
        const detail::KeyframeView perSample = detail::viewOf(*s);
        detail::KeyframeView cached = perSample;
        cached.arcs = s->quaternionArcs();
        ASSERT_FALSE(cached.arcs.empty()) << what;
        for (double t = -30.0; t <= 230.0; t += 1.3) {
            float a[4], b[4];
            detail::sampleKeyframes(perSample, t, a);
            detail::sampleKeyframes(cached, t, b);
            for (int c = 0; c < 4; ++c) ASSERT_EQ(a[c], b[c]) << what << ", time " << t << ", component " << c;
        }
    };
    expectSameBits("loop");
    const float q[4] = {0.6f, 0, 0, -0.8f};
    s->setKeyframe(3, 75, q);
    expectSameBits("after setKeyframe");
    s->setValidRange(1, 3);
    expectSameBits("after setValidRange");
}

// Looping time is mapped without fmod (a quotient from the kept reciprocal
// of the duration, corrected by one either way): the same bits as the fmod
// mapping, at fractional, negative, huge times and times a rounding away
// from a multiple of the duration, with and without the reciprocal, for a
// valid range that starts after time 0 too.
TEST(KeyframeSampler, LoopMappingGivesFmodsBits) {
    auto s = makeSeq(KeyframeSequence::LINEAR, KeyframeSequence::LOOP, 97,
                     {{3, {1.0f, -2.0f}}, {40, {7.5f, 3.25f}}, {41, {-4.0f, 0.5f}}, {90, {2.0f, 9.0f}}});
    auto fmodTime = [](double time, double duration, double first) {  // the fmod mapping
        double m = std::fmod(time, duration);
        if (m < 0.0) m += duration;
        if (m < first) m += duration;
        return m;
    };
    std::vector<double> times;
    for (double t = -1000.0; t <= 1000.0; t += 0.37) times.push_back(t);
    for (double k : {-1e11, -12345.0, -3.0, -1.0, 1.0, 2.0, 3.0, 1e6, 123456789.0, 1e10, 1.13e10, 1.14e10, 3e12, 1e20})
        for (double e : {0.0, 1e-9, -1e-9, 1e-30, -1e-30, 0.5, -0.5})
            times.push_back(k * 97.0 + e);
    for (double t : {-1e-30, 1e-300, 0x1p40 - 0.5, 0x1p40, -0x1p40 + 0.5, -0x1p40}) times.push_back(t);
    for (int first : {0, 1}) {
        s->setValidRange(first, 3);
        s->validate();
        const detail::KeyframeView kept = detail::viewOf(*s);
        ASSERT_GT(kept.inverseDuration, 0.0);
        detail::KeyframeView divided = kept;
        divided.inverseDuration = 0.0;
        const double firstTime = first == 0 ? 3.0 : 40.0;
        for (double t : times) {
            float a[2], b[2], c[2];
            detail::sampleKeyframes(kept, t, a);
            detail::sampleKeyframes(divided, t, b);
            detail::sampleKeyframes(kept, fmodTime(t, 97.0, firstTime), c);
            for (int i = 0; i < 2; ++i) {
                ASSERT_EQ(a[i], c[i]) << "time " << t << ", first key " << first << ", component " << i;
                ASSERT_EQ(b[i], c[i]) << "time " << t << ", first key " << first << ", component " << i;
            }
        }
    }
}

// SPLINE tangents kept per change of the sequence (splineTangents, as
// animate() samples) agree with computing them per sample to their float
// rounding, and every kind of change refreshes them.
TEST(KeyframeSampler, SplineTangentsCachedAgreeAndFollowChanges) {
    auto s = makeSeq(KeyframeSequence::SPLINE, KeyframeSequence::LOOP, 100,
                     {{0, {0, 1, -3}}, {15, {2, 0.5f, 4}}, {40, {-7, 3, 0}}, {70, {5, -1, 2}}, {90, {1, 8, -6}}});
    auto expectAgree = [&](const char* what) {
        s->validate();
        const detail::KeyframeView perSample = detail::viewOf(*s);
        detail::KeyframeView cached = perSample;
        cached.tangents = s->splineTangents();
        ASSERT_FALSE(cached.tangents.empty()) << what;
        for (double t = -30.0; t <= 230.0; t += 1.3) {
            float a[3], b[3];
            detail::sampleKeyframes(perSample, t, a);
            detail::sampleKeyframes(cached, t, b);
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(a[c], b[c], 2e-6f) << what << ", time " << t << ", component " << c;
        }
    };
    expectAgree("loop");
    const float v[3] = {9, -9, 9};
    s->setKeyframe(2, 45, v);
    expectAgree("after setKeyframe");
    s->setValidRange(1, 3);
    expectAgree("after setValidRange");
    s->setDuration(130);
    expectAgree("after setDuration");
    s->setRepeatMode(KeyframeSequence::CONSTANT);
    expectAgree("after setRepeatMode");
    auto linear = makeSeq(KeyframeSequence::LINEAR, KeyframeSequence::LOOP, 10, {{0, {1}}, {5, {2}}});
    EXPECT_TRUE(linear->splineTangents().empty());
}

// Flat segments (KeyframeSequence::flatSegments, as animate() samples): a
// segment is flat exactly where everything its samples read equals key j,
// worked out here from the keys: LINEAR and SLERP need the two keys equal;
// SPLINE and SQUAD also read the neighbours (tangents, control quaternions),
// so a looping hold of four equal keys A A A A B has one flat segment, 1 -> 2
// (0 -> 1 reads B before it, 2 -> 3 reads B after it). A CONSTANT sequence's
// end tangents are 0 whatever the neighbours. Sampling with the flags gives
// the same values as interpolating (== on floats: a -0 may become +0).
TEST(KeyframeSampler, FlatSegmentsHoldTheKeyAndSampleTheSame) {
    const std::vector<float> a = zQuat(10), b = zQuat(40), c = zQuat(-25);
    const std::vector<float> p = {1.5f, -2, 0.25f}, q = {3, 1, -4}, r = {-1, 0.5f, 2};
    struct Case {
        int interp;
        int repeat;
        std::vector<Key> keys;
        std::vector<unsigned char> flat;
    };
    const std::vector<Case> cases = {
        // A A B C C: 0 -> 1 and 3 -> 4 hold, 4 -> 0 wraps to a different key.
        {KeyframeSequence::LINEAR, KeyframeSequence::LOOP, {{0, p}, {10, p}, {20, q}, {35, r}, {50, r}}, {1, 0, 0, 1, 0}},
        {KeyframeSequence::SLERP, KeyframeSequence::LOOP, {{0, a}, {10, a}, {20, b}, {35, c}, {50, c}}, {1, 0, 0, 1, 0}},
        {KeyframeSequence::SPLINE, KeyframeSequence::LOOP, {{0, p}, {10, p}, {20, p}, {35, p}, {50, q}}, {0, 1, 0, 0, 0}},
        {KeyframeSequence::SQUAD, KeyframeSequence::LOOP, {{0, a}, {10, a}, {20, a}, {35, a}, {50, b}}, {0, 1, 0, 0, 0}},
        // CONSTANT: the first key's outgoing tangent is 0, key 2 = key 0.
        {KeyframeSequence::SPLINE, KeyframeSequence::CONSTANT, {{0, p}, {10, p}, {20, p}, {35, q}}, {1, 0, 0, 0}},
        {KeyframeSequence::STEP, KeyframeSequence::LOOP, {{0, p}, {10, p}, {20, q}}, {}},
    };
    for (const Case& k : cases) {
        auto s = makeSeq(k.interp, k.repeat, 70, k.keys);
        s->validate();
        const std::span<const unsigned char> flat = s->flatSegments();
        ASSERT_EQ(std::vector<unsigned char>(flat.begin(), flat.end()), k.flat) << "interpolation " << k.interp;
        // The view without the flags (per sample) and with the kept data.
        const detail::KeyframeView plain = detail::viewOf(*s);
        const detail::KeyframeView kept = detail::preparedViewOf(*s);
        ASSERT_EQ(kept.flat.size(), k.flat.size());
        const std::size_t n = std::size_t(s->getComponentCount());
        for (double t = -20.0; t <= 160.0; t += 0.7) {
            std::vector<float> x(n), y(n);
            detail::sampleKeyframes(plain, t, x);
            detail::sampleKeyframes(kept, t, y);
            for (std::size_t i = 0; i < n; ++i)
                ASSERT_NEAR(x[i], y[i], 2e-6f) << "interpolation " << k.interp << ", time " << t << ", component " << i;
        }
        // Inside a flat segment the sample is the key itself.
        for (std::size_t j = 0; j < k.flat.size(); ++j) {
            if (!k.flat[j]) continue;
            std::vector<float> y(n);
            detail::sampleKeyframes(kept, k.keys[j].time + 3.5, y);
            for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(y[i], k.keys[j].value[i]) << "segment " << j;
        }
    }
    // A change of a key recomputes the flags.
    auto s = makeSeq(KeyframeSequence::LINEAR, KeyframeSequence::LOOP, 70, {{0, p}, {10, p}, {20, q}});
    s->validate();
    EXPECT_EQ(s->flatSegments()[0], 1);
    s->setKeyframe(1, 10, q);
    s->validate();
    EXPECT_EQ(s->flatSegments()[0], 0);
    EXPECT_EQ(s->flatSegments()[1], 1);
}

// animate() leaves the SQUAD samples inside segments to sampleSquads, which
// computes several at a time: each must be what sampleKeyframes gives (bit
// for bit where the compiler cannot fuse multiply-adds differently in the
// two places), with the same validity and segment, and nothing else may be
// deferred. Keys: random unit quaternions, plus repeated, nearly equal and
// opposite neighbours (the arcs' Linear and Renormalise cases); LOOP and
// CONSTANT; more samples than one block, in an odd number.
TEST(KeyframeSampler, DeferredSquadSamplesEqualDirectOnes) {
    std::uint32_t state = 12345;
    auto next = [&] {
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / float(1u << 24) * 2.0f - 1.0f;
    };
    auto unit = [&] {
        std::vector<float> q = {next(), next(), next(), next()};
        const float n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        for (float& c : q) c /= n;
        return q;
    };
    for (int repeat : {KeyframeSequence::LOOP, KeyframeSequence::CONSTANT}) {
        for (int trial = 0; trial < 6; ++trial) {
            std::vector<Key> keys;
            for (int j = 0; j < 7; ++j) keys.push_back({j * 13 + (j > 3 ? 5 : 0), unit()});
            if (trial % 3 == 1) keys[2].value = keys[1].value;  // a held key
            if (trial % 3 == 2) {
                keys[3].value = keys[2].value;
                keys[3].value[0] += 1e-6f;  // nearly equal
                keys[5].value = keys[4].value;
                for (float& c : keys[5].value) c = -c;  // opposite
            }
            auto s = makeSeq(KeyframeSequence::SQUAD, repeat, 100, keys);
            const detail::KeyframeView kept = detail::preparedViewOf(*s);
            std::vector<double> times;
            for (double t = -15.0; t <= 230.0; t += 1.3) times.push_back(t);
            std::vector<float> direct(times.size() * 4), later(times.size() * 4, -7.0f);
            std::vector<detail::SquadSample> deferred;
            std::size_t interior = 0;
            for (std::size_t i = 0; i < times.size(); ++i) {
                int segA = 0, segB = 0;
                const auto a = detail::sampleKeyframes(kept, times[i], std::span(direct.data() + 4 * i, 4), &segA);
                const std::size_t before = deferred.size();
                const auto b = detail::sampleKeyframesDeferringSquad(kept, times[i], std::span(later.data() + 4 * i, 4),
                                                                      &segB, deferred);
                EXPECT_EQ(a.forward, b.forward);
                EXPECT_EQ(a.backward, b.backward);
                EXPECT_EQ(segA, segB);
                if (deferred.size() > before) {
                    ++interior;
                    EXPECT_EQ(later[4 * i], -7.0f) << "a deferred sample was written at once";
                }
            }
            ASSERT_GT(deferred.size(), 9u);
            EXPECT_EQ(deferred.size(), interior);
            detail::sampleSquads(deferred);
            for (std::size_t i = 0; i < times.size(); ++i)
                for (int c = 0; c < 4; ++c) {
#ifdef __FP_FAST_FMAF
                    EXPECT_NEAR(later[4 * i + c], direct[4 * i + c], 1e-6f) << "time " << times[i];
#else
                    EXPECT_EQ(later[4 * i + c], direct[4 * i + c]) << "time " << times[i] << ", component " << c;
#endif
                }
        }
    }
    // Other interpolations defer nothing.
    auto lin = makeSeq(KeyframeSequence::SLERP, KeyframeSequence::LOOP, 70, {{0, zQuat(10)}, {30, zQuat(50)}});
    const detail::KeyframeView view = detail::preparedViewOf(*lin);
    std::vector<detail::SquadSample> deferred;
    float out[4] = {};
    detail::sampleKeyframesDeferringSquad(view, 12.0, out, nullptr, deferred);
    EXPECT_TRUE(deferred.empty());
    EXPECT_NE(out[3], 0.0f);
}
