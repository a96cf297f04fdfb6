// Identifies loader input by its magic bytes (JSR-184 1.1, Loader), so that a
// non-M3G input is named instead of failing with a generic error.
//
// Internal to the loader (scene/), not part of the public API.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace m3g::detail {

enum class InputFormat {
    Empty,          ///< no bytes
    M3G,            ///< JSR-184 file identifier (or a prefix of it, for truncated input)
    M3G2,           ///< M3G 2.0 / JSR-297 (its own identifier, or the JSR-184 one with header version 2.x)
    M3GTextMangled, ///< JSR-184 identifier damaged by a text-mode (CR-LF) transfer
    PNG,
    JPEG,
    MascotMBAC,     ///< Mascot Capsule figure ("MB" + version)
    MascotMTRA,     ///< Mascot Capsule animation ("MT" + version)
    Zip,            ///< ZIP / JAR archive
    Gzip,
    Xml,            ///< e.g. an .m3x XML scene
    Unknown,
};

/// Identifies the input. Never throws.
InputFormat sniffFormat(std::span<const std::uint8_t> data);

/// A short name for messages ("a JPEG image", "a Mascot Capsule MBAC figure").
const char* describeFormat(InputFormat format);

/// Throws IOException with a clear message unless `format` is one the loader
/// reads (M3G 1.0, PNG or JPEG). `name` (may be empty) is the resource name.
void requireLoadableFormat(InputFormat format, const std::string& name = {});

}  // namespace m3g::detail
