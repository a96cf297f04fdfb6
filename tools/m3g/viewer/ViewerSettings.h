// What the viewer remembers between runs: window size, the last file and
// the panel layout (splitter positions),
// in $XDG_CONFIG_HOME/m3g-vk/viewer.ini (else ~/.config/m3g-vk/viewer.ini).
#pragma once

#include <string>

#include "ViewerLayout.h"

namespace m3gview {

struct Settings {
    int width = 1024, height = 768;
    std::string lastFile;
    LayoutSizes layout;

    /// The saved settings, or the defaults when there are none or the file
    /// is unreadable (a broken file is ignored, not fatal).
    static Settings load();
    /// Writes them back; failures are reported on stderr only.
    void save() const;
    static std::string path();
};

}  // namespace m3gview
