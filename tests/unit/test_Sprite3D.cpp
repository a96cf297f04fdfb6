// Sprite3D (JSR-184 1.1, Sprite3D; its animatable properties per
// AnimationTrack; Object3D.duplicate and animate).
#include <gtest/gtest.h>

#include <array>
#include <climits>
#include <vector>

#include <m3g/AnimationTrack.h>
#include <m3g/Appearance.h>
#include <m3g/Group.h>
#include <m3g/Image2D.h>
#include <m3g/Limits.h>
#include <m3g/Sprite3D.h>

using namespace m3g;

namespace {
struct LimitsGuard {
    Limits saved = getLimits();
    ~LimitsGuard() { setLimits(saved); }
};

std::vector<Object3D*> referencesOf(const Object3D& o) {
    std::vector<Ref<Object3D>> refs(static_cast<std::size_t>(o.getReferences()));
    o.getReferences(refs);
    std::vector<Object3D*> out;
    for (const auto& r : refs) out.push_back(r.get());
    return out;
}
}  // namespace

TEST(Sprite3D, ConstructorAndDefaults) {
    Ref<Image2D> img = make<Image2D>(Image2D::RGBA, 30, 17);  // any size
    Ref<Appearance> app = make<Appearance>();
    Ref<Sprite3D> s = make<Sprite3D>(true, img, app);
    EXPECT_TRUE(s->isScaled());
    EXPECT_EQ(s->getImage().get(), img.get());
    EXPECT_EQ(s->getAppearance().get(), app.get());
    EXPECT_EQ(s->getCropX(), 0);
    EXPECT_EQ(s->getCropY(), 0);
    EXPECT_EQ(s->getCropWidth(), 30);
    EXPECT_EQ(s->getCropHeight(), 17);
    // Node defaults.
    EXPECT_EQ(s->getParent(), nullptr);
    EXPECT_EQ(s->getAlphaFactor(), 1.0f);
    EXPECT_TRUE(s->isRenderingEnabled());
    EXPECT_TRUE(s->isPickingEnabled());
    EXPECT_EQ(s->getScope(), -1);
    EXPECT_STREQ(s->getClassName(), "Sprite3D");

    Ref<Sprite3D> u = make<Sprite3D>(false, img, nullptr);  // null appearance allowed
    EXPECT_FALSE(u->isScaled());
    EXPECT_EQ(u->getAppearance(), nullptr);
    EXPECT_THROW(Sprite3D(true, nullptr, app), NullPointerException);
}

TEST(Sprite3D, SetAppearance) {
    Ref<Sprite3D> s = make<Sprite3D>(false, make<Image2D>(Image2D::RGB, 4, 4), nullptr);
    Ref<Appearance> app = make<Appearance>();
    auto rev = s->getRevision();
    s->setAppearance(app);
    EXPECT_GT(s->getRevision(), rev);
    EXPECT_EQ(s->getAppearance().get(), app.get());
    s->setAppearance(nullptr);
    EXPECT_EQ(s->getAppearance(), nullptr);
}

TEST(Sprite3D, SetImageResetsCrop) {
    Ref<Sprite3D> s = make<Sprite3D>(false, make<Image2D>(Image2D::RGB, 4, 4), nullptr);
    s->setCrop(1, 2, -3, 4);
    Ref<Image2D> other = make<Image2D>(Image2D::LUMINANCE, 9, 5);
    auto rev = s->getRevision();
    s->setImage(other);
    EXPECT_GT(s->getRevision(), rev);
    EXPECT_EQ(s->getImage().get(), other.get());
    EXPECT_EQ(s->getCropX(), 0);
    EXPECT_EQ(s->getCropY(), 0);
    EXPECT_EQ(s->getCropWidth(), 9);
    EXPECT_EQ(s->getCropHeight(), 5);
    EXPECT_THROW(s->setImage(nullptr), NullPointerException);
    EXPECT_EQ(s->getImage().get(), other.get());
}

