// VertexBuffer (JSR-184 1.1, VertexBuffer).
#include <gtest/gtest.h>

#include <vector>

#include <m3g/AnimationTrack.h>
#include <m3g/Limits.h>
#include <m3g/VertexBuffer.h>

using namespace m3g;

namespace {
Ref<VertexArray> va(int vertices, int comps, int size = 2) { return new VertexArray(vertices, comps, size); }

// Restores the global limits when a test changes them.
struct LimitsGuard {
    Limits saved = getLimits();
    ~LimitsGuard() { setLimits(saved); }
};
}  // namespace

TEST(VertexBuffer, Defaults) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    EXPECT_EQ(vb->getVertexCount(), 0);
    EXPECT_EQ(vb->getDefaultColor(), static_cast<int>(0xFFFFFFFFu));
    EXPECT_EQ(vb->getPositions(), nullptr);
    EXPECT_EQ(vb->getNormals(), nullptr);
    EXPECT_EQ(vb->getColors(), nullptr);
    EXPECT_EQ(vb->getTexCoords(0), nullptr);
    EXPECT_EQ(vb->getTexCoords(1), nullptr);
    EXPECT_EQ(vb->getReferences(), 0);
    EXPECT_STREQ(vb->getClassName(), "VertexBuffer");
}

TEST(VertexBuffer, PositionsScaleBiasRoundTrip) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<VertexArray> p = va(4, 3);
    const float bias[3] = {1, 2, 3};
    vb->setPositions(p, 0.5f, bias);
    EXPECT_EQ(vb->getVertexCount(), 4);
    float sb[4] = {};
    EXPECT_EQ(vb->getPositions(sb), p);
    EXPECT_EQ(sb[0], 0.5f);
    EXPECT_EQ(sb[1], 1.0f);
    EXPECT_EQ(sb[2], 2.0f);
    EXPECT_EQ(sb[3], 3.0f);
    EXPECT_EQ(vb->getPositions(), p);  // null scaleBias: array only

    vb->setPositions(p, 2.0f, {});  // null bias -> zeros
    vb->getPositions(sb);
    EXPECT_EQ(sb[0], 2.0f);
    EXPECT_EQ(sb[1], 0.0f);
    EXPECT_EQ(sb[2], 0.0f);
    EXPECT_EQ(sb[3], 0.0f);
}

TEST(VertexBuffer, PositionsErrors) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    const float bias2[2] = {1, 2};
    EXPECT_THROW(vb->setPositions(va(4, 2), 1.0f, {}), IllegalArgumentException);
    EXPECT_THROW(vb->setPositions(va(4, 4), 1.0f, {}), IllegalArgumentException);
    EXPECT_THROW(vb->setPositions(va(4, 3), 1.0f, bias2), IllegalArgumentException);
    EXPECT_EQ(vb->getPositions(), nullptr);
    EXPECT_EQ(vb->getVertexCount(), 0);
    float sb3[3];
    EXPECT_THROW(vb->getPositions(sb3), IllegalArgumentException);
}

TEST(VertexBuffer, NullRemovesArrays) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    vb->setPositions(va(4, 3), 1.0f, {});
    vb->setNormals(va(4, 3));
    vb->setPositions(nullptr, 1.0f, {});
    EXPECT_EQ(vb->getPositions(), nullptr);
    EXPECT_EQ(vb->getVertexCount(), 4);  // normals remain
    vb->setNormals(nullptr);
    EXPECT_EQ(vb->getNormals(), nullptr);
    EXPECT_EQ(vb->getVertexCount(), 0);  // no array left
    vb->setColors(va(9, 3, 1));          // any count is fine again
    EXPECT_EQ(vb->getVertexCount(), 9);
}

TEST(VertexBuffer, AllArraysShareOneVertexCount) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    vb->setPositions(va(4, 3), 1.0f, {});
    EXPECT_THROW(vb->setNormals(va(5, 3)), IllegalArgumentException);
    EXPECT_THROW(vb->setColors(va(3, 4, 1)), IllegalArgumentException);
    EXPECT_THROW(vb->setTexCoords(0, va(5, 2), 1.0f, {}), IllegalArgumentException);
    EXPECT_EQ(vb->getNormals(), nullptr);
    EXPECT_EQ(vb->getColors(), nullptr);
    EXPECT_EQ(vb->getTexCoords(0), nullptr);
    // Replacing the only array may change the count.
    vb->setPositions(va(6, 3), 1.0f, {});
    EXPECT_EQ(vb->getVertexCount(), 6);
    vb->setNormals(va(6, 3));
    // With another array present the replacement must match.
    EXPECT_THROW(vb->setPositions(va(7, 3), 1.0f, {}), IllegalArgumentException);
    EXPECT_EQ(vb->getPositions()->getVertexCount(), 6);
    vb->setPositions(va(6, 3), 1.0f, {});
    EXPECT_EQ(vb->getVertexCount(), 6);
}

