// Appearance (JSR-184 1.1, Appearance; Object3D.duplicate).
#include <gtest/gtest.h>

#include <vector>

#include <m3g/Appearance.h>
#include <m3g/AnimationTrack.h>
#include <m3g/CompositingMode.h>
#include <m3g/Fog.h>
#include <m3g/Image2D.h>
#include <m3g/Limits.h>
#include <m3g/Material.h>
#include <m3g/PolygonMode.h>
#include <m3g/Texture2D.h>

using namespace m3g;

namespace {
struct LimitsGuard {
    Limits saved = getLimits();
    ~LimitsGuard() { setLimits(saved); }
};

Ref<Texture2D> texture() { return make<Texture2D>(make<Image2D>(Image2D::RGB, 2, 2)); }

std::vector<Object3D*> referencesOf(const Object3D& o) {
    std::vector<Ref<Object3D>> refs(static_cast<std::size_t>(o.getReferences()));
    o.getReferences(refs);
    std::vector<Object3D*> out;
    for (const auto& r : refs) out.push_back(r.get());
    return out;
}
}  // namespace

TEST(Appearance, Defaults) {
    Ref<Appearance> a = make<Appearance>();
    EXPECT_EQ(a->getLayer(), 0);
    EXPECT_EQ(a->getCompositingMode(), nullptr);
    EXPECT_EQ(a->getFog(), nullptr);
    EXPECT_EQ(a->getPolygonMode(), nullptr);
    EXPECT_EQ(a->getMaterial(), nullptr);
    for (int i = 0; i < getLimits().numTextureUnits; ++i) EXPECT_EQ(a->getTexture(i), nullptr);
    EXPECT_EQ(a->getReferences(), 0);
    EXPECT_STREQ(a->getClassName(), "Appearance");
}

TEST(Appearance, Layer) {
    Ref<Appearance> a = make<Appearance>();
    auto rev = a->getRevision();
    a->setLayer(-63);
    EXPECT_EQ(a->getLayer(), -63);
    EXPECT_GT(a->getRevision(), rev);
    a->setLayer(63);
    EXPECT_EQ(a->getLayer(), 63);
    EXPECT_THROW(a->setLayer(-64), IllegalArgumentException);
    EXPECT_THROW(a->setLayer(64), IllegalArgumentException);
    EXPECT_EQ(a->getLayer(), 63);
}

TEST(Appearance, ComponentsRoundTripAndNull) {
    Ref<Appearance> a = make<Appearance>();
    Ref<CompositingMode> cm = make<CompositingMode>();
    Ref<Fog> fog = make<Fog>();
    Ref<PolygonMode> pm = make<PolygonMode>();
    Ref<Material> mat = make<Material>();

    auto rev = a->getRevision();
    a->setCompositingMode(cm);
    EXPECT_GT(a->getRevision(), rev);
    rev = a->getRevision();
    a->setFog(fog);
    EXPECT_GT(a->getRevision(), rev);
    rev = a->getRevision();
    a->setPolygonMode(pm);
    EXPECT_GT(a->getRevision(), rev);
    rev = a->getRevision();
    a->setMaterial(mat);
    EXPECT_GT(a->getRevision(), rev);
    EXPECT_EQ(a->getCompositingMode().get(), cm.get());
    EXPECT_EQ(a->getFog().get(), fog.get());
    EXPECT_EQ(a->getPolygonMode().get(), pm.get());
    EXPECT_EQ(a->getMaterial().get(), mat.get());

    a->setCompositingMode(nullptr);
    a->setFog(nullptr);
    a->setPolygonMode(nullptr);
    a->setMaterial(nullptr);
    EXPECT_EQ(a->getCompositingMode(), nullptr);
    EXPECT_EQ(a->getFog(), nullptr);
    EXPECT_EQ(a->getPolygonMode(), nullptr);
    EXPECT_EQ(a->getMaterial(), nullptr);
}

TEST(Appearance, Textures) {
    Ref<Appearance> a = make<Appearance>();
    const int units = getLimits().numTextureUnits;
    Ref<Texture2D> t0 = texture();
    Ref<Texture2D> tl = texture();
    auto rev = a->getRevision();
    a->setTexture(0, t0);
    EXPECT_GT(a->getRevision(), rev);
    a->setTexture(units - 1, tl);
    EXPECT_EQ(a->getTexture(0).get(), t0.get());
    EXPECT_EQ(a->getTexture(units - 1).get(), tl.get());
    a->setTexture(0, nullptr);
    EXPECT_EQ(a->getTexture(0), nullptr);

    EXPECT_THROW(a->setTexture(-1, t0), IndexOutOfBoundsException);
    EXPECT_THROW(a->setTexture(units, t0), IndexOutOfBoundsException);
    EXPECT_THROW(a->getTexture(-1), IndexOutOfBoundsException);
    EXPECT_THROW(a->getTexture(units), IndexOutOfBoundsException);
}

