// Bounded little-endian reader for the .m3g primitive types (JSR-184 1.1 file format §3).
#include "ByteReader.h"

#include <bit>
#include <cstring>
#include <limits>
#include <utility>

#include <m3g/Exception.h>

#include "Check.h"

namespace m3g::detail {

ByteReader::ByteReader(std::span<const std::uint8_t> data, std::string context, std::size_t baseOffset,
                       LoadLog* log, std::string offsetWhere)
    : data_(data), base_(baseOffset), context_(std::move(context)), offsetWhere_(std::move(offsetWhere)),
      log_(log) {}

ByteReader ByteReader::described(std::span<const std::uint8_t> data, Describe describe, std::size_t baseOffset,
                                 LoadLog* log) {
    ByteReader r(data, std::string(), baseOffset, log);
    r.describe_ = std::move(describe);
    return r;
}

void ByteReader::describe() const {
    if (!describe_) return;
    describe_(context_, offsetWhere_);
    describe_ = nullptr;
}

std::string ByteReader::whereAt(std::size_t relativePos, const std::string& what) const {
    describe();
    std::string s;
    if (!context_.empty()) s = context_ + ": ";
    s += what;
    s += str(" at byte offset ", base_ + relativePos);
    if (!offsetWhere_.empty()) s += " " + offsetWhere_;
    return s;
}

std::string ByteReader::where(const std::string& what) const { return whereAt(pos_, what); }

void ByteReader::failAt(std::size_t relativePos, const std::string& what) const {
    throw IOException(whereAt(relativePos, what));
}

void ByteReader::fail(const std::string& what) const { failAt(pos_, what); }

void ByteReader::warnAt(std::size_t relativePos, const std::string& what) const {
    if (log_) log_->warn(whereAt(relativePos, what));
}

void ByteReader::warn(const std::string& what) const { warnAt(pos_, what); }

void ByteReader::need(std::size_t n, const char* what) {
    if (remaining() < n)
        fail(str("truncated: ", what, " needs ", n, " byte", n == 1 ? "" : "s", ", only ", remaining(),
                 " left"));
}

std::uint8_t ByteReader::readByte() {
    need(1, "Byte");
    return data_[pos_++];
}

std::uint16_t ByteReader::readUInt16() {
    need(2, "UInt16");
    const std::uint16_t v = static_cast<std::uint16_t>(data_[pos_] | (data_[pos_ + 1] << 8));
    pos_ += 2;
    return v;
}

std::int16_t ByteReader::readInt16() { return static_cast<std::int16_t>(readUInt16()); }

std::uint32_t ByteReader::readUInt32() {
    need(4, "UInt32");
    const std::uint32_t v = static_cast<std::uint32_t>(data_[pos_]) |
                            (static_cast<std::uint32_t>(data_[pos_ + 1]) << 8) |
                            (static_cast<std::uint32_t>(data_[pos_ + 2]) << 16) |
                            (static_cast<std::uint32_t>(data_[pos_ + 3]) << 24);
    pos_ += 4;
    return v;
}

std::int32_t ByteReader::readInt32() { return static_cast<std::int32_t>(readUInt32()); }

float ByteReader::readFloat32() {
    need(4, "Float32");
    const std::size_t at = pos_;
    const std::uint32_t bits = readUInt32();
    const std::uint32_t exponent = (bits >> 23) & 0xFFu;
    const std::uint32_t mantissa = bits & 0x7FFFFFu;
    if (exponent == 0xFFu)
        failAt(at, mantissa ? "Float32 is NaN (not allowed in M3G files)"
                            : "Float32 is infinite (not allowed in M3G files)");
    if (bits == 0x80000000u) {
        if (!lenient()) failAt(at, "Float32 is -0.0 (not allowed in M3G files; a lenient load accepts it)");
        warnAt(at, "Float32 -0.0 read as +0.0");
        return 0.0f;
    }
    if (exponent == 0 && mantissa != 0) failAt(at, "Float32 is a denormal (not allowed in M3G files)");
    return std::bit_cast<float>(bits);
}

bool isValidUtf8(std::span<const std::uint8_t> s) {
    std::size_t i = 0;
    while (i < s.size()) {
        const std::uint8_t c = s[i];
        if (c < 0x80) { ++i; continue; }
        std::size_t len;
        std::uint32_t cp;
        if ((c & 0xE0) == 0xC0) { len = 2; cp = c & 0x1Fu; }
        else if ((c & 0xF0) == 0xE0) { len = 3; cp = c & 0x0Fu; }
        else if ((c & 0xF8) == 0xF0) { len = 4; cp = c & 0x07u; }
        else return false;
        if (s.size() - i < len) return false;
        for (std::size_t k = 1; k < len; ++k) {
            if ((s[i + k] & 0xC0) != 0x80) return false;
            cp = (cp << 6) | (s[i + k] & 0x3Fu);
        }
        static constexpr std::uint32_t kMin[5] = {0, 0, 0x80, 0x800, 0x10000};
        if (cp < kMin[len] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return false;
        i += len;
    }
    return true;
}

std::string ByteReader::readString() {
    const std::size_t start = pos_;
    const std::uint8_t* begin = data_.data() + pos_;
    const void* nul = remaining() ? std::memchr(begin, 0, remaining()) : nullptr;
    if (!nul) fail(str("truncated: String has no NUL terminator in the remaining ", remaining(), " bytes"));
    const std::size_t len = static_cast<std::size_t>(static_cast<const std::uint8_t*>(nul) - begin);
    const auto bytes = data_.subspan(pos_, len);
    pos_ += len + 1;
    if (!isValidUtf8(bytes)) {
        if (!lenient()) failAt(start, "String is not valid UTF-8");
        warnAt(start, "String is not valid UTF-8 (bytes kept as they are)");
    }
    return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

bool ByteReader::readBoolean() {
    need(1, "Boolean");
    const std::uint8_t v = data_[pos_];
    if (v > 1) fail(str("Boolean has value ", int(v), " (must be 0 or 1)"));
    ++pos_;
    return v == 1;
}

std::array<float, 3> ByteReader::readVector3D() {
    need(12, "Vector3D");
    return {readFloat32(), readFloat32(), readFloat32()};
}

std::array<float, 16> ByteReader::readMatrix() {
    need(64, "Matrix");
    std::array<float, 16> m{};
    for (float& v : m) v = readFloat32();
    return m;
}

std::uint32_t ByteReader::readColorRGB() {
    need(3, "ColorRGB");
    const std::uint32_t r = data_[pos_], g = data_[pos_ + 1], b = data_[pos_ + 2];
    pos_ += 3;
    return (r << 16) | (g << 8) | b;
}

std::uint32_t ByteReader::readColorRGBA() {
    need(4, "ColorRGBA");
    const std::uint32_t r = data_[pos_], g = data_[pos_ + 1], b = data_[pos_ + 2], a = data_[pos_ + 3];
    pos_ += 4;
    return (a << 24) | (r << 16) | (g << 8) | b;
}

std::uint32_t ByteReader::readObjectIndex() {
    need(4, "ObjectIndex");
    return readUInt32();
}

void ByteReader::requireAvailable(std::uint64_t count, std::uint64_t elementSize, const char* what) {
    // count and elementSize are each < 2^32 in practice; guard the product anyway.
    if (elementSize != 0 && count > std::numeric_limits<std::uint64_t>::max() / elementSize)
        fail(str("count ", count, " of ", what, " is too large"));
    const std::uint64_t bytes = count * elementSize;
    if (bytes > remaining())
        fail(str("truncated: ", what, " has ", count, " element", count == 1 ? "" : "s", " (", bytes,
                 " bytes) but only ", remaining(), " bytes are left"));
}

std::uint32_t ByteReader::readCount(std::size_t elementSize, const char* what) {
    const std::size_t at = pos_;
    const std::uint32_t n = readUInt32();
    if (elementSize != 0 && std::uint64_t(n) * elementSize > remaining())
        failAt(at, str("count ", n, " of ", what, " needs ", std::uint64_t(n) * elementSize,
                       " bytes but only ", remaining(), " are left"));
    return n;
}

std::span<const std::uint8_t> ByteReader::readBytes(std::uint64_t n, const char* what) {
    requireAvailable(n, 1, what);
    const auto s = data_.subspan(pos_, static_cast<std::size_t>(n));
    pos_ += static_cast<std::size_t>(n);
    return s;
}

std::vector<std::uint8_t> ByteReader::readByteArray(const char* what) {
    const std::uint32_t n = readCount(1, what);
    const auto s = readBytes(n, what);
    return std::vector<std::uint8_t>(s.begin(), s.end());
}

std::vector<std::uint16_t> ByteReader::readUInt16Array(const char* what) {
    const std::uint32_t n = readCount(2, what);
    std::vector<std::uint16_t> v(n);
    for (auto& x : v) x = readUInt16();
    return v;
}

std::vector<std::uint32_t> ByteReader::readUInt32Array(const char* what) {
    const std::uint32_t n = readCount(4, what);
    std::vector<std::uint32_t> v(n);
    for (auto& x : v) x = readUInt32();
    return v;
}

std::vector<float> ByteReader::readFloat32Array(const char* what) {
    const std::uint32_t n = readCount(4, what);
    std::vector<float> v(n);
    for (auto& x : v) x = readFloat32();
    return v;
}

std::vector<std::uint32_t> ByteReader::readObjectIndexArray(const char* what) {
    const std::uint32_t n = readCount(4, what);
    std::vector<std::uint32_t> v(n);
    for (auto& x : v) x = readObjectIndex();
    return v;
}

std::vector<float> ByteReader::readFloat32s(std::uint64_t n, const char* what) {
    requireAvailable(n, 4, what);
    std::vector<float> v(static_cast<std::size_t>(n));
    for (auto& x : v) x = readFloat32();
    return v;
}

ByteReader ByteReader::sub(std::uint64_t n, std::string context, const char* what) {
    const std::size_t start = pos_;
    const auto s = readBytes(n, what);
    describe();  // the sub-reader keeps the offset qualifier
    return ByteReader(s, std::move(context), base_ + start, log_, offsetWhere_);
}

void ByteReader::expectEnd(const char* what) {
    if (!atEnd())
        fail(str(what, " not consumed exactly: ", remaining(), " byte", remaining() == 1 ? "" : "s",
                 " left over"));
}

}  // namespace m3g::detail
