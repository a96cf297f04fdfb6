// PngImage: PNG -> Image2D format and pixels per the colour-type mapping of
// docs/scene-setup.md (Image files); robustness against damaged PNGs.
#include <gtest/gtest.h>

#include <m3g/Image2D.h>

#include <csetjmp>
#include <filesystem>
#include <random>

#include <png.h>

#include <m3g/Exception.h>

#include "M3GTestBytes.h"
#include "PngTestBytes.h"
#include "PngImage.h"

using m3g::IOException;
using m3g::Image2D;
using m3g::detail::decodePng;
using m3g::detail::PngImage;
using namespace m3g::detail;
using m3gtest::Bytes;

using m3gtest::PngSpec;
using m3gtest::writePng;

TEST(PngImage, Grey8IsLuminance) {
    PngSpec s;
    s.rows = {0, 100, 255, 1, 2, 3};
    const PngImage img = decodePng(writePng(s));
    EXPECT_EQ(img.format, Image2D::LUMINANCE);
    EXPECT_EQ(img.width, 3);
    EXPECT_EQ(img.height, 2);
    EXPECT_EQ(img.pixels, s.rows);
}

TEST(PngImage, LowBitGreyIsExpanded) {
    PngSpec s;
    s.width = 4;
    s.height = 1;
    s.bitDepth = 2;
    s.rows = {0b00011011};  // 0,1,2,3
    PngImage img = decodePng(writePng(s));
    EXPECT_EQ(img.format, Image2D::LUMINANCE);
    EXPECT_EQ(img.pixels, (Bytes{0, 85, 170, 255}));
    s.bitDepth = 1;
    s.width = 8;
    s.rows = {0b10100001};
    img = decodePng(writePng(s));
    EXPECT_EQ(img.pixels, (Bytes{255, 0, 255, 0, 0, 0, 0, 255}));
    s.bitDepth = 4;
    s.width = 2;
    s.rows = {0x1F};
    img = decodePng(writePng(s));
    EXPECT_EQ(img.pixels, (Bytes{17, 255}));
}

TEST(PngImage, SixteenBitKeepsHighByte) {
    PngSpec s;
    s.width = 2;
    s.height = 1;
    s.bitDepth = 16;
    s.rows = {0x12, 0x34, 0xAB, 0xFF};
    EXPECT_EQ(decodePng(writePng(s)).pixels, (Bytes{0x12, 0xAB}));
    s.colorType = PNG_COLOR_TYPE_RGB_ALPHA;
    s.width = 1;
    s.rows = {0x10, 0xFF, 0x20, 0x00, 0x30, 0x80, 0x40, 0x01};
    const PngImage img = decodePng(writePng(s));
    EXPECT_EQ(img.format, Image2D::RGBA);
    EXPECT_EQ(img.pixels, (Bytes{0x10, 0x20, 0x30, 0x40}));
}

TEST(PngImage, GreyWithTrnsIsLuminanceAlpha) {
    PngSpec s;
    s.rows = {0, 100, 255, 100, 2, 3};
    s.trnsColor = true;
    s.trns.gray = 100;
    const PngImage img = decodePng(writePng(s));
    EXPECT_EQ(img.format, Image2D::LUMINANCE_ALPHA);
    EXPECT_EQ(img.pixels, (Bytes{0, 255, 100, 0, 255, 255, 100, 0, 2, 255, 3, 255}));
}

TEST(PngImage, GreyAlphaIsLuminanceAlpha) {
    PngSpec s;
    s.colorType = PNG_COLOR_TYPE_GRAY_ALPHA;
    s.width = 2;
    s.height = 1;
    s.rows = {10, 20, 30, 40};
    const PngImage img = decodePng(writePng(s));
    EXPECT_EQ(img.format, Image2D::LUMINANCE_ALPHA);
    EXPECT_EQ(img.pixels, s.rows);
}

TEST(PngImage, RgbAndRgbWithTrns) {
    PngSpec s;
    s.colorType = PNG_COLOR_TYPE_RGB;
    s.width = 2;
    s.height = 1;
    s.rows = {1, 2, 3, 4, 5, 6};
    PngImage img = decodePng(writePng(s));
    EXPECT_EQ(img.format, Image2D::RGB);
    EXPECT_EQ(img.pixels, s.rows);
    s.trnsColor = true;
    s.trns.red = 4;
    s.trns.green = 5;
    s.trns.blue = 6;
    img = decodePng(writePng(s));
    EXPECT_EQ(img.format, Image2D::RGBA);
    EXPECT_EQ(img.pixels, (Bytes{1, 2, 3, 255, 4, 5, 6, 0}));
}

