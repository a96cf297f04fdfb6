// Hand-made PNG files for the tests (and the fuzz seeds): libpng's writer
// on a small spec (size, colour type, bit depth, palette, tRNS, gAMA,
// interlace). Test-only.
#pragma once

#include <csetjmp>
#include <vector>

#include <png.h>

#include "M3GTestBytes.h"

namespace m3gtest {

struct PngSpec {
    int width = 3, height = 2;
    int colorType = PNG_COLOR_TYPE_GRAY;
    int bitDepth = 8;
    bool interlace = false;
    Bytes rows;                     // packed PNG rows (no filter bytes), height × rowbytes
    std::vector<png_color> palette;
    Bytes trnsAlpha;                // palette tRNS
    bool trnsColor = false;
    png_color_16 trns{};            // grey / RGB tRNS
    double gamma = 0;               // 0 = no gAMA chunk
};

inline void writeCb(png_structp png, png_bytep data, png_size_t n) {
    auto* out = static_cast<Bytes*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + n);
}

// Writes with libpng's writer. Only POD locals across setjmp.
inline bool writeImpl(const PngSpec* s, Bytes* out, png_bytepp rows) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, out, writeCb, nullptr);
    png_set_IHDR(png, info, static_cast<png_uint_32>(s->width), static_cast<png_uint_32>(s->height), s->bitDepth,
                 s->colorType, s->interlace ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (!s->palette.empty())
        png_set_PLTE(png, info, s->palette.data(), static_cast<int>(s->palette.size()));
    if (!s->trnsAlpha.empty())
        png_set_tRNS(png, info, s->trnsAlpha.data(), static_cast<int>(s->trnsAlpha.size()), nullptr);
    if (s->trnsColor) png_set_tRNS(png, info, nullptr, 0, &s->trns);
    if (s->gamma > 0) png_set_gAMA(png, info, s->gamma);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return true;
}

/// The PNG file of `s` (empty if libpng refuses the spec).
inline Bytes writePng(const PngSpec& s) {
    const std::size_t rowBytes = s.rows.size() / static_cast<std::size_t>(s.height);
    std::vector<png_bytep> rows;
    for (int y = 0; y < s.height; ++y)
        rows.push_back(const_cast<png_bytep>(s.rows.data()) + static_cast<std::size_t>(y) * rowBytes);
    Bytes out;
    if (!writeImpl(&s, &out, rows.data())) out.clear();
    dumpFuzzSeed(out, ".png");
    return out;
}

}  // namespace m3gtest
