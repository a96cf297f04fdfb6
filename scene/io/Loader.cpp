// javax.microedition.m3g.Loader (JSR-184 1.1, Loader, and the JSR-184 1.1
// file format).
#include <m3g/Loader.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <system_error>

#include <m3g/Exception.h>
#include <m3g/Image2D.h>

#include "Check.h"
#include "FormatSniffer.h"
#include "JpegImage.h"
#include "LoadOptions.h"
#include "M3GSections.h"
#include "ObjectDecoder.h"
#include "PngImage.h"

namespace m3g {

namespace fs = std::filesystem;

namespace {

using detail::str;

/// State shared by a load and the loads of its external references.
struct Session {
    LoaderOptions options;
    /// Files being loaded, outermost first (for loop detection and messages).
    std::vector<fs::path> chain;
    /// Warnings of every file, in the order met.
    std::vector<std::string> warnings;
    /// External references of every file, in the order met.
    std::vector<ExternalReference> references;
};

/// Largest file the loader reads (the format's sizes are 32-bit).
constexpr std::uintmax_t kMaxFileBytes = 0xFFFFFFFFu;

int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/// A name or URI as a file system path; `absolute` tells whether it is one
/// (a file: URI or an absolute path). Throws IOException for other schemes.
struct ResolvedName {
    fs::path path;
    bool absolute = false;
};

ResolvedName nameToPath(const std::string& name, const std::string& context) {
    std::string s = name;
    bool uri = false;
    if (s.size() >= 5 && std::equal(s.begin(), s.begin() + 5, "file:", [](char a, char b) {
            return std::tolower(static_cast<unsigned char>(a)) == b;
        })) {
        uri = true;
        s = s.substr(5);
        if (s.rfind("//", 0) == 0) {
            s = s.substr(2);
            // file://host/path: only an empty host or localhost is local.
            const std::size_t slash = s.find('/');
            const std::string host = s.substr(0, slash);
            if (!host.empty() && host != "localhost")
                throw IOException(str(context, "file URI '", name, "' names a remote host"));
            s = slash == std::string::npos ? std::string("/") : s.substr(slash);
        }
        // Percent-decoding.
        std::string d;
        for (std::size_t i = 0; i < s.size(); ++i) {
            if (s[i] == '%' && i + 2 < s.size() && hexValue(s[i + 1]) >= 0 && hexValue(s[i + 2]) >= 0) {
                d += static_cast<char>(hexValue(s[i + 1]) * 16 + hexValue(s[i + 2]));
                i += 2;
            } else {
                d += s[i];
            }
        }
        s = d;
    } else {
        // Another scheme ("http://...", "jar:...") is not supported.
        const std::size_t colon = s.find(':');
        if (colon != std::string::npos && colon > 1 && s.find('/') > colon) {
            bool scheme = std::isalpha(static_cast<unsigned char>(s[0])) != 0;
            for (std::size_t i = 1; i < colon && scheme; ++i)
                scheme = std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '+' || s[i] == '-' || s[i] == '.';
            if (scheme)
                throw IOException(str(context, "unsupported URI scheme in '", name,
                                      "' (only file paths and file: URIs are read)"));
        }
    }
    ResolvedName r;
    r.path = fs::path(s);
    r.absolute = r.path.is_absolute() || (uri && !s.empty() && s[0] == '/');
    return r;
}

std::string chainText(const std::vector<fs::path>& chain, const fs::path& last) {
    std::string s;
    for (const auto& p : chain) s += p.string() + " -> ";
    return s + last.string();
}

/// Reads a whole file; nullopt if it does not exist (or is not a regular file).
std::optional<std::vector<std::uint8_t>> readWholeFile(const fs::path& path, const std::string& context) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return std::nullopt;
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) throw IOException(str(context, "cannot read '", path.string(), "': ", ec.message()));
    if (size > kMaxFileBytes)
        throw IOException(str(context, "'", path.string(), "' is too large (", size, " bytes)"));
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IOException(str(context, "cannot open '", path.string(), "'"));
    std::vector<std::uint8_t> data(static_cast<std::size_t>(size));
    if (size > 0) in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(size));
    if (!in) throw IOException(str(context, "cannot read '", path.string(), "'"));
    return data;
}

LoadResult loadData(std::span<const std::uint8_t> data, const std::string& name,
                    const std::optional<fs::path>& baseDir, Session& session, bool nested);

/// Loads the file an External Reference names and returns the object that
/// takes its index.
Ref<Object3D> loadExternal(const std::string& uri, const detail::ByteReader& reader,
                           const std::optional<fs::path>& baseDir, Session& session) {
    const std::string context = reader.context() + ": external reference: ";
    if (uri.empty()) reader.fail("external reference with an empty URI");
    ResolvedName rn = nameToPath(uri, context);
    fs::path path;
    if (rn.absolute) {
        path = rn.path;
    } else if (!baseDir) {
        reader.fail(str("external reference '", uri,
                        "' is relative; a load from a byte array allows only absolute references"));
    } else {
        path = *baseDir / rn.path;
    }
    path = path.lexically_normal();
    std::error_code ec;
    fs::path canonical = fs::weakly_canonical(path, ec);
    if (ec) canonical = path;
    for (const auto& p : session.chain)
        if (p == canonical)
            reader.fail(str("external reference loop: ", chainText(session.chain, canonical)));

    auto bytes = readWholeFile(path, context);
    const std::string referencedBy = session.chain.empty() ? std::string() : session.chain.back().string();
    if (!bytes) {
        const std::string m = str("external reference '", uri, "': file '", path.string(), "' not found");
        if (!session.options.lenient) reader.fail(m);
        reader.warn(m + "; skipped, references to it read as null");
        session.references.push_back({referencedBy, uri, path.string(), false});
        return nullptr;
    }
    session.references.push_back({referencedBy, uri, path.string(), true});
    session.chain.push_back(canonical);
    LoadResult nested;
    try {
        nested = loadData(*bytes, path.string(), path.parent_path(), session, true);
    } catch (const IOException& e) {
        session.chain.pop_back();
        throw IOException(reader.where(str("external reference '", uri, "' (", path.string(), ") failed: ", e.what())));
    }
    session.chain.pop_back();
    if (nested.roots.empty())
        reader.fail(str("external reference '", uri, "' (", path.string(), ") holds no object"));
    return nested.roots.front();
}

