#include <m3g/Image2D.h>

#include <algorithm>
#include <new>

#include "Check.h"

namespace m3g {

int Image2D::bytesPerPixel(int format) noexcept {
    switch (format) {
    case ALPHA:
    case LUMINANCE: return 1;
    case LUMINANCE_ALPHA: return 2;
    case RGB: return 3;
    case RGBA: return 4;
    default: return 0;
    }
}

void Image2D::init(int format, int width, int height, const char* where) {
    detail::requireEnum(format, {ALPHA, LUMINANCE, LUMINANCE_ALPHA, RGB, RGBA}, where, "format");
    if (width <= 0)
        throw IllegalArgumentException(detail::str(where, ": width ", width, " out of range [1, 2147483647]"));
    if (height <= 0)
        throw IllegalArgumentException(detail::str(where, ": height ", height, " out of range [1, 2147483647]"));
    format_ = format;
    width_ = width;
    height_ = height;
}

namespace {
// width * height * bpp without overflow (both are positive ints).
std::size_t byteCount(int width, int height, int bpp) {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * static_cast<std::size_t>(bpp);
}

void allocate(std::vector<std::uint8_t>& v, std::size_t n, std::uint8_t fill, const char* where) {
    try {
        v.assign(n, fill);
    } catch (const std::bad_alloc&) {
        throw OutOfMemoryError(detail::str(where, ": cannot allocate ", n, " bytes of pixels"));
    } catch (const std::length_error&) {
        throw OutOfMemoryError(detail::str(where, ": cannot allocate ", n, " bytes of pixels"));
    }
}
}  // namespace

Image2D::Image2D(int format, int width, int height, std::span<const std::uint8_t> pixels) {
    const char* where = "Image2D::Image2D";
    init(format, width, height, where);
    if (pixels.data() == nullptr) detail::throwNull(where, "pixels");
    const std::size_t n = byteCount(width, height, bytesPerPixel());
    if (pixels.size() < n)
        throw IllegalArgumentException(
            detail::str(where, ": pixels has length ", pixels.size(), ", needs at least ", n, " (width * height * bpp)"));
    allocate(pixels_, n, 0, where);
    std::copy_n(pixels.begin(), n, pixels_.begin());
}

Image2D::Image2D(int format, int width, int height, std::span<const std::uint8_t> indices,
                 std::span<const std::uint8_t> palette) {
    const char* where = "Image2D::Image2D";
    init(format, width, height, where);
    if (indices.data() == nullptr) detail::throwNull(where, "indices");
    if (palette.data() == nullptr) detail::throwNull(where, "palette");
    const std::size_t count = byteCount(width, height, 1);
    if (indices.size() < count)
        throw IllegalArgumentException(
            detail::str(where, ": indices has length ", indices.size(), ", needs at least ", count, " (width * height)"));
    const std::size_t bpp = static_cast<std::size_t>(bytesPerPixel());
    const std::size_t fullPalette = 256 * bpp;
    if (palette.size() < fullPalette && palette.size() % bpp != 0)
        throw IllegalArgumentException(detail::str(where, ": palette length ", palette.size(),
                                                   " is shorter than 256 entries and not a multiple of ", bpp,
                                                   " bytes per entry"));
    palettized_ = true;
    const std::size_t paletteBytes = std::min(palette.size(), fullPalette);
    palette_.assign(palette.begin(), palette.begin() + static_cast<std::ptrdiff_t>(paletteBytes));
    allocate(indices_, count, 0, where);
    std::copy_n(indices.begin(), count, indices_.begin());
    allocate(pixels_, count * bpp, 0, where);
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t entry = static_cast<std::size_t>(indices_[i]) * bpp;
        if (entry + bpp <= palette_.size())
            std::copy_n(palette_.begin() + static_cast<std::ptrdiff_t>(entry), bpp,
                        pixels_.begin() + static_cast<std::ptrdiff_t>(i * bpp));
        // else: past the end of a short palette, left as zero bytes
    }
}

Image2D::Image2D(int format, int width, int height) : mutable_(true) {
    const char* where = "Image2D::Image2D";
    init(format, width, height, where);
    allocate(pixels_, byteCount(width, height, bytesPerPixel()), 0xFF, where);
}

Image2D::Image2D(const Image2D& other) = default;

Image2D::~Image2D() = default;

Object3D* Image2D::duplicateImpl(DuplicateMap&) const { return new Image2D(*this); }

void Image2D::set(int x, int y, int width, int height, std::span<const std::uint8_t> pixels) {
    const char* where = "Image2D::set";
    if (pixels.data() == nullptr) detail::throwNull(where, "pixels");
    if (!mutable_) detail::throwISE("Image2D::set: the image is immutable (only Image2D(format, width, height) is mutable)");
    detail::requireRange(x, 0, width_ - 1, where, "x");
    detail::requireRange(y, 0, height_ - 1, where, "y");
    detail::requireRange(width, 1, width_ - x, where, "width");
    detail::requireRange(height, 1, height_ - y, where, "height");
    const int bpp = bytesPerPixel();
    const std::size_t n = byteCount(width, height, bpp);
    if (pixels.size() < n)
        throw IllegalArgumentException(
            detail::str(where, ": pixels has length ", pixels.size(), ", needs at least ", n, " (width * height * bpp)"));
    const std::size_t rowBytes = static_cast<std::size_t>(width) * bpp;
    for (int row = 0; row < height; ++row) {
        const std::size_t dst = (static_cast<std::size_t>(y + row) * width_ + x) * bpp;
        std::copy_n(pixels.begin() + static_cast<std::ptrdiff_t>(row * rowBytes), rowBytes,
                    pixels_.begin() + static_cast<std::ptrdiff_t>(dst));
    }
    touch();
}

void Image2D::getPixelsRGBA8(std::vector<std::uint8_t>& out) const {
    const std::size_t count = byteCount(width_, height_, 1);
    out.resize(count * 4);
    const std::uint8_t* s = pixels_.data();
    std::uint8_t* d = out.data();
    for (std::size_t i = 0; i < count; ++i, d += 4) {
        switch (format_) {
        case ALPHA:
            d[0] = d[1] = d[2] = 255;
            d[3] = s[i];
            break;
        case LUMINANCE:
            d[0] = d[1] = d[2] = s[i];
            d[3] = 255;
            break;
        case LUMINANCE_ALPHA:
            d[0] = d[1] = d[2] = s[2 * i];
            d[3] = s[2 * i + 1];
            break;
        case RGB:
            d[0] = s[3 * i];
            d[1] = s[3 * i + 1];
            d[2] = s[3 * i + 2];
            d[3] = 255;
            break;
        default:  // RGBA
            std::copy_n(s + 4 * i, 4, d);
            break;
        }
    }
}

}  // namespace m3g
