// Load throughput over the corpus (MB/s of .m3g bytes turned into object
// graphs). A figure to report, never a pass/fail test.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <m3g/Loader.h>

namespace {

struct CorpusFile {
    std::string name;
    std::vector<std::uint8_t> bytes;
};

// Every corpus file that loads from memory (no external references).
const std::vector<CorpusFile>& corpus() {
    static const std::vector<CorpusFile> files = [] {
        std::vector<CorpusFile> out;
        const std::filesystem::path root = std::filesystem::path(M3G_CORPUS_DIR) / "models";
        if (!std::filesystem::exists(root)) return out;
        for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
            if (!e.is_regular_file()) continue;
            std::ifstream in(e.path(), std::ios::binary);
            std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            try {
                (void)m3g::Loader::load(bytes, 0);
            } catch (const m3g::Exception&) {
                continue;  // not M3G, external references, or a must-reject file
            }
            out.push_back({e.path().lexically_relative(root).string(), std::move(bytes)});
        }
        std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
        return out;
    }();
    return files;
}

void BM_LoadCorpus(benchmark::State& state) {
    const auto& files = corpus();
    if (files.empty()) {
        state.SkipWithError("corpus not found at " M3G_CORPUS_DIR);
        return;
    }
    std::size_t bytes = 0;
    for (const auto& f : files) bytes += f.bytes.size();
    for (auto _ : state) {
        for (const auto& f : files) benchmark::DoNotOptimize(m3g::Loader::load(f.bytes, 0));
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
    state.counters["files"] = static_cast<double>(files.size());
}
BENCHMARK(BM_LoadCorpus)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
