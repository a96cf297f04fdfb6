// Background (JSR-184 1.1, Background; its animatable properties per
// AnimationTrack; Object3D.duplicate and animate).
#include <gtest/gtest.h>

#include <vector>

#include <m3g/AnimationTrack.h>
#include <m3g/Background.h>
#include <m3g/Image2D.h>
#include <m3g/Limits.h>

using namespace m3g;

TEST(Background, ConstantsMatchSpec) {
    EXPECT_EQ(Background::BORDER, 32);
    EXPECT_EQ(Background::REPEAT, 33);
}

TEST(Background, Defaults) {
    Ref<Background> b = make<Background>();
    EXPECT_EQ(b->getColor(), 0x00000000);
    EXPECT_EQ(b->getImage(), nullptr);
    EXPECT_EQ(b->getImageModeX(), Background::BORDER);
    EXPECT_EQ(b->getImageModeY(), Background::BORDER);
    EXPECT_EQ(b->getCropX(), 0);
    EXPECT_EQ(b->getCropY(), 0);
    EXPECT_EQ(b->getCropWidth(), 0);
    EXPECT_EQ(b->getCropHeight(), 0);
    EXPECT_TRUE(b->isColorClearEnabled());
    EXPECT_TRUE(b->isDepthClearEnabled());
    EXPECT_EQ(b->getReferences(), 0);
    EXPECT_STREQ(b->getClassName(), "Background");
}

TEST(Background, ColorAndClearFlags) {
    Ref<Background> b = make<Background>();
    auto rev = b->getRevision();
    b->setColor(static_cast<int>(0x80FF4020u));
    EXPECT_EQ(b->getColor(), static_cast<int>(0x80FF4020u));  // full ARGB kept
    EXPECT_GT(b->getRevision(), rev);
    rev = b->getRevision();
    b->setColorClearEnable(false);
    EXPECT_FALSE(b->isColorClearEnabled());
    EXPECT_GT(b->getRevision(), rev);
    rev = b->getRevision();
    b->setDepthClearEnable(false);
    EXPECT_FALSE(b->isDepthClearEnabled());
    EXPECT_GT(b->getRevision(), rev);
    b->setColorClearEnable(true);
    EXPECT_TRUE(b->isColorClearEnabled());
}

TEST(Background, ImageResetsCrop) {
    Ref<Background> b = make<Background>();
    b->setCrop(5, 6, 7, 8);
    Ref<Image2D> rgb = make<Image2D>(Image2D::RGB, 30, 20);  // any size, not power of two
    auto rev = b->getRevision();
    b->setImage(rgb);
    EXPECT_GT(b->getRevision(), rev);
    EXPECT_EQ(b->getImage().get(), rgb.get());
    EXPECT_EQ(b->getCropX(), 0);
    EXPECT_EQ(b->getCropY(), 0);
    EXPECT_EQ(b->getCropWidth(), 30);
    EXPECT_EQ(b->getCropHeight(), 20);

    Ref<Image2D> rgba = make<Image2D>(Image2D::RGBA, 3, 5);
    b->setImage(rgba);
    EXPECT_EQ(b->getImage().get(), rgba.get());
    EXPECT_EQ(b->getCropWidth(), 3);
    EXPECT_EQ(b->getCropHeight(), 5);

    // Null removes the image and leaves the crop alone.
    b->setCrop(1, 2, 3, 4);
    b->setImage(nullptr);
    EXPECT_EQ(b->getImage(), nullptr);
    EXPECT_EQ(b->getCropX(), 1);
    EXPECT_EQ(b->getCropHeight(), 4);
}

TEST(Background, ImageFormatExceptions) {
    Ref<Background> b = make<Background>();
    Ref<Image2D> rgb = make<Image2D>(Image2D::RGB, 2, 2);
    b->setImage(rgb);
    for (int f : {Image2D::ALPHA, Image2D::LUMINANCE, Image2D::LUMINANCE_ALPHA}) {
        Ref<Image2D> bad = make<Image2D>(f, 4, 4);
        EXPECT_THROW(b->setImage(bad), IllegalArgumentException) << f;
    }
    EXPECT_EQ(b->getImage().get(), rgb.get());
    EXPECT_EQ(b->getCropWidth(), 2);
}

TEST(Background, ImageMode) {
    Ref<Background> b = make<Background>();
    auto rev = b->getRevision();
    b->setImageMode(Background::REPEAT, Background::BORDER);
    EXPECT_GT(b->getRevision(), rev);
    EXPECT_EQ(b->getImageModeX(), Background::REPEAT);
    EXPECT_EQ(b->getImageModeY(), Background::BORDER);
    b->setImageMode(Background::BORDER, Background::REPEAT);
    EXPECT_EQ(b->getImageModeX(), Background::BORDER);
    EXPECT_EQ(b->getImageModeY(), Background::REPEAT);
    EXPECT_THROW(b->setImageMode(31, Background::BORDER), IllegalArgumentException);
    EXPECT_THROW(b->setImageMode(Background::BORDER, 34), IllegalArgumentException);
    EXPECT_EQ(b->getImageModeY(), Background::REPEAT);
}

