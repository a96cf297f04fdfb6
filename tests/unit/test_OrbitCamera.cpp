// The viewer's orbit camera: hand-derived geometry (no window needed).
#include <cmath>

#include <gtest/gtest.h>

#include "OrbitCamera.h"

using m3gview::OrbitCamera;

namespace {

constexpr float kPi = 3.14159265f;

float length(const std::array<float, 3>& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// The camera's -Z axis in world space (where it looks).
std::array<float, 3> forward(const OrbitCamera& c) {
    const m3g::Transform t = c.transform();
    return {-t.at(0, 2), -t.at(1, 2), -t.at(2, 2)};
}

}  // namespace

TEST(OrbitCamera, FrameFitsTheSphereInTheFieldOfView) {
    OrbitCamera c;
    c.frame({1.0f, 2.0f, 3.0f}, 2.0f, 60.0f);
    // distance = 1.1 r / sin(fovy / 2) = 2.2 / 0.5
    EXPECT_NEAR(c.distance, 4.4f, 1e-5f);
    const auto eye = c.eye();
    EXPECT_NEAR(length({eye[0] - 1.0f, eye[1] - 2.0f, eye[2] - 3.0f}), 4.4f, 1e-4f);
    // yaw 30, pitch 20: the eye is above the target and towards +X, +Z.
    EXPECT_NEAR(eye[1] - 2.0f, 4.4f * std::sin(20.0f * kPi / 180.0f), 1e-4f);
    EXPECT_NEAR(eye[0] - 1.0f, 4.4f * std::cos(20.0f * kPi / 180.0f) * std::sin(30.0f * kPi / 180.0f), 1e-4f);
    EXPECT_NEAR(eye[2] - 3.0f, 4.4f * std::cos(20.0f * kPi / 180.0f) * std::cos(30.0f * kPi / 180.0f), 1e-4f);
}

TEST(OrbitCamera, LooksAtTheTargetFromAnyAngle) {
    OrbitCamera c;
    c.frame({0.5f, -1.0f, 2.0f}, 1.0f, 45.0f);
    for (float dx : {0.0f, 120.0f, -400.0f})
        for (float dy : {0.0f, 50.0f, -500.0f}) {
            c.orbit(dx, dy);
            const auto eye = c.eye(), f = forward(c);
            const std::array<float, 3> toTarget{c.target[0] - eye[0], c.target[1] - eye[1], c.target[2] - eye[2]};
            const float d = length(toTarget);
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(f[k], toTarget[k] / d, 1e-4f) << dx << "," << dy;
            EXPECT_LE(std::abs(c.pitch), 89.0f);
        }
}

TEST(OrbitCamera, OrbitTurnsByPointThreeDegreesPerPixel) {
    OrbitCamera c;
    c.frame({0, 0, 0}, 1.0f, 45.0f);
    c.orbit(100.0f, 50.0f);
    EXPECT_NEAR(c.yaw, 30.0f - 30.0f, 1e-4f);
    EXPECT_NEAR(c.pitch, 20.0f + 15.0f, 1e-4f);
    c.orbit(0.0f, 1000.0f);
    EXPECT_FLOAT_EQ(c.pitch, 89.0f);
}

TEST(OrbitCamera, PanKeepsTheTargetUnderTheCursor) {
    OrbitCamera c;
    c.frame({0, 0, 0}, 1.0f, 90.0f);  // tan(45 deg) = 1: 2 * distance world units over the view height
    c.yaw = 0.0f;
    c.pitch = 0.0f;
    const float perPixel = 2.0f * c.distance / 200.0f;
    c.pan(10.0f, 0.0f, 200);  // dragging right moves the target left (-X, the camera's right is +X)
    EXPECT_NEAR(c.target[0], -10.0f * perPixel, 1e-5f);
    EXPECT_NEAR(c.target[1], 0.0f, 1e-6f);
    c.pan(0.0f, 10.0f, 200);  // dragging down moves the target up
    EXPECT_NEAR(c.target[1], 10.0f * perPixel, 1e-5f);
}

TEST(OrbitCamera, ZoomAndPlanes) {
    OrbitCamera c;
    c.frame({0, 0, 0}, 1.0f, 45.0f);
    const float d = c.distance;
    c.zoom(1.0f);
    EXPECT_NEAR(c.distance, 0.9f * d, 1e-5f);
    c.zoom(-2.0f);
    EXPECT_NEAR(c.distance, d / 0.9f, 1e-4f);
    EXPECT_GT(c.nearPlane(), 0.0f);
    EXPECT_LT(c.nearPlane(), c.distance - c.radius);  // the sphere is between the planes
    EXPECT_GT(c.farPlane(), c.distance + c.radius);
    c.zoom(1000.0f);  // never through the target
    EXPECT_GT(c.distance, 0.0f);
}
