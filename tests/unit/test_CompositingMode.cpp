// CompositingMode (JSR-184 1.1, CompositingMode).
#include <gtest/gtest.h>

#include <cmath>

#include <m3g/AnimationTrack.h>
#include <m3g/CompositingMode.h>

using namespace m3g;

TEST(CompositingMode, ConstantsMatchSpec) {
    EXPECT_EQ(CompositingMode::ALPHA, 64);
    EXPECT_EQ(CompositingMode::ALPHA_ADD, 65);
    EXPECT_EQ(CompositingMode::MODULATE, 66);
    EXPECT_EQ(CompositingMode::MODULATE_X2, 67);
    EXPECT_EQ(CompositingMode::REPLACE, 68);
}

TEST(CompositingMode, Defaults) {
    Ref<CompositingMode> c = make<CompositingMode>();
    EXPECT_EQ(c->getBlending(), CompositingMode::REPLACE);
    EXPECT_EQ(c->getAlphaThreshold(), 0.0f);
    EXPECT_TRUE(c->isDepthTestEnabled());
    EXPECT_TRUE(c->isDepthWriteEnabled());
    EXPECT_TRUE(c->isColorWriteEnabled());
    EXPECT_TRUE(c->isAlphaWriteEnabled());
    EXPECT_EQ(c->getDepthOffsetFactor(), 0.0f);
    EXPECT_EQ(c->getDepthOffsetUnits(), 0.0f);
    EXPECT_EQ(c->getReferences(), 0);
    EXPECT_STREQ(c->getClassName(), "CompositingMode");
}

TEST(CompositingMode, SettersRoundTripAndTouch) {
    Ref<CompositingMode> c = make<CompositingMode>();
    for (int m : {CompositingMode::ALPHA, CompositingMode::ALPHA_ADD, CompositingMode::MODULATE,
                  CompositingMode::MODULATE_X2, CompositingMode::REPLACE}) {
        const auto rev = c->getRevision();
        c->setBlending(m);
        EXPECT_EQ(c->getBlending(), m);
        EXPECT_GT(c->getRevision(), rev);
    }
    auto rev = c->getRevision();
    c->setAlphaThreshold(0.25f);
    EXPECT_EQ(c->getAlphaThreshold(), 0.25f);
    EXPECT_GT(c->getRevision(), rev);
    c->setAlphaThreshold(1.0f);
    EXPECT_EQ(c->getAlphaThreshold(), 1.0f);

    rev = c->getRevision();
    c->setDepthTestEnable(false);
    EXPECT_FALSE(c->isDepthTestEnabled());
    EXPECT_GT(c->getRevision(), rev);
    rev = c->getRevision();
    c->setDepthWriteEnable(false);
    EXPECT_FALSE(c->isDepthWriteEnabled());
    EXPECT_GT(c->getRevision(), rev);
    rev = c->getRevision();
    c->setColorWriteEnable(false);
    EXPECT_FALSE(c->isColorWriteEnabled());
    EXPECT_GT(c->getRevision(), rev);
    rev = c->getRevision();
    c->setAlphaWriteEnable(false);
    EXPECT_FALSE(c->isAlphaWriteEnabled());
    EXPECT_GT(c->getRevision(), rev);
    c->setDepthTestEnable(true);
    EXPECT_TRUE(c->isDepthTestEnabled());

    rev = c->getRevision();
    c->setDepthOffset(-2.5f, 100.0f);  // unrestricted
    EXPECT_EQ(c->getDepthOffsetFactor(), -2.5f);
    EXPECT_EQ(c->getDepthOffsetUnits(), 100.0f);
    EXPECT_GT(c->getRevision(), rev);
}

TEST(CompositingMode, Exceptions) {
    Ref<CompositingMode> c = make<CompositingMode>();
    EXPECT_THROW(c->setBlending(63), IllegalArgumentException);
    EXPECT_THROW(c->setBlending(69), IllegalArgumentException);
    EXPECT_THROW(c->setAlphaThreshold(-0.01f), IllegalArgumentException);
    EXPECT_THROW(c->setAlphaThreshold(1.01f), IllegalArgumentException);
    EXPECT_THROW(c->setAlphaThreshold(std::nanf("")), IllegalArgumentException);
    EXPECT_EQ(c->getBlending(), CompositingMode::REPLACE);
    EXPECT_EQ(c->getAlphaThreshold(), 0.0f);
}

TEST(CompositingMode, DuplicateCopiesValues) {
    Ref<CompositingMode> c = make<CompositingMode>();
    c->setBlending(CompositingMode::ALPHA_ADD);
    c->setAlphaThreshold(0.5f);
    c->setDepthTestEnable(false);
    c->setDepthWriteEnable(false);
    c->setColorWriteEnable(false);
    c->setAlphaWriteEnable(false);
    c->setDepthOffset(1.5f, 3.0f);
    c->setUserID(9);
    Ref<CompositingMode> d = dynamicCast<CompositingMode>(c->duplicate());
    ASSERT_TRUE(d);
    EXPECT_NE(d.get(), c.get());
    EXPECT_EQ(d->getBlending(), CompositingMode::ALPHA_ADD);
    EXPECT_EQ(d->getAlphaThreshold(), 0.5f);
    EXPECT_FALSE(d->isDepthTestEnabled());
    EXPECT_FALSE(d->isDepthWriteEnabled());
    EXPECT_FALSE(d->isColorWriteEnabled());
    EXPECT_FALSE(d->isAlphaWriteEnabled());
    EXPECT_EQ(d->getDepthOffsetFactor(), 1.5f);
    EXPECT_EQ(d->getDepthOffsetUnits(), 3.0f);
    EXPECT_EQ(d->getUserID(), 9);
    d->setBlending(CompositingMode::MODULATE);
    EXPECT_EQ(c->getBlending(), CompositingMode::ALPHA_ADD);
}

TEST(CompositingMode, NotAnimatable) {
    Ref<CompositingMode> c = make<CompositingMode>();
    for (int p = AnimationTrack::ALPHA; p <= AnimationTrack::VISIBILITY; ++p) EXPECT_FALSE(c->isAnimatable(p)) << p;
    const float v[1] = {0.5f};
    EXPECT_THROW(c->updateProperty(AnimationTrack::ALPHA, v), IllegalArgumentException);
}
