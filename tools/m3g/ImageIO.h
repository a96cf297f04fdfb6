// PNG reading, PNG and JPEG writing (by the output's extension) and image comparison for the m3g tool and the image
// tests (the device tests' measure: count of pixels whose largest channel
// difference exceeds a threshold, and PSNR). Part of m3g_cli_support.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace m3g {
class Graphics;
}

namespace m3gcli {

/// 8-bit RGBA pixels, rows top to bottom.
struct RgbaImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> pixels;
};

/// The pixels of an lcdui-style Graphics surface (ARGB ints) as RGBA8.
RgbaImage fromGraphics(const m3g::Graphics& graphics);

/// Reads any PNG as RGBA8. Throws std::runtime_error naming the file.
RgbaImage readPng(const std::string& path);
/// Writes RGBA8 (or RGB8 when `alpha` is false) to `path`; "-" is stdout.
void writePng(const std::string& path, const RgbaImage& image, bool alpha);

/// The image file formats the tool writes.
enum class ImageFormat { Png, Jpeg };

/// The format an output path asks for by its extension, any case: .png;
/// .jpg or .jpeg; "-" (stdout) is PNG. Any other extension, or none, throws
/// CliError naming the path and the extensions written: an image is never
/// written in a format its name does not say.
ImageFormat imageFormatFor(const std::string& path);

/// Writes `image` in imageFormatFor(path): PNG as writePng, JPEG without
/// alpha. Throws CliError for an unknown extension, OutputError (naming the
/// path) when the file cannot be written.
void writeImage(const std::string& path, const RgbaImage& image, bool alpha);
/// The PNG file bytes of `image` (RGBA8, or RGB8 when `alpha` is false).
/// Throws std::runtime_error when libpng fails.
std::vector<std::uint8_t> encodePng(const RgbaImage& image, bool alpha);

struct Comparison {
    long long differing = 0;  ///< pixels whose largest RGB difference exceeds the threshold
    long long total = 0;
    double share = 0.0;       ///< differing / total
    double psnr = 0.0;        ///< over RGB, in dB; infinity when identical
    int maxDifference = 0;
};

/// Compares RGB channels of two images of the same size (throws
/// std::invalid_argument otherwise).
Comparison compareImages(const RgbaImage& a, const RgbaImage& b, int threshold);
/// The verdict of `m3g compare`: share <= maxShare and psnr >= minPsnr.
bool withinLimits(const Comparison& c, double maxShare, double minPsnr);
/// The report of `m3g compare` (several lines, ends with a newline):
/// differing pixels, PSNR, largest difference, then PASS or FAIL with the limits.
std::string comparisonReport(const Comparison& c, int threshold, double maxShare, double minPsnr);

/// True when every pixel of `image` (RGBA) is the same: a render that shows
/// nothing but the clear colour.
bool isUniform(const RgbaImage& image);

/// A diff image: grey copy of `a`, differing pixels in red with brightness
/// by difference.
RgbaImage diffImage(const RgbaImage& a, const RgbaImage& b, int threshold);

}  // namespace m3gcli
