// ImageCoverage (m3g compare --coverage): covered pixels by alpha or by key
// colour, counts, intersection over union, limits, the diff image and the
// key colour's parsing. Expectations come from how the test images are built.
#include <gtest/gtest.h>

#include <stdexcept>

#include "ImageCoverage.h"

using namespace m3gcli;

namespace {

RgbaImage filled(int w, int h, std::array<std::uint8_t, 4> rgba) {
    RgbaImage img;
    img.width = w;
    img.height = h;
    img.pixels.resize(static_cast<std::size_t>(w) * h * 4);
    for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = rgba[i % 4];
    return img;
}

/// Paints the rectangle [x0, x1) x [y0, y1) with `rgba`.
void paint(RgbaImage& img, int x0, int y0, int x1, int y1, std::array<std::uint8_t, 4> rgba) {
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            for (int k = 0; k < 4; ++k) img.pixels[static_cast<std::size_t>((y * img.width + x) * 4 + k)] = rgba[k];
}

const CoverageKey kMagenta = std::array<std::uint8_t, 3>{255, 0, 255};

}  // namespace

TEST(ImageCoverage, AlphaZeroIsBackgroundWithoutKey) {
    const std::uint8_t clear[4] = {255, 255, 255, 0}, opaque[4] = {0, 0, 0, 255}, faint[4] = {0, 0, 0, 1};
    EXPECT_FALSE(isCovered(clear, std::nullopt));
    EXPECT_TRUE(isCovered(opaque, std::nullopt));
    EXPECT_TRUE(isCovered(faint, std::nullopt));
}

TEST(ImageCoverage, KeyColourIsBackgroundWhateverTheAlpha) {
    const std::uint8_t key[4] = {255, 0, 255, 255}, keyClear[4] = {255, 0, 255, 0}, nearKey[4] = {255, 1, 255, 255},
                       blackClear[4] = {0, 0, 0, 0};
    EXPECT_FALSE(isCovered(key, kMagenta));
    EXPECT_FALSE(isCovered(keyClear, kMagenta));
    EXPECT_TRUE(isCovered(nearKey, kMagenta));
    // A renderer that writes alpha 0 over drawn pixels (a material with
    // alpha 0, no blending) still covers them by colour.
    EXPECT_TRUE(isCovered(blackClear, kMagenta));
}

TEST(ImageCoverage, CountsAndIntersectionOverUnion) {
    // A: a 4x4 square at (2,2); B: the same square moved one pixel right.
    // Both: 3x4 = 12; A only: one column of 4; B only: one column of 4.
    RgbaImage a = filled(10, 8, {255, 0, 255, 255}), b = a;
    paint(a, 2, 2, 6, 6, {10, 20, 30, 255});
    paint(b, 3, 2, 7, 6, {200, 100, 50, 255});  // other colour: coverage only
    const CoverageComparison c = compareCoverage(a, b, kMagenta);
    EXPECT_EQ(c.total, 80);
    EXPECT_EQ(c.coveredA, 16);
    EXPECT_EQ(c.coveredB, 16);
    EXPECT_EQ(c.both, 12);
    EXPECT_EQ(c.differing, 8);
    EXPECT_DOUBLE_EQ(c.share, 8.0 / 80.0);
    EXPECT_DOUBLE_EQ(c.iou, 12.0 / 20.0);
    EXPECT_TRUE(withinCoverageLimits(c, 0.1, 0.6));
    EXPECT_FALSE(withinCoverageLimits(c, 0.09, 0.6));
    EXPECT_FALSE(withinCoverageLimits(c, 0.1, 0.61));
}

TEST(ImageCoverage, IdenticalSilhouettesInDifferentColoursAgreeExactly) {
    RgbaImage a = filled(6, 6, {0, 0, 0, 0}), b = a;
    paint(a, 1, 1, 5, 4, {255, 0, 0, 255});
    paint(b, 1, 1, 5, 4, {0, 0, 255, 128});
    const CoverageComparison c = compareCoverage(a, b, std::nullopt);
    EXPECT_EQ(c.both, 12);
    EXPECT_EQ(c.differing, 0);
    EXPECT_DOUBLE_EQ(c.iou, 1.0);
}