TEST(Appearance, TextureUnitsFollowLimits) {
    LimitsGuard guard;
    Limits l = getLimits();
    l.numTextureUnits = kMaxTextureUnits;
    setLimits(l);
    Ref<Appearance> a = make<Appearance>();
    Ref<Texture2D> t = texture();
    EXPECT_NO_THROW(a->setTexture(kMaxTextureUnits - 1, t));
    EXPECT_EQ(a->getTexture(kMaxTextureUnits - 1).get(), t.get());
    EXPECT_THROW(a->setTexture(kMaxTextureUnits, t), IndexOutOfBoundsException);
    l.numTextureUnits = 1;
    setLimits(l);
    EXPECT_THROW(a->setTexture(1, t), IndexOutOfBoundsException);
    EXPECT_THROW(a->getTexture(1), IndexOutOfBoundsException);
}

TEST(Appearance, ReferencesOrder) {
    Ref<Appearance> a = make<Appearance>();
    Ref<CompositingMode> cm = make<CompositingMode>();
    Ref<Fog> fog = make<Fog>();
    Ref<PolygonMode> pm = make<PolygonMode>();
    Ref<Material> mat = make<Material>();
    Ref<Texture2D> t0 = texture();
    Ref<Texture2D> t1 = texture();
    // Set in a scrambled order; the reference order is fixed.
    a->setTexture(1, t1);
    a->setMaterial(mat);
    a->setTexture(0, t0);
    a->setFog(fog);
    a->setPolygonMode(pm);
    a->setCompositingMode(cm);
    EXPECT_EQ(referencesOf(*a),
              (std::vector<Object3D*>{cm.get(), fog.get(), pm.get(), mat.get(), t0.get(), t1.get()}));

    // Null components are skipped.
    a->setFog(nullptr);
    a->setTexture(0, nullptr);
    EXPECT_EQ(referencesOf(*a), (std::vector<Object3D*>{cm.get(), pm.get(), mat.get(), t1.get()}));

    std::vector<Ref<Object3D>> tooShort(3);
    EXPECT_THROW(a->getReferences(tooShort), IllegalArgumentException);
}

TEST(Appearance, FindReachesComponents) {
    Ref<Appearance> a = make<Appearance>();
    Ref<Texture2D> t = texture();
    t->getImage()->setUserID(77);
    a->setTexture(0, t);
    EXPECT_EQ(a->find(77).get(), t->getImage().get());
}

TEST(Appearance, DuplicateSharesComponents) {
    Ref<Appearance> a = make<Appearance>();
    Ref<CompositingMode> cm = make<CompositingMode>();
    Ref<Fog> fog = make<Fog>();
    Ref<PolygonMode> pm = make<PolygonMode>();
    Ref<Material> mat = make<Material>();
    Ref<Texture2D> t1 = texture();
    a->setLayer(-7);
    a->setCompositingMode(cm);
    a->setFog(fog);
    a->setPolygonMode(pm);
    a->setMaterial(mat);
    a->setTexture(1, t1);
    a->setUserID(21);
    Ref<Appearance> d = dynamicCast<Appearance>(a->duplicate());
    ASSERT_TRUE(d);
    EXPECT_NE(d.get(), a.get());
    EXPECT_EQ(d->getLayer(), -7);
    EXPECT_EQ(d->getUserID(), 21);
    EXPECT_EQ(d->getCompositingMode().get(), cm.get());
    EXPECT_EQ(d->getFog().get(), fog.get());
    EXPECT_EQ(d->getPolygonMode().get(), pm.get());
    EXPECT_EQ(d->getMaterial().get(), mat.get());
    EXPECT_EQ(d->getTexture(0), nullptr);
    EXPECT_EQ(d->getTexture(1).get(), t1.get());
    // Changing the copy's slots does not affect the original.
    d->setMaterial(nullptr);
    EXPECT_EQ(a->getMaterial().get(), mat.get());
}

TEST(Appearance, NotAnimatable) {
    Ref<Appearance> a = make<Appearance>();
    for (int p = AnimationTrack::ALPHA; p <= AnimationTrack::VISIBILITY; ++p) EXPECT_FALSE(a->isAnimatable(p)) << p;
}
