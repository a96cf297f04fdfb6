// IndexBuffer / TriangleStripArray (JSR-184 1.1, IndexBuffer and
// TriangleStripArray). Expected triangle lists are written out by hand from
// the strip rule: triangle j of a strip is
// (s[j], s[j+1], s[j+2]) for even j and (s[j], s[j+2], s[j+1]) for odd j.
#include <gtest/gtest.h>

#include <vector>

#include <m3g/TriangleStripArray.h>

using namespace m3g;
using Ints = std::vector<int>;

namespace {
Ints indicesOf(const IndexBuffer& ib) {
    Ints out(static_cast<std::size_t>(ib.getIndexCount()));
    ib.getIndices(out);
    return out;
}
}  // namespace

TEST(TriangleStripArray, ImplicitSingleStrip) {
    const int lengths[] = {5};
    Ref<TriangleStripArray> t = new TriangleStripArray(0, lengths);
    EXPECT_EQ(t->getIndexCount(), 9);  // 3 * (5 - 2)
    EXPECT_EQ(indicesOf(*t), (Ints{0, 1, 2, 1, 3, 2, 2, 3, 4}));
    EXPECT_STREQ(t->getClassName(), "TriangleStripArray");
    EXPECT_EQ(t->getReferences(), 0);
}

TEST(TriangleStripArray, ImplicitStripsContinueFromFirstIndex) {
    const int lengths[] = {3, 4};
    Ref<TriangleStripArray> t = new TriangleStripArray(10, lengths);
    EXPECT_EQ(t->getIndexCount(), 9);  // 3 * (1 + 2)
    // Strip 1: 10 11 12; strip 2: 13 14 15 16 (each strip starts even).
    EXPECT_EQ(indicesOf(*t), (Ints{10, 11, 12, 13, 14, 15, 14, 16, 15}));
    EXPECT_EQ(t->maxIndex(), 16);
    EXPECT_EQ(Ints(t->stripIndices().begin(), t->stripIndices().end()), (Ints{10, 11, 12, 13, 14, 15, 16}));
    EXPECT_EQ(Ints(t->stripLengths().begin(), t->stripLengths().end()), (Ints{3, 4}));
}

TEST(TriangleStripArray, ExplicitStripsKeepDegenerateTriangles) {
    const int indices[] = {7, 3, 9, 1, 5, 5, 6};
    const int lengths[] = {4, 3};
    Ref<TriangleStripArray> t = new TriangleStripArray(indices, lengths);
    EXPECT_EQ(t->getIndexCount(), 9);
    EXPECT_EQ(indicesOf(*t), (Ints{7, 3, 9, 3, 1, 9, 5, 5, 6}));
    EXPECT_EQ(t->maxIndex(), 9);
    auto tri = t->triangleIndices();
    EXPECT_EQ(Ints(tri.begin(), tri.end()), indicesOf(*t));
}

TEST(TriangleStripArray, LongStripAlternatesWinding) {
    const int indices[] = {0, 1, 2, 3, 4, 5};
    const int lengths[] = {6};
    Ref<TriangleStripArray> t = new TriangleStripArray(indices, lengths);
    EXPECT_EQ(indicesOf(*t), (Ints{0, 1, 2, 1, 3, 2, 2, 3, 4, 3, 5, 4}));
}

TEST(TriangleStripArray, GetIndicesChecks) {
    const int lengths[] = {4};
    Ref<TriangleStripArray> t = new TriangleStripArray(0, lengths);
    EXPECT_THROW(t->getIndices(std::span<int>()), NullPointerException);
    Ints tooShort(5);
    EXPECT_THROW(t->getIndices(tooShort), IllegalArgumentException);
    Ints longer(8, -1);
    t->getIndices(longer);
    EXPECT_EQ(longer, (Ints{0, 1, 2, 1, 3, 2, -1, -1}));
}

TEST(TriangleStripArray, ImplicitErrors) {
    const int ok[] = {3};
    const int two[] = {3, 2};
    const int dummy[] = {3};
    EXPECT_THROW(TriangleStripArray(0, std::span<const int>()), NullPointerException);
    EXPECT_THROW(TriangleStripArray(0, std::span<const int>(dummy, 0)), IllegalArgumentException);
    EXPECT_THROW(TriangleStripArray(0, two), IllegalArgumentException);
    EXPECT_THROW(TriangleStripArray(-1, ok), IndexOutOfBoundsException);
    EXPECT_THROW(TriangleStripArray(65533, ok), IndexOutOfBoundsException);  // 65533 + 3 > 65535
    EXPECT_NO_THROW(TriangleStripArray(65532, ok));                          // 65532 + 3 == 65535
}

TEST(TriangleStripArray, ExplicitErrors) {
    const int idx[] = {0, 1, 2, 3};
    const int len3[] = {3};
    const int len4[] = {4};
    const int len2[] = {2};
    const int len5[] = {5};
    EXPECT_THROW(TriangleStripArray(std::span<const int>(), len3), NullPointerException);
    EXPECT_THROW(TriangleStripArray(idx, std::span<const int>()), NullPointerException);
    EXPECT_THROW(TriangleStripArray(idx, std::span<const int>(len3, 0)), IllegalArgumentException);
    EXPECT_THROW(TriangleStripArray(idx, len2), IllegalArgumentException);
    EXPECT_THROW(TriangleStripArray(idx, len5), IllegalArgumentException);  // 4 indices < 5
    EXPECT_NO_THROW(TriangleStripArray(idx, len4));
    const int negative[] = {0, -1, 2};
    const int tooBig[] = {0, 65536, 2};
    const int maxOk[] = {0, 65535, 2};
    EXPECT_THROW(TriangleStripArray(negative, len3), IndexOutOfBoundsException);
    EXPECT_THROW(TriangleStripArray(tooBig, len3), IndexOutOfBoundsException);
    EXPECT_NO_THROW(TriangleStripArray(maxOk, len3));
    // Entries past sum(stripLengths) are not used, hence not checked.
    const int trailing[] = {0, 1, 2, -5};
    EXPECT_NO_THROW(TriangleStripArray(trailing, len3));
}

TEST(TriangleStripArray, DuplicateCopiesIndices) {
    const int indices[] = {4, 5, 6, 7};
    const int lengths[] = {4};
    Ref<TriangleStripArray> t = new TriangleStripArray(indices, lengths);
    t->setUserID(3);
    Ref<TriangleStripArray> d = dynamicCast<TriangleStripArray>(t->duplicate());
    ASSERT_TRUE(d);
    EXPECT_NE(d.get(), t.get());
    EXPECT_EQ(d->getUserID(), 3);
    EXPECT_EQ(indicesOf(*d), (Ints{4, 5, 6, 5, 7, 6}));
    EXPECT_EQ(d->maxIndex(), 7);
    Ref<IndexBuffer> asBase = d;
    EXPECT_EQ(asBase->getIndexCount(), 6);
}
