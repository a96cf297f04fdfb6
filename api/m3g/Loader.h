// javax.microedition.m3g.Loader (spec digest §4.27, §6, §7).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <m3g/Object3D.h>

namespace m3g {

/// Reads .m3g files (and PNG images) into object graphs. Static only.
/// The implementation is the loader work item; this header fixes the API.
class Loader {
public:
    Loader() = delete;

    /// Loads the named file (a path or file: URI). Returns the root objects
    /// (objects no other loaded object references), in file order.
    /// NPE if `name` is empty; IOException on any format or I/O error.
    static std::vector<Ref<Object3D>> load(const std::string& name);
    /// Loads from `data` starting at `offset`. NPE if `data` is null;
    /// IOOBE if offset < 0 or offset >= data.size(); IOException on error.
    static std::vector<Ref<Object3D>> load(std::span<const std::uint8_t> data, int offset);
};

}  // namespace m3g
