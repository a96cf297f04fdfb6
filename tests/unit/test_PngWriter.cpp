// The PNG writer extension (api/m3g/PngWriter.h): each Image2D format is
// written and read back through the loader's own PNG decoder, which maps
// PNG colour types to Image2D formats (JSR-184 1.1, Loader), so the pixels
// and the format must come back as they were written.
#include <gtest/gtest.h>

#include <filesystem>
#include <span>
#include <vector>

#include <m3g/m3g.h>

using namespace m3g;

namespace {

Ref<Image2D> reload(const std::vector<std::uint8_t>& png) {
    auto objects = Loader::load(std::span<const std::uint8_t>(png), 0);
    return objects.empty() ? nullptr : Ref<Image2D>(dynamic_cast<Image2D*>(objects[0].get()));
}

std::vector<std::uint8_t> ramp(std::size_t n) {
    std::vector<std::uint8_t> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<std::uint8_t>(i * 37 + 11);
    return v;
}

}  // namespace

TEST(PngWriter, EveryColourFormatRoundTripsThroughTheLoader) {
    for (int format : {Image2D::LUMINANCE, Image2D::LUMINANCE_ALPHA, Image2D::RGB, Image2D::RGBA}) {
        const int w = 5, h = 3;
        const auto pixels = ramp(static_cast<std::size_t>(w * h * Image2D::bytesPerPixel(format)));
        Ref<Image2D> image(new Image2D(format, w, h, std::span<const std::uint8_t>(pixels)));
        const std::vector<std::uint8_t> png = encodePng(*image);
        ASSERT_GT(png.size(), 8u);
        EXPECT_EQ(png[1], 'P');
        EXPECT_EQ(png[2], 'N');
        Ref<Image2D> back = reload(png);
        ASSERT_TRUE(back) << "format " << format;
        EXPECT_EQ(back->getFormat(), format);
        EXPECT_EQ(back->getWidth(), w);
        EXPECT_EQ(back->getHeight(), h);
        EXPECT_TRUE(std::equal(pixels.begin(), pixels.end(), back->pixels().begin(), back->pixels().end()))
            << "format " << format;
    }
}

TEST(PngWriter, AlphaImageIsWhiteWithItsAlpha) {
    const std::vector<std::uint8_t> alpha{0, 64, 128, 255};
    Ref<Image2D> image(new Image2D(Image2D::ALPHA, 2, 2, std::span<const std::uint8_t>(alpha)));
    Ref<Image2D> back = reload(encodePng(*image));
    ASSERT_TRUE(back);
    EXPECT_EQ(back->getFormat(), Image2D::RGBA);
    const std::vector<std::uint8_t> want{255, 255, 255, 0, 255, 255, 255, 64, 255, 255, 255, 128, 255, 255, 255, 255};
    EXPECT_TRUE(std::equal(want.begin(), want.end(), back->pixels().begin(), back->pixels().end()));
}

TEST(PngWriter, WritesAFileAndNamesAPathItCannotWrite) {
    const auto path = std::filesystem::temp_directory_path() / "m3g-pngwriter-test.png";
    Ref<Image2D> image(new Image2D(Image2D::RGB, 4, 2));  // mutable: opaque white
    writePng(*image, path.string());
    auto loaded = Loader::load(path.string());
    ASSERT_EQ(loaded.size(), 1u);
    auto* back = dynamic_cast<Image2D*>(loaded[0].get());
    ASSERT_TRUE(back);
    EXPECT_EQ(back->getWidth(), 4);
    EXPECT_EQ(back->pixels()[0], 255);
    std::filesystem::remove(path);
    try {
        writePng(*image, "/nonexistent-folder/x.png");
        FAIL() << "no IOException";
    } catch (const IOException& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent-folder/x.png"), std::string::npos) << e.what();
    }
}
