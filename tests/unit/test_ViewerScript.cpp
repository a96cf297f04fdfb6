// The viewer's script language: parsing, errors that name file and line.
#include <gtest/gtest.h>

#include "ViewerScript.h"

using m3gview::Script;
using m3gview::ScriptCommand;

TEST(ViewerScript, ParsesCommandsSkippingCommentsAndBlankLines) {
    const Script s = Script::parse("# a test\nframes 3\n\n  drag left 1 2 3 4  # orbit\nscreenshot a.png\n", "t");
    ASSERT_EQ(s.commands().size(), 3u);
    EXPECT_EQ(s.commands()[0].name, "frames");
    EXPECT_EQ(s.commands()[0].args, std::vector<std::string>{"3"});
    EXPECT_EQ(s.commands()[1].line, 4);
    EXPECT_EQ(s.commands()[1].args.size(), 5u);
    EXPECT_EQ(s.commands()[2].args[0], "a.png");
}

TEST(ViewerScript, UnknownCommandsAndWrongArityNameTheLine) {
    try {
        Script::parse("frames 1\njump 3\n", "s.txt");
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "s.txt:2: unknown command 'jump'");
    }
    try {
        Script::parse("click 1\n", "s.txt");
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "s.txt:1: 'click' takes 2 argument(s), got 1");
    }
    EXPECT_THROW(Script::load("/no/such/script.txt"), std::runtime_error);
}

TEST(ViewerScript, RunStopsAtQuitOrAtTheFirstFailure) {
    const Script s = Script::parse("frames 1\nquit\nframes 2\n", "t");
    int calls = 0;
    EXPECT_EQ(s.run([&](const ScriptCommand&) { return ++calls, 0; }), 0);
    EXPECT_EQ(calls, 1);
    const Script t = Script::parse("frames 1\nframes 2\nframes 3\n", "t");
    calls = 0;
    EXPECT_EQ(t.run([&](const ScriptCommand& c) { return ++calls, c.args[0] == "2" ? 5 : 0; }), 5);
    EXPECT_EQ(calls, 2);
}