TEST(VertexBuffer, Normals) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<VertexArray> n = va(3, 3, 1);
    vb->setNormals(n);
    EXPECT_EQ(vb->getNormals(), n);
    EXPECT_EQ(vb->getVertexCount(), 3);
    EXPECT_THROW(vb->setNormals(va(3, 2)), IllegalArgumentException);
    EXPECT_THROW(vb->setNormals(va(3, 4)), IllegalArgumentException);
    EXPECT_EQ(vb->getNormals(), n);
}

TEST(VertexBuffer, ColorsOnlyByteArraysWithThreeOrFourComponents) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<VertexArray> c3 = va(2, 3, 1);
    Ref<VertexArray> c4 = va(2, 4, 1);
    vb->setColors(c3);
    EXPECT_EQ(vb->getColors(), c3);
    vb->setColors(c4);
    EXPECT_EQ(vb->getColors(), c4);
    EXPECT_THROW(vb->setColors(va(2, 3, 2)), IllegalArgumentException);
    EXPECT_THROW(vb->setColors(va(2, 4, 2)), IllegalArgumentException);
    EXPECT_THROW(vb->setColors(va(2, 2, 1)), IllegalArgumentException);
    EXPECT_EQ(vb->getColors(), c4);
}

TEST(VertexBuffer, TexCoordsScaleBiasRoundTrip) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<VertexArray> t2 = va(5, 2);
    Ref<VertexArray> t3 = va(5, 3, 1);
    const float b2[2] = {0.25f, -0.5f};
    const float b3[3] = {1, 2, 3};
    vb->setTexCoords(0, t2, 0.125f, b2);
    vb->setTexCoords(1, t3, 4.0f, b3);
    EXPECT_EQ(vb->getVertexCount(), 5);
    float sb[4] = {9, 9, 9, 9};
    EXPECT_EQ(vb->getTexCoords(0, sb), t2);
    EXPECT_EQ(sb[0], 0.125f);
    EXPECT_EQ(sb[1], 0.25f);
    EXPECT_EQ(sb[2], -0.5f);
    EXPECT_EQ(sb[3], 9.0f);  // only componentCount + 1 values written
    EXPECT_EQ(vb->getTexCoords(1, sb), t3);
    EXPECT_EQ(sb[0], 4.0f);
    EXPECT_EQ(sb[1], 1.0f);
    EXPECT_EQ(sb[2], 2.0f);
    EXPECT_EQ(sb[3], 3.0f);
    // 2 + 1 values suffice for a 2-component array, not for 3 components.
    float sb3[3];
    EXPECT_NO_THROW(vb->getTexCoords(0, sb3));
    EXPECT_THROW(vb->getTexCoords(1, sb3), IllegalArgumentException);
    vb->setTexCoords(0, t2, 1.0f, {});  // null bias -> zeros
    vb->getTexCoords(0, sb);
    EXPECT_EQ(sb[0], 1.0f);
    EXPECT_EQ(sb[1], 0.0f);
    EXPECT_EQ(sb[2], 0.0f);
}

TEST(VertexBuffer, TexCoordsErrors) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    const float b1[1] = {0};
    const float b2[2] = {0, 0};
    EXPECT_THROW(vb->setTexCoords(-1, va(2, 2), 1.0f, {}), IndexOutOfBoundsException);
    EXPECT_THROW(vb->setTexCoords(getLimits().numTextureUnits, va(2, 2), 1.0f, {}), IndexOutOfBoundsException);
    EXPECT_THROW(vb->getTexCoords(-1), IndexOutOfBoundsException);
    EXPECT_THROW(vb->getTexCoords(getLimits().numTextureUnits), IndexOutOfBoundsException);
    EXPECT_THROW(vb->setTexCoords(0, va(2, 4), 1.0f, {}), IllegalArgumentException);
    EXPECT_THROW(vb->setTexCoords(0, va(2, 2), 1.0f, b1), IllegalArgumentException);
    EXPECT_THROW(vb->setTexCoords(0, va(2, 3), 1.0f, b2), IllegalArgumentException);
    EXPECT_EQ(vb->getTexCoords(0), nullptr);
    EXPECT_NO_THROW(vb->setTexCoords(0, nullptr, 1.0f, b1));  // removal: bias not checked
}

TEST(VertexBuffer, TextureUnitCountComesFromLimits) {
    LimitsGuard guard;
    Limits l = getLimits();
    l.numTextureUnits = 4;
    setLimits(l);
    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<VertexArray> t = va(2, 2);
    vb->setTexCoords(3, t, 1.0f, {});
    EXPECT_EQ(vb->getTexCoords(3), t);
    l.numTextureUnits = 1;
    setLimits(l);
    EXPECT_THROW(vb->setTexCoords(1, t, 1.0f, {}), IndexOutOfBoundsException);
}

