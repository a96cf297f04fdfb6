// `m3g render` run in-process (cmdRender, the code the m3g tool runs) on the
// project's sample scene, on archives written here, and on corpus files when
// ../shared/corpus is present. Assertions are on the PNG files produced.
#include "VkTestSupport.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../unit/ZipTestWriter.h"
#include "Commands.h"
#include "ImageIO.h"
#include "SampleScene.h"

using namespace m3g;
using m3gcli::RgbaImage;
using m3gtest::VkTest;
namespace fs = std::filesystem;

namespace {

class CliRenderTest : public VkTest {
protected:
    void SetUp() override {
        VkTest::SetUp();
        dir_ = fs::temp_directory_path() /
               ("m3g_cli_render_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        Ref<World> world = m3gcli::buildSampleScene();
        Object3D* roots[] = {world.get()};
        Saver::save(sample().string(), roots);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
        VkTest::TearDown();
    }

    fs::path sample() const { return dir_ / "sample.m3g"; }
    fs::path at(const std::string& name) const { return dir_ / name; }

    static int render(const std::vector<std::string>& args) {
        std::vector<std::string_view> views(args.begin(), args.end());
        return m3gcli::cmdRender(views);
    }
    /// A render of the sample at 64x48 with extra arguments.
    int renderSample(const std::string& out, std::vector<std::string> extra = {}) const {
        std::vector<std::string> args = {sample().string(), "-o", at(out).string(), "--size", "64x48"};
        args.insert(args.end(), extra.begin(), extra.end());
        return render(args);
    }
    static std::vector<std::uint8_t> bytes(const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }
    static bool identical(const RgbaImage& a, const RgbaImage& b) {
        return a.width == b.width && a.height == b.height && a.pixels == b.pixels;
    }
    static std::uint32_t rgba(const RgbaImage& img, int x, int y) {
        const std::size_t i = (static_cast<std::size_t>(y) * img.width + x) * 4;
        return (std::uint32_t(img.pixels[i]) << 24) | (std::uint32_t(img.pixels[i + 1]) << 16) |
               (std::uint32_t(img.pixels[i + 2]) << 8) | img.pixels[i + 3];
    }

    fs::path dir_;
};

}  // namespace

TEST_F(CliRenderTest, FramesWriteOnePngPerFrameAtTheFrameTimes) {
    // 4 frames at 4 fps: 0, 250, 500, 750 ms of the sample's 4 s cube spin.
    ASSERT_EQ(renderSample("anim_{frame}.png", {"--frames", "4", "--fps", "4"}), 0);
    std::vector<RgbaImage> frames;
    for (int k = 0; k < 4; ++k) {
        const fs::path p = at("anim_000" + std::to_string(k) + ".png");
        ASSERT_TRUE(fs::exists(p)) << p;
        frames.push_back(m3gcli::readPng(p.string()));
        EXPECT_EQ(frames.back().width, 64);
        EXPECT_EQ(frames.back().height, 48);
    }
    EXPECT_FALSE(fs::exists(at("anim_0004.png")));
    for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b) EXPECT_FALSE(identical(frames[a], frames[b])) << a << " vs " << b;
    // Frame 2 is the scene at 500 ms: the same pixels as a plain render at --time 500.
    ASSERT_EQ(renderSample("t500.png", {"--time", "500"}), 0);
    EXPECT_TRUE(identical(frames[2], m3gcli::readPng(at("t500.png").string())));
}

TEST_F(CliRenderTest, FramePatternDefaultsToSuffixBeforeTheExtension) {
    ASSERT_EQ(renderSample("seq.png", {"--frames", "2", "--fps", "10"}), 0);
    EXPECT_TRUE(fs::exists(at("seq_0000.png")));
    EXPECT_TRUE(fs::exists(at("seq_0001.png")));
    EXPECT_FALSE(fs::exists(at("seq.png")));
}

TEST_F(CliRenderTest, TurntableFrameZeroIsThePlainRenderAndTheOthersDiffer) {
    ASSERT_EQ(renderSample("turn_{frame}.png", {"--turntable", "4"}), 0);
    ASSERT_EQ(renderSample("plain.png"), 0);
    const RgbaImage plain = m3gcli::readPng(at("plain.png").string());
    std::vector<RgbaImage> frames;
    for (int k = 0; k < 4; ++k) frames.push_back(m3gcli::readPng(at("turn_000" + std::to_string(k) + ".png").string()));
    EXPECT_FALSE(fs::exists(at("turn_0004.png")));
    EXPECT_TRUE(identical(frames[0], plain));
    for (int k = 1; k < 4; ++k) {
        const m3gcli::Comparison c = m3gcli::compareImages(frames[0], frames[k], 8);
        EXPECT_GT(c.share, 0.05) << "turntable frame " << k << " looks like frame 0";
    }
}

