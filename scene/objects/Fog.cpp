#include <m3g/Fog.h>

#include <m3g/AnimationTrack.h>

#include "Check.h"
#include "PropertyUtil.h"

namespace m3g {

Fog::Fog() = default;
Fog::Fog(const Fog& other) = default;
Fog::~Fog() = default;

Object3D* Fog::duplicateImpl(DuplicateMap&) const { return new Fog(*this); }

void Fog::setMode(int mode) {
    detail::requireEnum(mode, {EXPONENTIAL, LINEAR}, "Fog::setMode", "mode");
    mode_ = mode;
    touch();
}

void Fog::setLinear(float nearDistance, float farDistance) noexcept {
    near_ = nearDistance;
    far_ = farDistance;
    touch();
}

void Fog::setDensity(float density) {
    if (!(density >= 0.0f))
        throw IllegalArgumentException(detail::str("Fog::setDensity: density ", density, " out of range [0, inf)"));
    density_ = density;
    touch();
}

void Fog::setColor(int RGB) noexcept {
    color_ = RGB & 0x00FFFFFF;
    touch();
}

bool Fog::isAnimatable(int property) const noexcept {
    switch (property) {
    case AnimationTrack::COLOR:
    case AnimationTrack::DENSITY:
    case AnimationTrack::NEAR_DISTANCE:
    case AnimationTrack::FAR_DISTANCE: return true;
    default: return Object3D::isAnimatable(property);
    }
}

void Fog::updateProperty(int property, std::span<const float> v) {
    switch (property) {
    case AnimationTrack::COLOR:
        color_ = detail::packRGB(v[0], v[1], v[2]);
        break;
    case AnimationTrack::DENSITY:
        density_ = v[0] > 0.0f ? v[0] : 0.0f;  // NaN -> 0
        break;
    case AnimationTrack::NEAR_DISTANCE:
        near_ = v[0];
        break;
    case AnimationTrack::FAR_DISTANCE:
        far_ = v[0];
        break;
    default:
        Object3D::updateProperty(property, v);
        return;
    }
    touch();
}

}  // namespace m3g
