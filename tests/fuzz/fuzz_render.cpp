// libFuzzer target: hostile .m3g bytes loaded and drawn on the Vulkan device
// (lavapipe; scripts/fuzz render sets VK_DRIVER_FILES). The rules are
// m3gfuzz::checkRender in FuzzRender.h. The validation layer is on unless
// M3G_VK_VALIDATION=0: its messages are findings.
#include <cstdlib>

#include "FuzzMain.h"
#include "FuzzRender.h"
#include "HoldDriver.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    m3gtest::holdLavapipeLoaded();  // past the loader's dlclose at exit (HoldDriver.h)
    if (!std::getenv("M3G_VK_VALIDATION")) m3g::vk::requestValidation(true);
    // The device, the renderer and its pipelines for a plain clear exist
    // before the first input, so that its leak check sees none of them.
    m3g::Ref<m3g::Graphics> surface(new m3g::Graphics(8, 8));
    m3gfuzz::detail::settleFrame(*surface);
    return 0;
}

M3G_FUZZ_TARGET(m3gfuzz::checkRender)
