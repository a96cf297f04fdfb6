// What the viewer remembers between runs: window size, the last file, the
// recently opened files (the file browser lists them) and the panel layout
// (splitter positions),
// in $XDG_CONFIG_HOME/m3g-vk/viewer.ini (else ~/.config/m3g-vk/viewer.ini).
#pragma once

#include <string>
#include <vector>

#include "ViewerLayout.h"

namespace m3gview {

struct Settings {
    int width = 1024, height = 768;
    std::string lastFile;
    LayoutSizes layout;
    /// Most recent first, at most kMaxRecent, absolute paths (a JAR entry
    /// as "game.jar!entry").
    std::vector<std::string> recent;
    static constexpr std::size_t kMaxRecent = 10;

    /// Puts `file` first in `recent` (once), dropping the oldest beyond
    /// kMaxRecent. A relative path is made absolute first, so that the list
    /// works from any folder.
    void remember(const std::string& file);

    /// The saved settings, or the defaults when there are none or the file
    /// is unreadable (a broken file is ignored, not fatal).
    static Settings load();
    /// Writes them back; failures are reported on stderr only.
    void save() const;
    static std::string path();
};

}  // namespace m3gview
