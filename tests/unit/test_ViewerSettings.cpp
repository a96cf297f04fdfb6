// The viewer's remembered settings (tools/m3g/viewer/ViewerSettings.h): the
// recent files, most recent first, absolute, at most kMaxRecent, kept
// through save and load.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "ViewerSettings.h"

using m3gview::Settings;
namespace fs = std::filesystem;

namespace {

// XDG_CONFIG_HOME pointed at a private folder for the test's life.
struct ConfigHome {
    fs::path path;
    std::string before;
    bool had = false;
    ConfigHome() {
        path = fs::temp_directory_path() / ("m3g_settings_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                             "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path);
        if (const char* v = std::getenv("XDG_CONFIG_HOME")) {
            before = v;
            had = true;
        }
        setenv("XDG_CONFIG_HOME", path.c_str(), 1);
    }
    ~ConfigHome() {
        if (had) setenv("XDG_CONFIG_HOME", before.c_str(), 1);
        else unsetenv("XDG_CONFIG_HOME");
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

}  // namespace

TEST(ViewerSettings, RecentFilesAreAbsoluteMostRecentFirstAndBounded) {
    Settings s;
    s.remember("/models/a.m3g");
    s.remember("/models/b.res");
    s.remember("/models/a.m3g");  // again: moves to the front, once
    EXPECT_EQ(s.recent, (std::vector<std::string>{"/models/a.m3g", "/models/b.res"}));
    s.remember("rel/c.m3g");
    EXPECT_EQ(s.recent.front(), (fs::current_path() / "rel/c.m3g").string());
    s.remember("/games/x.jar!models/ship.m3g");  // the entry after the archive's path
    EXPECT_EQ(s.recent.front(), "/games/x.jar!models/ship.m3g");
    for (int i = 0; i < 20; ++i) s.remember("/m/" + std::to_string(i) + ".m3g");
    EXPECT_EQ(s.recent.size(), Settings::kMaxRecent);
    EXPECT_EQ(s.recent.front(), "/m/19.m3g");
    EXPECT_EQ(s.recent.back(), "/m/10.m3g");
}

TEST(ViewerSettings, RecentFilesSurviveSaveAndLoad) {
    ConfigHome home;
    Settings s;
    s.width = 800;
    s.remember("/models/a.m3g");
    s.remember("/models/b.res");
    s.save();
    ASSERT_TRUE(fs::exists(home.path / "m3g-vk" / "viewer.ini"));
    const Settings back = Settings::load();
    EXPECT_EQ(back.width, 800);
    EXPECT_EQ(back.recent, (std::vector<std::string>{"/models/b.res", "/models/a.m3g"}));
    // A broken line is ignored, the rest kept.
    std::ofstream(home.path / "m3g-vk" / "viewer.ini", std::ios::app) << "width=banana\nrecent=\n";
    EXPECT_EQ(Settings::load().recent.size(), 2u);
}
