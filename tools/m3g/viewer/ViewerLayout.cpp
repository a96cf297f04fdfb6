#include "ViewerLayout.h"

#include <algorithm>
#include <cmath>

namespace m3gview {

LayoutSizes clampSizes(const LayoutSizes& in, int width, int height) {
    (void)height;
    LayoutSizes s = in;
    const float w = static_cast<float>(std::max(width, 1));
    auto finite = [](float v, float fallback) { return std::isfinite(v) ? v : fallback; };
    const LayoutSizes defaults;
    s.left = std::max(finite(s.left, defaults.left), Layout::kMinColumn);
    s.right = std::max(finite(s.right, defaults.right), Layout::kMinColumn);
    // Room for the columns beside the smallest view.
    const float room = std::max(0.0f, w - Layout::kMinView - 2.0f * Layout::kGap);
    if (s.left + s.right > room) {
        const float k = room / (s.left + s.right);
        s.left = std::floor(s.left * k);
        s.right = std::floor(s.right * k);
    }
    s.leftSplit = std::clamp(finite(s.leftSplit, defaults.leftSplit), 0.1f, 0.9f);
    s.rightSplit1 = std::clamp(finite(s.rightSplit1, defaults.rightSplit1), 0.1f, 0.8f);
    s.rightSplit2 = std::clamp(finite(s.rightSplit2, defaults.rightSplit2), s.rightSplit1 + 0.1f, 0.9f);
    return s;
}

Layout computeLayout(int width, int height, float menuHeight, bool panels, const LayoutSizes& sizes) {
    Layout l;
    const float W = static_cast<float>(std::max(width, 0)), H = static_cast<float>(std::max(height, 0));
    l.panels = panels;
    if (!panels) {
        l.view = {0, 0, W, H};
        return l;
    }
    const LayoutSizes s = clampSizes(sizes, width, height);
    const float top = std::min(std::round(menuHeight), H), colH = H - top, g = Layout::kGap;
    const float left = std::round(s.left), right = std::round(s.right);
    l.leftSplitter = {left, top, g, colH};
    l.rightSplitter = {W - right - g, top, g, colH};
    l.view = {left + g, top, std::max(0.0f, W - left - right - 2 * g), colH};

    // `a` runs from its y down to `split`; the splitter bar follows.
    auto rows = [&](float x, float w, float split, Rect& a, Rect& bar) {
        a = {x, a.y, w, std::max(0.0f, split - a.y)};
        bar = {x, split, w, g};
    };
    // Left column: Scene above, Objects/Textures below.
    const float ls = std::round(top + s.leftSplit * colH - g / 2);
    l.scene.y = top;
    rows(0, left, ls, l.scene, l.leftRowSplitter);
    l.objects = {0, ls + g, left, std::max(0.0f, H - ls - g)};
    // Right column: Properties, Animation, View.
    const float rx = W - right, r1 = std::round(top + s.rightSplit1 * colH - g / 2),
                r2 = std::round(top + s.rightSplit2 * colH - g / 2);
    l.properties.y = top;
    rows(rx, right, r1, l.properties, l.rightRowSplitter1);
    l.animation.y = r1 + g;
    rows(rx, right, r2, l.animation, l.rightRowSplitter2);
    l.stats = {rx, r2 + g, right, std::max(0.0f, H - r2 - g)};
    return l;
}

PixelRect pixels(const Rect& r, float scaleX, float scaleY) noexcept {
    // Edges rounded (not sizes), so that adjacent rectangles stay adjacent.
    PixelRect p;
    p.x = static_cast<int>(std::lround(r.x * scaleX));
    p.y = static_cast<int>(std::lround(r.y * scaleY));
    p.w = std::max(1, static_cast<int>(std::lround((r.x + r.w) * scaleX)) - p.x);
    p.h = std::max(1, static_cast<int>(std::lround((r.y + r.h) * scaleY)) - p.y);
    return p;
}

}  // namespace m3gview
