// tools/m3g/CliArgs and CliApp: the values on the m3g command line, and how
// CLI11's parse errors read (unknown names with a suggestion).
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "CliApp.h"
#include "CliArgs.h"

using m3gcli::CliError;

namespace {

/// A small command line: `info [FILE] [--json] [--time T]` and `render FILE
/// [-o OUT] [--size WxH]`.
struct TestApp {
    CLI::App root{"", "m3g"};
    std::string file, time, out, size;
    bool json = false;
    TestApp() {
        root.require_subcommand(0, 1);
        root.set_version_flag("--version", "1.0");
        CLI::App* info = root.add_subcommand("info");
        info->add_option("file", file);
        info->add_flag("--json", json);
        info->add_option("--time", time);
        CLI::App* render = root.add_subcommand("render");
        render->add_option("file", file, "the scene")->type_name("FILE")->required();
        render->add_option("-o,--output", out);
        render->add_option("--size", size);
    }
};

/// The CliError message of parsing `args`, or "" if it parses.
std::string error(std::initializer_list<std::string_view> args) {
    TestApp app;
    try {
        m3gcli::parseArgs(app.root, std::vector<std::string>(args.begin(), args.end()));
    } catch (const CliError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(CliApp, BothOptionValueForms) {
    TestApp a;
    m3gcli::parseArgs(a.root, {"render", "x.m3g", "--size=64x48", "-o", "out.png"});
    EXPECT_EQ(a.file, "x.m3g");
    EXPECT_EQ(a.size, "64x48");
    EXPECT_EQ(a.out, "out.png");
    TestApp b;
    m3gcli::parseArgs(b.root, {"info", "--time", "-20", "--json", "x.m3g"});
    EXPECT_EQ(b.time, "-20");  // a negative number is a value, not an option
    EXPECT_TRUE(b.json);
    TestApp c;
    m3gcli::parseArgs(c.root, {"info", "--", "--json"});
    EXPECT_EQ(c.file, "--json");
    EXPECT_FALSE(c.json);
}

TEST(CliApp, UnknownNamesGetASuggestion) {
    EXPECT_EQ(error({"rendr"}), "unknown command 'rendr'; did you mean 'render'?");
    EXPECT_EQ(error({"frobnicate"}), "unknown command 'frobnicate'");
    EXPECT_EQ(error({"render", "x.m3g", "--szie", "64x48"}), "unknown option '--szie'; did you mean '--size'?");
    EXPECT_EQ(error({"render", "x.m3g", "--szie=64x48"}), "unknown option '--szie'; did you mean '--size'?");
    EXPECT_EQ(error({"info", "x", "--jsn"}), "unknown option '--jsn'; did you mean '--json'?");
    EXPECT_EQ(error({"--verison"}), "unknown option '--verison'; did you mean '--version'?");
    // The unknown option is named even when a required operand is missing too.
    EXPECT_EQ(error({"render", "--szie", "1x1"}), "unknown option '--szie'; did you mean '--size'?");
}

TEST(CliApp, OtherParseErrors) {
    EXPECT_EQ(error({"info", "a", "b"}), "unexpected argument 'b'");
    EXPECT_EQ(error({"render"}), "missing FILE (the scene)");
    EXPECT_NE(error({"info", "x", "--time"}).find("--time"), std::string::npos);
    EXPECT_EQ(error({"info", "x"}), "");
}

TEST(CliApp, ExitCodesAreListed) {
    const std::string text = m3gcli::exitCodesText();
    for (const char* code : {"  0  ", "  1  ", "  2  ", "  3  ", "  4  ", "  5  "})
        EXPECT_NE(text.find(code), std::string::npos) << code;
    EXPECT_EQ(m3gcli::kExitInput, 3);
    EXPECT_EQ(m3gcli::kExitOutput, 4);
}

TEST(CliArgs, ParseInt) {
    EXPECT_EQ(m3gcli::parseInt("0"), 0);
    EXPECT_EQ(m3gcli::parseInt("-2147483648"), -2147483647 - 1);
    EXPECT_EQ(m3gcli::parseInt("2147483647"), 2147483647);
    EXPECT_FALSE(m3gcli::parseInt("2147483648"));
    EXPECT_FALSE(m3gcli::parseInt(""));
    EXPECT_FALSE(m3gcli::parseInt("+"));
    EXPECT_FALSE(m3gcli::parseInt("+-1"));
    EXPECT_FALSE(m3gcli::parseInt(" 1"));
    EXPECT_FALSE(m3gcli::parseInt("1.5"));
}

TEST(CliArgs, ParseSize) {
    int w = 7, h = 9;
    EXPECT_TRUE(m3gcli::parseSize("320x240", w, h));
    EXPECT_EQ(w, 320);
    EXPECT_EQ(h, 240);
    for (const char* bad : {"320", "x240", "320x", "0x240", "320x-1", "320X240", "3.5x2", "320x240x1"}) {
        EXPECT_FALSE(m3gcli::parseSize(bad, w, h)) << bad;
        EXPECT_EQ(w, 320) << bad;  // left alone
        EXPECT_EQ(h, 240) << bad;
    }
}

TEST(CliArgs, SizeLimits) {
    EXPECT_FALSE(m3gcli::sizeLimitError("--size", 2048, 2048, 2048, 2048));
    EXPECT_FALSE(m3gcli::sizeLimitError("--size", 1, 1, 2048, 2048));
    const auto wide = m3gcli::sizeLimitError("--size", 100000, 100000, 2048, 2048);
    ASSERT_TRUE(wide);
    EXPECT_NE(wide->find("--size 100000x100000 exceeds"), std::string::npos) << *wide;
    EXPECT_NE(wide->find("2048x2048"), std::string::npos) << *wide;
    EXPECT_TRUE(m3gcli::sizeLimitError("--size", 2049, 10, 2048, 2048));
    EXPECT_TRUE(m3gcli::sizeLimitError("--size", 10, 4000, 4096, 2048));
    // parseSizeOption: the library's limits (2048 by default).
    int w = 1, h = 1;
    m3gcli::parseSizeOption("--size", "640x480", w, h);
    EXPECT_EQ(w, 640);
    EXPECT_EQ(h, 480);
    EXPECT_THROW(m3gcli::parseSizeOption("--size", "100000x100000", w, h), CliError);
    EXPECT_THROW(m3gcli::parseSizeOption("--size", "64", w, h), CliError);
    EXPECT_EQ(w, 640);  // left alone
}

TEST(CliArgs, IntOptionsAndExtensions) {
    EXPECT_EQ(m3gcli::parseIntOption("--frames", "12", 1, "a positive integer"), 12);
    try {
        m3gcli::parseIntOption("--frames", "0", 1, "a positive integer");
        FAIL() << "no error";
    } catch (const CliError& e) {
        EXPECT_STREQ(e.what(), "--frames takes a positive integer, not '0'");
    }
    EXPECT_EQ(m3gcli::lowerExtension("dir.v1/Shot.JPG"), ".jpg");
    EXPECT_EQ(m3gcli::lowerExtension("out"), "");
}
