// JPEG decoding for the Loader (JSR-184 1.1, Loader: PNG is the image format
// the specification requires of every implementation; further formats are
// left to the implementation — paraphrased, not checked against a copy here).
// Nokia's M3G implementation (reference) read JPEG files where the handset's
// platform image decoder did, as a standalone file or an external reference,
// so a JPEG becomes an immutable Image2D as a PNG does:
//   greyscale -> LUMINANCE; YCbCr or RGB -> RGB (JPEG has no alpha).
// 8-bit baseline, extended and progressive files, Huffman or arithmetic coded,
// any sampling factors (12-bit and lossless files fail: Debian's libjpeg-turbo
// decodes neither through this API). CMYK and YCCK files fail: libjpeg-turbo
// converts them to CMYK only, not to RGB, and a CMYK -> RGB guess would be a
// colour policy of our own. No colour management (ICC profiles are ignored),
// as for PNG.
//
// Strict about damage: every libjpeg warning about the data (the file ends
// early, a bad Huffman code, bytes where a marker belongs) fails the load,
// where libjpeg would pad or guess and go on; only a warning about the JFIF
// version number (metadata) is ignored.
//
// Internal to the loader (scene/), not part of the public API.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "DecodedImage.h"

namespace m3g::detail {

using JpegImage = DecodedImage;

/// Most scans a progressive file may have (libjpeg-turbo's TurboJPEG API
/// limits it to the same number): each scan makes the decoder pass over the
/// whole image's coefficients again, so a small hostile file with thousands of
/// tiny scans costs minutes of CPU.
inline constexpr int kJpegMaxScans = 500;

/// Decodes a whole JPEG file. Throws IOException naming `context` (e.g. the
/// file name) and the reason on any error: not a JPEG, truncated or corrupt
/// data (with the byte offset the decoder had reached), an image over the limits of
/// DecodedImage.h, an unsupported colour space, too many scans.
JpegImage decodeJpeg(std::span<const std::uint8_t> data, const std::string& context = "JPEG image");

}  // namespace m3g::detail
