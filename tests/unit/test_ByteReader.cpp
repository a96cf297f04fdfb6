// ByteReader: the .m3g primitive types (JSR-184 1.1 file format §3), bounds and messages.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include <m3g/Exception.h>

#include "ByteReader.h"
#include "M3GSections.h"
#include "M3GTestBytes.h"

using m3g::IOException;
using m3g::detail::ByteReader;
using m3g::detail::LoadLog;
using m3g::detail::M3GObject;
using m3g::detail::objectReader;
using m3gtest::Bytes;
using m3gtest::Writer;

namespace {

std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const IOException& e) {
        return e.what();
    }
    ADD_FAILURE() << "no IOException";
    return {};
}

}  // namespace

TEST(ByteReader, IntegersAreLittleEndian) {
    Writer w;
    w.u8(0xFE).u16(0x1234).u16(0xFFFE).u32(0xDEADBEEF).i32(-5);
    ByteReader r(w.b);
    EXPECT_EQ(r.readByte(), 0xFE);
    EXPECT_EQ(r.readUInt16(), 0x1234);
    r = ByteReader(w.b);
    r.skip(3, "x");
    EXPECT_EQ(r.readInt16(), -2);
    EXPECT_EQ(r.readUInt32(), 0xDEADBEEFu);
    EXPECT_EQ(r.readInt32(), -5);
    EXPECT_TRUE(r.atEnd());
    EXPECT_EQ(r.position(), w.b.size());
}

TEST(ByteReader, Float32NormalValues) {
    Writer w;
    w.f32(1.5f).f32(-3.25f).f32(0.0f).f32(std::numeric_limits<float>::min()).f32(
        std::numeric_limits<float>::max());
    ByteReader r(w.b);
    EXPECT_EQ(r.readFloat32(), 1.5f);
    EXPECT_EQ(r.readFloat32(), -3.25f);
    const float z = r.readFloat32();
    EXPECT_EQ(z, 0.0f);
    EXPECT_FALSE(std::signbit(z));
    EXPECT_EQ(r.readFloat32(), std::numeric_limits<float>::min());
    EXPECT_EQ(r.readFloat32(), std::numeric_limits<float>::max());
}

TEST(ByteReader, Float32RejectsNaNInfDenormalAndNegativeZero) {
    const std::uint32_t bad[] = {0x7FC00000u, 0xFFC00001u, 0x7F800000u, 0xFF800000u, 0x00000001u, 0x807FFFFFu,
                                 0x80000000u};
    for (std::uint32_t bits : bad) {
        Writer w;
        w.u8(0).u32(bits);
        ByteReader r(w.b, "ctx", 100);
        r.readByte();
        const std::string m = messageOf([&] { r.readFloat32(); });
        EXPECT_NE(m.find("byte offset 101"), std::string::npos) << m;
        EXPECT_NE(m.find("ctx: "), std::string::npos) << m;
    }
}

TEST(ByteReader, LenientReadsNegativeZeroAsPositiveZeroWithWarning) {
    Writer w;
    w.u32(0x80000000u).u32(0x00000001u);
    LoadLog log;
    log.options.lenient = true;
    ByteReader r(w.b, "section 2, object 3 (Light, type 12)", 40, &log);
    const float z = r.readFloat32();
    EXPECT_EQ(z, 0.0f);
    EXPECT_FALSE(std::signbit(z));
    ASSERT_EQ(log.warnings.size(), 1u);
    EXPECT_NE(log.warnings[0].find("-0.0"), std::string::npos);
    EXPECT_NE(log.warnings[0].find("section 2, object 3"), std::string::npos);
    EXPECT_NE(log.warnings[0].find("byte offset 40"), std::string::npos);
    EXPECT_THROW(r.readFloat32(), IOException);  // denormals stay errors
}

TEST(ByteReader, Strings) {
    Writer w;
    w.str("abc").str("").str("\xC3\xA9t\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80");
    ByteReader r(w.b);
    EXPECT_EQ(r.readString(), "abc");
    EXPECT_EQ(r.readString(), "");
    EXPECT_EQ(r.readString(), "\xC3\xA9t\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80");
    EXPECT_TRUE(r.atEnd());
}

TEST(ByteReader, UnterminatedStringFails) {
    Bytes b = {'a', 'b', 'c'};
    ByteReader r(b);
    const std::string m = messageOf([&] { r.readString(); });
    EXPECT_NE(m.find("NUL"), std::string::npos) << m;
    ByteReader empty(Bytes{});
    EXPECT_THROW(empty.readString(), IOException);
}

