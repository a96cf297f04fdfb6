// VertexArray (JSR-184 1.1, VertexArray) and Transform::transform(VertexArray)
// (JSR-184 1.1, Transform.transform(VertexArray, float[], boolean)).
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include <m3g/Transform.h>
#include <m3g/VertexArray.h>

using namespace m3g;
using Bytes = std::vector<std::int8_t>;
using Shorts = std::vector<std::int16_t>;

TEST(VertexArray, ConstructorStoresShapeAndZeroes) {
    Ref<VertexArray> a = new VertexArray(10, 3, 2);
    EXPECT_EQ(a->getVertexCount(), 10);
    EXPECT_EQ(a->getComponentCount(), 3);
    EXPECT_EQ(a->getComponentType(), 2);
    EXPECT_STREQ(a->getClassName(), "VertexArray");
    Shorts s(30, 99);
    a->get(0, 10, s);
    for (auto v : s) EXPECT_EQ(v, 0);
    EXPECT_EQ(a->getReferences(), 0);
}

TEST(VertexArray, ConstructorLimits) {
    EXPECT_NO_THROW(VertexArray(1, 2, 1));
    EXPECT_NO_THROW(VertexArray(65535, 4, 2));
    EXPECT_THROW(VertexArray(0, 3, 1), IllegalArgumentException);
    EXPECT_THROW(VertexArray(65536, 3, 1), IllegalArgumentException);
    EXPECT_THROW(VertexArray(-1, 3, 1), IllegalArgumentException);
    EXPECT_THROW(VertexArray(4, 1, 1), IllegalArgumentException);
    EXPECT_THROW(VertexArray(4, 5, 1), IllegalArgumentException);
    EXPECT_THROW(VertexArray(4, 3, 0), IllegalArgumentException);
    EXPECT_THROW(VertexArray(4, 3, 3), IllegalArgumentException);
    EXPECT_THROW(VertexArray(4, 3, 4), IllegalArgumentException);
}

TEST(VertexArray, ByteSetGetRoundTrip) {
    Ref<VertexArray> a = new VertexArray(3, 2, 1);
    a->set(1, 2, Bytes{1, -2, 3, -128});
    Bytes out(6, 55);
    a->get(0, 3, out);
    EXPECT_EQ(out, (Bytes{0, 0, 1, -2, 3, -128}));
    Bytes part(2, 0);
    a->get(2, 1, part);
    EXPECT_EQ(part, (Bytes{3, -128}));
}

TEST(VertexArray, ShortSetGetRoundTrip) {
    Ref<VertexArray> a = new VertexArray(2, 4, 2);
    a->set(0, 2, Shorts{1, -1, 32767, -32768, 5, 6, 7, 8, 99});  // longer array: extra ignored
    Shorts out(8);
    a->get(0, 2, out);
    EXPECT_EQ(out, (Shorts{1, -1, 32767, -32768, 5, 6, 7, 8}));
}

TEST(VertexArray, ZeroCountIsAllowedUpToTheEnd) {
    Ref<VertexArray> a = new VertexArray(3, 2, 1);
    Bytes none(1);
    EXPECT_NO_THROW(a->set(3, 0, none));
    EXPECT_NO_THROW(a->get(0, 0, std::span<std::int8_t>(none.data(), 0)));
}

TEST(VertexArray, WrongComponentSizeIsIllegalState) {
    Ref<VertexArray> b = new VertexArray(2, 2, 1);
    Ref<VertexArray> s = new VertexArray(2, 2, 2);
    Shorts sv(4);
    Bytes bv(4);
    EXPECT_THROW(b->set(0, 2, std::span<const std::int16_t>(sv)), IllegalStateException);
    EXPECT_THROW(b->get(0, 2, std::span<std::int16_t>(sv)), IllegalStateException);
    EXPECT_THROW(s->set(0, 2, std::span<const std::int8_t>(bv)), IllegalStateException);
    EXPECT_THROW(s->get(0, 2, std::span<std::int8_t>(bv)), IllegalStateException);
}

TEST(VertexArray, RangeChecks) {
    Ref<VertexArray> a = new VertexArray(4, 3, 1);
    Bytes v(30);
    EXPECT_THROW(a->set(-1, 1, v), IndexOutOfBoundsException);
    EXPECT_THROW(a->set(2, 3, v), IndexOutOfBoundsException);
    EXPECT_THROW(a->set(4, 1, v), IndexOutOfBoundsException);
    EXPECT_THROW(a->get(-1, 1, std::span<std::int8_t>(v)), IndexOutOfBoundsException);
    EXPECT_THROW(a->get(3, 2, std::span<std::int8_t>(v)), IndexOutOfBoundsException);
    EXPECT_THROW(a->set(0, -1, v), IllegalArgumentException);
    EXPECT_THROW(a->get(0, -1, std::span<std::int8_t>(v)), IllegalArgumentException);
    Bytes shortArr(5);  // 2 vertices need 6 values
    EXPECT_THROW(a->set(0, 2, shortArr), IllegalArgumentException);
    EXPECT_THROW(a->get(0, 2, std::span<std::int8_t>(shortArr)), IllegalArgumentException);
}

TEST(VertexArray, NullArraysThrowNullPointer) {
    Ref<VertexArray> b = new VertexArray(2, 2, 1);
    Ref<VertexArray> s = new VertexArray(2, 2, 2);
    EXPECT_THROW(b->set(0, 1, std::span<const std::int8_t>()), NullPointerException);
    EXPECT_THROW(b->get(0, 1, std::span<std::int8_t>()), NullPointerException);
    EXPECT_THROW(s->set(0, 1, std::span<const std::int16_t>()), NullPointerException);
    EXPECT_THROW(s->get(0, 1, std::span<std::int16_t>()), NullPointerException);
}

