// The viewer's docked layout (ViewerLayout.h): the 3D view never lies under
// a panel, splitter sizes are clamped, and window pixels map into the view.
#include <gtest/gtest.h>

#include <limits>

#include "ViewerLayout.h"

using namespace m3gview;

namespace {

bool overlaps(const Rect& a, const Rect& b) {
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

}  // namespace

TEST(ViewerLayout, WithoutPanelsTheViewIsTheWholeWindow) {
    const Layout l = computeLayout(800, 600, 19.0f, false, LayoutSizes{});
    EXPECT_EQ(l.view, (Rect{0, 0, 800, 600}));
    EXPECT_FALSE(l.panels);
}

TEST(ViewerLayout, TheViewLiesBetweenTheColumnsBelowTheMenu) {
    LayoutSizes s;
    s.left = 200;
    s.right = 300;
    const Layout l = computeLayout(1000, 700, 19.0f, true, s);
    EXPECT_EQ(l.view, (Rect{204, 19, 1000 - 200 - 300 - 8, 700 - 19}));
    for (const Rect& panel : {l.scene, l.objects, l.properties, l.animation, l.stats}) {
        EXPECT_FALSE(overlaps(panel, l.view));
        EXPECT_GT(panel.w, 0.0f);
        EXPECT_GT(panel.h, 0.0f);
        EXPECT_GE(panel.y, 19.0f);
        EXPECT_LE(panel.y + panel.h, 700.0f);
    }
    // The columns' panels tile them: no overlap, the splitters in between.
    EXPECT_FALSE(overlaps(l.scene, l.objects));
    EXPECT_FALSE(overlaps(l.properties, l.animation));
    EXPECT_FALSE(overlaps(l.animation, l.stats));
    EXPECT_FLOAT_EQ(l.scene.y + l.scene.h + Layout::kGap, l.objects.y);
    EXPECT_FLOAT_EQ(l.objects.y + l.objects.h, 700.0f);
    EXPECT_FLOAT_EQ(l.stats.y + l.stats.h, 700.0f);
    EXPECT_FLOAT_EQ(l.properties.x, 700.0f);
    EXPECT_FLOAT_EQ(l.properties.w, 300.0f);
    EXPECT_EQ(l.leftSplitter, (Rect{200, 19, Layout::kGap, 681}));
    EXPECT_EQ(l.rightSplitter, (Rect{696, 19, Layout::kGap, 681}));
}

TEST(ViewerLayout, SizesAreClampedToTheWindow) {
    LayoutSizes s;
    s.left = 10;        // below the minimum column
    s.right = 5000;     // wider than the window
    s.leftSplit = 2.0f;
    s.rightSplit1 = 0.85f;
    s.rightSplit2 = 0.5f;  // above split 1: pushed below it
    const LayoutSizes c = clampSizes(s, 800, 600);
    EXPECT_GE(c.left, 1.0f);
    EXPECT_LE(c.left + c.right, 800 - Layout::kMinView - 2 * Layout::kGap);
    EXPECT_FLOAT_EQ(c.leftSplit, 0.9f);
    EXPECT_FLOAT_EQ(c.rightSplit1, 0.8f);
    EXPECT_FLOAT_EQ(c.rightSplit2, 0.9f);
    const Layout l = computeLayout(800, 600, 19.0f, true, s);
    EXPECT_GE(l.view.w, Layout::kMinView);
    // A wide enough window keeps sensible sizes as they are.
    const LayoutSizes d = clampSizes(LayoutSizes{}, 1920, 1080);
    EXPECT_FLOAT_EQ(d.left, LayoutSizes{}.left);
    EXPECT_FLOAT_EQ(d.right, LayoutSizes{}.right);
    // NaN (a broken settings file) falls back to the defaults.
    LayoutSizes n;
    n.left = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FLOAT_EQ(clampSizes(n, 1920, 1080).left, LayoutSizes{}.left);
}

TEST(ViewerLayout, ATinyWindowStillHasAView) {
    const Layout l = computeLayout(100, 50, 19.0f, true, LayoutSizes{});
    EXPECT_GE(l.view.w, 0.0f);
    for (const Rect& panel : {l.scene, l.objects, l.properties, l.animation, l.stats}) EXPECT_FALSE(overlaps(panel, l.view));
    const PixelRect p = pixels(l.view);
    EXPECT_GE(p.w, 1);
    EXPECT_GE(p.h, 1);
}

TEST(ViewerLayout, WindowPixelsMapIntoTheView) {
    const Layout l = computeLayout(1000, 700, 19.0f, true, LayoutSizes{});
    float vx = 0, vy = 0;
    toView(l.view, l.view.x + 10, l.view.y + 20, vx, vy);
    EXPECT_FLOAT_EQ(vx, 10.0f);
    EXPECT_FLOAT_EQ(vy, 20.0f);
    EXPECT_TRUE(l.view.contains(l.view.x, l.view.y));
    EXPECT_FALSE(l.view.contains(l.view.x - 1, l.view.y));
    EXPECT_FALSE(l.view.contains(l.view.x + l.view.w, l.view.y));
    EXPECT_FALSE(l.view.contains(5, 5));  // the menu bar / the Scene panel
}

TEST(ViewerLayout, PixelsScaleWindowUnitsToTheFramebuffer) {
    // A HiDPI window: 2 framebuffer pixels a unit. Edges are rounded, so
    // rectangles side by side stay side by side.
    const PixelRect p = pixels(Rect{244, 19, 422, 581}, 2.0f, 2.0f);
    EXPECT_EQ(p.x, 488);
    EXPECT_EQ(p.y, 38);
    EXPECT_EQ(p.w, 844);
    EXPECT_EQ(p.h, 1162);
    const PixelRect a = pixels(Rect{0, 0, 10.3f, 5}, 1.5f, 1.0f), b = pixels(Rect{10.3f, 0, 10, 5}, 1.5f, 1.0f);
    EXPECT_EQ(a.x + a.w, b.x);
}
