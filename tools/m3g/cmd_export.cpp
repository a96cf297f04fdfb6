// m3g export: load an .m3g file, animate it to a world time, write glTF 2.0
// (.glb or .gltf). The mapping is in docs/export.md.
#include <climits>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <m3g/m3g.h>

#include "CliArgs.h"
#include "Commands.h"
#include "ExportRun.h"
#include "GltfExport.h"
#include "InputFile.h"
#include "UpAxis.h"

namespace m3gcli {

namespace {

struct ExportArgs {
    std::string file, output, time, up;
    bool lenient = false, separateBin = false, quiet = false;
};

}  // namespace

bool isGltfPath(const std::string& path) {
    // Case as gltf::writeExport tells them apart.
    return path.ends_with(".glb") || path.ends_with(".gltf");
}

void exportToGltf(const m3g::LoadResult& loaded, const std::string& output, int time, bool separateBin, bool quiet,
                  const gltf::ExportOptions& options) {
    if (!isGltfPath(output)) throw CliError("the output must end in .glb or .gltf, not '" + output + "'");
    if (separateBin && !output.ends_with(".gltf")) throw CliError("--separate-bin applies to .gltf output only");
    std::vector<m3g::Object3D*> roots;
    for (const auto& r : loaded.roots) roots.push_back(r.get());
    // The static pose is the one M3G shows at --time (as `m3g render`).
    for (m3g::Object3D* r : roots) {
        try {
            r->animate(time);
        } catch (const m3g::Exception& e) {
            std::fprintf(stderr, "m3g export: warning: animate(%d) failed, exporting the stored pose: %s\n", time,
                         e.what());
        }
    }
    const gltf::ExportResult result = gltf::exportScene(roots, options);
    if (!quiet)
        for (const auto& w : result.warnings) std::fprintf(stderr, "m3g export: %s\n", w.c_str());
    try {
        gltf::writeExport(result, output, separateBin);
    } catch (const std::runtime_error& e) {
        throw OutputError(e.what());
    }
    if (!quiet) std::fprintf(stderr, "m3g: wrote %s\n", output.c_str());
}

void addExportCommand(CLI::App& parent, CommandTable& table) {
    CLI::App* app = addCommandApp(parent, "export",
                                  "glTF 2.0 export of the scene posed at --time, with its animations (docs/export.md)");
    auto args = std::make_shared<ExportArgs>();
    app->add_option("file", args->file, "the .m3g file to export")->type_name("FILE")->required();
    app->add_option("-o,--output", args->output, "the glTF file: .glb (binary) or .gltf (JSON)")
        ->type_name("OUT.glb|OUT.gltf")
        ->required();
    app->add_option("--time", args->time, "world time of the static pose in ms (default 0)")->type_name("MS");
    app->add_flag("--lenient", args->lenient, "accept the exporter faults seen in real files (LoaderOptions.lenient)");
    app->add_flag("--separate-bin", args->separateBin, ".gltf: write the buffer to OUT.bin beside it, not a data: URI");
    app->add_flag("-q,--quiet", args->quiet, "print no warnings");
    app->add_option("--up", args->up, "the scene's up axis, turned to glTF's +Y: auto (the active camera's up, "
                                      "default) or +X, -X, +Y, -Y, +Z, -Z")
        ->type_name("AXIS");
    table[app] = [args] {
        const int time = args->time.empty() ? 0 : parseIntOption("--time", args->time, INT_MIN, "an integer number of milliseconds");
        if (!isGltfPath(args->output)) throw CliError("the output must end in .glb or .gltf, not '" + args->output + "'");
        gltf::ExportOptions options;
        options.up = parseUpOption(args->up);
        const m3g::LoadResult loaded = loadInput(args->file, args->lenient);
        for (const auto& w : loaded.warnings) std::fprintf(stderr, "m3g export: warning: %s\n", w.c_str());
        exportToGltf(loaded, args->output, time, args->separateBin, args->quiet, options);
        return int(kExitOk);
    };
}

}  // namespace m3gcli
