// skin::InfluenceTable: per-vertex top-N bone influences (JSR-184 1.1,
// SkinnedMesh.addTransform).
// Every expected weight below is computed by hand from the integer weights.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include <m3g/skin/InfluenceTable.h>

using m3g::skin::InfluenceTable;

TEST(InfluenceTable, StartsEmpty) {
    InfluenceTable t(4);
    EXPECT_EQ(t.maxInfluences(), 4);
    EXPECT_EQ(t.vertexCount(), 0);
    EXPECT_EQ(t.boneCount(), 0);
    EXPECT_EQ(t.count(0), 0);
    EXPECT_TRUE(t.bones().empty());
    EXPECT_TRUE(t.weights().empty());
}

TEST(InfluenceTable, RejectsInvalidArguments) {
    EXPECT_THROW(InfluenceTable(0), std::invalid_argument);
    InfluenceTable t(2);
    EXPECT_THROW(t.add(-1, 1, 0, 1), std::invalid_argument);
    EXPECT_THROW(t.add(0, 0, 0, 1), std::invalid_argument);
    EXPECT_THROW(t.add(0, 1, -1, 1), std::invalid_argument);
    EXPECT_THROW(t.add(0, 1, 0, 0), std::invalid_argument);
    EXPECT_THROW(t.add(0, 1, 65535, 1), std::invalid_argument);
    EXPECT_THROW(t.add(0, 1, 2000000000, 2000000000), std::invalid_argument);  // no int overflow
    EXPECT_EQ(t.vertexCount(), 0);
}

TEST(InfluenceTable, GrowsToTheHighestVertexAndLeavesOthersEmpty) {
    InfluenceTable t(3);
    t.add(0, 7, 2, 3);  // vertices 2, 3, 4
    EXPECT_EQ(t.vertexCount(), 5);
    EXPECT_EQ(t.boneCount(), 1);
    EXPECT_EQ(t.bones().size(), 15u);
    EXPECT_EQ(t.weights().size(), 15u);
    EXPECT_EQ(t.count(0), 0);
    EXPECT_EQ(t.count(1), 0);
    EXPECT_EQ(t.count(5), 0);  // beyond the table
    for (int v = 2; v <= 4; ++v) {
        EXPECT_EQ(t.count(v), 1);
        EXPECT_EQ(t.bone(v, 0), 0);
        EXPECT_FLOAT_EQ(t.weight(v, 0), 1.0f);
        EXPECT_EQ(t.bone(v, 1), -1);
        EXPECT_FLOAT_EQ(t.weight(v, 1), 0.0f);
    }
    t.add(0, 1, 65534, 1);  // last vertex allowed
    EXPECT_EQ(t.vertexCount(), 65535);
}

TEST(InfluenceTable, SameBoneAccumulatesIntoOneSlot) {
    InfluenceTable t(4);
    t.add(0, 2, 0, 2);  // v0: b0=2, v1: b0=2
    t.add(1, 3, 0, 2);  // v0: b0=2 b1=3, v1: same
    t.add(0, 4, 1, 1);  // v1: b0=6 b1=3
    EXPECT_EQ(t.count(0), 2);
    EXPECT_EQ(t.count(1), 2);
    // v0: sorted by weight, b1 (3/5) before b0 (2/5).
    EXPECT_EQ(t.bone(0, 0), 1);
    EXPECT_FLOAT_EQ(t.weight(0, 0), 0.6f);
    EXPECT_EQ(t.bone(0, 1), 0);
    EXPECT_FLOAT_EQ(t.weight(0, 1), 0.4f);
    // v1: b0 = 6 of 9, b1 = 3 of 9.
    EXPECT_EQ(t.bone(1, 0), 0);
    EXPECT_FLOAT_EQ(t.weight(1, 0), 6.0f / 9.0f);
    EXPECT_EQ(t.bone(1, 1), 1);
    EXPECT_FLOAT_EQ(t.weight(1, 1), 3.0f / 9.0f);
}

TEST(InfluenceTable, KeepsTheNLargestWhenMoreThanNBones) {
    InfluenceTable t(2);
    t.add(0, 1, 0, 1);
    t.add(1, 3, 0, 1);
    t.add(2, 2, 0, 1);  // b0 (1) is the smallest: dropped
    EXPECT_EQ(t.count(0), 2);
    EXPECT_EQ(t.bone(0, 0), 1);
    EXPECT_FLOAT_EQ(t.weight(0, 0), 0.6f);  // 3 / (3 + 2)
    EXPECT_EQ(t.bone(0, 1), 2);
    EXPECT_FLOAT_EQ(t.weight(0, 1), 0.4f);  // 2 / (3 + 2)
    EXPECT_EQ(t.boneVertices(0, nullptr, nullptr), 0);
    EXPECT_EQ(t.boneCount(), 3);
}

TEST(InfluenceTable, NewSmallerBoneDoesNotEvict) {
    InfluenceTable t(2);
    t.add(0, 5, 0, 1);
    t.add(1, 4, 0, 1);
    t.add(2, 1, 0, 1);
    EXPECT_EQ(t.bone(0, 0), 0);
    EXPECT_EQ(t.bone(0, 1), 1);
    EXPECT_FLOAT_EQ(t.weight(0, 0), 5.0f / 9.0f);
    EXPECT_FLOAT_EQ(t.weight(0, 1), 4.0f / 9.0f);
}

TEST(InfluenceTable, NormalisesOverTheSelectedNOnly) {
    InfluenceTable t(2);
    t.add(0, 5, 0, 1);
    t.add(1, 3, 0, 1);
    t.add(2, 2, 0, 1);
    // Selected b0 (5) and b1 (3): 5/8 and 3/8, not 5/10 and 3/10.
    EXPECT_FLOAT_EQ(t.weight(0, 0), 0.625f);
    EXPECT_FLOAT_EQ(t.weight(0, 1), 0.375f);
    EXPECT_FLOAT_EQ(t.weight(0, 0) + t.weight(0, 1), 1.0f);
}

