// The commands of the m3g tool. Each adds its CLI11 App (every option
// described, for --help) to a parent and what runs it to the table
// (CliApp.h); the runs throw the errors of CliErrors.h, which give the exit
// code. m3g_cli.cpp puts them together.
#pragma once

#include <span>
#include <string_view>

#include "CliApp.h"

namespace m3gcli {

/// m3g info [FILE] [--json] [--lenient] [--time T] (cmd_info.cpp)
void addInfoCommand(CLI::App& parent, CommandTable& table);
/// m3g convert IN OUT [--compress] [--lenient]: the format by OUT's extension (cmd_convert.cpp)
void addConvertCommand(CLI::App& parent, CommandTable& table);
/// m3g pick FILE X Y [--time T] [--json] [--lenient] (cmd_pick.cpp)
void addPickCommand(CLI::App& parent, CommandTable& table);
/// m3g render FILE|DIR|GAME.jar -o OUT [options of RenderOptions.h] (cmd_render.cpp)
void addRenderCommand(CLI::App& parent, CommandTable& table);
/// m3g compare A.png B.png [--threshold N] [--max-share S] [--min-psnr DB] [--diff OUT] (cmd_compare.cpp)
void addCompareCommand(CLI::App& parent, CommandTable& table);
/// m3g sample -o OUT.m3g (cmd_sample.cpp)
void addSampleCommand(CLI::App& parent, CommandTable& table);
/// m3g export FILE -o OUT.glb|OUT.gltf [--time MS] [--lenient] [--separate-bin] [--quiet] (cmd_export.cpp)
void addExportCommand(CLI::App& parent, CommandTable& table);
/// m3g view [FILE] [options] (viewer/cmd_view.cpp; without GLFW and ImGui
/// at build time, viewer/cmd_view_missing.cpp says what to install)
void addViewCommand(CLI::App& parent, CommandTable& table);
/// m3g bench render|skin|morph|soak (cmd_bench.cpp adds the group and
/// skin/morph; cmd_bench_render.cpp and cmd_bench_soak.cpp the others)
void addBenchCommand(CLI::App& parent, CommandTable& table);
void addBenchRenderCommand(CLI::App& bench, CommandTable& table);
void addBenchSoakCommand(CLI::App& bench, CommandTable& table);

/// `m3g render ARGS...` in-process, as the tool runs it: the exit code
/// (CliErrors.h), messages on stderr.
int cmdRender(std::span<const std::string_view> args);

}  // namespace m3gcli
