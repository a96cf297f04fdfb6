// Round trip of every corpus file: load -> save -> load gives an equivalent
// graph (every getter of every reachable object compared), with and without
// zlib sections. Bytes are not compared: orientations are stored as angle +
// axis, so each load/save cycle may move the last bits of a quaternion (the
// graph comparison allows 1e-5 relative).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>

#include <m3g/m3g.h>

#include "M3GTestBytes.h"
#include "RoundTrip.h"

namespace fs = std::filesystem;
using namespace m3g;

namespace {
std::vector<const Object3D*> constRoots(const std::vector<Ref<Object3D>>& roots) {
    std::vector<const Object3D*> out;
    for (const auto& r : roots) out.push_back(r.get());
    return out;
}
std::vector<Object3D*> rawRoots(const std::vector<Ref<Object3D>>& roots) {
    std::vector<Object3D*> out;
    for (const auto& r : roots) out.push_back(r.get());
    return out;
}
}  // namespace

TEST(RoundTripCorpus, LoadSaveLoadIsEquivalentForEveryFile) {
    const auto corpus = m3gtest::corpusDir();
    if (!corpus) GTEST_SKIP() << "shared corpus not found (M3G_CORPUS_DIR/models); round-trip test skipped";
    const std::vector<fs::path> files = m3gtest::corpusFiles(*corpus);

    m3gtest::GraphCompareOptions options;
    options.compareMutablePixels = false;  // the format stores no pixels for mutable images
    int roundTripped = 0, skipped = 0;
    for (const auto& path : files) {
        std::vector<Ref<Object3D>> original;
        try {
            original = Loader::load(path.string());
        } catch (const IOException&) {
            ++skipped;  // must-reject files and the file with a missing texture
            continue;
        }
        SCOPED_TRACE(path.string());
        for (bool compress : {false, true}) {
            SaverOptions so;
            so.compress = compress;
            const auto saved = Saver::save(rawRoots(original), so);
            std::vector<Ref<Object3D>> reloaded;
            ASSERT_NO_THROW(reloaded = Loader::load(saved, 0)) << (compress ? "zlib" : "plain");
            const auto a = constRoots(original), b = constRoots(reloaded);
            const std::string diff = m3gtest::compareGraphs(a, b, options);
            EXPECT_EQ(diff, "") << (compress ? "zlib" : "plain");
        }
        ++roundTripped;
    }
    std::fflush(stdout);
    std::printf("[ round trip ] %d corpus files round-tripped, %d not loadable (skipped)\n", roundTripped, skipped);
    EXPECT_GE(roundTripped, 60);
}
