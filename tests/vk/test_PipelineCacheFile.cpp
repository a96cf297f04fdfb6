// The pipeline cache file (render-vk/PipelineCacheFile.h): the header check
// on hand-made headers, and a renderer that writes the file after its first
// frame, seeds the next renderer from it, and shrugs off a corrupt one.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include "Context.h"
#include "PipelineCacheFile.h"
#include "VkTestSupport.h"

using namespace m3g;
namespace fs = std::filesystem;

namespace {

VkPhysicalDeviceProperties someDevice() {
    VkPhysicalDeviceProperties p{};
    p.vendorID = 0x10de;
    p.deviceID = 0x2335;
    for (std::uint32_t i = 0; i < VK_UUID_SIZE; ++i) p.pipelineCacheUUID[i] = static_cast<std::uint8_t>(i * 7 + 1);
    return p;
}

/// A version-one header as the Vulkan specification lays it out, then `extra` payload bytes.
std::vector<std::uint8_t> header(const VkPhysicalDeviceProperties& p, std::uint32_t headerSize = 32,
                                 std::uint32_t version = VK_PIPELINE_CACHE_HEADER_VERSION_ONE, std::size_t extra = 8) {
    std::vector<std::uint8_t> out(32 + extra, 0xAB);
    const std::uint32_t words[4] = {headerSize, version, p.vendorID, p.deviceID};
    std::memcpy(out.data(), words, 16);
    std::memcpy(out.data() + 16, p.pipelineCacheUUID, VK_UUID_SIZE);
    return out;
}

/// Sets an environment variable for one scope.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old, had_ = true;
        setenv(name, value.c_str(), 1);
    }
    ~ScopedEnv() {
        if (had_)
            setenv(name_, old_.c_str(), 1);
        else
            unsetenv(name_);
    }

private:
    const char* name_;
    std::string old_;
    bool had_ = false;
};

/// One frame on a renderer of its own: a background image's quad, which
/// needs a pipeline.
void renderOnce(Image2D& target, Background& bg) {
    std::unique_ptr<Graphics3D> g = Graphics3D::create();
    g->bindTarget(&target);
    g->clear(&bg);
    g->releaseTarget();
}

}  // namespace

TEST(PipelineCacheFile, HeaderOfThisDeviceMatches) {
    const auto p = someDevice();
    EXPECT_TRUE(m3g::vk::pipelineCacheMatches(header(p), p));
    EXPECT_TRUE(m3g::vk::pipelineCacheMatches(header(p, 40, VK_PIPELINE_CACHE_HEADER_VERSION_ONE, 8), p));
}

TEST(PipelineCacheFile, OtherDevicesAndMalformedHeadersAreRefused) {
    const auto p = someDevice();
    auto other = p;
    other.vendorID = 0x1002;
    EXPECT_FALSE(m3g::vk::pipelineCacheMatches(header(other), p)) << "another vendor";
    other = p;
    other.deviceID ^= 1;
    EXPECT_FALSE(m3g::vk::pipelineCacheMatches(header(other), p)) << "another device";
    other = p;
    other.pipelineCacheUUID[15] ^= 0x80;
    EXPECT_FALSE(m3g::vk::pipelineCacheMatches(header(other), p)) << "another driver build (UUID)";
    EXPECT_FALSE(m3g::vk::pipelineCacheMatches(header(p, 32, 2), p)) << "unknown header version";
    EXPECT_FALSE(m3g::vk::pipelineCacheMatches(header(p, 31), p)) << "header size below the header";
    EXPECT_FALSE(m3g::vk::pipelineCacheMatches(header(p, 41, VK_PIPELINE_CACHE_HEADER_VERSION_ONE, 8), p))
        << "header size past the data";
    auto whole = header(p);
    EXPECT_FALSE(m3g::vk::pipelineCacheMatches(std::span(whole).first(31), p)) << "truncated";
    EXPECT_FALSE(m3g::vk::pipelineCacheMatches({}, p)) << "empty";
}

TEST(PipelineCacheFile, PathFollowsEnvironment) {
    const auto p = someDevice();
    {
        ScopedEnv file("M3G_VK_PIPELINE_CACHE", "/tmp/x/cache.bin");
        EXPECT_EQ(m3g::vk::pipelineCachePath(p), "/tmp/x/cache.bin");
    }
    {
        ScopedEnv off("M3G_VK_PIPELINE_CACHE", "off");
        EXPECT_EQ(m3g::vk::pipelineCachePath(p), "");
    }
    ScopedEnv unset("M3G_VK_PIPELINE_CACHE", "");
    ScopedEnv xdg("XDG_CACHE_HOME", "/var/cache/me");
    EXPECT_EQ(m3g::vk::pipelineCachePath(p),
              "/var/cache/me/m3g-vk/pipelines-10de-2335-01080f161d242b323940474e555c636a.bin");
}

