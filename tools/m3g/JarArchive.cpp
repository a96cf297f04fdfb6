#include "JarArchive.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <system_error>

#include <unzip.h>

#include <m3g/Exception.h>

#include "InputFile.h"

namespace m3gcli {

namespace fs = std::filesystem;

namespace {

unzFile handle(void* p) { return static_cast<unzFile>(p); }

/// An entry name that stays inside a folder it is extracted to: relative,
/// no ".." component, no empty component (zip-slip protection).
bool safeEntryName(const std::string& name) {
    if (name.empty() || name.front() == '/' || name.find('\\') != std::string::npos) return false;
    std::size_t start = 0;
    while (start <= name.size()) {
        const std::size_t slash = std::min(name.find('/', start), name.size());
        const std::string_view part(name.data() + start, slash - start);
        if (part.empty() || part == "..") return false;
        start = slash + 1;
    }
    return true;
}

void replaceAll(std::string& text, const std::string& from, const std::string& to) {
    if (from.empty()) return;
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
}

}  // namespace

JarArchive::JarArchive(const std::string& path) : path_(path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) throw JarError(path + ": no such archive (not a regular file)");
    zip_ = unzOpen64(path.c_str());
    if (!zip_) throw JarError(path + ": not a zip/jar archive, or its central directory is corrupt");
    int rc = unzGoToFirstFile(handle(zip_));
    while (rc == UNZ_OK) {
        unz_file_info64 info{};
        char name[4096];
        rc = unzGetCurrentFileInfo64(handle(zip_), &info, name, sizeof name, nullptr, 0, nullptr, 0);
        if (rc != UNZ_OK) break;
        if (info.size_filename >= sizeof name) {
            rc = UNZ_BADZIPFILE;
            break;
        }
        Entry e;
        e.name.assign(name, info.size_filename);
        e.size = info.uncompressed_size;
        e.compressedSize = info.compressed_size;
        if (!e.name.empty() && e.name.back() != '/') entries_.push_back(std::move(e));
        rc = unzGoToNextFile(handle(zip_));
    }
    if (rc != UNZ_END_OF_LIST_OF_FILE) {
        unzClose(handle(zip_));
        zip_ = nullptr;
        throw JarError(path + ": corrupt central directory (entry " + std::to_string(entries_.size()) +
                       ", minizip error " + std::to_string(rc) + ")");
    }
}

JarArchive::~JarArchive() {
    if (zip_) unzClose(handle(zip_));
    if (!extracted_.empty()) {
        std::error_code ec;
        fs::remove_all(extracted_, ec);  // best effort: nothing to report from a destructor
    }
}

std::vector<std::string> JarArchive::m3gEntries(std::vector<std::string>* others) const {
    std::vector<std::string> out;
    for (const Entry& e : entries_) {
        bool m3g = hasM3gName(e.name);
        if (!m3g && e.size > 0) {
            try {
                // The whole entry: J2ME archives are small, and an entry
                // over the size limit is no model a handset loaded.
                m3g = sniffBytes(read(e.name)).m3g;
            } catch (const std::exception&) {
                m3g = false;  // unreadable (encrypted, too large, corrupt): not listed as M3G
            }
        }
        if (m3g)
            out.push_back(e.name);
        else if (others)
            others->push_back(e.name);
    }
    return out;
}

bool JarArchive::contains(const std::string& name) const {
    return std::any_of(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.name == name; });
}

