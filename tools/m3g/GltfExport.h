// `m3g export`: an M3G scene graph as a glTF 2.0 document (node hierarchy,
// meshes, materials and PNG textures, cameras, KHR_lights_punctual lights,
// skins, morph targets, animations). The mapping and what it approximates
// are described in docs/export.md. Part of the m3g tool (tools/m3g/), built
// on the public API plus the keyframe sampler of scene/.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "GltfDocument.h"
#include "UpAxis.h"

namespace m3g {
class Object3D;
}

namespace m3gcli::gltf {

struct ExportResult {
    Document document;
    /// What was dropped or approximated, one line per kind (with counts).
    std::vector<std::string> warnings;
};

struct ExportOptions {
    /// The scene's up axis; nullopt: each World's own (UpAxis.h, the active
    /// camera's up). glTF is +Y up: a scene whose up is another axis is
    /// placed under a root node that turns it upright.
    std::optional<Axis> up;
};

/// Exports the scene reachable from `roots` (a Loader result): every World
/// becomes a glTF scene (the World's own transform is not applied, as in
/// M3G rendering; an active camera outside it is added as a root), root
/// nodes outside any World a further scene. Object state is taken as it is
/// now (animate() the roots first for a given time).
ExportResult exportScene(std::span<m3g::Object3D* const> roots, const ExportOptions& options = {});

/// Writes `result` to `path`: .glb (binary container) or .gltf (JSON; the
/// buffer as a data: URI, or with `separateBin` in PATH-without-extension.bin
/// next to it). Throws std::runtime_error on another extension or a write
/// failure, naming the file.
void writeExport(const ExportResult& result, const std::string& path, bool separateBin);

}  // namespace m3gcli::gltf
