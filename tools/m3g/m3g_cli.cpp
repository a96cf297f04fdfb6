// The m3g command-line tool.
//   m3g info                      library version and Graphics3D::getProperties()
//   m3g info FILE [--json] [--lenient] [--time T]
//                                 header, object counts, scene tree, warnings;
//                                 --json dumps every object's getter values
//   m3g convert IN OUT [--compress] [--lenient]
//                                 load and re-save as M3G 1.0
//   m3g render FILE -o OUT.png [--size WxH] [--time MS] [--align] [--lenient]
//                                 render the World (auto-framed if it has no
//                                 camera) to a PNG; -o - writes to stdout;
//                                 [--frames N --fps F] [--turntable N]
//                                 [--camera-index I] [--background RRGGBBAA]
//                                 [--reference REF.png --threshold T]
//   m3g render DIR|GAME.jar -o OUTDIR  every M3G file of a folder or .jar
//   m3g compare A.png B.png [--threshold N] [--max-share S] [--min-psnr DB] [--diff OUT.png]
//                                 share of pixels off by more than N, PSNR;
//                                 exit status 0 = within the limits
//   m3g sample -o OUT.m3g         write the project's sample scene
//   m3g export FILE -o OUT.glb|OUT.gltf [--time MS] [--lenient] [--separate-bin] [--quiet]
//                                 glTF 2.0 export (docs/export.md)
//   m3g pick FILE X Y [--time T] [--json] [--lenient]
//                                 pick through the World's active camera
//   m3g bench render FILE... [--size WxH] [--frames N]
//                                 rendering speed (first frame, fps, CPU per draw)
//   m3g bench soak FILE [--frames N] [--reload K] [--size WxH] [--report R]
//                                 memory over a long run with reloads (verdict)
//   m3g version
//   m3g bench skin|morph [...]  kernel benchmarks (tools/m3g/cmd_bench.cpp)
// Exit status: 0 success, 1 load/save failure (the IOException message on
// stderr), 2 bad command line.
#include <cstdio>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include <m3g/m3g.h>
#include <m3g/vk/Vulkan.h>

#include "CliArgs.h"
#include "Commands.h"
#include "ObjectDump.h"
#include "cmd_bench.h"
#include "cmd_pick.h"

