#include "ImageIO.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>

#include <png.h>

#include <m3g/Graphics.h>
#include <m3g/Image2D.h>
#include <m3g/PngWriter.h>

#include "CliErrors.h"
#include "JpegWriter.h"

namespace m3gcli {

RgbaImage fromGraphics(const m3g::Graphics& graphics) {
    RgbaImage out;
    out.width = graphics.getWidth();
    out.height = graphics.getHeight();
    const auto px = graphics.pixels();
    out.pixels.resize(px.size() * 4);
    for (std::size_t i = 0; i < px.size(); ++i) {
        out.pixels[i * 4] = static_cast<std::uint8_t>(px[i] >> 16);
        out.pixels[i * 4 + 1] = static_cast<std::uint8_t>(px[i] >> 8);
        out.pixels[i * 4 + 2] = static_cast<std::uint8_t>(px[i]);
        out.pixels[i * 4 + 3] = static_cast<std::uint8_t>(px[i] >> 24);
    }
    return out;
}

RgbaImage readPng(const std::string& path) {
    png_image img{};
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&img, path.c_str()))
        throw std::runtime_error("cannot read PNG " + path + ": " + img.message);
    img.format = PNG_FORMAT_RGBA;
    RgbaImage out;
    out.width = static_cast<int>(img.width);
    out.height = static_cast<int>(img.height);
    out.pixels.resize(PNG_IMAGE_SIZE(img));
    if (!png_image_finish_read(&img, nullptr, out.pixels.data(), 0, nullptr)) {
        std::string message = img.message;
        png_image_free(&img);
        throw std::runtime_error("cannot decode PNG " + path + ": " + message);
    }
    return out;
}

namespace {

/// A libpng simplified-API description of `image`; RGB8 data goes to `rgb`.
png_image describe(const RgbaImage& image, bool alpha, std::vector<std::uint8_t>& rgb, const void*& data) {
    png_image img{};
    img.version = PNG_IMAGE_VERSION;
    img.width = static_cast<png_uint_32>(image.width);
    img.height = static_cast<png_uint_32>(image.height);
    img.format = PNG_FORMAT_RGBA;
    data = image.pixels.data();
    if (!alpha) {
        img.format = PNG_FORMAT_RGB;
        rgb.resize(static_cast<std::size_t>(image.width) * image.height * 3);
        for (std::size_t i = 0; i < rgb.size() / 3; ++i)
            for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = image.pixels[i * 4 + c];
        data = rgb.data();
    }
    return img;
}

}  // namespace

void writePng(const std::string& path, const RgbaImage& image, bool alpha) {
    std::vector<std::uint8_t> rgb;
    const void* data = nullptr;
    png_image img = describe(image, alpha, rgb, data);
    const bool ok = path == "-" ? png_image_write_to_stdio(&img, stdout, 0, data, 0, nullptr)
                                : png_image_write_to_file(&img, path.c_str(), 0, data, 0, nullptr);
    if (!ok) throw std::runtime_error("cannot write PNG " + path + ": " + img.message);
}

ImageFormat imageFormatFor(const std::string& path) {
    if (path == "-") return ImageFormat::Png;
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".png") return ImageFormat::Png;
    if (ext == ".jpg" || ext == ".jpeg") return ImageFormat::Jpeg;
    throw CliError("cannot tell the image format of '" + path + "'" +
                   (ext.empty() ? std::string(" (no extension)") : " ('" + ext + "' is not one)") +
                   ": name it .png, .jpg or .jpeg");
}

void writeImage(const std::string& path, const RgbaImage& image, bool alpha) {
    const ImageFormat format = imageFormatFor(path);
    try {
        if (format == ImageFormat::Png) {
            writePng(path, image, alpha);
            return;
        }
        const std::vector<std::uint8_t> bytes = encodeJpeg(image);
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        if (out) out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        if (!out) throw std::runtime_error("cannot write JPEG " + path);
    } catch (const std::runtime_error& e) {
        throw OutputError(e.what());
    }
}

