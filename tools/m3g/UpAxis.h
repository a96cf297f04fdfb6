// Which way is up in a scene. M3G has no up axis: exporters from Y-up tools
// write +Y, those from 3ds Max and Blender often +Z (16 of the 25 shared
// corpus files with an active camera). The tools orbit (render --turntable,
// the viewer) and export (glTF is +Y up) around the scene's own up: the
// active camera's up direction in World space, snapped to the nearest axis.
// Part of m3g_cli_support.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include <m3g/m3g.h>

namespace m3gcli {

/// A unit axis: +X, -X, +Y, -Y, +Z or -Z.
using Axis = std::array<float, 3>;
inline constexpr Axis kUpY{0.0f, 1.0f, 0.0f};

/// The axis nearest to the World-space up (+Y) of `world`'s active camera;
/// +Y when there is none or it is not in `world`.
Axis sceneUp(m3g::World& world);
/// "x", "+y", "-Z" ... as an Axis; nullopt otherwise. ("auto" is the caller's.)
std::optional<Axis> parseAxis(std::string_view text);
/// The value of an --up option: "auto" (nullopt: the scene's own) or an
/// axis; throws CliError naming the option and the values it takes.
std::optional<Axis> parseUpOption(const std::string& text);
/// "+Z", "-Y" ...
std::string axisName(const Axis& axis);
/// A rotation taking +Y to `up` (the identity for +Y): for the orbit
/// cameras, whose yaw turns about +Y and pitch lifts towards it.
m3g::Transform upFromY(const Axis& up);

}  // namespace m3gcli