namespace {

int libraryInfo() {
    std::printf("m3g-vk %s: M3G 1.1 (JSR-184) object model\n", m3g::kVersionString);
    std::printf("Graphics3D.getProperties():\n");
    for (const auto& [key, value] : m3g::Graphics3D::getProperties()) {
        std::visit(
            [&](const auto& v) {
                using T = std::decay_t<decltype(v)>;
                if constexpr (std::is_same_v<T, bool>)
                    std::printf("  %-30s %s\n", key.c_str(), v ? "true" : "false");
                else if constexpr (std::is_same_v<T, int>)
                    std::printf("  %-30s %d\n", key.c_str(), v);
                else
                    std::printf("  %-30s %s\n", key.c_str(), v.c_str());
            },
            value);
    }
    // The Vulkan devices and the one Graphics3D renders with (M3G_VK_DEVICE
    // chooses), or why there is none: the first thing to know when a render
    // is slow (lavapipe) or fails.
    try {
        const auto devices = m3g::vk::listDevices();
        const m3g::vk::DeviceInfo current = m3g::vk::currentDevice();
        std::printf("Vulkan devices:\n");
        for (const auto& d : devices)
            std::printf("  %s %s (%s, Vulkan %u.%u)\n", d.deviceID == current.deviceID && d.name == current.name ? "*" : " ",
                        d.name.c_str(), d.type.c_str(), d.apiVersion >> 22, (d.apiVersion >> 12) & 0x3FF);
        std::printf("renders with: %s (%s)\n", current.name.c_str(), current.type.c_str());
    } catch (const std::exception& e) {
        std::printf("Vulkan: no device (%s)\n", e.what());
    }
    return 0;
}

std::vector<m3g::Object3D*> rawRoots(const std::vector<m3g::Ref<m3g::Object3D>>& roots) {
    std::vector<m3g::Object3D*> out;
    for (const auto& r : roots) out.push_back(r.get());
    return out;
}

int fileInfo(const m3gcli::CliArgs& args) {
    const std::string& file = args.files[0];
    m3g::LoaderOptions options;
    options.lenient = args.lenient;
    const m3g::LoadResult result = m3g::Loader::loadDetailed(file, options);
    if (args.time) {
        for (const auto& r : result.roots) r->animate(*args.time);
    }
    const auto roots = rawRoots(result.roots);
    if (args.json) {
        m3gcli::DumpOptions dump;
        dump.worldTime = args.time;
        std::printf("%s\n", m3gcli::dumpJson(roots, dump).c_str());
        return 0;
    }
    std::printf("file: %s\n", file.c_str());
    if (result.versionMajor || result.versionMinor || result.totalFileSize) {
        std::printf("version: %d.%d\n", result.versionMajor, result.versionMinor);
        std::printf("authoring field: %s\n", result.authoringField.c_str());
        std::printf("total file size: %u bytes\n", static_cast<unsigned>(result.totalFileSize));
        std::printf("approximate content size: %u bytes\n", static_cast<unsigned>(result.approximateContentSize));
        std::printf("external references: %s\n", result.hasExternalReferences ? "yes" : "no");
    } else {
        std::printf("format: image (PNG or JPEG)\n");
    }
    std::printf("objects: %zu loaded, %zu roots\n", result.objects.size(), result.roots.size());
    for (const auto& [cls, n] : m3gcli::countByClass(roots)) std::printf("  %-22s %d\n", cls.c_str(), n);
    if (args.time) std::printf("animated to world time %d ms\n", *args.time);
    std::printf("scene:\n%s", m3gcli::dumpTree(roots).c_str());
    if (!result.warnings.empty()) {
        std::printf("warnings (%zu):\n", result.warnings.size());
        for (const auto& w : result.warnings) std::printf("  %s\n", w.c_str());
    }
    return 0;
}

int convert(const m3gcli::CliArgs& args) {
    m3g::LoaderOptions options;
    options.lenient = args.lenient;
    const m3g::LoadResult result = m3g::Loader::loadDetailed(args.files[0], options);
    for (const auto& w : result.warnings) std::fprintf(stderr, "m3g: warning: %s\n", w.c_str());
    m3g::SaverOptions saveOptions;
    saveOptions.compress = args.compress;
    const auto roots = rawRoots(result.roots);
    m3g::Saver::save(args.files[1], roots, saveOptions);
    std::printf("wrote %s: %zu root objects%s\n", args.files[1].c_str(), roots.size(),
                args.compress ? " (zlib)" : "");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    // Subcommands with their own option parsing.
    if (argc >= 2) {
        const std::string_view command = argv[1];
        std::vector<std::string_view> rest(argv + 2, argv + argc);
        if (command == "render") return m3gcli::cmdRender(rest);
        if (command == "compare") return m3gcli::cmdCompare(rest);
        if (command == "sample") return m3gcli::cmdSample(rest);
        if (command == "view") return m3gcli::cmdView(rest);
        if (command == "export") return m3gcli::cmdExport(rest);
        if (command == "bench" && !rest.empty() && rest[0] == "render")
            return m3gcli::cmdBenchRender(std::span<const std::string_view>(rest).subspan(1));
        if (command == "bench" && !rest.empty() && rest[0] == "soak")
            return m3gcli::cmdBenchSoak(std::span<const std::string_view>(rest).subspan(1));
        if (command == "bench") return m3gcli::benchCommand(argc - 2, argv + 2);
    }
    m3gcli::CliArgs args;
    try {
        args = m3gcli::parseCliArgs(argc, argv);
    } catch (const m3gcli::CliError& e) {
        std::fprintf(stderr, "m3g: %s\n%s", e.what(), m3gcli::usageText().c_str());
        return 2;
    }
    try {
        if (args.command == "help") {
            std::printf("%s", m3gcli::usageText().c_str());
            return 0;
        }
        if (args.command == "version") {
            std::printf("%s\n", m3g::kVersionString);
            return 0;
        }
        if (args.command == "info") return args.files.empty() ? libraryInfo() : fileInfo(args);
        if (args.command == "convert") return convert(args);
        if (args.command == "pick") return m3gcli::runPick(args);
    } catch (const m3g::Exception& e) {
        std::fprintf(stderr, "m3g: %s\n", e.what());
        return 1;
    }
    std::fprintf(stderr, "m3g: unknown command '%s'\n%s", args.command.c_str(), m3gcli::usageText().c_str());
    return 2;
}
