// m3g info: without FILE, the library version, Graphics3D::getProperties()
// and the Vulkan devices; with FILE, its header, object counts, scene tree
// and warnings, or (--json) every object's getter values.
#include <climits>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include <m3g/m3g.h>
#include <m3g/vk/Vulkan.h>

#include "CliArgs.h"
#include "Commands.h"
#include "InputFile.h"
#include "ObjectDump.h"

namespace m3gcli {

namespace {

struct InfoArgs {
    std::string file, time;
    bool json = false, lenient = false;
};

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
    return kExitOk;
}

std::vector<m3g::Object3D*> rawRoots(const std::vector<m3g::Ref<m3g::Object3D>>& roots) {
    std::vector<m3g::Object3D*> out;
    for (const auto& r : roots) out.push_back(r.get());
    return out;
}

int fileInfo(const InfoArgs& args) {
    std::optional<int> time;
    if (!args.time.empty()) time = parseIntOption("--time", args.time, INT_MIN, "an integer (world time in ms)");
    const m3g::LoadResult result = loadInput(args.file, args.lenient);
    try {
        if (time)
            for (const auto& r : result.roots) r->animate(*time);
    } catch (const m3g::Exception& e) {
        throw InputError(withPath(args.file, std::string("animate: ") + e.what()));
    }
    const auto roots = rawRoots(result.roots);
    if (args.json) {
        DumpOptions dump;
        dump.worldTime = time;
        dump.load = &result;
        std::printf("%s\n", dumpJson(roots, dump).c_str());
        return kExitOk;
    }
    std::printf("file: %s\n", args.file.c_str());
    if (result.versionMajor || result.versionMinor || result.totalFileSize) {
        std::printf("version: %d.%d\n", result.versionMajor, result.versionMinor);
        std::printf("authoring field: %s\n", result.authoringField.c_str());
        std::printf("total file size: %u bytes\n", static_cast<unsigned>(result.totalFileSize));
        std::printf("approximate content size: %u bytes\n", static_cast<unsigned>(result.approximateContentSize));
        std::printf("external references: %s\n", result.hasExternalReferences ? "yes" : "no");
        for (const m3g::ExternalReference& e : result.externalReferences)
            std::printf("  %s -> %s%s\n", e.uri.c_str(), e.path.c_str(), e.loaded ? "" : " (missing: skipped)");
    } else {
        std::printf("format: image (PNG or JPEG)\n");
    }
    std::printf("objects: %zu loaded, %zu roots\n", result.objects.size(), result.roots.size());
    for (const auto& [cls, n] : countByClass(roots)) std::printf("  %-22s %d\n", cls.c_str(), n);
    if (time) std::printf("animated to world time %d ms\n", *time);
    std::printf("scene:\n%s", dumpTree(roots).c_str());
    if (!result.warnings.empty()) {
        std::printf("warnings (%zu):\n", result.warnings.size());
        for (const auto& w : result.warnings) std::printf("  %s\n", w.c_str());
    }
    return kExitOk;
}

}  // namespace

void addInfoCommand(CLI::App& parent, CommandTable& table) {
    CLI::App* app = addCommandApp(parent, "info",
                                  "a file's header, objects, scene tree and warnings; without FILE the library, its "
                                  "limits and the Vulkan devices");
    auto args = std::make_shared<InfoArgs>();
    app->add_option("file", args->file, "an .m3g, PNG or JPEG file")->type_name("FILE");
    app->add_flag("--json", args->json, "dump every object's properties (getter values) as JSON");
    app->add_flag("--lenient", args->lenient, "accept the exporter faults seen in real files (LoaderOptions.lenient)");
    app->add_option("--time", args->time, "animate the roots to world time T (ms) first")->type_name("T");
    table[app] = [args] { return args->file.empty() ? libraryInfo() : fileInfo(*args); };
}

}  // namespace m3gcli