TEST(VertexArray, SetTouchesGetDoesNot) {
    Ref<VertexArray> a = new VertexArray(2, 2, 1);
    const auto r0 = a->getRevision();
    a->set(0, 1, Bytes{1, 2});
    const auto r1 = a->getRevision();
    EXPECT_GT(r1, r0);
    Bytes out(4);
    a->get(0, 2, out);
    EXPECT_EQ(a->getRevision(), r1);
    Ref<VertexArray> s = new VertexArray(2, 2, 2);
    const auto s0 = s->getRevision();
    s->set(0, 1, Shorts{1, 2});
    EXPECT_GT(s->getRevision(), s0);
}

TEST(VertexArray, EngineDataAndFloats) {
    Ref<VertexArray> b = new VertexArray(2, 3, 1);
    b->set(0, 2, Bytes{1, -2, 3, 4, 5, -6});
    const auto* raw = static_cast<const std::int8_t*>(b->data());
    EXPECT_EQ(raw[1], -2);
    EXPECT_EQ(raw[5], -6);
    EXPECT_EQ(b->value(1, 2), -6);
    std::vector<float> f(3, 0.0f);
    b->getFloats(1, 1, f);
    EXPECT_EQ(f, (std::vector<float>{4.0f, 5.0f, -6.0f}));
    EXPECT_THROW(b->getFloats(1, 2, f), IndexOutOfBoundsException);
    EXPECT_THROW(b->getFloats(0, 2, f), IllegalArgumentException);

    Ref<VertexArray> s = new VertexArray(1, 2, 2);
    s->set(0, 1, Shorts{-300, 1000});
    const auto* sraw = static_cast<const std::int16_t*>(s->data());
    EXPECT_EQ(sraw[0], -300);
    std::vector<float> g(2);
    s->getFloats(0, 1, g);
    EXPECT_EQ(g, (std::vector<float>{-300.0f, 1000.0f}));
}

TEST(VertexArray, DuplicateCopiesValuesIndependently) {
    Ref<VertexArray> a = new VertexArray(2, 2, 2);
    a->set(0, 2, Shorts{1, 2, 3, 4});
    a->setUserID(42);
    Ref<VertexArray> c = dynamicCast<VertexArray>(a->duplicate());
    ASSERT_TRUE(c);
    EXPECT_NE(c.get(), a.get());
    EXPECT_EQ(c->getUserID(), 42);
    EXPECT_EQ(c->getVertexCount(), 2);
    EXPECT_EQ(c->getComponentCount(), 2);
    EXPECT_EQ(c->getComponentType(), 2);
    Shorts out(4);
    c->get(0, 2, out);
    EXPECT_EQ(out, (Shorts{1, 2, 3, 4}));
    c->set(0, 1, Shorts{9, 9});
    a->get(0, 2, out);
    EXPECT_EQ(out, (Shorts{1, 2, 3, 4}));
}

// ---- Transform::transform(VertexArray, float[], boolean) ----

namespace {
Transform translateScale() {
    Transform t;
    t.postTranslate(10, 20, 30);
    t.postScale(2, 2, 2);  // M = T * S: v -> 2v + (10, 20, 30) w
    return t;
}
}  // namespace

TEST(TransformVertexArray, ThreeComponentsWithAndWithoutW) {
    Ref<VertexArray> a = new VertexArray(2, 3, 2);
    a->set(0, 2, Shorts{1, 2, 3, -1, 0, 5});
    const Transform t = translateScale();
    std::vector<float> out(8, -7.0f);
    t.transform(a, out, true);
    EXPECT_EQ(out, (std::vector<float>{12, 24, 36, 1, 8, 20, 40, 1}));
    t.transform(a, out, false);
    EXPECT_EQ(out, (std::vector<float>{2, 4, 6, 0, -2, 0, 10, 0}));
}

TEST(TransformVertexArray, TwoComponentsPadZWithZero) {
    Ref<VertexArray> a = new VertexArray(1, 2, 1);
    a->set(0, 1, Bytes{5, -6});
    const Transform t = translateScale();
    std::vector<float> out(5, -7.0f);  // longer than needed: the tail is untouched
    t.transform(a, out, true);
    EXPECT_EQ(out, (std::vector<float>{20, 8, 30, 1, -7}));
}

TEST(TransformVertexArray, RawValuesOnly) {
    // A generic matrix to check every element: rows (1 2 3 4), (5 6 7 8), (9 10 11 12), (0 0 0 1).
    Transform t;
    const float rows[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 0, 0, 0, 1};
    t.set(rows);
    Ref<VertexArray> a = new VertexArray(1, 3, 1);
    a->set(0, 1, Bytes{1, 1, 1});
    std::vector<float> out(4);
    t.transform(a, out, true);
    EXPECT_EQ(out, (std::vector<float>{10, 26, 42, 1}));
}

TEST(TransformVertexArray, Errors) {
    const Transform t;
    Ref<VertexArray> a3 = new VertexArray(2, 3, 1);
    Ref<VertexArray> a4 = new VertexArray(2, 4, 1);
    std::vector<float> out(8);
    EXPECT_THROW(t.transform(nullptr, out, true), NullPointerException);
    EXPECT_THROW(t.transform(a3, std::span<float>(), true), NullPointerException);
    EXPECT_THROW(t.transform(a4, out, true), IllegalArgumentException);
    std::vector<float> tooShort(7);
    EXPECT_THROW(t.transform(a3, tooShort, false), IllegalArgumentException);
}