TEST(ByteReader, InvalidUtf8StrictFailsLenientWarns) {
    const Bytes bad[] = {{0xC3, 0}, {0x80, 0}, {0xC0, 0xAF, 0}, {0xED, 0xA0, 0x80, 0}, {0xF4, 0x90, 0x80, 0x80, 0},
                         {'A', 0xE9, 'B', 0}};
    for (const Bytes& b : bad) {
        ByteReader r(b);
        EXPECT_THROW(r.readString(), IOException);
        LoadLog log;
        log.options.lenient = true;
        ByteReader l(b, {}, 0, &log);
        EXPECT_EQ(l.readString().size(), b.size() - 1);
        EXPECT_EQ(log.warnings.size(), 1u);
    }
}

TEST(ByteReader, BooleanOnlyZeroOrOne) {
    Bytes b = {0, 1, 2};
    ByteReader r(b, "ctx", 7);
    EXPECT_FALSE(r.readBoolean());
    EXPECT_TRUE(r.readBoolean());
    const std::string m = messageOf([&] { r.readBoolean(); });
    EXPECT_NE(m.find("Boolean"), std::string::npos) << m;
    EXPECT_NE(m.find("byte offset 9"), std::string::npos) << m;
}

TEST(ByteReader, CompoundTypes) {
    Writer w;
    w.f32(1).f32(2).f32(3);
    for (int i = 0; i < 16; ++i) w.f32(float(i + 1));
    w.u8(0x11).u8(0x22).u8(0x33);
    w.u8(0x11).u8(0x22).u8(0x33).u8(0x80);
    w.u32(7);
    ByteReader r(w.b);
    EXPECT_EQ(r.readVector3D(), (std::array<float, 3>{1, 2, 3}));
    const auto m = r.readMatrix();
    for (int i = 0; i < 16; ++i) EXPECT_EQ(m[i], float(i + 1));
    EXPECT_EQ(r.readColorRGB(), 0x00112233u);
    EXPECT_EQ(r.readColorRGBA(), 0x80112233u);
    EXPECT_EQ(r.readObjectIndex(), 7u);
    EXPECT_TRUE(r.atEnd());
}

TEST(ByteReader, Arrays) {
    Writer w;
    w.u32(3).u8(9).u8(8).u8(7);
    w.u32(2).u16(0xBEEF).u16(1);
    w.u32(2).u32(5).u32(0xFFFFFFFF);
    w.u32(1).f32(0.5f);
    w.u32(2).u32(0).u32(3);
    w.f32(4).f32(5);
    w.u32(0);
    ByteReader r(w.b);
    EXPECT_EQ(r.readByteArray("a"), (Bytes{9, 8, 7}));
    EXPECT_EQ(r.readUInt16Array("b"), (std::vector<std::uint16_t>{0xBEEF, 1}));
    EXPECT_EQ(r.readUInt32Array("c"), (std::vector<std::uint32_t>{5, 0xFFFFFFFF}));
    EXPECT_EQ(r.readFloat32Array("d"), (std::vector<float>{0.5f}));
    EXPECT_EQ(r.readObjectIndexArray("e"), (std::vector<std::uint32_t>{0, 3}));
    EXPECT_EQ(r.readFloat32s(2, "f"), (std::vector<float>{4, 5}));
    EXPECT_TRUE(r.readByteArray("g").empty());
    EXPECT_TRUE(r.atEnd());
}

TEST(ByteReader, HugeCountsFailBeforeAllocating) {
    for (std::uint32_t count : {0xFFFFFFFFu, 0x80000000u, 0x40000001u, 5u}) {
        Writer w;
        w.u32(count).u32(1).u32(2);  // 8 bytes of payload
        auto run = [&](auto f) {
            ByteReader r(w.b, "section 2, object 5 (Mesh, type 14)", 1000);
            const std::string m = messageOf([&] { f(r); });
            EXPECT_NE(m.find("section 2, object 5 (Mesh, type 14)"), std::string::npos) << m;
            EXPECT_NE(m.find("byte offset 1000"), std::string::npos) << m;
            EXPECT_NE(m.find("names"), std::string::npos) << m;
        };
        if (count > 8) run([](ByteReader& r) { r.readByteArray("names"); });
        run([](ByteReader& r) { r.readUInt32Array("names"); });
        run([](ByteReader& r) { r.readFloat32Array("names"); });
        run([](ByteReader& r) { r.readObjectIndexArray("names"); });
        if (count > 4) run([](ByteReader& r) { r.readUInt16Array("names"); });
    }
    ByteReader r(Bytes(8));
    EXPECT_THROW(r.requireAvailable(0xFFFFFFFFFFFFFFFFull, 4, "x"), IOException);
    EXPECT_THROW(r.readFloat32s(3, "x"), IOException);
    EXPECT_THROW(r.readBytes(9, "x"), IOException);
    EXPECT_EQ(r.position(), 0u);
}

