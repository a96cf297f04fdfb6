// The m3g tool's command line on CLI11: the root App (help, --version, the
// exit-code table), the table of commands and what runs each, and the one
// place that turns a parse error or a command's exception into a message and
// an exit code (CliErrors.h). Part of m3g_cli_support.
#pragma once

#include <functional>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "CliErrors.h"

namespace m3gcli {

/// What runs a command once its options are parsed: returns the exit code,
/// or throws CliError / InputError / OutputError / RenderError (or
/// m3g::vk::VulkanError, taken as RenderError).
using CommandRun = std::function<int()>;

/// Each command's App (a subcommand of the root, or of `bench`) and what runs it.
using CommandTable = std::map<const CLI::App*, CommandRun>;

/// Adds one command (its App with every option described, and its CommandRun).
using CommandAdder = void (*)(CLI::App& parent, CommandTable& table);

/// Sets up the root App "m3g": description, --version, the exit-code
/// footer, at most one command.
void configureRoot(CLI::App& root);

/// Adds `help [COMMAND...]` (the usage of m3g or of a command) and `version`
/// (as --version), last in the usage.
void addHelpCommands(CLI::App& root, CommandTable& table);

/// Adds a command's App to `parent` with the settings every command shares
/// (the exit-code footer, at most one subcommand of its own).
CLI::App* addCommandApp(CLI::App& parent, const std::string& name, const std::string& description);

/// Parses `args` (without the program name) into `app`. A parse error
/// becomes a CliError whose message names what was wrong, with a
/// did-you-mean suggestion for an unknown option or command; --help and
/// --version pass through as CLI11's CallForHelp / CallForVersion.
void parseArgs(CLI::App& app, const std::vector<std::string>& args);

/// Parses and runs: --help / `help CMD` print that command's usage on
/// stdout (0), --version the version (0), a usage error its message and a
/// pointer to --help on stderr (2); otherwise the selected command's
/// CommandRun, its exceptions printed on stderr with their exit code.
int runCommandLine(CLI::App& root, const CommandTable& table, const std::vector<std::string>& args);

/// A command line of one command alone ("m3g NAME args..."), as the tests
/// run `m3g render` in-process.
int runOneCommand(CommandAdder add, const std::string& name, std::span<const std::string_view> args);

/// The exit code of the exception being handled (call inside a catch block),
/// after printing it on stderr prefixed with `where` ("m3g render").
int reportFailure(const std::string& where);

}  // namespace m3gcli
