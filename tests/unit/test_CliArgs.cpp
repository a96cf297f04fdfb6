// tools/m3g/CliArgs: the m3g command line.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "CliArgs.h"

using m3gcli::CliArgs;
using m3gcli::CliError;

namespace {

CliArgs parse(std::initializer_list<std::string_view> args) {
    const std::vector<std::string_view> v(args);
    return m3gcli::parseCliArgs(std::span<const std::string_view>(v));
}

/// The CliError message of parsing `args`, or "" if it parses.
std::string error(std::initializer_list<std::string_view> args) {
    try {
        parse(args);
    } catch (const CliError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(CliArgs, Info) {
    const CliArgs a = parse({"info", "scene.m3g"});
    EXPECT_EQ(a.command, "info");
    ASSERT_EQ(a.files.size(), 1u);
    EXPECT_EQ(a.files[0], "scene.m3g");
    EXPECT_FALSE(a.json);
    EXPECT_FALSE(a.lenient);
    EXPECT_FALSE(a.time.has_value());

    const CliArgs b = parse({"info", "--json", "x.m3g", "--lenient", "--time", "1500"});
    EXPECT_TRUE(b.json);
    EXPECT_TRUE(b.lenient);
    ASSERT_TRUE(b.time.has_value());
    EXPECT_EQ(*b.time, 1500);
    EXPECT_EQ(b.files, std::vector<std::string>{"x.m3g"});

    EXPECT_EQ(*parse({"info", "--time=-20", "x.m3g"}).time, -20);
    EXPECT_EQ(*parse({"info", "x.m3g", "--time", "+7"}).time, 7);
    EXPECT_TRUE(parse({"info"}).files.empty());  // library information
}

TEST(CliArgs, Convert) {
    const CliArgs a = parse({"convert", "in.m3g", "out.m3g", "--compress"});
    EXPECT_EQ(a.command, "convert");
    EXPECT_EQ(a.files, (std::vector<std::string>{"in.m3g", "out.m3g"}));
    EXPECT_TRUE(a.compress);
    EXPECT_FALSE(a.lenient);
    EXPECT_TRUE(parse({"convert", "--lenient", "a", "b"}).lenient);
}

TEST(CliArgs, OperandsAfterDoubleDashAndStdin) {
    const CliArgs a = parse({"info", "--", "--json"});
    EXPECT_FALSE(a.json);
    EXPECT_EQ(a.files, std::vector<std::string>{"--json"});
    EXPECT_EQ(parse({"info", "-"}).files, std::vector<std::string>{"-"});
}

TEST(CliArgs, Help) {
    EXPECT_EQ(parse({"help"}).command, "help");
    EXPECT_EQ(parse({"--help"}).command, "help");
    EXPECT_EQ(parse({"info", "x", "-h"}).command, "help");
    EXPECT_EQ(parse({"version"}).command, "version");
    EXPECT_NE(m3gcli::usageText().find("convert IN OUT"), std::string::npos);
}

TEST(CliArgs, Errors) {
    EXPECT_EQ(error({}), "no command given");
    EXPECT_EQ(error({"frobnicate"}), "unknown command 'frobnicate'");
    EXPECT_EQ(error({"--json"}), "expected a command before option '--json'");
    EXPECT_EQ(error({"info", "x", "--jsn"}), "unknown option '--jsn'");
    EXPECT_EQ(error({"info", "x", "-j"}), "unknown option '-j'");
    EXPECT_EQ(error({"info", "x", "--time"}), "option --time needs a value (world time in ms)");
    EXPECT_EQ(error({"info", "x", "--time", "abc"}),
              "option --time expects an integer (world time in ms), got 'abc'");
    EXPECT_EQ(error({"info", "x", "--time", "12ms"}),
              "option --time expects an integer (world time in ms), got '12ms'");
    EXPECT_EQ(error({"info", "x", "--time="}), "option --time expects an integer (world time in ms), got ''");
    EXPECT_EQ(error({"info", "x", "--time", "99999999999"}),
              "option --time expects an integer (world time in ms), got '99999999999'");
    EXPECT_EQ(error({"info", "x", "--time", "1", "--time", "2"}), "option --time given more than once");
    EXPECT_EQ(error({"info", "x", "--json=yes"}), "option --json takes no value");
    EXPECT_EQ(error({"info", "x", "--compress"}), "option --compress does not apply to 'info'");
    EXPECT_EQ(error({"convert", "a", "b", "--json"}), "option --json does not apply to 'convert'");
    EXPECT_EQ(error({"info", "a", "b"}), "unexpected argument 'b' for 'info'");
    EXPECT_EQ(error({"convert"}), "convert needs an input and an output file");
    EXPECT_EQ(error({"convert", "a"}), "convert needs an output file");
    EXPECT_EQ(error({"version", "x"}), "unexpected argument 'x' for 'version'");
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

TEST(CliArgs, ArgvOverload) {
    const char* argv[] = {"m3g", "info", "f.m3g", "--json"};
    const CliArgs a = m3gcli::parseCliArgs(4, argv);
    EXPECT_EQ(a.command, "info");
    EXPECT_TRUE(a.json);
}
