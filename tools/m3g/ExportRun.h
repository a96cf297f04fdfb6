// The glTF step shared by `m3g export` and `m3g convert IN OUT.glb|.gltf`
// (defined in cmd_export.cpp): pose the loaded scene, export, write.
#pragma once

#include "GltfExport.h"

#include <string>

#include <m3g/Loader.h>

namespace m3gcli {

/// Whether `path` names a glTF output (.glb or .gltf, as gltf::writeExport
/// tells them).
bool isGltfPath(const std::string& path);

/// Animates the roots of `loaded` to `time` (a failure is a warning: the
/// stored pose is exported), exports them (docs/export.md) and writes
/// `output` (.glb or .gltf; `separateBin`: the buffer beside a .gltf).
/// Warnings go to stderr unless `quiet`. Throws CliError for --separate-bin
/// with .glb, OutputError when the file cannot be written.
void exportToGltf(const m3g::LoadResult& loaded, const std::string& output, int time, bool separateBin, bool quiet,
                  const gltf::ExportOptions& options = {});

}  // namespace m3gcli
