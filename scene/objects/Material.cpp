#include <m3g/Material.h>

#include <algorithm>
#include <cmath>

#include <m3g/AnimationTrack.h>

#include "Check.h"
#include "PropertyUtil.h"

namespace m3g {

namespace {
constexpr int kAllTargets = Material::AMBIENT | Material::DIFFUSE | Material::EMISSIVE | Material::SPECULAR;
}

Material::Material() = default;
Material::Material(const Material& other) = default;
Material::~Material() = default;

Object3D* Material::duplicateImpl(DuplicateMap&) const { return new Material(*this); }

void Material::setColor(int target, int ARGB) {
    if (target == 0 || (target & ~kAllTargets) != 0)
        throw IllegalArgumentException(detail::str(
            "Material::setColor: target ", target,
            " must be a non-empty OR of AMBIENT (1024), DIFFUSE (2048), EMISSIVE (4096), SPECULAR (8192)"));
    const int rgb = ARGB & 0x00FFFFFF;
    if (target & AMBIENT) ambient_ = rgb;
    if (target & DIFFUSE) diffuse_ = ARGB;
    if (target & EMISSIVE) emissive_ = rgb;
    if (target & SPECULAR) specular_ = rgb;
    touch();
}

int Material::getColor(int target) const {
    detail::requireEnum(target, {AMBIENT, DIFFUSE, EMISSIVE, SPECULAR}, "Material::getColor", "target");
    switch (target) {
    case AMBIENT: return ambient_;
    case DIFFUSE: return diffuse_;
    case EMISSIVE: return emissive_;
    default: return specular_;
    }
}

void Material::setShininess(float shininess) {
    detail::requireRange(shininess, 0.0f, 128.0f, "Material::setShininess", "shininess");
    shininess_ = shininess;
    touch();
}

void Material::setVertexColorTrackingEnable(bool enable) noexcept {
    vertexColorTracking_ = enable;
    touch();
}

bool Material::isAnimatable(int property) const noexcept {
    switch (property) {
    case AnimationTrack::ALPHA:
    case AnimationTrack::AMBIENT_COLOR:
    case AnimationTrack::DIFFUSE_COLOR:
    case AnimationTrack::EMISSIVE_COLOR:
    case AnimationTrack::SPECULAR_COLOR:
    case AnimationTrack::SHININESS: return true;
    default: return Object3D::isAnimatable(property);
    }
}

void Material::updateProperty(int property, std::span<const float> v) {
    switch (property) {
    case AnimationTrack::ALPHA:
        diffuse_ = (diffuse_ & 0x00FFFFFF) | detail::packAlpha(v[0]);
        break;
    case AnimationTrack::AMBIENT_COLOR:
        ambient_ = detail::packRGB(v[0], v[1], v[2]);
        break;
    case AnimationTrack::DIFFUSE_COLOR:
        diffuse_ = (diffuse_ & static_cast<int>(0xFF000000u)) | detail::packRGB(v[0], v[1], v[2]);
        break;
    case AnimationTrack::EMISSIVE_COLOR:
        emissive_ = detail::packRGB(v[0], v[1], v[2]);
        break;
    case AnimationTrack::SPECULAR_COLOR:
        specular_ = detail::packRGB(v[0], v[1], v[2]);
        break;
    case AnimationTrack::SHININESS:
        shininess_ = std::isnan(v[0]) ? 0.0f : std::clamp(v[0], 0.0f, 128.0f);
        break;
    default:
        Object3D::updateProperty(property, v);
        return;
    }
    touch();
}

}  // namespace m3g
