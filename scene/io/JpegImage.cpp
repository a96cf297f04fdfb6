// JPEG decoding with libjpeg-turbo's libjpeg API (JSR-184 1.1, Loader; the
// colour mapping and the strictness rules are in JpegImage.h).
//
// Why the libjpeg API (Debian: libjpeg62-turbo-dev) and not libjpeg-turbo's
// TurboJPEG API (libturbojpeg0-dev): TurboJPEG 2.1's tjDecompressHeader3
// refuses valid files whose sampling factors are not one of its six named
// subsamplings (e.g. Y 1x2, Cb 1x1, Cr 1x2: "Could not determine subsampling
// type for JPEG image"), which libjpeg decodes; and libjpeg names each
// warning (msg_code), so a metadata warning can be told from damaged data.
// The price is libjpeg's error reporting: its default handler calls exit(),
// so errors come back here by longjmp from a custom error manager, to setjmp
// points in functions whose locals are all trivially destructible (as
// PngImage.cpp does with libpng). libjpeg's own state is freed by the
// Decompressor's destructor, which no jump skips.
#include "JpegImage.h"

#include <algorithm>
#include <csetjmp>
#include <cstdint>
#include <cstdio>  // before jpeglib.h, which uses FILE

#include <jpeglib.h>
#include <jerror.h>

#include <m3g/Exception.h>
#include <m3g/Image2D.h>

#include "Check.h"

namespace m3g::detail {

namespace {

// libjpeg's error manager plus where to jump back to and the message. Left by
// longjmp, so trivially destructible.
struct ErrorManager {
    jpeg_error_mgr pub;  // first: libjpeg hands back a pointer to this member
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
};

ErrorManager* errorManager(j_common_ptr cinfo) { return reinterpret_cast<ErrorManager*>(cinfo->err); }

// Replaces libjpeg's default, which prints the message and calls exit().
[[noreturn]] void errorExit(j_common_ptr cinfo) {
    ErrorManager* err = errorManager(cinfo);
    (*cinfo->err->format_message)(cinfo, err->message);
    std::longjmp(err->jump, 1);
}

// Level -1 is a warning: libjpeg found damaged data and would pad or guess
// (a file ending early is completed with grey). A load must not show that,
// so a warning is an error, except the one about the JFIF version number,
// which says nothing about the pixels. Levels 0 and up are trace messages.
void emitMessage(j_common_ptr cinfo, int level) {
    if (level >= 0) return;
    if (cinfo->err->msg_code == JWRN_JFIF_MAJOR) {
        ++cinfo->err->num_warnings;
        return;
    }
    errorExit(cinfo);
}

// Called by libjpeg as it reads; a progressive file is read whole, scan by
// scan, inside jpeg_start_decompress.
void progressMonitor(j_common_ptr cinfo) {
    if (!cinfo->is_decompressor) return;
    if (reinterpret_cast<j_decompress_ptr>(cinfo)->input_scan_number <= kJpegMaxScans) return;
    ErrorManager* err = errorManager(cinfo);
    std::snprintf(err->message, sizeof err->message,
                  "progressive JPEG with more than %d scans (a limit against hostile input)", kJpegMaxScans);
    std::longjmp(err->jump, 1);
}

// libjpeg's decompressor and what it calls back. The struct is zeroed before
// jpeg_create_decompress so that jpeg_destroy_decompress is safe whenever
// creation stopped (it frees nothing while cinfo.mem is null).
struct Decompressor {
    jpeg_decompress_struct cinfo{};
    ErrorManager err{};
    jpeg_progress_mgr progress{};

