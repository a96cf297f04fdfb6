// Checksum repair for fuzz inputs. A mutated .m3g almost always fails its
// section Adler-32 and a mutated PNG its chunk CRC-32, so the decoders behind
// them would never be reached; the targets (and the regression replay in
// tests/unit/test_FuzzRegressions.cpp) therefore load each input twice: as
// is, and with every checksum that lies inside the input recomputed (and the
// .m3g TotalFileSize set to the input size). Test-only, header-only (zlib).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <zlib.h>

namespace m3gfuzz {

using Bytes = std::vector<std::uint8_t>;

namespace detail {
inline std::uint32_t le32(const Bytes& b, std::size_t at) {
    return std::uint32_t(b[at]) | std::uint32_t(b[at + 1]) << 8 | std::uint32_t(b[at + 2]) << 16 |
           std::uint32_t(b[at + 3]) << 24;
}
inline void putLe32(Bytes& b, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b[at + std::size_t(i)] = std::uint8_t(v >> (8 * i));
}
inline std::uint32_t be32(const Bytes& b, std::size_t at) {
    return std::uint32_t(b[at]) << 24 | std::uint32_t(b[at + 1]) << 16 | std::uint32_t(b[at + 2]) << 8 |
           std::uint32_t(b[at + 3]);
}
inline void putBe32(Bytes& b, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b[at + std::size_t(i)] = std::uint8_t(v >> (8 * (3 - i)));
}
}  // namespace detail

inline constexpr std::uint8_t kM3GIdentifier[12] = {0xAB, 0x4A, 0x53, 0x52, 0x31, 0x38,
                                                    0x34, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
inline constexpr std::uint8_t kPngSignature[8] = {0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A};

/// .m3g (JSR-184 1.1 file format, section "File Structure"): identifier,
/// then sections of CompressionScheme (1), TotalSectionLength (4),
/// UncompressedLength (4), Objects, Checksum (4, Adler-32 of everything
/// before it in the section). Stops at the first
/// section that does not fit. TotalFileSize (header object of an
/// uncompressed first section, file offset 29) becomes the input size.
inline Bytes repairM3G(Bytes b) {
    using namespace detail;
    if (b.size() < 12 || !std::equal(b.begin(), b.begin() + 12, kM3GIdentifier)) return b;
    if (b.size() >= 33 && b[12] == 0 && b[21] == 0) putLe32(b, 29, static_cast<std::uint32_t>(b.size()));
    std::size_t at = 12;
    while (at + 9 <= b.size()) {
        const std::uint32_t total = le32(b, at + 1);
        if (total < 13 || total > b.size() - at) break;
        const std::size_t sum = at + total - 4;
        putLe32(b, sum, static_cast<std::uint32_t>(adler32(adler32(0L, Z_NULL, 0), b.data() + at, uInt(total - 4))));
        at += total;
    }
    return b;
}

/// PNG: signature, then chunks of Length (4, big-endian), Type (4), Data,
/// CRC-32 of Type and Data (4). Stops at the first chunk that does not fit.
inline Bytes repairPng(Bytes b) {
    using namespace detail;
    if (b.size() < 8 || !std::equal(b.begin(), b.begin() + 8, kPngSignature)) return b;
    std::size_t at = 8;
    while (at + 12 <= b.size()) {
        const std::uint32_t len = be32(b, at);
        if (len > b.size() - at - 12) break;
        putBe32(b, at + 8 + len, static_cast<std::uint32_t>(crc32(crc32(0L, Z_NULL, 0), b.data() + at + 4, uInt(len + 4))));
        at += 12 + std::size_t(len);
    }
    return b;
}

/// Whichever of the two applies (the input unchanged if neither does).
inline Bytes repairChecksums(std::span<const std::uint8_t> data) {
    Bytes b(data.begin(), data.end());
    return b.size() >= 8 && std::equal(b.begin(), b.begin() + 8, kPngSignature) ? repairPng(std::move(b))
                                                                                : repairM3G(std::move(b));
}

}  // namespace m3gfuzz
