#include "FileBrowser.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <system_error>

#include "InputFile.h"

namespace m3gview {

namespace fs = std::filesystem;

const char* kindName(BrowserEntry::Kind kind) {
    switch (kind) {
        case BrowserEntry::Kind::Parent: return "parent";
        case BrowserEntry::Kind::Folder: return "folder";
        case BrowserEntry::Kind::M3G: return "m3g";
        case BrowserEntry::Kind::Jar: return "jar";
    }
    return "?";
}

namespace {

bool hasJarName(const std::string& name) {
    if (name.size() < 4) return false;
    std::string ext = name.substr(name.size() - 4);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".jar";
}

}  // namespace

void FileBrowser::open(const fs::path& folder) {
    std::error_code ec;
    fs::path dir = fs::weakly_canonical(fs::absolute(folder, ec), ec);
    if (ec) dir = fs::absolute(folder).lexically_normal();
    if (!fs::is_directory(dir, ec)) throw std::runtime_error(dir.string() + ": no such folder");
    std::vector<BrowserEntry> folders, files;
    int others = 0;
    fs::directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
    if (ec) throw std::runtime_error(dir.string() + ": cannot list the folder (" + ec.message() + ")");
    for (; it != fs::directory_iterator(); it.increment(ec)) {
        if (ec) throw std::runtime_error(dir.string() + ": cannot list the folder (" + ec.message() + ")");
        const std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        std::error_code typeError;
        if (it->is_directory(typeError)) {
            folders.push_back({BrowserEntry::Kind::Folder, name, 0});
            continue;
        }
        if (!it->is_regular_file(typeError)) continue;
        const std::uint64_t size = it->file_size(typeError);
        const m3gcli::FileContent content = m3gcli::sniffFile(it->path());
        if (m3gcli::listedAsM3g(content, name)) files.push_back({BrowserEntry::Kind::M3G, name, size});
        else if (content.zip && hasJarName(name)) files.push_back({BrowserEntry::Kind::Jar, name, size});
        else ++others;
    }
    auto byName = [](const BrowserEntry& a, const BrowserEntry& b) { return a.name < b.name; };
    std::sort(folders.begin(), folders.end(), byName);
    std::sort(files.begin(), files.end(), byName);
    entries_.clear();
    if (dir.has_parent_path() && dir.parent_path() != dir) entries_.push_back({BrowserEntry::Kind::Parent, "..", 0});
    entries_.insert(entries_.end(), folders.begin(), folders.end());
    entries_.insert(entries_.end(), files.begin(), files.end());
    folder_ = dir;
    otherFiles_ = others;
}

void FileBrowser::up() {
    if (folder_.has_parent_path() && folder_.parent_path() != folder_) open(folder_.parent_path());
}

std::string FileBrowser::activate(std::size_t index) {
    if (index >= entries_.size())
        throw std::out_of_range("file browser: entry " + std::to_string(index) + " of " +
                                std::to_string(entries_.size()) + " (valid: 0.." + std::to_string(static_cast<long long>(entries_.size()) - 1) + ")");
    const BrowserEntry e = entries_[index];
    switch (e.kind) {
        case BrowserEntry::Kind::Parent: up(); return "";
        case BrowserEntry::Kind::Folder: open(folder_ / e.name); return "";
        default: return (folder_ / e.name).string();
    }
}

}  // namespace m3gview
