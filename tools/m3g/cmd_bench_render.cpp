// m3g bench render: frames per second and CPU cost of rendering .m3g files
// headless (the figures in docs/rendering.md, "Measuring"). Not a test: it
// prints.
//
//   m3g bench render FILE... [--size WxH] [--frames N]
//
// Per file: first-frame latency (a fresh renderer: pipeline and upload
// work included); steady-state wall time and process CPU time per frame (all
// threads, lavapipe's rasterizer included) for bind, render(World) and
// releaseTarget with read-back; the calling thread's CPU time in
// render(World) per draw (collect, uploads if any, recording; the frame is
// opened by a clear(null) before it); and pipelines created in steady state
// (should be 0). M3G_VK_PREWARM=1/0 forces pipeline pre-warming on or off.
#include <chrono>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include <m3g/m3g.h>
#include <m3g/vk/Vulkan.h>

#include "CliArgs.h"
#include "Commands.h"
#include "SceneSetup.h"

namespace m3gcli {

namespace {

double clockSeconds(clockid_t clock) {
    timespec ts{};
    clock_gettime(clock, &ts);
    return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}
/// The whole process: recording plus lavapipe's rasterizer threads.
double cpuSeconds() { return clockSeconds(CLOCK_PROCESS_CPUTIME_ID); }
/// This thread only: what recording a frame costs the caller.
double threadCpuSeconds() { return clockSeconds(CLOCK_THREAD_CPUTIME_ID); }

double wallSeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

int cmdBenchRender(std::span<const std::string_view> args) {
    std::vector<std::string> files;
    int width = 320, height = 240, frames = 100;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--size" && i + 1 < args.size()) {
            if (!parseSize(args[++i], width, height)) {
                std::fprintf(stderr, "m3g: bench render: --size takes WxH\n");
                return 2;
            }
        } else if (args[i] == "--frames" && i + 1 < args.size()) {
            auto n = parseInt(args[++i]);
            if (!n || *n <= 0) {
                std::fprintf(stderr, "m3g: bench render: --frames takes a positive integer\n");
                return 2;
            }
            frames = *n;
        } else if (!args[i].empty() && args[i][0] == '-') {
            std::fprintf(stderr, "m3g: bench render: unknown option %s\n", std::string(args[i]).c_str());
            return 2;
        } else {
            files.emplace_back(args[i]);
        }
    }
    if (files.empty()) {
        std::fprintf(stderr, "m3g: usage: m3g bench render FILE... [--size WxH] [--frames N]\n");
        return 2;
    }
    m3g::Graphics3D* g = m3g::Graphics3D::getInstance();
    std::printf("%dx%d, %d frames per file\n", width, height, frames);
    std::printf("%-40s %7s %9s %9s %9s %8s %9s %6s\n", "file", "draws", "first ms", "ms/frame", "fps", "cpu ms", "us/draw", "pipes");
    for (const std::string& file : files) {
        try {
            m3g::LoadResult loaded = m3g::Loader::loadDetailed(file);
            PreparedScene scene = prepareScene(loaded, width, height);
            scene.world->animate(0);
            m3g::Ref<m3g::Graphics> target(new m3g::Graphics(width, height));
            g->releaseRenderer();  // first frame from a fresh renderer
            auto frame = [&](double* renderCpu) {
                g->bindTarget(target.get(), true, 0);
                g->clear(nullptr);  // opens the frame (target upload) outside the timed part
                const double c0 = threadCpuSeconds();
                g->render(scene.world.get());
                if (renderCpu) *renderCpu += threadCpuSeconds() - c0;
                g->releaseTarget();
            };
            const double f0 = wallSeconds();
            frame(nullptr);
            const double first = wallSeconds() - f0;
            const auto before = m3g::vk::renderStats();
            double renderCpu = 0.0;
            const double w0 = wallSeconds(), c0 = cpuSeconds();
            for (int i = 0; i < frames; ++i) frame(&renderCpu);
            const double wall = (wallSeconds() - w0) / frames, cpu = (cpuSeconds() - c0) / frames;
            const auto after = m3g::vk::renderStats();
            const double draws = static_cast<double>(after.draws - before.draws) / frames;
            std::string name = file.size() > 40 ? "..." + file.substr(file.size() - 37) : file;
            std::printf("%-40s %7.0f %9.1f %9.2f %9.1f %8.2f %9.2f %6llu\n", name.c_str(), draws, first * 1e3, wall * 1e3,
                        1.0 / wall, cpu * 1e3, draws > 0 ? renderCpu / frames / draws * 1e6 : 0.0,
                        static_cast<unsigned long long>(after.pipelinesCreated - before.pipelinesCreated));
            std::fflush(stdout);  // a run stopped by a time limit keeps the files measured
        } catch (const std::exception& e) {
            std::printf("%-40s error: %s\n", file.c_str(), e.what());
        }
    }
    try {
        const auto info = m3g::vk::currentDevice();
        std::printf("device: %s (%s)\n", info.name.c_str(), info.type.c_str());
    } catch (const m3g::vk::VulkanError& e) {
        std::fprintf(stderr, "m3g: %s\n", e.what());
        return 1;
    }
    return 0;
}

}  // namespace m3gcli
