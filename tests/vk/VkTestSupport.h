// Device tests: one Vulkan device per process, validation layer
// on, and a check after every test that the layer said nothing. Golden
// images live in tests/golden; on a mismatch the actual, expected and diff
// PNGs are written to the build tree (M3G_GOLDEN_OUT) and named in the
// failure. M3G_UPDATE_GOLDEN=1 rewrites the baselines.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include <m3g/m3g.h>
#include <m3g/vk/Vulkan.h>

#include "ImageIO.h"

namespace m3gtest {

/// True in an AddressSanitizer build (scripts/test's sanitizer stage): its
/// quarantine holds freed blocks back, so resident memory grows by design
/// and the soak tests' resident-memory bounds say nothing there.
#ifdef __SANITIZE_ADDRESS__
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif

class VkTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    /// A mutable RGBA Image2D of the given size filled with `argb`.
    static m3g::Ref<m3g::Image2D> target(int width, int height, std::uint32_t argb = 0xFF000000u);
    /// RGBA pixel (r, g, b, a) of an RGB/RGBA Image2D as 0xAARRGGBB.
    static std::uint32_t pixel(const m3g::Image2D& image, int x, int y);
    static m3gcli::RgbaImage toRgba(const m3g::Image2D& image);
    /// Compares `image` with tests/golden/<name>.png: at most `maxShare` of the
    /// pixels may differ by more than `threshold` in a channel.
    static void expectGolden(const m3g::Image2D& image, const std::string& name, int threshold = 3,
                             double maxShare = 0.002);

    std::uint64_t messagesBefore_ = 0;
};

/// A device test that changes Graphics3D's skinning mode: leaves it as it
/// found it (M3G_SKINNING may have set it for the whole run).
class SkinningModeTest : public VkTest {
protected:
    void SetUp() override;
    void TearDown() override;

    int mode_ = 0;
};

}  // namespace m3gtest
