// Little-endian writer for the .m3g primitive types (JSR-184 1.1 file format §3).
#include "ByteWriter.h"

#include <bit>

#include <m3g/Exception.h>

#include "Check.h"

namespace m3g::detail {

std::uint32_t float32BitsForFile(float v, const char* what) {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(v);
    const std::uint32_t exponent = (bits >> 23) & 0xFFu;
    if (exponent == 0xFFu)
        throw IOException(str("Saver: ", what, " is ", (bits & 0x7FFFFFu) ? "NaN" : "infinite",
                              ", which the M3G format cannot store"));
    // Zero (either sign) and denormals become +0.0.
    if (exponent == 0) return 0;
    return bits;
}

void ByteWriter::writeUInt16(std::uint16_t v) {
    out_.push_back(static_cast<std::uint8_t>(v & 0xFF));
    out_.push_back(static_cast<std::uint8_t>(v >> 8));
}

void ByteWriter::writeUInt32(std::uint32_t v) {
    out_.push_back(static_cast<std::uint8_t>(v & 0xFF));
    out_.push_back(static_cast<std::uint8_t>((v >> 8) & 0xFF));
    out_.push_back(static_cast<std::uint8_t>((v >> 16) & 0xFF));
    out_.push_back(static_cast<std::uint8_t>(v >> 24));
}

void ByteWriter::writeFloat32(float v, const char* what) { writeUInt32(float32BitsForFile(v, what)); }

void ByteWriter::writeString(const std::string& s) {
    out_.insert(out_.end(), s.begin(), s.end());
    out_.push_back(0);
}

void ByteWriter::writeVector3D(const float* xyz, const char* what) {
    for (int i = 0; i < 3; ++i) writeFloat32(xyz[i], what);
}

void ByteWriter::writeMatrix(const std::array<float, 16>& rows, const char* what) {
    for (float v : rows) writeFloat32(v, what);
}

void ByteWriter::writeColorRGB(std::uint32_t rgb) {
    writeByte(static_cast<std::uint8_t>((rgb >> 16) & 0xFF));
    writeByte(static_cast<std::uint8_t>((rgb >> 8) & 0xFF));
    writeByte(static_cast<std::uint8_t>(rgb & 0xFF));
}

void ByteWriter::writeColorRGBA(std::uint32_t argb) {
    writeColorRGB(argb);
    writeByte(static_cast<std::uint8_t>(argb >> 24));
}

void ByteWriter::writeByteArray(std::span<const std::uint8_t> bytes) {
    writeUInt32(static_cast<std::uint32_t>(bytes.size()));
    writeBytes(bytes);
}

void ByteWriter::writeBytes(std::span<const std::uint8_t> bytes) { out_.insert(out_.end(), bytes.begin(), bytes.end()); }

void ByteWriter::patchUInt32(std::size_t pos, std::uint32_t v) {
    out_[pos] = static_cast<std::uint8_t>(v & 0xFF);
    out_[pos + 1] = static_cast<std::uint8_t>((v >> 8) & 0xFF);
    out_[pos + 2] = static_cast<std::uint8_t>((v >> 16) & 0xFF);
    out_[pos + 3] = static_cast<std::uint8_t>(v >> 24);
}

}  // namespace m3g::detail
