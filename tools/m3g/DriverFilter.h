// Which Vulkan drivers the m3g tool asks the loader to skip: those of GPUs
// whose device nodes this machine does not have (docs/rendering.md, "Whole
// process"). The Vulkan loader opens every installed driver at instance
// creation; on a machine without a GPU (CI, containers, servers) Debian's
// intel, intel_hasvk and radeon drivers are loaded, relocated and asked for
// devices they cannot find, about 10-15 ms of a 0.19 s `m3g render`.
// The tool, not the library, does it: it changes the process's environment
// (VK_LOADER_DRIVERS_DISABLE, read by the loader from Vulkan SDK 1.3.234 on;
// older loaders ignore it), which a library must not do to its host.
#pragma once

#include <filesystem>
#include <string>

namespace m3gcli {

/// The device nodes GPU drivers open (Linux).
struct DeviceNodes {
    bool renderNode = false;  // /dev/dri/renderD*: every Mesa GPU driver
    bool nvidia = false;      // /dev/nvidia*: NVIDIA's driver
    bool dxg = false;         // /dev/dxg: Mesa's dzn on WSL
};

/// The nodes present under `dev` (normally /dev).
DeviceNodes findDeviceNodes(const std::filesystem::path& dev);

/// Comma-separated loader globs (matched against driver manifest file
/// names) of the drivers that cannot find a device without the missing
/// nodes: Mesa's GPU drivers without a render node, NVIDIA's without a
/// /dev/nvidia* node, dzn without /dev/dxg; empty when nothing is missing.
/// Software drivers (lavapipe, SwiftShader) and drivers not named here are
/// never listed.
std::string driverGlobsToDisable(const DeviceNodes& nodes);

/// Sets VK_LOADER_DRIVERS_DISABLE to driverGlobsToDisable(findDeviceNodes
/// ("/dev")) on Linux, before any Vulkan call, unless the user chose the
/// drivers (VK_DRIVER_FILES, VK_ICD_FILENAMES, VK_ADD_DRIVER_FILES,
/// VK_LOADER_DRIVERS_SELECT or VK_LOADER_DRIVERS_DISABLE set) or asked for
/// all of them (M3G_VK_ALL_DRIVERS=1). Returns the value set; empty when
/// it set nothing.
std::string skipDriversWithoutDevices();

}  // namespace m3gcli
