// PolygonMode (JSR-184 1.1, PolygonMode).
#include <gtest/gtest.h>

#include <m3g/AnimationTrack.h>
#include <m3g/PolygonMode.h>

using namespace m3g;

TEST(PolygonMode, ConstantsMatchSpec) {
    EXPECT_EQ(PolygonMode::CULL_BACK, 160);
    EXPECT_EQ(PolygonMode::CULL_FRONT, 161);
    EXPECT_EQ(PolygonMode::CULL_NONE, 162);
    EXPECT_EQ(PolygonMode::SHADE_FLAT, 164);
    EXPECT_EQ(PolygonMode::SHADE_SMOOTH, 165);
    EXPECT_EQ(PolygonMode::WINDING_CCW, 168);
    EXPECT_EQ(PolygonMode::WINDING_CW, 169);
}

TEST(PolygonMode, Defaults) {
    Ref<PolygonMode> p = make<PolygonMode>();
    EXPECT_EQ(p->getCulling(), PolygonMode::CULL_BACK);
    EXPECT_EQ(p->getShading(), PolygonMode::SHADE_SMOOTH);
    EXPECT_EQ(p->getWinding(), PolygonMode::WINDING_CCW);
    EXPECT_FALSE(p->isTwoSidedLightingEnabled());
    EXPECT_FALSE(p->isLocalCameraLightingEnabled());
    EXPECT_FALSE(p->isPerspectiveCorrectionEnabled());
    EXPECT_EQ(p->getReferences(), 0);
    EXPECT_STREQ(p->getClassName(), "PolygonMode");
}

TEST(PolygonMode, SettersRoundTripAndTouch) {
    Ref<PolygonMode> p = make<PolygonMode>();
    for (int m : {PolygonMode::CULL_FRONT, PolygonMode::CULL_NONE, PolygonMode::CULL_BACK}) {
        const auto rev = p->getRevision();
        p->setCulling(m);
        EXPECT_EQ(p->getCulling(), m);
        EXPECT_GT(p->getRevision(), rev);
    }
    for (int m : {PolygonMode::SHADE_FLAT, PolygonMode::SHADE_SMOOTH}) {
        const auto rev = p->getRevision();
        p->setShading(m);
        EXPECT_EQ(p->getShading(), m);
        EXPECT_GT(p->getRevision(), rev);
    }
    for (int m : {PolygonMode::WINDING_CW, PolygonMode::WINDING_CCW}) {
        const auto rev = p->getRevision();
        p->setWinding(m);
        EXPECT_EQ(p->getWinding(), m);
        EXPECT_GT(p->getRevision(), rev);
    }
    auto rev = p->getRevision();
    p->setTwoSidedLightingEnable(true);
    EXPECT_TRUE(p->isTwoSidedLightingEnabled());
    EXPECT_GT(p->getRevision(), rev);
    rev = p->getRevision();
    p->setLocalCameraLightingEnable(true);
    EXPECT_TRUE(p->isLocalCameraLightingEnabled());
    EXPECT_GT(p->getRevision(), rev);
    rev = p->getRevision();
    p->setPerspectiveCorrectionEnable(true);
    EXPECT_TRUE(p->isPerspectiveCorrectionEnabled());
    EXPECT_GT(p->getRevision(), rev);
    p->setTwoSidedLightingEnable(false);
    EXPECT_FALSE(p->isTwoSidedLightingEnabled());
}

TEST(PolygonMode, Exceptions) {
    Ref<PolygonMode> p = make<PolygonMode>();
    EXPECT_THROW(p->setCulling(159), IllegalArgumentException);
    EXPECT_THROW(p->setCulling(163), IllegalArgumentException);
    EXPECT_THROW(p->setShading(163), IllegalArgumentException);
    EXPECT_THROW(p->setShading(166), IllegalArgumentException);
    EXPECT_THROW(p->setWinding(167), IllegalArgumentException);
    EXPECT_THROW(p->setWinding(170), IllegalArgumentException);
    EXPECT_THROW(p->setCulling(PolygonMode::SHADE_FLAT), IllegalArgumentException);
    EXPECT_EQ(p->getCulling(), PolygonMode::CULL_BACK);
    EXPECT_EQ(p->getShading(), PolygonMode::SHADE_SMOOTH);
    EXPECT_EQ(p->getWinding(), PolygonMode::WINDING_CCW);
}

TEST(PolygonMode, DuplicateCopiesValues) {
    Ref<PolygonMode> p = make<PolygonMode>();
    p->setCulling(PolygonMode::CULL_NONE);
    p->setShading(PolygonMode::SHADE_FLAT);
    p->setWinding(PolygonMode::WINDING_CW);
    p->setTwoSidedLightingEnable(true);
    p->setLocalCameraLightingEnable(true);
    p->setPerspectiveCorrectionEnable(true);
    p->setUserID(3);
    Ref<PolygonMode> d = dynamicCast<PolygonMode>(p->duplicate());
    ASSERT_TRUE(d);
    EXPECT_NE(d.get(), p.get());
    EXPECT_EQ(d->getCulling(), PolygonMode::CULL_NONE);
    EXPECT_EQ(d->getShading(), PolygonMode::SHADE_FLAT);
    EXPECT_EQ(d->getWinding(), PolygonMode::WINDING_CW);
    EXPECT_TRUE(d->isTwoSidedLightingEnabled());
    EXPECT_TRUE(d->isLocalCameraLightingEnabled());
    EXPECT_TRUE(d->isPerspectiveCorrectionEnabled());
    EXPECT_EQ(d->getUserID(), 3);
}

TEST(PolygonMode, NotAnimatable) {
    Ref<PolygonMode> p = make<PolygonMode>();
    for (int prop = AnimationTrack::ALPHA; prop <= AnimationTrack::VISIBILITY; ++prop)
        EXPECT_FALSE(p->isAnimatable(prop)) << prop;
}
