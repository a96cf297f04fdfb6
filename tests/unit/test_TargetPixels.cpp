// The read-back of a frame into a Graphics surface (scene/frame/TargetPixels):
// RGBA or BGRA texels to opaque 0xAARRGGBB words, on the calling thread for
// small frames and spread over the shared thread pool for large ones. Every
// word is checked against the formula written out here, byte by byte.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include <m3g/Graphics.h>

#include "TargetPixels.h"

using namespace m3g;

namespace {

/// Texel i's bytes: distinct per channel and position, so a swapped channel,
/// a shifted chunk or a skipped texel changes the word.
std::vector<std::uint8_t> texels(std::size_t count) {
    std::vector<std::uint8_t> t(count * 4);
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t c = 0; c < 4; ++c) t[i * 4 + c] = static_cast<std::uint8_t>((i * 7 + c * 61 + i / 251) & 0xFF);
    return t;
}

/// The expected word: alpha 0xFF, then red, green, blue from their bytes.
std::uint32_t expected(const std::vector<std::uint8_t>& t, std::size_t i, bool bgra) {
    const std::uint32_t r = t[i * 4 + (bgra ? 2 : 0)], g = t[i * 4 + 1], b = t[i * 4 + (bgra ? 0 : 2)];
    return 0xFF000000u | r << 16 | g << 8 | b;
}

}  // namespace

TEST(TargetPixels, OneTexelOfEachOrderByHand) {
    const std::uint8_t rgba[4] = {0x12, 0x34, 0x56, 0x00};
    std::uint32_t out = 0;
    detail::texelsToArgb(rgba, &out, 1, false);
    EXPECT_EQ(out, 0xFF123456u);
    detail::texelsToArgb(rgba, &out, 1, true);  // the same bytes read as B G R A
    EXPECT_EQ(out, 0xFF563412u);
}

TEST(TargetPixels, SmallAndLargeFramesGiveEveryWord) {
    // 5 (the scalar tail alone), 320x240 (on the calling thread), 1280x960
    // and 1280x960 + 3 (chunks over the pool, the last one partial).
    for (std::size_t count : {std::size_t{5}, std::size_t{320 * 240}, std::size_t{1280 * 960},
                              std::size_t{1280 * 960 + 3}}) {
        const auto t = texels(count);
        for (bool bgra : {false, true}) {
            std::vector<std::uint32_t> out(count + 1, 0xDEADBEEFu);  // one guard word past the end
            detail::texelsToArgbParallel(t.data(), out.data(), count, bgra);
            std::size_t wrong = 0;
            for (std::size_t i = 0; i < count; ++i) wrong += out[i] != expected(t, i, bgra);
            EXPECT_EQ(wrong, 0u) << count << " texels, bgra " << bgra;
            EXPECT_EQ(out[count], 0xDEADBEEFu) << "written past " << count << " texels";
        }
    }
}

TEST(TargetPixels, GraphicsSurfaceGetsTheFrame) {
    Graphics g(1280, 960);
    const auto t = texels(1280 * 960);
    detail::GraphicsTargetPixels pixels(g);
    pixels.write(t.data(), false);
    const auto px = g.pixels();
    ASSERT_EQ(px.size(), t.size() / 4);
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < px.size(); ++i) wrong += px[i] != expected(t, i, false);
    EXPECT_EQ(wrong, 0u);
}
