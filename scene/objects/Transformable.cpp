#include <m3g/Transformable.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include <m3g/AnimationTrack.h>

#include "Check.h"
#include "MathUtil.h"

namespace m3g {

namespace {
/// A setter given the value the object already holds, bit for bit, changes
/// nothing and leaves the revision alone: animate() sets every animated
/// property each frame, and a bone held still through a segment of equal
/// keys (common in exported clips) then keeps its composite transform, its
/// bone matrix and its palette entry instead of having them composed again.
/// Bits, not ==: -0 and +0 stay distinct changes, a NaN is always one.
template <std::size_t N>
bool sameBits(const std::array<float, N>& a, const std::array<float, N>& b) noexcept {
    return std::memcmp(a.data(), b.data(), sizeof(float) * N) == 0;
}

glm::quat toGlmQuat(const std::array<float, 4>& q) { return glm::quat(q[3], q[0], q[1], q[2]); }

glm::quat axisAngleOrThrow(float angle, float ax, float ay, float az, const char* where) {
    glm::quat q;
    if (!detail::quatFromAxisAngle(angle, ax, ay, az, q))
        throw IllegalArgumentException(
            detail::str(where, ": rotation axis is (0, 0, 0) with angle ", angle, " (axis must be non-zero)"));
    return q;
}
}  // namespace

Transformable::Transformable() = default;

void Transformable::setOrientationQuat(float qx, float qy, float qz, float qw) noexcept {
    const float len = std::sqrt(qx * qx + qy * qy + qz * qz + qw * qw);
    const std::array<float, 4> q = len > 0.0f && std::isfinite(len)
                                       ? std::array<float, 4>{qx / len, qy / len, qz / len, qw / len}
                                       : std::array<float, 4>{0, 0, 0, 1};
    if (sameBits(q, q_)) return;
    q_ = q;
    transformChanged();
}

void Transformable::setOrientation(float angle, float ax, float ay, float az) {
    const glm::quat q = axisAngleOrThrow(angle, ax, ay, az, "Transformable::setOrientation");
    setOrientationQuat(q.x, q.y, q.z, q.w);
}

void Transformable::postRotate(float angle, float ax, float ay, float az) {
    const glm::quat r = toGlmQuat(q_) * axisAngleOrThrow(angle, ax, ay, az, "Transformable::postRotate");
    setOrientationQuat(r.x, r.y, r.z, r.w);
}

void Transformable::preRotate(float angle, float ax, float ay, float az) {
    const glm::quat r = axisAngleOrThrow(angle, ax, ay, az, "Transformable::preRotate") * toGlmQuat(q_);
    setOrientationQuat(r.x, r.y, r.z, r.w);
}

void Transformable::getOrientation(std::span<float> angleAxis) const {
    detail::requireArray(angleAxis, 4, "Transformable::getOrientation", "angleAxis");
    // q = (sin(a/2) n, cos(a/2)); the identity reports angle 0 about (0, 0, 0)
    // as Nokia's core does.
    const float w = std::clamp(q_[3], -1.0f, 1.0f);
    const float s = std::sqrt(std::max(0.0f, 1.0f - w * w));
    if (s < 1e-6f) {
        angleAxis[0] = 0.0f;
        angleAxis[1] = angleAxis[2] = angleAxis[3] = 0.0f;
        return;
    }
    angleAxis[0] = glm::degrees(2.0f * std::acos(w));
    angleAxis[1] = q_[0] / s;
    angleAxis[2] = q_[1] / s;
    angleAxis[3] = q_[2] / s;
}

void Transformable::setScale(float sx, float sy, float sz) {
    const std::array<float, 3> s{sx, sy, sz};
    if (sameBits(s, s_)) return;
    s_ = s;
    transformChanged();
}

void Transformable::scale(float sx, float sy, float sz) {
    s_[0] *= sx;
    s_[1] *= sy;
    s_[2] *= sz;
    transformChanged();
}

void Transformable::getScale(std::span<float> xyz) const {
    detail::requireArray(xyz, 3, "Transformable::getScale", "xyz");
    for (int i = 0; i < 3; ++i) xyz[i] = s_[i];
}

void Transformable::setTranslation(float tx, float ty, float tz) {
    const std::array<float, 3> t{tx, ty, tz};
    if (sameBits(t, t_)) return;
    t_ = t;
    transformChanged();
}

void Transformable::translate(float tx, float ty, float tz) {
    t_[0] += tx;
    t_[1] += ty;
    t_[2] += tz;
    transformChanged();
}

void Transformable::getTranslation(std::span<float> xyz) const {
    detail::requireArray(xyz, 3, "Transformable::getTranslation", "xyz");
    for (int i = 0; i < 3; ++i) xyz[i] = t_[i];
}

void Transformable::setTransform(const Transform* transform) {
    if (!transform) {
        m_.setIdentity();
        hasM_ = false;
        transformChanged();
        return;
    }
    if (requiresAffineTransform() &&
        (transform->at(3, 0) != 0.0f || transform->at(3, 1) != 0.0f || transform->at(3, 2) != 0.0f ||
         transform->at(3, 3) != 1.0f))
        throw IllegalArgumentException(detail::str(
            getClassName(), "::setTransform: bottom row (", transform->at(3, 0), ", ", transform->at(3, 1), ", ",
            transform->at(3, 2), ", ", transform->at(3, 3), ") must be (0, 0, 0, 1) for a Node"));
    m_ = *transform;
    hasM_ = !(m_ == Transform());
    transformChanged();
}

void Transformable::getTransform(Transform* transform) const {
    detail::requireNonNull(transform, "Transformable::getTransform", "transform");
    *transform = m_;
}

void Transformable::getCompositeTransform(Transform* transform) const {
    detail::requireNonNull(transform, "Transformable::getCompositeTransform", "transform");
    *transform = compositeTransform();
}

Transform Transformable::compositeTransform() const noexcept {
    // T R S: rotation columns scaled by S, translation in the last column.
    // R written out from the unit quaternion (glm::mat3_cast's terms, in its
    // order, so the bits are the same): this runs for every node of every
    // rendered, picked or skinned frame, and going through a glm 4x4 and a
    // general product cost five times as much.
    const float x = q_[0], y = q_[1], z = q_[2], w = q_[3];
    const float xx = x * x, yy = y * y, zz = z * z, xz = x * z, xy = x * y, yz = y * z;
    const float wx = w * x, wy = w * y, wz = w * z;
    const float sx = s_[0], sy = s_[1], sz = s_[2];
    const std::array<float, 16> trs{(1.0f - 2.0f * (yy + zz)) * sx, 2.0f * (xy - wz) * sy, 2.0f * (xz + wy) * sz, t_[0],
                                    2.0f * (xy + wz) * sx, (1.0f - 2.0f * (xx + zz)) * sy, 2.0f * (yz - wx) * sz, t_[1],
                                    2.0f * (xz - wy) * sx, 2.0f * (yz + wx) * sy, (1.0f - 2.0f * (xx + yy)) * sz, t_[2],
                                    0.0f, 0.0f, 0.0f, 1.0f};
    if (!hasM_) return Transform::fromRows(trs);
    // (T R S) M: TRS's bottom row is (0, 0, 0, 1), so the product's is M's.
    const auto& m = m_.rows();
    std::array<float, 16> out;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) {
            float sum = 0.0f;
            for (int k = 0; k < 4; ++k) sum += trs[r * 4 + k] * m[k * 4 + c];
            out[r * 4 + c] = sum;
        }
    for (int c = 0; c < 4; ++c) out[12 + c] = m[12 + c];
    return Transform::fromRows(out);
}

bool Transformable::isAnimatable(int property) const noexcept {
    return property == AnimationTrack::ORIENTATION || property == AnimationTrack::SCALE ||
           property == AnimationTrack::TRANSLATION || Object3D::isAnimatable(property);
}

void Transformable::updateProperty(int property, std::span<const float> v) {
    switch (property) {
    case AnimationTrack::ORIENTATION:
        setOrientationQuat(v[0], v[1], v[2], v[3]);
        return;
    case AnimationTrack::SCALE:
        if (v.size() >= 3)
            setScale(v[0], v[1], v[2]);
        else
            setScale(v[0], v[0], v[0]);
        return;
    case AnimationTrack::TRANSLATION:
        setTranslation(v[0], v[1], v[2]);
        return;
    default:
        Object3D::updateProperty(property, v);
    }
}

}  // namespace m3g
