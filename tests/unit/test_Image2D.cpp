// Image2D (JSR-184 1.1, Image2D): constructors, palette resolution, set(),
// RGBA8 expansion, exceptions. Expected pixels are computed by hand.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include <m3g/Image2D.h>

using namespace m3g;
using Bytes = std::vector<std::uint8_t>;

namespace {
Bytes bytesOf(const Image2D& img) { return Bytes(img.pixels().begin(), img.pixels().end()); }
}  // namespace

TEST(Image2D, ConstantsMatchSpec) {
    EXPECT_EQ(Image2D::ALPHA, 96);
    EXPECT_EQ(Image2D::LUMINANCE, 97);
    EXPECT_EQ(Image2D::LUMINANCE_ALPHA, 98);
    EXPECT_EQ(Image2D::RGB, 99);
    EXPECT_EQ(Image2D::RGBA, 100);
}

TEST(Image2D, BytesPerPixel) {
    EXPECT_EQ(Image2D::bytesPerPixel(Image2D::ALPHA), 1);
    EXPECT_EQ(Image2D::bytesPerPixel(Image2D::LUMINANCE), 1);
    EXPECT_EQ(Image2D::bytesPerPixel(Image2D::LUMINANCE_ALPHA), 2);
    EXPECT_EQ(Image2D::bytesPerPixel(Image2D::RGB), 3);
    EXPECT_EQ(Image2D::bytesPerPixel(Image2D::RGBA), 4);
    EXPECT_EQ(Image2D::bytesPerPixel(101), 0);
}

TEST(Image2D, ImmutableFromPixels) {
    const Bytes px{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 99, 98};  // 2 extra bytes ignored
    Ref<Image2D> img = make<Image2D>(Image2D::RGB, 2, 2, px);
    EXPECT_EQ(img->getFormat(), Image2D::RGB);
    EXPECT_EQ(img->getWidth(), 2);
    EXPECT_EQ(img->getHeight(), 2);
    EXPECT_FALSE(img->isMutable());
    EXPECT_FALSE(img->isPalettized());
    EXPECT_EQ(img->bytesPerPixel(), 3);
    EXPECT_EQ(bytesOf(*img), (Bytes{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}));
    EXPECT_EQ(img->getReferences(), 0);
    EXPECT_STREQ(img->getClassName(), "Image2D");
}

TEST(Image2D, PixelsAreCopied) {
    Bytes px{10, 20};
    Ref<Image2D> img = make<Image2D>(Image2D::LUMINANCE_ALPHA, 1, 1, px);
    px[0] = 0;
    EXPECT_EQ(bytesOf(*img), (Bytes{10, 20}));
}

TEST(Image2D, ConstructorExceptions) {
    const Bytes px(64, 0);
    EXPECT_THROW(Image2D(95, 2, 2, px), IllegalArgumentException);
    EXPECT_THROW(Image2D(101, 2, 2, px), IllegalArgumentException);
    EXPECT_THROW(Image2D(Image2D::RGB, 0, 2, px), IllegalArgumentException);
    EXPECT_THROW(Image2D(Image2D::RGB, 2, -1, px), IllegalArgumentException);
    EXPECT_THROW(Image2D(Image2D::RGB, 2, 2, std::span<const std::uint8_t>()), NullPointerException);
    // 2x2 RGBA needs 16 bytes.
    EXPECT_THROW(Image2D(Image2D::RGBA, 2, 2, std::span<const std::uint8_t>(px.data(), 15)),
                 IllegalArgumentException);
    EXPECT_NO_THROW(Image2D(Image2D::RGBA, 2, 2, std::span<const std::uint8_t>(px.data(), 16)));
    // Mutable constructor.
    EXPECT_THROW(Image2D(42, 1, 1), IllegalArgumentException);
    EXPECT_THROW(Image2D(Image2D::RGB, -1, 1), IllegalArgumentException);
    EXPECT_THROW(Image2D(Image2D::RGB, 1, 0), IllegalArgumentException);
}

