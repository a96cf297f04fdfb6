// The PNG writer extension (api/m3g/PngWriter.h), through libpng's
// simplified API, which the loader's libpng dependency already brings.
#include <m3g/PngWriter.h>

#include <png.h>

#include <fstream>

#include <m3g/Exception.h>
#include <m3g/Image2D.h>

namespace m3g {

std::vector<std::uint8_t> encodePng(const Image2D& image) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = static_cast<png_uint_32>(image.getWidth());
    png.height = static_cast<png_uint_32>(image.getHeight());
    std::vector<std::uint8_t> expanded;
    const std::uint8_t* pixels = image.pixels().data();
    switch (image.getFormat()) {
    case Image2D::LUMINANCE: png.format = PNG_FORMAT_GRAY; break;
    case Image2D::LUMINANCE_ALPHA: png.format = PNG_FORMAT_GA; break;
    case Image2D::RGB: png.format = PNG_FORMAT_RGB; break;
    case Image2D::RGBA: png.format = PNG_FORMAT_RGBA; break;
    default:  // ALPHA: no PNG colour type holds alpha alone
        png.format = PNG_FORMAT_RGBA;
        image.getPixelsRGBA8(expanded);
        pixels = expanded.data();
        break;
    }
    png_alloc_size_t size = 0;
    if (!png_image_write_to_memory(&png, nullptr, &size, 0, pixels, 0, nullptr))
        throw IOException(std::string("encodePng: ") + png.message);
    std::vector<std::uint8_t> out(size);
    if (!png_image_write_to_memory(&png, out.data(), &size, 0, pixels, 0, nullptr))
        throw IOException(std::string("encodePng: ") + png.message);
    out.resize(size);
    return out;
}

void writePng(const Image2D& image, const std::string& path) {
    const std::vector<std::uint8_t> bytes = encodePng(image);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out || !out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size())))
        throw IOException("writePng: cannot write " + path);
}

}  // namespace m3g
