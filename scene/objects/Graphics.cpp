#include <m3g/Graphics.h>

#include <algorithm>

#include "Check.h"

namespace m3g {

Graphics::Graphics(int width, int height) : width_(width), height_(height), clipW_(width), clipH_(height) {
    if (width <= 0 || height <= 0)
        throw IllegalArgumentException(
            detail::str("Graphics::Graphics: size ", width, " x ", height, " must be positive"));
    pixels_.assign(static_cast<std::size_t>(width) * height, 0xFF000000u);
}

Graphics::~Graphics() = default;

void Graphics::resizeSurface(int width, int height) {
    if (width <= 0 || height <= 0)
        throw IllegalArgumentException(
            detail::str("Graphics::resizeSurface: size ", width, " x ", height, " must be positive"));
    width_ = width;
    height_ = height;
    translateX_ = translateY_ = 0;
    clipX_ = clipY_ = 0;
    clipW_ = width;
    clipH_ = height;
    pixels_.assign(static_cast<std::size_t>(width) * height, 0xFF000000u);
}

void Graphics::translate(int x, int y) noexcept {
    translateX_ += x;
    translateY_ += y;
}

void Graphics::setClip(int x, int y, int width, int height) noexcept {
    // Work in 64 bits: x + width may overflow int for hostile values.
    const long long x0 = std::clamp<long long>(static_cast<long long>(x) + translateX_, 0, width_);
    const long long y0 = std::clamp<long long>(static_cast<long long>(y) + translateY_, 0, height_);
    const long long x1 = std::clamp<long long>(static_cast<long long>(x) + translateX_ + std::max(width, 0), 0, width_);
    const long long y1 = std::clamp<long long>(static_cast<long long>(y) + translateY_ + std::max(height, 0), 0, height_);
    clipX_ = static_cast<int>(x0);
    clipY_ = static_cast<int>(y0);
    clipW_ = static_cast<int>(x1 - x0);
    clipH_ = static_cast<int>(y1 - y0);
}

std::uint32_t Graphics::getPixel(int x, int y) const {
    detail::requireIndex(x, width_, "Graphics::getPixel", "x");
    detail::requireIndex(y, height_, "Graphics::getPixel", "y");
    return pixels_[static_cast<std::size_t>(y) * width_ + x];
}

}  // namespace m3g
