// Loader on hostile input: truncation at every byte length of small corpus
// files, random byte flips with the sections' Adler-32 (and zlib) redone so
// that the object decoder sees the damage, and a deep hierarchy. Each case
// must give an IOException or a valid load, never a crash or another error.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <m3g/Exception.h>
#include <m3g/Loader.h>

#include "LoaderTestObjects.h"
#include "M3GSections.h"

using namespace m3g;
using namespace m3gtest;
namespace fs = std::filesystem;

namespace {

enum class Outcome { Loaded, IOError, OtherError };

Outcome tryLoad(const Bytes& data, bool lenient, std::string* message = nullptr) {
    if (data.empty()) return Outcome::IOError;
    LoaderOptions o;
    o.lenient = lenient;
    try {
        Loader::loadDetailed(std::span<const std::uint8_t>(data), 0, o);
        return Outcome::Loaded;
    } catch (const IOException&) {
        return Outcome::IOError;
    } catch (const std::exception& e) {
        if (message) *message = e.what();
        return Outcome::OtherError;
    }
}

const char* kSmallFiles[] = {
    "BaalNetbek__M3G-Viewer/com.wizzer.m3g.toolkit/test/cube.m3g",
    "mrlordkaj__j2me-3dmoto/design_3d/misc.m3g",
    "mrlordkaj__j2me-3dmoto/source.zip.contents/3DMoto_240x320_en/assets/streetlight.m3g",
};

/// The raw (inflated) Objects area and scheme of every section of a file.
struct Sections {
    std::vector<Bytes> raw;
    std::vector<int> scheme;
    std::vector<Bytes> built;  // section bytes of raw[i] (cache; empty = rebuild)
};

Sections splitSections(const Bytes& file) {
    detail::LoadLog log;
    const auto f = detail::parseM3GFile(file, log);
    Sections s;
    for (const auto& sec : f.sections) {
        s.raw.emplace_back(sec.objects.begin(), sec.objects.end());
        s.scheme.push_back(sec.compressionScheme);
    }
    return s;
}

/// Reassembles a file with fresh checksums (and compression) and a matching TotalFileSize.
Bytes assemble(const Sections& s) {
    std::vector<Bytes> secs;
    std::size_t total = kIdentifier.size();
    for (std::size_t i = 0; i < s.raw.size(); ++i) {
        const bool cached = i < s.built.size() && !s.built[i].empty();
        secs.push_back(cached ? s.built[i] : section(s.scheme[i], {s.raw[i]}));
        total += secs.back().size();
    }
    if (!s.raw.empty() && s.raw[0].size() >= 12 && s.scheme[0] == 0) {
        Bytes h = s.raw[0];
        for (int k = 0; k < 4; ++k) h[std::size_t(8 + k)] = std::uint8_t(total >> (8 * k));
        secs[0] = section(0, {h});
    }
    Bytes out = kIdentifier;
    for (const auto& x : secs) out.insert(out.end(), x.begin(), x.end());
    return out;
}

}  // namespace

TEST(LoaderRobustness, TruncationAtEveryLength) {
    const auto corpus = corpusDir();
    if (!corpus) GTEST_SKIP() << "shared corpus not found (M3G_CORPUS_DIR/models); truncation test skipped";
    for (const char* rel : kSmallFiles) {
        const Bytes full = readFile(*corpus / "models" / rel);
        ASSERT_FALSE(full.empty()) << rel;
        ASSERT_EQ(tryLoad(full, false), Outcome::Loaded) << rel;
        int loaded = 0;
        for (std::size_t n = 1; n < full.size(); ++n) {
            const Bytes cut(full.begin(), full.begin() + static_cast<std::ptrdiff_t>(n));
            for (bool lenient : {false, true}) {
                std::string m;
                const Outcome r = tryLoad(cut, lenient, &m);
                ASSERT_NE(r, Outcome::OtherError) << rel << " cut at " << n << ": " << m;
                loaded += r == Outcome::Loaded;
            }
        }
        std::cout << "[ truncated ] " << rel << ": " << full.size() - 1 << " lengths, " << loaded
                  << " lenient/strict loads succeeded\n";
    }
}

