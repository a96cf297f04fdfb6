// tools/m3g/Suggest: the did-you-mean of the m3g tool.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "Suggest.h"

using m3gcli::closestName;
using m3gcli::editDistance;

TEST(Suggest, EditDistance) {
    EXPECT_EQ(editDistance("", ""), 0u);
    EXPECT_EQ(editDistance("abc", ""), 3u);
    EXPECT_EQ(editDistance("render", "render"), 0u);
    EXPECT_EQ(editDistance("rendr", "render"), 1u);    // deletion
    EXPECT_EQ(editDistance("renderr", "render"), 1u);  // insertion
    EXPECT_EQ(editDistance("rander", "render"), 1u);   // substitution
    EXPECT_EQ(editDistance("szie", "size"), 1u);       // neighbours swapped
    EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
}

TEST(Suggest, ClosestCommand) {
    const std::vector<std::string> commands{"info", "convert", "render", "compare", "export", "pick", "view", "bench"};
    EXPECT_EQ(closestName("rendr", commands), "render");
    EXPECT_EQ(closestName("comapre", commands), "compare");
    EXPECT_EQ(closestName("inof", commands), "info");
    EXPECT_EQ(closestName("expor", commands), "export");
    EXPECT_EQ(closestName("conv", commands), "convert");  // the start of one command
    EXPECT_FALSE(closestName("frobnicate", commands));
    EXPECT_FALSE(closestName("x", commands));
    EXPECT_FALSE(closestName("", commands));
    EXPECT_FALSE(closestName("rendr", {}));
}

TEST(Suggest, ClosestOption) {
    const std::vector<std::string> options{"-h", "--help", "-o", "--output", "--size", "--time", "--turntable",
                                           "--threshold"};
    EXPECT_EQ(closestName("--szie", options), "--size");
    EXPECT_EQ(closestName("--szie=64x48", options), "--size");  // the value is not part of the name
    EXPECT_EQ(closestName("--tim", options), "--time");
    EXPECT_EQ(closestName("--turn", options), "--turntable");
    EXPECT_EQ(closestName("--outptu", options), "--output");
    EXPECT_EQ(closestName("-output", options), "--output");  // dashes are not counted
    EXPECT_FALSE(closestName("--frobnicate", options));
    EXPECT_FALSE(closestName("-x", options));
}
