// m3g bench soak: memory over thousands of frames (docs/rendering.md,
// "Resources"). Not a
// speed measurement: it prints resident and GPU memory per reload cycle and
// a verdict; exit status 0 when both are flat after the warm-up and the
// validation layer (M3G_VK_VALIDATION=1) reported nothing.
//
//   m3g bench soak FILE [--frames N] [--reload K] [--size WxH] [--report R] [--warmup C]
#include <cstdio>
#include <optional>
#include <string>

#include <m3g/m3g.h>
#include <m3g/vk/Vulkan.h>

#include "CliArgs.h"
#include "Commands.h"
#include "Soak.h"

namespace m3gcli {

namespace {

constexpr const char* kUsage =
    "usage: m3g bench soak FILE [--frames N] [--reload K] [--size WxH] [--report R] [--warmup C]\n"
    "  load, animate and render FILE for N frames (default 3000), dropping and loading it again\n"
    "  every K frames (default 300), with immediate-mode draws; prints memory every R frames\n"
    "  (default: at every reload) and a verdict over the cycles after the first C (default 2)\n";

double mib(std::uint64_t bytes) { return static_cast<double>(bytes) / 1048576.0; }

}  // namespace

int cmdBenchSoak(std::span<const std::string_view> args) {
    SoakOptions o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view a = args[i];
        auto number = [&](int& out) {
            std::optional<int> n = i + 1 < args.size() ? parseInt(args[++i]) : std::nullopt;
            if (!n || *n < 0) return false;
            out = *n;
            return true;
        };
        bool ok = true;
        if (a == "--frames") ok = number(o.frames) && o.frames > 0;
        else if (a == "--reload") ok = number(o.reload) && o.reload > 0;
        else if (a == "--report") ok = number(o.reportEvery);
        else if (a == "--warmup") ok = number(o.warmupCycles);
        else if (a == "--size") {
            ok = i + 1 < args.size() && parseSize(args[++i], o.width, o.height);
        } else if (!a.empty() && a[0] == '-') ok = false;
        else if (o.file.empty()) o.file = a;
        else ok = false;
        if (!ok) {
            std::fprintf(stderr, "m3g: bench soak: bad argument %s\n%s", std::string(a).c_str(), kUsage);
            return 2;
        }
    }
    if (o.file.empty()) {
        std::fprintf(stderr, "m3g: bench soak: no input file\n%s", kUsage);
        return 2;
    }
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
        if (r.judgedCycles == 0) return 1;
        return r.gpuFlat && r.residentFlat && r.validationMessages == 0 ? 0 : 1;
    } catch (const m3g::vk::VulkanError& e) {
        std::fprintf(stderr, "m3g: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "m3g: bench soak: %s: %s\n", o.file.c_str(), e.what());
        return 1;
    }
}

}  // namespace m3gcli
