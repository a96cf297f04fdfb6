#include <m3g/CompositingMode.h>

#include "Check.h"

namespace m3g {

CompositingMode::CompositingMode() = default;
CompositingMode::CompositingMode(const CompositingMode& other) = default;
CompositingMode::~CompositingMode() = default;

Object3D* CompositingMode::duplicateImpl(DuplicateMap&) const { return new CompositingMode(*this); }

void CompositingMode::setBlending(int mode) {
    detail::requireEnum(mode, {ALPHA, ALPHA_ADD, MODULATE, MODULATE_X2, REPLACE}, "CompositingMode::setBlending",
                        "mode");
    blending_ = mode;
    touch();
}

void CompositingMode::setAlphaThreshold(float threshold) {
    detail::requireRange(threshold, 0.0f, 1.0f, "CompositingMode::setAlphaThreshold", "threshold");
    alphaThreshold_ = threshold;
    touch();
}

void CompositingMode::setDepthTestEnable(bool enable) noexcept {
    depthTest_ = enable;
    touch();
}

void CompositingMode::setDepthWriteEnable(bool enable) noexcept {
    depthWrite_ = enable;
    touch();
}

void CompositingMode::setColorWriteEnable(bool enable) noexcept {
    colorWrite_ = enable;
    touch();
}

void CompositingMode::setAlphaWriteEnable(bool enable) noexcept {
    alphaWrite_ = enable;
    touch();
}

void CompositingMode::setDepthOffset(float factor, float units) noexcept {
    depthOffsetFactor_ = factor;
    depthOffsetUnits_ = units;
    touch();
}

}  // namespace m3g
