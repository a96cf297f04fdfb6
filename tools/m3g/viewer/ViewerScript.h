// Scripted input for the viewer (tests, demos): one command per line,
// '#' starts a comment. Commands (docs/viewer.md):
//   frames N                 render N frames
//   time MS | play | pause   animation time / clock
//   drag left|right X0 Y0 X1 Y1   orbit (left) or pan (right) by a mouse drag
//   scroll STEPS             zoom (positive: closer)
//   click X Y                pick at pixel (X, Y)
//   expect-pick CLASS|none   fail unless the last pick hit a CLASS (or nothing)
//   key NAME                 space r w l h f1 left right 0..9
//   camera I                 -1 orbit, else the I-th camera
//   screenshot PATH          render one frame and save the 3D view as PNG
//   screenshot-ui PATH       the same with the panels (the whole window)
//   quit
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace m3gview {

struct ScriptCommand {
    int line = 0;
    std::string name;
    std::vector<std::string> args;
};

class Script {
public:
    /// Reads and checks a script (std::runtime_error naming file and line
    /// for an unknown command or a wrong argument count).
    static Script load(const std::string& path);
    static Script parse(const std::string& text, const std::string& name);

    /// Runs each command through `apply`, which returns 0 to go on, or an
    /// exit status (stops). Returns the first non-zero status, else 0.
    int run(const std::function<int(const ScriptCommand&)>& apply) const;

    const std::vector<ScriptCommand>& commands() const noexcept { return commands_; }

private:
    std::vector<ScriptCommand> commands_;
};

}  // namespace m3gview
