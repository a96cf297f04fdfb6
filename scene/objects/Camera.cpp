#include <m3g/Camera.h>

#include <algorithm>
#include <cmath>

#include <m3g/AnimationTrack.h>

#include "Check.h"

namespace m3g {

Camera::Camera() = default;

Camera::~Camera() = default;

Object3D* Camera::duplicateImpl(DuplicateMap&) const { return new Camera(*this); }

void Camera::setPerspective(float fovy, float aspectRatio, float near, float far) {
    const char* where = "Camera::setPerspective";
    if (!(fovy > 0.0f && fovy < 180.0f))
        throw IllegalArgumentException(detail::str(where, ": fovy ", fovy, " out of range (0, 180)"));
    if (!(aspectRatio > 0.0f))
        throw IllegalArgumentException(detail::str(where, ": aspectRatio ", aspectRatio, " must be > 0"));
    if (!(near > 0.0f))
        throw IllegalArgumentException(detail::str(where, ": near ", near, " must be > 0"));
    if (!(far > 0.0f))
        throw IllegalArgumentException(detail::str(where, ": far ", far, " must be > 0"));
    type_ = PERSPECTIVE;
    params_ = {fovy, aspectRatio, near, far};
    touch();
}

void Camera::setParallel(float height, float aspectRatio, float near, float far) {
    const char* where = "Camera::setParallel";
    if (!(height > 0.0f))
        throw IllegalArgumentException(detail::str(where, ": height ", height, " must be > 0"));
    if (!(aspectRatio > 0.0f))
        throw IllegalArgumentException(detail::str(where, ": aspectRatio ", aspectRatio, " must be > 0"));
    type_ = PARALLEL;
    params_ = {height, aspectRatio, near, far};
    touch();
}

void Camera::setGeneric(const Transform* transform) {
    detail::requireNonNull(transform, "Camera::setGeneric", "transform");
    type_ = GENERIC;
    generic_ = *transform;
    touch();
}

int Camera::getProjection(Transform* transform) const {
    if (!transform) return type_;
    if (type_ == GENERIC) {
        *transform = generic_;
        return type_;
    }
    const double a = params_[1], n = params_[2], f = params_[3];
    if (n == f)
        throw ArithmeticException(
            detail::str("Camera::getProjection: near and far are both ", params_[2], " (zero-depth view volume)"));
    std::array<float, 16> m{};
    if (type_ == PERSPECTIVE) {
        const double h = std::tan(params_[0] * (3.14159265358979323846 / 180.0) * 0.5);
        m[0] = float(1.0 / (a * h));
        m[5] = float(1.0 / h);
        m[10] = float(-(f + n) / (f - n));
        m[11] = float(-2.0 * f * n / (f - n));
        m[14] = -1.0f;
    } else {
        const double height = params_[0];
        m[0] = float(2.0 / (a * height));
        m[5] = float(2.0 / height);
        m[10] = float(-2.0 / (f - n));
        m[11] = float(-(f + n) / (f - n));
        m[15] = 1.0f;
    }
    *transform = Transform::fromRows(m);
    return type_;
}

int Camera::getProjection(std::span<float> params) const {
    if (params.data() != nullptr) {
        detail::requireArray(params, 4, "Camera::getProjection", "params");
        if (type_ != GENERIC)
            for (int i = 0; i < 4; ++i) params[std::size_t(i)] = params_[std::size_t(i)];
    }
    return type_;
}

bool Camera::isAnimatable(int property) const noexcept {
    return property == AnimationTrack::FIELD_OF_VIEW || property == AnimationTrack::NEAR_DISTANCE ||
           property == AnimationTrack::FAR_DISTANCE || Node::isAnimatable(property);
}

void Camera::updateProperty(int property, std::span<const float> v) {
    // Perspective clamps fovy to [0, 180] and near/far to >= 0; otherwise the
    // height is clamped to >= 0 and near/far are free (as in Nokia's core).
    const bool perspective = type_ == PERSPECTIVE;
    switch (property) {
    case AnimationTrack::FIELD_OF_VIEW:
        params_[0] = perspective ? std::clamp(v[0], 0.0f, 180.0f) : std::max(v[0], 0.0f);
        touch();
        return;
    case AnimationTrack::NEAR_DISTANCE:
        params_[2] = perspective ? std::max(v[0], 0.0f) : v[0];
        touch();
        return;
    case AnimationTrack::FAR_DISTANCE:
        params_[3] = perspective ? std::max(v[0], 0.0f) : v[0];
        touch();
        return;
    default:
        Node::updateProperty(property, v);
    }
}

}  // namespace m3g