TEST(ByteReader, TruncationOfEveryPrimitive) {
    const Bytes three = {1, 2, 3};
    const std::function<void(ByteReader&)> reads[] = {
        [](ByteReader& r) { r.readUInt32(); },  [](ByteReader& r) { r.readInt32(); },
        [](ByteReader& r) { r.readFloat32(); }, [](ByteReader& r) { r.readVector3D(); },
        [](ByteReader& r) { r.readMatrix(); },  [](ByteReader& r) { r.readColorRGBA(); },
        [](ByteReader& r) { r.readObjectIndex(); }};
    for (const auto& f : reads) {
        ByteReader r(three, "ctx", 50);
        const std::string m = messageOf([&] { f(r); });
        EXPECT_NE(m.find("truncated"), std::string::npos) << m;
        EXPECT_NE(m.find("byte offset 50"), std::string::npos) << m;
    }
    ByteReader e(Bytes{});
    EXPECT_THROW(e.readByte(), IOException);
    EXPECT_THROW(e.readBoolean(), IOException);
    EXPECT_THROW(e.readUInt16(), IOException);
    EXPECT_THROW(e.readColorRGB(), IOException);
    ByteReader one(Bytes{1});
    EXPECT_THROW(one.readInt16(), IOException);
}

TEST(ByteReader, SubReaderContinuesOffsetsAndExpectEnd) {
    Writer w;
    w.u8(1).u8(2).u32(0xAABBCCDD).u8(3).u8(4);
    ByteReader r(w.b, "outer", 10);
    r.readUInt16();
    ByteReader s = r.sub(5, "inner", "object");
    EXPECT_EQ(r.position(), 7u);
    EXPECT_EQ(s.offset(), 12u);
    EXPECT_EQ(s.readUInt32(), 0xAABBCCDDu);
    const std::string m = messageOf([&] { s.expectEnd(); });
    EXPECT_NE(m.find("inner: object data not consumed exactly: 1 byte left over at byte offset 16"),
              std::string::npos)
        << m;
    s.readByte();
    EXPECT_NO_THROW(s.expectEnd());
    EXPECT_THROW(r.sub(2, "x", "y"), IOException);
}

TEST(ByteReader, OffsetQualifierForInflatedData) {
    ByteReader r(Bytes{}, "section 3, object 9 (Group, type 9)", 77, nullptr, "of the inflated data of section 3");
    const std::string m = messageOf([&] { r.readByte(); });
    EXPECT_NE(m.find("byte offset 77 of the inflated data of section 3"), std::string::npos) << m;
}

// An object's reader (objectReader) describes itself only when a message
// needs it: the failure and the warning still name the object and, for a
// zlib section, the inflated data; a sub-reader keeps the qualifier.
TEST(ByteReader, ObjectReaderDescribesItselfInMessages) {
    const Bytes bytes{1, 2};
    M3GObject o;
    o.type = 14;
    o.section = 2;
    o.index = 5;
    o.dataOffset = 40;
    o.inflated = true;
    o.data = bytes;
    LoadLog log;
    log.options.lenient = true;
    ByteReader r = objectReader(o, &log);
    r.warn("odd value");
    ASSERT_EQ(log.warnings.size(), 1u);
    EXPECT_NE(log.warnings[0].find("section 2, object 5 (Mesh, type 14): odd value at byte offset 40 of the inflated "
                                   "data of section 2"),
              std::string::npos)
        << log.warnings[0];
    ByteReader fresh = objectReader(o, &log);
    ByteReader inner = fresh.sub(1, "inner", "the inner part");
    const std::string m = messageOf([&] { inner.readInt32(); });
    EXPECT_NE(m.find("inner: "), std::string::npos) << m;
    EXPECT_NE(m.find("at byte offset 40 of the inflated data of section 2"), std::string::npos) << m;
    const std::string own = messageOf([&] { fresh.readInt32(); });
    EXPECT_NE(own.find("section 2, object 5 (Mesh, type 14): "), std::string::npos) << own;
    EXPECT_NE(own.find("at byte offset 41 of the inflated data of section 2"), std::string::npos) << own;
}
