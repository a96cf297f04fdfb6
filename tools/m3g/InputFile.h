// Opening the m3g tool's inputs so that every failure is an InputError
// (exit code 3) that names the path once and says what is wrong: missing,
// a directory, not a regular file, or what the Loader found malformed.
// Part of m3g_cli_support.
#pragma once

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

}  // namespace m3gcli
