// Rendering a prepared World headless into an RgbaImage, as `m3g render`
// does it (and the ported-game example's frame dump): an lcdui-style
// Graphics surface by default, an RGBA Image2D when the output must keep
// alpha; plus the view changes of `m3g render` (turntable orbit, background
// override). Part of m3g_cli_support.
#pragma once

#include <array>
#include <cstdint>

#include <m3g/m3g.h>

#include "ImageIO.h"

namespace m3gcli {

/// Renders `world` through its active camera at width x height. With
/// `keepAlpha` the target is a mutable RGBA Image2D (the alpha channel holds
/// what the renderer wrote, e.g. the Background colour's alpha); otherwise a
/// Graphics surface as a MIDlet renders to (alpha reads 255). Exceptions of
/// Graphics3D pass through with the target released.
RgbaImage renderWorldImage(m3g::World& world, int width, int height, bool keepAlpha);

/// Replaces the World's Background with one that clears colour and depth to
/// `argb` (0xAARRGGBB) and has no image.
void overrideBackground(m3g::World& world, std::uint32_t argb);

/// A camera's orbit around the scene's up axis (UpAxis.h: the active
/// camera's up, +Y or +Z in real files) through a centre, for turntable
/// frames. The constructor captures the camera's World-space transform C;
/// setAngle(a) gives it T(center) * R_up(a) * T(-center) * C, so the camera
/// keeps looking at the same point of the turning scene. Expressed in the camera's own components (JSR-184 1.1,
/// Transformable): T, R, S reset, M = parent-to-World inverse times that.
class CameraOrbit {
public:
    /// Throws std::invalid_argument when `camera` is not in `world`.
    CameraOrbit(m3g::Camera& camera, m3g::World& world, const std::array<float, 3>& center);
    /// The same about a given `up` axis.
    CameraOrbit(m3g::Camera& camera, m3g::World& world, const std::array<float, 3>& center,
                const std::array<float, 3>& up);
    /// Places the camera at `degrees` around the orbit. Until a non-zero angle
    /// is set, 0 leaves the camera untouched (bit-exact with a plain render).
    void setAngle(float degrees);

private:
    m3g::Ref<m3g::Camera> camera_;
    m3g::Transform cameraToWorld_, worldToParent_;
    std::array<float, 3> center_, up_;
    bool moved_ = false;
};

}  // namespace m3gcli
