// Helpers for the loader tests: build .m3g bytes by hand (identifier,
// sections with Adler-32, zlib sections via compress2, objects, header) and
// locate the shared corpus. Test-only.
#pragma once

#include <algorithm>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include <zlib.h>

namespace m3gtest {

using Bytes = std::vector<std::uint8_t>;

struct Writer {
    Bytes b;
    Writer& u8(std::uint8_t v) { b.push_back(v); return *this; }
    Writer& u16(std::uint16_t v) { u8(std::uint8_t(v)); return u8(std::uint8_t(v >> 8)); }
    Writer& u32(std::uint32_t v) {
        for (int i = 0; i < 4; ++i) u8(std::uint8_t(v >> (8 * i)));
        return *this;
    }
    Writer& i32(std::int32_t v) { return u32(std::uint32_t(v)); }
    Writer& f32(float f) {
        std::uint32_t v;
        std::memcpy(&v, &f, 4);
        return u32(v);
    }
    Writer& str(const std::string& s) {
        b.insert(b.end(), s.begin(), s.end());
        return u8(0);
    }
    Writer& bytes(const Bytes& x) {
        b.insert(b.end(), x.begin(), x.end());
        return *this;
    }
};

inline const Bytes kIdentifier = {0xAB, 0x4A, 0x53, 0x52, 0x31, 0x38, 0x34, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};

inline std::uint32_t adler(const std::uint8_t* p, std::size_t n) {
    return static_cast<std::uint32_t>(adler32(adler32(0L, Z_NULL, 0), p, static_cast<uInt>(n)));
}

/// ObjectType, Length, Data.
inline Bytes object(std::uint8_t type, const Bytes& data) {
    Writer w;
    w.u8(type).u32(static_cast<std::uint32_t>(data.size())).bytes(data);
    return w.b;
}

struct SectionSpec {
    int scheme = 0;
    std::vector<Bytes> objects;
};

/// A complete section: scheme, lengths, Objects (compressed for scheme 1), Adler-32.
inline Bytes section(int scheme, const std::vector<Bytes>& objects) {
    Bytes raw;
    for (const auto& o : objects) raw.insert(raw.end(), o.begin(), o.end());
    Bytes stored = raw;
    if (scheme == 1) {
        uLongf len = compressBound(static_cast<uLong>(raw.size()));
        stored.resize(len);
        compress2(stored.data(), &len, raw.data(), static_cast<uLong>(raw.size()), 9);
        stored.resize(len);
    }
    Writer w;
    w.u8(std::uint8_t(scheme)).u32(static_cast<std::uint32_t>(stored.size() + 13)).u32(
        static_cast<std::uint32_t>(raw.size()));
    w.bytes(stored);
    w.u32(adler(w.b.data(), w.b.size()));
    return w.b;
}

inline Bytes headerData(std::uint8_t major, std::uint8_t minor, std::uint8_t hasExt, std::uint32_t totalFileSize,
                        std::uint32_t approxSize, const std::string& authoring) {
    Writer w;
    w.u8(major).u8(minor).u8(hasExt).u32(totalFileSize).u32(approxSize).str(authoring);
    return w.b;
}

/// Writes `bytes` into the folder named by the environment variable
/// M3G_FUZZ_SEED_DIR, if set, as <FNV-1a 64 hash><ext>: scripts/fuzz runs the
/// loader tests this way to collect their hand-made files as fuzz seeds.
inline void dumpFuzzSeed(const Bytes& bytes, const char* ext) {
    const char* dir = std::getenv("M3G_FUZZ_SEED_DIR");
    if (!dir || !*dir || bytes.empty()) return;
    std::uint64_t h = 14695981039346656037ull;
    for (std::uint8_t c : bytes) h = (h ^ c) * 1099511628211ull;
    char name[17];
    std::snprintf(name, sizeof name, "%016llx", static_cast<unsigned long long>(h));
    std::ofstream out(std::filesystem::path(dir) / (std::string(name) + ext), std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

/// A whole file. TotalFileSize is computed unless overridden.
struct FileSpec {
    std::uint8_t major = 1, minor = 0;
    std::uint8_t hasExt = 0;
    std::optional<std::uint32_t> totalFileSize;
    std::uint32_t approxSize = 1234;
    std::string authoring = "m3g-vk test";
    int headerScheme = 0;
    std::vector<SectionSpec> sections;  // after section 0

    Bytes build() const {
        Bytes rest;
        for (const auto& s : sections) {
            Bytes sec = section(s.scheme, s.objects);
            rest.insert(rest.end(), sec.begin(), sec.end());
        }
        // The header section's size does not depend on the TotalFileSize value
        // (for scheme 0), so build it twice.
        Bytes h0 = section(headerScheme, {object(0, headerData(major, minor, hasExt, 0, approxSize, authoring))});
        const std::uint32_t total = totalFileSize.value_or(
            static_cast<std::uint32_t>(kIdentifier.size() + h0.size() + rest.size()));
        Bytes h = section(headerScheme, {object(0, headerData(major, minor, hasExt, total, approxSize, authoring))});
        Bytes out = kIdentifier;
        out.insert(out.end(), h.begin(), h.end());
        out.insert(out.end(), rest.begin(), rest.end());
        dumpFuzzSeed(out, ".m3g");
        return out;
    }
};

inline Bytes readFile(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// ../shared/corpus relative to the source tree, if present.
inline std::optional<std::filesystem::path> corpusDir() {
#ifdef M3G_CORPUS_DIR
    std::filesystem::path p(M3G_CORPUS_DIR);
    std::error_code ec;
    if (std::filesystem::is_directory(p / "models", ec)) return p;
#endif
    return std::nullopt;
}

/// Every regular file under `corpus`/models, sorted (stable test output).
inline std::vector<std::filesystem::path> corpusFiles(const std::filesystem::path& corpus) {
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(corpus / "models"))
        if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

#ifdef M3G_FUZZ_REGRESSIONS_DIR
/// The committed reproducers of one fuzz target (tests/fuzz/regressions/
/// `target`), sorted; empty when there are none.
inline std::vector<std::filesystem::path> regressionFiles(const std::string& target) {
    std::vector<std::filesystem::path> files;
    const std::filesystem::path dir = std::filesystem::path(M3G_FUZZ_REGRESSIONS_DIR) / target;
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) return files;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}
#endif

}  // namespace m3gtest
