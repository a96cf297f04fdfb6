// Writes object graphs as .m3g files (JSR-184 1.1 file format). Not part of
// JSR-184: the counterpart of Loader.
#pragma once

#include <m3g/Export.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <m3g/Object3D.h>

namespace m3g {

struct SaverOptions {
    /// Store the objects section zlib-compressed (compression scheme 1).
    bool compress = false;
    /// The header's AuthoringField (UTF-8 without NUL, else IAE).
    std::string authoringField = "m3g-vk";
};

/// Serialises object graphs to M3G 1.0 files. Static only.
///
/// Everything reachable from the roots is written (getReferences, plus node
/// alignment references and SkinnedMesh bones), each object once, every
/// object after all the objects it references (the format allows no forward
/// references). The file has the header section and one objects section.
/// User parameters (a `std::shared_ptr<const UserParameters>` user object)
/// are written; any other user object is not serialisable and is skipped.
/// Mutable Image2Ds are written as mutable, without pixels (JSR-184 1.1 file
/// format, section "Per-Class Data", Image2D).
class M3G_API Saver {
public:
    Saver() = delete;

    /// The file as bytes. NPE if `roots` is null (data() == nullptr, the
    /// conventions' Java null) or has a null element; IAE if the authoring field is not NUL-free UTF-8;
    /// IOException if the graph cannot be represented (a NaN or infinite
    /// float, a reference cycle through alignment references, an unknown
    /// Object3D class, a size over 4 GiB).
    static std::vector<std::uint8_t> save(std::span<Object3D* const> roots, const SaverOptions& options = {});
    /// Writes the file to `path`; as above, plus IOException if it cannot be
    /// written.
    static void save(const std::string& path, std::span<Object3D* const> roots,
                     const SaverOptions& options = {});
};

}  // namespace m3g