TEST(InfluenceTable, TiesGoToTheLowerBoneIndex) {
    // Documented rule: among equal accumulated weights the lower bone index
    // (the bone registered first) wins, whatever order the vertex saw them.
    InfluenceTable t(2);
    t.add(2, 2, 0, 1);
    t.add(0, 2, 0, 1);
    t.add(1, 2, 0, 1);
    EXPECT_EQ(t.count(0), 2);
    EXPECT_EQ(t.bone(0, 0), 0);
    EXPECT_EQ(t.bone(0, 1), 1);
    EXPECT_FLOAT_EQ(t.weight(0, 0), 0.5f);
    EXPECT_FLOAT_EQ(t.weight(0, 1), 0.5f);

    // Ties within the kept slots are ordered by bone index too.
    InfluenceTable u(4);
    u.add(3, 1, 0, 1);
    u.add(1, 1, 0, 1);
    EXPECT_EQ(u.bone(0, 0), 1);
    EXPECT_EQ(u.bone(0, 1), 3);
}

TEST(InfluenceTable, EvictedBoneThatGrowsPastAKeptOneComesBack) {
    InfluenceTable t(2);
    t.add(0, 5, 0, 1);
    t.add(1, 4, 0, 1);
    t.add(2, 3, 0, 1);  // kept {b0 5, b1 4}, b2 (3) out
    EXPECT_EQ(t.bone(0, 0), 0);
    EXPECT_EQ(t.bone(0, 1), 1);
    t.add(2, 3, 0, 1);  // b2 accumulates to 6 although it was not kept
    EXPECT_EQ(t.bone(0, 0), 2);
    EXPECT_FLOAT_EQ(t.weight(0, 0), 6.0f / 11.0f);
    EXPECT_EQ(t.bone(0, 1), 0);
    EXPECT_FLOAT_EQ(t.weight(0, 1), 5.0f / 11.0f);
    t.add(1, 3, 0, 1);  // b1 (evicted at 4) grows to 7
    EXPECT_EQ(t.bone(0, 0), 1);
    EXPECT_FLOAT_EQ(t.weight(0, 0), 7.0f / 13.0f);
    EXPECT_EQ(t.bone(0, 1), 2);
    EXPECT_FLOAT_EQ(t.weight(0, 1), 6.0f / 13.0f);
    EXPECT_EQ(t.boneVertices(0, nullptr, nullptr), 0);
}

TEST(InfluenceTable, SingleInfluencePerVertex) {
    InfluenceTable t(1);
    t.add(0, 1, 0, 1);
    t.add(1, 2, 0, 1);
    EXPECT_EQ(t.count(0), 1);
    EXPECT_EQ(t.bone(0, 0), 1);
    EXPECT_FLOAT_EQ(t.weight(0, 0), 1.0f);
    t.add(0, 2, 0, 1);  // b0 = 3 > 2
    EXPECT_EQ(t.bone(0, 0), 0);
    EXPECT_FLOAT_EQ(t.weight(0, 0), 1.0f);
}

TEST(InfluenceTable, BoneVerticesListsVerticesInOrderWithNormalisedWeights) {
    InfluenceTable t(4);
    t.add(0, 1, 0, 4);  // vertices 0..3
    t.add(1, 3, 2, 4);  // vertices 2..5
    std::vector<int> v;
    std::vector<float> w;
    EXPECT_EQ(t.boneVertices(0, &v, &w), 4);
    EXPECT_EQ(v, (std::vector<int>{0, 1, 2, 3}));
    ASSERT_EQ(w.size(), 4u);
    EXPECT_FLOAT_EQ(w[0], 1.0f);
    EXPECT_FLOAT_EQ(w[1], 1.0f);
    EXPECT_FLOAT_EQ(w[2], 0.25f);
    EXPECT_FLOAT_EQ(w[3], 0.25f);
    v.clear();
    w.clear();
    EXPECT_EQ(t.boneVertices(1, &v, &w), 4);
    EXPECT_EQ(v, (std::vector<int>{2, 3, 4, 5}));
    EXPECT_FLOAT_EQ(w[0], 0.75f);
    EXPECT_FLOAT_EQ(w[1], 0.75f);
    EXPECT_FLOAT_EQ(w[2], 1.0f);
    EXPECT_FLOAT_EQ(w[3], 1.0f);
    EXPECT_EQ(t.boneVertices(7, nullptr, nullptr), 0);
}

TEST(InfluenceTable, SoAArraysMatchTheAccessors) {
    InfluenceTable t(2);
    t.add(0, 1, 0, 2);
    t.add(1, 1, 1, 1);
    const auto b = t.bones();
    const auto w = t.weights();
    ASSERT_EQ(b.size(), 4u);
    EXPECT_EQ(b[0], 0);
    EXPECT_EQ(b[1], -1);
    EXPECT_EQ(b[2], 0);
    EXPECT_EQ(b[3], 1);
    EXPECT_FLOAT_EQ(w[0], 1.0f);
    EXPECT_FLOAT_EQ(w[1], 0.0f);
    EXPECT_FLOAT_EQ(w[2], 0.5f);
    EXPECT_FLOAT_EQ(w[3], 0.5f);
}

TEST(InfluenceTable, RevisionCountsAdds) {
    InfluenceTable t(2);
    const auto r0 = t.revision();
    t.add(0, 1, 0, 1);
    t.add(0, 1, 0, 1);
    EXPECT_EQ(t.revision(), r0 + 2);
}
