// Bounded little-endian reader for the primitive types of the .m3g format
// (JSR-184 1.1 file format §3). Every failure throws m3g::IOException whose message
// names the caller's context and the byte offset.
//
// Internal to the loader (scene/), not part of the public API.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "LoadOptions.h"

namespace m3g::detail {

class ByteReader {
public:
    /// Reads `data`. `baseOffset` is added to positions in messages (the
    /// offset of data[0] in the file or in the inflated section);
    /// `offsetWhere` qualifies the offset in messages ("" = in the file,
    /// e.g. "of the inflated section 2 data"). `context` prefixes every
    /// message ("section 2, object 5 (Mesh, type 14)"). `log` (may be null:
    /// strict, no warnings) gives the lenient flag and receives warnings.
    explicit ByteReader(std::span<const std::uint8_t> data, std::string context = {},
                        std::size_t baseOffset = 0, LoadLog* log = nullptr,
                        std::string offsetWhere = {});
    /// Fills `context` and `offsetWhere` (as above) when a message first
    /// needs them: most readers never fail or warn, and building the two
    /// strings for every object was a sixth of a small file's load.
    using Describe = std::function<void(std::string& context, std::string& offsetWhere)>;
    static ByteReader described(std::span<const std::uint8_t> data, Describe describe, std::size_t baseOffset,
                                LoadLog* log);

    // --- position -------------------------------------------------------
    std::size_t position() const { return pos_; }                 ///< relative to data[0]
    std::size_t offset() const { return base_ + pos_; }           ///< as named in messages
    std::size_t size() const { return data_.size(); }
    std::size_t remaining() const { return data_.size() - pos_; }
    bool atEnd() const { return pos_ == data_.size(); }
    const std::string& context() const {
        describe();
        return context_;
    }
    LoadLog* log() const { return log_; }
    bool lenient() const { return log_ && log_->lenient(); }

    // --- primitives (JSR-184 1.1 file format §3) ----------------------
    std::uint8_t readByte();
    std::int16_t readInt16();
    std::uint16_t readUInt16();
    std::int32_t readInt32();
    std::uint32_t readUInt32();
    /// IEEE single. NaN, ±Inf, denormals and -0.0 are errors; a lenient load
    /// reads -0.0 as +0.0 and records a warning.
    float readFloat32();
    /// UTF-8, NUL-terminated; the terminator must lie inside the data.
    /// Malformed UTF-8 is an error (a lenient load keeps the bytes, warns).
    std::string readString();
    /// One byte, 0 or 1; anything else is an error.
    bool readBoolean();
    std::array<float, 3> readVector3D();
    /// 16 floats, row-major (Transform.get order).
    std::array<float, 16> readMatrix();
    /// R,G,B bytes -> 0x00RRGGBB.
    std::uint32_t readColorRGB();
    /// R,G,B,A bytes -> 0xAARRGGBB (ColorRGBA, JSR-184 1.1 file format §3).
    std::uint32_t readColorRGBA();
    /// UInt32: 0 = null, 1 = header, 2.. = following objects.
    std::uint32_t readObjectIndex();

    // --- arrays -----------------------------------------------------------
    /// Reads a UInt32 element count and checks, before anything is allocated,
    /// that count × elementSize bytes remain. `what` names the array.
    std::uint32_t readCount(std::size_t elementSize, const char* what);
    /// Checks that count × elementSize bytes remain (for counts known from
    /// context, e.g. vertexCount × componentCount).
    void requireAvailable(std::uint64_t count, std::uint64_t elementSize, const char* what);

    /// Byte[]: UInt32 count then the bytes.
    std::vector<std::uint8_t> readByteArray(const char* what);
    /// UInt16[] / UInt32[] / Float32[] / ObjectIndex[]: UInt32 count then elements.
    std::vector<std::uint16_t> readUInt16Array(const char* what);
    std::vector<std::uint32_t> readUInt32Array(const char* what);
    std::vector<float> readFloat32Array(const char* what);
    std::vector<std::uint32_t> readObjectIndexArray(const char* what);
    /// Type[n] with n known from context.
    std::vector<float> readFloat32s(std::uint64_t n, const char* what);

    /// The next n raw bytes (a view into the data), advancing past them.
    std::span<const std::uint8_t> readBytes(std::uint64_t n, const char* what);
    void skip(std::uint64_t n, const char* what) { (void)readBytes(n, what); }

    /// A reader over the next n bytes (offsets continue), advancing past them.
    ByteReader sub(std::uint64_t n, std::string context, const char* what);

    /// Error unless every byte has been consumed.
    void expectEnd(const char* what = "object data");

    // --- errors and warnings --------------------------------------------
    /// Throws IOException "<context>: <what> at byte offset N".
    [[noreturn]] void fail(const std::string& what) const;
    [[noreturn]] void failAt(std::size_t relativePos, const std::string& what) const;
    /// "<context>: <what> at byte offset N" for the current position.
    std::string where(const std::string& what) const;
    std::string whereAt(std::size_t relativePos, const std::string& what) const;
    /// Records a warning (no-op without a log).
    void warn(const std::string& what) const;
    void warnAt(std::size_t relativePos, const std::string& what) const;

private:
    void need(std::size_t n, const char* what);
    /// Runs describe_ once (messages only).
    void describe() const;

    std::span<const std::uint8_t> data_;
    std::size_t pos_ = 0;
    std::size_t base_ = 0;
    mutable Describe describe_;
    mutable std::string context_;
    mutable std::string offsetWhere_;
    LoadLog* log_ = nullptr;
};

/// True if `bytes` is well-formed UTF-8 (no overlongs, surrogates or > U+10FFFF).
bool isValidUtf8(std::span<const std::uint8_t> bytes);

}  // namespace m3g::detail
