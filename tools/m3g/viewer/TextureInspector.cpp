#include "TextureInspector.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace m3gview {

using m3g::Image2D;

const char* imageFormatName(int format) {
    switch (format) {
        case Image2D::ALPHA: return "ALPHA";
        case Image2D::LUMINANCE: return "LUMINANCE";
        case Image2D::LUMINANCE_ALPHA: return "LUMINANCE_ALPHA";
        case Image2D::RGB: return "RGB";
        case Image2D::RGBA: return "RGBA";
        default: return "?";
    }
}

std::string Texel::describe() const {
    std::string s = "(" + std::to_string(x) + ", " + std::to_string(y) + ") " + imageFormatName(format);
    if (paletteIndex >= 0) s += " index " + std::to_string(paletteIndex) + " ->";
    for (int c : channels) s += " " + std::to_string(c);
    return s;
}

std::optional<Texel> texelAt(const Image2D& image, int x, int y) {
    if (x < 0 || y < 0 || x >= image.getWidth() || y >= image.getHeight()) return std::nullopt;
    Texel t;
    t.x = x;
    t.y = y;
    t.format = image.getFormat();
    const int bpp = image.bytesPerPixel();
    const std::size_t at = static_cast<std::size_t>(y) * static_cast<std::size_t>(image.getWidth()) + static_cast<std::size_t>(x);
    // pixels() has the palette resolved already; the index is kept apart.
    if (image.isPalettized() && at < image.paletteIndices().size()) t.paletteIndex = image.paletteIndices()[at];
    const auto pixels = image.pixels();
    for (int k = 0; k < bpp; ++k) t.channels.push_back(pixels[at * static_cast<std::size_t>(bpp) + static_cast<std::size_t>(k)]);
    return t;
}

void TextureInspector::open(int index, int zoom) {
    setZoom(zoom);
    index_ = index;
    wasDrawn = false;
}

void TextureInspector::setZoom(int zoom) {
    const bool powerOfTwo = zoom >= 1 && zoom <= kMaxZoom && (zoom & (zoom - 1)) == 0;
    if (zoom != kFit && !powerOfTwo)
        throw std::invalid_argument("texture zoom " + std::to_string(zoom) + ": fit (0) or 1, 2, 4 ... " +
                                    std::to_string(kMaxZoom));
    zoom_ = zoom;
}

float TextureInspector::scale(int imageWidth, int imageHeight, const Rect& area) const {
    if (zoom_ != kFit) return static_cast<float>(zoom_);
    if (imageWidth <= 0 || imageHeight <= 0 || area.w <= 0.0f || area.h <= 0.0f) return 1.0f;
    return std::min(area.w / static_cast<float>(imageWidth), area.h / static_cast<float>(imageHeight));
}

void TextureInspector::zoomIn(int imageWidth, int imageHeight, const Rect& area) {
    // The first power of two above the scale shown (a fitted view included).
    const float shown = scale(imageWidth, imageHeight, area);
    int z = 1;
    while (z < kMaxZoom && static_cast<float>(z) <= shown + 1e-3f) z *= 2;
    zoom_ = z;
}

void TextureInspector::zoomOut(int imageWidth, int imageHeight, const Rect& area) {
    // The last power of two below the scale shown, at least 1.
    const float shown = scale(imageWidth, imageHeight, area);
    int z = kMaxZoom;
    while (z > 1 && static_cast<float>(z) >= shown - 1e-3f) z /= 2;
    zoom_ = z;
}

Rect TextureInspector::placement(int imageWidth, int imageHeight, const Rect& area) const {
    const float s = scale(imageWidth, imageHeight, area);
    Rect r{area.x, area.y, s * static_cast<float>(imageWidth), s * static_cast<float>(imageHeight)};
    // Whole pixels, so that texel edges fall on pixel edges at integer zooms.
    if (r.w < area.w) r.x = std::floor(area.x + (area.w - r.w) * 0.5f);
    if (r.h < area.h) r.y = std::floor(area.y + (area.h - r.h) * 0.5f);
    return r;
}

std::optional<std::pair<int, int>> TextureInspector::texelUnder(float px, float py, const Rect& drawn, int imageWidth,
                                                                int imageHeight) {
    if (!drawn.contains(px, py) || imageWidth <= 0 || imageHeight <= 0) return std::nullopt;
    const int x = static_cast<int>(std::floor((px - drawn.x) * static_cast<float>(imageWidth) / drawn.w));
    const int y = static_cast<int>(std::floor((py - drawn.y) * static_cast<float>(imageHeight) / drawn.h));
    if (x < 0 || y < 0 || x >= imageWidth || y >= imageHeight) return std::nullopt;
    return std::pair{x, y};
}

}  // namespace m3gview
