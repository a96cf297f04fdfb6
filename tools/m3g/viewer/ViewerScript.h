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
//   screenshot [PATH]        render one frame and save the 3D view as PNG
//                            (no PATH: the next free m3g-screenshot-NNNN.png)
//   screenshot-ui PATH       the same with the panels (the whole window)
//   select ID                select the object with `m3g info` id ID
//   edit ID PROPERTY V...    edit a property (ViewerEdit.h names them), undoable
//   expect ID PROPERTY V...  fail unless the property has these values (1e-3)
//   undo | redo              the edit stack
//   save PATH                write the scene with m3g::Saver
//   panels on|off            show / hide the panels (F1)
//   layout                   print the layout's rectangles
//   expect-view X Y W H      fail unless the 3D view is that rectangle
//   splitter NAME PIXELS     set a layout size as dragging its splitter
//                            does (left, right: column widths; left-split,
//                            right-split1, right-split2: shares 0..1)
//   expect-pixel PNG X Y RRGGBB   fail unless pixel (X, Y) of a PNG (e.g. a
//                            screenshot-ui) has that colour (+-8 per channel)
//   browse [DIR]             open the file browser at DIR (default: the
//                            opened file's folder, else the current one)
//   browse-list [FILE]       its entries, "INDEX KIND NAME" a line, to FILE
//                            (appended) or stdout
//   browse-open N            activate entry N (a folder: enter; a file: open)
//   browse-up | browse-close
//   recent [FILE]            the recent files, one a line
//   drop PATH                as if PATH were dropped on the window
//   expect-error TEXT...|none  fail unless the Messages panel's error
//                            contains TEXT (or there is none)
//   expect-scene SUFFIX      fail unless the opened scene's name ends so
//   inspect N [ZOOM]         the texture inspector on the Textures tab's
//                            N-th image (0-based), ZOOM fit|1|2|4...
//   inspect-close
//   texel X Y [FILE]         print the inspected image's texel (X, Y)
//   hover X Y [FILE]         print the texel under window point (X, Y) in
//                            the inspector as last drawn (or "none")
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
