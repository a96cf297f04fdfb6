// `m3g render` options (tools/m3g/RenderOptions, on CLI11): parsing, background colours
// and frame file names.
#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

#include "CliArgs.h"
#include "RenderOptions.h"

using m3gcli::CliError;
using m3gcli::RenderOptions;

namespace {

RenderOptions parse(std::vector<std::string_view> args) {
    return m3gcli::parseRenderOptions(std::span<const std::string_view>(args));
}

std::string errorOf(std::vector<std::string_view> args) {
    try {
        parse(args);
    } catch (const CliError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST(RenderOptions, Defaults) {
    const RenderOptions o = parse({"a.m3g", "-o", "a.png"});
    EXPECT_EQ(o.input, "a.m3g");
    EXPECT_EQ(o.output, "a.png");
    EXPECT_EQ(o.width, 320);
    EXPECT_EQ(o.height, 240);
    EXPECT_EQ(o.time, 0);
    EXPECT_EQ(o.imageCount(), 1);
    EXPECT_FALSE(o.sequence());
    EXPECT_FALSE(o.background);
    EXPECT_FALSE(o.cameraIndex);
    EXPECT_EQ(o.threshold, 8);
    EXPECT_DOUBLE_EQ(o.maxShare, 0.01);
}

TEST(RenderOptions, ValuesAfterEqualsSign) {
    const RenderOptions o = parse({"a.m3g", "--output=a.jpg", "--size=64x48", "--time=-100", "--frames=3"});
    EXPECT_EQ(o.output, "a.jpg");
    EXPECT_EQ(o.width, 64);
    EXPECT_EQ(o.height, 48);
    EXPECT_EQ(o.time, -100);
    EXPECT_EQ(o.frames, 3);
}

TEST(RenderOptions, AllOptions) {
    const RenderOptions o = parse({"--size", "64x48", "in.m3g", "--frames", "12", "--fps", "24", "--time", "-100",
                                   "--camera-index", "2", "--background", "transparent", "--align", "--lenient",
                                   "-o", "f_{frame}.png"});
    EXPECT_EQ(o.width, 64);
    EXPECT_EQ(o.height, 48);
    EXPECT_EQ(o.frames, 12);
    EXPECT_FLOAT_EQ(o.fps, 24.0f);
    EXPECT_EQ(o.time, -100);
    EXPECT_EQ(o.cameraIndex, 2);
    EXPECT_EQ(o.background, 0x00000000u);
    EXPECT_TRUE(o.align && o.lenient);
    EXPECT_EQ(o.imageCount(), 12);
    const RenderOptions t = parse({"in.m3g", "--turntable", "36"});
    EXPECT_EQ(t.imageCount(), 36);
    EXPECT_TRUE(t.output.empty());  // cmdRender picks out_{frame}.png
    const RenderOptions r = parse({"in.m3g", "-o", "x.png", "--reference", "ref.png", "--threshold", "3",
                                   "--max-share", "0.5", "--min-psnr", "30"});
    EXPECT_EQ(r.reference, "ref.png");
    EXPECT_EQ(r.threshold, 3);
    EXPECT_DOUBLE_EQ(r.maxShare, 0.5);
    EXPECT_DOUBLE_EQ(r.minPsnr, 30.0);
}

TEST(RenderOptions, Errors) {
    EXPECT_NE(errorOf({"-o", "x.png"}).find("missing FILE|DIR|GAME.jar"), std::string::npos);
    EXPECT_NE(errorOf({"a.m3g", "-o", "x.png", "--frames", "3", "--turntable", "4"}).find("exclude each other"),
              std::string::npos);
    EXPECT_NE(errorOf({"a.m3g", "--frames", "3", "--reference", "r.png"}).find("--reference"), std::string::npos);
    EXPECT_NE(errorOf({"a.m3g", "-o", "x.png", "--threshold", "3"}).find("need --reference"), std::string::npos);
    EXPECT_NE(errorOf({"a.m3g", "-o", "x.png", "--frames", "0"}).find("positive integer"), std::string::npos);
    EXPECT_NE(errorOf({"a.m3g", "-o", "x.png", "--fps", "0"}).find("--fps"), std::string::npos);
    EXPECT_NE(errorOf({"a.m3g", "-o", "x.png", "--camera-index", "-1"}).find("--camera-index"), std::string::npos);
    EXPECT_NE(errorOf({"a.m3g", "-o", "x.png", "--background", "red"}).find("RRGGBBAA"), std::string::npos);
    EXPECT_NE(errorOf({"a.m3g", "-o", "x.png", "--reference", "r.png", "--threshold", "256"}).find("[0, 255]"),
              std::string::npos);
    EXPECT_NE(errorOf({"a.m3g", "-o", "-", "--turntable", "3"}).find("stdout"), std::string::npos);
    EXPECT_EQ(errorOf({"a.m3g", "-o", "x.png", "--spin"}), "unknown option '--spin'");
    EXPECT_EQ(errorOf({"a.m3g", "-o", "x.png", "--turntabel", "3"}),
              "unknown option '--turntabel'; did you mean '--turntable'?");
    EXPECT_EQ(errorOf({"a.m3g", "b.m3g", "-o", "x.png"}), "unexpected argument 'b.m3g'");
    EXPECT_NE(errorOf({"a.m3g", "--frames"}).find("--frames"), std::string::npos);
    // --size: WxH within the renderer's limits (2048x2048 by default), never a bad_alloc later.
    EXPECT_NE(errorOf({"a.m3g", "-o", "x.png", "--size", "100000x100000"}).find("exceeds the renderer's limit"),
              std::string::npos);
    EXPECT_NE(errorOf({"a.m3g", "-o", "x.png", "--size", "big"}).find("WxH"), std::string::npos);
}

TEST(RenderOptions, BackgroundColorIsRRGGBBAA) {
    EXPECT_EQ(m3gcli::parseBackgroundColor("FF008040"), 0x40FF0080u);
    EXPECT_EQ(m3gcli::parseBackgroundColor("a1b2c3d4"), 0xD4A1B2C3u);
    EXPECT_EQ(m3gcli::parseBackgroundColor("transparent"), 0x00000000u);
    EXPECT_FALSE(m3gcli::parseBackgroundColor("FF00804"));
    EXPECT_FALSE(m3gcli::parseBackgroundColor("FF0080400"));
    EXPECT_FALSE(m3gcli::parseBackgroundColor("GG008040"));
    EXPECT_FALSE(m3gcli::parseBackgroundColor(""));
}

TEST(RenderOptions, FrameFileNames) {
    EXPECT_EQ(m3gcli::frameFileName("out_{frame}.png", 3, 10), "out_0003.png");
    EXPECT_EQ(m3gcli::frameFileName("{frame}/a{frame}.png", 7, 8), "0007/a0007.png");
    EXPECT_EQ(m3gcli::frameFileName("shot.png", 12, 20), "shot_0012.png");
    EXPECT_EQ(m3gcli::frameFileName("dir.v1/shot", 5, 20), "dir.v1/shot_0005");
    EXPECT_EQ(m3gcli::frameFileName("f{frame}.png", 42, 10000), "f0042.png");   // 9999 fits in 4 digits
    EXPECT_EQ(m3gcli::frameFileName("f{frame}.png", 42, 10001), "f00042.png");  // 10000 needs 5
    EXPECT_EQ(m3gcli::frameFileName("f{frame}.png", 123456, 200000), "f123456.png");
}
