// What the loader's image decoders (PngImage, JpegImage) produce, and the
// limits they share against hostile input (JSR-184 1.1, Loader: a PNG or
// JPEG file loads as one immutable Image2D).
//
// Internal to the loader (scene/), not part of the public API. Creating the
// Image2D from the result is the loader's job.
#pragma once

#include <cstdint>
#include <vector>

namespace m3g::detail {

/// An image file decoded to Image2D pixels.
struct DecodedImage {
    int format = 0;  ///< Image2D::LUMINANCE, LUMINANCE_ALPHA, RGB or RGBA
    int width = 0;
    int height = 0;
    /// Rows top to bottom, tightly packed, Image2D::bytesPerPixel(format) bytes per pixel.
    std::vector<std::uint8_t> pixels;
};

/// Largest width or height accepted, and largest decoded size in bytes, for
/// every image format: a few bytes can declare a huge image, and the checks
/// come before anything that size is allocated.
inline constexpr std::uint32_t kImageMaxDimension = 16384;
inline constexpr std::uint64_t kImageMaxDecodedBytes = 256ull << 20;

}  // namespace m3g::detail
