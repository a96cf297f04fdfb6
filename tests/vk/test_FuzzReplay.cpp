// The render fuzz target's rules (tests/fuzz/FuzzRender.h) on the device:
// every committed fuzz reproducer (tests/fuzz/regressions/*: the render
// target's own, and the loader, round-trip and PNG targets', each a hostile
// input for the renderer too) and every file of the shared corpus is loaded,
// drawn with CPU and compute deformation and in immediate mode, picked, and
// dropped twice, with no exception outside the documented ones, no
// validation message and no GPU buffer, texture, pipeline or memory kept
// by the second pass. Under the ASan + UBSan build of scripts/test this is also
// the memory check of the renderer on those inputs.
#include "VkTestSupport.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "FuzzRender.h"

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> filesUnder(const fs::path& dir, const std::string& extension) {
    std::vector<fs::path> files;
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file() && (extension.empty() || e.path().extension() == extension)) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

m3gfuzz::Bytes readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return m3gfuzz::Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// checkRender on each file; returns how many were checked.
std::size_t replay(const std::vector<fs::path>& files) {
    for (const fs::path& f : files) {
        SCOPED_TRACE(f.string());
        const m3gfuzz::Bytes bytes = readBytes(f);
        EXPECT_FALSE(bytes.empty()) << "unreadable or empty";
        try {
            m3gfuzz::checkRender(std::span<const std::uint8_t>(bytes));
        } catch (const m3gfuzz::Failure& failure) {
            ADD_FAILURE() << failure.what;
        }
    }
    return files.size();
}

}  // namespace

using m3gtest::VkTest;

TEST_F(VkTest, FuzzReproducersRenderWithinTheRenderFuzzRules) {
    std::size_t total = 0;
    for (const char* target : {"render", "loader", "roundtrip", "png"}) {
        const std::size_t n = replay(filesUnder(fs::path(M3G_FUZZ_REGRESSIONS_DIR) / target, ""));
        std::printf("[ replayed ] %zu %s reproducer(s)\n", n, target);
        total += n;
    }
    // The committed reproducers include at least the PNG and round-trip ones.
    EXPECT_GE(total, 2u);
}

TEST_F(VkTest, CorpusFilesRenderWithinTheRenderFuzzRules) {
    const fs::path corpus = M3G_CORPUS_DIR;
    const std::vector<fs::path> files = filesUnder(corpus / "models", ".m3g");
    if (files.empty()) GTEST_SKIP() << "shared corpus not found at " << corpus << " (no .m3g under models/)";
    std::printf("[ replayed ] %zu corpus file(s)\n", replay(files));
}