TEST(PngImage, RgbaIsRgba) {
    PngSpec s;
    s.colorType = PNG_COLOR_TYPE_RGB_ALPHA;
    s.width = 1;
    s.height = 2;
    s.rows = {1, 2, 3, 4, 5, 6, 7, 8};
    const PngImage img = decodePng(writePng(s));
    EXPECT_EQ(img.format, Image2D::RGBA);
    EXPECT_EQ(img.pixels, s.rows);
}

TEST(PngImage, PaletteIsRgbOrRgbaWithTrns) {
    PngSpec s;
    s.colorType = PNG_COLOR_TYPE_PALETTE;
    s.width = 3;
    s.height = 1;
    s.palette = {{10, 20, 30}, {40, 50, 60}, {70, 80, 90}};
    s.rows = {2, 0, 1};
    PngImage img = decodePng(writePng(s));
    EXPECT_EQ(img.format, Image2D::RGB);
    EXPECT_EQ(img.pixels, (Bytes{70, 80, 90, 10, 20, 30, 40, 50, 60}));
    s.trnsAlpha = {0, 128};  // entry 2 has no tRNS entry: opaque
    img = decodePng(writePng(s));
    EXPECT_EQ(img.format, Image2D::RGBA);
    EXPECT_EQ(img.pixels, (Bytes{70, 80, 90, 255, 10, 20, 30, 0, 40, 50, 60, 128}));
    // 4-bit and 1-bit palettes.
    s.trnsAlpha.clear();
    s.bitDepth = 4;
    s.width = 2;
    s.rows = {0x21};
    img = decodePng(writePng(s));
    EXPECT_EQ(img.pixels, (Bytes{70, 80, 90, 40, 50, 60}));
    s.bitDepth = 1;
    s.palette.resize(2);
    s.width = 3;
    s.rows = {0b01000000};
    img = decodePng(writePng(s));
    EXPECT_EQ(img.pixels, (Bytes{10, 20, 30, 40, 50, 60, 10, 20, 30}));
}

TEST(PngImage, InterlacedAndGammaDoNotChangeValues) {
    PngSpec s;
    s.colorType = PNG_COLOR_TYPE_RGB;
    s.width = 9;
    s.height = 7;
    s.interlace = true;
    s.gamma = 1.0 / 2.2;
    for (int i = 0; i < s.width * s.height * 3; ++i) s.rows.push_back(static_cast<std::uint8_t>(i * 7));
    const PngImage img = decodePng(writePng(s));
    EXPECT_EQ(img.format, Image2D::RGB);
    EXPECT_EQ(img.pixels, s.rows);
}

namespace {

Bytes samplePng() {
    PngSpec s;
    s.colorType = PNG_COLOR_TYPE_PALETTE;
    s.width = 16;
    s.height = 16;
    s.palette = {{1, 2, 3}, {4, 5, 6}};
    s.trnsAlpha = {7};
    for (int i = 0; i < 256; ++i) s.rows.push_back(static_cast<std::uint8_t>(i % 2));
    return writePng(s);
}

std::string pngFailure(const Bytes& b) {
    try {
        decodePng(b, "tex.png");
    } catch (const IOException& e) {
        return e.what();
    }
    ADD_FAILURE() << "no IOException";
    return {};
}

void putBE32(Bytes& b, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (24 - 8 * i));
}

void fixCrc(Bytes& b, std::size_t chunkStart) {
    const std::uint32_t len = (std::uint32_t(b[chunkStart]) << 24) | (std::uint32_t(b[chunkStart + 1]) << 16) |
                              (std::uint32_t(b[chunkStart + 2]) << 8) | b[chunkStart + 3];
    const uLong c = crc32(crc32(0L, Z_NULL, 0), b.data() + chunkStart + 4, len + 4);
    putBE32(b, chunkStart + 8 + len, static_cast<std::uint32_t>(c));
}

}  // namespace

TEST(PngImage, Errors) {
    EXPECT_NE(pngFailure({}).find("tex.png: not a PNG image"), std::string::npos);
    EXPECT_NE(pngFailure(Bytes{0xFF, 0xD8, 0xFF, 0, 0, 0, 0, 0, 0}).find("bad signature"), std::string::npos);
    Bytes b = samplePng();
    b[20] ^= 1;  // IHDR width byte: CRC error
    EXPECT_NE(pngFailure(b).find("tex.png: invalid PNG"), std::string::npos);
}

