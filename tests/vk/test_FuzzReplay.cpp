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

#include <cstdio>
#include <filesystem>
#include <vector>

#include "FuzzRender.h"
#include "M3GTestBytes.h"

namespace fs = std::filesystem;

namespace {

/// checkRender on each file; returns how many were checked.
std::size_t replay(const std::vector<fs::path>& files) {
    for (const fs::path& f : files) {
        SCOPED_TRACE(f.string());
        const m3gtest::Bytes bytes = m3gtest::readFile(f);
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
    for (const char* target : {"render", "loader", "roundtrip", "png", "jpeg"}) {
        const std::size_t n = replay(m3gtest::regressionFiles(target));
        std::printf("[ replayed ] %zu %s reproducer(s)\n", n, target);
        total += n;
    }
    // The committed reproducers include at least the PNG and round-trip ones.
    EXPECT_GE(total, 2u);
}

TEST_F(VkTest, CorpusFilesRenderWithinTheRenderFuzzRules) {
    const auto corpus = m3gtest::corpusDir();
    if (!corpus) GTEST_SKIP() << "shared corpus not found at " << M3G_CORPUS_DIR << " (no models/ folder)";
    std::vector<fs::path> files = m3gtest::corpusFiles(*corpus);
    std::erase_if(files, [](const fs::path& f) { return f.extension() != ".m3g"; });
    ASSERT_FALSE(files.empty()) << "no .m3g under " << *corpus / "models";
    std::printf("[ replayed ] %zu corpus file(s)\n", replay(files));
}
