// m3g bench skin   the founding paper's skinning experiment, reproduced and
//                  extended (tests/bench/SkinWorkload.h): per-frame cost per
//                  vertex of the paper's baseline (Nokia's engine as the paper
//                  describes it) and of this library's palette + kernel on
//                  each code path, with the speed-up over the baseline;
//                  then, for 4 influences, the memory-bandwidth reference
//                  (SkinStreamRoof.h: a stream of the kernel's bytes per
//                  vertex) and the influence table's memory per vertex.
// m3g bench morph  the morph kernel against the plain per-target loop.
// Both add the compute-shader path (Graphics3D::SKINNING_COMPUTE; on
// lavapipe when that is the device) as a last column (ComputeBench.h).
// Options: --quick (fewer sizes, shorter runs), --baseline-max N (largest
// mesh the O(V^2) baseline runs on, default 100000), --run L (vertices per
// addTransform record, default 16), --time S (seconds per measurement,
// default 0.3), --no-compute (CPU paths only).
#include "Commands.h"

#include <algorithm>
#include <chrono>
#include <iterator>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <m3g/skin/Isa.h>
#include <m3g/skin/Skinning.h>
#include <m3g/skin/ThreadPool.h>

#include "ComputeBench.h"
#include "SkinWorkload.h"

namespace m3gcli {

namespace {

using m3gbench::Variant;
using Clock = std::chrono::steady_clock;

struct BenchOptions {
    bool quick = false;
    std::size_t baselineMax = 100000;
    int runLength = 16;
    double seconds = 0.3;
    bool compute = true;
};

/// Median seconds per frame of `frame()`: batches of at least 2 ms (or one
/// frame), repeated for about `seconds` (at least 3 batches, or a single
/// frame when one frame already takes longer than `seconds`).
template <class F>
double secondsPerFrame(F&& frame, double seconds) {
    auto t0 = Clock::now();
    frame();  // warm-up (caches, first-touch, thread start)
    const double first = std::chrono::duration<double>(Clock::now() - t0).count();
    if (first > seconds) return first;
    const std::size_t batch = std::max<std::size_t>(1, static_cast<std::size_t>(0.002 / std::max(first, 1e-9)));
    std::vector<double> samples;
    const auto start = Clock::now();
    while (samples.size() < 3 || std::chrono::duration<double>(Clock::now() - start).count() < seconds) {
        t0 = Clock::now();
        for (std::size_t i = 0; i < batch; ++i) frame();
        samples.push_back(std::chrono::duration<double>(Clock::now() - t0).count() / static_cast<double>(batch));
        if (samples.size() >= 1000) break;
    }
    std::nth_element(samples.begin(), samples.begin() + static_cast<long>(samples.size() / 2), samples.end());
    return samples[samples.size() / 2];
}

const Variant kVariants[] = {Variant::Baseline, Variant::Scalar, Variant::Sse2, Variant::Avx2, Variant::Avx512,
                             Variant::Parallel};
/// Columns: the variants, then the compute path (column kCompute).
constexpr int kCompute = static_cast<int>(std::size(kVariants));
constexpr int kColumns = kCompute + 1;
constexpr int kAvx2Column = 3, kParallelColumn = 5;  // kVariants' Avx2 and Parallel

const char* columnName(int i) { return i < kCompute ? m3gbench::variantName(kVariants[i]) : "compute"; }

void printHeader(const char* first, const char* second, const char* third) {
    std::printf("%9s %6s %6s", first, second, third);
    for (int i = 0; i < kColumns; ++i) std::printf(" %10s", columnName(i));
    std::printf(" %8s %9s\n", "best", "speed-up");
}

/// Median device time of `frames` frames (GPU timestamps around the
/// dispatches); negative when the device has no timestamps.
template <class F>
double medianDispatchSeconds(const ComputeBench& compute, F&& frame, int frames = 9) {
    std::vector<double> t;
    for (int i = 0; i < frames; ++i) {
        frame();
        t.push_back(compute.lastDispatchSeconds());
    }
    std::nth_element(t.begin(), t.begin() + frames / 2, t.end());
    return t[static_cast<std::size_t>(frames / 2)];
}

/// Process CPU seconds (all threads: the caller, the driver's queue and
/// worker threads) per call of `frame()`, over at least 3 calls and about
/// `seconds` of wall time. On lavapipe the "device" is these threads, so
/// this is the compute path's cost in CPU time, which a busy machine does
/// not inflate the way it inflates the wall time of a submit-and-wait.
template <class F>
double cpuSecondsPerFrame(F&& frame, double seconds) {
    auto cpuNow = [] {
        timespec t{};
        clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
        return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
    };
    const double c0 = cpuNow();
    const auto start = Clock::now();
    int frames = 0;
    while (frames < 3 || std::chrono::duration<double>(Clock::now() - start).count() < seconds) {
        frame();
        ++frames;
    }
    return (cpuNow() - c0) / frames;
}

/// The compute path's device, or null (with the reason printed) when it is
/// off or no Vulkan device is usable.
std::unique_ptr<ComputeBench> openCompute(const BenchOptions& o) {
    if (!o.compute) return nullptr;
    std::string why;
    auto bench = ComputeBench::create(why);
    if (bench)
        std::printf("compute path on: %s (palette on the CPU, upload, dispatch, submit and wait per frame)\n",
                    bench->deviceName().c_str());
    else
        std::printf("compute path: not measured (%s)\n", why.c_str());
    return bench;
}

/// Prints one row: ns per vertex per column (negative = not run); a
/// negative `b` leaves its column empty.
void printRow(std::size_t vertices, int a, int b, const double (&ns)[kColumns]) {
    if (b >= 0)
        std::printf("%9zu %6d %6d", vertices, a, b);
    else
        std::printf("%9zu %6d %6s", vertices, a, "");
    double best = -1;
    int bestIndex = -1;
    for (int i = 0; i < kColumns; ++i) {
        if (ns[i] < 0) {
            std::printf(" %10s", "-");
            continue;
        }
        std::printf(" %10.2f", ns[i]);
        if (i > 0 && (best < 0 || ns[i] < best)) {
            best = ns[i];
            bestIndex = i;
        }
    }
    std::printf(" %8s", bestIndex > 0 ? columnName(bestIndex) : "-");
    if (ns[0] > 0 && best > 0)
        std::printf(" %8.1fx\n", ns[0] / best);
    else
        std::printf(" %9s\n", "-");
    std::fflush(stdout);
}

void printIsa(m3g::skin::ThreadPool& pool) {
    std::printf(
        "code paths on this CPU: scalar, sse2 %s, avx2+fma %s, avx512 %s (runs; default %s); avx2+mt uses %d "
        "threads\n",
        m3g::skin::isaSupported(m3g::skin::Isa::Sse2) ? "yes" : "no",
        m3g::skin::isaSupported(m3g::skin::Isa::Avx2) ? "yes" : "no",
        m3g::skin::isaSupported(m3g::skin::Isa::Avx512) ? "yes" : "no",
        m3g::skin::isaName(m3g::skin::resolveIsa(m3g::skin::Isa::Auto)), pool.threadCount());
}

int benchSkin(const BenchOptions& o) {
    auto& pool = m3g::skin::ThreadPool::shared();
    std::printf("m3g bench skin: nanoseconds per vertex per frame (positions + normals; the palette or\n"
                "the paper's per-bone PT/NT included), median of timed batches. Baseline: the paper's\n"
                "description of Nokia's engine (record list searched per vertex, weights normalised at\n"
                "render time), one record per %d-vertex run and bone.\n",
                o.runLength);
    printIsa(pool);
    auto compute = openCompute(o);
    std::printf("The paper's meshes: 100, 350, 500 and 1,200 polygons (taken here as vertices).\n\n");
    struct ComputeRow {
        std::size_t vertices;
        double ns, dispatchNs, cpuNs, difference;
    };
    std::vector<ComputeRow> computeRows;
    struct RoofRow {
        std::size_t vertices;
        double avx2, parallel;                // ns per vertex
        double stream[2], streamParallel[2];  // [0]: run vertex (48 B), [1]: loose vertex (84 B)
    };
    std::vector<RoofRow> roofRows;
    printHeader("vertices", "infl", "bones");
    std::vector<std::size_t> sizes{100, 350, 500, 1200, 10000, 100000, 1000000};
    std::vector<int> influences{1, 2, 3, 4};
    if (o.quick) {
        sizes = {100, 1200, 10000, 100000};
        influences = {1, 4};
    }
    for (std::size_t v : sizes) {
        const int bones = v <= 1200 ? 20 : 60;
        for (int k : influences) {
            m3gbench::SkinWorkload w(v, k, bones, o.runLength);
            double ns[kColumns];
            for (int i = 0; i < kCompute; ++i) {
                const Variant var = kVariants[i];
                if ((var == Variant::Baseline && v > o.baselineMax) || !w.frame(var, &pool)) {
                    ns[i] = -1;
                    continue;
                }
                ns[i] = secondsPerFrame([&] { w.frame(var, &pool); }, o.seconds) * 1e9 / static_cast<double>(v);
            }
            ns[kCompute] = -1;
            if (compute) {
                compute->reset();
                compute->skinFrame(w);  // uploads the static inputs: once per mesh, not per frame
                ns[kCompute] = secondsPerFrame([&] { compute->skinFrame(w); }, o.seconds) * 1e9 / static_cast<double>(v);
                const double dispatch = medianDispatchSeconds(*compute, [&] { compute->skinFrame(w); });
                const double cpu = cpuSecondsPerFrame([&] { compute->skinFrame(w); }, o.seconds);
                w.frame(Variant::Scalar);  // the CPU result to check the device's against
                const double diff = compute->skinDifference(w);
                if (diff > 1e-4) std::printf("warning: compute skinning differs from the CPU by %.3g\n", diff);
                if (k == 4 && v >= 10000)
                    computeRows.push_back({v, ns[kCompute], dispatch * 1e9 / static_cast<double>(v),
                                           cpu * 1e9 / static_cast<double>(v), diff});
            }
            printRow(v, k, bones, ns);
            if (k == m3gbench::SkinWorkload::kMaxInfluences && ns[kAvx2Column] > 0) {
                RoofRow row{v, ns[kAvx2Column], ns[kParallelColumn], {}, {}};
                for (int t = 0; t < 2; ++t) {
                    const m3gbench::SkinStreamRoof roof = w.streamRoof(t == 1);
                    const double perV = 1e9 / static_cast<double>(v);
                    row.stream[t] = secondsPerFrame([&] { roof.frame(); }, o.seconds) * perV;
                    row.streamParallel[t] = secondsPerFrame([&] { roof.frame(&pool); }, o.seconds) * perV;
                }
                roofRows.push_back(row);
            }
        }
    }
    if (!roofRows.empty()) {
        // The workload's vertices are all in shared-influence runs (run
        // length >= InfluencePartition::kMinRun), so the kernel moves the
        // 48-byte stream's bytes; the 84-byte one is a loose vertex's.
        const bool runs = static_cast<std::size_t>(o.runLength) >= m3g::skin::InfluencePartition::kMinRun;
        const int t = runs ? 0 : 1;
        const double bytes = runs ? double(m3gbench::SkinStreamRoof::kVertexBytes)
                                  : double(m3gbench::SkinStreamRoof::kBytesPerVertex);
        std::printf("\nmemory-bandwidth reference, %d influences: a plain stream of the kernel's %.0f bytes per\n"
                    "vertex\n  (%s),\n1 thread and %d threads; 'share' = stream time / kernel time;\n"
                    "last columns: the %.0f-byte stream of %s:\n"
                    "%9s %10s %8s %9s %9s %7s %10s %8s %9s %9s %7s %10s %10s\n",
                    m3gbench::SkinWorkload::kMaxInfluences, bytes,
                    runs ? "shared-influence runs: position and normal read and written, the influences once per run"
                         : "loose vertices: list entry, position, normal, 4 bone indices and weights read;\n  position "
                           "and normal written",
                    pool.threadCount(),
                    runs ? double(m3gbench::SkinStreamRoof::kBytesPerVertex)
                         : double(m3gbench::SkinStreamRoof::kVertexBytes),
                    runs ? "a loose vertex" : "a run vertex", "vertices", "stream ns", "GB/s", "Mv/s", "avx2 ns",
                    "share", "stream mt", "GB/s", "Mv/s", "mt ns", "share", "other ns", "other mt");
        for (const RoofRow& r : roofRows)
            std::printf("%9zu %10.2f %8.1f %9.1f %9.2f %6.0f%% %10.2f %8.1f %9.1f %9.2f %6.0f%% %10.2f %10.2f\n",
                        r.vertices, r.stream[t], bytes / r.stream[t], 1e3 / r.stream[t], r.avx2,
                        100.0 * r.stream[t] / r.avx2, r.streamParallel[t], bytes / r.streamParallel[t],
                        1e3 / r.streamParallel[t], r.parallel,
                        r.parallel > 0 ? 100.0 * r.streamParallel[t] / r.parallel : 0.0, r.stream[1 - t],
                        r.streamParallel[1 - t]);
    }
    {
        // Per-vertex memory of the weights: ours is N slots, the paper's
        // dense table one weight per (vertex, bone).
        constexpr int n = m3gbench::SkinWorkload::kMaxInfluences;
        std::printf("\ninfluence table per vertex (N = %d): %d bytes (N x int32 bone + N x float weight) + %d bytes\n"
                    "of int64 accumulated weights kept for addTransform (never read by the kernel) = %d bytes;\n"
                    "read per frame: the %d for a loose vertex, and for a run of shared influences one vertex's\n"
                    "%d plus the %zu-byte run record, whatever its length. The paper's dense V x B float table:\n"
                    "4 x B bytes = %d (20 bones), %d (60 bones), whatever the influences per vertex.\n",
                    n, 8 * n, 8 * n, 16 * n, 8 * n, 8 * n, sizeof(m3g::skin::InfluenceRun), 4 * 20, 4 * 60);
    }
    if (!computeRows.empty()) {
        std::printf("\ncompute path, 4 influences, positions + normals. frame: wall time of palette, upload,\n"
                    "record, submit and wait; dispatch: device timestamps around the dispatch; cpu: process\n"
                    "CPU time per frame, all threads (on lavapipe the device is CPU threads):\n"
                    "%9s %11s %11s %11s %11s %11s %11s %9s\n",
                    "vertices", "frame ns/v", "frame Mv/s", "disp. ns/v", "disp. Mv/s", "cpu ns/v", "cpu Mv/s",
                    "max diff");
        for (const ComputeRow& r : computeRows) {
            std::printf("%9zu %11.2f %11.2f", r.vertices, r.ns, 1e3 / r.ns);
            if (r.dispatchNs > 0)
                std::printf(" %11.2f %11.2f", r.dispatchNs, 1e3 / r.dispatchNs);
            else
                std::printf(" %11s %11s", "-", "-");
            std::printf(" %11.2f %11.2f %9.2g\n", r.cpuNs, 1e3 / r.cpuNs, r.difference);
        }
    }
    return 0;
}

int benchMorph(const BenchOptions& o) {
    auto& pool = m3g::skin::ThreadPool::shared();
    std::printf("m3g bench morph: nanoseconds per vertex per frame (positions + renormalised normals);\n"
                "baseline: one pass over the array per target (the earlier reference loop).\n");
    printIsa(pool);
    auto compute = openCompute(o);
    std::printf("\n");
    printHeader("vertices", "targets", "");
    std::vector<std::size_t> sizes{1200, 10000, 100000, 1000000};
    if (o.quick) sizes = {1200, 100000};
    for (std::size_t v : sizes)
        for (int t : {1, 4}) {
            m3gbench::MorphWorkload w(v, t);
            double ns[kColumns];
            for (int i = 0; i < kCompute; ++i) {
                const Variant var = kVariants[i];
                if (!w.frame(var, &pool)) {
                    ns[i] = -1;
                    continue;
                }
                ns[i] = secondsPerFrame([&] { w.frame(var, &pool); }, o.seconds) * 1e9 / static_cast<double>(v);
            }
            ns[kCompute] = -1;
            if (compute) {
                compute->reset();
                compute->morphFrame(w);  // uploads the static inputs
                ns[kCompute] = secondsPerFrame([&] { compute->morphFrame(w); }, o.seconds) * 1e9 / static_cast<double>(v);
                w.frame(Variant::Scalar);
                const double diff = compute->morphDifference(w);
                if (diff > 1e-4) std::printf("warning: compute morph differs from the CPU by %.3g\n", diff);
            }
            printRow(v, t, -1, ns);
        }
    return 0;
}

/// The options of `bench skin` and `bench morph`, as given.
struct BenchFlags {
    bool quick = false, noCompute = false;
    std::string baselineMax, runLength, seconds;
};

/// A positive number option, or `fallback` when not given.
double positive(const char* name, const std::string& v, double fallback) {
    if (v.empty()) return fallback;
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (*end != '\0' || !(x > 0)) throw CliError(std::string(name) + " takes a positive number, not '" + v + "'");
    return x;
}

BenchOptions finish(const BenchFlags& f) {
    BenchOptions o;
    o.quick = f.quick;
    if (f.quick) o.seconds = 0.1;
    o.compute = !f.noCompute;
    o.baselineMax = static_cast<std::size_t>(positive("--baseline-max", f.baselineMax, double(o.baselineMax)));
    o.runLength = std::max(1, static_cast<int>(positive("--run", f.runLength, o.runLength)));
    o.seconds = positive("--time", f.seconds, o.seconds);
    return o;
}

void addKernelBench(CLI::App& bench, CommandTable& table, const char* name, const char* description,
                    int (*run)(const BenchOptions&)) {
    CLI::App* app = addCommandApp(bench, name, description);
    auto f = std::make_shared<BenchFlags>();
    app->add_flag("--quick", f->quick, "fewer sizes and shorter runs (0.1 s per measurement)");
    app->add_option("--baseline-max", f->baselineMax, "largest mesh the O(V^2) baseline runs on (default 100000)")
        ->type_name("N");
    app->add_option("--run", f->runLength, "vertices per addTransform record (default 16)")->type_name("L");
    app->add_option("--time", f->seconds, "seconds per measurement (default 0.3)")->type_name("SECONDS");
    app->add_flag("--no-compute", f->noCompute, "CPU paths only (no compute-shader column)");
    table[app] = [f, run] { return run(finish(*f)); };
}

}  // namespace

void addBenchCommand(CLI::App& parent, CommandTable& table) {
    CLI::App* bench = addCommandApp(parent, "bench", "benchmarks: render, soak, skin, morph (m3g bench WHAT --help)");
    addBenchRenderCommand(*bench, table);
    addBenchSoakCommand(*bench, table);
    addKernelBench(*bench, table, "skin",
                   "skinning kernels against the founding paper's baseline (docs/skinning.md)",
                   benchSkin);
    addKernelBench(*bench, table, "morph", "the morph kernel against the plain per-target loop",
                   benchMorph);
}

}  // namespace m3gcli
