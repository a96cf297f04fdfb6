// m3g render: load, animate, optionally align, render the World to images
// (with the auto-framing and camera fix-up of docs/scene-setup.md):
// one image, an animation sequence, a turntable, a comparison with a
// reference image, or a batch over a folder or a J2ME .jar. Each failure
// has its exit code (CliErrors.h): a missing input 3, an unwritable image 4,
// a render that fails 5, a reference over the limits 1.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <m3g/m3g.h>
#include <m3g/vk/Vulkan.h>

#include "CliArgs.h"
#include "Commands.h"
#include "ImageIO.h"
#include "InputFile.h"
#include "JarArchive.h"
#include "RenderRun.h"
#include "SceneRender.h"
#include "UpAxis.h"
#include "SceneSetup.h"

namespace m3gcli {

namespace fs = std::filesystem;

namespace {

/// One line when an image came out as a single colour: most often the
/// camera looks away from the scene, not a broken renderer.
void hintIfUniform(const RgbaImage& image, const std::string& path, std::FILE* log) {
    if (!log || !isUniform(image)) return;
    std::fprintf(log,
                 "m3g render: note: %s is uniform (every pixel the same colour): the scene's camera may look away "
                 "from it, the scene may lie outside the clipping range, or colour writes are off\n",
                 path == "-" ? "the image" : path.c_str());
}

RgbaImage renderImage(m3g::World& world, int width, int height, bool keepAlpha) {
    try {
        return renderWorldImage(world, width, height, keepAlpha);
    } catch (const m3g::vk::VulkanError&) {
        throw;  // says what to install: exit code 5 as it is
    } catch (const std::exception& e) {
        throw RenderError(std::string("rendering failed: ") + e.what());
    }
}

void writeOutput(const std::string& path, const RgbaImage& image, bool keepAlpha) {
    if (path != "-") {
        const fs::path parent = fs::path(path).parent_path();
        std::error_code ec;
        if (!parent.empty()) fs::create_directories(parent, ec);
        if (ec) throw OutputError(path + ": cannot create the folder " + parent.string() + ": " + ec.message());
    }
    writeImage(path, image, keepAlpha);
}

int runRender(RenderOptions o) {
    std::error_code ec;
    const bool batch =
        fs::is_directory(o.input, ec) || (fs::is_regular_file(o.input, ec) && JarArchive::looksLikeZip(o.input));
    if (batch && o.output.empty()) throw CliError("batch mode needs an output folder (-o OUTDIR)");
    if (batch && !o.reference.empty()) throw CliError("--reference compares one image, not a batch");
    if (batch && o.output == "-") throw CliError("batch mode writes files, not stdout");
    if (o.output.empty()) {
        if (!o.sequence()) throw CliError("no output (-o OUT.png, or -o - for stdout)");
        o.output = "out_{frame}.png";
    }
    if (batch) return renderBatch(o);
    imageFormatFor(o.output);  // an unknown extension is refused before the work
    const m3g::LoadResult loaded = loadInput(o.input, o.lenient);
    for (const auto& w : loaded.warnings) std::fprintf(stderr, "m3g render: warning: %s\n", w.c_str());
    // Read before rendering: a missing reference writes nothing.
    std::optional<RgbaImage> reference;
    if (!o.reference.empty()) reference = readPngInput(o.reference);
    const RgbaImage image = renderToFiles(loaded, o, o.output, stderr);
    if (!reference) return kExitOk;
    // The exit code is the verdict, as `m3g compare` gives it.
    std::FILE* report = o.output == "-" ? stderr : stdout;
    if (image.width != reference->width || image.height != reference->height) {
        std::fprintf(report, "FAIL: the image is %dx%d, the reference %s %dx%d\n", image.width, image.height,
                     o.reference.c_str(), reference->width, reference->height);
        return kExitMismatch;
    }
    const Comparison c = compareImages(image, *reference, o.threshold);
    std::fprintf(report, "%s", comparisonReport(c, o.threshold, o.maxShare, o.minPsnr).c_str());
    return withinLimits(c, o.maxShare, o.minPsnr) ? kExitOk : kExitMismatch;
}

}  // namespace

RgbaImage renderToFiles(const m3g::LoadResult& loaded, const RenderOptions& o, const std::string& output,
                        std::FILE* log) {
    PreparedScene scene = prepareScene(loaded, o.width, o.height);
    if (o.cameraIndex) {
        try {
            useCamera(scene, loaded, *o.cameraIndex);
        } catch (const std::logic_error& e) {  // out_of_range, invalid_argument: the index does not fit the file
            throw CliError(std::string("--camera-index: ") + e.what());
        }
    }
    if (log)
        for (const auto& n : scene.notes) std::fprintf(log, "m3g render: %s\n", n.c_str());
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
        const Axis up = o.up ? *o.up : sceneUp(world);
        if (log) std::fprintf(log, "m3g render: the turntable turns about %s%s\n", axisName(up).c_str(),
                              o.up ? " (--up)" : " (the active camera's up)");
        orbit.emplace(*world.getActiveCamera(), world, center, up);
    }
    RgbaImage image;
    bool hinted = false;
    for (int k = 0; k < count; ++k) {
        int time = o.time;
        if (orbit) {
            orbit->setAngle(360.0f * static_cast<float>(k) / static_cast<float>(count));
        } else {
            time = o.time + static_cast<int>(std::lround(static_cast<double>(k) * 1000.0 / o.fps));
            world.animate(time);
            if (o.align) world.align(nullptr);
        }
        image = renderImage(world, o.width, o.height, keepAlpha);
        const std::string path = o.sequence() ? frameFileName(output, k, count) : output;
        writeOutput(path, image, keepAlpha);
        if (!hinted) {
            hintIfUniform(image, path, log);
            hinted = isUniform(image);
        }
        if (log && path != "-") {
            char orbitNote[48] = "";
            if (orbit) std::snprintf(orbitNote, sizeof orbitNote, ", orbit %.1f deg", 360.0 * k / count);
            std::fprintf(log, "m3g render: wrote %s (%dx%d, t = %d ms%s)\n", path.c_str(), o.width, o.height, time,
                         orbitNote);
        }
    }
    return image;
}

void addRenderCommand(CLI::App& parent, CommandTable& table) {
    CLI::App* app = addCommandApp(parent, "render",
                                  "render a file's World to an image, a sequence or a turntable; a folder or a .jar: "
                                  "every M3G file in it");
    auto flags = std::make_shared<RenderFlags>();
    addRenderOptions(*app, *flags);
    table[app] = [flags] { return runRender(finishRenderOptions(*flags)); };
}

int cmdRender(std::span<const std::string_view> args) { return runOneCommand(addRenderCommand, "render", args); }

}  // namespace m3gcli
