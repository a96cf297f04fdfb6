// Opening the m3g tool's inputs so that every failure is an InputError
// (exit code 3) that names the path once and says what is wrong: missing,
// a directory, not a regular file, or what the Loader found malformed.
// Part of m3g_cli_support.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include <m3g/Loader.h>

#include "ImageIO.h"

namespace m3gcli {

/// Throws InputError "PATH: no such file", "PATH: is a directory" or
/// "PATH: is not a regular file" unless `path` is a regular file (or "-").
void requireInputFile(const std::string& path);

/// requireInputFile, then Loader::loadDetailed. A Loader failure becomes an
/// InputError whose message names `path` once (the Loader's messages start
/// with it, or not, depending on where they arise).
m3g::LoadResult loadInput(const std::string& path, bool lenient);

/// requireInputFile, then readPng (ImageIO.h); a failure is an InputError.
RgbaImage readPngInput(const std::string& path);

/// "PATH: message" with `path` said once: any "PATH: " prefixes `message`
/// already has are dropped first.
std::string withPath(const std::string& path, const std::string& message);

/// What a file's first bytes say it is (the Loader's format sniffing:
/// the JSR-184 1.1 file identifier for M3G), whatever its name: games ship
/// models as .res, .mod, .tex... The one rule by which batch render, a
/// .jar's listing and the viewer's file browser find M3G data.
struct FileContent {
    bool m3g = false;    ///< begins with the JSR-184 file identifier (M3G 1.0)
    bool zip = false;    ///< a zip archive (a J2ME .jar)
    bool image = false;  ///< PNG or JPEG
    std::string what;    ///< "an M3G 1.0 file", "a PNG image", "an unrecognised file" ...
};
FileContent sniffBytes(std::span<const std::uint8_t> head);
/// sniffBytes of the file's first bytes; an unreadable file is "an unreadable file".
FileContent sniffFile(const std::filesystem::path& file);
/// True if `name` ends with ".m3g" in any case.
bool hasM3gName(const std::string& name);
/// What is listed as M3G: data beginning with the identifier, or a file
/// named .m3g (listed so that a broken one is reported, not hidden).
inline bool listedAsM3g(const FileContent& content, const std::string& name) {
    return content.m3g || hasM3gName(name);
}

}  // namespace m3gcli
