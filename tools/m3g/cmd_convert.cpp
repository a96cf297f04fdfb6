// m3g convert IN OUT: load IN and write OUT in the format its extension
// names. .m3g: the Saver (M3G 1.0, zlib sections with --compress).
// .glb/.gltf: the glTF export of `m3g export` at world time 0, because a
// user who names a .glb wants a .glb, and `export` is the same code with its
// extra options (--time, --separate-bin); writing M3G bytes under a glTF
// name would hand a broken file to the next program. Other extensions are
// refused before anything is loaded.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <m3g/m3g.h>

#include "CliArgs.h"
#include "Commands.h"
#include "ExportRun.h"
#include "InputFile.h"

namespace m3gcli {

namespace {

struct ConvertArgs {
    std::string input, output;
    bool compress = false, lenient = false;
};

int convert(const ConvertArgs& args) {
    const bool gltf = isGltfPath(args.output);
    if (!gltf && lowerExtension(args.output) != ".m3g")
        throw CliError("cannot tell the output format of '" + args.output + "': name it .m3g (M3G), .glb or .gltf (glTF)");
    if (gltf && args.compress) throw CliError("--compress applies to .m3g output only");
    const m3g::LoadResult result = loadInput(args.input, args.lenient);
    for (const auto& w : result.warnings) std::fprintf(stderr, "m3g convert: warning: %s\n", w.c_str());
    if (gltf) {
        exportToGltf(result, args.output, 0, false, false);
        return kExitOk;
    }
    std::vector<m3g::Object3D*> roots;
    for (const auto& r : result.roots) roots.push_back(r.get());
    m3g::SaverOptions saveOptions;
    saveOptions.compress = args.compress;
    try {
        m3g::Saver::save(args.output, roots, saveOptions);
    } catch (const m3g::IOException& e) {
        throw OutputError(e.what());
    }
    std::printf("wrote %s: %zu root objects%s\n", args.output.c_str(), roots.size(), args.compress ? " (zlib)" : "");
    return kExitOk;
}

}  // namespace

void addConvertCommand(CLI::App& parent, CommandTable& table) {
    CLI::App* app = addCommandApp(parent, "convert",
                                  "load IN and write OUT as its extension says: .m3g, or .glb/.gltf (as export)");
    auto args = std::make_shared<ConvertArgs>();
    app->add_option("input", args->input, "the file to load (.m3g, PNG or JPEG)")->type_name("IN")->required();
    app->add_option("output", args->output, "the file to write: .m3g, .glb or .gltf")->type_name("OUT")->required();
    app->add_flag("--compress", args->compress, "zlib-compress the M3G sections (.m3g output)");
    app->add_flag("--lenient", args->lenient, "accept the exporter faults seen in real files (LoaderOptions.lenient)");
    table[app] = [args] { return convert(*args); };
}

}  // namespace m3gcli
