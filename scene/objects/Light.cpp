#include <m3g/Light.h>

#include <algorithm>
#include <cmath>

#include <m3g/AnimationTrack.h>

#include "Check.h"
#include "PropertyUtil.h"

namespace m3g {

Light::Light() = default;

Light::~Light() = default;

Object3D* Light::duplicateImpl(DuplicateMap&) const { return new Light(*this); }

void Light::setMode(int mode) {
    detail::requireEnum(mode, {AMBIENT, DIRECTIONAL, OMNI, SPOT}, "Light::setMode", "mode");
    mode_ = mode;
    touch();
}

void Light::setColor(int RGB) noexcept {
    color_ = RGB & 0x00FFFFFF;
    touch();
}

void Light::setIntensity(float intensity) noexcept {
    intensity_ = intensity;
    touch();
}

void Light::setSpotAngle(float angle) {
    detail::requireRange(angle, 0.0f, 90.0f, "Light::setSpotAngle", "angle");
    spotAngle_ = angle;
    touch();
}

void Light::setSpotExponent(float exponent) {
    detail::requireRange(exponent, 0.0f, 128.0f, "Light::setSpotExponent", "exponent");
    spotExponent_ = exponent;
    touch();
}

void Light::setAttenuation(float constant, float linear, float quadratic) {
    const char* where = "Light::setAttenuation";
    if (!(constant >= 0.0f) || !(linear >= 0.0f) || !(quadratic >= 0.0f))
        throw IllegalArgumentException(detail::str(where, ": attenuation (", constant, ", ", linear, ", ", quadratic,
                                                   ") has a negative component"));
    if (constant == 0.0f && linear == 0.0f && quadratic == 0.0f)
        throw IllegalArgumentException(detail::str(where, ": attenuation (0, 0, 0): at least one must be non-zero"));
    attenuation_[0] = constant;
    attenuation_[1] = linear;
    attenuation_[2] = quadratic;
    touch();
}

bool Light::isAnimatable(int property) const noexcept {
    return property == AnimationTrack::COLOR || property == AnimationTrack::INTENSITY ||
           property == AnimationTrack::SPOT_ANGLE || property == AnimationTrack::SPOT_EXPONENT ||
           Node::isAnimatable(property);
}

void Light::updateProperty(int property, std::span<const float> v) {
    switch (property) {
    case AnimationTrack::COLOR:
        color_ = detail::packRGB(v[0], v[1], v[2]);
        touch();
        return;
    case AnimationTrack::INTENSITY:
        intensity_ = v[0];
        touch();
        return;
    case AnimationTrack::SPOT_ANGLE:
        spotAngle_ = std::clamp(v[0], 0.0f, 90.0f);
        touch();
        return;
    case AnimationTrack::SPOT_EXPONENT:
        spotExponent_ = std::clamp(v[0], 0.0f, 128.0f);
        touch();
        return;
    default:
        Node::updateProperty(property, v);
    }
}

}  // namespace m3g
