// The threading model (docs/threading.md): one Graphics3D per thread
// (Graphics3D::create), each with its own objects and target, sharing the
// process's Vulkan device. Two threads render their own World many times at
// once; every frame must equal the same frame rendered on one thread, and
// the validation layer (with its thread-safety checks) must stay silent.
#include <array>
#include <atomic>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "RobustScenes.h"
#include "SceneSetup.h"
#include "VkTestSupport.h"

using namespace m3g;
using m3gtest::VkTest;

namespace {

constexpr int kSize = 48;
constexpr int kPhases = 4;  // frames repeat with this period

/// Renders frame `frame` of scene `variant` with `g` and returns the pixels.
using FrameFn = std::function<std::vector<std::uint8_t>(Graphics3D& g, int variant, int frame)>;

/// For each variant, the reference pixels of every phase, rendered on this
/// thread; then both variants on two threads for `frames` frames each,
/// compared with the references. Returns the number of mismatching frames.
int renderOnTwoThreads(const FrameFn& render, int frames) {
    std::array<std::vector<std::vector<std::uint8_t>>, 2> reference;
    {
        std::unique_ptr<Graphics3D> g = Graphics3D::create();
        for (int v = 0; v < 2; ++v)
            for (int p = 0; p < kPhases; ++p) reference[v].push_back(render(*g, v, p));
    }
    EXPECT_NE(reference[0][0], reference[1][0]) << "the two variants should look different";
    std::atomic<int> mismatches{0}, failures{0};
    std::array<std::string, 2> errors;
    auto worker = [&](int variant) {
        try {
            std::unique_ptr<Graphics3D> g = Graphics3D::create();
            for (int f = 0; f < frames; ++f)
                if (render(*g, variant, f % kPhases) != reference[variant][f % kPhases]) ++mismatches;
        } catch (const std::exception& e) {
            errors[variant] = e.what();
            ++failures;
        }
    };
    std::thread a(worker, 0), b(worker, 1);
    a.join();
    b.join();
    EXPECT_EQ(failures.load(), 0) << errors[0] << " / " << errors[1];
    return mismatches.load();
}

std::vector<std::uint8_t> pixelsOf(const Image2D& image) {
    std::vector<std::uint8_t> px;
    image.getPixelsRGBA8(px);
    return px;
}

}  // namespace

// Each thread builds its World anew every frame (uploads, texture creation
// through the shared upload pool, deferred frees) and adds an immediate-mode
// draw; ANTIALIAS on odd phases switches its target images too.
TEST_F(VkTest, TwoThreadsRenderTheirOwnWorlds) {
    const FrameFn render = [](Graphics3D& g, int variant, int phase) {
        Ref<World> world = m3gtest::robustWorld(variant);
        m3gtest::ImmediateDraw immediate = m3gtest::immediateDraw(phase, kSize);
        Ref<Image2D> img(new Image2D(Image2D::RGBA, kSize, kSize));
        g.bindTarget(img.get(), true, (phase % 2) ? Graphics3D::ANTIALIAS : 0);
        g.render(world.get());
        g.render(immediate.quad.vb.get(), immediate.quad.ib.get(), immediate.appearance.get(), nullptr);
        g.releaseTarget();
        return pixelsOf(*img);
    };
    EXPECT_EQ(renderOnTwoThreads(render, 60), 0);
}

// The same with a skinned, animated corpus model: each thread loads its own
// copy once (skinning runs on the shared skinning thread pool).
TEST_F(VkTest, TwoThreadsRenderSkinnedCorpusModel) {
    const std::filesystem::path file = std::filesystem::path(M3G_CORPUS_DIR) / "models" / "bryan10328__java-m3g" /
                                       "res" / "mahosyojo-with-sexy-walking.m3g";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << "corpus file not found: " << file;
    // One World per (Graphics3D, variant): worlds are never shared between threads.
    std::mutex worldsMutex;
    std::map<std::pair<Graphics3D*, int>, Ref<World>> worlds;
    const FrameFn render = [&](Graphics3D& g, int variant, int phase) {
        Ref<World> world;
        {
            std::lock_guard lock(worldsMutex);
            world = worlds[{&g, variant}];
        }
        if (!world) {
            world = m3gcli::prepareScene(Loader::loadDetailed(file.string()), kSize, kSize).world;
            std::lock_guard lock(worldsMutex);
            worlds[{&g, variant}] = world;
        }
        world->animate(variant * 5000 + phase * 400);
        Ref<Image2D> img(new Image2D(Image2D::RGB, kSize, kSize));
        g.bindTarget(img.get());
        g.render(world.get());
        g.releaseTarget();
        return pixelsOf(*img);
    };
    EXPECT_EQ(renderOnTwoThreads(render, 24), 0);
}
