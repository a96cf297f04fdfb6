// A 2D drawing surface standing in for javax.microedition.lcdui.Graphics, the
// usual Graphics3D target of a MIDlet (JSR-184 1.1, Graphics3D.bindTarget).
#pragma once

#include <m3g/Export.h>

#include <cstdint>
#include <span>
#include <vector>

#include <m3g/Exception.h>
#include <m3g/Ref.h>

namespace m3g {

/// An offscreen 32-bit ARGB surface (0xAARRGGBB, rows top to bottom) with the
/// lcdui notions Graphics3D uses: a translation and a clip rectangle (in
/// translated coordinates). Graphics3D::bindTarget sets the default viewport
/// from the clip; releaseTarget writes the rendered pixels here.
class M3G_API Graphics : public RefCounted {
public:
    /// An opaque black surface; IAE unless width > 0 and height > 0.
    Graphics(int width, int height);
    ~Graphics() override;

    int getWidth() const noexcept { return width_; }
    int getHeight() const noexcept { return height_; }

    /// Moves the origin by (x, y), as lcdui's translate (cumulative).
    void translate(int x, int y) noexcept;
    int getTranslateX() const noexcept { return translateX_; }
    int getTranslateY() const noexcept { return translateY_; }

    /// Sets the clip rectangle in translated coordinates (as lcdui's setClip:
    /// not intersected with the previous clip; clipped to the surface).
    void setClip(int x, int y, int width, int height) noexcept;
    int getClipX() const noexcept { return clipX_ - translateX_; }
    int getClipY() const noexcept { return clipY_ - translateY_; }
    int getClipWidth() const noexcept { return clipW_; }
    int getClipHeight() const noexcept { return clipH_; }

    /// Pixel (x, y) in surface coordinates (no translation); IOOBE outside.
    std::uint32_t getPixel(int x, int y) const;
    /// All pixels, width * height, rows top to bottom.
    std::span<std::uint32_t> pixels() noexcept { return pixels_; }
    std::span<const std::uint32_t> pixels() const noexcept { return pixels_; }

protected:
    /// For surfaces whose size follows something else (a window): a new
    /// size, opaque black pixels, no translation, the clip on the whole
    /// surface. IAE unless width > 0 and height > 0.
    void resizeSurface(int width, int height);

private:
    int width_, height_;
    int translateX_ = 0, translateY_ = 0;
    int clipX_ = 0, clipY_ = 0, clipW_, clipH_;  // surface coordinates
    std::vector<std::uint32_t> pixels_;
};

}  // namespace m3g