TEST_F(CliRenderTest, BackgroundColourFillsTheEmptyPixelsWithAlpha) {
    // The sample's camera looks 15 degrees down from above the ground: the top
    // corners of the image show only the background.
    ASSERT_EQ(renderSample("bg.png", {"--background", "FF008040"}), 0);
    const RgbaImage bg = m3gcli::readPng(at("bg.png").string());
    EXPECT_EQ(rgba(bg, 0, 0), 0xFF008040u);
    EXPECT_EQ(rgba(bg, 63, 0), 0xFF008040u);
    ASSERT_EQ(renderSample("clear.png", {"--background", "transparent"}), 0);
    const RgbaImage clear = m3gcli::readPng(at("clear.png").string());
    EXPECT_EQ(rgba(clear, 0, 0), 0x00000000u);
    // The opaque cube in the middle keeps alpha 255.
    EXPECT_EQ(rgba(clear, 32, 24) & 0xFFu, 0xFFu);
    // Without --background: the file's own background colour (0x1E2838), opaque.
    ASSERT_EQ(renderSample("own.png"), 0);
    EXPECT_EQ(rgba(m3gcli::readPng(at("own.png").string()), 0, 0), 0x1E2838FFu);
}

TEST_F(CliRenderTest, ReferenceComparisonIsTheExitStatus) {
    ASSERT_EQ(renderSample("ref.png"), 0);
    EXPECT_EQ(renderSample("again.png", {"--reference", at("ref.png").string()}), 0);
    ASSERT_EQ(renderSample("later.png", {"--time", "1000"}), 0);
    // The cube has turned a quarter: far more than 1% of the pixels differ.
    EXPECT_EQ(renderSample("x.png", {"--time", "1000", "--reference", at("ref.png").string()}), 1);
    // ... unless no difference can exceed the threshold.
    EXPECT_EQ(renderSample("y.png", {"--time", "1000", "--reference", at("ref.png").string(), "--threshold", "255"}), 0);
    // A reference of another size is a mismatch (1); a missing one cannot be
    // read (3) and nothing is written; bad usage: 2.
    ASSERT_EQ(render({sample().string(), "-o", at("big.png").string(), "--size", "80x60"}), 0);
    EXPECT_EQ(renderSample("z.png", {"--reference", at("big.png").string()}), 1);
    EXPECT_EQ(renderSample("none-out.png", {"--reference", at("none.png").string()}), 3);
    EXPECT_FALSE(fs::exists(at("none-out.png")));
    EXPECT_EQ(renderSample("z.png", {"--reference", at("ref.png").string(), "--frames", "2"}), 2);
}

TEST_F(CliRenderTest, CameraIndexCountsCamerasInFileOrder) {
    ASSERT_EQ(renderSample("plain.png"), 0);
    ASSERT_EQ(renderSample("cam0.png", {"--camera-index", "0"}), 0);
    EXPECT_TRUE(identical(m3gcli::readPng(at("plain.png").string()), m3gcli::readPng(at("cam0.png").string())));
    testing::internal::CaptureStderr();
    const int status = renderSample("cam1.png", {"--camera-index", "1"});
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(status, 2);  // the option does not fit the file: a usage error
    EXPECT_NE(err.find("the file has 1 Camera"), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(at("cam1.png")));
}

TEST_F(CliRenderTest, CameraIndexSelectsAnotherCamera) {
    // The sample plus a second camera, looking straight down from above.
    Ref<World> world = m3gcli::buildSampleScene();
    Ref<Camera> top(new Camera());
    top->setPerspective(60.0f, 4.0f / 3.0f, 0.5f, 50.0f);
    top->setTranslation(0.0f, 3.0f, 0.0f);
    top->setOrientation(-90.0f, 1.0f, 0.0f, 0.0f);
    world->addChild(top.get());
    Object3D* roots[] = {world.get()};
    Saver::save(at("two.m3g").string(), roots);
    ASSERT_EQ(render({at("two.m3g").string(), "-o", at("c0.png").string(), "--size", "64x48", "--camera-index", "0"}), 0);
    ASSERT_EQ(render({at("two.m3g").string(), "-o", at("c1.png").string(), "--size", "64x48", "--camera-index", "1"}), 0);
    const RgbaImage c0 = m3gcli::readPng(at("c0.png").string()), c1 = m3gcli::readPng(at("c1.png").string());
    // From 4.2 units above the 8x8 ground, it fills the whole view: no background at the corner.
    EXPECT_EQ(rgba(c0, 0, 0), 0x1E2838FFu);
    EXPECT_NE(rgba(c1, 0, 0), 0x1E2838FFu);
}