    Decompressor() {
        cinfo.err = jpeg_std_error(&err.pub);
        err.pub.error_exit = errorExit;
        err.pub.emit_message = emitMessage;
        progress.progress_monitor = progressMonitor;
    }
    ~Decompressor() { jpeg_destroy_decompress(&cinfo); }
    Decompressor(const Decompressor&) = delete;
    Decompressor& operator=(const Decompressor&) = delete;
};

struct JpegHeader {
    std::uint32_t width, height;
    int components;
    J_COLOR_SPACE colorSpace;
    bool arithmetic;
    /// 8x8 blocks of the component with the most (its DC coefficients are
    /// all coded, each with at least one bit in a Huffman-coded file).
    std::uint64_t largestComponentBlocks;
};

// Phase 1: create the decompressor and read the markers up to the first scan.
// Returns false on error (message in d->err). Only trivially destructible
// locals: libjpeg may longjmp back here.
bool readHeader(Decompressor* d, const std::uint8_t* data, std::size_t size, JpegHeader* out) {
    if (setjmp(d->err.jump)) return false;
    jpeg_create_decompress(&d->cinfo);
    d->cinfo.progress = &d->progress;
    jpeg_mem_src(&d->cinfo, data, static_cast<unsigned long>(size));
    jpeg_read_header(&d->cinfo, TRUE);  // TRUE: a tables-only stream is an error
    out->width = d->cinfo.image_width;
    out->height = d->cinfo.image_height;
    out->components = d->cinfo.num_components;
    out->colorSpace = d->cinfo.jpeg_color_space;
    out->arithmetic = d->cinfo.arith_code != FALSE;
    out->largestComponentBlocks = 0;
    for (int c = 0; c < d->cinfo.num_components; ++c) {
        const jpeg_component_info& comp = d->cinfo.comp_info[c];
        out->largestComponentBlocks = std::max(out->largestComponentBlocks,
                                               std::uint64_t(comp.width_in_blocks) * comp.height_in_blocks);
    }
    return true;
}

// Phase 2: decode into caller-owned storage of height rows of rowBytes.
bool readPixels(Decompressor* d, J_COLOR_SPACE outSpace, int components, std::uint8_t* pixels,
                std::size_t rowBytes) {
    if (setjmp(d->err.jump)) return false;
    d->cinfo.out_color_space = outSpace;
    jpeg_start_decompress(&d->cinfo);
    if (d->cinfo.output_components != components ||
        std::size_t(d->cinfo.output_width) * std::size_t(components) != rowBytes ||
        d->cinfo.output_height != d->cinfo.image_height) {
        std::snprintf(d->err.message, sizeof d->err.message,
                      "unexpected decoder output (%d components, %u x %u)", d->cinfo.output_components,
                      static_cast<unsigned>(d->cinfo.output_width), static_cast<unsigned>(d->cinfo.output_height));
        return false;
    }
    while (d->cinfo.output_scanline < d->cinfo.output_height) {
        JSAMPROW row = pixels + std::size_t(d->cinfo.output_scanline) * rowBytes;
        jpeg_read_scanlines(&d->cinfo, &row, 1);
    }
    jpeg_finish_decompress(&d->cinfo);  // reads on to EOI: a file cut after the pixels still fails
    return true;
}

/// Where in `data` libjpeg stood when it stopped: its source pointer, which it
/// moves on after each marker segment and each block of scan data (so the
/// problem lies at or after it), or the end once it ran past the end (the
/// memory source then reads a fake EOI of its own).
std::size_t inputPosition(const Decompressor& d, std::span<const std::uint8_t> data) {
    if (!d.cinfo.src) return 0;
    const auto next = reinterpret_cast<std::uintptr_t>(d.cinfo.src->next_input_byte);
    const auto begin = reinterpret_cast<std::uintptr_t>(data.data());
    if (next < begin || next > begin + data.size()) return data.size();
    return static_cast<std::size_t>(next - begin);
}

}  // namespace

JpegImage decodeJpeg(std::span<const std::uint8_t> data, const std::string& context) {
    auto fail = [&](const std::string& why) -> void { throw IOException(context + ": " + why); };
    if (data.size() < 3 || data[0] != 0xFF || data[1] != 0xD8 || data[2] != 0xFF)
        fail("not a JPEG image (bad signature: a JPEG file starts FF D8 FF)");

    Decompressor d;
    auto decoderFailure = [&] {
        fail(str("invalid JPEG: ", d.err.message, " (at or after byte ", inputPosition(d, data), " of ",
                 data.size(), ")"));
    };
    JpegHeader h{};
    if (!readHeader(&d, data.data(), data.size(), &h)) decoderFailure();
    if (h.width == 0 || h.height == 0) fail("invalid JPEG: zero width or height");

    int format = 0;
    J_COLOR_SPACE outSpace = JCS_UNKNOWN;
    switch (h.colorSpace) {
        case JCS_GRAYSCALE: format = Image2D::LUMINANCE; outSpace = JCS_GRAYSCALE; break;
        case JCS_YCbCr:
        case JCS_RGB: format = Image2D::RGB; outSpace = JCS_RGB; break;
        case JCS_CMYK:
        case JCS_YCCK:
            fail("CMYK JPEG images are not supported (the decoder does not convert CMYK to RGB)");
            break;
        default:
            fail(str("JPEG images with ", h.components,
                     " colour components are not supported (only greyscale, YCbCr and RGB)"));
    }
    const int bpp = Image2D::bytesPerPixel(format);
    if (h.width > kImageMaxDimension || h.height > kImageMaxDimension)
        fail(str("JPEG image ", h.width, "x", h.height, " is too large (limit ", kImageMaxDimension,
                 " pixels a side)"));
    const std::size_t rowBytes = std::size_t(h.width) * std::size_t(bpp);
    const std::uint64_t total = std::uint64_t(rowBytes) * h.height;
    if (total > kImageMaxDecodedBytes)
        fail(str("JPEG image ", h.width, "x", h.height, " is too large (", total, " bytes decoded; limit ",
                 kImageMaxDecodedBytes, ")"));
    // A file far too small for the size it declares is cut short; say so
    // before allocating for it (as PngImage.cpp does with the IDAT bytes).
    // Arithmetic coding can spend under a bit on a block: no bound there.
    if (!h.arithmetic && h.largestComponentBlocks > std::uint64_t(data.size()) * 8)
        fail(str("truncated or corrupt JPEG: ", h.width, "x", h.height, " has ", h.largestComponentBlocks,
                 " blocks of 8x8 samples in one component, which take at least ", (h.largestComponentBlocks + 7) / 8,
                 " bytes of Huffman-coded data, but the file has only ", data.size(), " bytes"));

    JpegImage img;
    img.format = format;
    img.width = static_cast<int>(h.width);
    img.height = static_cast<int>(h.height);
    img.pixels.resize(static_cast<std::size_t>(total));
    if (!readPixels(&d, outSpace, bpp, img.pixels.data(), rowBytes)) decoderFailure();
    return img;
}

}  // namespace m3g::detail
