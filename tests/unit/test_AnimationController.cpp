// AnimationController (JSR-184 1.1, AnimationController): interval, speed re-basing,
// position mapping, weight.
#include <gtest/gtest.h>

#include <m3g/AnimationController.h>

using namespace m3g;

TEST(AnimationController, Defaults) {
    Ref<AnimationController> c = make<AnimationController>();
    EXPECT_EQ(c->getActiveIntervalStart(), 0);
    EXPECT_EQ(c->getActiveIntervalEnd(), 0);
    EXPECT_EQ(c->getSpeed(), 1.0f);
    EXPECT_EQ(c->getWeight(), 1.0f);
    EXPECT_EQ(c->getRefWorldTime(), 0);
    EXPECT_EQ(c->getPosition(0), 0.0f);
    EXPECT_EQ(c->getPosition(1000), 1000.0f);
    EXPECT_EQ(c->getPosition(-250), -250.0f);
    EXPECT_STREQ(c->getClassName(), "AnimationController");
}

TEST(AnimationController, ActiveInterval) {
    Ref<AnimationController> c = make<AnimationController>();
    EXPECT_TRUE(c->isActive(-100000));  // [0, 0]: always
    EXPECT_TRUE(c->isActive(123456));
    c->setActiveInterval(10, 20);
    EXPECT_EQ(c->getActiveIntervalStart(), 10);
    EXPECT_EQ(c->getActiveIntervalEnd(), 20);
    EXPECT_FALSE(c->isActive(9));
    EXPECT_TRUE(c->isActive(10));
    EXPECT_TRUE(c->isActive(19));
    EXPECT_FALSE(c->isActive(20));
    c->setActiveInterval(5, 5);  // start == end: always
    EXPECT_TRUE(c->isActive(0));
    EXPECT_TRUE(c->isActive(5));
    EXPECT_TRUE(c->isActive(100));
    EXPECT_THROW(c->setActiveInterval(21, 20), IllegalArgumentException);
    EXPECT_EQ(c->getActiveIntervalStart(), 5);
}

TEST(AnimationController, PositionAndRebasing) {
    Ref<AnimationController> c = make<AnimationController>();
    c->setPosition(5, 100);
    EXPECT_EQ(c->getRefWorldTime(), 100);
    EXPECT_FLOAT_EQ(c->getPosition(100), 5);
    EXPECT_FLOAT_EQ(c->getPosition(110), 15);
    EXPECT_FLOAT_EQ(c->getPosition(90), -5);
    // At 200 the position is 105; it stays continuous there.
    c->setSpeed(2, 200);
    EXPECT_EQ(c->getSpeed(), 2.0f);
    EXPECT_EQ(c->getRefWorldTime(), 200);
    EXPECT_FLOAT_EQ(c->getPosition(200), 105);
    EXPECT_FLOAT_EQ(c->getPosition(210), 125);
    // Negative speed: plays backwards from 125 at 210.
    c->setSpeed(-0.5f, 210);
    EXPECT_FLOAT_EQ(c->getPosition(210), 125);
    EXPECT_FLOAT_EQ(c->getPosition(230), 115);
    // Zero speed freezes.
    c->setSpeed(0, 230);
    EXPECT_FLOAT_EQ(c->getPosition(100000), 115);
}

TEST(AnimationController, LargeWorldTimesDoNotOverflow) {
    Ref<AnimationController> c = make<AnimationController>();
    c->setPosition(0, -2000000000);
    EXPECT_FLOAT_EQ(c->getPosition(2000000000), 4.0e9f);
}

TEST(AnimationController, Weight) {
    Ref<AnimationController> c = make<AnimationController>();
    c->setWeight(0);
    EXPECT_EQ(c->getWeight(), 0.0f);
    c->setWeight(2.5f);
    EXPECT_EQ(c->getWeight(), 2.5f);
    EXPECT_THROW(c->setWeight(-0.001f), IllegalArgumentException);
    EXPECT_EQ(c->getWeight(), 2.5f);
}

TEST(AnimationController, MutatorsTouch) {
    Ref<AnimationController> c = make<AnimationController>();
    auto r = c->getRevision();
    c->setSpeed(2, 0);
    EXPECT_GT(c->getRevision(), r);
    r = c->getRevision();
    c->setPosition(1, 1);
    EXPECT_GT(c->getRevision(), r);
    r = c->getRevision();
    c->setWeight(1);
    EXPECT_GT(c->getRevision(), r);
    r = c->getRevision();
    c->setActiveInterval(0, 1);
    EXPECT_GT(c->getRevision(), r);
}

TEST(AnimationController, DuplicateCopiesState) {
    Ref<AnimationController> c = make<AnimationController>();
    c->setActiveInterval(1, 9);
    c->setPosition(3, 40);
    c->setSpeed(2, 50);
    c->setWeight(0.5f);
    Ref<AnimationController> d = dynamicCast<AnimationController>(c->duplicate());
    ASSERT_TRUE(d);
    EXPECT_NE(d.get(), c.get());
    EXPECT_EQ(d->getActiveIntervalStart(), 1);
    EXPECT_EQ(d->getActiveIntervalEnd(), 9);
    EXPECT_EQ(d->getSpeed(), 2.0f);
    EXPECT_EQ(d->getWeight(), 0.5f);
    EXPECT_EQ(d->getRefWorldTime(), 50);
    EXPECT_FLOAT_EQ(d->getPosition(60), 33);  // 13 at 50, +2*10
}
