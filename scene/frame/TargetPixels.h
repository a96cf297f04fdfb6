// The bound target's pixels as a back end reads and writes them
// (frame::TargetPixels): an Image2D (JSR-184 1.1, Graphics3D.bindTarget with
// an Image2D) or a Graphics surface.
#pragma once

#include <m3g/frame/FrameBackend.h>

#include <m3g/Forward.h>

namespace m3g::detail {

class ImageTargetPixels final : public frame::TargetPixels {
public:
    explicit ImageTargetPixels(Image2D& image) noexcept : image_(image) {}
    void read(std::span<std::uint8_t> out) const override;
    /// RGB images keep the colour channels; `bgra` never comes from an image target.
    void write(const std::uint8_t* texels, bool bgra) override;

private:
    Image2D& image_;
};

class GraphicsTargetPixels final : public frame::TargetPixels {
public:
    explicit GraphicsTargetPixels(Graphics& graphics) noexcept : graphics_(graphics) {}
    void read(std::span<std::uint8_t> out) const override;
    void write(const std::uint8_t* texels, bool bgra) override;

private:
    Graphics& graphics_;
};

/// `count` RGBA (or BGRA) texels to opaque 0xAARRGGBB words.
void texelsToArgb(const std::uint8_t* src, std::uint32_t* out, std::size_t count, bool bgra) noexcept;

/// texelsToArgb, spread over the shared thread pool (skin::ThreadPool) in
/// fixed chunks when `count` is large (a 1280x960 frame), on the calling
/// thread otherwise; the same words either way.
void texelsToArgbParallel(const std::uint8_t* src, std::uint32_t* out, std::size_t count, bool bgra) noexcept;

}  // namespace m3g::detail
