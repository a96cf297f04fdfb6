// PNG decoding with libpng (JSR-184 1.1, Loader; the colour-type mapping is in
// PngImage.h).
#include "PngImage.h"

#include <csetjmp>
#include <cstring>
#include <string>

#include <png.h>

#include <m3g/Exception.h>
#include <m3g/Image2D.h>

#include "Check.h"

namespace m3g::detail {

namespace {

// State shared with libpng's callbacks. Trivially destructible: libpng reports
// errors with longjmp, which must not skip C++ destructors.
struct PngState {
    const std::uint8_t* data;
    std::size_t size;
    std::size_t pos;
    char message[256];
};

void pngError(png_structp png, png_const_charp msg) {
    auto* st = static_cast<PngState*>(png_get_error_ptr(png));
    std::strncpy(st->message, msg ? msg : "unknown libpng error", sizeof st->message - 1);
    st->message[sizeof st->message - 1] = '\0';
    png_longjmp(png, 1);
}

void pngWarning(png_structp, png_const_charp) {}  // ancillary problems are not load errors

void pngRead(png_structp png, png_bytep out, png_size_t n) {
    auto* st = static_cast<PngState*>(png_get_io_ptr(png));
    if (n > st->size - st->pos) png_error(png, "truncated: the file ends inside a chunk");
    std::memcpy(out, st->data + st->pos, n);
    st->pos += n;
}

struct PngInfo {
    png_uint_32 width, height;
    int format;
    int channels;
    std::size_t rowBytes;
    std::size_t rawRowBytes;  // before transforms, without the filter byte
};

// The chunk list up to IEND, before libpng sees it.
struct ChunkScan {
    /// Sum of the IDAT chunk lengths (a deflate stream inflates to at most
    /// about 1032 times its size, so this bounds the pixels a file can carry).
    std::uint64_t idatBytes = 0;
    /// The first chunk whose declared length runs past the end of the data,
    /// described for the error message; empty if none. libpng allocates and
    /// clears an ancillary chunk's declared length before reading it, so a
    /// 100-byte file declaring a 1.7 GB tEXt chunk would cost that much memory
    /// before the truncation is found (fuzzing finding, docs/reliability.md).
    std::string overrun;
};

ChunkScan scanChunks(std::span<const std::uint8_t> d) {
    ChunkScan scan;
    std::size_t pos = 8;
    while (d.size() - pos >= 8) {
        const std::uint32_t len = (std::uint32_t(d[pos]) << 24) | (std::uint32_t(d[pos + 1]) << 16) |
                                  (std::uint32_t(d[pos + 2]) << 8) | d[pos + 3];
        const std::uint8_t* type = d.data() + pos + 4;
        const std::uint64_t next = std::uint64_t(pos) + 12 + len;
        if (next > d.size()) {
            std::string name;
            for (int i = 0; i < 4; ++i) {
                const char c = static_cast<char>(type[i]);
                name += (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') ? c : '?';
            }
            scan.overrun = str("truncated: chunk '", name, "' at byte ", pos, " declares ", len,
                               " data bytes but the file has only ", d.size() - pos - 8, " left after its header");
            break;
        }
        if (std::memcmp(type, "IDAT", 4) == 0) scan.idatBytes += len;
        if (std::memcmp(type, "IEND", 4) == 0) break;
        pos = static_cast<std::size_t>(next);
    }
    return scan;
}

// Phase 1: header and transforms. Returns false on error (message in st).
// Only trivially destructible locals: libpng may longjmp back here.
bool readHeader(png_structp png, png_infop info, PngInfo* out) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_user_limits(png, kImageMaxDimension, kImageMaxDimension);
    png_read_info(png, info);
    const png_uint_32 w = png_get_image_width(png, info);
    const png_uint_32 h = png_get_image_height(png, info);
    const int colorType = png_get_color_type(png, info);
    const int bitDepth = png_get_bit_depth(png, info);
    const bool hasTrns = png_get_valid(png, info, PNG_INFO_tRNS) != 0;
    out->rawRowBytes = png_get_rowbytes(png, info);

    int format = 0;
    switch (colorType) {
        case PNG_COLOR_TYPE_GRAY: format = hasTrns ? Image2D::LUMINANCE_ALPHA : Image2D::LUMINANCE; break;
        case PNG_COLOR_TYPE_GRAY_ALPHA: format = Image2D::LUMINANCE_ALPHA; break;
        case PNG_COLOR_TYPE_RGB: format = hasTrns ? Image2D::RGBA : Image2D::RGB; break;
        case PNG_COLOR_TYPE_PALETTE: format = hasTrns ? Image2D::RGBA : Image2D::RGB; break;
        case PNG_COLOR_TYPE_RGB_ALPHA: format = Image2D::RGBA; break;
        default: png_error(png, "unknown PNG colour type");
    }
    if (colorType == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (colorType == PNG_COLOR_TYPE_GRAY && bitDepth < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (hasTrns) png_set_tRNS_to_alpha(png);
    if (bitDepth == 16) png_set_strip_16(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);

    out->width = w;
    out->height = h;
    out->format = format;
    out->channels = png_get_channels(png, info);
    out->rowBytes = png_get_rowbytes(png, info);
    return true;
}

// Phase 2: the pixels, into caller-owned storage.
bool readPixels(png_structp png, png_infop info, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    png_read_end(png, info);
    return true;
}

struct PngHandles {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~PngHandles() { png_destroy_read_struct(&png, info ? &info : nullptr, nullptr); }
};

}  // namespace

PngImage decodePng(std::span<const std::uint8_t> data, const std::string& context) {
    auto fail = [&](const std::string& why) -> void { throw IOException(context + ": " + why); };
    if (data.size() < 8 || png_sig_cmp(data.data(), 0, 8) != 0) fail("not a PNG image (bad signature)");
    const ChunkScan chunks = scanChunks(data);
    if (!chunks.overrun.empty()) fail(str("invalid PNG: ", chunks.overrun));

    PngState st{data.data(), data.size(), 0, {0}};
    PngHandles h;
    h.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &st, pngError, pngWarning);
    if (!h.png) fail("libpng could not be initialised");
    h.info = png_create_info_struct(h.png);
    if (!h.info) fail("libpng could not be initialised");
    png_set_read_fn(h.png, &st, pngRead);

    PngInfo pi{};
    if (!readHeader(h.png, h.info, &pi)) fail(str("invalid PNG: ", st.message));
    const int bpp = Image2D::bytesPerPixel(pi.format);
    if (pi.width == 0 || pi.height == 0) fail("invalid PNG: zero width or height");
    if (pi.channels != bpp || pi.rowBytes != std::size_t(pi.width) * std::size_t(bpp))
        fail(str("unexpected PNG layout after conversion (", pi.channels, " channels, ", pi.rowBytes,
                 " bytes per row)"));
    const std::uint64_t total = std::uint64_t(pi.rowBytes) * pi.height;
    if (total > kImageMaxDecodedBytes)
        fail(str("PNG image ", pi.width, "x", pi.height, " is too large (", total, " bytes decoded; limit ",
                 kImageMaxDecodedBytes, ")"));

    const std::uint64_t rawTotal = (std::uint64_t(pi.rawRowBytes) + 1) * pi.height;
    const std::uint64_t idat = chunks.idatBytes;
    if (rawTotal > idat * 1032 + 65536)
        fail(str("truncated or corrupt PNG: ", pi.width, "x", pi.height, " needs ", rawTotal,
                 " bytes of image data but the IDAT chunks hold only ", idat, " compressed bytes"));

    PngImage img;
    img.format = pi.format;
    img.width = static_cast<int>(pi.width);
    img.height = static_cast<int>(pi.height);
    img.pixels.resize(static_cast<std::size_t>(total));
    std::vector<png_bytep> rows(pi.height);
    for (png_uint_32 y = 0; y < pi.height; ++y) rows[y] = img.pixels.data() + std::size_t(y) * pi.rowBytes;
    if (!readPixels(h.png, h.info, rows.data())) fail(str("invalid PNG: ", st.message));
    return img;
}

}  // namespace m3g::detail