TEST(Sprite3D, Crop) {
    Ref<Sprite3D> s = make<Sprite3D>(false, make<Image2D>(Image2D::RGB, 4, 4), nullptr);
    auto rev = s->getRevision();
    s->setCrop(-5, 7, -2, -3);  // negative sizes mirror and keep their sign
    EXPECT_GT(s->getRevision(), rev);
    EXPECT_EQ(s->getCropX(), -5);
    EXPECT_EQ(s->getCropY(), 7);
    EXPECT_EQ(s->getCropWidth(), -2);
    EXPECT_EQ(s->getCropHeight(), -3);
    const int maxDim = getLimits().maxSpriteCropDimension;
    EXPECT_NO_THROW(s->setCrop(0, 0, maxDim, -maxDim));
    EXPECT_EQ(s->getCropWidth(), maxDim);
    EXPECT_EQ(s->getCropHeight(), -maxDim);
    EXPECT_THROW(s->setCrop(0, 0, maxDim + 1, 1), IllegalArgumentException);
    EXPECT_THROW(s->setCrop(0, 0, -maxDim - 1, 1), IllegalArgumentException);
    EXPECT_THROW(s->setCrop(0, 0, 1, maxDim + 1), IllegalArgumentException);
    EXPECT_THROW(s->setCrop(0, 0, 1, -maxDim - 1), IllegalArgumentException);
    EXPECT_THROW(s->setCrop(0, 0, INT_MIN, 1), IllegalArgumentException);
    EXPECT_EQ(s->getCropWidth(), maxDim);
}

TEST(Sprite3D, CropLimitFollowsLimits) {
    LimitsGuard guard;
    Limits l = getLimits();
    l.maxSpriteCropDimension = 256;
    setLimits(l);
    Ref<Sprite3D> s = make<Sprite3D>(false, make<Image2D>(Image2D::RGB, 4, 4), nullptr);
    EXPECT_NO_THROW(s->setCrop(0, 0, 256, 256));
    EXPECT_THROW(s->setCrop(0, 0, 257, 1), IllegalArgumentException);
}

TEST(Sprite3D, ReferencesOrder) {
    Ref<Image2D> img = make<Image2D>(Image2D::RGB, 4, 4);
    Ref<Appearance> app = make<Appearance>();
    Ref<Group> root = make<Group>();
    Ref<Group> target = make<Group>();
    Ref<Sprite3D> s = make<Sprite3D>(true, img, app);
    root->addChild(target);
    root->addChild(s);
    EXPECT_EQ(referencesOf(*s), (std::vector<Object3D*>{img.get(), app.get()}));
    // Alignment references are not listed (they point up or across the graph).
    s->setAlignment(target, Node::ORIGIN, nullptr, Node::NONE);
    EXPECT_EQ(referencesOf(*s), (std::vector<Object3D*>{img.get(), app.get()}));
    s->setAppearance(nullptr);
    EXPECT_EQ(referencesOf(*s), (std::vector<Object3D*>{img.get()}));
}

TEST(Sprite3D, DuplicateSharesImageAndAppearance) {
    Ref<Image2D> img = make<Image2D>(Image2D::RGB, 4, 4);
    Ref<Appearance> app = make<Appearance>();
    Ref<Group> root = make<Group>();
    Ref<Sprite3D> s = make<Sprite3D>(true, img, app);
    root->addChild(s);
    s->setCrop(1, 2, -3, 4);
    s->setTranslation(1, 2, 3);
    s->setAlphaFactor(0.5f);
    s->setUserID(31);
    Ref<Sprite3D> d = dynamicCast<Sprite3D>(s->duplicate());
    ASSERT_TRUE(d);
    EXPECT_NE(d.get(), s.get());
    EXPECT_EQ(d->getParent(), nullptr);
    EXPECT_TRUE(d->isScaled());
    EXPECT_EQ(d->getImage().get(), img.get());
    EXPECT_EQ(d->getAppearance().get(), app.get());
    EXPECT_EQ(d->getCropX(), 1);
    EXPECT_EQ(d->getCropY(), 2);
    EXPECT_EQ(d->getCropWidth(), -3);
    EXPECT_EQ(d->getCropHeight(), 4);
    EXPECT_EQ(d->getAlphaFactor(), 0.5f);
    EXPECT_EQ(d->getUserID(), 31);
    float t[3];
    d->getTranslation(t);
    EXPECT_EQ(t[0], 1.0f);
    EXPECT_EQ(t[2], 3.0f);
}

