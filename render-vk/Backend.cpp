// Installs the Vulkan renderer as the back end every Graphics3D makes at its
// first draw (frame/FrameBackend.h). The CMake target m3g_render_vk makes
// its users' link keep this file (the anchor symbol below), so linking the
// library is all an application does.
#include <m3g/frame/FrameBackend.h>

#include "Renderer.h"

namespace {

std::unique_ptr<m3g::frame::FrameBackend> makeRenderer() { return std::make_unique<m3g::vk::Renderer>(); }

[[maybe_unused]] const bool gInstalled = [] {
    m3g::frame::setBackendFactory(&makeRenderer);
    return true;
}();

}  // namespace

// Exported from libm3g.so too (a hidden-visibility build), where programs
// name it to keep the library (cmake/SharedLibraries.cmake).
extern "C" {
M3G_FRAME_API int m3g_vk_backend_anchor = 0;
}
