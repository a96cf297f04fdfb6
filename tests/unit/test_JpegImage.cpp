// JpegImage: JPEG -> Image2D format and pixels (greyscale -> LUMINANCE,
// colour -> RGB), checked against the pixels the test encoded; robustness
// against damaged and hostile JPEGs (JSR-184 1.1, Loader).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <string>

#include <m3g/Exception.h>
#include <m3g/Image2D.h>

#include "JpegImage.h"
#include "JpegTestBytes.h"
#include "M3GTestBytes.h"

using m3g::Image2D;
using m3g::IOException;
using m3g::detail::decodeJpeg;
using m3g::detail::JpegImage;
using m3gtest::Bytes;
using m3gtest::JpegSpec;
using m3gtest::jpegTestPattern;
using m3gtest::writeJpeg;

namespace {

// JPEG is lossy. At quality 100 every quantiser step is 1, so what remains is
// rounding: RGB -> YCbCr and back in 8-bit integers and the integer DCT and
// IDCT, each worth a level or so. These patterns decode within 3 levels of
// the source with libjpeg-turbo 2.1.5 (greyscale within 1); 4 leaves a level
// for another conforming IDCT and still fails a swapped channel, a mirrored
// row or a pixel shifted by one, which the patterns (at most 24 wide) turn
// into errors of 7 levels or more.
constexpr int kTolerance = 4;

int maxDifference(const Bytes& a, const Bytes& b) {
    EXPECT_EQ(a.size(), b.size());
    int worst = 0;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
    return worst;
}

/// The test pattern as a JPEG to encode: `components` 3 (RGB) or 1 (grey).
JpegSpec patternSpec(int components, int w, int h) {
    JpegSpec s;
    s.width = w;
    s.height = h;
    s.components = components;
    s.pixels = jpegTestPattern(w, h, components);
    return s;
}

JpegSpec rgbSpec(int w = 16, int h = 16) { return patternSpec(3, w, h); }
JpegSpec greySpec(int w = 16, int h = 16) { return patternSpec(1, w, h); }

std::string jpegFailure(const Bytes& b) {
    try {
        decodeJpeg(b, "tex.jpg");
    } catch (const IOException& e) {
        return e.what();
    }
    ADD_FAILURE() << "no IOException";
    return {};
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST(JpegImage, RgbDecodesToRgbWithinTolerance) {
    const JpegSpec s = rgbSpec(17, 11);  // not a multiple of the 8x8 block: partial blocks at the edges
    const Bytes file = writeJpeg(s);
    ASSERT_FALSE(file.empty());
    const JpegImage img = decodeJpeg(file);
    EXPECT_EQ(img.format, Image2D::RGB);
    EXPECT_EQ(img.width, 17);
    EXPECT_EQ(img.height, 11);
    EXPECT_LE(maxDifference(img.pixels, s.pixels), kTolerance);
}

TEST(JpegImage, GreyscaleIsLuminance) {
    const JpegSpec s = greySpec(9, 13);
    const JpegImage img = decodeJpeg(writeJpeg(s));
    EXPECT_EQ(img.format, Image2D::LUMINANCE);
    EXPECT_EQ(img.width, 9);
    EXPECT_EQ(img.height, 13);
    EXPECT_LE(maxDifference(img.pixels, s.pixels), kTolerance);
}

TEST(JpegImage, ProgressiveDecodes) {
    JpegSpec s = rgbSpec(24, 16);
    const Bytes baseline = writeJpeg(s);
    s.progressive = true;
    const Bytes progressive = writeJpeg(s);
    ASSERT_TRUE(m3gtest::findMarker(progressive, 0xC2)) << "no SOF2: not a progressive file";
    ASSERT_FALSE(m3gtest::findMarker(progressive, 0xC0));
    const JpegImage img = decodeJpeg(progressive);
    EXPECT_EQ(img.format, Image2D::RGB);
    EXPECT_EQ(img.width, 24);
    EXPECT_EQ(img.height, 16);
    EXPECT_LE(maxDifference(img.pixels, s.pixels), kTolerance);
    // Successive approximation refines to the same coefficients as the
    // baseline file, so the two decode to the same pixels.
    EXPECT_EQ(img.pixels, decodeJpeg(baseline).pixels);
    // Greyscale progressive too.
    JpegSpec g = greySpec();
    g.progressive = true;
    const JpegImage grey = decodeJpeg(writeJpeg(g));
    EXPECT_EQ(grey.format, Image2D::LUMINANCE);
    EXPECT_LE(maxDifference(grey.pixels, g.pixels), kTolerance);
}

TEST(JpegImage, ArithmeticCodedDecodes) {
    JpegSpec s = rgbSpec();
    s.arithmetic = true;
    const Bytes file = writeJpeg(s);
    ASSERT_TRUE(m3gtest::findMarker(file, 0xC9)) << "no SOF9: not arithmetic coded";
    const JpegImage img = decodeJpeg(file);
    EXPECT_EQ(img.format, Image2D::RGB);
    EXPECT_LE(maxDifference(img.pixels, s.pixels), kTolerance);
}

// Chroma subsampling: libjpeg upsamples; an image whose colour does not change
// along the subsampled direction loses nothing to it. Y 1x2, Cb 1x1, Cr 1x2 is
// one of the sampling layouts libjpeg-turbo's TurboJPEG 2.1 API refuses (the
// reason this decoder uses the libjpeg API, JpegImage.cpp).
TEST(JpegImage, SubsampledChromaDecodes) {
    JpegSpec s;
    s.width = 16;
    s.height = 16;
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            s.pixels.push_back(static_cast<std::uint8_t>(20 + x * 13));
            s.pixels.push_back(static_cast<std::uint8_t>(200 - x * 9));
            s.pixels.push_back(static_cast<std::uint8_t>(90 + x * 5));
        }
    s.sampling = {{1, 2}, {1, 1}, {1, 2}};
    JpegImage img = decodeJpeg(writeJpeg(s));
    EXPECT_EQ(img.format, Image2D::RGB);
    EXPECT_LE(maxDifference(img.pixels, s.pixels), kTolerance);
    // 4:2:0, the common camera layout, on one flat colour.
    s.pixels.clear();
    for (int i = 0; i < s.width * s.height; ++i) s.pixels.insert(s.pixels.end(), {200, 120, 40});
    s.sampling = {{2, 2}, {1, 1}, {1, 1}};
    img = decodeJpeg(writeJpeg(s));
    EXPECT_EQ(img.format, Image2D::RGB);
    EXPECT_LE(maxDifference(img.pixels, s.pixels), kTolerance);
}

TEST(JpegImage, JfifVersionWarningIsIgnored) {
    const JpegSpec s = greySpec();
    Bytes b = writeJpeg(s);
    const auto app0 = m3gtest::findMarker(b, 0xE0);
    ASSERT_TRUE(app0);
    ASSERT_EQ(std::string(reinterpret_cast<const char*>(b.data() + *app0 + 4), 4), "JFIF");
    b[*app0 + 9] = 3;  // major version: libjpeg warns "unknown JFIF revision number 3.01"
    EXPECT_LE(maxDifference(decodeJpeg(b).pixels, s.pixels), kTolerance);
}

TEST(JpegImage, CmykFails) {
    JpegSpec s;
    s.components = 4;
    s.pixels = jpegTestPattern(s.width, s.height, 4);
    const Bytes b = writeJpeg(s);
    ASSERT_FALSE(b.empty());
    const std::string m = jpegFailure(b);
    EXPECT_TRUE(contains(m, "tex.jpg: CMYK JPEG images are not supported")) << m;
}

TEST(JpegImage, Errors) {
    EXPECT_TRUE(contains(jpegFailure({}), "tex.jpg: not a JPEG image (bad signature"));
    EXPECT_TRUE(contains(jpegFailure(Bytes{0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A}), "not a JPEG image"));
    EXPECT_TRUE(contains(jpegFailure(Bytes{0xFF, 0xD8}), "not a JPEG image"));

    const Bytes good = writeJpeg(rgbSpec());
    // Truncated in the scan data: libjpeg would complete the image with grey.
    std::string m = jpegFailure(Bytes(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(good.size() * 3 / 4)));
    EXPECT_TRUE(contains(m, "tex.jpg: invalid JPEG: Premature end of JPEG file")) << m;
    // The decoder stands at or before the cut when the data runs out.
    const std::size_t at = std::stoul(m.substr(m.find("at or after byte ") + 17));
    EXPECT_LE(at, good.size() * 3 / 4) << m;
    EXPECT_TRUE(contains(m, " of " + std::to_string(good.size() * 3 / 4) + ")")) << m;

    // Garbage after the SOI marker instead of the file's segments (FF D8 FF
    // and no SOI at all are the signature; see "not a JPEG image" above).
    std::mt19937 rng(7);
    Bytes garbage = {0xFF, 0xD8, 0xFF};
    for (int i = 0; i < 200; ++i) garbage.push_back(static_cast<std::uint8_t>(rng() % 0xFF));  // never FF
    m = jpegFailure(garbage);
    EXPECT_TRUE(contains(m, "tex.jpg: invalid JPEG: ")) << m;
    // Garbage between two segments: libjpeg would skip it with a warning.
    const auto app0 = m3gtest::findMarker(good, 0xE0);
    ASSERT_TRUE(app0);
    const std::size_t next = *app0 + 2 + (std::size_t(good[*app0 + 2]) << 8 | good[*app0 + 3]);
    ASSERT_EQ(good[next], 0xFF);
    ASSERT_EQ(good[next + 1], 0xDB);  // libjpeg writes the quantisation tables next
    Bytes inserted(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(next));
    inserted.insert(inserted.end(), {0x12, 0x34, 0x56});
    inserted.insert(inserted.end(), good.begin() + static_cast<std::ptrdiff_t>(next), good.end());
    m = jpegFailure(inserted);
    EXPECT_TRUE(contains(m, "tex.jpg: invalid JPEG: Corrupt JPEG data: 3 extraneous bytes before marker 0xdb")) << m;

    // Zero width or height in the frame header.
    for (auto [w, h] : {std::pair<int, int>{0, 16}, {16, 0}, {0, 0}}) {
        Bytes b = good;
        m3gtest::setJpegSize(b, static_cast<std::uint16_t>(w), static_cast<std::uint16_t>(h));
        m = jpegFailure(b);
        EXPECT_TRUE(contains(m, "tex.jpg: invalid JPEG: Empty JPEG image")) << m;
    }

    // A tables-only stream (no frame): libjpeg's "abbreviated" form.
    m = jpegFailure(Bytes{0xFF, 0xD8, 0xFF, 0xD9});
    EXPECT_TRUE(contains(m, "tex.jpg: invalid JPEG: ")) << m;
}

TEST(JpegImage, OversizedDimensionsFailBeforeDecoding) {
    const Bytes good = writeJpeg(rgbSpec());
    auto sized = [&](int w, int h) {
        Bytes b = good;
        m3gtest::setJpegSize(b, static_cast<std::uint16_t>(w), static_cast<std::uint16_t>(h));
        return jpegFailure(b);
    };
    std::string m = sized(16385, 1);
    EXPECT_TRUE(contains(m, "tex.jpg: JPEG image 16385x1 is too large (limit 16384 pixels a side)")) << m;
    m = sized(1, 65535);  // over libjpeg's own limit (65500) too
    EXPECT_TRUE(contains(m, "tex.jpg: invalid JPEG: Maximum supported image dimension is 65500 pixels")) << m;
    m = sized(16384, 16384);  // 768 MiB of RGB
    EXPECT_TRUE(contains(m, "tex.jpg: JPEG image 16384x16384 is too large (805306368 bytes decoded; limit 268435456)"))
        << m;
    // Within the limits, but far more blocks than the file could code: each
    // 8x8 block's DC coefficient takes at least one Huffman-coded bit.
    m = sized(4000, 4000);
    EXPECT_TRUE(contains(m, "tex.jpg: truncated or corrupt JPEG: 4000x4000 has 250000 blocks of 8x8 samples in "
                            "one component, which take at least 31250 bytes of Huffman-coded data, but the file "
                            "has only " + std::to_string(good.size()) + " bytes"))
        << m;
}

// Each scan of a progressive file is another pass over the whole image; a
// file with hundreds of one-coefficient refinement scans fails at scan 501.
TEST(JpegImage, TooManyProgressiveScansFail) {
    JpegSpec s = greySpec(8, 8);
    s.scans.push_back({1, {0}, 0, 0, 0, 0});  // DC, full precision
    for (int k = 1; k < 64; ++k) {
        s.scans.push_back({1, {0}, k, k, 0, 9});  // coefficient k, top bits first
        for (int a = 9; a >= 1; --a) s.scans.push_back({1, {0}, k, k, a, a - 1});  // then one bit per scan
    }
    ASSERT_EQ(s.scans.size(), 631u);
    const Bytes b = writeJpeg(s);
    ASSERT_FALSE(b.empty());
    const std::string m = jpegFailure(b);
    EXPECT_TRUE(contains(m, "tex.jpg: invalid JPEG: progressive JPEG with more than 500 scans")) << m;
    // The same refinement with a few scans decodes to the picture.
    s.scans.resize(1 + 10 * 20);  // coefficients 1..20 only: fewer than 500 scans
    s.scans.push_back({1, {0}, 21, 63, 0, 0});
    const JpegImage img = decodeJpeg(writeJpeg(s));
    EXPECT_LE(maxDifference(img.pixels, s.pixels), kTolerance);
}

TEST(JpegImage, TruncationAtEveryLength) {
    for (bool progressive : {false, true}) {
        JpegSpec s = rgbSpec(8, 8);
        s.progressive = progressive;
        const Bytes b = writeJpeg(s);
        ASSERT_NO_THROW(decodeJpeg(b));
        // Even a cut in the final EOI marker fails: the strict reading is that
        // a file without its end is not whole.
        for (std::size_t n = 0; n < b.size(); ++n)
            EXPECT_THROW(decodeJpeg(std::span<const std::uint8_t>(b).first(n)), IOException) << n;
    }
}

TEST(JpegImage, CorruptedBytesNeverCrash) {
    JpegSpec s = rgbSpec(8, 8);
    for (bool progressive : {false, true}) {
        s.progressive = progressive;
        const Bytes b = writeJpeg(s);
        for (std::size_t i = 0; i < b.size(); ++i) {
            Bytes x = b;
            x[i] ^= 0xFF;
            try {
                const JpegImage img = decodeJpeg(x);
                EXPECT_EQ(img.pixels.size(), std::size_t(img.width) * std::size_t(img.height) *
                                                 std::size_t(Image2D::bytesPerPixel(img.format)));
            } catch (const IOException&) {
            }
        }
        std::mt19937 rng(99);
        for (int iter = 0; iter < 1000; ++iter) {
            Bytes x = b;
            for (int k = 0; k < 3; ++k) x[2 + rng() % (x.size() - 2)] = static_cast<std::uint8_t>(rng());
            try {
                decodeJpeg(x);
            } catch (const IOException&) {
            }
        }
    }
}
