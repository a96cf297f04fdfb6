#include <m3g/Transform.h>

#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>

#include "Check.h"
#include "MathUtil.h"

namespace m3g {

namespace detail {

bool quatFromAxisAngle(float angleDeg, float ax, float ay, float az, glm::quat& out) noexcept {
    out = glm::quat(1, 0, 0, 0);
    if (angleDeg == 0.0f) return true;
    const float len = std::sqrt(ax * ax + ay * ay + az * az);
    if (!(len > 0.0f)) return false;
    const float half = glm::radians(angleDeg) * 0.5f;
    const float s = std::sin(half) / len;
    out = glm::quat(std::cos(half), ax * s, ay * s, az * s);
    return true;
}

glm::mat4 quatToMatrix(const glm::quat& q) noexcept { return glm::mat4_cast(q); }

}  // namespace detail

using detail::fromGlm;
using detail::toGlm;

void Transform::setIdentity() noexcept {
    m_.fill(0.0f);
    m_[0] = m_[5] = m_[10] = m_[15] = 1.0f;
}

void Transform::set(const Transform* transform) {
    detail::requireNonNull(transform, "Transform::set", "transform");
    m_ = transform->m_;
}

void Transform::set(std::span<const float> matrix) {
    detail::requireArray(matrix, 16, "Transform::set", "matrix");
    for (int i = 0; i < 16; ++i) m_[i] = matrix[i];
}

void Transform::get(std::span<float> matrix) const {
    detail::requireArray(matrix, 16, "Transform::get", "matrix");
    for (int i = 0; i < 16; ++i) matrix[i] = m_[i];
}

void Transform::invert() {
    const glm::mat4 g = toGlm(*this);
    // Determinant in double: float cancellation would call well-conditioned
    // matrices of large or small scale singular.
    glm::dmat4 d(g);
    const double det = glm::determinant(d);
    if (det == 0.0 || !std::isfinite(det))
        throw ArithmeticException("Transform::invert: matrix is singular (determinant 0)");
    const Transform inv = fromGlm(glm::mat4(glm::inverse(d)));
    for (float v : inv.m_)
        if (!std::isfinite(v))
            throw ArithmeticException("Transform::invert: matrix is singular (inverse not finite)");
    m_ = inv.m_;
}

void Transform::transpose() noexcept {
    for (int r = 0; r < 4; ++r)
        for (int c = r + 1; c < 4; ++c) std::swap(m_[r * 4 + c], m_[c * 4 + r]);
}

Transform Transform::operator*(const Transform& o) const noexcept {
    // Each entry is ((((0 + a0 b0) + a1 b1) + a2 b2) + a3 b3), as the
    // textbook loop sums it; with the column innermost the compiler adds
    // whole rows of `o` at once (bone paths compose one per node per frame).
    Transform out;
    for (int r = 0; r < 4; ++r) {
        float row[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        for (int k = 0; k < 4; ++k) {
            const float a = m_[r * 4 + k];
            for (int c = 0; c < 4; ++c) row[c] += a * o.m_[k * 4 + c];
        }
        for (int c = 0; c < 4; ++c) out.m_[r * 4 + c] = row[c];
    }
    return out;
}

void Transform::postMultiply(const Transform* transform) {
    detail::requireNonNull(transform, "Transform::postMultiply", "transform");
    *this = *this * *transform;
}

void Transform::postScale(float sx, float sy, float sz) noexcept {
    for (int r = 0; r < 4; ++r) {
        m_[r * 4 + 0] *= sx;
        m_[r * 4 + 1] *= sy;
        m_[r * 4 + 2] *= sz;
    }
}

void Transform::postRotate(float angle, float ax, float ay, float az) {
    glm::quat q;
    if (!detail::quatFromAxisAngle(angle, ax, ay, az, q))
        throw IllegalArgumentException(detail::str(
            "Transform::postRotate: rotation axis is (0, 0, 0) with angle ", angle, " (axis must be non-zero)"));
    if (angle == 0.0f) return;
    *this = *this * fromGlm(detail::quatToMatrix(q));
}

void Transform::postRotateQuat(float qx, float qy, float qz, float qw) {
    const float len = std::sqrt(qx * qx + qy * qy + qz * qz + qw * qw);
    if (!(len > 0.0f))
        throw IllegalArgumentException("Transform::postRotateQuat: quaternion (0, 0, 0, 0) cannot be normalised");
    const glm::quat q(qw / len, qx / len, qy / len, qz / len);
    *this = *this * fromGlm(detail::quatToMatrix(q));
}

void Transform::postTranslate(float tx, float ty, float tz) noexcept {
    for (int r = 0; r < 4; ++r) m_[r * 4 + 3] += m_[r * 4 + 0] * tx + m_[r * 4 + 1] * ty + m_[r * 4 + 2] * tz;
}

void Transform::transform(std::span<float> vectors) const {
    if (vectors.data() == nullptr) detail::throwNull("Transform::transform", "vectors");
    if (vectors.size() % 4 != 0)
        throw IllegalArgumentException(detail::str("Transform::transform: vectors length ", vectors.size(),
                                                   " is not a multiple of 4"));
    for (std::size_t i = 0; i < vectors.size(); i += 4) {
        const float v[4] = {vectors[i], vectors[i + 1], vectors[i + 2], vectors[i + 3]};
        for (int r = 0; r < 4; ++r)
            vectors[i + r] = m_[r * 4] * v[0] + m_[r * 4 + 1] * v[1] + m_[r * 4 + 2] * v[2] + m_[r * 4 + 3] * v[3];
    }
}

// Transform::transform(const VertexArray*, ...) lives in VertexArray.cpp.

}  // namespace m3g