TEST(Image2D, MessageNamesClassMethodAndRange) {
    try {
        Image2D(Image2D::RGB, 0, 2);
        FAIL();
    } catch (const IllegalArgumentException& e) {
        EXPECT_NE(std::string(e.what()).find("Image2D::Image2D"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("width 0"), std::string::npos) << e.what();
    }
}

TEST(Image2D, PaletteLookupRGB) {
    const Bytes indices{2, 0, 1, 2};
    const Bytes palette{10, 20, 30, 40, 50, 60, 70, 80, 90};
    Ref<Image2D> img = make<Image2D>(Image2D::RGB, 2, 2, indices, palette);
    EXPECT_TRUE(img->isPalettized());
    EXPECT_FALSE(img->isMutable());
    EXPECT_EQ(bytesOf(*img), (Bytes{70, 80, 90, 10, 20, 30, 40, 50, 60, 70, 80, 90}));
    EXPECT_EQ(Bytes(img->paletteIndices().begin(), img->paletteIndices().end()), indices);
    EXPECT_EQ(Bytes(img->palette().begin(), img->palette().end()), palette);
}

TEST(Image2D, PaletteLookupLuminanceAlpha) {
    // Entries: 0 -> (1, 2), 1 -> (3, 4). Indices row-major for a 3x1 image.
    Ref<Image2D> img = make<Image2D>(Image2D::LUMINANCE_ALPHA, 3, 1, Bytes{1, 1, 0}, Bytes{1, 2, 3, 4});
    EXPECT_EQ(bytesOf(*img), (Bytes{3, 4, 3, 4, 1, 2}));
}

TEST(Image2D, PaletteIndexPastShortPaletteIsZero) {
    Ref<Image2D> img = make<Image2D>(Image2D::RGB, 2, 1, Bytes{0, 5}, Bytes{7, 8, 9});
    EXPECT_EQ(bytesOf(*img), (Bytes{7, 8, 9, 0, 0, 0}));
}

TEST(Image2D, PaletteWithMoreThan256EntriesIgnoresExtra) {
    Bytes palette(257, 0);  // ALPHA: 1 byte per entry, 257 entries
    palette[255] = 200;
    palette[256] = 77;
    Ref<Image2D> img = make<Image2D>(Image2D::ALPHA, 1, 1, Bytes{255}, palette);
    EXPECT_EQ(bytesOf(*img), (Bytes{200}));
    EXPECT_EQ(img->palette().size(), 256u);
}

TEST(Image2D, PaletteExceptions) {
    const Bytes idx{0, 0, 0, 0};
    EXPECT_THROW(Image2D(Image2D::RGB, 2, 2, std::span<const std::uint8_t>(), Bytes{1, 2, 3}), NullPointerException);
    EXPECT_THROW(Image2D(Image2D::RGB, 2, 2, idx, std::span<const std::uint8_t>()), NullPointerException);
    EXPECT_THROW(Image2D(Image2D::RGB, 2, 2, Bytes{0, 0, 0}, Bytes{1, 2, 3}), IllegalArgumentException);
    EXPECT_THROW(Image2D(Image2D::RGB, 2, 2, idx, Bytes{1, 2, 3, 4, 5}), IllegalArgumentException);
    EXPECT_THROW(Image2D(Image2D::RGBA, 2, 2, idx, Bytes{1, 2, 3, 4, 5, 6}), IllegalArgumentException);
    EXPECT_THROW(Image2D(77, 2, 2, idx, Bytes{1, 2, 3}), IllegalArgumentException);
    EXPECT_THROW(Image2D(Image2D::RGB, 0, 2, idx, Bytes{1, 2, 3}), IllegalArgumentException);
    // A full 256-entry palette plus a stray byte is accepted (the extra is ignored).
    EXPECT_NO_THROW(Image2D(Image2D::RGB, 2, 2, idx, Bytes(256 * 3 + 1, 0)));
}

TEST(Image2D, MutableIsOpaqueWhite) {
    Ref<Image2D> rgba = make<Image2D>(Image2D::RGBA, 2, 1);
    EXPECT_TRUE(rgba->isMutable());
    EXPECT_FALSE(rgba->isPalettized());
    EXPECT_EQ(bytesOf(*rgba), Bytes(8, 255));
    Ref<Image2D> a = make<Image2D>(Image2D::ALPHA, 3, 2);
    EXPECT_EQ(bytesOf(*a), Bytes(6, 255));
    Ref<Image2D> la = make<Image2D>(Image2D::LUMINANCE_ALPHA, 1, 1);
    EXPECT_EQ(bytesOf(*la), Bytes(2, 255));
}

TEST(Image2D, SetSubRectangleLuminance) {
    Ref<Image2D> img = make<Image2D>(Image2D::LUMINANCE, 4, 3);
    const auto rev = img->getRevision();
    img->set(1, 1, 2, 2, Bytes{1, 2, 3, 4});
    EXPECT_GT(img->getRevision(), rev);
    EXPECT_EQ(bytesOf(*img), (Bytes{255, 255, 255, 255,  //
                                    255, 1, 2, 255,      //
                                    255, 3, 4, 255}));
}

TEST(Image2D, SetColumnRGB) {
    Ref<Image2D> img = make<Image2D>(Image2D::RGB, 3, 2);
    img->set(2, 0, 1, 2, Bytes{1, 2, 3, 4, 5, 6});
    EXPECT_EQ(bytesOf(*img), (Bytes{255, 255, 255, 255, 255, 255, 1, 2, 3,  //
                                    255, 255, 255, 255, 255, 255, 4, 5, 6}));
    img->set(0, 0, 3, 2, Bytes(18, 9));
    EXPECT_EQ(bytesOf(*img), Bytes(18, 9));
}

TEST(Image2D, SetExceptions) {
    Ref<Image2D> img = make<Image2D>(Image2D::RGB, 4, 4);
    const Bytes px(64, 0);
    EXPECT_THROW(img->set(0, 0, 1, 1, std::span<const std::uint8_t>()), NullPointerException);
    EXPECT_THROW(img->set(-1, 0, 1, 1, px), IllegalArgumentException);
    EXPECT_THROW(img->set(0, -1, 1, 1, px), IllegalArgumentException);
    EXPECT_THROW(img->set(0, 0, 0, 1, px), IllegalArgumentException);
    EXPECT_THROW(img->set(0, 0, 1, 0, px), IllegalArgumentException);
    EXPECT_THROW(img->set(3, 0, 2, 1, px), IllegalArgumentException);
    EXPECT_THROW(img->set(0, 3, 1, 2, px), IllegalArgumentException);
    EXPECT_THROW(img->set(4, 0, 1, 1, px), IllegalArgumentException);
    EXPECT_THROW(img->set(0, 0, 2, 2, std::span<const std::uint8_t>(px.data(), 11)), IllegalArgumentException);
    EXPECT_NO_THROW(img->set(3, 3, 1, 1, std::span<const std::uint8_t>(px.data(), 3)));

    Ref<Image2D> fixed = make<Image2D>(Image2D::RGB, 1, 1, Bytes{1, 2, 3});
    EXPECT_THROW(fixed->set(0, 0, 1, 1, Bytes{4, 5, 6}), IllegalStateException);
    EXPECT_EQ(bytesOf(*fixed), (Bytes{1, 2, 3}));
    Ref<Image2D> pal = make<Image2D>(Image2D::RGB, 1, 1, Bytes{0}, Bytes{1, 2, 3});
    EXPECT_THROW(pal->set(0, 0, 1, 1, Bytes{4, 5, 6}), IllegalStateException);
}

TEST(Image2D, RGBA8Expansion) {
    std::vector<std::uint8_t> out;
    make<Image2D>(Image2D::LUMINANCE, 2, 1, Bytes{10, 20})->getPixelsRGBA8(out);
    EXPECT_EQ(out, (Bytes{10, 10, 10, 255, 20, 20, 20, 255}));
    make<Image2D>(Image2D::ALPHA, 2, 1, Bytes{10, 20})->getPixelsRGBA8(out);
    EXPECT_EQ(out, (Bytes{255, 255, 255, 10, 255, 255, 255, 20}));
    make<Image2D>(Image2D::LUMINANCE_ALPHA, 2, 1, Bytes{10, 20, 30, 40})->getPixelsRGBA8(out);
    EXPECT_EQ(out, (Bytes{10, 10, 10, 20, 30, 30, 30, 40}));
    make<Image2D>(Image2D::RGB, 1, 2, Bytes{1, 2, 3, 4, 5, 6})->getPixelsRGBA8(out);
    EXPECT_EQ(out, (Bytes{1, 2, 3, 255, 4, 5, 6, 255}));
    make<Image2D>(Image2D::RGBA, 1, 1, Bytes{1, 2, 3, 4})->getPixelsRGBA8(out);
    EXPECT_EQ(out, (Bytes{1, 2, 3, 4}));
    // Paletted LUMINANCE: entries 0 -> 5, 1 -> 6.
    make<Image2D>(Image2D::LUMINANCE, 2, 1, Bytes{1, 0}, Bytes{5, 6})->getPixelsRGBA8(out);
    EXPECT_EQ(out, (Bytes{6, 6, 6, 255, 5, 5, 5, 255}));
}

TEST(Image2D, DuplicateCopiesPixelsAndState) {
    Ref<Image2D> img = make<Image2D>(Image2D::LUMINANCE, 2, 1);
    img->set(0, 0, 1, 1, Bytes{7});
    img->setUserID(42);
    Ref<Image2D> dup = dynamicCast<Image2D>(img->duplicate());
    ASSERT_TRUE(dup);
    EXPECT_NE(dup.get(), img.get());
    EXPECT_EQ(dup->getUserID(), 42);
    EXPECT_EQ(dup->getFormat(), Image2D::LUMINANCE);
    EXPECT_EQ(dup->getWidth(), 2);
    EXPECT_EQ(dup->getHeight(), 1);
    EXPECT_TRUE(dup->isMutable());
    EXPECT_EQ(bytesOf(*dup), (Bytes{7, 255}));
    // The copy has its own pixels.
    dup->set(1, 0, 1, 1, Bytes{8});
    EXPECT_EQ(bytesOf(*img), (Bytes{7, 255}));

    Ref<Image2D> pal = make<Image2D>(Image2D::RGB, 1, 1, Bytes{0}, Bytes{1, 2, 3});
    Ref<Image2D> pdup = dynamicCast<Image2D>(pal->duplicate());
    EXPECT_TRUE(pdup->isPalettized());
    EXPECT_FALSE(pdup->isMutable());
    EXPECT_EQ(bytesOf(*pdup), (Bytes{1, 2, 3}));
}

TEST(Image2D, NotAnimatable) {
    Ref<Image2D> img = make<Image2D>(Image2D::RGB, 1, 1);
    EXPECT_FALSE(img->isAnimatable(256));  // ALPHA
    EXPECT_FALSE(img->isAnimatable(258));  // COLOR
}
