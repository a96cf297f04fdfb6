// Subcommands of the m3g tool that parse their own options. Each returns
// the exit status: 0 success, 1 failure (message on stderr), 2 bad usage.
#pragma once

#include <span>
#include <string_view>

namespace m3gcli {

/// m3g render FILE|DIR|GAME.jar -o OUT [--size WxH] [--time MS] [--align] [--lenient]
///   [--frames N --fps F | --turntable N] [--camera-index I] [--background RRGGBBAA|transparent]
///   [--reference REF.png [--threshold T] [--max-share S] [--min-psnr DB]]
/// (options: RenderOptions.h). With --reference the status is the verdict:
/// 0 within the limits, 1 not (or any failure).
int cmdRender(std::span<const std::string_view> args);
/// m3g compare A.png B.png [--threshold N] [--max-share S] [--min-psnr DB] [--diff OUT.png]
int cmdCompare(std::span<const std::string_view> args);

/// m3g bench render FILE... [--size WxH] [--frames N]
int cmdBenchRender(std::span<const std::string_view> args);
/// m3g bench soak FILE [--frames N] [--reload K] [--size WxH] [--report R] [--warmup C]
int cmdBenchSoak(std::span<const std::string_view> args);
/// m3g sample -o OUT.m3g: writes the project's sample scene.
int cmdSample(std::span<const std::string_view> args);
/// m3g view (tools/m3g/viewer/); without GLFW and ImGui at build time it
/// says what to install.
int cmdView(std::span<const std::string_view> args);
/// m3g export FILE -o OUT.glb|OUT.gltf [--time MS] [--lenient] [--separate-bin] [--quiet]
int cmdExport(std::span<const std::string_view> args);

}  // namespace m3gcli
