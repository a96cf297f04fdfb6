// Mouse, keyboard and drag-and-drop of the viewer window, and the same
// actions driven by a script: orbit/pan/zoom, picking, shortcuts.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "ViewerScript.h"
#include "ViewerState.h"

struct GLFWwindow;

namespace m3gview {

class Input {
public:
    explicit Input(ViewerState& state) : state_(state) {}
    /// Installs the GLFW callbacks (before ImGui's GLFW backend, which then
    /// forwards events here; events ImGui wants are ignored here).
    void install(GLFWwindow* window);
    /// A file dropped on the window since the last call (the viewer opens
    /// it as File > Open does: the same identifier check, a folder opens
    /// the browser).
    std::optional<std::string> takeDrop();
    /// What dropping `path` on the window does (the script's `drop`).
    void drop(const std::string& path) { dropped_ = path; }

    // Actions (from the window or a script). Positions are window pixels,
    // mapped into the 3D view's rectangle (state.layout.view).
    void drag(bool pan, float dx, float dy);
    void scroll(float steps);
    void click(float x, float y);
    /// A shortcut by name (space r s w l h f1 left right 0..9, ctrl+z,
    /// ctrl+y, ctrl+shift+z, ctrl+s, ctrl+o); false if unknown.
    bool key(const std::string& name);

    // Edits (the status line says what happened; false on failure).
    bool undo();
    bool redo();
    /// Saves the scene to `path` (state.savePath when empty).
    bool save(const std::string& path);

    /// Runs one script command; `frame` renders a frame, `screenshot` one
    /// to a file ("" : the next numbered name). Returns 0, or 1 after
    /// printing why the script failed.
    int apply(const ScriptCommand& c, const std::function<void()>& frame,
              const std::function<void(const std::string&, bool withUi)>& screenshot);

private:
    ViewerState& state_;
    std::optional<std::string> dropped_;
    double lastX_ = 0, lastY_ = 0, pressX_ = 0, pressY_ = 0;
    int button_ = -1;
    bool moved_ = false;

    friend struct InputCallbacks;
};

/// Recomputes state.layout from the framebuffer size, the panels' switch
/// and the splitter sizes; when the 3D view's size changed, the orbit
/// camera's aspect follows it.
void updateLayout(ViewerState& state);

/// Opens a file for the viewer: M3G data (by its identifier bytes, or a
/// file named .m3g), a PNG or JPEG gives a scene; a .jar lists its M3G
/// entries in `state` and gives null; "game.jar!path/x.m3g" opens that
/// entry. Throws on load errors, and for any other file a message saying
/// what its bytes are (the Messages panel shows it).
std::unique_ptr<ViewerScene> openScene(const std::string& request, int width, int height, ViewerState& state);

/// Shows the file browser at `folder`; empty: the opened file's folder, else
/// the current one. Throws std::runtime_error for a folder it cannot list.
void showBrowser(ViewerState& state, const std::string& folder);

}  // namespace m3gview