TEST(Background, Crop) {
    Ref<Background> b = make<Background>();
    auto rev = b->getRevision();
    b->setCrop(-10, -20, 30, 40);  // x, y unrestricted
    EXPECT_GT(b->getRevision(), rev);
    EXPECT_EQ(b->getCropX(), -10);
    EXPECT_EQ(b->getCropY(), -20);
    EXPECT_EQ(b->getCropWidth(), 30);
    EXPECT_EQ(b->getCropHeight(), 40);
    b->setCrop(0, 0, 0, 0);
    EXPECT_EQ(b->getCropWidth(), 0);
    const int maxDim = getLimits().maxViewportDimension;
    EXPECT_NO_THROW(b->setCrop(0, 0, maxDim, maxDim));
    EXPECT_THROW(b->setCrop(0, 0, -1, 1), IllegalArgumentException);
    EXPECT_THROW(b->setCrop(0, 0, 1, -1), IllegalArgumentException);
    EXPECT_THROW(b->setCrop(0, 0, maxDim + 1, 1), IllegalArgumentException);
    EXPECT_THROW(b->setCrop(0, 0, 1, maxDim + 1), IllegalArgumentException);
    EXPECT_EQ(b->getCropWidth(), maxDim);
}

TEST(Background, ReferencesAndDuplicate) {
    Ref<Background> b = make<Background>();
    Ref<Image2D> img = make<Image2D>(Image2D::RGBA, 8, 4);
    b->setImage(img);
    std::vector<Ref<Object3D>> refs(1);
    ASSERT_EQ(b->getReferences(refs), 1);
    EXPECT_EQ(refs[0].get(), img.get());

    b->setColor(0x11223344);
    b->setImageMode(Background::REPEAT, Background::REPEAT);
    b->setCrop(1, 2, 3, 4);
    b->setColorClearEnable(false);
    b->setDepthClearEnable(false);
    b->setUserID(99);
    Ref<Background> d = dynamicCast<Background>(b->duplicate());
    ASSERT_TRUE(d);
    EXPECT_NE(d.get(), b.get());
    EXPECT_EQ(d->getImage().get(), img.get());  // shared
    EXPECT_EQ(d->getColor(), 0x11223344);
    EXPECT_EQ(d->getImageModeX(), Background::REPEAT);
    EXPECT_EQ(d->getImageModeY(), Background::REPEAT);
    EXPECT_EQ(d->getCropX(), 1);
    EXPECT_EQ(d->getCropY(), 2);
    EXPECT_EQ(d->getCropWidth(), 3);
    EXPECT_EQ(d->getCropHeight(), 4);
    EXPECT_FALSE(d->isColorClearEnabled());
    EXPECT_FALSE(d->isDepthClearEnabled());
    EXPECT_EQ(d->getUserID(), 99);
}

TEST(Background, IsAnimatable) {
    Ref<Background> b = make<Background>();
    for (int p : {AnimationTrack::ALPHA, AnimationTrack::COLOR, AnimationTrack::CROP}) EXPECT_TRUE(b->isAnimatable(p));
    for (int p : {AnimationTrack::DENSITY, AnimationTrack::TRANSLATION, AnimationTrack::DIFFUSE_COLOR,
                  AnimationTrack::VISIBILITY})
        EXPECT_FALSE(b->isAnimatable(p)) << p;
}

TEST(Background, UpdatePropertyColorAndAlpha) {
    Ref<Background> b = make<Background>();
    b->setColor(0x11223344);
    auto rev = b->getRevision();
    // ALPHA replaces the top byte only: 0.5 -> 128 = 0x80.
    const float a[1] = {0.5f};
    b->updateProperty(AnimationTrack::ALPHA, a);
    EXPECT_GT(b->getRevision(), rev);
    EXPECT_EQ(b->getColor(), static_cast<int>(0x80223344u));
    const float a2[1] = {7.0f};
    b->updateProperty(AnimationTrack::ALPHA, a2);
    EXPECT_EQ(b->getColor(), static_cast<int>(0xFF223344u));
    // COLOR replaces RGB and keeps alpha: (2, 0.2, -1) -> FF 33 00.
    const float c[3] = {2.0f, 0.2f, -1.0f};
    b->updateProperty(AnimationTrack::COLOR, c);
    EXPECT_EQ(b->getColor(), static_cast<int>(0xFFFF3300u));
}

TEST(Background, UpdatePropertyCrop) {
    Ref<Background> b = make<Background>();
    b->setCrop(0, 0, 10, 20);
    // Two components: x, y only (rounded, halves up: -2.6 -> -3, 1.4 -> 1).
    const float xy[2] = {1.4f, -2.6f};
    b->updateProperty(AnimationTrack::CROP, xy);
    EXPECT_EQ(b->getCropX(), 1);
    EXPECT_EQ(b->getCropY(), -3);
    EXPECT_EQ(b->getCropWidth(), 10);
    EXPECT_EQ(b->getCropHeight(), 20);
    // Four components: 0.5 -> 1, -0.5 -> 0, width -3 -> 0 (clamped), 10.49 -> 10.
    const float all[4] = {0.5f, -0.5f, -3.0f, 10.49f};
    b->updateProperty(AnimationTrack::CROP, all);
    EXPECT_EQ(b->getCropX(), 1);
    EXPECT_EQ(b->getCropY(), 0);
    EXPECT_EQ(b->getCropWidth(), 0);
    EXPECT_EQ(b->getCropHeight(), 10);
    // Upper clamp at maxViewportDimension.
    const int maxDim = getLimits().maxViewportDimension;
    const float huge[4] = {0, 0, 1e9f, static_cast<float>(maxDim)};
    b->updateProperty(AnimationTrack::CROP, huge);
    EXPECT_EQ(b->getCropWidth(), maxDim);
    EXPECT_EQ(b->getCropHeight(), maxDim);

    const float d[1] = {1.0f};
    EXPECT_THROW(b->updateProperty(AnimationTrack::DENSITY, d), IllegalArgumentException);
}