std::vector<std::uint8_t> JarArchive::read(const std::string& name) const {
    const std::string where = path_ + "!/" + name;
    if (!contains(name) || unzLocateFile(handle(zip_), name.c_str(), 1) != UNZ_OK)
        throw JarError(where + ": no such entry in the archive");
    unz_file_info64 info{};
    if (unzGetCurrentFileInfo64(handle(zip_), &info, nullptr, 0, nullptr, 0, nullptr, 0) != UNZ_OK)
        throw JarError(where + ": cannot read the entry's header");
    if (info.flag & 1u) throw JarError(where + ": the entry is encrypted");
    if (info.uncompressed_size > kMaxEntryBytes)
        throw JarError(where + ": entry of " + std::to_string(info.uncompressed_size) + " bytes exceeds the limit of " +
                       std::to_string(kMaxEntryBytes));
    if (unzOpenCurrentFile(handle(zip_)) != UNZ_OK) throw JarError(where + ": corrupt local header");
    std::vector<std::uint8_t> data;
    data.reserve(static_cast<std::size_t>(info.uncompressed_size));
    std::uint8_t chunk[65536];
    int n = 0;
    // Read until the stream ends, not just the size the directory claims, so
    // that a wrong size field is noticed rather than trusted.
    while ((n = unzReadCurrentFile(handle(zip_), chunk, sizeof chunk)) > 0) {
        if (data.size() + static_cast<std::size_t>(n) > info.uncompressed_size) {
            unzCloseCurrentFile(handle(zip_));
            throw JarError(where + ": entry data is longer than its recorded size " + std::to_string(info.uncompressed_size));
        }
        data.insert(data.end(), chunk, chunk + n);
    }
    const int closeRc = unzCloseCurrentFile(handle(zip_));
    if (n < 0) throw JarError(where + ": corrupt compressed data (minizip error " + std::to_string(n) + ")");
    if (data.size() != info.uncompressed_size)
        throw JarError(where + ": entry data is " + std::to_string(data.size()) + " bytes, its recorded size is " +
                       std::to_string(info.uncompressed_size));
    if (closeRc == UNZ_CRCERROR) throw JarError(where + ": CRC-32 mismatch (corrupt entry)");
    if (closeRc != UNZ_OK) throw JarError(where + ": minizip error " + std::to_string(closeRc) + " closing the entry");
    return data;
}

void JarArchive::extractAll() const {
    if (!extracted_.empty()) return;
    std::string pattern = (fs::temp_directory_path() / "m3g-jar-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw JarError(path_ + ": cannot create a temporary folder to extract into");
    const fs::path dir = pattern;
    try {
        std::uint64_t total = 0;
        for (const Entry& e : entries_) total += e.size;
        if (total > kMaxExtractBytes)
            throw JarError(path_ + ": entries total " + std::to_string(total) + " bytes, over the extraction limit of " +
                           std::to_string(kMaxExtractBytes));
        for (const Entry& e : entries_) {
            if (!safeEntryName(e.name)) continue;  // could not be referenced from inside anyway
            const fs::path target = dir / fs::path(e.name);
            fs::create_directories(target.parent_path());
            const std::vector<std::uint8_t> bytes = read(e.name);
            std::ofstream out(target, std::ios::binary);
            out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
            if (!out) throw JarError(path_ + ": cannot write " + target.string());
        }
    } catch (...) {
        std::error_code ec;
        fs::remove_all(dir, ec);
        throw;
    }
    extracted_ = dir;
}

std::string JarArchive::rewriteTempPaths(std::string text) const {
    replaceAll(text, (extracted_ / "").string(), path_ + "!/");
    return text;
}

m3g::LoadResult JarArchive::load(const std::string& name, const m3g::LoaderOptions& options) const {
    if (!contains(name)) throw JarError(path_ + "!/" + name + ": no such entry in the archive");
    if (!safeEntryName(name)) throw JarError(path_ + "!/" + name + ": entry name leaves the archive's folder");
    extractAll();
    try {
        m3g::LoadResult r = m3g::Loader::loadDetailed((extracted_ / fs::path(name)).string(), options);
        for (std::string& w : r.warnings) w = rewriteTempPaths(std::move(w));
        return r;
    } catch (const m3g::IOException& e) {
        throw m3g::IOException(rewriteTempPaths(e.what()));
    }
}

bool JarArchive::looksLikeZip(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[4] = {};
    if (!in.read(magic, 4)) return false;
    return magic[0] == 'P' && magic[1] == 'K' && ((magic[2] == 3 && magic[3] == 4) || (magic[2] == 5 && magic[3] == 6));
}

}  // namespace m3gcli