TEST(ImageCoverage, NothingCoveredInEitherIsFullAgreement) {
    const RgbaImage a = filled(3, 3, {255, 0, 255, 255});
    const CoverageComparison c = compareCoverage(a, a, kMagenta);
    EXPECT_EQ(c.coveredA, 0);
    EXPECT_DOUBLE_EQ(c.iou, 1.0);
    EXPECT_DOUBLE_EQ(c.share, 0.0);
}

TEST(ImageCoverage, OneEmptyImageHasZeroOverlap) {
    RgbaImage a = filled(4, 4, {255, 0, 255, 255}), b = a;
    paint(b, 0, 0, 2, 2, {1, 2, 3, 255});
    const CoverageComparison c = compareCoverage(a, b, kMagenta);
    EXPECT_EQ(c.differing, 4);
    EXPECT_DOUBLE_EQ(c.iou, 0.0);
}

TEST(ImageCoverage, DifferentSizesAreRefused) {
    EXPECT_THROW(compareCoverage(filled(2, 2, {}), filled(2, 3, {}), std::nullopt), std::invalid_argument);
}

TEST(ImageCoverage, DiffImageMarksWhereEachCovers) {
    RgbaImage a = filled(4, 1, {255, 0, 255, 255}), b = a;
    paint(a, 0, 0, 2, 1, {9, 9, 9, 255});  // A covers x = 0, 1
    paint(b, 1, 0, 3, 1, {9, 9, 9, 255});  // B covers x = 1, 2
    const RgbaImage d = coverageDiffImage(a, b, kMagenta);
    const auto px = [&](int x) {
        return std::array<int, 4>{d.pixels[x * 4], d.pixels[x * 4 + 1], d.pixels[x * 4 + 2], d.pixels[x * 4 + 3]};
    };
    EXPECT_EQ(px(0), (std::array<int, 4>{255, 0, 0, 255}));      // A only: red
    EXPECT_EQ(px(1), (std::array<int, 4>{255, 255, 255, 255}));  // both: white
    EXPECT_EQ(px(2), (std::array<int, 4>{0, 255, 0, 255}));      // B only: green
    EXPECT_EQ(px(3), (std::array<int, 4>{40, 40, 40, 255}));     // neither
}

TEST(ImageCoverage, ReportNamesTheBackgroundAndTheVerdict) {
    RgbaImage a = filled(10, 10, {255, 0, 255, 255}), b = a;
    paint(a, 0, 0, 5, 5, {1, 1, 1, 255});
    paint(b, 0, 0, 5, 4, {1, 1, 1, 255});
    const CoverageComparison c = compareCoverage(a, b, kMagenta);  // 25 vs 20: IoU 0.8, 5% differ
    const std::string pass = coverageReport(c, kMagenta, 0.05, 0.8);
    EXPECT_NE(pass.find("background: colour FF00FF"), std::string::npos) << pass;
    EXPECT_NE(pass.find("25 in A, 20 in B, 20 in both"), std::string::npos) << pass;
    EXPECT_NE(pass.find("5 of 100 (5.000%)"), std::string::npos) << pass;
    EXPECT_NE(pass.find("intersection over union: 0.8000"), std::string::npos) << pass;
    EXPECT_NE(pass.find("PASS"), std::string::npos) << pass;
    EXPECT_NE(coverageReport(c, std::nullopt, 0.05, 0.81).find("background: alpha 0"), std::string::npos);
    EXPECT_NE(coverageReport(c, kMagenta, 0.05, 0.81).find("FAIL"), std::string::npos);
}

TEST(ImageCoverage, KeyColourParsing) {
    EXPECT_EQ(parseKeyColor("FF00ff"), kMagenta);
    EXPECT_EQ(parseKeyColor("102030"), (CoverageKey{std::array<std::uint8_t, 3>{0x10, 0x20, 0x30}}));
    EXPECT_FALSE(parseKeyColor("FF00FFFF"));  // RRGGBBAA: alpha is not part of a key
    EXPECT_FALSE(parseKeyColor("GG0000"));
    EXPECT_FALSE(parseKeyColor(""));
    EXPECT_FALSE(parseKeyColor("magenta"));
}
