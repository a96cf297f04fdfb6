#include "VkTestSupport.h"

#include <cstdlib>
#include <filesystem>

#include "HoldDriver.h"

namespace m3gtest {

#ifdef __SANITIZE_ADDRESS__
namespace {
// The leak check stays on for these tests (HoldDriver.h says why this is needed).
[[maybe_unused]] const bool gDriverHeld = holdLavapipeLoaded();
}  // namespace
#endif

void VkTest::SetUp() {
    m3g::vk::requestValidation(true);
    messagesBefore_ = m3g::vk::validationMessageCount();
}

void VkTest::TearDown() {
    m3g::Graphics3D::getInstance()->releaseTarget();
    const auto after = m3g::vk::validationMessageCount();
    EXPECT_EQ(after, messagesBefore_) << "validation layer messages during the test; last: "
                                      << m3g::vk::lastValidationMessage();
}

m3g::Ref<m3g::Image2D> VkTest::target(int width, int height, std::uint32_t argb) {
    m3g::Ref<m3g::Image2D> image(new m3g::Image2D(m3g::Image2D::RGBA, width, height));
    std::vector<std::uint8_t> px(static_cast<std::size_t>(width) * height * 4);
    for (std::size_t i = 0; i < px.size(); i += 4) {
        px[i] = static_cast<std::uint8_t>(argb >> 16);
        px[i + 1] = static_cast<std::uint8_t>(argb >> 8);
        px[i + 2] = static_cast<std::uint8_t>(argb);
        px[i + 3] = static_cast<std::uint8_t>(argb >> 24);
    }
    image->set(0, 0, width, height, px);
    return image;
}

std::uint32_t VkTest::pixel(const m3g::Image2D& image, int x, int y) {
    std::vector<std::uint8_t> rgba;
    image.getPixelsRGBA8(rgba);
    const std::size_t i = (static_cast<std::size_t>(y) * image.getWidth() + x) * 4;
    return (std::uint32_t(rgba[i + 3]) << 24) | (std::uint32_t(rgba[i]) << 16) | (std::uint32_t(rgba[i + 1]) << 8) |
           rgba[i + 2];
}

m3gcli::RgbaImage VkTest::toRgba(const m3g::Image2D& image) {
    m3gcli::RgbaImage out;
    out.width = image.getWidth();
    out.height = image.getHeight();
    image.getPixelsRGBA8(out.pixels);
    return out;
}

void VkTest::expectGolden(const m3g::Image2D& image, const std::string& name, int threshold, double maxShare) {
    namespace fs = std::filesystem;
    const fs::path golden = fs::path(M3G_GOLDEN_DIR) / (name + ".png");
    const m3gcli::RgbaImage actual = toRgba(image);
    const char* update = std::getenv("M3G_UPDATE_GOLDEN");
    if (update && std::string(update) == "1") {
        m3gcli::writePng(golden.string(), actual, false);
        return;
    }
    ASSERT_TRUE(fs::exists(golden)) << "no golden image " << golden << " (run with M3G_UPDATE_GOLDEN=1 to create it)";
    const m3gcli::RgbaImage expected = m3gcli::readPng(golden.string());
    const m3gcli::Comparison c = m3gcli::compareImages(actual, expected, threshold);
    if (c.share > maxShare) {
        const fs::path out = fs::path(M3G_GOLDEN_OUT);
        fs::create_directories(out);
        m3gcli::writePng((out / (name + ".actual.png")).string(), actual, false);
        m3gcli::writePng((out / (name + ".expected.png")).string(), expected, false);
        m3gcli::writePng((out / (name + ".diff.png")).string(), m3gcli::diffImage(actual, expected, threshold), false);
        ADD_FAILURE() << name << ": " << c.differing << " of " << c.total << " pixels differ by more than " << threshold
                      << " (share " << c.share << " > " << maxShare << "), PSNR " << c.psnr << " dB; see "
                      << (out / (name + ".{actual,expected,diff}.png"));
    }
}

void SkinningModeTest::SetUp() {
    VkTest::SetUp();
    mode_ = m3g::Graphics3D::getInstance()->getSkinningMode();
}

void SkinningModeTest::TearDown() {
    m3g::Graphics3D::getInstance()->setSkinningMode(mode_);
    VkTest::TearDown();
}

}  // namespace m3gtest
