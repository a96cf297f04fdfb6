// Implementation limits reported by Graphics3D::getProperties() (JSR-184 1.1,
// Graphics3D.getProperties)
// and enforced by the object model (texture units, texture size, sprite crop,
// transforms per vertex, viewport size).
#pragma once

#include <m3g/Export.h>

namespace m3g {

/// Compile-time capacity; Limits::numTextureUnits may be configured up to this.
inline constexpr int kMaxTextureUnits = 4;

struct Limits {
    bool supportAntialiasing = true;
    bool supportTrueColor = true;
    bool supportDithering = false;
    bool supportMipmapping = true;
    bool supportPerspectiveCorrection = true;
    bool supportLocalCameraLighting = true;
    int maxLights = 8;
    int maxViewportWidth = 2048;
    int maxViewportHeight = 2048;
    int maxViewportDimension = 2048;
    int maxTextureDimension = 1024;
    int maxSpriteCropDimension = 1024;
    int maxTransformsPerVertex = 4;
    int numTextureUnits = 2;
};

/// The limits in force (handset-like defaults above).
M3G_API const Limits& getLimits() noexcept;

/// Replaces the limits; IllegalArgumentException if a value is below the
/// spec minimum (maxLights >= 8, viewport and texture sizes >= 256,
/// maxTransformsPerVertex >= 2, numTextureUnits in [1, kMaxTextureUnits]).
/// Objects created earlier keep what they validated against.
M3G_API void setLimits(const Limits& limits);

}  // namespace m3g
