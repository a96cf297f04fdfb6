// Light (JSR-184 1.1, Light): defaults, checks, animation clamping.
#include <gtest/gtest.h>

#include <limits>

#include <m3g/AnimationTrack.h>
#include <m3g/Light.h>

using namespace m3g;

TEST(Light, Constants) {
    EXPECT_EQ(Light::AMBIENT, 128);
    EXPECT_EQ(Light::DIRECTIONAL, 129);
    EXPECT_EQ(Light::OMNI, 130);
    EXPECT_EQ(Light::SPOT, 131);
}

TEST(Light, Defaults) {
    Ref<Light> l = make<Light>();
    EXPECT_EQ(l->getMode(), Light::DIRECTIONAL);
    EXPECT_EQ(l->getColor(), 0xFFFFFF);
    EXPECT_EQ(l->getIntensity(), 1.0f);
    EXPECT_EQ(l->getConstantAttenuation(), 1.0f);
    EXPECT_EQ(l->getLinearAttenuation(), 0.0f);
    EXPECT_EQ(l->getQuadraticAttenuation(), 0.0f);
    EXPECT_EQ(l->getSpotAngle(), 45.0f);
    EXPECT_EQ(l->getSpotExponent(), 0.0f);
    EXPECT_STREQ(l->getClassName(), "Light");
}

TEST(Light, SettersRoundTrip) {
    Ref<Light> l = make<Light>();
    for (int m : {Light::AMBIENT, Light::DIRECTIONAL, Light::OMNI, Light::SPOT}) {
        l->setMode(m);
        EXPECT_EQ(l->getMode(), m);
    }
    l->setColor(0x123456);
    EXPECT_EQ(l->getColor(), 0x123456);
    l->setColor(static_cast<int>(0xAB654321u));
    EXPECT_EQ(l->getColor(), 0x654321);  // top byte dropped
    l->setIntensity(-2.5f);
    EXPECT_EQ(l->getIntensity(), -2.5f);
    l->setSpotAngle(0);
    EXPECT_EQ(l->getSpotAngle(), 0.0f);
    l->setSpotAngle(90);
    EXPECT_EQ(l->getSpotAngle(), 90.0f);
    l->setSpotExponent(128);
    EXPECT_EQ(l->getSpotExponent(), 128.0f);
    l->setAttenuation(0, 0.5f, 2);
    EXPECT_EQ(l->getConstantAttenuation(), 0.0f);
    EXPECT_EQ(l->getLinearAttenuation(), 0.5f);
    EXPECT_EQ(l->getQuadraticAttenuation(), 2.0f);
}

TEST(Light, ArgumentChecks) {
    Ref<Light> l = make<Light>();
    EXPECT_THROW(l->setMode(127), IllegalArgumentException);
    EXPECT_THROW(l->setMode(132), IllegalArgumentException);
    EXPECT_THROW(l->setSpotAngle(-0.1f), IllegalArgumentException);
    EXPECT_THROW(l->setSpotAngle(90.1f), IllegalArgumentException);
    EXPECT_THROW(l->setSpotExponent(-1), IllegalArgumentException);
    EXPECT_THROW(l->setSpotExponent(128.5f), IllegalArgumentException);
    EXPECT_THROW(l->setAttenuation(-1, 0, 0), IllegalArgumentException);
    EXPECT_THROW(l->setAttenuation(1, -1, 0), IllegalArgumentException);
    EXPECT_THROW(l->setAttenuation(1, 0, -1), IllegalArgumentException);
    EXPECT_THROW(l->setAttenuation(0, 0, 0), IllegalArgumentException);
    // Failed calls leave the values alone.
    EXPECT_EQ(l->getMode(), Light::DIRECTIONAL);
    EXPECT_EQ(l->getSpotAngle(), 45.0f);
    EXPECT_EQ(l->getConstantAttenuation(), 1.0f);
}

TEST(Light, SettersTouch) {
    Ref<Light> l = make<Light>();
    auto r = l->getRevision();
    l->setIntensity(2);
    EXPECT_GT(l->getRevision(), r);
    r = l->getRevision();
    l->setColor(0);
    EXPECT_GT(l->getRevision(), r);
}

