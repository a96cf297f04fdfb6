// Texture2D (JSR-184 1.1, Texture2D; its animatable properties per
// AnimationTrack; Object3D.duplicate and animate).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include <m3g/AnimationTrack.h>
#include <m3g/Image2D.h>
#include <m3g/Limits.h>
#include <m3g/Texture2D.h>

using namespace m3g;

namespace {
struct LimitsGuard {
    Limits saved = getLimits();
    ~LimitsGuard() { setLimits(saved); }
};

Ref<Image2D> image(int w, int h, int format = Image2D::RGB) { return make<Image2D>(format, w, h); }
}  // namespace

TEST(Texture2D, ConstantsMatchSpec) {
    EXPECT_EQ(Texture2D::FILTER_BASE_LEVEL, 208);
    EXPECT_EQ(Texture2D::FILTER_LINEAR, 209);
    EXPECT_EQ(Texture2D::FILTER_NEAREST, 210);
    EXPECT_EQ(Texture2D::FUNC_ADD, 224);
    EXPECT_EQ(Texture2D::FUNC_BLEND, 225);
    EXPECT_EQ(Texture2D::FUNC_DECAL, 226);
    EXPECT_EQ(Texture2D::FUNC_MODULATE, 227);
    EXPECT_EQ(Texture2D::FUNC_REPLACE, 228);
    EXPECT_EQ(Texture2D::WRAP_CLAMP, 240);
    EXPECT_EQ(Texture2D::WRAP_REPEAT, 241);
}

TEST(Texture2D, Defaults) {
    Ref<Image2D> img = image(4, 2);
    Ref<Texture2D> t = make<Texture2D>(img);
    EXPECT_EQ(t->getImage().get(), img.get());
    EXPECT_EQ(t->getBlendColor(), 0x000000);
    EXPECT_EQ(t->getBlending(), Texture2D::FUNC_MODULATE);
    EXPECT_EQ(t->getWrappingS(), Texture2D::WRAP_REPEAT);
    EXPECT_EQ(t->getWrappingT(), Texture2D::WRAP_REPEAT);
    EXPECT_EQ(t->getLevelFilter(), Texture2D::FILTER_BASE_LEVEL);
    EXPECT_EQ(t->getImageFilter(), Texture2D::FILTER_NEAREST);
    Transform m;
    t->getTransform(&m);
    EXPECT_EQ(m, Transform());
    EXPECT_STREQ(t->getClassName(), "Texture2D");
}

TEST(Texture2D, ImageChecks) {
    EXPECT_THROW(Texture2D(nullptr), NullPointerException);
    EXPECT_THROW(Texture2D(image(3, 4)), IllegalArgumentException);
    EXPECT_THROW(Texture2D(image(4, 6)), IllegalArgumentException);
    EXPECT_NO_THROW(Texture2D(image(1, 1)));
    const int maxDim = getLimits().maxTextureDimension;
    EXPECT_NO_THROW(Texture2D(image(maxDim, 1, Image2D::LUMINANCE)));
    EXPECT_NO_THROW(Texture2D(image(1, maxDim, Image2D::LUMINANCE)));
    EXPECT_THROW(Texture2D(image(2 * maxDim, 1, Image2D::LUMINANCE)), IllegalArgumentException);
    EXPECT_THROW(Texture2D(image(1, 2 * maxDim, Image2D::LUMINANCE)), IllegalArgumentException);

    Ref<Texture2D> t = make<Texture2D>(image(2, 2));
    Ref<Image2D> other = image(8, 16, Image2D::RGBA);
    const auto rev = t->getRevision();
    t->setImage(other);
    EXPECT_GT(t->getRevision(), rev);
    EXPECT_EQ(t->getImage().get(), other.get());
    EXPECT_THROW(t->setImage(nullptr), NullPointerException);
    EXPECT_THROW(t->setImage(image(5, 8)), IllegalArgumentException);
    EXPECT_EQ(t->getImage().get(), other.get());
}

