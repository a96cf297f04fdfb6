// m3g view when the build lacked GLFW or Dear ImGui.
#include <cstdio>

#include "Commands.h"

namespace m3gcli {

int cmdView(std::span<const std::string_view>) {
    std::fprintf(stderr, "m3g: view: this m3g was built without the viewer; install libglfw3-dev and libimgui-dev "
                         "(scripts/setup does) and rebuild\n");
    return 1;
}

}  // namespace m3gcli
