// Loader options and the warnings a lenient load collects (JSR-184 1.1 file
// format; JSR-184 1.1, Loader).
//
// Internal to the loader (scene/), not part of the public API.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace m3g::detail {

/// Options of one load call.
struct LoadOptions {
    /// Strict (false, the default) matches what Nokia's implementation accepts.
    /// Lenient accepts the exporter faults seen in real files (wrong or zero
    /// TotalFileSize, header version 1.x other than 1.0, -0.0 floats) and
    /// records each as a warning.
    bool lenient = false;
};

/// The options of a load plus the warnings it produced, in the order met.
/// Each warning names what was tolerated and where (section, object, offset).
struct LoadLog {
    LoadOptions options;
    std::vector<std::string> warnings;

    bool lenient() const { return options.lenient; }
    void warn(std::string message) { warnings.push_back(std::move(message)); }
};

}  // namespace m3g::detail
