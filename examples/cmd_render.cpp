// m3g render: load, animate, optionally align, render the World to a PNG
// (with the auto-framing and camera fix-up of ../shared/corpus/REFERENCE.md).
#include <cstdio>
#include <optional>
#include <string>

#include <m3g/m3g.h>
#include <m3g/vk/Vulkan.h>

#include "CliArgs.h"
#include "Commands.h"
#include "ImageIO.h"
#include "SceneSetup.h"

namespace m3gcli {

namespace {

struct RenderArgs {
    std::string file, output;
    int width = 320, height = 240;
    int time = 0;
    bool align = false, lenient = false;
};

bool parseSize(std::string_view text, int& w, int& h) {
    const auto x = text.find('x');
    if (x == std::string_view::npos) return false;
    auto a = parseInt(text.substr(0, x)), b = parseInt(text.substr(x + 1));
    if (!a || !b || *a <= 0 || *b <= 0) return false;
    w = *a;
    h = *b;
    return true;
}

RenderArgs parse(std::span<const std::string_view> args) {
    RenderArgs r;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view a = args[i];
        auto value = [&](const char* name) -> std::string_view {
            if (i + 1 >= args.size()) throw CliError(std::string("render: ") + name + " needs a value");
            return args[++i];
        };
        if (a == "-o" || a == "--output") r.output = value("-o");
        else if (a == "--size") {
            if (!parseSize(value("--size"), r.width, r.height)) throw CliError("render: --size takes WxH, e.g. 320x240");
        } else if (a == "--time") {
            auto t = parseInt(value("--time"));
            if (!t) throw CliError("render: --time takes an integer number of milliseconds");
            r.time = *t;
        } else if (a == "--align") r.align = true;
        else if (a == "--lenient") r.lenient = true;
        else if (!a.empty() && a[0] == '-' && a != "-") throw CliError("render: unknown option " + std::string(a));
        else if (r.file.empty()) r.file = a;
        else throw CliError("render: unexpected operand " + std::string(a));
    }
    if (r.file.empty()) throw CliError("render: no input file");
    if (r.output.empty()) throw CliError("render: no output (-o OUT.png, or -o - for stdout)");
    return r;
}

}  // namespace

int cmdRender(std::span<const std::string_view> argv) {
    RenderArgs args;
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
        PreparedScene scene = prepareScene(loaded, args.width, args.height);
        for (const auto& n : scene.notes) std::fprintf(stderr, "m3g: %s\n", n.c_str());
        scene.world->animate(args.time);
        if (args.align) scene.world->align(nullptr);

        // A Graphics surface, as a MIDlet renders (and as the reference images
        // were made): background images must then be RGB.
        m3g::Ref<m3g::Graphics> target(new m3g::Graphics(args.width, args.height));
        m3g::Graphics3D* g = m3g::Graphics3D::getInstance();
        g->bindTarget(target.get(), true, 0);
        try {
            g->setViewport(0, 0, args.width, args.height);
            g->render(scene.world.get());
        } catch (...) {
            g->releaseTarget();
            throw;
        }
        g->releaseTarget();
        writePng(args.output, fromGraphics(*target), false);
        if (args.output != "-") std::fprintf(stderr, "m3g: wrote %s (%dx%d, t = %d ms)\n", args.output.c_str(), args.width, args.height, args.time);
        return 0;
    } catch (const m3g::vk::VulkanError& e) {
        std::fprintf(stderr, "m3g: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "m3g: %s: %s\n", args.file.c_str(), e.what());
        return 1;
    }
}

}  // namespace m3gcli
