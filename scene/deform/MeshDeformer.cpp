// Deformation of SkinnedMesh and MorphingMesh vertices with the skin/
// kernels, recomputed only when an input changed.
//
// Change detection compares exactly what the result is made of:
//  - the VertexBuffers and VertexArrays read (object id and revision: a
//    replaced array has a new id, an edited one a new revision);
//  - SkinnedMesh: the influence table's revision (every addTransform) and the
//    bone palette, recomputed each call from the bones' current transforms and
//    compared with the previous one: a bone moves through any node between it
//    and the mesh (animate, setTranslation, setTransform...), so comparing the
//    matrices is both simpler and exact where tracking revisions along every
//    path would not be;
//  - MorphingMesh: the weights (values, bit for bit).
// The mesh's own revision is deliberately not used: it also changes with its
// node transform and appearances, which do not change the deformed vertices.
#include "MeshDeformer.h"

#include <algorithm>
#include <cstring>
#include <typeinfo>

#include <m3g/MorphingMesh.h>
#include <m3g/SkinnedMesh.h>
#include <m3g/skin/InfluenceTable.h>
#include <m3g/skin/Isa.h>
#include <m3g/VertexArray.h>
#include <m3g/VertexBuffer.h>
#include <m3g/skin/Morph.h>
#include <m3g/skin/ThreadPool.h>

#include "Check.h"
#include "PropertyUtil.h"

