// Conversions between the API's row-major Transform and GLM, plus the
// quaternion helpers shared by Transform and Transformable.
#pragma once

#include <array>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <m3g/Transform.h>

namespace m3g::detail {

inline glm::mat4 toGlm(const Transform& t) noexcept {
    glm::mat4 m;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m[c][r] = t.at(r, c);  // GLM is column-major
    return m;
}

inline Transform fromGlm(const glm::mat4& m) noexcept {
    std::array<float, 16> rows;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) rows[r * 4 + c] = m[c][r];
    return Transform::fromRows(rows);
}

/// Unit quaternion of a rotation of `angleDeg` about (ax, ay, az). Returns
/// false (and identity) if the axis is zero; a zero angle is identity.
bool quatFromAxisAngle(float angleDeg, float ax, float ay, float az, glm::quat& out) noexcept;

/// Rotation matrix of a unit quaternion.
glm::mat4 quatToMatrix(const glm::quat& q) noexcept;

}  // namespace m3g::detail
