// `m3g pick FILE X Y [--time T] [--json] [--lenient]`: load a file, animate
// its World to T ms (default 0) and pick through the World's active camera at
// normalised viewport coordinates (X, Y) ((0, 0) top left, (1, 1) bottom
// right; JSR-184 1.1, Group.pick). Prints the RayIntersection or
// "no hit". Part of m3g_cli_support (tools/m3g/), not of the library.
#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include <m3g/Object3D.h>

#include "CliApp.h"

namespace m3gcli {

/// The file has no World, or its World has no active camera (or one outside
/// the World); what() is a
/// one-line message for stderr (without the "m3g: " prefix).
class PickError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Animates the first World among `roots` to `time`, picks (scope -1) at
/// (x, y) through its active camera and describes the result:
///  text: "hit: Class #id userID=N" (ids as in `m3g info`), distance,
///        submesh, S/T per texture unit, normal, ray; or "no hit";
///  json: {"time", "x", "y", "hit": bool, and on a hit "node": {"id",
///        "class", "userID"}, "distance", "submesh", "textureCoordinates":
///        [{"unit", "s", "t"}...], "normal": [x, y, z], "ray": {"origin",
///        "direction"}}.
/// Throws PickError if there is no World, no active camera or the camera is
/// not in the World; m3g
/// exceptions from animate() or pick() pass through.
std::string pickReport(std::span<m3g::Object3D* const> roots, int time, float x, float y, bool json);

/// The command line of `m3g pick`, as given (values checked by runPick).
struct PickArgs {
    std::string file, x, y;
    std::string time;  ///< --time T, empty: 0
    bool json = false, lenient = false;
};

/// Adds FILE X Y and the options of `m3g pick` to `app`, bound to `args`.
void addPickOptions(CLI::App& app, PickArgs& args);

/// Parses the arguments after "pick" (throws CliError as parseArgs does).
PickArgs parsePickArgs(std::span<const std::string_view> args);

/// The whole command: loads, reports on stdout; 0 on success (hit or not).
/// Throws CliError when X, Y or --time is not a number, InputError when the
/// file cannot be loaded or has nothing to pick in (PickError).
int runPick(const PickArgs& args);

}  // namespace m3gcli
