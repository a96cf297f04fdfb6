// Reading a J2ME game's .jar (a zip file) with Debian's minizip: list the
// entries, read one entry's bytes, and load an .m3g entry with its external
// references resolved to other entries of the same archive. Part of
// m3g_cli_support (used by `m3g render GAME.jar` and the viewer).
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <m3g/Loader.h>

namespace m3gcli {

/// A missing, unreadable, corrupt or non-zip archive, or a bad entry;
/// what() names the archive (and the entry).
class JarError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// An open zip archive. Not thread-safe: minizip keeps one read position per
/// handle, so use one JarArchive per thread.
class JarArchive {
public:
    struct Entry {
        std::string name;              ///< path inside the archive, '/' separated
        std::uint64_t size = 0;        ///< uncompressed size from the central directory
        std::uint64_t compressedSize = 0;
    };

    /// Largest entry read() accepts (a hostile size field cannot make it
    /// allocate more).
    static constexpr std::uint64_t kMaxEntryBytes = 256ull << 20;
    /// Largest total of entry sizes load() extracts.
    static constexpr std::uint64_t kMaxExtractBytes = 1ull << 30;

    /// Opens `path` and reads its central directory. Throws JarError when the
    /// file is missing or is not a readable zip archive.
    explicit JarArchive(const std::string& path);
    ~JarArchive();
    JarArchive(const JarArchive&) = delete;
    JarArchive& operator=(const JarArchive&) = delete;

    const std::string& path() const noexcept { return path_; }
    /// File entries in central directory order (folders left out).
    const std::vector<Entry>& entries() const noexcept { return entries_; }
    /// The entries that hold M3G data, in archive order: those whose bytes
    /// begin with the JSR-184 file identifier, whatever their name (games
    /// ship models as .res, .mod, .bin...), and those named ".m3g" (any
    /// case), which a batch then reports if they are broken. The other file
    /// entries go to `others` when it is given.
    std::vector<std::string> m3gEntries(std::vector<std::string>* others = nullptr) const;
    bool contains(const std::string& name) const;

    /// The bytes of entry `name`. Throws JarError when there is no such entry,
    /// it is encrypted, larger than kMaxEntryBytes, or its data is corrupt
    /// (inflate error, size or CRC-32 mismatch).
    std::vector<std::uint8_t> read(const std::string& name) const;

    /// Loads entry `name` with m3g::Loader::loadDetailed. External references
    /// (relative URIs) resolve against the entry's folder inside the archive:
    /// the Loader has no resolver hook, so the archive's entries are extracted
    /// once into a private temporary folder (removed by the destructor) and
    /// the entry is loaded from there. Messages and warnings name
    /// "ARCHIVE!/ENTRY" rather than the temporary path. Throws JarError for
    /// archive problems, m3g::IOException (and the Loader's other exceptions)
    /// for the file's content.
    m3g::LoadResult load(const std::string& name, const m3g::LoaderOptions& options = {}) const;

    /// True if the file at `path` starts with a zip signature ("PK\3\4", or
    /// "PK\5\6" for an empty archive).
    static bool looksLikeZip(const std::filesystem::path& path);

private:
    void extractAll() const;
    std::string rewriteTempPaths(std::string text) const;

    std::string path_;
    void* zip_ = nullptr;  // unzFile
    std::vector<Entry> entries_;
    mutable std::filesystem::path extracted_;  // empty until load() needs it
};

}  // namespace m3gcli