std::vector<std::uint8_t> encodePng(const RgbaImage& image, bool alpha) {
    // The library's encoder (api/m3g/PngWriter.h), over an Image2D of the pixels.
    std::vector<std::uint8_t> rgb;
    const void* data = nullptr;
    describe(image, alpha, rgb, data);
    const std::size_t bytes = static_cast<std::size_t>(image.width) * image.height * (alpha ? 4 : 3);
    m3g::Ref<m3g::Image2D> pixels(new m3g::Image2D(alpha ? m3g::Image2D::RGBA : m3g::Image2D::RGB, image.width,
                                                   image.height,
                                                   std::span<const std::uint8_t>(static_cast<const std::uint8_t*>(data), bytes)));
    return m3g::encodePng(*pixels);
}

Comparison compareImages(const RgbaImage& a, const RgbaImage& b, int threshold) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                    " and " + std::to_string(b.width) + "x" + std::to_string(b.height));
    Comparison c;
    c.total = static_cast<long long>(a.width) * a.height;
    double squared = 0.0;
    for (long long i = 0; i < c.total; ++i) {
        int largest = 0;
        for (int k = 0; k < 3; ++k) {
            const int d = std::abs(static_cast<int>(a.pixels[i * 4 + k]) - static_cast<int>(b.pixels[i * 4 + k]));
            largest = std::max(largest, d);
            squared += static_cast<double>(d) * d;
        }
        if (largest > threshold) ++c.differing;
        c.maxDifference = std::max(c.maxDifference, largest);
    }
    c.share = c.total ? static_cast<double>(c.differing) / static_cast<double>(c.total) : 0.0;
    const double mse = c.total ? squared / (3.0 * static_cast<double>(c.total)) : 0.0;
    c.psnr = mse == 0.0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(255.0 * 255.0 / mse);
    return c;
}

bool withinLimits(const Comparison& c, double maxShare, double minPsnr) {
    return c.share <= maxShare && c.psnr >= minPsnr;
}

std::string comparisonReport(const Comparison& c, int threshold, double maxShare, double minPsnr) {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "differing pixels (max channel diff > %d): %lld of %lld (%.3f%%)\n"
                  "PSNR: %.2f dB\nlargest difference: %d\n"
                  "%s (limits: share <= %.3f%%, PSNR >= %.1f dB)\n",
                  threshold, c.differing, c.total, 100.0 * c.share, c.psnr, c.maxDifference,
                  withinLimits(c, maxShare, minPsnr) ? "PASS" : "FAIL", 100.0 * maxShare, minPsnr);
    return buf;
}

bool isUniform(const RgbaImage& image) {
    const std::size_t n = image.pixels.size();
    for (std::size_t i = 4; i < n; ++i)
        if (image.pixels[i] != image.pixels[i % 4]) return false;
    return true;
}

RgbaImage diffImage(const RgbaImage& a, const RgbaImage& b, int threshold) {
    RgbaImage out = a;
    const std::size_t n = static_cast<std::size_t>(a.width) * a.height;
    for (std::size_t i = 0; i < n; ++i) {
        int largest = 0;
        for (int k = 0; k < 3; ++k)
            largest = std::max(largest, std::abs(static_cast<int>(a.pixels[i * 4 + k]) - static_cast<int>(b.pixels[i * 4 + k])));
        const auto grey = static_cast<std::uint8_t>((a.pixels[i * 4] + a.pixels[i * 4 + 1] + a.pixels[i * 4 + 2]) / 6);
        if (largest > threshold) {
            out.pixels[i * 4] = static_cast<std::uint8_t>(std::min(255, 128 + largest));
            out.pixels[i * 4 + 1] = out.pixels[i * 4 + 2] = 0;
        } else {
            out.pixels[i * 4] = out.pixels[i * 4 + 1] = out.pixels[i * 4 + 2] = grey;
        }
        out.pixels[i * 4 + 3] = 255;
    }
    return out;
}

}  // namespace m3gcli
