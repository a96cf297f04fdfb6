// Keeping lavapipe loaded for the whole process, for the programs that run
// under LeakSanitizer (the device tests of the ASan build, the render fuzz
// target). Test-only, header-only.
//
// Lavapipe keeps heap blocks reachable from its own globals until the Vulkan
// loader dlcloses it at vkDestroyInstance; once its data segment is gone
// LeakSanitizer sees those blocks as leaked (240 bytes a process, from an
// "<unknown module>" no suppression can name). Held loaded, as in any
// process that does not unload its driver, it leaks nothing, so the leak
// check stays on for m3g-vk's own code.
#pragma once

#include <dlfcn.h>

namespace m3gtest {

/// Opens lavapipe with RTLD_NODELETE (a no-op where it is not installed).
/// Returns whether it was found.
inline bool holdLavapipeLoaded() noexcept {
    return dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_NODELETE) != nullptr;
}

}  // namespace m3gtest
