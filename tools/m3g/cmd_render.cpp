// m3g render: load, animate, optionally align, render the World to PNGs
// (with the auto-framing and camera fix-up of ../shared/corpus/REFERENCE.md):
// one image, an animation sequence, a turntable, a comparison with a
// reference image, or a batch over a folder or a J2ME .jar.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include <m3g/m3g.h>
#include <m3g/vk/Vulkan.h>

#include "CliArgs.h"
#include "Commands.h"
#include "ImageIO.h"
#include "JarArchive.h"
#include "RenderRun.h"
#include "SceneRender.h"
#include "SceneSetup.h"

namespace m3gcli {

namespace fs = std::filesystem;

RgbaImage renderToFiles(const m3g::LoadResult& loaded, const RenderOptions& o, const std::string& output,
                        std::FILE* log) {
    PreparedScene scene = prepareScene(loaded, o.width, o.height);
    if (o.cameraIndex) useCamera(scene, loaded, *o.cameraIndex);
    if (log)
        for (const auto& n : scene.notes) std::fprintf(log, "m3g: %s\n", n.c_str());
    m3g::World& world = *scene.world;
    if (o.background) overrideBackground(world, *o.background);
    const bool keepAlpha = o.background.has_value();
    const int count = o.imageCount();

    std::optional<CameraOrbit> orbit;
    if (o.turntable > 0) {
        world.animate(o.time);
        if (o.align) world.align(nullptr);
        std::array<float, 3> center = scene.center;
        float radius = scene.radius;
        if (!scene.autoFramed) sceneBounds(world, center, radius);
        orbit.emplace(*world.getActiveCamera(), world, center);
    }
    RgbaImage image;
    for (int k = 0; k < count; ++k) {
        int time = o.time;
        if (orbit) {
            orbit->setAngle(360.0f * static_cast<float>(k) / static_cast<float>(count));
        } else {
            time = o.time + static_cast<int>(std::lround(static_cast<double>(k) * 1000.0 / o.fps));
            world.animate(time);
            if (o.align) world.align(nullptr);
        }
        image = renderWorldImage(world, o.width, o.height, keepAlpha);
        const std::string path = o.sequence() ? frameFileName(output, k, count) : output;
        if (path != "-") {
            const fs::path parent = fs::path(path).parent_path();
            if (!parent.empty()) fs::create_directories(parent);
        }
        writePng(path, image, keepAlpha);
        if (log && path != "-") {
            char orbitNote[48] = "";
            if (orbit) std::snprintf(orbitNote, sizeof orbitNote, ", orbit %.1f deg", 360.0 * k / count);
            std::fprintf(log, "m3g: wrote %s (%dx%d, t = %d ms%s)\n", path.c_str(), o.width, o.height, time, orbitNote);
        }
    }
    return image;
}

int cmdRender(std::span<const std::string_view> argv) {
    RenderOptions o;
    bool batch = false;
    try {
        o = parseRenderOptions(argv);
        std::error_code ec;
        batch = fs::is_directory(o.input, ec) || (fs::is_regular_file(o.input, ec) && JarArchive::looksLikeZip(o.input));
        if (batch && o.output.empty()) throw CliError("render: batch mode needs an output folder (-o OUTDIR)");
        if (batch && !o.reference.empty()) throw CliError("render: --reference compares one image, not a batch");
        if (batch && o.output == "-") throw CliError("render: batch mode writes files, not stdout");
        if (o.output.empty()) {
            if (!o.sequence()) throw CliError("render: no output (-o OUT.png, or -o - for stdout)");
            o.output = "out_{frame}.png";
        }
    } catch (const CliError& e) {
        std::fprintf(stderr, "m3g: %s\n", e.what());
        return 2;
    }
    if (batch) return renderBatch(o);
    try {
        m3g::LoaderOptions options;
        options.lenient = o.lenient;
        const m3g::LoadResult loaded = m3g::Loader::loadDetailed(o.input, options);
        for (const auto& w : loaded.warnings) std::fprintf(stderr, "m3g: warning: %s\n", w.c_str());
        const RgbaImage image = renderToFiles(loaded, o, o.output, stderr);
        if (o.reference.empty()) return 0;
        // The exit status is the verdict, as `m3g compare` gives it.
        const Comparison c = compareImages(image, readPng(o.reference), o.threshold);
        std::FILE* report = o.output == "-" ? stderr : stdout;
        std::fprintf(report, "%s", comparisonReport(c, o.threshold, o.maxShare, o.minPsnr).c_str());
        return withinLimits(c, o.maxShare, o.minPsnr) ? 0 : 1;
    } catch (const m3g::vk::VulkanError& e) {
        std::fprintf(stderr, "m3g: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        // Loader messages already start with the file's name.
        const std::string message = e.what();
        if (message.rfind(o.input + ": ", 0) == 0) std::fprintf(stderr, "m3g: %s\n", message.c_str());
        else std::fprintf(stderr, "m3g: %s: %s\n", o.input.c_str(), message.c_str());
        return 1;
    }
}

}  // namespace m3gcli
