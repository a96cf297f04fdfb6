// Writing an Image2D as a PNG file: an m3g-vk extension (JSR-184 1.1 has
// no image writer; a Java MIDlet reads pixels through its Canvas instead),
// for headless programs that render into an Image2D and keep the result
// (docs/library.md).
#pragma once

#include <m3g/Export.h>

#include <cstdint>
#include <string>
#include <vector>

namespace m3g {

class Image2D;

/// The image as PNG bytes, 8 bits per sample: LUMINANCE as grey,
/// LUMINANCE_ALPHA as grey + alpha, RGB as RGB, RGBA as RGBA, ALPHA as
/// white with that alpha (RGBA). A palettised image is written with its
/// palette resolved.
M3G_API std::vector<std::uint8_t> encodePng(const Image2D& image);

/// Writes encodePng(image) to `path`, replacing the file. IOException naming
/// the path if it cannot be written.
M3G_API void writePng(const Image2D& image, const std::string& path);

}  // namespace m3g
