// Little-endian writer for the primitive types of the .m3g format (JSR-184
// 1.1 file format §3), the mirror of ByteReader. Used by the Saver.
//
// Internal to the writer (scene/), not part of the public API.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace m3g::detail {

class ByteWriter {
public:
    ByteWriter() = default;

    const std::vector<std::uint8_t>& bytes() const noexcept { return out_; }
    std::vector<std::uint8_t>& bytes() noexcept { return out_; }
    std::size_t size() const noexcept { return out_.size(); }
    void clear() noexcept { out_.clear(); }

    // --- primitives (JSR-184 1.1 file format §3) ----------------------
    void writeByte(std::uint8_t v) { out_.push_back(v); }
    void writeInt16(std::int16_t v) { writeUInt16(static_cast<std::uint16_t>(v)); }
    void writeUInt16(std::uint16_t v);
    void writeInt32(std::int32_t v) { writeUInt32(static_cast<std::uint32_t>(v)); }
    void writeUInt32(std::uint32_t v);
    /// IEEE single. -0.0 and denormals are written as +0.0 (the format allows
    /// only normal numbers and +0); NaN and ±Inf throw IOException (`what`
    /// names the field in the message).
    void writeFloat32(float v, const char* what = "Float32");
    /// UTF-8 bytes then a NUL.
    void writeString(const std::string& s);
    void writeBoolean(bool v) { out_.push_back(v ? 1 : 0); }
    void writeVector3D(const float* xyz, const char* what = "Vector3D");
    /// 16 floats, row-major (Transform.get order).
    void writeMatrix(const std::array<float, 16>& rows, const char* what = "Matrix");
    /// 0x??RRGGBB -> R, G, B.
    void writeColorRGB(std::uint32_t rgb);
    /// 0xAARRGGBB -> R, G, B, A (ColorRGBA, JSR-184 1.1 file format §3).
    void writeColorRGBA(std::uint32_t argb);
    void writeObjectIndex(std::uint32_t index) { writeUInt32(index); }
    /// Byte[]: UInt32 count then the bytes.
    void writeByteArray(std::span<const std::uint8_t> bytes);
    /// Raw bytes, no count.
    void writeBytes(std::span<const std::uint8_t> bytes);

    /// Overwrites 4 bytes at `pos` (for lengths known afterwards).
    void patchUInt32(std::size_t pos, std::uint32_t v);

private:
    std::vector<std::uint8_t> out_;
};

/// The Float32 bits the writer emits for `v` (after the -0/denormal rule).
/// Throws IOException for NaN and ±Inf.
std::uint32_t float32BitsForFile(float v, const char* what);

}  // namespace m3g::detail
