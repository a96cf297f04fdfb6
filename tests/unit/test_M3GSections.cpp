// M3GSections: identifier, sections, checksums, zlib, object records, header
// and section rules (JSR-184 1.1 file format, sections "File Structure",
// "Header Object" and "External Reference", and §8); robustness against
// truncated and corrupted input; the shared corpus.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <iostream>
#include <random>
#include <set>

#include <m3g/Exception.h>

#include "FormatSniffer.h"
#include "M3GSections.h"
#include "M3GTestBytes.h"

using m3g::IOException;
using m3g::detail::LoadLog;
using m3g::detail::M3GFile;
using m3g::detail::parseM3GFile;
using namespace m3gtest;

namespace {

std::string failure(const Bytes& b, bool lenient = false) {
    LoadLog log;
    log.options.lenient = lenient;
    try {
        parseM3GFile(b, log);
    } catch (const IOException& e) {
        return e.what();
    }
    ADD_FAILURE() << "no IOException";
    return {};
}

M3GFile parse(const Bytes& b, LoadLog& log) { return parseM3GFile(b, log); }

const Bytes kVertexArrayData = {2, 3, 0, 1, 0, 1, 0, 2, 0, 3, 0};
const Bytes kMeshData = {9, 8, 7, 6, 5, 4, 3, 2, 1};

FileSpec twoSectionFile() {
    FileSpec f;
    f.sections.push_back({0, {object(20, kVertexArrayData), object(14, kMeshData)}});
    f.sections.push_back({1, {object(9, Bytes(40, 0x5A)), object(22, {}), object(20, kVertexArrayData)}});
    return f;
}

}  // namespace

TEST(M3GSections, HeaderOnlyFile) {
    FileSpec spec;
    spec.approxSize = 4321;
    spec.authoring = "Hand-made \xE2\x9C\x93";
    const Bytes b = spec.build();
    LoadLog log;
    const M3GFile f = parse(b, log);
    EXPECT_EQ(f.header.versionMajor, 1);
    EXPECT_EQ(f.header.versionMinor, 0);
    EXPECT_FALSE(f.header.hasExternalReferences);
    EXPECT_EQ(f.header.totalFileSize, b.size());
    EXPECT_EQ(f.header.approximateContentSize, 4321u);
    EXPECT_EQ(f.header.authoringField, spec.authoring);
    ASSERT_EQ(f.sections.size(), 1u);
    EXPECT_EQ(f.sections[0].fileOffset, 12u);
    ASSERT_EQ(f.objects.size(), 1u);
    EXPECT_EQ(f.objects[0].type, 0);
    EXPECT_EQ(f.objects[0].index, 1u);
    EXPECT_EQ(f.fileSize, b.size());
    EXPECT_TRUE(log.warnings.empty());
}

