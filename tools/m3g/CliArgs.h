// Values on the m3g tool's command line: whole numbers, sizes (WxH, within
// the renderer's viewport limits) and floats. CLI11 (CliApp.h) splits the
// command line; these say what a value means and why it is wrong, in the
// tool's words. Part of m3g_cli_support (tools/m3g/), not of the library;
// the ported-game example uses them too.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "CliErrors.h"

namespace m3gcli {

/// Parses a whole decimal int (optional sign); nullopt if `text` is empty,
/// has other characters or is out of range.
std::optional<int> parseInt(std::string_view text);

/// Parses an image size "WxH" (both positive ints) into width and height;
/// false (and both left alone) otherwise.
bool parseSize(std::string_view text, int& width, int& height);

/// Why width x height exceeds maxWidth x maxHeight, as one line naming
/// `option` ("--size 100000x100000 exceeds ..."), or nullopt when it fits.
std::optional<std::string> sizeLimitError(std::string_view option, int width, int height, int maxWidth,
                                          int maxHeight);

/// The value of a size option ("--size"): parseSize, then the renderer's
/// limits (m3g::getLimits(): maxViewportWidth/Height, which
/// Graphics3D::getProperties() reports). Throws CliError otherwise.
void parseSizeOption(std::string_view option, std::string_view text, int& width, int& height);

/// Parses a whole finite decimal float (optional sign, as std::from_chars
/// reads it); nullopt otherwise.
std::optional<float> parseFloat(std::string_view text);

/// The extension of the file name in `path`, lower-case, with its dot
/// (".png"); "" when it has none. Outputs are written in the format their
/// extension names.
std::string lowerExtension(std::string_view path);

/// The value of an integer option: parseInt and at least `min`, else a
/// CliError saying what the option takes (`what`, e.g. "a positive integer").
int parseIntOption(std::string_view option, std::string_view text, int min, std::string_view what);

}  // namespace m3gcli
