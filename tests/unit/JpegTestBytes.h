// Hand-made JPEG files for the tests: libjpeg's encoder on a small spec
// (size, components, quality, sampling factors, progressive or custom scan
// script, arithmetic coding), and the byte positions of the markers the
// tests patch. Test-only.
#pragma once

#include <algorithm>
#include <csetjmp>
#include <cstdio>  // before jpeglib.h, which uses FILE
#include <cstdlib>
#include <optional>
#include <utility>
#include <vector>

#include <jpeglib.h>

#include "M3GTestBytes.h"

namespace m3gtest {

struct JpegSpec {
    int width = 16, height = 16;
    int components = 3;  ///< 1 greyscale, 3 RGB (stored as YCbCr), 4 CMYK
    Bytes pixels;        ///< width × height × components, rows top to bottom
    int quality = 100;
    /// (h, v) sampling factor per component; empty: 1x1 each (4:4:4).
    std::vector<std::pair<int, int>> sampling;
    bool progressive = false;  ///< libjpeg's standard progressive script
    std::vector<jpeg_scan_info> scans;  ///< a scan script of one's own (overrides progressive)
    bool arithmetic = false;
};

struct JpegWriteError {
    jpeg_error_mgr pub;  // first: libjpeg hands back a pointer to it
    std::jmp_buf jump;
};

// libjpeg's default would call exit(); the writer reports failure instead.
[[noreturn]] inline void jpegWriteErrorExit(j_common_ptr cinfo) {
    std::longjmp(reinterpret_cast<JpegWriteError*>(cinfo->err)->jump, 1);
}

// Encodes with libjpeg. Only trivially destructible locals across setjmp.
inline bool jpegWriteImpl(const JpegSpec* s, jpeg_compress_struct* c, JpegWriteError* err, unsigned char** buf,
                          unsigned long* size) {
    if (setjmp(err->jump)) return false;
    jpeg_create_compress(c);
    jpeg_mem_dest(c, buf, size);
    c->image_width = static_cast<JDIMENSION>(s->width);
    c->image_height = static_cast<JDIMENSION>(s->height);
    c->input_components = s->components;
    c->in_color_space = s->components == 1 ? JCS_GRAYSCALE : s->components == 4 ? JCS_CMYK : JCS_RGB;
    jpeg_set_defaults(c);
    jpeg_set_quality(c, s->quality, TRUE);
    c->dct_method = JDCT_ISLOW;
    c->arith_code = s->arithmetic ? TRUE : FALSE;
    for (int i = 0; i < c->num_components; ++i) {
        const bool given = static_cast<std::size_t>(i) < s->sampling.size();
        c->comp_info[i].h_samp_factor = given ? s->sampling[static_cast<std::size_t>(i)].first : 1;
        c->comp_info[i].v_samp_factor = given ? s->sampling[static_cast<std::size_t>(i)].second : 1;
    }
    if (!s->scans.empty()) {
        c->scan_info = s->scans.data();
        c->num_scans = static_cast<int>(s->scans.size());
    } else if (s->progressive) {
        jpeg_simple_progression(c);
    }
    jpeg_start_compress(c, TRUE);
    const std::size_t rowBytes = static_cast<std::size_t>(s->width) * static_cast<std::size_t>(s->components);
    while (c->next_scanline < c->image_height) {
        JSAMPROW row = const_cast<JSAMPROW>(s->pixels.data()) + c->next_scanline * rowBytes;
        jpeg_write_scanlines(c, &row, 1);
    }
    jpeg_finish_compress(c);
    return true;
}

/// The JPEG file of `s` (empty if libjpeg refuses the spec).
inline Bytes writeJpeg(const JpegSpec& s) {
    jpeg_compress_struct c{};
    JpegWriteError err{};
    c.err = jpeg_std_error(&err.pub);
    err.pub.error_exit = jpegWriteErrorExit;
    unsigned char* buf = nullptr;
    unsigned long size = 0;
    Bytes out;
    if (jpegWriteImpl(&s, &c, &err, &buf, &size)) out.assign(buf, buf + size);
    jpeg_destroy_compress(&c);
    std::free(buf);  // jpeg_mem_dest's buffer, malloc'd by libjpeg (also after a failure)
    dumpFuzzSeed(out, ".jpg");  // seeds of the jpeg fuzz target (scripts/fuzz)
    return out;
}

/// Byte offset of the first marker FF `code` in `b` (after SOI), if any.
inline std::optional<std::size_t> findMarker(const Bytes& b, std::uint8_t code) {
    for (std::size_t i = 2; i + 1 < b.size(); ++i)
        if (b[i] == 0xFF && b[i + 1] == code) return i;
    return std::nullopt;
}

/// Sets the image size in the frame header (SOF0, SOF2 or SOF9 marker:
/// FF Cn, length(2), precision(1), height(2), width(2), ...).
inline void setJpegSize(Bytes& b, std::uint16_t width, std::uint16_t height) {
    for (std::uint8_t sof : {std::uint8_t(0xC0), std::uint8_t(0xC2), std::uint8_t(0xC9)}) {
        if (auto at = findMarker(b, sof)) {
            b[*at + 5] = static_cast<std::uint8_t>(height >> 8);
            b[*at + 6] = static_cast<std::uint8_t>(height);
            b[*at + 7] = static_cast<std::uint8_t>(width >> 8);
            b[*at + 8] = static_cast<std::uint8_t>(width);
            return;
        }
    }
}

/// width × height × components samples of a pattern whose neighbouring
/// samples and channels differ by far more than JPEG's loss at quality 100:
/// red follows x, green follows y, blue the diagonal (grey: x + y).
inline Bytes jpegTestPattern(int width, int height, int components) {
    Bytes px;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const int r = 16 + x * 224 / std::max(1, width - 1);
            const int g = 16 + y * 224 / std::max(1, height - 1);
            const int bl = 240 - (x + y) * 224 / std::max(1, width + height - 2);
            if (components == 1) {
                px.push_back(static_cast<std::uint8_t>((r + g) / 2));
            } else {
                px.push_back(static_cast<std::uint8_t>(r));
                px.push_back(static_cast<std::uint8_t>(g));
                px.push_back(static_cast<std::uint8_t>(bl));
                if (components == 4) px.push_back(static_cast<std::uint8_t>(40));
            }
        }
    return px;
}

}  // namespace m3gtest
