// Per-class decoding of .m3g object records into objects (JSR-184 1.1 file
// format, section "Per-Class Data", and §8).
//
// Internal to the loader (scene/), not part of the public API.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <m3g/Object3D.h>

#include "ByteReader.h"
#include "LoadOptions.h"
#include "M3GSections.h"

namespace m3g::detail {

/// Loads the target of an External Reference (type 255). `uri` is the
/// string read from the file; `reader` names the referencing object for
/// messages (its where()/fail()). Returns the object, or null when a lenient
/// load skipped a missing file (the resolver records the warning).
using ExternalResolver = std::function<Ref<Object3D>(const std::string& uri, const ByteReader& reader)>;

/// The decoded objects of one file.
struct DecodedObjects {
    /// One entry per object after the header, in file order (ObjectIndex k is
    /// entry k - 2). Null where a lenient load skipped an object (a missing
    /// external reference, or an object that needed one, see decodeObjects).
    std::vector<Ref<Object3D>> table;
    /// True for entries some ObjectIndex of another object refers to.
    std::vector<bool> referenced;
    /// True for entries skipped by a lenient load.
    std::vector<bool> skipped;
};

/// Decodes every object of `file` (objects[1..]) in file order.
///
/// Every failure is an IOException naming section, object index, object type
/// and byte offset. Exceptions thrown by the object setters (IAE, IOOBE, ISE,
/// NPE, ...) are rethrown as IOException with that context and the original
/// message.
///
/// Lenient loads: an external reference whose file is missing is skipped and
/// every ObjectIndex that refers to it reads as null. Slots that accept null
/// take it (e.g. Appearance textures, Background image). In list slots
/// (Group children, SkinnedMesh bones) the entry is left out. Where an
/// object cannot exist without the reference (its constructor or setter
/// throws NullPointerException, e.g. a Texture2D whose image is missing), that
/// object is skipped too, with a warning, and references to it behave the
/// same way (so the skip cascades only through objects that need it).
DecodedObjects decodeObjects(const M3GFile& file, LoadLog& log, const ExternalResolver& resolveExternal);

}  // namespace m3g::detail
