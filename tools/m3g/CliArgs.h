// Command-line arguments of the m3g tool:
//   m3g <command> [FILE] [--json] [--lenient] [--time T] [--compress] [OUT]
// Part of m3g_cli_support (tools/m3g/), not of the library.
#pragma once

#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace m3gcli {

/// A malformed command line; what() is a one-line message for stderr
/// (without the "m3g: " prefix).
class CliError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct CliArgs {
    /// "info", "convert", "pick", "version" or "help" ("--help"/"-h" anywhere also
    /// give "help").
    std::string command;
    /// Operands in order: info [FILE], convert IN OUT, pick FILE X Y.
    std::vector<std::string> files;
    bool json = false;      ///< --json (info, pick)
    bool lenient = false;   ///< --lenient (info, convert, pick)
    bool compress = false;  ///< --compress (convert)
    /// --time T (info, pick): world time in milliseconds passed to animate().
    std::optional<int> time;
};

/// Parses the arguments after the program name. Options may appear anywhere
/// after the command, as `--time T` or `--time=T`; `--` ends the options.
/// Throws CliError on: no command, an unknown command, an unknown option,
/// an option not taken by the command, a missing or non-integer (or out of
/// int range) --time value, a repeated --time, a value given to a flag, or a
/// wrong number of operands (info: 0 or 1, convert: 2, pick: 3, version/help:
/// 0). An argument that reads as a number ("-0.5") is an operand.
CliArgs parseCliArgs(std::span<const std::string_view> args);
/// Convenience: argv[1..argc).
CliArgs parseCliArgs(int argc, const char* const* argv);

/// Parses a whole decimal int (optional sign); nullopt if `text` is empty,
/// has other characters or is out of range.
std::optional<int> parseInt(std::string_view text);

/// Parses an image size "WxH" (both positive ints) into width and height;
/// false (and both left alone) otherwise.
bool parseSize(std::string_view text, int& width, int& height);

/// Parses a whole finite decimal float (optional sign, as std::from_chars
/// reads it); nullopt otherwise.
std::optional<float> parseFloat(std::string_view text);

/// The usage text (several lines, ends with a newline).
std::string usageText();

}  // namespace m3gcli
