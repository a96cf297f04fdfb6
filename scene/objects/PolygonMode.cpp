#include <m3g/PolygonMode.h>

#include "Check.h"

namespace m3g {

PolygonMode::PolygonMode() = default;
PolygonMode::PolygonMode(const PolygonMode& other) = default;
PolygonMode::~PolygonMode() = default;

Object3D* PolygonMode::duplicateImpl(DuplicateMap&) const { return new PolygonMode(*this); }

void PolygonMode::setCulling(int mode) {
    detail::requireEnum(mode, {CULL_BACK, CULL_FRONT, CULL_NONE}, "PolygonMode::setCulling", "mode");
    culling_ = mode;
    touch();
}

void PolygonMode::setShading(int mode) {
    detail::requireEnum(mode, {SHADE_FLAT, SHADE_SMOOTH}, "PolygonMode::setShading", "mode");
    shading_ = mode;
    touch();
}

void PolygonMode::setWinding(int mode) {
    detail::requireEnum(mode, {WINDING_CCW, WINDING_CW}, "PolygonMode::setWinding", "mode");
    winding_ = mode;
    touch();
}

void PolygonMode::setTwoSidedLightingEnable(bool enable) noexcept {
    twoSided_ = enable;
    touch();
}

void PolygonMode::setLocalCameraLightingEnable(bool enable) noexcept {
    localCamera_ = enable;
    touch();
}

void PolygonMode::setPerspectiveCorrectionEnable(bool enable) noexcept {
    perspectiveCorrection_ = enable;
    touch();
}

}  // namespace m3g
