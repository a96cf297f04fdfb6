// Material (JSR-184 1.1, Material; its animatable properties per
// AnimationTrack; Object3D.duplicate and animate).
#include <gtest/gtest.h>

#include <cmath>

#include <m3g/AnimationTrack.h>
#include <m3g/Material.h>

using namespace m3g;

namespace {
constexpr int argb(unsigned v) { return static_cast<int>(v); }
}

TEST(Material, ConstantsMatchSpec) {
    EXPECT_EQ(Material::AMBIENT, 1024);
    EXPECT_EQ(Material::DIFFUSE, 2048);
    EXPECT_EQ(Material::EMISSIVE, 4096);
    EXPECT_EQ(Material::SPECULAR, 8192);
}

TEST(Material, Defaults) {
    Ref<Material> m = make<Material>();
    EXPECT_EQ(m->getColor(Material::AMBIENT), 0x00333333);
    EXPECT_EQ(m->getColor(Material::DIFFUSE), argb(0xFFCCCCCCu));
    EXPECT_EQ(m->getColor(Material::EMISSIVE), 0x00000000);
    EXPECT_EQ(m->getColor(Material::SPECULAR), 0x00000000);
    EXPECT_EQ(m->getShininess(), 0.0f);
    EXPECT_FALSE(m->isVertexColorTrackingEnabled());
    EXPECT_EQ(m->getReferences(), 0);
    EXPECT_STREQ(m->getClassName(), "Material");
}

TEST(Material, SetColorSingleTargets) {
    Ref<Material> m = make<Material>();
    auto rev = m->getRevision();
    m->setColor(Material::DIFFUSE, argb(0x80112233u));
    EXPECT_GT(m->getRevision(), rev);
    EXPECT_EQ(m->getColor(Material::DIFFUSE), argb(0x80112233u));  // diffuse keeps alpha
    m->setColor(Material::AMBIENT, argb(0xFF445566u));
    EXPECT_EQ(m->getColor(Material::AMBIENT), 0x00445566);  // others drop it
    m->setColor(Material::EMISSIVE, argb(0x12ABCDEFu));
    EXPECT_EQ(m->getColor(Material::EMISSIVE), 0x00ABCDEF);
    m->setColor(Material::SPECULAR, 0x00010203);
    EXPECT_EQ(m->getColor(Material::SPECULAR), 0x00010203);
    EXPECT_EQ(m->getColor(Material::DIFFUSE), argb(0x80112233u));
}

TEST(Material, SetColorOredTargets) {
    Ref<Material> m = make<Material>();
    m->setColor(Material::AMBIENT | Material::SPECULAR, argb(0x80112233u));
    EXPECT_EQ(m->getColor(Material::AMBIENT), 0x00112233);
    EXPECT_EQ(m->getColor(Material::SPECULAR), 0x00112233);
    EXPECT_EQ(m->getColor(Material::DIFFUSE), argb(0xFFCCCCCCu));
    EXPECT_EQ(m->getColor(Material::EMISSIVE), 0);
    m->setColor(Material::AMBIENT | Material::DIFFUSE | Material::EMISSIVE | Material::SPECULAR, argb(0x7F010203u));
    EXPECT_EQ(m->getColor(Material::AMBIENT), 0x00010203);
    EXPECT_EQ(m->getColor(Material::DIFFUSE), 0x7F010203);
    EXPECT_EQ(m->getColor(Material::EMISSIVE), 0x00010203);
    EXPECT_EQ(m->getColor(Material::SPECULAR), 0x00010203);
}

TEST(Material, ColorTargetExceptions) {
    Ref<Material> m = make<Material>();
    EXPECT_THROW(m->setColor(0, 0), IllegalArgumentException);
    EXPECT_THROW(m->setColor(1, 0), IllegalArgumentException);
    EXPECT_THROW(m->setColor(Material::AMBIENT | 1, 0), IllegalArgumentException);
    EXPECT_THROW(m->setColor(16384, 0), IllegalArgumentException);
    EXPECT_EQ(m->getColor(Material::AMBIENT), 0x00333333);  // unchanged
    EXPECT_THROW(m->getColor(0), IllegalArgumentException);
    EXPECT_THROW(m->getColor(Material::AMBIENT | Material::DIFFUSE), IllegalArgumentException);
    EXPECT_THROW(m->getColor(512), IllegalArgumentException);
}

TEST(Material, Shininess) {
    Ref<Material> m = make<Material>();
    auto rev = m->getRevision();
    m->setShininess(64.5f);
    EXPECT_EQ(m->getShininess(), 64.5f);
    EXPECT_GT(m->getRevision(), rev);
    m->setShininess(128.0f);
    EXPECT_EQ(m->getShininess(), 128.0f);
    m->setShininess(0.0f);
    EXPECT_EQ(m->getShininess(), 0.0f);
    EXPECT_THROW(m->setShininess(-0.001f), IllegalArgumentException);
    EXPECT_THROW(m->setShininess(128.01f), IllegalArgumentException);
    EXPECT_THROW(m->setShininess(std::nanf("")), IllegalArgumentException);
    EXPECT_EQ(m->getShininess(), 0.0f);
}

