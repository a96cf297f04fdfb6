#include "DriverFilter.h"

#include <cstdlib>
#include <cstring>
#include <system_error>

namespace m3gcli {

DeviceNodes findDeviceNodes(const std::filesystem::path& dev) {
    namespace fs = std::filesystem;
    DeviceNodes nodes;
    std::error_code ec;
    for (fs::directory_iterator it(dev / "dri", ec), end; !ec && it != end; it.increment(ec))
        if (it->path().filename().string().rfind("renderD", 0) == 0) nodes.renderNode = true;
    // Any /dev/nvidia* (nvidiactl, nvidia0, ...): a container may pass the
    // nodes through in any combination, and keeping the driver is the safe side.
    ec.clear();
    for (fs::directory_iterator it(dev, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.rfind("nvidia", 0) == 0) nodes.nvidia = true;
        if (name == "dxg") nodes.dxg = true;
    }
    return nodes;
}

std::string driverGlobsToDisable(const DeviceNodes& nodes) {
    std::string out;
    const auto add = [&out](const char* glob) {
        if (!out.empty()) out += ',';
        out += glob;
    };
    if (!nodes.renderNode)
        // Mesa's manifests (intel_icd, intel_hasvk_icd, radeon_icd, ...):
        // each driver opens a render node to find its GPU.
        for (const char* glob : {"intel_*", "radeon_*", "nouveau_*", "freedreno_*", "panfrost_*", "broadcom_*",
                                 "asahi_*", "virtio_*", "powervr_mesa_*"})
            add(glob);
    if (!nodes.nvidia) add("nvidia_*");
    if (!nodes.dxg) add("dzn_*");
    return out;
}

std::string skipDriversWithoutDevices() {
#if defined(__linux__)
    for (const char* chosen : {"VK_DRIVER_FILES", "VK_ICD_FILENAMES", "VK_ADD_DRIVER_FILES", "VK_LOADER_DRIVERS_SELECT",
                               "VK_LOADER_DRIVERS_DISABLE"})
        if (const char* v = std::getenv(chosen); v && *v) return {};
    if (const char* all = std::getenv("M3G_VK_ALL_DRIVERS"); all && std::strcmp(all, "1") == 0) return {};
    const std::string globs = driverGlobsToDisable(findDeviceNodes("/dev"));
    if (!globs.empty()) setenv("VK_LOADER_DRIVERS_DISABLE", globs.c_str(), 0);
    return globs;
#else
    return {};
#endif
}

}  // namespace m3gcli
