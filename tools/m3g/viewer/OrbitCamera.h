// The viewer's orbit/pan/zoom camera: a point it looks at, a distance, and
// yaw/pitch around the scene's up axis (+Y, or +Z for many real files:
// UpAxis.h), so a model stays upright as it turns (M3G cameras look down
// their -Z).
// Pure math, so it is unit-tested without a window.
#pragma once

#include <array>

#include <m3g/Transform.h>

namespace m3gview {

class OrbitCamera {
public:
    /// Looks at a sphere (center, radius) from the front-right, slightly
    /// above, at a distance where it fills a vertical field of `fovyDegrees`.
    void frame(const std::array<float, 3>& center, float radius, float fovyDegrees);
    /// Turns by (dx, dy) pixels of mouse motion (0.3 degrees per pixel);
    /// the pitch stays within +-89 degrees.
    void orbit(float dx, float dy);
    /// Moves the target with the mouse: (dx, dy) pixels in a view
    /// `viewportHeight` pixels high keep the target under the cursor.
    void pan(float dx, float dy, int viewportHeight);
    /// Wheel steps: each one brings the camera 10% closer (negative: away).
    void zoom(float steps);

    /// Camera-to-world transform (for Node::setTransform or Graphics3D::setCamera).
    m3g::Transform transform() const;
    /// The camera's position in world space.
    std::array<float, 3> eye() const;
    /// Near and far planes enclosing the framed sphere from here.
    float nearPlane() const;
    float farPlane() const;

    std::array<float, 3> target{0.0f, 0.0f, 0.0f};
    float distance = 5.0f;
    float yaw = 30.0f;    ///< degrees about `up`
    float pitch = 20.0f;  ///< degrees above the horizon
    float fovy = 45.0f;
    float radius = 1.0f;
    /// The axis yaw turns about and pitch lifts towards (a unit axis).
    std::array<float, 3> up{0.0f, 1.0f, 0.0f};
};

}  // namespace m3gview
