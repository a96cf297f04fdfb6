// m3g view when the build lacked GLFW or Dear ImGui: the command exists (its
// --help too) and says what to install.
#include <memory>
#include <string>
#include <vector>

#include "Commands.h"

namespace m3gcli {

void addViewCommand(CLI::App& parent, CommandTable& table) {
    CLI::App* app = addCommandApp(parent, "view",
                                  "the desktop viewer (not in this build: needs libglfw3-dev and libimgui-dev)");
    // Whatever was given: the answer is the same.
    app->allow_extras();
    table[app] = []() -> int {
        throw RenderError("this m3g was built without the viewer; install libglfw3-dev and libimgui-dev (scripts/setup "
                          "does) and rebuild");
    };
}

}  // namespace m3gcli