TEST(M3GSections, UncompressedAndZlibSections) {
    const Bytes b = twoSectionFile().build();
    LoadLog log;
    const M3GFile f = parse(b, log);
    ASSERT_EQ(f.sections.size(), 3u);
    EXPECT_EQ(f.sections[1].compressionScheme, 0);
    EXPECT_EQ(f.sections[2].compressionScheme, 1);
    EXPECT_EQ(f.sections[2].uncompressedLength, 5u + 40 + 5 + 0 + 5 + kVertexArrayData.size());
    EXPECT_EQ(f.sections[1].objectCount, 2u);
    EXPECT_EQ(f.sections[2].objectCount, 3u);
    ASSERT_EQ(f.objects.size(), 6u);
    const std::uint8_t types[] = {0, 20, 14, 9, 22, 20};
    for (std::size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(f.objects[i].type, types[i]);
        EXPECT_EQ(f.objects[i].index, i + 1);
        EXPECT_EQ(f.objects[i].section, i == 0 ? 0 : i < 3 ? 1 : 2);
    }
    EXPECT_EQ(Bytes(f.objects[1].data.begin(), f.objects[1].data.end()), kVertexArrayData);
    EXPECT_EQ(Bytes(f.objects[2].data.begin(), f.objects[2].data.end()), kMeshData);
    EXPECT_EQ(Bytes(f.objects[3].data.begin(), f.objects[3].data.end()), Bytes(40, 0x5A));
    EXPECT_TRUE(f.objects[4].data.empty());
    EXPECT_EQ(Bytes(f.objects[5].data.begin(), f.objects[5].data.end()), kVertexArrayData);
    // Offsets: in the file for scheme 0, in the inflated data for scheme 1.
    EXPECT_FALSE(f.objects[2].inflated);
    EXPECT_EQ(b[f.objects[2].dataOffset], kMeshData[0]);
    EXPECT_EQ(f.objects[2].data.data(), b.data() + f.objects[2].dataOffset);
    EXPECT_TRUE(f.objects[3].inflated);
    EXPECT_EQ(f.objects[3].dataOffset, 5u);
    EXPECT_EQ(f.objects[5].dataOffset, 5u + 40 + 5 + 5);
    EXPECT_EQ(m3g::detail::objectContext(f.objects[2]), "section 1, object 3 (Mesh, type 14)");

    // Object readers name the object and offsets.
    auto r = m3g::detail::objectReader(f.objects[5], &log);
    r.skip(kVertexArrayData.size(), "all");
    try {
        r.readByte();
        FAIL();
    } catch (const IOException& e) {
        EXPECT_NE(std::string(e.what()).find("section 2, object 6 (VertexArray, type 20)"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("of the inflated data of section 2"), std::string::npos);
    }
}

TEST(M3GSections, MovedFileKeepsInflatedSpansValid) {
    const Bytes b = twoSectionFile().build();
    LoadLog log;
    std::vector<M3GFile> files;
    files.push_back(parse(b, log));
    files.push_back(parse(b, log));
    M3GFile moved = std::move(files[0]);
    files.clear();
    EXPECT_EQ(Bytes(moved.objects[3].data.begin(), moved.objects[3].data.end()), Bytes(40, 0x5A));
}

TEST(M3GSections, EmptySectionsAreAllowed) {
    FileSpec spec;
    spec.sections.push_back({0, {}});
    spec.sections.push_back({1, {}});
    spec.sections.push_back({0, {object(13, {1, 2})}});
    LoadLog log;
    const M3GFile f = parse(spec.build(), log);
    EXPECT_EQ(f.sections.size(), 4u);
    ASSERT_EQ(f.objects.size(), 2u);
    EXPECT_EQ(f.objects[1].index, 2u);
    EXPECT_EQ(f.objects[1].section, 3);
}

TEST(M3GSections, ChecksumMismatch) {
    Bytes b = twoSectionFile().build();
    LoadLog log;
    const M3GFile f = parse(b, log);
    const std::size_t at = f.objects[2].dataOffset;
    b[at] ^= 0x01;
    const std::string m = failure(b);
    EXPECT_NE(m.find("section 1"), std::string::npos) << m;
    EXPECT_NE(m.find("Adler-32"), std::string::npos) << m;
    EXPECT_NE(m.find("byte offset"), std::string::npos) << m;
}

namespace {

// Builds identifier + header section + one custom raw section.
Bytes withRawSection(const Bytes& rawSection) {
    FileSpec spec;
    Bytes h = spec.build();
    FileSpec sized;
    sized.totalFileSize = static_cast<std::uint32_t>(h.size() + rawSection.size());
    Bytes out = sized.build();
    out.insert(out.end(), rawSection.begin(), rawSection.end());
    return out;
}

Bytes rawSection(std::uint8_t scheme, std::uint32_t total, std::uint32_t uncompressed, const Bytes& stored,
                 bool fixChecksum = true) {
    Writer w;
    w.u8(scheme).u32(total).u32(uncompressed).bytes(stored);
    w.u32(fixChecksum ? adler(w.b.data(), w.b.size()) : 0);
    return w.b;
}

Bytes deflate(const Bytes& raw) {
    uLongf len = compressBound(static_cast<uLong>(raw.size()));
    Bytes out(len);
    compress2(out.data(), &len, raw.data(), static_cast<uLong>(raw.size()), 9);
    out.resize(len);
    return out;
}

}  // namespace

TEST(M3GSections, SectionHeaderErrors) {
    const Bytes objs = object(13, {1, 2, 3});
    const auto n = static_cast<std::uint32_t>(objs.size());
    // Valid baseline.
    {
        LoadLog log;
        EXPECT_EQ(parse(withRawSection(rawSection(0, n + 13, n, objs)), log).objects.size(), 2u);
    }
    EXPECT_NE(failure(withRawSection(rawSection(2, n + 13, n, objs))).find("CompressionScheme 2"),
              std::string::npos);
    EXPECT_NE(failure(withRawSection(rawSection(0, n + 13, n + 1, objs))).find("UncompressedLength"),
              std::string::npos);
    EXPECT_NE(failure(withRawSection(rawSection(0, 12, n, objs))).find("TotalSectionLength 12"), std::string::npos);
    EXPECT_NE(failure(withRawSection(rawSection(0, 0xFFFFFFFF, n, objs))).find("truncated"), std::string::npos);
    EXPECT_NE(failure(withRawSection(rawSection(0, n + 13, n, objs, false))).find("Adler-32"), std::string::npos);
}

TEST(M3GSections, ZlibLengthMustMatch) {
    const Bytes objs = object(13, Bytes(100, 7));
    const Bytes z = deflate(objs);
    const auto total = static_cast<std::uint32_t>(z.size() + 13);
    const auto n = static_cast<std::uint32_t>(objs.size());
    {
        LoadLog log;
        EXPECT_EQ(parse(withRawSection(rawSection(1, total, n, z)), log).objects.size(), 2u);
    }
    for (std::uint32_t wrong : {n - 1, n + 1, 0u, 0xFFFFFFFFu, 0x7FFFFFFFu}) {
        const std::string m = failure(withRawSection(rawSection(1, total, wrong, z)));
        EXPECT_NE(m.find("section 1"), std::string::npos) << m;
        EXPECT_NE(m.find("UncompressedLength"), std::string::npos) << m;
    }
    // Not a zlib stream at all.
    EXPECT_NE(failure(withRawSection(rawSection(1, n + 13, n, objs))).find("zlib"), std::string::npos);
    // Truncated stream.
    Bytes cut(z.begin(), z.end() - 6);
    EXPECT_NE(failure(withRawSection(rawSection(1, static_cast<std::uint32_t>(cut.size() + 13), n, cut)))
                  .find("zlib"),
              std::string::npos);
    // Trailing bytes after the stream.
    Bytes extra = z;
    extra.push_back(0);
    EXPECT_NE(failure(withRawSection(rawSection(1, static_cast<std::uint32_t>(extra.size() + 13), n, extra)))
                  .find("after the end of the zlib stream"),
              std::string::npos);
}

TEST(M3GSections, ZlibBombIsBoundedByDeclaredLength) {
    // 16 MiB of zeros compress to ~16 KiB; declare less and it must fail
    // without producing more than the declared length.
    const Bytes raw(16u << 20, 0);
    const Bytes z = deflate(raw);
    const std::string m =
        failure(withRawSection(rawSection(1, static_cast<std::uint32_t>(z.size() + 13), 1000, z)));
    EXPECT_NE(m.find("more than UncompressedLength 1000"), std::string::npos) << m;
}

TEST(M3GSections, ObjectRecordErrors) {
    auto sectionWith = [](const Bytes& raw) {
        return withRawSection(rawSection(0, static_cast<std::uint32_t>(raw.size() + 13),
                                         static_cast<std::uint32_t>(raw.size()), raw));
    };
    Writer longLen;
    longLen.u8(13).u32(0xFFFFFFFF).u8(1);
    std::string m = failure(sectionWith(longLen.b));
    EXPECT_NE(m.find("Length 4294967295"), std::string::npos) << m;
    EXPECT_NE(m.find("section 1"), std::string::npos) << m;
    Writer shortHdr;
    shortHdr.u8(13).u8(0).u8(0);
    EXPECT_NE(failure(sectionWith(shortHdr.b)).find("object header"), std::string::npos);
    m = failure(sectionWith(object(23, {})));
    EXPECT_NE(m.find("reserved ObjectType 23"), std::string::npos) << m;
    EXPECT_NE(failure(sectionWith(object(254, {}))).find("reserved"), std::string::npos);
}

TEST(M3GSections, HeaderRules) {
    // Header outside section 0.
    FileSpec a;
    a.sections.push_back({0, {object(0, headerData(1, 0, 0, 0, 0, ""))}});
    std::string m = failure(a.build());
    EXPECT_NE(m.find("section 1, object 2 (Header, type 0)"), std::string::npos) << m;
    EXPECT_NE(m.find("only in section 0"), std::string::npos) << m;

    // Section 0 with a second object / a non-header / nothing.
    Bytes b = kIdentifier;
    Bytes s0 = section(0, {object(0, headerData(1, 0, 0, 0, 0, "")), object(9, {})});
    b.insert(b.end(), s0.begin(), s0.end());
    m = failure(b);
    EXPECT_NE(m.find("only the header"), std::string::npos) << m;
    b = kIdentifier;
    s0 = section(0, {object(9, {})});
    b.insert(b.end(), s0.begin(), s0.end());
    EXPECT_NE(failure(b).find("must be the header"), std::string::npos);
    b = kIdentifier;
    s0 = section(0, {});
    b.insert(b.end(), s0.begin(), s0.end());
    EXPECT_NE(failure(b).find("section is empty"), std::string::npos);

    // Header object fields.
    FileSpec badBool;
    badBool.hasExt = 2;
    EXPECT_NE(failure(badBool.build()).find("Boolean"), std::string::npos);
    b = kIdentifier;
    Bytes hd = headerData(1, 0, 0, 0, 0, "x");
    hd.push_back(0);
    s0 = section(0, {object(0, hd)});
    b.insert(b.end(), s0.begin(), s0.end());
    EXPECT_NE(failure(b).find("not consumed exactly"), std::string::npos);
}

TEST(M3GSections, Versions) {
    FileSpec v11;
    v11.minor = 1;
    EXPECT_NE(failure(v11.build()).find("1.1"), std::string::npos);
    LoadLog log;
    log.options.lenient = true;
    const M3GFile f = parse(v11.build(), log);
    EXPECT_EQ(f.header.versionMinor, 1);
    ASSERT_EQ(log.warnings.size(), 1u);
    EXPECT_NE(log.warnings[0].find("version 1.1"), std::string::npos);
    EXPECT_NE(log.warnings[0].find("section 0, object 1 (Header, type 0)"), std::string::npos);

    FileSpec v2;
    v2.major = 2;
    EXPECT_NE(failure(v2.build(), true).find("M3G 2.0 (JSR-297) files are not supported"), std::string::npos);
    FileSpec v0;
    v0.major = 0;
    EXPECT_NE(failure(v0.build(), true).find("unsupported file version 0.0"), std::string::npos);
}

TEST(M3GSections, ExternalReferenceRules) {
    FileSpec ok;
    ok.hasExt = 1;
    ok.sections.push_back({0, {object(255, {'a', '.', 'p', 'n', 'g', 0}), object(255, {'b', 0})}});
    ok.sections.push_back({1, {object(9, {})}});
    LoadLog log;
    const M3GFile f = parse(ok.build(), log);
    EXPECT_TRUE(f.header.hasExternalReferences);
    ASSERT_EQ(f.objects.size(), 4u);
    EXPECT_EQ(f.objects[1].type, 255);
    EXPECT_EQ(f.objects[1].index, 2u);
    EXPECT_EQ(f.objects[3].index, 4u);

    FileSpec noFlag = ok;
    noFlag.hasExt = 0;
    EXPECT_NE(failure(noFlag.build()).find("hasExternalReferences is false"), std::string::npos);

    FileSpec wrongSection;
    wrongSection.hasExt = 1;
    wrongSection.sections.push_back({0, {object(255, {'a', 0})}});
    wrongSection.sections.push_back({0, {object(255, {'b', 0})}});
    EXPECT_NE(failure(wrongSection.build()).find("only in section 1"), std::string::npos);

    FileSpec mixed;
    mixed.hasExt = 1;
    mixed.sections.push_back({0, {object(255, {'a', 0}), object(9, {})}});
    EXPECT_NE(failure(mixed.build()).find("may hold only external references"), std::string::npos);

    FileSpec missing;
    missing.hasExt = 1;
    EXPECT_NE(failure(missing.build()).find("no section 1"), std::string::npos);
    LoadLog lenient;
    lenient.options.lenient = true;
    EXPECT_NO_THROW(parse(missing.build(), lenient));
    EXPECT_EQ(lenient.warnings.size(), 1u);
}

TEST(M3GSections, TotalFileSizeStrictAndLenient) {
    const FileSpec base = twoSectionFile();
    const Bytes good = base.build();

    FileSpec zero = base;
    zero.totalFileSize = 0;
    EXPECT_NE(failure(zero.build()).find("TotalFileSize is 0"), std::string::npos);
    {
        LoadLog log;
        log.options.lenient = true;
        const M3GFile f = parse(zero.build(), log);
        EXPECT_EQ(f.objects.size(), 6u);
        ASSERT_EQ(log.warnings.size(), 1u);
        EXPECT_NE(log.warnings[0].find("TotalFileSize is 0"), std::string::npos);
    }
    FileSpec big = base;
    big.totalFileSize = static_cast<std::uint32_t>(good.size() + 100);
    EXPECT_NE(failure(big.build()).find("truncated: TotalFileSize"), std::string::npos);
    {
        LoadLog log;
        log.options.lenient = true;
        EXPECT_EQ(parse(big.build(), log).objects.size(), 6u);
        EXPECT_EQ(log.warnings.size(), 1u);
    }
    // Ends inside the last section: strict fails, lenient reads on and warns.
    FileSpec small = base;
    small.totalFileSize = static_cast<std::uint32_t>(good.size() - 7);
    EXPECT_THROW(parse(small.build(), *std::make_unique<LoadLog>()), IOException);
    {
        LoadLog log;
        log.options.lenient = true;
        const M3GFile f = parse(small.build(), log);
        EXPECT_EQ(f.objects.size(), 6u);
        EXPECT_EQ(f.fileSize, good.size());
        ASSERT_EQ(log.warnings.size(), 1u);
        EXPECT_NE(log.warnings[0].find("does not match where the sections end (" + std::to_string(good.size()) + ")"), std::string::npos) << log.warnings[0];
    }
    // Smaller than the header section.
    FileSpec tiny = base;
    tiny.totalFileSize = 20;
    EXPECT_NE(failure(tiny.build()).find("smaller than the header section"), std::string::npos);
}

TEST(M3GSections, EmbeddedFileStopsAtTotalFileSize) {
    Bytes b = twoSectionFile().build();
    const std::size_t size = b.size();
    const Bytes trailer = {0xDE, 0xAD, 0xBE, 0xEF, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14};
    b.insert(b.end(), trailer.begin(), trailer.end());
    Bytes container = {'J', 'A', 'R'};
    container.insert(container.end(), b.begin(), b.end());
    for (bool lenient : {false, true}) {
        LoadLog log;
        log.options.lenient = lenient;
        const M3GFile f = parseM3GFile(std::span<const std::uint8_t>(container).subspan(3), log);
        EXPECT_EQ(f.fileSize, size);
        EXPECT_EQ(f.objects.size(), 6u);
        EXPECT_TRUE(log.warnings.empty());
    }
}

TEST(M3GSections, CompressedHeaderSectionStrictFailsLenientWarns) {
    FileSpec spec;
    spec.headerScheme = 1;
    spec.totalFileSize = 0;  // its compressed size depends on the value; lenient ignores 0 anyway
    EXPECT_NE(failure(spec.build()).find("compressed"), std::string::npos);
    LoadLog log;
    log.options.lenient = true;
    EXPECT_NO_THROW(parse(spec.build(), log));
    EXPECT_EQ(log.warnings.size(), 2u);
}

TEST(M3GSections, IdentifierErrors) {
    EXPECT_NE(failure({}).find("empty"), std::string::npos);
    Bytes id = kIdentifier;
    std::string m = failure(id);
    EXPECT_NE(m.find("section 0"), std::string::npos) << m;
    EXPECT_NE(m.find("truncated"), std::string::npos) << m;
    Bytes bad = twoSectionFile().build();
    bad[8] = 0x0A;
    m = failure(bad);
    EXPECT_NE(m.find("byte offset 8"), std::string::npos) << m;
    EXPECT_NE(failure(Bytes(kIdentifier.begin(), kIdentifier.begin() + 5)).find("truncated"), std::string::npos);
}

// Every prefix of a valid file fails cleanly (strict); lenient either fails
// cleanly or succeeds with a warning about the size.
TEST(M3GSections, TruncationAtEveryLength) {
    FileSpec spec = twoSectionFile();
    spec.sections.push_back({0, {object(19, Bytes(33, 1))}});
    const Bytes b = spec.build();
    for (std::size_t n = 0; n < b.size(); ++n) {
        const Bytes cut(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(n));
        LoadLog strict;
        EXPECT_THROW(parseM3GFile(cut, strict), IOException) << "length " << n;
        LoadLog lenient;
        lenient.options.lenient = true;
        try {
            parseM3GFile(cut, lenient);
            EXPECT_FALSE(lenient.warnings.empty()) << "length " << n;
        } catch (const IOException&) {
        }
    }
}

// Corruptions never crash or allocate wildly: each byte flipped, each aligned
// word set to 0xFFFFFFFF, and random multi-byte damage.
TEST(M3GSections, CorruptedBytes) {
    const Bytes b = twoSectionFile().build();
    auto tryParse = [](const Bytes& x) {
        for (bool lenient : {false, true}) {
            LoadLog log;
            log.options.lenient = lenient;
            try {
                parseM3GFile(x, log);
            } catch (const IOException&) {
            }
        }
    };
    int failures = 0;
    for (std::size_t i = 0; i < b.size(); ++i) {
        Bytes x = b;
        x[i] ^= 0xFF;
        LoadLog log;
        try {
            parseM3GFile(x, log);
        } catch (const IOException&) {
            ++failures;
        }
        tryParse(x);
    }
    // The checksums (and identifier) catch every single-byte flip.
    EXPECT_EQ(failures, static_cast<int>(b.size()));
    for (std::size_t i = 0; i + 4 <= b.size(); ++i) {
        Bytes x = b;
        for (int k = 0; k < 4; ++k) x[i + static_cast<std::size_t>(k)] = 0xFF;
        tryParse(x);
    }
    std::mt19937 rng(1234);
    for (int iter = 0; iter < 2000; ++iter) {
        Bytes x = b;
        const int flips = 1 + int(rng() % 6);
        for (int k = 0; k < flips; ++k) x[rng() % x.size()] = static_cast<std::uint8_t>(rng());
        tryParse(x);
    }
}

// Objects with corrupted lengths inside sections whose checksums are recomputed,
// so that the object layer (not the checksum) must catch them.
TEST(M3GSections, CorruptedLengthsWithValidChecksums) {
    for (std::uint32_t len : {0xFFFFFFFFu, 0x80000000u, 12u, 14u, 100u}) {
        Writer raw;
        raw.u8(20).u32(len).bytes(Bytes(13, 0));
        for (int scheme : {0, 1}) {
            Bytes sec;
            if (scheme == 0) {
                sec = rawSection(0, static_cast<std::uint32_t>(raw.b.size() + 13),
                                 static_cast<std::uint32_t>(raw.b.size()), raw.b);
            } else {
                const Bytes z = deflate(raw.b);
                sec = rawSection(1, static_cast<std::uint32_t>(z.size() + 13),
                                 static_cast<std::uint32_t>(raw.b.size()), z);
            }
            const Bytes file = withRawSection(sec);
            if (len == 13) continue;
            const std::string m = failure(file);
            EXPECT_NE(m.find("section 1"), std::string::npos) << m;
        }
    }
}

// ---------------------------------------------------------------------------
// The shared corpus (../shared/corpus next to the source tree; not copied).

TEST(M3GSectionsCorpus, IdOnlyFileIsRejected) {
    const auto dir = corpusDir();
    if (!dir) GTEST_SKIP() << "corpus not found (expected ../shared/corpus next to the source tree)";
    const auto p = *dir / "models/vadosnaprimer__desktop-m3g/exlib/m3g-reader-writer/test/id-only.hex";
    if (!std::filesystem::exists(p)) GTEST_SKIP() << "id-only.hex not in the corpus";
    const Bytes b = readFile(p);
    ASSERT_EQ(b.size(), 12u);
    EXPECT_EQ(m3g::detail::sniffFormat(b), m3g::detail::InputFormat::M3G);
    for (bool lenient : {false, true}) {
        LoadLog log;
        log.options.lenient = lenient;
        EXPECT_THROW(parseM3GFile(b, log), IOException);
    }
}

TEST(M3GSectionsCorpus, EveryM3GFileParsesAtSectionLevel) {
    const auto dir = corpusDir();
    if (!dir) GTEST_SKIP() << "corpus not found (expected ../shared/corpus next to the source tree)";

    // Files the corpus says must be rejected.
    std::set<std::string> mustReject;
    {
        const Bytes j = readFile(*dir / "must_reject.json");
        const std::string s(j.begin(), j.end());
        // Every "file": "..." value (the files hold no escaped quotes).
        const std::string key = "\"file\"";
        for (std::size_t at = s.find(key); at != std::string::npos; at = s.find(key, at + 1)) {
            const std::size_t open = s.find('"', s.find(':', at + key.size()) + 1);
            const std::size_t close = open == std::string::npos ? open : s.find('"', open + 1);
            if (close == std::string::npos) break;
            mustReject.insert(s.substr(open + 1, close - open - 1));
        }
    }

    int m3gExtension = 0, m3gSniffed = 0, parsed = 0, rejectedAsExpected = 0, sections = 0, objects = 0,
        zlibSections = 0;
    std::vector<std::string> failures;
    for (const auto& path : m3gtest::corpusFiles(*dir)) {
        const std::string rel = std::filesystem::relative(path, *dir / "models").generic_string();
        if (path.extension() == ".m3g") ++m3gExtension;
        const Bytes b = readFile(path);
        if (m3g::detail::sniffFormat(b) != m3g::detail::InputFormat::M3G) continue;
        ++m3gSniffed;
        LoadLog log;
        try {
            const M3GFile f = parseM3GFile(b, log);
            EXPECT_FALSE(mustReject.count(rel)) << rel << " should have been rejected";
            EXPECT_EQ(f.fileSize, b.size()) << rel;
            EXPECT_TRUE(log.warnings.empty()) << rel;
            ++parsed;
            sections += static_cast<int>(f.sections.size());
            objects += static_cast<int>(f.objects.size());
            for (const auto& s : f.sections) zlibSections += s.compressionScheme == 1;
        } catch (const IOException& ex) {
            if (mustReject.count(rel)) {
                ++rejectedAsExpected;
            } else {
                failures.push_back(rel + ": " + ex.what());
            }
        }
    }
    std::cout << "[corpus] *.m3g files: " << m3gExtension << "; files identified as M3G: " << m3gSniffed
              << "; parsed at section level: " << parsed << " (" << sections << " sections, " << zlibSections
              << " zlib, " << objects << " objects); rejected as must_reject.json says: " << rejectedAsExpected
              << "; unexpected failures: " << failures.size() << "\n";
    for (const auto& f : failures) ADD_FAILURE() << f;
    EXPECT_EQ(rejectedAsExpected, static_cast<int>(mustReject.size()));
    EXPECT_GT(parsed, 0);
}

// Truncating real files at every length (strict) must fail cleanly.
TEST(M3GSectionsCorpus, TruncatedCorpusFilesFailCleanly) {
    const auto dir = corpusDir();
    if (!dir) GTEST_SKIP() << "corpus not found (expected ../shared/corpus next to the source tree)";
    const char* files[] = {"models/BaalNetbek__M3G-Viewer/com.wizzer.m3g.toolkit/test/cube.m3g",
                           "models/jacques-gasselin__m3x/tools/test/data/teapot.m3g",
                           "models/jacques-gasselin__m3x/tools/res/xml/quad.m3g"};
    int tested = 0;
    for (const char* rel : files) {
        const auto p = *dir / rel;
        if (!std::filesystem::exists(p)) continue;
        const Bytes b = readFile(p);
        ++tested;
        for (std::size_t n = 0; n < b.size(); ++n) {
            LoadLog log;
            EXPECT_THROW(parseM3GFile(std::span<const std::uint8_t>(b).first(n), log), IOException) << rel << " " << n;
        }
    }
    if (tested == 0) GTEST_SKIP() << "none of the truncation test files is in the corpus";
}
