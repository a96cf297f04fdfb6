// m3g bench soak: memory over thousands of frames (docs/rendering.md,
// "Resources"). Not a
// speed measurement: it prints resident and GPU memory per reload cycle and
// a verdict; exit status 0 when both are flat after the warm-up and the
// validation layer (M3G_VK_VALIDATION=1) reported nothing.
//
//   m3g bench soak FILE [--frames N] [--reload K] [--size WxH] [--report R] [--warmup C]
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include <m3g/m3g.h>
#include <m3g/vk/Vulkan.h>

#include "CliArgs.h"
#include "Commands.h"
#include "InputFile.h"
#include "Soak.h"

namespace m3gcli {

namespace {

double mib(std::uint64_t bytes) { return static_cast<double>(bytes) / 1048576.0; }

struct SoakFlags {
    std::string file, frames, reload, size, report, warmup;
};

int benchSoak(const SoakFlags& f) {
    SoakOptions o;
    o.file = f.file;
    if (!f.frames.empty()) o.frames = parseIntOption("--frames", f.frames, 1, "a positive integer");
    if (!f.reload.empty()) o.reload = parseIntOption("--reload", f.reload, 1, "a positive integer");
    if (!f.report.empty()) o.reportEvery = parseIntOption("--report", f.report, 0, "a non-negative integer");
    if (!f.warmup.empty()) o.warmupCycles = parseIntOption("--warmup", f.warmup, 0, "a non-negative integer");
    if (!f.size.empty()) parseSizeOption("--size", f.size, o.width, o.height);
    requireInputFile(o.file);
    try {
        std::printf("soak %s: %d frames at %dx%d, reload every %d frames, immediate draws every frame\n",
                    o.file.c_str(), o.frames, o.width, o.height, o.reload);
        std::printf("%8s %6s %12s %12s %8s %9s\n", "frame", "cycle", "resident MiB", "GPU MiB", "buffers", "textures");
        const SoakResult r = runSoak(o, [](const SoakSample& s) {
            std::printf("%8d %6d %12.2f %12.3f %8llu %9llu\n", s.frame, s.cycle, mib(s.residentBytes), mib(s.deviceBytes),
                        static_cast<unsigned long long>(s.liveBuffers), static_cast<unsigned long long>(s.liveTextures));
            std::fflush(stdout);
        });
        const auto info = m3g::vk::currentDevice();
        std::printf("device: %s; draws: %llu; validation layer: %s, %llu messages\n", info.name.c_str(),
                    static_cast<unsigned long long>(r.draws), m3g::vk::validationEnabled() ? "on" : "off",
                    static_cast<unsigned long long>(r.validationMessages));
        std::printf("verdict: %s\n", r.verdict.c_str());
        if (r.judgedCycles == 0) return kExitMismatch;
        return r.gpuFlat && r.residentFlat && r.validationMessages == 0 ? kExitOk : kExitMismatch;
    } catch (const m3g::vk::VulkanError&) {
        throw;
    } catch (const m3g::Exception& e) {
        // The Loader's (the file is loaded again and again) or Graphics3D's.
        throw InputError(withPath(o.file, e.what()));
    }
}

}  // namespace

void addBenchSoakCommand(CLI::App& bench, CommandTable& table) {
    CLI::App* app = addCommandApp(bench, "soak",
                                  "memory over a long run with reloads; exit code 1 unless flat after the warm-up");
    auto f = std::make_shared<SoakFlags>();
    app->add_option("file", f->file, "the .m3g file")->type_name("FILE")->required();
    app->add_option("--frames", f->frames, "frames in all (default 3000)")->type_name("N");
    app->add_option("--reload", f->reload, "drop and load the file again every K frames (default 300)")->type_name("K");
    app->add_option("--size", f->size, "target size in pixels (default 160x120)")->type_name("WxH");
    app->add_option("--report", f->report, "print memory every R frames (default 0: at every reload)")->type_name("R");
    app->add_option("--warmup", f->warmup, "cycles left out of the verdict (default 2)")->type_name("C");
    table[app] = [f] { return benchSoak(*f); };
}

}  // namespace m3gcli
