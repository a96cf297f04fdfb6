// The command line of `m3g render` (single image, animation sequence,
// turntable, reference comparison, batch over a folder or a .jar), and the
// output naming of frame sequences. Part of m3g_cli_support.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "CliApp.h"

namespace m3gcli {

struct RenderOptions {
    std::string input;    ///< an .m3g/.png file, a folder, or a .jar (batch)
    std::string output;   ///< -o: PNG, frame pattern, or output folder (batch)
    int width = 320, height = 240;
    int time = 0;         ///< --time: world time of the (first) frame in ms
    bool align = false, lenient = false;
    int frames = 0;       ///< --frames N: an animation sequence of N frames (0: one image)
    float fps = 30.0f;    ///< --fps F: frame k is at time + round(k * 1000 / F)
    int turntable = 0;    ///< --turntable N: N frames orbiting the bounds centre (0: off)
    /// --up: the axis the turntable turns about; nullopt (auto): the scene's (UpAxis.h).
    std::optional<std::array<float, 3>> up;
    std::optional<int> cameraIndex;            ///< --camera-index I (0-based, file order)
    std::optional<std::uint32_t> background;   ///< --background, as 0xAARRGGBB
    std::string reference;                     ///< --reference REF.png
    int threshold = 8;                         ///< --threshold (with --reference)
    double maxShare = 0.01;                    ///< --max-share (with --reference)
    double minPsnr = 0.0;                      ///< --min-psnr (with --reference)

    /// Number of images per input: frames, turntable or 1.
    int imageCount() const { return frames > 0 ? frames : turntable > 0 ? turntable : 1; }
    bool sequence() const { return frames > 0 || turntable > 0; }
};

/// The command line of `m3g render` as given: CLI11 fills it,
/// finishRenderOptions says what it means. An empty value: not given.
struct RenderFlags {
    std::string input, output, size, time, frames, fps, turntable, up, cameraIndex, background, reference, threshold,
        maxShare, minPsnr;
    bool align = false, lenient = false;
};

/// Adds INPUT and every option of `m3g render`, described, to `app`.
void addRenderOptions(CLI::App& app, RenderFlags& flags);

/// The options `flags` stand for. Throws CliError for a malformed value, a
/// --size beyond the renderer's limits (CliArgs.h, parseSizeOption),
/// --frames together with --turntable, --reference with a sequence, or a
/// sequence to stdout. `output` stays empty without -o (cmdRender decides:
/// batch and single images need it, a sequence writes "out_{frame}.png").
RenderOptions finishRenderOptions(const RenderFlags& flags);

/// Parses the arguments after "render" (addRenderOptions, parseArgs,
/// finishRenderOptions); throws CliError for an unknown option too.
RenderOptions parseRenderOptions(std::span<const std::string_view> args);

/// "RRGGBBAA" (hex, any case) or "transparent" as 0xAARRGGBB; nullopt otherwise.
std::optional<std::uint32_t> parseBackgroundColor(std::string_view text);

/// The file name of frame `frame` of `count`: "{frame}" in `pattern` is
/// replaced by the frame number zero-padded to at least 4 digits (more when
/// count - 1 needs them); a pattern without "{frame}" gets "_{frame}" before
/// its extension ("shot.png" -> "shot_0003.png").
std::string frameFileName(const std::string& pattern, int frame, int count);

}  // namespace m3gcli
