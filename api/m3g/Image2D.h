// javax.microedition.m3g.Image2D (JSR-184 1.1, Image2D).
#pragma once

#include <m3g/Export.h>

#include <cstdint>
#include <span>
#include <vector>

#include <m3g/Object3D.h>

namespace m3g {

/// A 2D image: ALPHA, LUMINANCE, LUMINANCE_ALPHA, RGB or RGBA, 8 bits per
/// component, rows top to bottom, pixels left to right, no row padding.
/// Immutable images are created from pixels or palette+indices; mutable ones
/// start opaque white and are changed with set(). The Java constructor from an
/// lcdui Image has no C++ counterpart.
class M3G_API Image2D : public Object3D {
public:
    static constexpr int ALPHA = 96;
    static constexpr int LUMINANCE = 97;
    static constexpr int LUMINANCE_ALPHA = 98;
    static constexpr int RGB = 99;
    static constexpr int RGBA = 100;

    /// Immutable image from `pixels` (bytesPerPixel(format) bytes per pixel,
    /// component order L,A / R,G,B / R,G,B,A). IAE if the format is invalid,
    /// width or height <= 0, or pixels.size() < width * height * bpp; NPE if
    /// pixels is null (data() == nullptr).
    Image2D(int format, int width, int height, std::span<const std::uint8_t> pixels);
    /// Immutable paletted image: one index byte per pixel (>= width * height),
    /// palette entries of bpp bytes each; at most 256 entries are used, extra
    /// bytes are ignored. IAE as above, or if the palette is shorter than 256
    /// entries and its length is not a multiple of bpp; NPE if either is null.
    /// An index past the end of a short palette resolves to all-zero bytes.
    Image2D(int format, int width, int height, std::span<const std::uint8_t> indices,
            std::span<const std::uint8_t> palette);
    /// Mutable image initialised to opaque white (every byte 0xFF). IAE if the
    /// format is invalid or width or height <= 0.
    Image2D(int format, int width, int height);
    ~Image2D() override;

    /// Replaces the rectangle (x, y, width, height) with `pixels` (tightly
    /// packed rows of width * bpp bytes). ISE if the image is immutable; IAE if
    /// x < 0, y < 0, width <= 0, height <= 0, the rectangle leaves the image, or
    /// pixels.size() < width * height * bpp; NPE if pixels is null.
    void set(int x, int y, int width, int height, std::span<const std::uint8_t> pixels);

    bool isMutable() const noexcept { return mutable_; }
    int getFormat() const noexcept { return format_; }
    int getWidth() const noexcept { return width_; }
    int getHeight() const noexcept { return height_; }

    const char* getClassName() const noexcept override { return "Image2D"; }

    // ---- Engine interface (renderer, loader) ----

    /// Bytes per pixel of `format` (1, 1, 2, 3, 4), or 0 for an invalid format.
    static int bytesPerPixel(int format) noexcept;
    /// Bytes per pixel of this image.
    int bytesPerPixel() const noexcept { return bytesPerPixel(format_); }
    /// The pixels, palette already resolved: width * height * bpp bytes, rows
    /// top to bottom, no padding.
    std::span<const std::uint8_t> pixels() const noexcept { return pixels_; }
    /// True if the image was created from indices and a palette.
    bool isPalettized() const noexcept { return palettized_; }
    /// The original indices of a paletted image (empty otherwise).
    std::span<const std::uint8_t> paletteIndices() const noexcept { return indices_; }
    /// The palette as given (at most 256 * bpp bytes; empty if not paletted).
    std::span<const std::uint8_t> palette() const noexcept { return palette_; }
    /// Expands the image to RGBA8 (4 bytes per pixel, same row order) into
    /// `out` (resized to width * height * 4):
    ///   LUMINANCE       -> L, L, L, 255
    ///   ALPHA           -> 255, 255, 255, A  (white: texture MODULATE then keeps
    ///                      the fragment color, as the ALPHA row of the texture
    ///                      function table of JSR-184 1.1, Texture2D requires;
    ///                      REPLACE needs the renderer to know the format anyway)
    ///   LUMINANCE_ALPHA -> L, L, L, A
    ///   RGB             -> R, G, B, 255
    ///   RGBA            -> R, G, B, A
    void getPixelsRGBA8(std::vector<std::uint8_t>& out) const;

protected:
    Image2D(const Image2D& other);
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    void init(int format, int width, int height, const char* where);

    int format_ = RGB;
    int width_ = 0;
    int height_ = 0;
    bool mutable_ = false;
    bool palettized_ = false;
    std::vector<std::uint8_t> pixels_;
    std::vector<std::uint8_t> indices_;
    std::vector<std::uint8_t> palette_;
};

}  // namespace m3g
