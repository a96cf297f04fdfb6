// The rendering step shared by `m3g render` on one file and its batch mode:
// a loaded file, the options, and the PNG files written. Part of
// m3g_cli_support (the CLI tests call it through cmdRender).
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include <m3g/m3g.h>

#include "ImageIO.h"
#include "RenderOptions.h"

namespace m3gcli {

/// Prepares the World of `loaded` (SceneSetup), applies --camera-index and
/// --background, renders imageCount() images (animation frames at
/// time + round(k * 1000 / fps), turntable steps of 360/N degrees, or one
/// image at --time) and writes each to frameFileName(output, k, n), or to
/// `output` itself for a single image ("-" is stdout), as PNG or JPEG by the
/// extension (ImageIO.h, writeImage). RGBA PNGs with --background, RGB
/// otherwise. Notes, and a hint when an image is uniform, go to `log` when
/// it is not null. Returns the last image rendered. Throws CliError for a
/// --camera-index the file lacks, RenderError (or m3g::vk::VulkanError) when
/// rendering fails, OutputError when an image cannot be written.
RgbaImage renderToFiles(const m3g::LoadResult& loaded, const RenderOptions& options, const std::string& output,
                        std::FILE* log);

/// Batch mode of `m3g render`: every .m3g in the folder (recursively, sorted)
/// or in the .jar `options.input`, written under the folder `options.output`
/// with the input's relative path and ".png" (frame numbers for sequences).
/// A progress bar on stderr when it is a terminal; a summary (ok / failed
/// with reasons) at the end. Returns 0 when every file rendered, otherwise
/// the exit code of the first failure (3 load, 4 write, 5 render). Throws
/// InputError when the folder or .jar cannot be read or holds no M3G data,
/// RenderError when there is no Vulkan device.
int renderBatch(const RenderOptions& options);

}  // namespace m3gcli