TEST(LoaderRobustness, RandomByteFlipsWithChecksumsRedone) {
    const auto corpus = corpusDir();
    if (!corpus) GTEST_SKIP() << "shared corpus not found (M3G_CORPUS_DIR/models); byte-flip test skipped";
    std::vector<Sections> files;
    std::vector<std::string> names = {kSmallFiles[0], kSmallFiles[1], kSmallFiles[2],
                                      "jacques-gasselin__m3x/tools/test/data/helloworld.m3g",
                                      "j2me-preservation__midpath/demos/resources/org/thenesis/midpath/demo/m3g/data/robot.m3g"};
    for (const auto& n : names) {
        const Bytes b = readFile(*corpus / "models" / n);
        if (b.empty()) continue;
        files.push_back(splitSections(b));
        for (const auto& raw : files.back().raw)
            files.back().built.push_back(section(files.back().scheme[files.back().built.size()], {raw}));
        ASSERT_EQ(tryLoad(assemble(files.back()), false), Outcome::Loaded) << n;
    }
    ASSERT_FALSE(files.empty());
    std::mt19937 rng(184);
    int loaded = 0, rejected = 0;
    for (int i = 0; i < 2000; ++i) {
        Sections s = files[std::size_t(i) % files.size()];
        // Mostly scene sections; sometimes the header.
        std::size_t sec = (rng() % 16 == 0 || s.raw.size() < 2) ? 0 : 1 + rng() % (s.raw.size() - 1);
        Bytes& raw = s.raw[sec];
        s.built[sec].clear();
        if (raw.empty()) continue;
        const int flips = 1 + int(rng() % 3);
        for (int k = 0; k < flips; ++k) {
            const std::size_t pos = rng() % raw.size();
            switch (rng() % 4) {
            case 0: raw[pos] ^= std::uint8_t(1u << (rng() % 8)); break;
            case 1: raw[pos] = std::uint8_t(rng()); break;
            case 2: raw[pos] = 0xFF; break;
            default: raw[pos] = 0; break;
            }
        }
        const Bytes data = assemble(s);
        for (bool lenient : {false, true}) {
            std::string m;
            const Outcome r = tryLoad(data, lenient, &m);
            ASSERT_NE(r, Outcome::OtherError) << "iteration " << i << ": " << m;
            (r == Outcome::Loaded ? loaded : rejected) += 1;
        }
    }
    std::cout << "[ byte flips ] 2000 mutated files x strict/lenient: " << loaded << " loads, " << rejected
              << " IOExceptions\n";
}

TEST(LoaderRobustness, DeepHierarchyIsRejectedNotACrash) {
    std::vector<Bytes> objs;
    objs.push_back(group({}));
    for (std::uint32_t i = 1; i < 1500; ++i) objs.push_back(group({i + 1}));
    const Bytes file = sceneFile(objs);
    try {
        Loader::load(std::span<const std::uint8_t>(file), 0);
        ADD_FAILURE();
    } catch (const IOException& e) {
        EXPECT_NE(std::string(e.what()).find("deeper than"), std::string::npos) << e.what();
    }
    objs.resize(900);
    const Bytes ok = sceneFile(objs);
    EXPECT_EQ(Loader::load(std::span<const std::uint8_t>(ok), 0).size(), 1u);
}

TEST(LoaderRobustness, HugeCountsDoNotAllocate) {
    // Counts that claim far more data than present.
    O g;
    g.plainNode().u32(0x7FFFFFFF);
    EXPECT_EQ(tryLoad(sceneFile({g.as(9)}), false), Outcome::IOError);
    O p;
    p.obj3d().u32(0).u32(0xFFFFFFFF);  // animation tracks 0, parameters 4G
    EXPECT_EQ(tryLoad(sceneFile({p.as(6)}), false), Outcome::IOError);
    O img;
    img.obj3d().u8(99).boolean(false).u32(65535).u32(65535).u32(0).u32(0xFFFFFFF0);
    EXPECT_EQ(tryLoad(sceneFile({img.as(10)}), false), Outcome::IOError);
}
