// The m3g tool's driver filter (tools/m3g/DriverFilter.h): which GPU drivers
// the loader is told to skip, from the device nodes of a made-up /dev.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "DriverFilter.h"

namespace fs = std::filesystem;
using namespace m3gcli;

namespace {

// A temporary folder standing for /dev, with the named files in it.
struct FakeDev {
    fs::path root;
    explicit FakeDev(std::initializer_list<const char*> files) {
        root = fs::temp_directory_path() / ("m3g-fakedev-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                            "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root);
        fs::create_directories(root);
        for (const char* f : files) {
            fs::create_directories((root / f).parent_path());
            std::ofstream(root / f).put('\n');
        }
    }
    ~FakeDev() { fs::remove_all(root); }
};

const std::string kMesa = "intel_*,radeon_*,nouveau_*,freedreno_*,panfrost_*,broadcom_*,asahi_*,virtio_*,powervr_mesa_*";

}  // namespace

TEST(DriverFilter, NoGpuNodesSkipsEveryGpuDriverButNeverSoftwareOnes) {
    FakeDev dev({"null", "tty0"});
    const DeviceNodes nodes = findDeviceNodes(dev.root);
    EXPECT_FALSE(nodes.renderNode);
    EXPECT_FALSE(nodes.nvidia);
    EXPECT_FALSE(nodes.dxg);
    const std::string globs = driverGlobsToDisable(nodes);
    EXPECT_EQ(globs, kMesa + ",nvidia_*,dzn_*");
    // lavapipe's and SwiftShader's manifests match none of them.
    EXPECT_EQ(globs.find("lvp"), std::string::npos);
    EXPECT_EQ(globs.find("swiftshader"), std::string::npos);
}

TEST(DriverFilter, ARenderNodeKeepsMesasGpuDrivers) {
    FakeDev dev({"dri/card0", "dri/renderD128"});
    const DeviceNodes nodes = findDeviceNodes(dev.root);
    EXPECT_TRUE(nodes.renderNode);
    EXPECT_EQ(driverGlobsToDisable(nodes), "nvidia_*,dzn_*");
}

TEST(DriverFilter, ACardNodeAloneIsNoRenderNode) {
    FakeDev dev({"dri/card0", "dri/by-path/x"});
    EXPECT_FALSE(findDeviceNodes(dev.root).renderNode);
}

TEST(DriverFilter, NvidiaAndDxgNodesKeepTheirDrivers) {
    FakeDev dev({"nvidia0", "dxg"});  // any /dev/nvidia* node, nvidiactl or not
    const DeviceNodes nodes = findDeviceNodes(dev.root);
    EXPECT_TRUE(nodes.nvidia);
    EXPECT_TRUE(nodes.dxg);
    EXPECT_EQ(driverGlobsToDisable(nodes), kMesa);
    EXPECT_EQ(driverGlobsToDisable({true, true, true}), "");
}

#if defined(__linux__)
// The user's own choice of drivers, or M3G_VK_ALL_DRIVERS=1, wins: nothing is
// set. Otherwise the variable holds what /dev says.
TEST(DriverFilter, TheUsersChoiceWins) {
    ::unsetenv("VK_LOADER_DRIVERS_DISABLE");
    ::unsetenv("M3G_VK_ALL_DRIVERS");
    for (const char* chosen : {"VK_DRIVER_FILES", "VK_ICD_FILENAMES", "VK_ADD_DRIVER_FILES", "VK_LOADER_DRIVERS_SELECT"})
        ::unsetenv(chosen);
    ::setenv("VK_DRIVER_FILES", "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json", 1);
    EXPECT_EQ(skipDriversWithoutDevices(), "");
    EXPECT_EQ(std::getenv("VK_LOADER_DRIVERS_DISABLE"), nullptr);
    ::unsetenv("VK_DRIVER_FILES");
    ::setenv("M3G_VK_ALL_DRIVERS", "1", 1);
    EXPECT_EQ(skipDriversWithoutDevices(), "");
    EXPECT_EQ(std::getenv("VK_LOADER_DRIVERS_DISABLE"), nullptr);
    ::unsetenv("M3G_VK_ALL_DRIVERS");
    const std::string expected = driverGlobsToDisable(findDeviceNodes("/dev"));
    EXPECT_EQ(skipDriversWithoutDevices(), expected);
    const char* set = std::getenv("VK_LOADER_DRIVERS_DISABLE");
    if (expected.empty())
        EXPECT_EQ(set, nullptr);
    else
        EXPECT_EQ(std::string(set ? set : "(unset)"), expected);
    // Set once: a user's later value is not overwritten by a second call.
    ::setenv("VK_LOADER_DRIVERS_DISABLE", "mine_*", 1);
    EXPECT_EQ(skipDriversWithoutDevices(), "");
    EXPECT_STREQ(std::getenv("VK_LOADER_DRIVERS_DISABLE"), "mine_*");
    ::unsetenv("VK_LOADER_DRIVERS_DISABLE");
}
#endif