TEST(Texture2D, MaxTextureDimensionFollowsLimits) {
    LimitsGuard guard;
    Limits l = getLimits();
    l.maxTextureDimension = 256;
    setLimits(l);
    EXPECT_NO_THROW(Texture2D(image(256, 1, Image2D::ALPHA)));
    EXPECT_THROW(Texture2D(image(512, 1, Image2D::ALPHA)), IllegalArgumentException);
}

TEST(Texture2D, MutableImageIsShared) {
    Ref<Image2D> img = image(2, 2);
    Ref<Texture2D> t = make<Texture2D>(img);
    img->set(0, 0, 1, 1, std::vector<std::uint8_t>{1, 2, 3});
    EXPECT_EQ(t->getImage()->pixels()[0], 1);
}

TEST(Texture2D, SettersRoundTrip) {
    Ref<Texture2D> t = make<Texture2D>(image(2, 2));
    auto rev = t->getRevision();
    t->setFiltering(Texture2D::FILTER_LINEAR, Texture2D::FILTER_LINEAR);
    EXPECT_GT(t->getRevision(), rev);
    EXPECT_EQ(t->getLevelFilter(), Texture2D::FILTER_LINEAR);
    EXPECT_EQ(t->getImageFilter(), Texture2D::FILTER_LINEAR);
    t->setFiltering(Texture2D::FILTER_NEAREST, Texture2D::FILTER_NEAREST);
    EXPECT_EQ(t->getLevelFilter(), Texture2D::FILTER_NEAREST);
    EXPECT_EQ(t->getImageFilter(), Texture2D::FILTER_NEAREST);

    rev = t->getRevision();
    t->setWrapping(Texture2D::WRAP_CLAMP, Texture2D::WRAP_REPEAT);
    EXPECT_GT(t->getRevision(), rev);
    EXPECT_EQ(t->getWrappingS(), Texture2D::WRAP_CLAMP);
    EXPECT_EQ(t->getWrappingT(), Texture2D::WRAP_REPEAT);

    for (int f : {Texture2D::FUNC_ADD, Texture2D::FUNC_BLEND, Texture2D::FUNC_DECAL, Texture2D::FUNC_MODULATE,
                  Texture2D::FUNC_REPLACE}) {
        t->setBlending(f);
        EXPECT_EQ(t->getBlending(), f);
    }
    rev = t->getRevision();
    t->setBlendColor(static_cast<int>(0x80123456u));
    EXPECT_GT(t->getRevision(), rev);
    EXPECT_EQ(t->getBlendColor(), 0x123456);
}

TEST(Texture2D, EnumExceptions) {
    Ref<Texture2D> t = make<Texture2D>(image(2, 2));
    EXPECT_THROW(t->setFiltering(207, Texture2D::FILTER_NEAREST), IllegalArgumentException);
    EXPECT_THROW(t->setFiltering(Texture2D::FILTER_NEAREST, Texture2D::FILTER_BASE_LEVEL), IllegalArgumentException);
    EXPECT_THROW(t->setFiltering(Texture2D::FILTER_NEAREST, 211), IllegalArgumentException);
    EXPECT_THROW(t->setWrapping(239, Texture2D::WRAP_CLAMP), IllegalArgumentException);
    EXPECT_THROW(t->setWrapping(Texture2D::WRAP_CLAMP, 242), IllegalArgumentException);
    EXPECT_THROW(t->setBlending(223), IllegalArgumentException);
    EXPECT_THROW(t->setBlending(229), IllegalArgumentException);
    // Unchanged after failures.
    EXPECT_EQ(t->getLevelFilter(), Texture2D::FILTER_BASE_LEVEL);
    EXPECT_EQ(t->getWrappingS(), Texture2D::WRAP_REPEAT);
    EXPECT_EQ(t->getBlending(), Texture2D::FUNC_MODULATE);
}

TEST(Texture2D, AcceptsProjectiveTransform) {
    Ref<Texture2D> t = make<Texture2D>(image(2, 2));
    std::array<float, 16> rows{1, 0, 0, 0,  //
                               0, 1, 0, 0,  //
                               0, 0, 1, 0,  //
                               0, 0, 0.5f, 2};
    const Transform proj = Transform::fromRows(rows);
    EXPECT_NO_THROW(t->setTransform(&proj));
    Transform back;
    t->getTransform(&back);
    EXPECT_EQ(back, proj);
}

