// libjpeg reports errors by calling error_exit, whose default prints and
// calls exit(); here it longjmps back to a setjmp point in a function whose
// locals are all trivially destructible (as scene/io/JpegImage.cpp does).
#include "JpegWriter.h"

#include <csetjmp>
#include <cstdio>  // before jpeglib.h, which uses FILE
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <jpeglib.h>

namespace m3gcli {

namespace {

struct ErrorManager {
    jpeg_error_mgr pub;  // first: libjpeg hands back a pointer to this member
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void errorExit(j_common_ptr cinfo) {
    auto* err = reinterpret_cast<ErrorManager*>(cinfo->err);
    (*cinfo->err->format_message)(cinfo, err->message);
    std::longjmp(err->jump, 1);
}

/// The compressor and the memory destination's buffer (malloc'ed by libjpeg,
/// grown as it writes); freed by the destructor, which no jump skips.
struct Compressor {
    jpeg_compress_struct cinfo{};
    ErrorManager err{};
    unsigned char* buffer = nullptr;
    unsigned long size = 0;

    Compressor() {
        cinfo.err = jpeg_std_error(&err.pub);
        err.pub.error_exit = errorExit;
    }
    ~Compressor() {
        jpeg_destroy_compress(&cinfo);
        std::free(buffer);
    }
    Compressor(const Compressor&) = delete;
    Compressor& operator=(const Compressor&) = delete;
};

/// Encodes `rgb` (width x height x 3) into c->buffer; false on error
/// (message in c->err). Only trivially destructible locals.
bool compress(Compressor* c, const std::uint8_t* rgb, int width, int height, int quality) {
    if (setjmp(c->err.jump)) return false;
    jpeg_create_compress(&c->cinfo);
    jpeg_mem_dest(&c->cinfo, &c->buffer, &c->size);
    c->cinfo.image_width = static_cast<JDIMENSION>(width);
    c->cinfo.image_height = static_cast<JDIMENSION>(height);
    c->cinfo.input_components = 3;
    c->cinfo.in_color_space = JCS_RGB;
    jpeg_set_defaults(&c->cinfo);
    jpeg_set_quality(&c->cinfo, quality, TRUE);
    jpeg_start_compress(&c->cinfo, TRUE);
    while (c->cinfo.next_scanline < c->cinfo.image_height) {
        JSAMPROW row = const_cast<JSAMPROW>(rgb + static_cast<std::size_t>(c->cinfo.next_scanline) * width * 3);
        jpeg_write_scanlines(&c->cinfo, &row, 1);
    }
    jpeg_finish_compress(&c->cinfo);
    return true;
}

}  // namespace

std::vector<std::uint8_t> encodeJpeg(const RgbaImage& image, int quality) {
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(image.width) * image.height * 3);
    for (std::size_t i = 0; i < rgb.size() / 3; ++i)
        for (int k = 0; k < 3; ++k) rgb[i * 3 + k] = image.pixels[i * 4 + k];
    Compressor c;
    if (!compress(&c, rgb.data(), image.width, image.height, quality))
        throw std::runtime_error(std::string("JPEG encoding failed: ") + c.err.message);
    return std::vector<std::uint8_t>(c.buffer, c.buffer + c.size);
}

}  // namespace m3gcli
