// The section layer of the .m3g format (JSR-184 1.1 file format, sections
// "File Structure", "Header Object" and "External Reference", and §8): file
// identifier, sections (uncompressed or zlib), Adler-32 checksums, the object
// records inside the sections, the header object and the section rules.
// Per-class decoding of the object data is done elsewhere, on the spans
// produced here.
//
// Internal to the loader (scene/), not part of the public API.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "ByteReader.h"
#include "LoadOptions.h"

namespace m3g::detail {

/// «JSR184»\r\n\x1A\n
inline constexpr std::array<std::uint8_t, 12> kM3GFileIdentifier = {
    0xAB, 0x4A, 0x53, 0x52, 0x31, 0x38, 0x34, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};

/// ObjectType values (JSR-184 1.1 file format: each class's ObjectType in
/// section "Per-Class Data"; 0 the header object, 255 an external reference).
enum M3GObjectType : std::uint8_t {
    kTypeHeader = 0,
    kTypeAnimationController = 1,
    kTypeAnimationTrack = 2,
    kTypeAppearance = 3,
    kTypeBackground = 4,
    kTypeCamera = 5,
    kTypeCompositingMode = 6,
    kTypeFog = 7,
    kTypePolygonMode = 8,
    kTypeGroup = 9,
    kTypeImage2D = 10,
    kTypeTriangleStripArray = 11,
    kTypeLight = 12,
    kTypeMaterial = 13,
    kTypeMesh = 14,
    kTypeMorphingMesh = 15,
    kTypeSkinnedMesh = 16,
    kTypeTexture2D = 17,
    kTypeSprite3D = 18,
    kTypeKeyframeSequence = 19,
    kTypeVertexArray = 20,
    kTypeVertexBuffer = 21,
    kTypeWorld = 22,
    kTypeExternalReference = 255,
};

/// "Mesh", "External Reference", or "reserved" for 23..254.
const char* objectTypeName(std::uint8_t type);

/// The header object (type 0, JSR-184 1.1 file format, section "Header Object").
struct M3GHeader {
    std::uint8_t versionMajor = 0;
    std::uint8_t versionMinor = 0;
    bool hasExternalReferences = false;
    std::uint32_t totalFileSize = 0;
    std::uint32_t approximateContentSize = 0;
    std::string authoringField;
};

/// One section as stored.
struct M3GSection {
    int index = 0;                       ///< 0 = header section
    std::uint8_t compressionScheme = 0;  ///< 0 = none, 1 = zlib
    std::uint32_t totalSectionLength = 0;
    std::uint32_t uncompressedLength = 0;
    std::uint32_t checksum = 0;          ///< stored Adler-32 (verified)
    std::size_t fileOffset = 0;          ///< of the CompressionScheme byte
    std::size_t objectCount = 0;
    /// The Objects area (inflated for scheme 1): a view into the input or
    /// into a buffer owned by the M3GFile.
    std::span<const std::uint8_t> objects;
};

/// One object record (ObjectType, Length, Data).
struct M3GObject {
    std::uint8_t type = 0;
    int section = 0;
    /// The ObjectIndex that refers to this object: 1 = the header, 2.. = the
    /// following objects in file order (external references first).
    std::uint32_t index = 0;
    /// Offset of data[0]: in the file for an uncompressed section, in the
    /// inflated Objects area for a zlib section (`inflated`).
    std::size_t dataOffset = 0;
    bool inflated = false;
    std::span<const std::uint8_t> data;
};

/// A parsed file: header, sections and object records in file order.
/// Move-only (the spans point into owned inflate buffers or into the input,
/// which the caller keeps alive).
struct M3GFile {
    M3GHeader header;
    std::vector<M3GSection> sections;
    std::vector<M3GObject> objects;  ///< objects[0] is the header (index 1)
    /// Bytes of the input that belong to this file (TotalFileSize, or where
    /// the last section ended in a lenient load with a wrong TotalFileSize).
    std::size_t fileSize = 0;

    M3GFile() = default;
    M3GFile(M3GFile&&) = default;
    M3GFile& operator=(M3GFile&&) = default;
    M3GFile(const M3GFile&) = delete;
    M3GFile& operator=(const M3GFile&) = delete;

private:
    friend M3GFile parseM3GFile(std::span<const std::uint8_t>, LoadLog&);
    std::vector<std::unique_ptr<std::vector<std::uint8_t>>> buffers_;
};

/// Parses the identifier, every section (checksum, inflate) and every object
/// record of the M3G file at data[0], applying the section rules (JSR-184 1.1
/// file format, sections "File Structure" and "Header Object", and §8). The
/// file ends at TotalFileSize, so trailing bytes after an embedded file are
/// ignored. Throws IOException naming the section, object and byte offset.
/// Warnings (lenient loads) go to `log`.
M3GFile parseM3GFile(std::span<const std::uint8_t> data, LoadLog& log);

/// "section 2, object 5 (Mesh, type 14)" — object is the ObjectIndex.
std::string objectContext(const M3GObject& object);

/// A reader over the object's data with its context and offsets.
ByteReader objectReader(const M3GObject& object, LoadLog* log);

/// Adler-32 of `bytes` (zlib's adler32, initial value 1).
std::uint32_t adler32Of(std::span<const std::uint8_t> bytes);

/// Inflates a zlib stream that must produce exactly `expectedLength` bytes,
/// allocating no more than the stream actually produces (so a lying length
/// cannot force a large allocation). `reader` names errors.
std::vector<std::uint8_t> inflateExact(std::span<const std::uint8_t> compressed, std::uint32_t expectedLength,
                                       const ByteReader& reader, std::size_t compressedPos);

}  // namespace m3g::detail
