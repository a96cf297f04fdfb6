// The viewer's texture inspector logic (tools/m3g/viewer/TextureInspector.h):
// texel values as the Image2D stores them (format order, palette index),
// zoom levels, and which texel lies under a screen point.
#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

#include <m3g/m3g.h>

#include "TextureInspector.h"

using namespace m3g;
using m3gview::Rect;
using m3gview::TextureInspector;
using m3gview::texelAt;

TEST(TextureInspector, TexelsAreReadInTheImagesFormat) {
    // 3x2 RGB, rows top to bottom: texel (x, y) = (10x + y, 100 + x, 200 + y).
    std::vector<std::uint8_t> rgb;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x) rgb.insert(rgb.end(), {std::uint8_t(10 * x + y), std::uint8_t(100 + x), std::uint8_t(200 + y)});
    Image2D image(Image2D::RGB, 3, 2, rgb);
    const auto t = texelAt(image, 2, 1);
    ASSERT_TRUE(t);
    EXPECT_EQ(t->channels, (std::vector<int>{21, 102, 201}));
    EXPECT_EQ(t->paletteIndex, -1);
    EXPECT_EQ(t->describe(), "(2, 1) RGB 21 102 201");
    EXPECT_FALSE(texelAt(image, 3, 0));
    EXPECT_FALSE(texelAt(image, 0, -1));

    const std::uint8_t la[] = {1, 2, 3, 4, 5, 6, 7, 8};  // 2x2 LUMINANCE_ALPHA
    Image2D lumAlpha(Image2D::LUMINANCE_ALPHA, 2, 2, la);
    EXPECT_EQ(texelAt(lumAlpha, 1, 1)->describe(), "(1, 1) LUMINANCE_ALPHA 7 8");
    const std::uint8_t a[] = {9, 200};
    Image2D alpha(Image2D::ALPHA, 2, 1, a);
    EXPECT_EQ(texelAt(alpha, 1, 0)->describe(), "(1, 0) ALPHA 200");
}

TEST(TextureInspector, APalettedTexelGivesItsIndexAndEntry) {
    const std::uint8_t indices[] = {0, 2, 1, 2};
    const std::uint8_t palette[] = {10, 11, 12, 13, 20, 21, 22, 23, 30, 31, 32, 33};  // 3 RGBA entries
    Image2D image(Image2D::RGBA, 2, 2, indices, palette);
    const auto t = texelAt(image, 1, 0);
    ASSERT_TRUE(t);
    EXPECT_EQ(t->paletteIndex, 2);
    EXPECT_EQ(t->describe(), "(1, 0) RGBA index 2 -> 30 31 32 33");
}

TEST(TextureInspector, ZoomFitsOrMagnifiesByPowersOfTwo) {
    TextureInspector in;
    in.open(0);
    const Rect area{10, 20, 400, 300};
    EXPECT_FLOAT_EQ(in.scale(64, 32, area), 6.25f);  // min(400 / 64, 300 / 32)
    // Centred in the area, on whole pixels.
    const Rect p = in.placement(64, 32, area);
    EXPECT_FLOAT_EQ(p.w, 400.0f);
    EXPECT_FLOAT_EQ(p.h, 200.0f);
    EXPECT_FLOAT_EQ(p.x, 10.0f);
    EXPECT_FLOAT_EQ(p.y, 70.0f);
    in.zoomIn(64, 32, area);  // from 6.25: 8
    EXPECT_EQ(in.zoom(), 8);
    in.zoomIn(64, 32, area);
    EXPECT_EQ(in.zoom(), 16);
    in.zoomOut(64, 32, area);
    in.zoomOut(64, 32, area);
    in.zoomOut(64, 32, area);
    EXPECT_EQ(in.zoom(), 2);
    in.setZoom(TextureInspector::kFit);
    in.zoomOut(64, 32, area);  // from 6.25: 4
    EXPECT_EQ(in.zoom(), 4);
    in.setZoom(1);
    in.zoomOut(64, 32, area);
    EXPECT_EQ(in.zoom(), 1);
    EXPECT_THROW(in.setZoom(3), std::invalid_argument);
    EXPECT_THROW(in.setZoom(128), std::invalid_argument);
    // Larger than the area: from its top-left corner (scrolled).
    in.setZoom(16);
    const Rect big = in.placement(64, 32, area);
    EXPECT_EQ(big, (Rect{10, 20, 1024, 512}));
}

TEST(TextureInspector, TheTexelUnderAPoint) {
    const Rect drawn{100, 50, 64, 32};  // a 16x8 image at 4 pixels a texel
    EXPECT_EQ(TextureInspector::texelUnder(100, 50, drawn, 16, 8), (std::pair{0, 0}));
    EXPECT_EQ(TextureInspector::texelUnder(103.9f, 53.9f, drawn, 16, 8), (std::pair{0, 0}));
    EXPECT_EQ(TextureInspector::texelUnder(104, 54, drawn, 16, 8), (std::pair{1, 1}));
    EXPECT_EQ(TextureInspector::texelUnder(163.5f, 81.5f, drawn, 16, 8), (std::pair{15, 7}));
    EXPECT_FALSE(TextureInspector::texelUnder(164, 60, drawn, 16, 8));
    EXPECT_FALSE(TextureInspector::texelUnder(99, 60, drawn, 16, 8));
}
