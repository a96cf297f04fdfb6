// Reports on an object graph for `m3g info`: a JSON dump of every property,
// a human-readable scene tree and object counts by class.
// Part of m3g_cli_support (tools/m3g/), not of the library.
//
// Reachable objects: everything reachable from the roots through
// getReferences(), plus the bones of SkinnedMeshes and the alignment
// references of Nodes (which getReferences() does not list). Each object is
// numbered once, in depth-first pre-order of first visit: roots in order,
// each object's references in the order getReferences() gives them, then its
// bones (bone-index order), then its Z and Y alignment references.
#pragma once

#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <m3g/Loader.h>
#include <m3g/Object3D.h>

namespace m3gcli {

struct DumpOptions {
    /// Vertex arrays: values of at most this many vertices ("truncated": true past it).
    int maxVertices = 64;
    /// Index buffers: at most this many triangle-list indices (and strip lengths).
    int maxIndices = 192;
    /// Keyframe sequences: at most this many keyframes.
    int maxKeyframes = 64;
    /// If set, AnimationControllers also report getPosition() and isActive()
    /// at this world time (what `m3g info --time T` animated to).
    std::optional<int> worldTime;
    /// Numbering roots: when set, ids are those of the objects reachable from
    /// these (the whole file: `m3g info`'s "#id", the viewer's panels), while
    /// only what is reachable from the dumped roots is written. Objects outside
    /// the numbering (e.g. a viewer's own camera) get ids after its last.
    std::vector<m3g::Object3D*> numberingRoots;
    /// The load that gave the roots (`m3g info --json`): when set, the
    /// document starts with its "file" header, "externalReferences" and
    /// "warnings" (see dumpJson).
    const m3g::LoadResult* load = nullptr;
};

/// Where an object is in `m3g info`'s numbering of the objects reachable
/// from `roots` (see above); -1 if it is not reachable from them.
class ObjectNumbering {
public:
    explicit ObjectNumbering(std::span<m3g::Object3D* const> roots);
    int id(const m3g::Object3D* object) const;
    /// "Class #id", as `m3g info`'s tree prints it ("Class" alone outside the numbering).
    std::string label(const m3g::Object3D& object) const;

private:
    std::map<const m3g::Object3D*, int> ids_;
};

/// Every reachable object once, in id order (see above). Null roots are skipped.
std::vector<m3g::Object3D*> collectObjects(std::span<m3g::Object3D* const> roots);

/// JSON document, written with nlohmann::json (standard 2-space indented
/// layout: every member and array element on its own line; deterministic;
/// members in the order below; with DumpOptions::load first
///   "file": {"format": "m3g"|"image", "version": "1.0", "authoringField",
///            "totalFileSize", "approximateContentSize", "hasExternalReferences"},
///   "externalReferences": [{"referencedBy", "uri", "path", "loaded"}...],
///   "warnings": [the loader's warnings]; floats in the shortest form that reads back as
/// the same float; no NaN/Infinity: a non-finite float is written as null):
///   { "objectCount": N, "roots": [ids], "objects": [ {"id", "class",
///     "userID", "userObject", "userParameters", "animationTracks",
///     "references", ...the values of the class's getters...}, ... ] }
/// References to other objects are ids (null for none). Enumerations are
/// written as the Java constant names ("PERSPECTIVE"), colors as "0xAARRGGBB"
/// strings, matrices as 16 row-major floats.
std::string dumpJson(std::span<m3g::Object3D* const> roots, const DumpOptions& options = {});

/// One line per object: nodes indented under their parent (a SkinnedMesh's
/// skeleton under the mesh), "Class #id" with the ids of dumpJson, the user
/// ID when non-zero and a short summary. Non-node roots get one line each.
std::string dumpTree(std::span<m3g::Object3D* const> roots);

/// Number of reachable objects of each class (getClassName()).
std::map<std::string, int> countByClass(std::span<m3g::Object3D* const> roots);

}  // namespace m3gcli
