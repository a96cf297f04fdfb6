// Skinning and morphing throughput: the founding paper's experiment
// reproduced and extended. Figures to report, never a pass/fail test.
//
// Paper: Cho, Lee, Choo, "A study on Optimizing Mobile 3D Game Engine using
// JSR-184" (2007): meshes of 100, 350, 500 and 1,200 polygons, the paper's
// precomputed per-vertex weights against Nokia's list of weighted transforms
// searched per vertex at render time (reimplemented in SkinBaseline.h).
// Here: those sizes (taken as that many vertices) plus 10k, 100k and 1M
// vertices; 1-4 influences; 20 bones for the paper's sizes, 60 above; and
// positions + normals. Variants: the baseline, this library's palette +
// kernel on its scalar, SSE2 and AVX2 paths, and AVX2 on the thread pool.
//
// Counter "per_vertex" is seconds per vertex per frame (shown as ns, "n"),
// from wall-clock time (UseRealTime): the thread-pool variant's work runs on
// other threads too, which the default per-thread CPU time would not see.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <tuple>

#include "SkinWorkload.h"

namespace {

using m3gbench::Variant;

m3gbench::SkinWorkload& skinWorkload(std::size_t v, int k, int bones) {
    static std::map<std::tuple<std::size_t, int, int>, std::unique_ptr<m3gbench::SkinWorkload>> cache;
    auto& slot = cache[{v, k, bones}];
    if (!slot) slot = std::make_unique<m3gbench::SkinWorkload>(v, k, bones);
    return *slot;
}

/// Times `w.frame(variant)` (a skin or morph workload) over `vertices`;
/// false (the benchmark skipped) when the CPU lacks the variant.
template <class Workload>
bool runFrames(benchmark::State& state, Workload& w, Variant variant, std::size_t vertices) {
    if (!w.frame(variant)) {
        state.SkipWithError("variant not supported on this CPU");
        return false;
    }
    for (auto _ : state) {
        w.frame(variant);
        benchmark::DoNotOptimize(w.outPositions.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * vertices));
    state.counters["per_vertex"] = benchmark::Counter(
        static_cast<double>(vertices), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    return true;
}

void BM_Skin(benchmark::State& state) {
    const auto v = static_cast<std::size_t>(state.range(0));
    const int k = static_cast<int>(state.range(1)), bones = static_cast<int>(state.range(2));
    const auto variant = static_cast<Variant>(state.range(3));
    auto& w = skinWorkload(v, k, bones);
    if (!runFrames(state, w, variant, v)) return;
    state.SetLabel(std::string(m3gbench::variantName(variant)) + " v=" + std::to_string(v) + " k=" +
                   std::to_string(k) + " bones=" + std::to_string(bones));
}

void skinArgs(benchmark::internal::Benchmark* b) {
    b->ArgNames({"vertices", "influences", "bones", "variant"});
    for (std::int64_t v : {100, 350, 500, 1200, 10000, 100000, 1000000}) {
        const std::int64_t bones = v <= 1200 ? 20 : 60;
        for (std::int64_t k = 1; k <= 4; ++k)
            for (Variant var : {Variant::Baseline, Variant::Scalar, Variant::Sse2, Variant::Avx2, Variant::Avx512,
                                Variant::Parallel}) {
                // The baseline searches the whole record list per vertex:
                // O(V^2); at 1M vertices one frame would take minutes.
                if (var == Variant::Baseline && v > 100000) continue;
                b->Args({v, k, bones, static_cast<std::int64_t>(var)});
            }
    }
}
BENCHMARK(BM_Skin)->Apply(skinArgs)->Unit(benchmark::kMicrosecond)->UseRealTime();

// Shared-influence runs of other lengths than BM_Skin's 16: runLength 1
// (every vertex with its own bones and weights, no two neighbours alike:
// all vertices take the per-vertex blend path), 4 (the shortest run kept
// as a run), 16 and 256 (the per-run cost spread thin).
void BM_SkinRunLength(benchmark::State& state) {
    const auto v = static_cast<std::size_t>(state.range(0));
    const int k = static_cast<int>(state.range(1));
    const int run = static_cast<int>(state.range(2));
    const auto variant = static_cast<Variant>(state.range(3));
    static std::map<std::tuple<std::size_t, int, int>, std::unique_ptr<m3gbench::SkinWorkload>> cache;
    auto& slot = cache[{v, k, run}];
    if (!slot) slot = std::make_unique<m3gbench::SkinWorkload>(v, k, 60, run);
    runFrames(state, *slot, variant, v);
}
BENCHMARK(BM_SkinRunLength)
    ->ArgNames({"vertices", "influences", "run", "variant"})
    ->ArgsProduct({{10000, 100000, 1000000},
                   {1, 4},
                   {1, 4, 13, 16, 23, 256},
                   {static_cast<std::int64_t>(Variant::Sse2), static_cast<std::int64_t>(Variant::Avx2),
                    static_cast<std::int64_t>(Variant::Avx512), static_cast<std::int64_t>(Variant::Parallel)}})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

// The memory-bandwidth reference: a plain stream of the 4-influence
// kernel's bytes per vertex (SkinStreamRoof.h), 1 thread or the pool;
// tables 1: a loose vertex's 84 bytes, 0: a run vertex's 48.
void BM_SkinStreamRoof(benchmark::State& state) {
    const auto v = static_cast<std::size_t>(state.range(0));
    const bool parallel = state.range(1) != 0;
    auto& w = skinWorkload(v, m3gbench::SkinWorkload::kMaxInfluences, v <= 1200 ? 20 : 60);
    const m3gbench::SkinStreamRoof roof = w.streamRoof(state.range(2) != 0);
    m3g::skin::ThreadPool* pool = parallel ? &m3g::skin::ThreadPool::shared() : nullptr;
    for (auto _ : state) {
        roof.frame(pool);
        benchmark::DoNotOptimize(w.outPositions.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * v));
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * v * roof.bytesPerVertex()));
    state.counters["per_vertex"] =
        benchmark::Counter(static_cast<double>(v), benchmark::Counter::kIsIterationInvariantRate |
                                                       benchmark::Counter::kInvert);
}
BENCHMARK(BM_SkinStreamRoof)
    ->ArgNames({"vertices", "parallel", "tables"})
    ->ArgsProduct({{100, 350, 500, 1200, 10000, 100000, 1000000}, {0, 1}, {0, 1}})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