TEST(Sprite3D, DuplicateOfGroupCopiesSprite) {
    Ref<Image2D> img = make<Image2D>(Image2D::RGB, 4, 4);
    Ref<Group> root = make<Group>();
    Ref<Sprite3D> s = make<Sprite3D>(false, img, nullptr);
    root->addChild(s);
    Ref<Group> d = dynamicCast<Group>(root->duplicate());
    ASSERT_TRUE(d);
    ASSERT_EQ(d->getChildCount(), 1);
    Ref<Sprite3D> ds = dynamicCast<Sprite3D>(d->getChild(0));
    ASSERT_TRUE(ds);
    EXPECT_NE(ds.get(), s.get());
    EXPECT_EQ(ds->getParent().get(), d.get());
    EXPECT_EQ(ds->getImage().get(), img.get());
}

TEST(Sprite3D, IsAnimatable) {
    Ref<Sprite3D> s = make<Sprite3D>(false, make<Image2D>(Image2D::RGB, 4, 4), nullptr);
    for (int p : {AnimationTrack::CROP, AnimationTrack::ALPHA, AnimationTrack::PICKABILITY, AnimationTrack::VISIBILITY,
                  AnimationTrack::TRANSLATION, AnimationTrack::ORIENTATION, AnimationTrack::SCALE})
        EXPECT_TRUE(s->isAnimatable(p)) << p;
    for (int p : {AnimationTrack::COLOR, AnimationTrack::DENSITY, AnimationTrack::MORPH_WEIGHTS})
        EXPECT_FALSE(s->isAnimatable(p)) << p;
}

TEST(Sprite3D, UpdatePropertyCrop) {
    Ref<Sprite3D> s = make<Sprite3D>(false, make<Image2D>(Image2D::RGB, 4, 8), nullptr);
    auto rev = s->getRevision();
    // Two components: x, y (halves up: 2.5 -> 3, -1.5 -> -1); size kept.
    const float xy[2] = {2.5f, -1.5f};
    s->updateProperty(AnimationTrack::CROP, xy);
    EXPECT_GT(s->getRevision(), rev);
    EXPECT_EQ(s->getCropX(), 3);
    EXPECT_EQ(s->getCropY(), -1);
    EXPECT_EQ(s->getCropWidth(), 4);
    EXPECT_EQ(s->getCropHeight(), 8);
    // Four components; negative sizes kept (mirroring): -2.6 -> -3, 5.49 -> 5.
    const float all[4] = {0.2f, 0.7f, -2.6f, 5.49f};
    s->updateProperty(AnimationTrack::CROP, all);
    EXPECT_EQ(s->getCropX(), 0);
    EXPECT_EQ(s->getCropY(), 1);
    EXPECT_EQ(s->getCropWidth(), -3);
    EXPECT_EQ(s->getCropHeight(), 5);
    // Sizes clamped to +-maxSpriteCropDimension.
    const int maxDim = getLimits().maxSpriteCropDimension;
    const float huge[4] = {0, 0, 1e7f, -1e7f};
    s->updateProperty(AnimationTrack::CROP, huge);
    EXPECT_EQ(s->getCropWidth(), maxDim);
    EXPECT_EQ(s->getCropHeight(), -maxDim);
}

TEST(Sprite3D, UpdatePropertyDelegatesToNode) {
    Ref<Sprite3D> s = make<Sprite3D>(false, make<Image2D>(Image2D::RGB, 4, 4), nullptr);
    const float alpha[1] = {1.5f};
    s->updateProperty(AnimationTrack::ALPHA, alpha);
    EXPECT_EQ(s->getAlphaFactor(), 1.0f);
    const float vis[1] = {0.25f};
    s->updateProperty(AnimationTrack::VISIBILITY, vis);
    EXPECT_FALSE(s->isRenderingEnabled());
    const float tr[3] = {1, 2, 3};
    s->updateProperty(AnimationTrack::TRANSLATION, tr);
    float t[3];
    s->getTranslation(t);
    EXPECT_EQ(t[1], 2.0f);
    const float c[3] = {1, 1, 1};
    EXPECT_THROW(s->updateProperty(AnimationTrack::COLOR, c), IllegalArgumentException);
}

TEST(Sprite3D, RejectsNonAffineTransform) {
    Ref<Sprite3D> s = make<Sprite3D>(false, make<Image2D>(Image2D::RGB, 4, 4), nullptr);
    std::array<float, 16> rows{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1};
    const Transform t = Transform::fromRows(rows);
    EXPECT_THROW(s->setTransform(&t), IllegalArgumentException);
}
