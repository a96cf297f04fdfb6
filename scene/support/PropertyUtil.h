// Conversions shared by the updateProperty implementations (JSR-184 1.1,
// Object3D.animate and AnimationTrack):
// animated floats to packed colors and to integers.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace m3g::detail {

/// A color channel in [0, 1] to a byte: clamped to [0, 1] first (NaN -> 0),
/// then rounded to the nearest of v * 255 (0.5 rounds up).
inline std::uint32_t channelToByte(float v) noexcept {
    if (!(v > 0.0f)) return 0;  // also NaN
    if (v >= 1.0f) return 255;
    return static_cast<std::uint32_t>(std::floor(v * 255.0f + 0.5f));
}

/// 0x00RRGGBB from three channels in [0, 1] (clamped).
inline int packRGB(float r, float g, float b) noexcept {
    return static_cast<int>((channelToByte(r) << 16) | (channelToByte(g) << 8) | channelToByte(b));
}

/// 0xAA000000 from one channel in [0, 1] (clamped).
inline int packAlpha(float a) noexcept { return static_cast<int>(channelToByte(a) << 24); }

/// A byte or short normal component as OpenGL maps signed integers to
/// [-1, 1]: (2c + 1) / (2^bits - 1). componentSize is 1 or 2 (VertexArray).
inline float normalComponent(int value, int componentSize) noexcept {
    return (2.0f * static_cast<float>(value) + 1.0f) / (componentSize == 1 ? 255.0f : 65535.0f);
}

/// Rounds to the nearest integer, halves towards +infinity (floor(v + 0.5)),
/// saturating at the int range; NaN -> 0.
inline int roundToInt(float v) noexcept {
    if (std::isnan(v)) return 0;
    const double r = std::floor(static_cast<double>(v) + 0.5);
    if (r >= static_cast<double>(std::numeric_limits<int>::max())) return std::numeric_limits<int>::max();
    if (r <= static_cast<double>(std::numeric_limits<int>::min())) return std::numeric_limits<int>::min();
    return static_cast<int>(r);
}

}  // namespace m3g::detail
