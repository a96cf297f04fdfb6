// javax.microedition.m3g.Loader (JSR-184 1.1, Loader, and the JSR-184 1.1
// file format).
#pragma once

#include <m3g/Export.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <m3g/Object3D.h>

namespace m3g {

/// Options of one load call (engine extension, not Java API).
struct LoaderOptions {
    /// Strict (false, the default) matches what Nokia's implementation accepts.
    /// Lenient accepts the exporter faults seen in real files (wrong or zero
    /// TotalFileSize, header version 1.x, -0.0 floats, a compressed header
    /// section) and skips external references whose file is missing; every
    /// tolerated fault is recorded in LoadResult::warnings.
    bool lenient = false;
};

/// One external reference met by a load (engine extension, not Java API).
struct ExternalReference {
    std::string referencedBy;  ///< the file that holds it ("" for a load from bytes)
    std::string uri;           ///< as written in the file
    std::string path;          ///< the file it resolved to ("" when it could not resolve)
    bool loaded = false;       ///< false: skipped by a lenient load (file missing)
};

/// Everything a load produced (engine extension, not Java API).
struct LoadResult {
    /// Loaded objects referenced by no other loaded object, in file order
    /// (what Loader::load returns).
    std::vector<Ref<Object3D>> roots;
    /// Every loaded object in file order (the header excluded). An external
    /// reference contributes the object it loaded (the first root of a nested
    /// .m3g, or the Image2D of a PNG or JPEG); one skipped by a lenient load
    /// contributes nothing. A PNG or JPEG input gives its one Image2D.
    std::vector<Ref<Object3D>> objects;
    /// Header fields of the .m3g file (0 / false / empty for an image input).
    int versionMajor = 0;
    int versionMinor = 0;
    bool hasExternalReferences = false;
    std::uint32_t totalFileSize = 0;
    std::uint32_t approximateContentSize = 0;
    std::string authoringField;
    /// Faults tolerated by a lenient load, in the order met (also those of
    /// externally referenced files, prefixed with their name). Always empty
    /// for a strict load.
    std::vector<std::string> warnings;
    /// Every external reference met, in the order met (those of referenced
    /// files too, after the reference that loaded them).
    std::vector<ExternalReference> externalReferences;
};

/// Reads .m3g files (and PNG and JPEG images) into object graphs. Static only.
///
/// Images (JSR-184 1.1, Loader: PNG is the image format every implementation
/// must read; JPEG is read too, as Nokia's M3G implementation (reference) did
/// where the handset's platform decoder did). Either, loaded on its own or
/// through an external reference, is one immutable Image2D:
/// - PNG: grey -> LUMINANCE; grey+alpha or grey+tRNS -> LUMINANCE_ALPHA;
///   RGB or palette -> RGB; RGB+tRNS, palette+tRNS or RGBA -> RGBA.
/// - JPEG (baseline or progressive): greyscale -> LUMINANCE, colour -> RGB;
///   CMYK files fail. Damaged data (a file cut short, a bad Huffman code)
///   fails rather than loading with the grey or guessed pixels a decoder
///   would fill in.
/// - Either fails over 16384 pixels a side or 256 MiB of pixels.
///
/// Decoding notes (JSR-184 1.1 file format, section "Per-Class Data", and where
/// Nokia's M3G implementation (reference) reads a field otherwise):
/// - Background clear flags are read in spec order: depthClearEnabled, then
///   colorClearEnabled (Nokia's M3G implementation (reference) reads them the
///   other way round).
/// - Appearance.layer is a two's-complement signed byte (the format calls it a
///   Byte, but layers are -63..63; Nokia's M3G implementation (reference)
///   reads it signed).
/// - Null Appearance textures and null VertexBuffer arrays are not set (the
///   slot stays empty), so a null slot past the unit count is no error.
/// - User parameters become `std::shared_ptr<const UserParameters>` in the
///   user object (none if the count is 0); a repeated parameter ID fails.
/// - Every ObjectIndex must refer to an earlier object of the expected class
///   (0 = null, 1 = the header, which no slot accepts). Each one read counts
///   as a reference when the roots are chosen (alignment references,
///   skeletons, bones, morph targets and animation tracks included).
/// - External references: relative URIs resolve against the referencing
///   file's folder; a nested .m3g gives its first root object, a PNG or JPEG
///   an immutable Image2D; loops fail, naming the chain of files. The file's
///   contents, not its name, tell which it is.
/// - Lenient loads skip an external reference whose file is missing: every
///   ObjectIndex to it reads as null. Slots that accept null take it; list
///   entries (Group children, SkinnedMesh bones, animation tracks) are left
///   out; an object that cannot exist without it (its constructor or setter
///   throws NullPointerException, e.g. a Texture2D without its image) is
///   skipped too, and so on transitively. Each skip is a warning.
/// - Limits against hostile input: node hierarchies deeper than 1000 levels
///   and mutable images over 16384 pixels a side or 64 MiB fail.
/// - A value an object setter rejects (IAE, IOOBE, ISE, NPE) fails the load
///   with an IOException naming section, object index, type, byte offset and
///   the setter's message. Loads are all-or-nothing.
class M3G_API Loader {
public:
    Loader() = delete;

    /// Loads the named file (a path or file: URI). Returns the root objects
    /// (objects no other loaded object references), in file order.
    /// NPE if `name` is empty; IOException on any format or I/O error.
    static std::vector<Ref<Object3D>> load(const std::string& name);
    /// Loads from `data` starting at `offset`. NPE if `data` is null;
    /// IOOBE if offset < 0 or offset >= data.size(); IOException on error.
    /// External references must be absolute (a path starting with '/' or a
    /// file: URI).
    static std::vector<Ref<Object3D>> load(std::span<const std::uint8_t> data, int offset);

    /// As load(name), with options and every detail of the load.
    static LoadResult loadDetailed(const std::string& name, const LoaderOptions& options = {});
    /// As load(data, offset), with options and every detail of the load.
    static LoadResult loadDetailed(std::span<const std::uint8_t> data, int offset,
                                   const LoaderOptions& options = {});
};

}  // namespace m3g
