// JPEG encoding of an RgbaImage for `m3g render -o OUT.jpg` (and the other
// image outputs), with libjpeg-turbo's libjpeg API, which the library's
// loader already uses to decode (scene/io/JpegImage.cpp). Part of
// m3g_cli_support.
#pragma once

#include <cstdint>
#include <vector>

#include "ImageIO.h"

namespace m3gcli {

/// The JPEG file bytes of the RGB channels of `image` (alpha is dropped:
/// JPEG has none), baseline, 4:2:0, at `quality` (1..100). Throws
/// std::runtime_error with libjpeg's message when encoding fails.
std::vector<std::uint8_t> encodeJpeg(const RgbaImage& image, int quality = 92);

}  // namespace m3gcli
