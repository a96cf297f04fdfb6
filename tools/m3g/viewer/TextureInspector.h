// The texture inspector's logic, without a window: which Image2D is shown,
// at which zoom, where its texels lie on the screen, and what a texel holds
// in the image's own format (JSR-184 1.1, Image2D: ALPHA, LUMINANCE,
// LUMINANCE_ALPHA, RGB, RGBA, 8 bits a component; a paletted image keeps
// its index and palette). The panel (ViewerUi) and the script commands
// (ViewerInput) share it, so what a test reads is what the panel shows.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <m3g/Image2D.h>

#include "ViewerLayout.h"

namespace m3gview {

/// "ALPHA", "LUMINANCE", "LUMINANCE_ALPHA", "RGB", "RGBA" (or "?").
const char* imageFormatName(int format);

/// One texel as the Image2D stores it.
struct Texel {
    int x = 0, y = 0;
    int format = m3g::Image2D::RGB;
    int paletteIndex = -1;      ///< the index byte of a paletted image, else -1
    std::vector<int> channels;  ///< in the format's order (L A / R G B / R G B A), 0..255

    /// "(x, y) RGB 255 0 0", with "index 7 -> " before the values of a
    /// paletted image.
    std::string describe() const;
};

/// The texel (x, y) of `image`, 0 <= x < width, 0 <= y < height (rows top
/// to bottom); nullopt outside.
std::optional<Texel> texelAt(const m3g::Image2D& image, int x, int y);

class TextureInspector {
public:
    /// Zoom 0 fits the image in the area; 1, 2, 4, ... are screen pixels per
    /// texel (whole numbers, so every texel is the same square).
    static constexpr int kFit = 0;
    static constexpr int kMaxZoom = 64;

    /// Shows images()[index] of the scene; -1 closes the inspector.
    void open(int index, int zoom = kFit);
    void close() { index_ = -1; }
    bool isOpen() const noexcept { return index_ >= 0; }
    int index() const noexcept { return index_; }
    int zoom() const noexcept { return zoom_; }
    /// kFit or a power of two 1..kMaxZoom; std::invalid_argument otherwise.
    void setZoom(int zoom);
    /// The next power of two up / down from the zoom shown (a fitted view
    /// starts from the scale it has).
    void zoomIn(int imageWidth, int imageHeight, const Rect& area);
    void zoomOut(int imageWidth, int imageHeight, const Rect& area);

    /// Screen pixels per texel of a width x height image in `area`.
    float scale(int imageWidth, int imageHeight, const Rect& area) const;
    /// Where the image lies for `area`: centred when it is smaller than the
    /// area, else from the area's top-left corner (ImGui scrolls it).
    Rect placement(int imageWidth, int imageHeight, const Rect& area) const;

    /// The texel under screen point (px, py) of an image drawn on `drawn`
    /// (the rectangle the panel drew it on this frame), or nullopt outside.
    static std::optional<std::pair<int, int>> texelUnder(float px, float py, const Rect& drawn, int imageWidth,
                                                          int imageHeight);

    /// The rectangle the panel drew the image on in the last frame (window
    /// coordinates), whether it was drawn at all, and the area it had.
    Rect drawn;
    bool wasDrawn = false;
    Rect lastArea{0, 0, 256, 256};

private:
    int index_ = -1;
    int zoom_ = kFit;
};

}  // namespace m3gview