TEST(PngImage, OversizedDimensionsFailWithoutLargeAllocation) {
    for (std::uint32_t dim : {16384u, 100000u, 0x7FFFFFFFu}) {
        Bytes b = samplePng();
        putBE32(b, 16, dim);  // IHDR width
        putBE32(b, 20, dim);  // IHDR height
        fixCrc(b, 8);
        const std::string m = pngFailure(b);
        EXPECT_NE(m.find("tex.png"), std::string::npos) << m;
    }
    Bytes zero = samplePng();
    putBE32(zero, 16, 0);
    fixCrc(zero, 8);
    EXPECT_THROW(decodePng(zero), IOException);
}

// Fuzzing finding (docs/reliability.md): an ancillary chunk declaring more
// bytes than the file holds made libpng allocate and clear the declared
// length (1.7 GB for a 250-byte file) before noticing the truncation. The
// chunk list is checked first; the error names the chunk and its offset.
TEST(PngImage, ChunkLongerThanTheFileFailsBeforeDecoding) {
    const Bytes good = samplePng();
    for (std::uint32_t declared : {0x69545874u, 0x7FFFFFFFu, 100u}) {
        Bytes b(good.begin(), good.begin() + 33);  // signature + IHDR (8 + 25)
        const Bytes text = {0, 0, 0, 0, 't', 'E', 'X', 't', 'a', 'b', 'c'};
        b.insert(b.end(), text.begin(), text.end());
        putBE32(b, 33, declared);
        const std::string m = pngFailure(b);
        EXPECT_NE(m.find("tex.png: invalid PNG: truncated: chunk 'tEXt' at byte 33 declares " +
                         std::to_string(declared) + " data bytes but the file has only 3 left"),
                  std::string::npos)
            << m;
    }
}

TEST(PngImage, TruncationAtEveryLength) {
    const Bytes b = samplePng();
    ASSERT_NO_THROW(decodePng(b));
    // The IEND chunk (last 12 bytes) carries nothing; libpng may or may not
    // insist on it, so only cuts before it must fail.
    for (std::size_t n = 0; n + 12 < b.size(); ++n)
        EXPECT_THROW(decodePng(std::span<const std::uint8_t>(b).first(n)), IOException) << n;
    for (std::size_t n = b.size() - 12; n < b.size(); ++n) {
        try {
            decodePng(std::span<const std::uint8_t>(b).first(n));
        } catch (const IOException&) {
        }
    }
}

TEST(PngImage, CorruptedBytesNeverCrash) {
    const Bytes b = samplePng();
    for (std::size_t i = 0; i < b.size(); ++i) {
        Bytes x = b;
        x[i] ^= 0xFF;
        try {
            const PngImage img = decodePng(x);
            EXPECT_EQ(img.pixels.size(),
                      std::size_t(img.width) * std::size_t(img.height) * std::size_t(Image2D::bytesPerPixel(img.format)));
        } catch (const IOException&) {
        }
    }
    std::mt19937 rng(99);
    for (int iter = 0; iter < 2000; ++iter) {
        Bytes x = b;
        for (int k = 0; k < 3; ++k) x[8 + rng() % (x.size() - 8)] = static_cast<std::uint8_t>(rng());
        try {
            decodePng(x);
        } catch (const IOException&) {
        }
    }
}

TEST(PngImage, CorpusTextures) {
    const auto dir = m3gtest::corpusDir();
    if (!dir) GTEST_SKIP() << "corpus not found (expected ../shared/corpus next to the source tree)";
    int n = 0;
    for (const auto& path : m3gtest::corpusFiles(*dir)) {
        if (path.extension() != ".png") continue;
        const Bytes b = m3gtest::readFile(path);
        ASSERT_GE(b.size(), 33u);
        const int w = (b[16] << 24) | (b[17] << 16) | (b[18] << 8) | b[19];
        const int h = (b[20] << 24) | (b[21] << 16) | (b[22] << 8) | b[23];
        const int colorType = b[25];
        const PngImage img = decodePng(b, path.string());
        EXPECT_EQ(img.width, w);
        EXPECT_EQ(img.height, h);
        const int expected = colorType == 0 ? Image2D::LUMINANCE
                             : colorType == 4 ? Image2D::LUMINANCE_ALPHA
                             : colorType == 6 ? Image2D::RGBA
                                              : Image2D::RGB;  // 2 or 3, unless tRNS
        if (colorType == 2 || colorType == 3 || colorType == 0)
            EXPECT_TRUE(img.format == expected || img.format == expected + 1) << path;
        else
            EXPECT_EQ(img.format, expected) << path;
        ++n;
    }
    EXPECT_GT(n, 0);
}
