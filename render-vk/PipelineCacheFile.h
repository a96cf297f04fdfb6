// The pipeline cache kept on disk between runs, so that a GPU driver
// compiles each shader variant once per machine instead of once per process
// (on an NVIDIA H200 the first frame spent 400-1,000 ms creating pipelines;
// docs/gpu.md). The file holds what vkGetPipelineCacheData returned; its
// header (VkPipelineCacheHeaderVersionOne) is checked against the device
// before the bytes reach the driver, and any failure to read or write it
// leaves an empty cache: the cache is an optimisation, never an error.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <volk.h>

namespace m3g::vk {

/// Where the cache of this device lives: M3G_VK_PIPELINE_CACHE when set (a
/// file path; "0" or "off": no file), else
/// $XDG_CACHE_HOME/m3g-vk/pipelines-VENDOR-DEVICE-UUID.bin, else the same
/// under $HOME/.cache; "" when there is none of these.
std::string pipelineCachePath(const VkPhysicalDeviceProperties& props);

/// Whether `data` begins with a version-one pipeline cache header naming
/// this device (vendor, device id and pipelineCacheUUID).
bool pipelineCacheMatches(std::span<const std::uint8_t> data, const VkPhysicalDeviceProperties& props);

/// The file's bytes when they are a cache of this device, else empty.
std::vector<std::uint8_t> readPipelineCache(const std::string& path, const VkPhysicalDeviceProperties& props);

/// Writes `data` to `path` through a temporary file renamed into place (a
/// reader never sees half a file), creating the folder; false on failure.
bool writePipelineCache(const std::string& path, std::span<const std::uint8_t> data);

}  // namespace m3g::vk
