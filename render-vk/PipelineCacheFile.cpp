#include "PipelineCacheFile.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <unistd.h>

namespace m3g::vk {

namespace {

/// A cache file larger than this is not read (no driver's cache of this
/// program's few dozen pipelines comes near it; a stray huge file must not
/// be loaded into memory).
constexpr std::uintmax_t kMaxFileBytes = 256u << 20;

std::string hex(const std::uint8_t* bytes, std::size_t n) {
    static const char digits[] = "0123456789abcdef";
    std::string out;
    for (std::size_t i = 0; i < n; ++i) {
        out += digits[bytes[i] >> 4];
        out += digits[bytes[i] & 15];
    }
    return out;
}

std::uint32_t readU32(const std::uint8_t* p) {
    std::uint32_t v;
    std::memcpy(&v, p, 4);  // the header is in the host's byte order
    return v;
}

}  // namespace

std::string pipelineCachePath(const VkPhysicalDeviceProperties& props) {
    if (const char* v = std::getenv("M3G_VK_PIPELINE_CACHE"); v && *v) {
        if (std::strcmp(v, "0") == 0 || std::strcmp(v, "off") == 0) return "";
        return v;
    }
    std::filesystem::path dir;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        dir = xdg;
    else if (const char* home = std::getenv("HOME"); home && *home)
        dir = std::filesystem::path(home) / ".cache";
    else
        return "";
    char name[64];
    std::snprintf(name, sizeof name, "pipelines-%04x-%04x-", props.vendorID, props.deviceID);
    return (dir / "m3g-vk" / (name + hex(props.pipelineCacheUUID, VK_UUID_SIZE) + ".bin")).string();
}

bool pipelineCacheMatches(std::span<const std::uint8_t> data, const VkPhysicalDeviceProperties& props) {
    // VkPipelineCacheHeaderVersionOne: headerSize, headerVersion, vendorID,
    // deviceID (4 bytes each), then the 16-byte pipelineCacheUUID.
    constexpr std::size_t kHeader = 16 + VK_UUID_SIZE;
    if (data.size() < kHeader) return false;
    const std::uint32_t headerSize = readU32(data.data());
    return headerSize >= kHeader && headerSize <= data.size() &&
           readU32(data.data() + 4) == VK_PIPELINE_CACHE_HEADER_VERSION_ONE && readU32(data.data() + 8) == props.vendorID &&
           readU32(data.data() + 12) == props.deviceID &&
           std::memcmp(data.data() + 16, props.pipelineCacheUUID, VK_UUID_SIZE) == 0;
}

std::vector<std::uint8_t> readPipelineCache(const std::string& path, const VkPhysicalDeviceProperties& props) {
    if (path.empty()) return {};
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec || size == 0 || size > kMaxFileBytes) return {};
    std::vector<std::uint8_t> data(static_cast<std::size_t>(size));
    std::ifstream in(path, std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(data.size()))) return {};
    if (!pipelineCacheMatches(data, props)) return {};
    return data;
}

bool writePipelineCache(const std::string& path, std::span<const std::uint8_t> data) {
    if (path.empty() || data.empty()) return false;
    std::error_code ec;
    const std::filesystem::path target(path);
    if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path(), ec);
    // One temporary name per process: two processes saving at once each
    // rename a whole file of their own into place.
    const std::string temporary = path + ".tmp." + std::to_string(static_cast<long>(getpid()));
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out.write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(data.size()))) {
            out.close();
            std::filesystem::remove(temporary, ec);
            return false;
        }
    }
    std::filesystem::rename(temporary, target, ec);
    if (!ec) return true;
    std::filesystem::remove(temporary, ec);
    return false;
}

}  // namespace m3g::vk
