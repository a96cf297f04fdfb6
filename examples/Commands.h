// Subcommands of the m3g tool that parse their own options. Each returns
// the exit status: 0 success, 1 failure (message on stderr), 2 bad usage.
#pragma once

#include <span>
#include <string_view>

namespace m3gcli {

/// m3g render FILE -o OUT.png [--size WxH] [--time MS] [--align] [--lenient]
int cmdRender(std::span<const std::string_view> args);
/// m3g compare A.png B.png [--threshold N] [--max-share S] [--min-psnr DB] [--diff OUT.png]
int cmdCompare(std::span<const std::string_view> args);

/// m3g bench render FILE... [--size WxH] [--frames N]
int cmdBenchRender(std::span<const std::string_view> args);
/// m3g bench soak FILE [--frames N] [--reload K] [--size WxH] [--report R] [--warmup C]
int cmdBenchSoak(std::span<const std::string_view> args);
/// m3g sample -o OUT.m3g: writes the project's sample scene.
int cmdSample(std::span<const std::string_view> args);

}  // namespace m3gcli