TEST(Light, Animatable) {
    Ref<Light> l = make<Light>();
    EXPECT_TRUE(l->isAnimatable(AnimationTrack::COLOR));
    EXPECT_TRUE(l->isAnimatable(AnimationTrack::INTENSITY));
    EXPECT_TRUE(l->isAnimatable(AnimationTrack::SPOT_ANGLE));
    EXPECT_TRUE(l->isAnimatable(AnimationTrack::SPOT_EXPONENT));
    EXPECT_TRUE(l->isAnimatable(AnimationTrack::VISIBILITY));
    EXPECT_TRUE(l->isAnimatable(AnimationTrack::ORIENTATION));
    EXPECT_FALSE(l->isAnimatable(AnimationTrack::FIELD_OF_VIEW));
    EXPECT_FALSE(l->isAnimatable(AnimationTrack::DENSITY));
    EXPECT_FALSE(l->isAnimatable(AnimationTrack::DIFFUSE_COLOR));
}

TEST(Light, UpdatePropertyClamps) {
    Ref<Light> l = make<Light>();
    const float color[3] = {1.0f, 0.5f, 0.0f};  // 255, round(127.5) = 128, 0
    l->updateProperty(AnimationTrack::COLOR, color);
    EXPECT_EQ(l->getColor(), 0xFF8000);
    const float color2[3] = {2.0f, -1.0f, 0.2f};  // clamped; 0.2*255 = 51
    l->updateProperty(AnimationTrack::COLOR, color2);
    EXPECT_EQ(l->getColor(), 0xFF0033);
    float v = -3;
    l->updateProperty(AnimationTrack::INTENSITY, std::span<const float>(&v, 1));
    EXPECT_EQ(l->getIntensity(), -3.0f);
    v = 120;
    l->updateProperty(AnimationTrack::SPOT_ANGLE, std::span<const float>(&v, 1));
    EXPECT_EQ(l->getSpotAngle(), 90.0f);
    v = -4;
    l->updateProperty(AnimationTrack::SPOT_ANGLE, std::span<const float>(&v, 1));
    EXPECT_EQ(l->getSpotAngle(), 0.0f);
    v = 200;
    l->updateProperty(AnimationTrack::SPOT_EXPONENT, std::span<const float>(&v, 1));
    EXPECT_EQ(l->getSpotExponent(), 128.0f);
    v = -1;
    l->updateProperty(AnimationTrack::SPOT_EXPONENT, std::span<const float>(&v, 1));
    EXPECT_EQ(l->getSpotExponent(), 0.0f);
    v = 0.25f;
    l->updateProperty(AnimationTrack::ALPHA, std::span<const float>(&v, 1));  // Node property
    EXPECT_EQ(l->getAlphaFactor(), 0.25f);
}

TEST(Light, DuplicateCopiesEverything) {
    Ref<Light> l = make<Light>();
    l->setMode(Light::SPOT);
    l->setColor(0x102030);
    l->setIntensity(3);
    l->setSpotAngle(30);
    l->setSpotExponent(5);
    l->setAttenuation(0, 1, 2);
    Ref<Light> d = dynamicCast<Light>(l->duplicate());
    ASSERT_TRUE(d);
    EXPECT_NE(d.get(), l.get());
    EXPECT_EQ(d->getMode(), Light::SPOT);
    EXPECT_EQ(d->getColor(), 0x102030);
    EXPECT_EQ(d->getIntensity(), 3.0f);
    EXPECT_EQ(d->getSpotAngle(), 30.0f);
    EXPECT_EQ(d->getSpotExponent(), 5.0f);
    EXPECT_EQ(d->getConstantAttenuation(), 0.0f);
    EXPECT_EQ(d->getLinearAttenuation(), 1.0f);
    EXPECT_EQ(d->getQuadraticAttenuation(), 2.0f);
}

TEST(Light, AnimatedNaNColorChannelBecomesZero) {
    // The shared color conversion maps NaN to 0 (lround(NaN) was undefined).
    Ref<Light> l = make<Light>();
    const float v[] = {std::numeric_limits<float>::quiet_NaN(), 1.0f, 0.5f};
    l->updateProperty(AnimationTrack::COLOR, v);
    EXPECT_EQ(l->getColor(), 0x00FF80);  // 0.5 * 255 = 127.5 rounds up to 128
}
