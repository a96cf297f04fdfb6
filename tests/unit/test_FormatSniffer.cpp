// FormatSniffer: naming the input by its magic bytes (JSR-184 1.1, Loader).
#include <gtest/gtest.h>

#include <filesystem>

#include <m3g/Exception.h>

#include "FormatSniffer.h"
#include "M3GTestBytes.h"

using m3g::IOException;
using m3g::detail::InputFormat;
using m3g::detail::requireLoadableFormat;
using m3g::detail::sniffFormat;
using namespace m3gtest;

namespace {

std::string rejection(InputFormat f, const std::string& name = {}) {
    try {
        requireLoadableFormat(f, name);
    } catch (const IOException& e) {
        return e.what();
    }
    ADD_FAILURE() << "no IOException";
    return {};
}

}  // namespace

TEST(FormatSniffer, M3GAndTruncatedIdentifier) {
    FileSpec spec;
    EXPECT_EQ(sniffFormat(spec.build()), InputFormat::M3G);
    EXPECT_EQ(sniffFormat(kIdentifier), InputFormat::M3G);
    for (std::size_t n = 1; n < kIdentifier.size(); ++n)
        EXPECT_EQ(sniffFormat(Bytes(kIdentifier.begin(), kIdentifier.begin() + static_cast<std::ptrdiff_t>(n))),
                  InputFormat::M3G)
            << n;
    EXPECT_NO_THROW(requireLoadableFormat(InputFormat::M3G));
}

TEST(FormatSniffer, M3G2ByIdentifierOrHeaderVersion) {
    Bytes id297 = {0xAB, 0x4A, 0x53, 0x52, 0x32, 0x39, 0x37, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A, 0, 0};
    EXPECT_EQ(sniffFormat(id297), InputFormat::M3G2);
    FileSpec v2;
    v2.major = 2;
    EXPECT_EQ(sniffFormat(v2.build()), InputFormat::M3G2);
    EXPECT_NE(rejection(InputFormat::M3G2).find("M3G 2.0 (JSR-297) files are not supported"), std::string::npos);
}

TEST(FormatSniffer, Empty) {
    EXPECT_EQ(sniffFormat({}), InputFormat::Empty);
    EXPECT_NE(rejection(InputFormat::Empty, "a.m3g").find("a.m3g: empty file"), std::string::npos);
}

TEST(FormatSniffer, ImagesAndArchives) {
    EXPECT_EQ(sniffFormat(Bytes{0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A, 0, 0, 0, 13}), InputFormat::PNG);
    EXPECT_NO_THROW(requireLoadableFormat(InputFormat::PNG));
    // JPEG: SOI (FF D8) and the first byte of the next marker.
    EXPECT_EQ(sniffFormat(Bytes{0xFF, 0xD8, 0xFF, 0xE0, 0, 0x10, 'J', 'F', 'I', 'F'}), InputFormat::JPEG);
    EXPECT_EQ(sniffFormat(Bytes{0xFF, 0xD8, 0xFF}), InputFormat::JPEG);
    EXPECT_EQ(sniffFormat(Bytes{0xFF, 0xD8, 0x00}), InputFormat::Unknown);
    EXPECT_NO_THROW(requireLoadableFormat(InputFormat::JPEG));
    EXPECT_EQ(sniffFormat(Bytes{'P', 'K', 3, 4, 20, 0}), InputFormat::Zip);
    EXPECT_EQ(sniffFormat(Bytes{0x1F, 0x8B, 8, 0}), InputFormat::Gzip);
    const std::string xml = "\n  <?xml version=\"1.0\"?><m3g/>";
    EXPECT_EQ(sniffFormat(Bytes(xml.begin(), xml.end())), InputFormat::Xml);
    EXPECT_NE(rejection(InputFormat::Zip).find("ZIP/JAR"), std::string::npos);
}

TEST(FormatSniffer, MascotCapsule) {
    // "MB" + UInt16 version (3..5 seen in the wild) then format bytes.
    EXPECT_EQ(sniffFormat(Bytes{'M', 'B', 5, 0, 1, 2, 1, 1, 10, 0}), InputFormat::MascotMBAC);
    EXPECT_EQ(sniffFormat(Bytes{'M', 'B', 3, 0, 8, 0}), InputFormat::MascotMBAC);
    EXPECT_EQ(sniffFormat(Bytes{'M', 'T', 5, 0, 1, 0}), InputFormat::MascotMTRA);
    EXPECT_EQ(sniffFormat(Bytes{'M', 'B', 'x', 'y'}), InputFormat::Unknown);
    const std::string m = rejection(InputFormat::MascotMBAC);
    EXPECT_NE(m.find("Mascot Capsule"), std::string::npos) << m;
    EXPECT_NE(m.find("not an M3G file"), std::string::npos) << m;
    EXPECT_NE(rejection(InputFormat::MascotMTRA).find("MTRA"), std::string::npos);
}

TEST(FormatSniffer, TextModeDamage) {
    // CR-LF -> LF turns "\r\n\x1A\n" into "\n\x1A\n".
    Bytes b = {0xAB, 0x4A, 0x53, 0x52, 0x31, 0x38, 0x34, 0xBB, 0x0A, 0x1A, 0x0A, 0x00, 0x01};
    EXPECT_EQ(sniffFormat(b), InputFormat::M3GTextMangled);
    EXPECT_NE(rejection(InputFormat::M3GTextMangled).find("text-mode"), std::string::npos);
}

TEST(FormatSniffer, Unknown) {
    EXPECT_EQ(sniffFormat(Bytes{'h', 'e', 'l', 'l', 'o'}), InputFormat::Unknown);
    EXPECT_EQ(sniffFormat(Bytes{0}), InputFormat::Unknown);
    EXPECT_NE(rejection(InputFormat::Unknown, "x.bin").find("x.bin: not an M3G file or a PNG or JPEG image"),
              std::string::npos);
}

TEST(FormatSniffer, CorpusFilesAreM3GOrPng) {
    const auto dir = corpusDir();
    if (!dir) GTEST_SKIP() << "corpus not found (expected ../shared/corpus next to the source tree)";
    int m3g = 0, png = 0;
    for (const auto& path : m3gtest::corpusFiles(*dir)) {
        const InputFormat f = sniffFormat(readFile(path));
        const auto ext = path.extension();
        if (ext == ".png") {
            EXPECT_EQ(f, InputFormat::PNG) << path;
            ++png;
        } else {
            EXPECT_EQ(f, InputFormat::M3G) << path;
            ++m3g;
        }
    }
    EXPECT_GT(m3g, 0);
    EXPECT_GT(png, 0);
}
