// Writes zip archives for the JAR tests with minizip's zip writer (Debian's
// libminizip-dev), so that no binary .jar is committed. Test-only.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <zip.h>

namespace m3gtest {

struct ZipEntry {
    std::string name;                ///< a name ending in '/' is a folder entry
    std::vector<std::uint8_t> data;
    bool deflate = true;             ///< false: stored
};

/// Writes `entries` in order to a new archive at `path` (gtest failures on error).
inline void writeZip(const std::filesystem::path& path, const std::vector<ZipEntry>& entries) {
    zipFile zf = zipOpen(path.string().c_str(), APPEND_STATUS_CREATE);
    ASSERT_NE(zf, nullptr) << path;
    for (const ZipEntry& e : entries) {
        zip_fileinfo info{};
        ASSERT_EQ(zipOpenNewFileInZip(zf, e.name.c_str(), &info, nullptr, 0, nullptr, 0, nullptr,
                                      e.deflate ? Z_DEFLATED : 0, e.deflate ? 6 : 0),
                  ZIP_OK);
        if (!e.data.empty()) {
            ASSERT_EQ(zipWriteInFileInZip(zf, e.data.data(), static_cast<unsigned>(e.data.size())), ZIP_OK);
        }
        ASSERT_EQ(zipCloseFileInZip(zf), ZIP_OK);
    }
    ASSERT_EQ(zipClose(zf, nullptr), ZIP_OK);
}

}  // namespace m3gtest