TEST(Texture2D, ReferencesAndDuplicate) {
    Ref<Image2D> img = image(4, 4);
    Ref<Texture2D> t = make<Texture2D>(img);
    std::vector<Ref<Object3D>> refs(1);
    ASSERT_EQ(t->getReferences(refs), 1);
    EXPECT_EQ(refs[0].get(), img.get());

    t->setBlending(Texture2D::FUNC_DECAL);
    t->setBlendColor(0x00ABCDEF);
    t->setWrapping(Texture2D::WRAP_CLAMP, Texture2D::WRAP_CLAMP);
    t->setFiltering(Texture2D::FILTER_LINEAR, Texture2D::FILTER_LINEAR);
    t->setTranslation(1, 2, 3);
    t->setUserID(7);
    Ref<Texture2D> d = dynamicCast<Texture2D>(t->duplicate());
    ASSERT_TRUE(d);
    EXPECT_NE(d.get(), t.get());
    EXPECT_EQ(d->getImage().get(), img.get());  // shared, not copied
    EXPECT_EQ(d->getBlending(), Texture2D::FUNC_DECAL);
    EXPECT_EQ(d->getBlendColor(), 0x00ABCDEF);
    EXPECT_EQ(d->getWrappingS(), Texture2D::WRAP_CLAMP);
    EXPECT_EQ(d->getWrappingT(), Texture2D::WRAP_CLAMP);
    EXPECT_EQ(d->getLevelFilter(), Texture2D::FILTER_LINEAR);
    EXPECT_EQ(d->getImageFilter(), Texture2D::FILTER_LINEAR);
    EXPECT_EQ(d->getUserID(), 7);
    float tr[3];
    d->getTranslation(tr);
    EXPECT_FLOAT_EQ(tr[0], 1);
    EXPECT_FLOAT_EQ(tr[1], 2);
    EXPECT_FLOAT_EQ(tr[2], 3);
}

TEST(Texture2D, Animation) {
    Ref<Texture2D> t = make<Texture2D>(image(2, 2));
    EXPECT_TRUE(t->isAnimatable(AnimationTrack::COLOR));
    EXPECT_TRUE(t->isAnimatable(AnimationTrack::TRANSLATION));
    EXPECT_TRUE(t->isAnimatable(AnimationTrack::ORIENTATION));
    EXPECT_TRUE(t->isAnimatable(AnimationTrack::SCALE));
    EXPECT_FALSE(t->isAnimatable(AnimationTrack::ALPHA));
    EXPECT_FALSE(t->isAnimatable(AnimationTrack::CROP));
    EXPECT_FALSE(t->isAnimatable(AnimationTrack::VISIBILITY));

    const auto rev = t->getRevision();
    // Clamped to [0, 1]; 0.5 * 255 = 127.5 rounds to 128 = 0x80.
    const float color[3] = {-0.5f, 0.5f, 2.0f};
    t->updateProperty(AnimationTrack::COLOR, color);
    EXPECT_GT(t->getRevision(), rev);
    EXPECT_EQ(t->getBlendColor(), 0x0080FF);
    const float c2[3] = {0.2f, 1.0f, 0.0f};  // 0.2 * 255 = 51 = 0x33
    t->updateProperty(AnimationTrack::COLOR, c2);
    EXPECT_EQ(t->getBlendColor(), 0x33FF00);

    const float tr[3] = {4, 5, 6};
    t->updateProperty(AnimationTrack::TRANSLATION, tr);
    float back[3];
    t->getTranslation(back);
    EXPECT_FLOAT_EQ(back[0], 4);
    EXPECT_FLOAT_EQ(back[2], 6);
    const float a[1] = {0.5f};
    EXPECT_THROW(t->updateProperty(AnimationTrack::ALPHA, a), IllegalArgumentException);
}
