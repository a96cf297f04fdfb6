#include "TargetPixels.h"

#include <algorithm>
#include <cstring>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <m3g/Graphics.h>
#include <m3g/Image2D.h>
#include <m3g/skin/ThreadPool.h>

namespace m3g::detail {

namespace {

/// Texels per task of a parallel conversion (128 KiB each way), and the
/// fewest tasks worth waking the pool for: a 320x240 frame (77K texels,
/// tens of microseconds) stays on the calling thread, a 1280x960 one (1.2M
/// texels: 4.9 MB read and 4.9 MB written, a memory-bound pass that one core
/// does not saturate) is spread over the cores, which lavapipe's rasteriser
/// threads have left idle by the time the frame is read back.
constexpr std::size_t kTexelsPerTask = std::size_t{1} << 15;
constexpr std::size_t kMinTasks = 4;

}  // namespace

void texelsToArgb(const std::uint8_t* src, std::uint32_t* out, std::size_t count, bool bgra) noexcept {
    std::size_t i = 0;
#if defined(__SSE2__)
    // Four texels per step: at 1280x960 the byte-by-byte loop was a quarter
    // of an empty headless frame's CPU time (GCC does not vectorise it at -O2).
    const __m128i opaque = _mm_set1_epi32(static_cast<int>(0xFF000000u));
    const __m128i green = _mm_set1_epi32(0x0000FF00);
    const __m128i low = _mm_set1_epi32(0x000000FF);
    for (; i + 4 <= count; i += 4) {
        const __m128i t = _mm_loadu_si128(reinterpret_cast<const __m128i*>(src + i * 4));
        __m128i argb;
        if (bgra) {
            argb = _mm_or_si128(t, opaque);
        } else {  // R | G << 8 | B << 16 -> B | G << 8 | R << 16
            const __m128i r = _mm_slli_epi32(_mm_and_si128(t, low), 16);
            const __m128i b = _mm_and_si128(_mm_srli_epi32(t, 16), low);
            argb = _mm_or_si128(_mm_or_si128(r, b), _mm_or_si128(_mm_and_si128(t, green), opaque));
        }
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i), argb);
    }
#endif
    const int red = bgra ? 2 : 0, blue = bgra ? 0 : 2;
    for (; i < count; ++i)
        out[i] = 0xFF000000u | (static_cast<std::uint32_t>(src[i * 4 + red]) << 16) |
                 (static_cast<std::uint32_t>(src[i * 4 + 1]) << 8) | src[i * 4 + blue];
}

void ImageTargetPixels::read(std::span<std::uint8_t> out) const {
    std::vector<std::uint8_t> rgba;
    image_.getPixelsRGBA8(rgba);
    std::memcpy(out.data(), rgba.data(), std::min(rgba.size(), out.size()));
}

void ImageTargetPixels::write(const std::uint8_t* texels, bool) {
    const int w = image_.getWidth(), h = image_.getHeight();
    const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
    if (image_.getFormat() == Image2D::RGBA) {
        image_.set(0, 0, w, h, {texels, n * 4});
        return;
    }
    std::vector<std::uint8_t> rgb(n * 3);
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = texels[i * 4 + c];
    image_.set(0, 0, w, h, rgb);
}

void GraphicsTargetPixels::read(std::span<std::uint8_t> out) const {
    const auto px = graphics_.pixels();
    const std::size_t n = std::min(px.size(), out.size() / 4);
    for (std::size_t i = 0; i < n; ++i) {
        out[i * 4 + 0] = static_cast<std::uint8_t>(px[i] >> 16);
        out[i * 4 + 1] = static_cast<std::uint8_t>(px[i] >> 8);
        out[i * 4 + 2] = static_cast<std::uint8_t>(px[i]);
        out[i * 4 + 3] = static_cast<std::uint8_t>(px[i] >> 24);
    }
}

void texelsToArgbParallel(const std::uint8_t* src, std::uint32_t* out, std::size_t count, bool bgra) noexcept {
    const std::size_t tasks = (count + kTexelsPerTask - 1) / kTexelsPerTask;
    if (tasks < kMinTasks) {
        texelsToArgb(src, out, count, bgra);
        return;
    }
    auto task = [&](std::size_t t) {
        const std::size_t first = t * kTexelsPerTask;
        const std::size_t n = std::min(kTexelsPerTask, count - first);
        texelsToArgb(src + first * 4, out + first, n, bgra);
    };
    skin::ThreadPool::shared().parallelFor(tasks, task);
}

void GraphicsTargetPixels::write(const std::uint8_t* texels, bool bgra) {
    auto px = graphics_.pixels();
    texelsToArgbParallel(texels, px.data(), px.size(), bgra);
}

}  // namespace m3g::detail