/// A PNG or JPEG input: one immutable Image2D (JSR-184 1.1, Loader). PNG is
/// the image format the specification requires; JPEG is read because Nokia's
/// implementation read it where the handset's platform decoder did.
LoadResult loadImage(detail::InputFormat format, std::span<const std::uint8_t> data, const std::string& name) {
    const detail::DecodedImage decoded =
        format == detail::InputFormat::JPEG
            ? detail::decodeJpeg(data, name.empty() ? std::string("JPEG image") : name)
            : detail::decodePng(data, name.empty() ? std::string("PNG image") : name);
    LoadResult r;
    Ref<Image2D> img =
        make<Image2D>(decoded.format, decoded.width, decoded.height, std::span<const std::uint8_t>(decoded.pixels));
    r.objects.push_back(img);
    r.roots.push_back(img);
    return r;
}

LoadResult loadData(std::span<const std::uint8_t> data, const std::string& name,
                    const std::optional<fs::path>& baseDir, Session& session, bool nested) {
    const detail::InputFormat format = detail::sniffFormat(data);
    if (format == detail::InputFormat::PNG || format == detail::InputFormat::JPEG)
        return loadImage(format, data, name);
    detail::requireLoadableFormat(format, name);

    detail::LoadLog log;
    log.options.lenient = session.options.lenient;
    const std::size_t firstWarning = session.warnings.size();
    auto flushWarnings = [&] {
        // This file's own warnings go before those of the files it references.
        const std::string prefix = nested ? name + ": " : std::string();
        std::vector<std::string> mine;
        for (auto& w : log.warnings) mine.push_back(prefix + w);
        log.warnings.clear();
        session.warnings.insert(session.warnings.begin() + static_cast<std::ptrdiff_t>(firstWarning), mine.begin(),
                                mine.end());
    };
    detail::M3GFile file = detail::parseM3GFile(data, log);
    detail::DecodedObjects decoded = detail::decodeObjects(
        file, log, [&](const std::string& uri, const detail::ByteReader& reader) {
            return loadExternal(uri, reader, baseDir, session);
        });
    flushWarnings();

    LoadResult r;
    r.versionMajor = file.header.versionMajor;
    r.versionMinor = file.header.versionMinor;
    r.hasExternalReferences = file.header.hasExternalReferences;
    r.totalFileSize = file.header.totalFileSize;
    r.approximateContentSize = file.header.approximateContentSize;
    r.authoringField = file.header.authoringField;
    for (std::size_t i = 0; i < decoded.table.size(); ++i) {
        if (!decoded.table[i]) continue;
        r.objects.push_back(decoded.table[i]);
        if (!decoded.referenced[i]) r.roots.push_back(decoded.table[i]);
    }
    return r;
}

LoadResult loadNamed(const std::string& name, const LoaderOptions& options) {
    if (name.empty()) throw NullPointerException("Loader::load: name is null or empty");
    Session session;
    session.options = options;
    ResolvedName rn = nameToPath(name, "");
    auto bytes = readWholeFile(rn.path, "");
    if (!bytes) throw IOException(str("file '", rn.path.string(), "' not found"));
    std::error_code ec;
    fs::path canonical = fs::weakly_canonical(rn.path, ec);
    if (ec) canonical = rn.path;
    session.chain.push_back(canonical);
    fs::path dir = rn.path.parent_path();
    if (dir.empty()) dir = ".";
    LoadResult r;
    try {
        r = loadData(*bytes, rn.path.string(), dir, session, false);
    } catch (const IOException& e) {
        throw IOException(str(rn.path.string(), ": ", e.what()));
    }
    r.warnings = std::move(session.warnings);
    r.externalReferences = std::move(session.references);
    return r;
}

LoadResult loadBytes(std::span<const std::uint8_t> data, int offset, const LoaderOptions& options) {
    if (data.data() == nullptr) throw NullPointerException("Loader::load: data is null");
    if (offset < 0 || static_cast<std::size_t>(offset) >= data.size())
        throw IndexOutOfBoundsException(
            str("Loader::load: offset ", offset, " out of range [0, ", data.size(), ")"));
    Session session;
    session.options = options;
    LoadResult r = loadData(data.subspan(static_cast<std::size_t>(offset)), "", std::nullopt, session, false);
    r.warnings = std::move(session.warnings);
    r.externalReferences = std::move(session.references);
    return r;
}

}  // namespace

std::vector<Ref<Object3D>> Loader::load(const std::string& name) { return loadNamed(name, {}).roots; }

std::vector<Ref<Object3D>> Loader::load(std::span<const std::uint8_t> data, int offset) {
    return loadBytes(data, offset, {}).roots;
}

LoadResult Loader::loadDetailed(const std::string& name, const LoaderOptions& options) {
    return loadNamed(name, options);
}

LoadResult Loader::loadDetailed(std::span<const std::uint8_t> data, int offset, const LoaderOptions& options) {
    return loadBytes(data, offset, options);
}

}  // namespace m3g