// The palette alone (one entry per bone per frame): what a small mesh's
// frame pays before its first vertex. Scalar (double), SSE2 and AVX2 (float).
void BM_SkinPalette(benchmark::State& state) {
    const auto bones = static_cast<std::size_t>(state.range(0));
    const auto isa = static_cast<m3g::skin::Isa>(state.range(1));
    auto& w = skinWorkload(100, 1, static_cast<int>(bones));
    m3g::skin::PaletteJob job;
    job.boneCount = bones;
    job.boneToMesh = w.boneToMesh;
    job.atRest = w.atRest;
    job.output = w.palette;
    job.isa = isa;
    if (!job.run()) {
        state.SkipWithError("isa not supported on this CPU");
        return;
    }
    for (auto _ : state) {
        job.run();
        benchmark::DoNotOptimize(w.palette.data());
        benchmark::ClobberMemory();
    }
    state.counters["per_bone"] = benchmark::Counter(static_cast<double>(bones), benchmark::Counter::kIsIterationInvariantRate |
                                                                                   benchmark::Counter::kInvert);
}
BENCHMARK(BM_SkinPalette)
    ->ArgNames({"bones", "isa"})
    ->ArgsProduct({{20, 60},
                   {static_cast<std::int64_t>(m3g::skin::Isa::Scalar), static_cast<std::int64_t>(m3g::skin::Isa::Sse2),
                    static_cast<std::int64_t>(m3g::skin::Isa::Avx2)}})
    ->Unit(benchmark::kNanosecond);

void BM_Morph(benchmark::State& state) {
    const auto v = static_cast<std::size_t>(state.range(0));
    const int targets = static_cast<int>(state.range(1));
    const auto variant = static_cast<Variant>(state.range(2));
    static std::map<std::pair<std::size_t, int>, std::unique_ptr<m3gbench::MorphWorkload>> cache;
    auto& slot = cache[{v, targets}];
    if (!slot) slot = std::make_unique<m3gbench::MorphWorkload>(v, targets);
    runFrames(state, *slot, variant, v);
}

void morphArgs(benchmark::internal::Benchmark* b) {
    b->ArgNames({"vertices", "targets", "variant"});
    for (std::int64_t v : {1200, 10000, 100000, 1000000})
        for (std::int64_t t : {1, 4})
            for (Variant var : {Variant::Baseline, Variant::Scalar, Variant::Sse2, Variant::Avx2, Variant::Parallel})
                b->Args({v, t, static_cast<std::int64_t>(var)});
}
BENCHMARK(BM_Morph)->Apply(morphArgs)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