TEST_F(CliRenderTest, BatchOverAFolderRendersEveryM3gAndReportsFailures) {
    const fs::path in = at("in");
    fs::create_directories(in / "sub");
    fs::copy_file(sample(), in / "a.m3g");
    fs::copy_file(sample(), in / "sub" / "b.M3G");
    fs::copy_file(sample(), in / "sub" / "level.res");  // M3G data under a game's own extension
    std::ofstream(in / "broken.m3g") << "not an m3g file";
    std::ofstream(in / "notes.txt") << "ignored";
    testing::internal::CaptureStdout();
    const int status = render({in.string(), "-o", at("out").string(), "--size", "32x24"});
    const std::string out = testing::internal::GetCapturedStdout();
    EXPECT_EQ(status, 3);  // one file failed to load
    EXPECT_NE(out.find("4 file(s)"), std::string::npos) << out;
    EXPECT_NE(out.find("3 ok, 1 failed"), std::string::npos) << out;
    EXPECT_NE(out.find("failed: " + (in / "broken.m3g").string() + ": "), std::string::npos) << out;
    EXPECT_NE(out.find("skipped 1 file(s) that are not M3G data"), std::string::npos) << out;
    EXPECT_NE(out.find("notes.txt"), std::string::npos) << out;
    EXPECT_TRUE(fs::exists(at("out") / "a.png"));
    EXPECT_TRUE(fs::exists(at("out") / "sub" / "b.png"));
    EXPECT_TRUE(fs::exists(at("out") / "sub" / "level.res.png")) << "found by its identifier, not its name";
    EXPECT_FALSE(fs::exists(at("out") / "broken.png"));
    EXPECT_FALSE(fs::exists(at("out") / "notes.png"));
    EXPECT_EQ(m3gcli::readPng((at("out") / "a.png").string()).width, 32);

    fs::remove(in / "broken.m3g");
    testing::internal::CaptureStdout();
    EXPECT_EQ(render({in.string(), "-o", at("out2").string(), "--size", "32x24", "--frames", "2"}), 0);
    testing::internal::GetCapturedStdout();
    EXPECT_TRUE(fs::exists(at("out2") / "a_0000.png"));
    EXPECT_TRUE(fs::exists(at("out2") / "sub" / "b_0001.png"));
    EXPECT_EQ(render({in.string(), "--size", "32x24"}), 2);  // no output folder
}

TEST_F(CliRenderTest, BatchOverAJarRendersItsM3gEntries) {
    const fs::path jar = at("game.jar");
    m3gtest::writeZip(jar, {{"META-INF/MANIFEST.MF", {'M'}},
                            {"Game.class", std::vector<std::uint8_t>(64, 0xCA)},
                            {"res/level.m3g", bytes(sample())},
                            {"res/models/car.mod", bytes(sample())},
                            {"res/broken.m3g", {'x', 'y'}}});
    testing::internal::CaptureStdout();
    const int status = render({jar.string(), "-o", at("out").string(), "--size", "32x24"});
    const std::string out = testing::internal::GetCapturedStdout();
    EXPECT_EQ(status, 3);
    EXPECT_NE(out.find("2 ok, 1 failed"), std::string::npos) << out;
    EXPECT_NE(out.find(jar.string() + "!/res/broken.m3g"), std::string::npos) << out;
    EXPECT_NE(out.find("skipped 2 file(s) that are not M3G data"), std::string::npos) << out;
    EXPECT_NE(out.find("Game.class"), std::string::npos) << out;
    EXPECT_TRUE(fs::exists(at("out") / "res" / "level.png"));
    EXPECT_TRUE(fs::exists(at("out") / "res" / "models" / "car.mod.png")) << "found by its identifier, not its name";
    // The same pixels as rendering the file directly.
    ASSERT_EQ(render({sample().string(), "-o", at("direct.png").string(), "--size", "32x24"}), 0);
    EXPECT_TRUE(identical(m3gcli::readPng((at("out") / "res" / "level.png").string()),
                          m3gcli::readPng(at("direct.png").string())));
    // A .jar that is not a zip is rendered as a file (and fails as one).
    std::ofstream(at("fake.jar")) << "plain text";
    EXPECT_EQ(render({at("fake.jar").string(), "-o", at("fake.png").string()}), 3);
}