TEST(Material, VertexColorTracking) {
    Ref<Material> m = make<Material>();
    const auto rev = m->getRevision();
    m->setVertexColorTrackingEnable(true);
    EXPECT_TRUE(m->isVertexColorTrackingEnabled());
    EXPECT_GT(m->getRevision(), rev);
    m->setVertexColorTrackingEnable(false);
    EXPECT_FALSE(m->isVertexColorTrackingEnabled());
}

TEST(Material, DuplicateCopiesValues) {
    Ref<Material> m = make<Material>();
    m->setColor(Material::AMBIENT, 0x010203);
    m->setColor(Material::DIFFUSE, argb(0x40050607u));
    m->setColor(Material::EMISSIVE, 0x080910);
    m->setColor(Material::SPECULAR, 0x111213);
    m->setShininess(12.0f);
    m->setVertexColorTrackingEnable(true);
    m->setUserID(5);
    Ref<Material> d = dynamicCast<Material>(m->duplicate());
    ASSERT_TRUE(d);
    EXPECT_NE(d.get(), m.get());
    EXPECT_EQ(d->getColor(Material::AMBIENT), 0x010203);
    EXPECT_EQ(d->getColor(Material::DIFFUSE), argb(0x40050607u));
    EXPECT_EQ(d->getColor(Material::EMISSIVE), 0x080910);
    EXPECT_EQ(d->getColor(Material::SPECULAR), 0x111213);
    EXPECT_EQ(d->getShininess(), 12.0f);
    EXPECT_TRUE(d->isVertexColorTrackingEnabled());
    EXPECT_EQ(d->getUserID(), 5);
}

TEST(Material, IsAnimatable) {
    Ref<Material> m = make<Material>();
    for (int p : {AnimationTrack::ALPHA, AnimationTrack::AMBIENT_COLOR, AnimationTrack::DIFFUSE_COLOR,
                  AnimationTrack::EMISSIVE_COLOR, AnimationTrack::SPECULAR_COLOR, AnimationTrack::SHININESS})
        EXPECT_TRUE(m->isAnimatable(p)) << p;
    for (int p : {AnimationTrack::COLOR, AnimationTrack::CROP, AnimationTrack::DENSITY, AnimationTrack::TRANSLATION,
                  AnimationTrack::VISIBILITY})
        EXPECT_FALSE(m->isAnimatable(p)) << p;
}

TEST(Material, UpdatePropertyClampsAndRounds) {
    Ref<Material> m = make<Material>();
    auto rev = m->getRevision();
    // ALPHA: diffuse alpha only; 0.5 * 255 = 127.5 -> 128 = 0x80.
    const float half[1] = {0.5f};
    m->updateProperty(AnimationTrack::ALPHA, half);
    EXPECT_GT(m->getRevision(), rev);
    EXPECT_EQ(m->getColor(Material::DIFFUSE), argb(0x80CCCCCCu));
    const float neg[1] = {-1.0f};
    m->updateProperty(AnimationTrack::ALPHA, neg);
    EXPECT_EQ(m->getColor(Material::DIFFUSE), 0x00CCCCCC);
    const float big[1] = {3.0f};
    m->updateProperty(AnimationTrack::ALPHA, big);
    EXPECT_EQ(m->getColor(Material::DIFFUSE), argb(0xFFCCCCCCu));

    // DIFFUSE_COLOR: RGB only, alpha kept. 1.5 -> 255, 0.2 -> 51 = 0x33, -1 -> 0.
    m->updateProperty(AnimationTrack::ALPHA, half);
    const float diffuse[3] = {1.5f, 0.2f, -1.0f};
    m->updateProperty(AnimationTrack::DIFFUSE_COLOR, diffuse);
    EXPECT_EQ(m->getColor(Material::DIFFUSE), argb(0x80FF3300u));

    // 0.1 * 255 = 25.5 -> 26 = 0x1A; 0.9 * 255 = 229.5 -> 230 = 0xE6; 1/255 -> 1.
    const float amb[3] = {0.1f, 0.9f, 1.0f / 255.0f};
    m->updateProperty(AnimationTrack::AMBIENT_COLOR, amb);
    EXPECT_EQ(m->getColor(Material::AMBIENT), 0x001AE601);
    const float em[3] = {0.0f, 1.0f, 2.0f};
    m->updateProperty(AnimationTrack::EMISSIVE_COLOR, em);
    EXPECT_EQ(m->getColor(Material::EMISSIVE), 0x0000FFFF);
    const float sp[3] = {-0.2f, 0.5f, 0.0f};
    m->updateProperty(AnimationTrack::SPECULAR_COLOR, sp);
    EXPECT_EQ(m->getColor(Material::SPECULAR), 0x00008000);

    const float s1[1] = {200.0f};
    m->updateProperty(AnimationTrack::SHININESS, s1);
    EXPECT_EQ(m->getShininess(), 128.0f);
    const float s2[1] = {-3.0f};
    m->updateProperty(AnimationTrack::SHININESS, s2);
    EXPECT_EQ(m->getShininess(), 0.0f);
    const float s3[1] = {17.25f};
    m->updateProperty(AnimationTrack::SHININESS, s3);
    EXPECT_EQ(m->getShininess(), 17.25f);

    const float c[3] = {1, 1, 1};
    EXPECT_THROW(m->updateProperty(AnimationTrack::COLOR, c), IllegalArgumentException);
}
