// How a command of the m3g tool fails: the exit codes, one per meaning, and
// the exceptions that carry a failure to the one place that prints it and
// picks the code (CliApp.cpp). Part of m3g_cli_support.
#pragma once

#include <stdexcept>
#include <string>

namespace m3gcli {

/// The m3g tool's exit codes (also in the usage text, exitCodesText(), and
/// in README.md). Scripts tell a failed check from a broken input by them.
enum ExitCode : int {
    kExitOk = 0,
    /// A check said no: compare or render --reference over the limits,
    /// bench soak's verdict, a viewer script's expect-pick.
    kExitMismatch = 1,
    /// The command line is wrong (unknown command or option, bad value).
    kExitUsage = 2,
    /// An input cannot be read or loaded (missing, a directory, malformed).
    kExitInput = 3,
    /// An output cannot be written.
    kExitOutput = 4,
    /// No Vulkan device or display, or rendering (or another step of the
    /// work itself) failed.
    kExitRender = 5,
};

/// The exit-code table for the usage text (several lines, ends with a newline).
std::string exitCodesText();

/// A malformed command line; what() is a one-line message for stderr
/// (without the "m3g: " prefix). Exit code 2.
class CliError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// An input that cannot be read or loaded; what() names the path once.
/// Exit code 3.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// An output that cannot be written; what() names the path. Exit code 4.
class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Rendering failed (or no device). Exit code 5.
class RenderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace m3gcli
