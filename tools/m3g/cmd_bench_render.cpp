// m3g bench render: frames per second and CPU cost of rendering .m3g files
// headless (the figures in docs/rendering.md, "Measuring"). Not a test: it
// prints.
//
//   m3g bench render FILE... [--size WxH] [--frames N] [--invocations] [--animate MS]
//
// Per file: first-frame latency (a fresh renderer: pipeline and upload
// work included); steady-state wall time and process CPU time per frame (all
// threads, lavapipe's rasterizer included) for bind, render(World) and
// releaseTarget with read-back; the calling thread's CPU time in
// render(World) per draw (collect, uploads if any, recording; the frame is
// opened by a clear(null) before it); pipelines created in steady state
// (should be 0); and where the frame's fixed cost goes, wall time per frame
// (RenderStats): from the submit until the frame's fence signalled (the
// device's work and the driver's round trip) and the read-back into the
// Graphics surface. With --invocations, also the vertex and fragment shader
// invocations per frame the device counted (a pipeline-statistics query around
// each frame; `-` where the device cannot count them). M3G_VK_PREWARM=1/0
// forces pipeline pre-warming on or off. With --animate MS, each frame
// first animates the World MS milliseconds later than the last (inside the
// timed part, as a game's loop does: animation, skinning, uploads), world
// time starting again from 0 after the longest KeyframeSequence's duration
// so that the content keeps moving; without it every frame draws the pose
// at time 0.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <string>
#include <memory>
#include <vector>

#include <m3g/m3g.h>
#include <m3g/vk/Vulkan.h>

#include "CliArgs.h"
#include "Commands.h"
#include "InputFile.h"
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

struct BenchRenderArgs {
    std::vector<std::string> files;
    std::string size, frames, animate;
    bool invocations = false;
};

int benchRender(const BenchRenderArgs& args) {
    int width = 320, height = 240, frames = 100;
    if (!args.size.empty()) parseSizeOption("--size", args.size, width, height);
    if (!args.frames.empty()) frames = parseIntOption("--frames", args.frames, 1, "a positive integer");
    const int step = args.animate.empty() ? 0 : parseIntOption("--animate", args.animate, 1, "a positive number of milliseconds");
    const std::vector<std::string>& files = args.files;
    // Every file is checked before the first is measured: a typo should not
    // cost a benchmark run.
    for (const std::string& file : files) requireInputFile(file);
    int failed = 0;
    m3g::Graphics3D* g = m3g::Graphics3D::getInstance();
    std::printf("%dx%d, %d frames per file", width, height, frames);
    if (step > 0) std::printf(", animated %d ms a frame", step);
    std::printf("\n");
    std::printf("%-40s %7s %9s %9s %9s %8s %9s %6s %8s %8s", "file", "draws", "first ms", "ms/frame", "fps", "cpu ms",
                "us/draw", "pipes", "wait ms", "read ms");
    if (args.invocations) std::printf(" %10s %10s", "vs/frame", "fs/frame");
    std::printf("\n");
    m3g::vk::setShaderInvocationCounting(args.invocations);
    for (const std::string& file : files) {
        try {
            m3g::LoadResult loaded = loadInput(file, false);
            PreparedScene scene = prepareScene(loaded, width, height);
            scene.world->animate(0);
            const int period = std::max(1, longestSequence(loaded));
            int time = 0;
            m3g::Ref<m3g::Graphics> target(new m3g::Graphics(width, height));
            g->releaseRenderer();  // first frame from a fresh renderer
            auto frame = [&](double* renderCpu) {
                if (step > 0) {
                    scene.world->animate(time);
                    time = static_cast<int>((static_cast<long long>(time) + step) % period);
                }
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
            const double waitMs = static_cast<double>(after.frameWaitNanoseconds - before.frameWaitNanoseconds) / frames * 1e-6;
            const double readMs = static_cast<double>(after.readBackNanoseconds - before.readBackNanoseconds) / frames * 1e-6;
            std::printf("%-40s %7.0f %9.1f %9.2f %9.1f %8.2f %9.2f %6llu %8.3f %8.3f", name.c_str(), draws, first * 1e3,
                        wall * 1e3, 1.0 / wall, cpu * 1e3, draws > 0 ? renderCpu / frames / draws * 1e6 : 0.0,
                        static_cast<unsigned long long>(after.pipelinesCreated - before.pipelinesCreated), waitMs, readMs);
            if (args.invocations) {
                const std::uint64_t counted = after.countedFrames - before.countedFrames;
                if (counted == 0) {
                    std::printf(" %10s %10s", "-", "-");  // the device cannot count them
                } else {
                    const double n = static_cast<double>(counted);
                    std::printf(" %10.0f %10.0f",
                                static_cast<double>(after.vertexShaderInvocations - before.vertexShaderInvocations) / n,
                                static_cast<double>(after.fragmentShaderInvocations - before.fragmentShaderInvocations) / n);
                }
            }
            std::printf("\n");
            std::fflush(stdout);  // a run stopped by a time limit keeps the files measured
        } catch (const m3g::vk::VulkanError&) {
            throw;  // no device: every file would fail the same way
        } catch (const InputError& e) {
            // The file is the row's first column: its name is not said again.
            std::printf("%-40s error: %s\n", file.c_str(), withPath(file, e.what()).substr(file.size() + 2).c_str());
            failed = failed ? failed : int(kExitInput);
        } catch (const std::exception& e) {
            std::printf("%-40s error: %s\n", file.c_str(), e.what());
            failed = failed ? failed : int(kExitRender);
        }
    }
    m3g::vk::setShaderInvocationCounting(false);
    const auto info = m3g::vk::currentDevice();
    std::printf("device: %s (%s)\n", info.name.c_str(), info.type.c_str());
    if (args.invocations && !m3g::vk::shaderInvocationCountingSupported())
        std::printf("shader invocations: not counted (the device lacks pipelineStatisticsQuery)\n");
    return failed;  // 0, or the first failure's code (3 load, 5 render)
}

}  // namespace

void addBenchRenderCommand(CLI::App& bench, CommandTable& table) {
    CLI::App* app = addCommandApp(bench, "render",
                                  "rendering speed per file: first frame, ms per frame, fps, CPU per draw, device wait and read-back per frame");
    auto args = std::make_shared<BenchRenderArgs>();
    app->add_option("files", args->files, "the .m3g files to measure")->type_name("FILE")->required();
    app->add_option("--size", args->size, "target size in pixels (default 320x240)")->type_name("WxH");
    app->add_option("--frames", args->frames, "frames measured per file (default 100)")->type_name("N");
    app->add_flag("--invocations", args->invocations,
                  "also count the vertex and fragment shader invocations per frame (a Vulkan pipeline-statistics "
                  "query; lavapipe counts fragments in whole 4x4 blocks)");
    app->add_option("--animate", args->animate,
                    "animate the World MS milliseconds further before each frame, inside the timed part (animation, "
                    "skinning and uploads counted; time wraps after the longest keyframe sequence)")
        ->type_name("MS");
    table[app] = [args] { return benchRender(*args); };
}

}  // namespace m3gcli
