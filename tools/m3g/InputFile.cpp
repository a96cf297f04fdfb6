#include "InputFile.h"

#include <filesystem>

#include <m3g/Exception.h>

#include "CliErrors.h"
#include "ImageIO.h"

namespace m3gcli {

namespace fs = std::filesystem;

std::string withPath(const std::string& path, const std::string& message) {
    // The Loader prefixes the path where a load fails and again where it
    // began (scene/io/Loader.cpp, loadNamed), so it may come twice.
    std::string_view rest = message;
    const std::string prefix = path + ": ";
    while (rest.starts_with(prefix)) rest.remove_prefix(prefix.size());
    return prefix + std::string(rest);
}

void requireInputFile(const std::string& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) throw InputError(path + ": no such file");
    if (fs::is_directory(status)) throw InputError(path + ": is a directory");
    if (!fs::is_regular_file(status)) throw InputError(path + ": is not a regular file");
}

m3g::LoadResult loadInput(const std::string& path, bool lenient) {
    requireInputFile(path);
    m3g::LoaderOptions options;
    options.lenient = lenient;
    try {
        return m3g::Loader::loadDetailed(path, options);
    } catch (const m3g::Exception& e) {
        throw InputError(withPath(path, e.what()));
    }
}

RgbaImage readPngInput(const std::string& path) {
    requireInputFile(path);
    try {
        return readPng(path);
    } catch (const std::runtime_error& e) {
        throw InputError(e.what());
    }
}

}  // namespace m3gcli
