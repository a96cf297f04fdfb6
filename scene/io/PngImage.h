// PNG decoding for the Loader (JSR-184 1.1, Loader): a PNG becomes an
// immutable Image2D whose format follows the PNG colour type, mapped as
// Nokia's M3G implementation (reference) maps it:
//   grey -> LUMINANCE; grey+alpha or grey+tRNS -> LUMINANCE_ALPHA;
//   RGB or palette -> RGB; RGB+tRNS, palette+tRNS or RGBA -> RGBA.
// 16-bit samples are reduced to 8 bits (high byte), 1/2/4-bit grey and
// palettes are expanded. No gamma or colour-space conversion is applied.
//
// Internal to the loader (scene/), not part of the public API. Creating the
// Image2D from the result is the loader's job.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "DecodedImage.h"

namespace m3g::detail {

using PngImage = DecodedImage;

/// Decodes a whole PNG file. Throws IOException naming `context` (e.g. the
/// file name) and the reason on any error (bad signature, truncation, CRC or
/// zlib errors, an image over the limits of DecodedImage.h).
PngImage decodePng(std::span<const std::uint8_t> data, const std::string& context = "PNG image");

}  // namespace m3g::detail
