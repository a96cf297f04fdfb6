#include "InputFile.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include <m3g/Exception.h>

#include "CliErrors.h"
#include "FormatSniffer.h"
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

FileContent sniffBytes(std::span<const std::uint8_t> head) {
    using m3g::detail::InputFormat;
    const InputFormat format = m3g::detail::sniffFormat(head);
    FileContent c;
    c.m3g = format == InputFormat::M3G;
    c.zip = format == InputFormat::Zip;
    c.image = format == InputFormat::PNG || format == InputFormat::JPEG;
    c.what = m3g::detail::describeFormat(format);
    return c;
}

FileContent sniffFile(const fs::path& file) {
    std::uint8_t head[32] = {};  // enough to tell M3G 2.0 from 1.0 (FormatSniffer.cpp)
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        FileContent c;
        c.what = "an unreadable file";
        return c;
    }
    in.read(reinterpret_cast<char*>(head), sizeof head);
    return sniffBytes(std::span<const std::uint8_t>(head, static_cast<std::size_t>(in.gcount())));
}

bool hasM3gName(const std::string& name) {
    if (name.size() < 4) return false;
    std::string ext = name.substr(name.size() - 4);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".m3g";
}

}  // namespace m3gcli
