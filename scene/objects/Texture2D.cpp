#include <m3g/Texture2D.h>

#include <m3g/AnimationTrack.h>
#include <m3g/Image2D.h>
#include <m3g/Limits.h>

#include "Check.h"
#include "PropertyUtil.h"

namespace m3g {

namespace {
bool isPowerOfTwo(int v) noexcept { return v > 0 && (v & (v - 1)) == 0; }

void checkTextureImage(const Image2D* image, const char* where) {
    detail::requireNonNull(image, where, "image");
    const int maxDim = getLimits().maxTextureDimension;
    const int w = image->getWidth();
    const int h = image->getHeight();
    if (!isPowerOfTwo(w) || w > maxDim)
        throw IllegalArgumentException(detail::str(where, ": image width ", w,
                                                   " must be a power of two in range [1, ", maxDim, "]"));
    if (!isPowerOfTwo(h) || h > maxDim)
        throw IllegalArgumentException(detail::str(where, ": image height ", h,
                                                   " must be a power of two in range [1, ", maxDim, "]"));
}
}  // namespace

Texture2D::Texture2D(Image2D* image) {
    checkTextureImage(image, "Texture2D::Texture2D");
    image_ = image;
}

Texture2D::Texture2D(const Texture2D& other) = default;

Texture2D::~Texture2D() = default;

void Texture2D::setImage(Image2D* image) {
    checkTextureImage(image, "Texture2D::setImage");
    image_ = image;
    touch();
}

Ref<Image2D> Texture2D::getImage() const { return image_; }

void Texture2D::setFiltering(int levelFilter, int imageFilter) {
    detail::requireEnum(levelFilter, {FILTER_BASE_LEVEL, FILTER_NEAREST, FILTER_LINEAR}, "Texture2D::setFiltering",
                        "levelFilter");
    detail::requireEnum(imageFilter, {FILTER_NEAREST, FILTER_LINEAR}, "Texture2D::setFiltering", "imageFilter");
    levelFilter_ = levelFilter;
    imageFilter_ = imageFilter;
    touch();
}

void Texture2D::setWrapping(int wrapS, int wrapT) {
    detail::requireEnum(wrapS, {WRAP_CLAMP, WRAP_REPEAT}, "Texture2D::setWrapping", "wrapS");
    detail::requireEnum(wrapT, {WRAP_CLAMP, WRAP_REPEAT}, "Texture2D::setWrapping", "wrapT");
    wrapS_ = wrapS;
    wrapT_ = wrapT;
    touch();
}

void Texture2D::setBlending(int func) {
    detail::requireEnum(func, {FUNC_ADD, FUNC_BLEND, FUNC_DECAL, FUNC_MODULATE, FUNC_REPLACE}, "Texture2D::setBlending",
                        "func");
    blending_ = func;
    touch();
}

void Texture2D::setBlendColor(int RGB) noexcept {
    blendColor_ = RGB & 0x00FFFFFF;
    touch();
}

void Texture2D::collectReferences(std::vector<Object3D*>& out) const {
    Transformable::collectReferences(out);
    if (image_) out.push_back(image_.get());
}

Object3D* Texture2D::duplicateImpl(DuplicateMap&) const { return new Texture2D(*this); }

bool Texture2D::isAnimatable(int property) const noexcept {
    return property == AnimationTrack::COLOR || Transformable::isAnimatable(property);
}

void Texture2D::updateProperty(int property, std::span<const float> v) {
    if (property == AnimationTrack::COLOR) {
        blendColor_ = detail::packRGB(v[0], v[1], v[2]);
        touch();
        return;
    }
    Transformable::updateProperty(property, v);
}

}  // namespace m3g
