#include "OrbitCamera.h"

#include "UpAxis.h"

#include <algorithm>
#include <cmath>

namespace m3gview {

namespace {
constexpr float kDegrees = 3.14159265358979f / 180.0f;
}

void OrbitCamera::frame(const std::array<float, 3>& center, float r, float fovyDegrees) {
    target = center;
    radius = r > 0.0f ? r : 1.0f;
    fovy = fovyDegrees;
    yaw = 30.0f;
    pitch = 20.0f;
    // The sphere touches the view cone's sides, plus a 10% margin.
    distance = 1.1f * radius / std::sin(0.5f * fovy * kDegrees);
}

void OrbitCamera::orbit(float dx, float dy) {
    yaw -= dx * 0.3f;
    pitch = std::clamp(pitch + dy * 0.3f, -89.0f, 89.0f);
    yaw = std::fmod(yaw, 360.0f);
}

void OrbitCamera::pan(float dx, float dy, int viewportHeight) {
    // World units per pixel at the target's depth.
    const float perPixel = 2.0f * distance * std::tan(0.5f * fovy * kDegrees) / static_cast<float>(std::max(1, viewportHeight));
    const m3g::Transform t = transform();
    for (int i = 0; i < 3; ++i) target[i] += (-dx * t.at(i, 0) + dy * t.at(i, 1)) * perPixel;
}

void OrbitCamera::zoom(float steps) { distance = std::max(distance * std::pow(0.9f, steps), radius * 1e-3f); }

m3g::Transform OrbitCamera::transform() const {
    m3g::Transform t;
    t.postTranslate(target[0], target[1], target[2]);
    const m3g::Transform basis = m3gcli::upFromY(up);  // +Y to the scene's up
    t.postMultiply(&basis);
    t.postRotate(yaw, 0.0f, 1.0f, 0.0f);
    t.postRotate(-pitch, 1.0f, 0.0f, 0.0f);
    t.postTranslate(0.0f, 0.0f, distance);
    return t;
}

std::array<float, 3> OrbitCamera::eye() const {
    const m3g::Transform t = transform();
    return {t.at(0, 3), t.at(1, 3), t.at(2, 3)};
}

float OrbitCamera::nearPlane() const { return std::max(distance - 2.0f * radius, distance * 0.01f); }

float OrbitCamera::farPlane() const { return distance + 4.0f * radius; }

}  // namespace m3gview