TEST(PipelineCacheFile, ReadRefusesMissingForeignAndWriteFailsOnBadPath) {
    const auto p = someDevice();
    const fs::path dir = fs::temp_directory_path() / ("m3g-pcache-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    EXPECT_TRUE(m3g::vk::readPipelineCache((dir / "none.bin").string(), p).empty());
    const auto good = header(p);
    ASSERT_TRUE(m3g::vk::writePipelineCache((dir / "sub" / "c.bin").string(), good)) << "creates the folder";
    EXPECT_EQ(m3g::vk::readPipelineCache((dir / "sub" / "c.bin").string(), p), good);
    auto other = p;
    other.deviceID = 1;
    EXPECT_TRUE(m3g::vk::readPipelineCache((dir / "sub" / "c.bin").string(), other).empty());
    std::ofstream(dir / "junk.bin") << "not a pipeline cache at all, but long enough to hold a header";
    EXPECT_TRUE(m3g::vk::readPipelineCache((dir / "junk.bin").string(), p).empty());
    EXPECT_FALSE(m3g::vk::writePipelineCache((dir / "junk.bin" / "below-a-file.bin").string(), good));
    EXPECT_FALSE(fs::exists(dir / ("junk.bin.tmp." + std::to_string(::getpid()))));
    fs::remove_all(dir);
}

namespace m3gtest {

TEST_F(VkTest, PipelineCacheWrittenAfterFirstFrameAndSeedsTheNext) {
    const fs::path dir = fs::temp_directory_path() / ("m3g-pcache-vk-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    const fs::path file = dir / "pipelines.bin";
    ScopedEnv env("M3G_VK_PIPELINE_CACHE", file.string());

    const std::vector<std::uint8_t> grey{200, 200, 200, 255, 200, 200, 200, 255, 200, 200, 200, 255, 200, 200, 200, 255};
    Ref<Image2D> img(new Image2D(Image2D::RGBA, 2, 2, std::span<const std::uint8_t>(grey)));  // the target's format
    Ref<Background> bg(new Background());
    bg->setImage(img.get());
    auto out = target(16, 16);
    const auto before = m3g::vk::renderStats();
    renderOnce(*out, *bg);
    EXPECT_EQ(pixel(*out, 8, 8), 0xFFC8C8C8u) << "the background image drawn";
    const auto afterFirst = m3g::vk::renderStats();
    ASSERT_TRUE(fs::exists(file)) << "written after the frame that created pipelines";
    EXPECT_GT(afterFirst.pipelineCacheSaves, before.pipelineCacheSaves);
    const VkPhysicalDeviceProperties& props = m3g::vk::Context::get().properties();
    std::vector<std::uint8_t> bytes(fs::file_size(file));
    std::ifstream(file, std::ios::binary).read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    EXPECT_TRUE(m3g::vk::pipelineCacheMatches(bytes, props)) << "the driver's header for this device";

    // The next renderer is seeded with the file.
    auto out2 = target(16, 16);
    renderOnce(*out2, *bg);
    EXPECT_EQ(pixel(*out2, 8, 8), 0xFFC8C8C8u);
    EXPECT_GE(m3g::vk::renderStats().pipelineCacheBytesLoaded - afterFirst.pipelineCacheBytesLoaded, bytes.size());

    // A corrupt file: the renderer starts with an empty cache, draws the
    // same, the validation layer says nothing (TearDown), and the file is
    // a valid cache again once it has been rewritten.
    {
        std::ofstream junk(file, std::ios::binary | std::ios::trunc);
        junk << std::string(4096, '\x7f');
    }
    const auto beforeJunk = m3g::vk::renderStats();
    auto out3 = target(16, 16);
    {
        std::unique_ptr<Graphics3D> g = Graphics3D::create();
        g->bindTarget(out3.get());
        g->clear(bg.get());
        g->releaseTarget();
        EXPECT_EQ(m3g::vk::renderStats().pipelineCacheBytesLoaded, beforeJunk.pipelineCacheBytesLoaded)
            << "nothing of the corrupt file reached the driver";
    }
    EXPECT_EQ(pixel(*out3, 8, 8), 0xFFC8C8C8u);
    bytes.assign(fs::file_size(file), 0);
    std::ifstream(file, std::ios::binary).read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    EXPECT_TRUE(m3g::vk::pipelineCacheMatches(bytes, props)) << "rewritten by the renderer that created pipelines";
    fs::remove_all(dir);
}

}  // namespace m3gtest