TEST_F(CliRenderTest, JpegOutputHasTheRenderedPixels) {
    // -o x.jpg writes a JPEG (read back by the library's decoder), close to the PNG.
    ASSERT_EQ(renderSample("plain.png"), 0);
    ASSERT_EQ(renderSample("plain.jpg"), 0);
    const std::vector<std::uint8_t> jpeg = bytes(at("plain.jpg"));
    ASSERT_GE(jpeg.size(), 3u);
    EXPECT_EQ(jpeg[0], 0xFF);
    EXPECT_EQ(jpeg[1], 0xD8);  // SOI marker
    Ref<Image2D> decoded = dynamic_cast<Image2D*>(Loader::load(at("plain.jpg").string()).at(0).get());
    ASSERT_NE(decoded.get(), nullptr);
    EXPECT_EQ(decoded->getWidth(), 64);
    EXPECT_EQ(decoded->getHeight(), 48);
    RgbaImage fromJpeg;
    fromJpeg.width = 64;
    fromJpeg.height = 48;
    decoded->getPixelsRGBA8(fromJpeg.pixels);
    const m3gcli::Comparison c = m3gcli::compareImages(fromJpeg, m3gcli::readPng(at("plain.png").string()), 48);
    EXPECT_LT(c.share, 0.05);
    // An extension the tool does not write is refused, nothing written.
    EXPECT_EQ(renderSample("plain.bmp"), 2);
    EXPECT_FALSE(fs::exists(at("plain.bmp")));
}

TEST_F(CliRenderTest, UniformImageGetsAHint) {
    // A PNG file has no nodes: the auto-framed empty World is all background.
    ASSERT_EQ(renderSample("plain.png"), 0);
    testing::internal::CaptureStderr();
    ASSERT_EQ(render({at("plain.png").string(), "-o", at("empty.png").string(), "--size", "32x24"}), 0);
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("is uniform"), std::string::npos) << err;
    testing::internal::CaptureStderr();
    ASSERT_EQ(renderSample("again.png"), 0);
    EXPECT_EQ(testing::internal::GetCapturedStderr().find("is uniform"), std::string::npos);
}

TEST_F(CliRenderTest, CorpusTeapotTurntable) {
    const fs::path teapot = fs::path(M3G_CORPUS_DIR) / "models/jacques-gasselin__m3x/tools/test/data/teapot.m3g";
    if (!fs::exists(teapot)) GTEST_SKIP() << "no shared corpus file " << teapot << " (skipped)";
    ASSERT_EQ(render({teapot.string(), "-o", at("tp_{frame}.png").string(), "--size", "64x48", "--turntable", "3"}), 0);
    ASSERT_EQ(render({teapot.string(), "-o", at("tp.png").string(), "--size", "64x48"}), 0);
    const RgbaImage f0 = m3gcli::readPng(at("tp_0000.png").string());
    EXPECT_TRUE(identical(f0, m3gcli::readPng(at("tp.png").string())));
    for (int k = 1; k < 3; ++k)
        EXPECT_FALSE(identical(f0, m3gcli::readPng(at("tp_000" + std::to_string(k) + ".png").string()))) << k;
    // A render compared with an identical one passes.
    EXPECT_EQ(render({teapot.string(), "-o", at("tp2.png").string(), "--size", "64x48", "--reference",
                      at("tp.png").string()}),
              0);
}

// A Z-up model (BaalNetbek's robot: its camera's up is +Z) stays upright
// through the turntable: about the scene's own up its height on screen
// holds within 10% in every frame; about +Y (--up +Y) it lies down at 90
// and 270 degrees (measured: 96, 50, 94, 44 pixel rows at 320x240), so the
// test sees the difference.
TEST_F(CliRenderTest, ZUpTurntableKeepsTheModelUpright) {
    const fs::path robot = fs::path(M3G_CORPUS_DIR) / "models/BaalNetbek__M3G-Viewer/com.wizzer.m3g.toolkit/test/robot.m3g";
    if (!fs::exists(robot)) GTEST_SKIP() << "no shared corpus file " << robot << " (skipped)";
    // Rows holding a pixel unlike the top-left corner (the background).
    auto height = [](const RgbaImage& img) {
        int top = img.height, bottom = -1;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x)
                if (std::memcmp(&img.pixels[(static_cast<std::size_t>(y) * img.width + x) * 4], img.pixels.data(), 3) != 0) {
                    top = std::min(top, y);
                    bottom = std::max(bottom, y);
                }
        return bottom >= top ? bottom - top + 1 : 0;
    };
    auto heights = [&](const std::string& prefix, std::vector<std::string> extra) {
        std::vector<std::string> args = {robot.string(), "-o", at(prefix + "_{frame}.png").string(), "--turntable", "4"};
        args.insert(args.end(), extra.begin(), extra.end());
        EXPECT_EQ(render(args), 0);
        std::vector<int> h;
        for (int k = 0; k < 4; ++k) h.push_back(height(m3gcli::readPng(at(prefix + "_000" + std::to_string(k) + ".png").string())));
        return h;
    };
    const std::vector<int> own = heights("own", {});
    const std::vector<int> y = heights("y", {"--up", "+Y"});
    ASSERT_GT(own[0], 40);
    for (int k = 1; k < 4; ++k) EXPECT_GE(own[k] * 10, own[0] * 9) << "frame " << k << " about the scene's up";
    EXPECT_LT(std::min(y[1], y[3]) * 10, own[0] * 7) << "about +Y the model should lie down at 90 and 270 degrees";
}