TEST(VertexBuffer, DefaultColorRoundTrip) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    vb->setDefaultColor(static_cast<int>(0x80112233u));
    EXPECT_EQ(vb->getDefaultColor(), static_cast<int>(0x80112233u));
    vb->setDefaultColor(0);
    EXPECT_EQ(vb->getDefaultColor(), 0);
}

TEST(VertexBuffer, AnimatesColorAndAlphaOfTheDefaultColor) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    EXPECT_TRUE(vb->isAnimatable(AnimationTrack::COLOR));
    EXPECT_TRUE(vb->isAnimatable(AnimationTrack::ALPHA));
    EXPECT_FALSE(vb->isAnimatable(AnimationTrack::MORPH_WEIGHTS));
    EXPECT_FALSE(vb->isAnimatable(AnimationTrack::TRANSLATION));
    vb->setDefaultColor(static_cast<int>(0x40000000u));
    const float rgb[3] = {1.0f, 0.5f, -1.0f};  // 255, round(127.5) = 128, clamped 0
    vb->updateProperty(AnimationTrack::COLOR, rgb);
    EXPECT_EQ(vb->getDefaultColor(), static_cast<int>(0x40FF8000u));
    const float big[1] = {2.0f};  // clamped to 1
    vb->updateProperty(AnimationTrack::ALPHA, big);
    EXPECT_EQ(vb->getDefaultColor(), static_cast<int>(0xFFFF8000u));
    const float a[1] = {0.2f};  // 0.2 * 255 = 51 = 0x33
    vb->updateProperty(AnimationTrack::ALPHA, a);
    EXPECT_EQ(vb->getDefaultColor(), static_cast<int>(0x33FF8000u));
    EXPECT_THROW(vb->updateProperty(AnimationTrack::TRANSLATION, rgb), IllegalArgumentException);
}

TEST(VertexBuffer, ReferencesOrderPositionsNormalsColorsTexCoords) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<VertexArray> p = va(3, 3), n = va(3, 3), c = va(3, 4, 1), t0 = va(3, 2), t1 = va(3, 2);
    vb->setTexCoords(1, t1, 1.0f, {});
    vb->setColors(c);
    vb->setNormals(n);
    vb->setPositions(p, 1.0f, {});
    vb->setTexCoords(0, t0, 1.0f, {});
    std::vector<Ref<Object3D>> refs(5);
    ASSERT_EQ(vb->getReferences(refs), 5);
    EXPECT_EQ(refs[0].get(), p.get());
    EXPECT_EQ(refs[1].get(), n.get());
    EXPECT_EQ(refs[2].get(), c.get());
    EXPECT_EQ(refs[3].get(), t0.get());
    EXPECT_EQ(refs[4].get(), t1.get());
    vb->setNormals(nullptr);
    EXPECT_EQ(vb->getReferences(), 4);  // nulls omitted
}

TEST(VertexBuffer, DuplicateSharesArraysAndCopiesSettings) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<VertexArray> p = va(3, 3), t = va(3, 2);
    const float bias[3] = {1, 2, 3};
    vb->setPositions(p, 0.5f, bias);
    vb->setTexCoords(1, t, 2.0f, bias);
    vb->setDefaultColor(0x11223344);
    vb->setUserID(7);
    Ref<VertexBuffer> d = dynamicCast<VertexBuffer>(vb->duplicate());
    ASSERT_TRUE(d);
    EXPECT_NE(d.get(), vb.get());
    EXPECT_EQ(d->getUserID(), 7);
    float sb[4];
    EXPECT_EQ(d->getPositions(sb).get(), p.get());
    EXPECT_EQ(sb[0], 0.5f);
    EXPECT_EQ(sb[3], 3.0f);
    EXPECT_EQ(d->getTexCoords(1, sb).get(), t.get());
    EXPECT_EQ(sb[0], 2.0f);
    EXPECT_EQ(sb[2], 2.0f);
    EXPECT_EQ(d->getDefaultColor(), 0x11223344);
    EXPECT_EQ(d->getVertexCount(), 3);
    // Independent settings after the copy.
    d->setPositions(nullptr, 1.0f, {});
    EXPECT_EQ(vb->getPositions().get(), p.get());
}

TEST(VertexBuffer, MutatorsTouch) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    auto r = vb->getRevision();
    auto bumped = [&] {
        const auto now = vb->getRevision();
        const bool b = now > r;
        r = now;
        return b;
    };
    vb->setPositions(va(2, 3), 1.0f, {});
    EXPECT_TRUE(bumped());
    vb->setNormals(va(2, 3));
    EXPECT_TRUE(bumped());
    vb->setColors(va(2, 3, 1));
    EXPECT_TRUE(bumped());
    vb->setTexCoords(0, va(2, 2), 1.0f, {});
    EXPECT_TRUE(bumped());
    vb->setDefaultColor(1);
    EXPECT_TRUE(bumped());
    const float a[1] = {0.5f};
    vb->updateProperty(AnimationTrack::ALPHA, a);
    EXPECT_TRUE(bumped());
}
