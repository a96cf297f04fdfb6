// tools/m3g/ImageIO and JpegWriter: the output format by extension, the JPEG
// encoder (read back by the library's own decoder) and the uniform-image
// check behind `m3g render`'s hint. No device.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include <m3g/m3g.h>

#include "CliErrors.h"
#include "ImageIO.h"
#include "JpegWriter.h"

using m3gcli::ImageFormat;
using m3gcli::RgbaImage;

namespace {

/// A 16x8 image: left half red, right half blue, opaque.
RgbaImage twoColours() {
    RgbaImage img;
    img.width = 16;
    img.height = 8;
    img.pixels.resize(16 * 8 * 4);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) {
            std::uint8_t* p = &img.pixels[(static_cast<std::size_t>(y) * 16 + x) * 4];
            p[0] = x < 8 ? 220 : 10;
            p[1] = 20;
            p[2] = x < 8 ? 30 : 200;
            p[3] = 255;
        }
    return img;
}

}  // namespace

TEST(ImageOutput, FormatByExtension) {
    EXPECT_EQ(m3gcli::imageFormatFor("a.png"), ImageFormat::Png);
    EXPECT_EQ(m3gcli::imageFormatFor("dir.v1/A.PNG"), ImageFormat::Png);
    EXPECT_EQ(m3gcli::imageFormatFor("a.jpg"), ImageFormat::Jpeg);
    EXPECT_EQ(m3gcli::imageFormatFor("a.JPEG"), ImageFormat::Jpeg);
    EXPECT_EQ(m3gcli::imageFormatFor("-"), ImageFormat::Png);  // stdout
    EXPECT_THROW(m3gcli::imageFormatFor("a.bmp"), m3gcli::CliError);
    EXPECT_THROW(m3gcli::imageFormatFor("a"), m3gcli::CliError);
    EXPECT_THROW(m3gcli::imageFormatFor("dir.png/a"), m3gcli::CliError);
}

TEST(ImageOutput, JpegRoundTripsThroughTheLoader) {
    const RgbaImage img = twoColours();
    const std::vector<std::uint8_t> jpeg = m3gcli::encodeJpeg(img);
    ASSERT_GT(jpeg.size(), 4u);
    EXPECT_EQ(jpeg[0], 0xFF);
    EXPECT_EQ(jpeg[1], 0xD8);
    const auto roots = m3g::Loader::load(std::span<const std::uint8_t>(jpeg), 0);
    ASSERT_EQ(roots.size(), 1u);
    auto* decoded = dynamic_cast<m3g::Image2D*>(roots[0].get());
    ASSERT_NE(decoded, nullptr);
    EXPECT_EQ(decoded->getWidth(), 16);
    EXPECT_EQ(decoded->getHeight(), 8);
    std::vector<std::uint8_t> rgba;
    decoded->getPixelsRGBA8(rgba);
    ASSERT_EQ(rgba.size(), img.pixels.size());
    // Lossy, but the halves keep their colours away from the edge between them.
    for (int y = 0; y < 8; ++y)
        for (int x : {1, 2, 13, 14})
            for (int c = 0; c < 3; ++c) {
                const std::size_t i = (static_cast<std::size_t>(y) * 16 + x) * 4 + c;
                EXPECT_LE(std::abs(int(rgba[i]) - int(img.pixels[i])), 24) << x << "," << y << " channel " << c;
            }
}

TEST(ImageOutput, UniformImage) {
    RgbaImage img = twoColours();
    EXPECT_FALSE(m3gcli::isUniform(img));
    for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = img.pixels[i % 4];
    EXPECT_TRUE(m3gcli::isUniform(img));
    img.pixels.back() = 254;  // one alpha value off
    EXPECT_FALSE(m3gcli::isUniform(img));
    EXPECT_TRUE(m3gcli::isUniform(RgbaImage{}));
}
