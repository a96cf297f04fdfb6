// Fog (JSR-184 1.1, Fog; its animatable properties per AnimationTrack;
// Object3D.duplicate and animate).
#include <gtest/gtest.h>

#include <cmath>

#include <m3g/AnimationTrack.h>
#include <m3g/Fog.h>

using namespace m3g;

TEST(Fog, ConstantsMatchSpec) {
    EXPECT_EQ(Fog::EXPONENTIAL, 80);
    EXPECT_EQ(Fog::LINEAR, 81);
}

TEST(Fog, Defaults) {
    Ref<Fog> f = make<Fog>();
    EXPECT_EQ(f->getMode(), Fog::LINEAR);
    EXPECT_EQ(f->getColor(), 0x000000);
    EXPECT_EQ(f->getDensity(), 1.0f);
    EXPECT_EQ(f->getNearDistance(), 0.0f);
    EXPECT_EQ(f->getFarDistance(), 1.0f);
    EXPECT_EQ(f->getReferences(), 0);
    EXPECT_STREQ(f->getClassName(), "Fog");
}

TEST(Fog, SettersRoundTripAndTouch) {
    Ref<Fog> f = make<Fog>();
    auto rev = f->getRevision();
    f->setMode(Fog::EXPONENTIAL);
    EXPECT_EQ(f->getMode(), Fog::EXPONENTIAL);
    EXPECT_GT(f->getRevision(), rev);
    f->setMode(Fog::LINEAR);
    EXPECT_EQ(f->getMode(), Fog::LINEAR);

    rev = f->getRevision();
    f->setLinear(10.0f, -5.0f);  // unrestricted, near > far allowed
    EXPECT_EQ(f->getNearDistance(), 10.0f);
    EXPECT_EQ(f->getFarDistance(), -5.0f);
    EXPECT_GT(f->getRevision(), rev);

    rev = f->getRevision();
    f->setDensity(0.25f);
    EXPECT_EQ(f->getDensity(), 0.25f);
    EXPECT_GT(f->getRevision(), rev);
    f->setDensity(0.0f);
    EXPECT_EQ(f->getDensity(), 0.0f);
    f->setDensity(1000.0f);
    EXPECT_EQ(f->getDensity(), 1000.0f);

    rev = f->getRevision();
    f->setColor(static_cast<int>(0xFF123456u));
    EXPECT_EQ(f->getColor(), 0x123456);  // top byte cleared
    EXPECT_GT(f->getRevision(), rev);
}

TEST(Fog, Exceptions) {
    Ref<Fog> f = make<Fog>();
    EXPECT_THROW(f->setMode(79), IllegalArgumentException);
    EXPECT_THROW(f->setMode(82), IllegalArgumentException);
    EXPECT_THROW(f->setDensity(-0.001f), IllegalArgumentException);
    EXPECT_THROW(f->setDensity(std::nanf("")), IllegalArgumentException);
    EXPECT_EQ(f->getMode(), Fog::LINEAR);
    EXPECT_EQ(f->getDensity(), 1.0f);
}

TEST(Fog, DuplicateCopiesValues) {
    Ref<Fog> f = make<Fog>();
    f->setMode(Fog::EXPONENTIAL);
    f->setLinear(2.0f, 20.0f);
    f->setDensity(0.5f);
    f->setColor(0x00A0B0C0);
    f->setUserID(11);
    Ref<Fog> d = dynamicCast<Fog>(f->duplicate());
    ASSERT_TRUE(d);
    EXPECT_NE(d.get(), f.get());
    EXPECT_EQ(d->getMode(), Fog::EXPONENTIAL);
    EXPECT_EQ(d->getNearDistance(), 2.0f);
    EXPECT_EQ(d->getFarDistance(), 20.0f);
    EXPECT_EQ(d->getDensity(), 0.5f);
    EXPECT_EQ(d->getColor(), 0x00A0B0C0);
    EXPECT_EQ(d->getUserID(), 11);
}

TEST(Fog, IsAnimatable) {
    Ref<Fog> f = make<Fog>();
    for (int p : {AnimationTrack::COLOR, AnimationTrack::DENSITY, AnimationTrack::NEAR_DISTANCE,
                  AnimationTrack::FAR_DISTANCE})
        EXPECT_TRUE(f->isAnimatable(p)) << p;
    for (int p : {AnimationTrack::ALPHA, AnimationTrack::CROP, AnimationTrack::INTENSITY, AnimationTrack::TRANSLATION})
        EXPECT_FALSE(f->isAnimatable(p)) << p;
}

TEST(Fog, UpdatePropertyClamps) {
    Ref<Fog> f = make<Fog>();
    auto rev = f->getRevision();
    // 1.2 -> 255, 0.5 -> 127.5 -> 128 = 0x80, -0.3 -> 0.
    const float color[3] = {1.2f, 0.5f, -0.3f};
    f->updateProperty(AnimationTrack::COLOR, color);
    EXPECT_EQ(f->getColor(), 0x00FF8000);
    EXPECT_GT(f->getRevision(), rev);

    const float d1[1] = {-2.0f};
    f->updateProperty(AnimationTrack::DENSITY, d1);
    EXPECT_EQ(f->getDensity(), 0.0f);
    const float d2[1] = {3.5f};
    f->updateProperty(AnimationTrack::DENSITY, d2);
    EXPECT_EQ(f->getDensity(), 3.5f);

    const float n[1] = {-5.0f};
    f->updateProperty(AnimationTrack::NEAR_DISTANCE, n);
    EXPECT_EQ(f->getNearDistance(), -5.0f);
    const float fa[1] = {100.0f};
    f->updateProperty(AnimationTrack::FAR_DISTANCE, fa);
    EXPECT_EQ(f->getFarDistance(), 100.0f);

    const float a[1] = {0.5f};
    EXPECT_THROW(f->updateProperty(AnimationTrack::ALPHA, a), IllegalArgumentException);
}
