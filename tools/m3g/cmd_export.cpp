// m3g export: load an .m3g file, animate it to a world time, write glTF 2.0
// (.glb or .gltf). The mapping is in docs/export.md.
#include <cstdio>
#include <string>
#include <vector>

#include <m3g/m3g.h>

#include "CliArgs.h"
#include "Commands.h"
#include "GltfExport.h"

namespace m3gcli {

namespace {

struct ExportArgs {
    std::string file, output;
    int time = 0;
    bool lenient = false, separateBin = false, quiet = false;
};

ExportArgs parse(std::span<const std::string_view> args) {
    ExportArgs r;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view a = args[i];
        auto value = [&](const char* name) -> std::string_view {
            if (i + 1 >= args.size()) throw CliError(std::string("export: ") + name + " needs a value");
            return args[++i];
        };
        if (a == "-o" || a == "--output") r.output = value("-o");
        else if (a == "--time") {
            auto t = parseInt(value("--time"));
            if (!t) throw CliError("export: --time takes an integer number of milliseconds");
            r.time = *t;
        } else if (a == "--lenient") r.lenient = true;
        else if (a == "--separate-bin") r.separateBin = true;
        else if (a == "--quiet" || a == "-q") r.quiet = true;
        else if (!a.empty() && a[0] == '-') throw CliError("export: unknown option " + std::string(a));
        else if (r.file.empty()) r.file = a;
        else throw CliError("export: unexpected operand " + std::string(a));
    }
    if (r.file.empty()) throw CliError("export: no input file");
    if (r.output.empty()) throw CliError("export: no output (-o OUT.glb or -o OUT.gltf)");
    return r;
}

}  // namespace

int cmdExport(std::span<const std::string_view> argv) {
    ExportArgs args;
    try {
        args = parse(argv);
    } catch (const CliError& e) {
        std::fprintf(stderr, "m3g: %s\n", e.what());
        return 2;
    }
    try {
        m3g::LoaderOptions options;
        options.lenient = args.lenient;
        const m3g::LoadResult loaded = m3g::Loader::loadDetailed(args.file, options);
        for (const auto& w : loaded.warnings) std::fprintf(stderr, "m3g: warning: %s\n", w.c_str());
        std::vector<m3g::Object3D*> roots;
        for (const auto& r : loaded.roots) roots.push_back(r.get());
        // The static pose is the one M3G shows at --time (as `m3g render`).
        for (m3g::Object3D* r : roots) {
            try {
                r->animate(args.time);
            } catch (const m3g::Exception& e) {
                std::fprintf(stderr, "m3g: warning: animate(%d) failed, exporting the stored pose: %s\n", args.time,
                             e.what());
            }
        }
        const gltf::ExportResult result = gltf::exportScene(roots);
        if (!args.quiet)
            for (const auto& w : result.warnings) std::fprintf(stderr, "m3g: export: %s\n", w.c_str());
        gltf::writeExport(result, args.output, args.separateBin);
        if (!args.quiet) std::fprintf(stderr, "m3g: wrote %s\n", args.output.c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "m3g: %s: %s\n", args.file.c_str(), e.what());
        return 1;
    }
}

}  // namespace m3gcli
