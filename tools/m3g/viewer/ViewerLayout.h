// The viewer's window layout: the 3D view in its own rectangle, panels
// docked in a left column (Scene; Objects/Textures) and a right column
// (Properties; Animation; View), with splitters between them. ImGui 1.89
// has no docking, so the windows are placed from this layout every frame
// and the M3G frame is drawn into `view` only (Graphics3D::setViewport).
// Pure math, unit-tested without a window.
#pragma once

namespace m3gview {

struct Rect {
    float x = 0, y = 0, w = 0, h = 0;
    bool contains(float px, float py) const noexcept { return px >= x && py >= y && px < x + w && py < y + h; }
    bool operator==(const Rect&) const = default;
};

/// What the user sets by dragging the splitters (remembered in the settings).
struct LayoutSizes {
    float left = 240.0f;        ///< left column width, pixels
    float right = 330.0f;       ///< right column width, pixels
    float leftSplit = 0.5f;     ///< share of the left column for Scene (the rest: Objects/Textures)
    float rightSplit1 = 0.45f;  ///< share of the right column above the Properties/Animation boundary
    float rightSplit2 = 0.7f;   ///< share above the Animation/View boundary
};

struct Layout {
    static constexpr float kGap = 4.0f;         ///< splitter thickness
    static constexpr float kMinColumn = 120.0f;
    static constexpr float kMinView = 64.0f;
    Rect view;                          ///< the 3D view (window units, top-left origin)
    Rect scene, objects;                ///< left column
    Rect properties, animation, stats;  ///< right column
    Rect leftSplitter, rightSplitter;   ///< vertical bars beside the view
    Rect leftRowSplitter, rightRowSplitter1, rightRowSplitter2;  ///< horizontal bars in the columns
    bool panels = false;
};

/// Clamps sizes to what a width x height window can hold: columns at least
/// kMinColumn wide (unless the window is too narrow: then both shrink in
/// proportion), the view at least kMinView wide, splits within [0.1, 0.9]
/// and rightSplit1 + 0.1 <= rightSplit2.
LayoutSizes clampSizes(const LayoutSizes& sizes, int width, int height);

/// The layout of a width x height window with a menu bar `menuHeight`
/// pixels high. Without panels the view is the whole window.
Layout computeLayout(int width, int height, float menuHeight, bool panels, const LayoutSizes& sizes);

/// Window pixel -> view pixel (may lie outside the view).
inline void toView(const Rect& view, float x, float y, float& vx, float& vy) noexcept {
    vx = x - view.x;
    vy = y - view.y;
}

/// The view rectangle in whole pixels (what the viewport and screenshots use).
struct PixelRect {
    int x = 0, y = 0, w = 0, h = 0;
};
/// `r` (window coordinates, the layout's unit) in whole framebuffer pixels,
/// `scaleX` x `scaleY` framebuffer pixels per window unit: 1 on most
/// screens, 2 on a HiDPI one whose window system scales windows (GLFW's
/// cursor and ImGui use window units, the swapchain framebuffer pixels).
PixelRect pixels(const Rect& r, float scaleX = 1.0f, float scaleY = 1.0f) noexcept;

}  // namespace m3gview
