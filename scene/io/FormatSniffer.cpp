// Input identification by magic bytes (JSR-184 1.1, Loader).
#include "FormatSniffer.h"

#include <algorithm>
#include <array>
#include <cstring>

#include <m3g/Exception.h>

#include "M3GSections.h"

namespace m3g::detail {

namespace {

bool startsWith(std::span<const std::uint8_t> d, std::span<const std::uint8_t> magic) {
    return d.size() >= magic.size() && std::equal(magic.begin(), magic.end(), d.begin());
}

/// The JSR-297 (M3G 2.0) identifier: like JSR-184's with "297" for "184".
/// (Recalled from the JSR-297 specification; not verified against a copy.)
constexpr std::array<std::uint8_t, 12> kM3G2FileIdentifier = {
    0xAB, 0x4A, 0x53, 0x52, 0x32, 0x39, 0x37, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};

constexpr std::array<std::uint8_t, 8> kPngSignature = {0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A};

}  // namespace

InputFormat sniffFormat(std::span<const std::uint8_t> d) {
    if (d.empty()) return InputFormat::Empty;

    const std::span<const std::uint8_t> m3g(kM3GFileIdentifier);
    if (startsWith(d, m3g)) {
        // Section 0 of a JSR-184-identified file: scheme(1) total(4) uncompressed(4),
        // then the header object: type(1) length(4) VersionNumber[2] at offset 26.
        if (d.size() > 26 && d[12] == 0 && d[21] == 0 && d[26] == 2) return InputFormat::M3G2;
        return InputFormat::M3G;
    }
    if (d.size() < m3g.size() && std::equal(d.begin(), d.end(), m3g.begin())) return InputFormat::M3G;  // truncated
    if (startsWith(d, std::span<const std::uint8_t>(kM3G2FileIdentifier))) return InputFormat::M3G2;
    // «JSR184» followed by a damaged line-ending tail (CR-LF <-> LF conversions).
    if (startsWith(d, m3g.first(8)) && d.size() >= 9 && !startsWith(d, m3g)) return InputFormat::M3GTextMangled;

    if (startsWith(d, std::span<const std::uint8_t>(kPngSignature))) return InputFormat::PNG;
    if (d.size() >= 3 && d[0] == 0xFF && d[1] == 0xD8 && d[2] == 0xFF) return InputFormat::JPEG;

    // Mascot Capsule v3: "MB" / "MT" then a little-endian UInt16 format version
    // (MBAC versions 3..5 and MTRA version 5 are known; accept small values).
    if (d.size() >= 4 && d[0] == 'M' && (d[1] == 'B' || d[1] == 'T') && d[3] == 0 && d[2] >= 1 && d[2] <= 15)
        return d[1] == 'B' ? InputFormat::MascotMBAC : InputFormat::MascotMTRA;

    if (d.size() >= 4 && d[0] == 'P' && d[1] == 'K' && d[2] == 3 && d[3] == 4) return InputFormat::Zip;
    if (d.size() >= 2 && d[0] == 0x1F && d[1] == 0x8B) return InputFormat::Gzip;
    {
        std::size_t i = 0;
        if (d.size() >= 3 && d[0] == 0xEF && d[1] == 0xBB && d[2] == 0xBF) i = 3;  // UTF-8 BOM
        while (i < d.size() && (d[i] == ' ' || d[i] == '\t' || d[i] == '\r' || d[i] == '\n')) ++i;
        if (d.size() - i >= 5 && std::memcmp(d.data() + i, "<?xml", 5) == 0) return InputFormat::Xml;
    }
    return InputFormat::Unknown;
}

const char* describeFormat(InputFormat f) {
    switch (f) {
        case InputFormat::Empty: return "an empty file";
        case InputFormat::M3G: return "an M3G 1.0 file";
        case InputFormat::M3G2: return "an M3G 2.0 (JSR-297) file";
        case InputFormat::M3GTextMangled: return "an M3G file damaged by a text-mode (line-ending) conversion";
        case InputFormat::PNG: return "a PNG image";
        case InputFormat::JPEG: return "a JPEG image";
        case InputFormat::MascotMBAC: return "a Mascot Capsule figure (MBAC)";
        case InputFormat::MascotMTRA: return "a Mascot Capsule animation (MTRA)";
        case InputFormat::Zip: return "a ZIP/JAR archive";
        case InputFormat::Gzip: return "a gzip-compressed file";
        case InputFormat::Xml: return "an XML document";
        case InputFormat::Unknown: return "an unrecognised file";
    }
    return "an unrecognised file";
}

void requireLoadableFormat(InputFormat f, const std::string& name) {
    const std::string prefix = name.empty() ? std::string() : name + ": ";
    switch (f) {
        case InputFormat::M3G:
        case InputFormat::PNG:
        case InputFormat::JPEG:
            return;
        case InputFormat::Empty:
            throw IOException(prefix + "empty file (0 bytes): not an M3G file");
        case InputFormat::M3G2:
            throw IOException(prefix + "M3G 2.0 (JSR-297) files are not supported (only M3G 1.0)");
        case InputFormat::M3GTextMangled:
            throw IOException(prefix +
                              "the M3G file identifier is damaged at bytes 8-11 (line endings converted, e.g. by a "
                              "text-mode transfer): not a valid M3G file");
        case InputFormat::MascotMBAC:
        case InputFormat::MascotMTRA:
            throw IOException(prefix + "this is " + describeFormat(f) +
                              ", not an M3G file: Mascot Capsule (Micro3D) files are not supported");
        case InputFormat::Zip:
        case InputFormat::Gzip:
        case InputFormat::Xml:
            throw IOException(prefix + "this is " + describeFormat(f) + ", not an M3G file");
        case InputFormat::Unknown:
            break;
    }
    throw IOException(prefix +
                      "not an M3G file or a PNG or JPEG image (unrecognised file identifier at byte offset 0)");
}

}  // namespace m3g::detail
