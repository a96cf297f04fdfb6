#include <m3g/Background.h>

#include <algorithm>

#include <m3g/AnimationTrack.h>
#include <m3g/Image2D.h>
#include <m3g/Limits.h>

#include "Check.h"
#include "PropertyUtil.h"

namespace m3g {

Background::Background() = default;
Background::Background(const Background& other) = default;  // shares the image
Background::~Background() = default;

Object3D* Background::duplicateImpl(DuplicateMap&) const { return new Background(*this); }

void Background::setColor(int ARGB) noexcept {
    color_ = ARGB;
    touch();
}

int Background::getColor() const noexcept { return color_; }

void Background::setImage(Image2D* image) {
    if (image) {
        const int f = image->getFormat();
        if (f != Image2D::RGB && f != Image2D::RGBA)
            throw IllegalArgumentException(detail::str("Background::setImage: image format ", f,
                                                       " is not one of {", Image2D::RGB, " (RGB), ", Image2D::RGBA,
                                                       " (RGBA)}"));
        cropX_ = 0;
        cropY_ = 0;
        cropWidth_ = image->getWidth();
        cropHeight_ = image->getHeight();
    }
    image_ = image;
    touch();
}

Ref<Image2D> Background::getImage() const { return image_; }

void Background::setImageMode(int modeX, int modeY) {
    detail::requireEnum(modeX, {BORDER, REPEAT}, "Background::setImageMode", "modeX");
    detail::requireEnum(modeY, {BORDER, REPEAT}, "Background::setImageMode", "modeY");
    modeX_ = modeX;
    modeY_ = modeY;
    touch();
}

int Background::getImageModeX() const noexcept { return modeX_; }
int Background::getImageModeY() const noexcept { return modeY_; }

void Background::setCrop(int cropX, int cropY, int width, int height) {
    const int maxDim = getLimits().maxViewportDimension;
    detail::requireRange(width, 0, maxDim, "Background::setCrop", "width");
    detail::requireRange(height, 0, maxDim, "Background::setCrop", "height");
    cropX_ = cropX;
    cropY_ = cropY;
    cropWidth_ = width;
    cropHeight_ = height;
    touch();
}

int Background::getCropX() const noexcept { return cropX_; }
int Background::getCropY() const noexcept { return cropY_; }
int Background::getCropWidth() const noexcept { return cropWidth_; }
int Background::getCropHeight() const noexcept { return cropHeight_; }

void Background::setColorClearEnable(bool enable) noexcept {
    colorClear_ = enable;
    touch();
}

bool Background::isColorClearEnabled() const noexcept { return colorClear_; }

void Background::setDepthClearEnable(bool enable) noexcept {
    depthClear_ = enable;
    touch();
}

bool Background::isDepthClearEnabled() const noexcept { return depthClear_; }

void Background::collectReferences(std::vector<Object3D*>& out) const {
    Object3D::collectReferences(out);
    if (image_) out.push_back(image_.get());
}

bool Background::isAnimatable(int property) const noexcept {
    return property == AnimationTrack::ALPHA || property == AnimationTrack::COLOR ||
           property == AnimationTrack::CROP || Object3D::isAnimatable(property);
}

void Background::updateProperty(int property, std::span<const float> v) {
    switch (property) {
    case AnimationTrack::ALPHA:
        color_ = (color_ & 0x00FFFFFF) | detail::packAlpha(v[0]);
        break;
    case AnimationTrack::COLOR:
        color_ = (color_ & static_cast<int>(0xFF000000u)) | detail::packRGB(v[0], v[1], v[2]);
        break;
    case AnimationTrack::CROP:
        // x, y rounded; width and height rounded and clamped to [0, maxViewportDimension].
        cropX_ = detail::roundToInt(v[0]);
        cropY_ = detail::roundToInt(v[1]);
        if (v.size() >= 4) {
            const int maxDim = getLimits().maxViewportDimension;
            cropWidth_ = std::clamp(detail::roundToInt(v[2]), 0, maxDim);
            cropHeight_ = std::clamp(detail::roundToInt(v[3]), 0, maxDim);
        }
        break;
    default:
        Object3D::updateProperty(property, v);
        return;
    }
    touch();
}

}  // namespace m3g
