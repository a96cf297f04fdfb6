// The viewer's file browser, without a window: a folder's sub-folders, its
// M3G files and its .jar archives. M3G files are found by their first bytes
// (m3gcli::sniffFile, the rule of batch render and of a .jar's listing),
// not by their names, since games name them .res, .mod, .tex... The panel
// (ViewerUi) and the script commands (ViewerInput) drive the same object.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace m3gview {

struct BrowserEntry {
    enum class Kind { Parent, Folder, M3G, Jar };
    Kind kind = Kind::Folder;
    std::string name;         ///< the name in the folder; ".." for the parent
    std::uint64_t size = 0;   ///< bytes (files only)
};

/// "parent", "folder", "m3g", "jar".
const char* kindName(BrowserEntry::Kind kind);

class FileBrowser {
public:
    /// Lists `folder` (made absolute): ".." first unless it is the root, then
    /// the sub-folders, then the M3G files and the .jar files, each by name.
    /// Hidden entries (".name") are left out. Throws std::runtime_error
    /// naming the folder when it is missing or unreadable (the listing
    /// shown before is kept).
    void open(const std::filesystem::path& folder);
    /// Lists the folder again (files may have come or gone).
    void refresh() { open(folder_); }
    bool isOpen() const noexcept { return !folder_.empty(); }

    const std::filesystem::path& folder() const noexcept { return folder_; }
    const std::vector<BrowserEntry>& entries() const noexcept { return entries_; }
    /// The folder's files that are not listed (neither M3G nor .jar).
    int otherFiles() const noexcept { return otherFiles_; }

    /// Goes to the parent folder (nothing at the root).
    void up();
    /// The entry `index`: a folder (or "..") is entered and "" is returned;
    /// a file's path is returned, for the viewer to open. Throws
    /// std::out_of_range for a bad index, and what open() throws.
    std::string activate(std::size_t index);

private:
    std::filesystem::path folder_;
    std::vector<BrowserEntry> entries_;
    int otherFiles_ = 0;
};

}  // namespace m3gview