namespace m3g::detail {

namespace {

/// Meshes with at least this many vertices are deformed on the shared
/// thread pool, in chunks of kGrain vertices.
constexpr std::size_t kParallelVertices = 16384;
constexpr std::size_t kGrain = 4096;

/// Whether two palette entries differ in any bit: eight bytes at a time
/// straight from the entries, which the compiler turns into a few vector
/// compares (memcmp was a library call per bone per frame; copies into
/// local arrays went through the stack).
bool entryDiffers(const skin::PaletteEntry& a, const skin::PaletteEntry& b) noexcept {
    constexpr std::size_t words = sizeof(skin::PaletteEntry) / sizeof(std::uint64_t);
    const auto* pa = reinterpret_cast<const unsigned char*>(&a);
    const auto* pb = reinterpret_cast<const unsigned char*>(&b);
    std::uint64_t diff = 0;
    for (std::size_t i = 0; i < words; ++i) {
        std::uint64_t x, y;
        std::memcpy(&x, pa + i * sizeof x, sizeof x);
        std::memcpy(&y, pb + i * sizeof y, sizeof y);
        diff |= x ^ y;
    }
    return diff != 0;
}

/// Raw values of `array` as floats (componentCount per vertex).
void rawFloats(const VertexArray* array, std::vector<float>& out) {
    out.resize(static_cast<std::size_t>(array->getVertexCount()) * array->getComponentCount());
    array->getFloats(0, array->getVertexCount(), out);
}

/// Normals as floats with the GL signed-integer mapping (2c + 1) / (2^bits - 1);
/// empty when there is no array.
void floatNormals(const VertexArray* array, std::vector<float>& out) {
    out.clear();
    if (!array) return;
    rawFloats(array, out);
    const int size = array->getComponentType();
    for (float& c : out) c = normalComponent(static_cast<int>(c), size);
}

/// Positions with the given scale and bias applied (the base's, for morph
/// targets too), xyz per vertex.
void scaledPositions(const VertexArray* array, float scale, const std::array<float, 3>& bias, std::vector<float>& out) {
    rawFloats(array, out);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = scale * out[i] + bias[i % 3];
}

/// Colours as RGBA in [0, 1] per vertex (RGB arrays get alpha 1; no array:
/// the default colour for every vertex).
void unitColors(const VertexBuffer& vb, std::vector<float>& out) {
    const int n = vb.getVertexCount();
    out.resize(static_cast<std::size_t>(n) * 4);
    const VertexArray* c = vb.colors();
    const auto argb = static_cast<std::uint32_t>(vb.getDefaultColor());
    for (int v = 0; v < n; ++v) {
        for (int k = 0; k < 4; ++k) {
            unsigned value;
            if (c) value = k < c->getComponentCount() ? static_cast<unsigned>(c->value(v, k) & 0xFF) : 255u;
            else value = k == 3 ? (argb >> 24) & 0xFF : (argb >> (16 - 8 * k)) & 0xFF;
            out[static_cast<std::size_t>(v) * 4 + k] = static_cast<float>(value) / 255.0f;
        }
    }
}

void requireSameArrays(const VertexBuffer& base, const VertexBuffer& target, int index) {
    auto same = [](const VertexArray* a, const VertexArray* b) {
        if (!a || !b) return a == b;
        return a->getComponentCount() == b->getComponentCount() && a->getVertexCount() == b->getVertexCount();
    };
    bool ok = same(base.positions(), target.positions()) && same(base.normals(), target.normals()) &&
              same(base.colors(), target.colors());
    for (int u = 0; u < kMaxTextureUnits; ++u) ok = ok && same(base.texCoords(u), target.texCoords(u));
    if (!ok)
        throw IllegalStateException(str("MorphingMesh: morph target ", index,
                                        " does not have the same vertex arrays (kind, components, count) as the base"));
}

/// The kernels only fail on malformed input, which update() never builds.
void require(bool ok, const char* what) {
    if (!ok) throw IllegalStateException(str("MeshDeformer: internal error, invalid ", what));
}

/// `n` packed xyz triples as three planes: every x, then every y, then every z.
void toPlanes(std::span<const float> xyz, std::size_t n, std::vector<float>& out) {
    out.resize(3 * n);
    for (std::size_t v = 0; v < n; ++v)
        for (std::size_t c = 0; c < 3; ++c) out[c * n + v] = xyz[3 * v + c];
}

/// The runs of `runs` with a slot whose bone's palette entry changed (a bone
/// outside the palette counts as changed: the kernel handles it), `start`
/// renumbered as the kernels require; `runs` itself when that is all of
/// them. A run's vertices depend on nothing else once the inputs are the
/// last call's, so the others keep their outputs.
std::span<const skin::InfluenceRun> movedRuns(std::span<const skin::InfluenceRun> runs,
                                              std::span<const std::int32_t> bones, int stride, int count,
                                              std::span<const std::uint8_t> changed,
                                              std::vector<skin::InfluenceRun>& out) {
    out.clear();
    std::uint32_t start = 0;
    for (const skin::InfluenceRun& r : runs) {
        const std::int32_t* slots = bones.data() + static_cast<std::size_t>(r.firstVertex) * static_cast<std::size_t>(stride);
        bool moved = false;
        for (int k = 0; k < count && !moved; ++k) {
            const auto b = static_cast<std::size_t>(slots[k]);
            moved = b >= changed.size() || changed[b] != 0;
        }
        if (!moved) continue;
        out.push_back({r.firstVertex, r.vertexCount, start});
        start += r.vertexCount;
    }
    if (out.size() == runs.size()) return runs;
    return out;
}

}  // namespace

std::vector<float> DeformedVertices::inMeshOrder(std::span<const float> values, int components) const {
    if (order.empty()) return {values.begin(), values.end()};
    const auto c = static_cast<std::size_t>(components);
    std::vector<float> out(values.size());
    for (std::size_t i = 0; i < order.size() && (i + 1) * c <= values.size(); ++i)
        std::copy_n(values.data() + i * c, c, out.data() + std::size_t{order[i]} * c);
    return out;
}

void DeformedVertices::inSlotOrder(std::span<const float> values, int components, std::vector<float>& out) const {
    if (order.empty()) {
        out.assign(values.begin(), values.end());
        return;
    }
    const auto c = static_cast<std::size_t>(components);
    out.resize(values.size());
    for (std::size_t i = 0; i < order.size() && (std::size_t{order[i]} + 1) * c <= values.size(); ++i)
        std::copy_n(values.data() + std::size_t{order[i]} * c, c, out.data() + i * c);
}

void MeshDeformer::addSource(const VertexBuffer* vb) {
    newSources_.push_back(vb ? Source{vb->getObjectId(), vb->getRevision()} : Source{});
}

void MeshDeformer::addSource(const VertexArray* array) {
    newSources_.push_back(array ? Source{array->getObjectId(), array->getRevision()} : Source{});
}

bool MeshDeformer::meshChanged(Kind kind, const Mesh& mesh) {
    const bool changed = kind != kind_ || mesh.getObjectId() != meshId_;
    kind_ = kind;
    meshId_ = mesh.getObjectId();
    return changed;
}

bool MeshDeformer::sourcesChanged(Kind kind, const Mesh& mesh) {
    const bool changed = meshChanged(kind, mesh) || newSources_ != sources_;
    sources_.swap(newSources_);
    return changed;
}

void MeshDeformer::finish() {
    valid_ = true;
    ++stamp_;
}

SkinInputs MeshDeformer::skinInputs() const noexcept {
    return kind_ == Kind::Skinned && valid_ ? skinInputs_ : SkinInputs{};
}

MorphAttributeInputs MeshDeformer::morphAttribute(int index) const noexcept {
    if (kind_ != Kind::Morphing || !valid_ || index < 0 || index >= kMorphAttributes) return {};
    const MorphAttribute& a = morph_[static_cast<std::size_t>(index)];
    if (a.components == 0) return {};
    return {a.components, a.values[0], std::span<const std::vector<float>>(a.values).subspan(1)};
}

bool MeshDeformer::update(const Mesh& mesh, Output output, Rigid rigid) {
    // A result made for the other output is not a result for this one.
    if (output != output_ || rigid != rigidMode_) valid_ = false;
    output_ = output;
    rigidMode_ = rigid;
    // The exact class first: a type_info comparison rather than a
    // dynamic_cast's walk, once per SkinnedMesh per frame.
    if (typeid(mesh) == typeid(SkinnedMesh)) return updateSkinned(static_cast<const SkinnedMesh&>(mesh));
    if (const auto* skinned = dynamic_cast<const SkinnedMesh*>(&mesh)) return updateSkinned(*skinned);
    if (const auto* morphing = dynamic_cast<const MorphingMesh*>(&mesh)) return updateMorphing(*morphing);
    out_ = DeformedVertices{};
    skinInputs_ = SkinInputs{};
    kind_ = Kind::None;
    valid_ = false;
    sources_.clear();
    return false;
}

bool MeshDeformer::updateSkinned(const SkinnedMesh& mesh) {
    // The raw pointer: getVertexBuffer()'s Ref costs two atomic operations.
    const VertexBuffer& vb = *mesh.vertexBuffer();
    // A fixed set of three: compared in place (sourcesChanged's list is for
    // the MorphingMesh's variable one).
    // Compared and stored field by field: a copy of the whole array read
    // its padding back with 16-byte loads that the fields' 8- and 4-byte
    // stores could not forward to (a stall per mesh per frame).
    const Object3D* const sources[3] = {&vb, vb.positions(), vb.normals()};
    bool sourcesDiffer = false;
    for (std::size_t i = 0; i < 3; ++i) {
        const std::uint64_t id = sources[i] ? sources[i]->getObjectId() : 0;
        const std::uint32_t revision = sources[i] ? sources[i]->getRevision() : 0;
        sourcesDiffer |= id != skinnedSources_[i].id || revision != skinnedSources_[i].revision;
        skinnedSources_[i].id = id;
        skinnedSources_[i].revision = revision;
    }
    // (Another kind of mesh since, and back: meshChanged says so, whatever
    // skinnedSources_ and sources_ still hold.)
    const bool inputsChanged = meshChanged(Kind::Skinned, mesh) || sourcesDiffer || !valid_;
    const auto n = static_cast<std::size_t>(vb.getVertexCount());
    if (inputsChanged) {
        valid_ = false;
        if (vb.positions())
            rawFloats(vb.positions(), rawPositions_);
        else
            rawPositions_.assign(n * 3, 0.0f);
        floatNormals(vb.normals(), baseNormals_);
        out_.vertexCount = static_cast<int>(n);
        const bool cpu = output_ == Output::Vertices;
        out_.positions.resize(cpu ? n * 3 : 0);
        out_.normals.resize(cpu ? baseNormals_.size() : 0);
        out_.colors.clear();
        for (auto& t : out_.texCoords) t.clear();
        out_.texCoordComponents.fill(0);
    }

    const skin::InfluenceTable& table = mesh.influenceTable();
    const bool tableChanged = inputsChanged || table.revision() != tableRevision_;
    if (tableChanged) {
        valid_ = false;
        // Every vertex with influences goes to the compact space, sorted by
        // influence set: the outputs stay in that order (order_). Short
        // runs beside a bone run of their bones join it where this CPU's
        // kernels have bone runs (InfluencePartition::runBlock).
        partition_.buildForKernels(table, n);
        rigidBone_ = table.rigidBone(n);
        tableRevision_ = table.revision();
        ++inputStamp_;
        planOrder(n);
        planGroups(n, table.maxInfluences());
    }

    // The palette, once per bone: (bone -> mesh now) x (at rest). The
    // at-rest matrices are captured by addTransform, which also changes the
    // table: copied only then. No node on the bones' paths changed: the
    // palette, and so the vertices, are the last call's.
    const auto bones = static_cast<std::size_t>(mesh.boneCount());
    const bool bonesMoved = boneTransforms_.compute(mesh, boneMatrices_);
    if (valid_ && !bonesMoved && palette_.size() == bones) return false;
    if (tableChanged || atRest_.size() != bones * 16) {
        atRest_.resize(bones * 16);
        for (std::size_t b = 0; b < bones; ++b) {
            const auto& rest = mesh.atRestTransform(static_cast<int>(b)).rows();
            std::copy(rest.begin(), rest.end(), atRest_.begin() + b * 16);
        }
    }
    newPalette_.resize(bones);
    // The VertexBuffer's position scale and bias go into the palette's
    // position rows (once per bone), so the kernels and the compute shader
    // take the raw positions with scale 1 and bias 0 (no fold per run).
    const bool hasPositions = vb.positions() != nullptr;
    skin::PaletteJob paletteJob;
    paletteJob.boneCount = bones;
    paletteJob.boneToMesh = boneMatrices_;
    paletteJob.atRest = atRest_;
    paletteJob.output = newPalette_;
    if (hasPositions) {
        paletteJob.positionScale = vb.positionScale();
        paletteJob.positionBias = vb.positionBias();
    }
    // Bones that only rotate and translate (one common scale): the
    // bone-run kernels may turn normals with the position rows (half their
    // per-lane blend). Measured only where there are bone runs.
    bool conformal = false;
    if (std::any_of(groups_.begin(), groups_.end(), [](const GroupPlan& g) { return !g.boneRuns.empty(); }))
        paletteJob.conformal = &conformal;
    require(paletteJob.run(), "palette job");
    // Which entries changed, bit for bit (only the bones composed again can
    // have: an entry is a function of its bone's matrix, the at-rest matrix,
    // scale and bias, and a change of the last three invalidates out_).
    // With out_ valid, only the vertices of changed entries are skinned.
    // out_ holds the last call's vertices for these inputs: vertices without
    // bones keep theirs.
    const bool kept = valid_ && palette_.size() == bones;
    bool partial = kept;
    entryChanged_.assign(bones, 1);
    if (kept) {
        const auto composed = boneTransforms_.changedBones();
        // Through local pointers: stores to entryChanged_ would otherwise
        // make the compiler reload every vector's data pointer per bone.
        const skin::PaletteEntry* before = palette_.data();
        const skin::PaletteEntry* after = newPalette_.data();
        std::uint8_t* entryChanged = entryChanged_.data();
        std::size_t changed = 0;
        for (std::size_t b = 0; b < bones; ++b) {
            const bool differs = composed[b] && entryDiffers(before[b], after[b]);
            entryChanged[b] = differs;
            changed += differs;
        }
        if (changed == 0) return false;
        // Every entry changed (the common animated frame): no run to leave
        // out, the run lists as they are. Nor when the bone runs' normals
        // change method (conformal_): the kept ones would be the other's.
        partial = changed < bones && conformal == conformal_;
    }
    conformal_ = conformal;
    palette_.swap(newPalette_);
    valid_ = false;

    // No position array: zeros (skinned like any point).
    skinInputs_.vertexCount = static_cast<int>(n);
    skinInputs_.positions = rawPositions_;
    skinInputs_.positionScale = hasPositions ? vb.positionScale() : 1.0f;
    skinInputs_.positionBias = hasPositions ? vb.positionBias() : std::array<float, 3>{0.0f, 0.0f, 0.0f};
    skinInputs_.normals = baseNormals_;
    skinInputs_.influenceStride = table.maxInfluences();
    skinInputs_.bones = table.bones();
    skinInputs_.weights = table.weights();
    skinInputs_.palette = palette_;
    out_.rigid = rigidMode_ == Rigid::AsTransform && rigidBone_ >= 0 &&
                 static_cast<std::size_t>(rigidBone_) < palette_.size();
    if (out_.rigid) out_.rigidTransform = palette_[static_cast<std::size_t>(rigidBone_)];
    if (output_ == Output::InputsOnly || out_.rigid) {
        finish();
        return true;
    }
    // A partial frame (out_ valid for these inputs, some entries changed):
    // vertices without bones keep their outputs, runs whose bones did not
    // move keep theirs; loose vertices are all skinned again (their blocks
    // mix bones). Every job works in the output order: the compact space's
    // influenced vertices, then those without bones.
    for (GroupPlan& g : groups_) {
        // The plan's job (planGroups), with what changes from frame to frame.
        skin::SkinningJob& job = g.job;
        const int c = job.influenceCount, stride = job.influenceStride;
        if (c == 0 && kept) continue;
        job.runs = partial ? movedRuns(g.runs, partition_.compactBones(), stride, c, entryChanged_, movedRuns_)
                           : g.runs;
        // A bone run's vertices share its bones: it moved with them.
        job.boneRuns = partial ? movedRuns(g.boneRuns, partition_.compactBones(), stride, c, entryChanged_,
                                           movedBoneRuns_)
                               : g.boneRuns;
        if (job.vertices.empty() && job.runs.empty() && job.boneRuns.empty()) continue;
        job.palette = palette_;  // one of two buffers, swapped each frame
        job.normalsFromPositions = conformal;
        // Influenced vertices: the palette applies the scale and bias.
        if (c == 0) {
            job.positionScale = skinInputs_.positionScale;
            job.positionBias = skinInputs_.positionBias;
        }
        require(g.parallel ? job.runParallel(skin::ThreadPool::shared(), kGrain) : job.run(), "skinning job");
    }
    finish();
    return true;
}

void MeshDeformer::planOrder(std::size_t n) {
    // The compact space covers the vertices with influences (the partition
    // is built with weights and no run kept in place); those without bones
    // follow in the mesh's order.
    const auto compact = partition_.compactOrder();
    const auto unboned = partition_.group(0);
    require(compact.size() + unboned.size() == n, "compact space");
    order_.assign(compact.begin(), compact.end());
    order_.insert(order_.end(), unboned.begin(), unboned.end());
    unboned_.resize(unboned.size());
    for (std::size_t i = 0; i < unboned_.size(); ++i) unboned_[i] = static_cast<std::uint32_t>(compact.size() + i);
    ordered_ = false;
    for (std::size_t i = 0; i < n && !ordered_; ++i) ordered_ = order_[i] != i;
    ++orderStamp_;
    if (!ordered_) {
        // Already the mesh's order (one influence set, as otokka_jump2's
        // meshes): nothing to gather, nothing for consumers to remap.
        order_.clear();
        location_.clear();
        orderedPositions_.clear();
        orderedNormals_.clear();
    } else {
        location_.resize(n);
        for (std::size_t i = 0; i < n; ++i) location_[order_[i]] = static_cast<std::uint32_t>(i);
    }
    out_.order = order_;
    out_.location = location_;
    if (ordered_) {
        out_.inSlotOrder(rawPositions_, 3, orderedPositions_);
        out_.inSlotOrder(baseNormals_, 3, orderedNormals_);
    }
    // Planes only help the lane kernels (AVX2, AVX-512) on the CPU;
    // elsewhere they would be memory for nothing.
    positionPlanes_.clear();
    normalPlanes_.clear();
    const skin::Isa isa = skin::resolveIsa(skin::Isa::Auto);
    if (output_ == Output::Vertices && baseNormals_.size() == 3 * n &&
        (isa == skin::Isa::Avx2 || isa == skin::Isa::Avx512)) {
        toPlanes(ordered_ ? orderedPositions_ : rawPositions_, n, positionPlanes_);
        toPlanes(ordered_ ? orderedNormals_ : baseNormals_, n, normalPlanes_);
    }
}

void MeshDeformer::planGroups(std::size_t n, int stride) {
    groups_.clear();
    const std::span<const float> inPositions = ordered_ ? std::span<const float>(orderedPositions_) : rawPositions_;
    const std::span<const float> inNormals = ordered_ ? std::span<const float>(orderedNormals_) : baseNormals_;
    for (int c = 0; c <= partition_.maxInfluences(); ++c) {
        const auto group = partition_.group(c);
        if (group.empty()) continue;
        GroupPlan& g = groups_.emplace_back();
        g.parallel = group.size() >= kParallelVertices;
        // Everything of the group's job that holds until the next plan
        // (these arrays are only resized on the way here), set once rather
        // than a job built each frame.
        skin::SkinningJob& job = g.job;
        if (c == 0) {
            job.vertices = unboned_;
        } else {
            job.vertices = partition_.compactLoose(c);
            g.runs = partition_.compactRuns(c);
            g.boneRuns = partition_.compactBoneRuns(c);
        }
        job.vertexCount = n;
        job.influenceCount = c;
        job.influenceStride = stride;
        job.boneIndices = partition_.compactBones();
        job.boneWeights = partition_.compactWeights();
        job.inPositions = inPositions;
        job.outPositions = out_.positions;
        job.inNormals = inNormals;
        job.outNormals = out_.normals;
        job.inPositionPlanes = positionPlanes_;
        job.inNormalPlanes = normalPlanes_;
    }
}

bool MeshDeformer::updateMorphing(const MorphingMesh& mesh) {
    const VertexBuffer& base = *mesh.getVertexBuffer();
    const int count = mesh.getMorphTargetCount();
    newSources_.clear();
    auto addBuffer = [&](const VertexBuffer& vb) {
        addSource(&vb);
        addSource(vb.positions());
        addSource(vb.normals());
        addSource(vb.colors());
        for (int u = 0; u < kMaxTextureUnits; ++u) addSource(vb.texCoords(u));
    };
    addBuffer(base);
    for (int t = 0; t < count; ++t) addBuffer(*mesh.morphTarget(t));
    const bool inputsChanged = sourcesChanged(Kind::Morphing, mesh) || !valid_;
    const std::span<const float> weights = mesh.weights();
    const bool weightsChanged =
        weights_.size() != weights.size() ||
        (!weights.empty() && std::memcmp(weights_.data(), weights.data(), weights.size() * sizeof(float)) != 0);
    if (!inputsChanged && !weightsChanged) return false;
    valid_ = false;

    const auto n = static_cast<std::size_t>(base.getVertexCount());
    if (inputsChanged) {
        for (int t = 0; t < count; ++t) requireSameArrays(base, *mesh.morphTarget(t), t);
        for (auto& a : morph_) {
            a.values.resize(static_cast<std::size_t>(count) + 1);
            a.components = 0;
        }
        auto buffer = [&](int i) -> const VertexBuffer& { return i == 0 ? base : *mesh.morphTarget(i - 1); };
        for (int i = 0; i <= count; ++i) {
            const VertexBuffer& vb = buffer(i);
            const auto slot = static_cast<std::size_t>(i);
            // Targets use the base's scale and bias (the formula is linear,
            // so scaling before or after blending is the same).
            if (vb.positions()) {
                scaledPositions(vb.positions(), base.positionScale(), base.positionBias(),
                                morph_[kMorphPositions].values[slot]);
                morph_[kMorphPositions].components = 3;
            }
            if (vb.normals()) {
                floatNormals(vb.normals(), morph_[kMorphNormals].values[slot]);
                morph_[kMorphNormals].components = 3;
            }
            unitColors(vb, morph_[kMorphColors].values[slot]);
            morph_[kMorphColors].components = 4;
            for (int u = 0; u < kMaxTextureUnits; ++u) {
                if (!vb.texCoords(u)) continue;
                rawFloats(vb.texCoords(u), morph_[kMorphTexCoords + u].values[slot]);
                morph_[kMorphTexCoords + u].components = vb.texCoords(u)->getComponentCount();
            }
        }
        out_.vertexCount = static_cast<int>(n);
        out_.rigid = false;
        out_.order = {};
        out_.location = {};
        auto size = [&](int attribute, std::vector<float>& out) {
            const int comps = morph_[static_cast<std::size_t>(attribute)].components;
            if (comps == 0 || output_ == Output::InputsOnly)
                out.clear();
            else
                out.resize(n * static_cast<std::size_t>(comps));
        };
        size(kMorphPositions, out_.positions);
        size(kMorphNormals, out_.normals);
        size(kMorphColors, out_.colors);
        for (int u = 0; u < kMaxTextureUnits; ++u) {
            size(kMorphTexCoords + u, out_.texCoords[u]);
            out_.texCoordComponents[u] = morph_[kMorphTexCoords + u].components;
        }
        ++inputStamp_;
    }
    weights_.assign(weights.begin(), weights.end());
    if (output_ == Output::InputsOnly) {
        finish();
        return true;
    }

    // Targets with weight 0 contribute nothing: leave them out.
    activeWeights_.clear();
    for (int t = 0; t < count; ++t)
        if (weights[t] != 0.0f) activeWeights_.push_back(weights[t]);
    for (std::size_t a = 0; a < morph_.size(); ++a) {
        const MorphAttribute& attribute = morph_[a];
        if (attribute.components == 0) continue;
        activeTargets_.clear();
        for (int t = 0; t < count; ++t)
            if (weights[t] != 0.0f) activeTargets_.push_back(attribute.values[static_cast<std::size_t>(t) + 1]);
        std::vector<float>& out = a == kMorphPositions ? out_.positions
                                  : a == kMorphNormals ? out_.normals
                                  : a == kMorphColors  ? out_.colors
                                                       : out_.texCoords[a - kMorphTexCoords];
        skin::MorphJob job;
        job.base = attribute.values[0];
        job.targets = activeTargets_;
        job.weights = activeWeights_;
        job.output = out;
        job.clamp = a == kMorphColors;  // colours clamped to [0, 1] (0..255 in bytes)
        job.normalize = a == kMorphNormals;
        require(n >= kParallelVertices ? job.runParallel(skin::ThreadPool::shared(), kGrain) : job.run(), "morph job");
    }
    finish();
    return true;
}

}  // namespace m3g::detail
