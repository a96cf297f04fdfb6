#include <m3g/Sprite3D.h>

#include <algorithm>
#include <cstdlib>

#include <m3g/Appearance.h>
#include <m3g/AnimationTrack.h>
#include <m3g/Image2D.h>
#include <m3g/Limits.h>

#include "Check.h"
#include "PropertyUtil.h"

namespace m3g {

Sprite3D::Sprite3D(bool scaled, Image2D* image, Appearance* appearance) : scaled_(scaled) {
    detail::requireNonNull(image, "Sprite3D::Sprite3D", "image");
    image_ = image;
    appearance_ = appearance;
    cropWidth_ = image->getWidth();
    cropHeight_ = image->getHeight();
}

// Image and appearance are shared with the original, per duplicate().
Sprite3D::Sprite3D(const Sprite3D& other) = default;

Sprite3D::~Sprite3D() = default;

Object3D* Sprite3D::duplicateImpl(DuplicateMap&) const { return new Sprite3D(*this); }

void Sprite3D::setAppearance(Appearance* appearance) {
    if (appearance_.get() != appearance) referencesChanged();
    appearance_ = appearance;
    touch();
}

Ref<Appearance> Sprite3D::getAppearance() const { return appearance_; }

void Sprite3D::setImage(Image2D* image) {
    detail::requireNonNull(image, "Sprite3D::setImage", "image");
    image_ = image;
    cropX_ = 0;
    cropY_ = 0;
    cropWidth_ = image->getWidth();
    cropHeight_ = image->getHeight();
    touch();
}

Ref<Image2D> Sprite3D::getImage() const { return image_; }

void Sprite3D::setCrop(int cropX, int cropY, int width, int height) {
    const int maxDim = getLimits().maxSpriteCropDimension;
    // In long long: -INT_MIN does not fit an int.
    detail::requireRange<long long>(width, -maxDim, maxDim, "Sprite3D::setCrop", "width");
    detail::requireRange<long long>(height, -maxDim, maxDim, "Sprite3D::setCrop", "height");
    cropX_ = cropX;
    cropY_ = cropY;
    cropWidth_ = width;
    cropHeight_ = height;
    touch();
}

void Sprite3D::collectReferences(std::vector<Object3D*>& out) const {
    Node::collectReferences(out);
    if (image_) out.push_back(image_.get());
    if (appearance_) out.push_back(appearance_.get());
}

bool Sprite3D::isAnimatable(int property) const noexcept {
    return property == AnimationTrack::CROP || Node::isAnimatable(property);
}

void Sprite3D::updateProperty(int property, std::span<const float> v) {
    if (property != AnimationTrack::CROP) {
        Node::updateProperty(property, v);
        return;
    }
    cropX_ = detail::roundToInt(v[0]);
    cropY_ = detail::roundToInt(v[1]);
    if (v.size() >= 4) {
        const int maxDim = getLimits().maxSpriteCropDimension;
        cropWidth_ = std::clamp(detail::roundToInt(v[2]), -maxDim, maxDim);
        cropHeight_ = std::clamp(detail::roundToInt(v[3]), -maxDim, maxDim);
    }
    touch();
}

}  // namespace m3g
