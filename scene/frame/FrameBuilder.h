// Frame preparation on the scene side: from a sorted RenderQueue to a
// DrawList (state translated, meshes deformed, resources named by id and
// version), and the FrameSources a back end reads stale resources through.
// Keeps one entry per object a draw list named, to tell the back end which
// of them no longer exist (sweep), and each deforming mesh's MeshDeformer.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include <m3g/Object3D.h>
#include <m3g/Ref.h>
#include <m3g/frame/FrameBackend.h>

#include "MeshDeformer.h"
#include "StateTranslation.h"

namespace m3g::detail {

struct RenderItem;
struct RenderQueue;

class FrameBuilder final : public frame::FrameSources {
public:
    FrameBuilder();
    ~FrameBuilder() override;

    /// The draws of a sorted `queue` into `out` (reset first): each
    /// submesh's vertex data is deformed now (on the CPU, or its kernel
    /// inputs refreshed when `gpuDeform`), then its state is translated.
    /// Throws IllegalStateException for vertex data a draw cannot use (no
    /// positions, an index past the vertices, morph targets unlike their
    /// base), before anything is handed to a back end.
    void build(const RenderQueue& queue, const frame::ViewState& view, bool gpuDeform,
               const frame::DrawOptions& options, frame::DrawList& out);
    /// Makes `object` readable through the FrameSources (by its id) and
    /// watched for release: every resource a draw list names goes through
    /// here (build() does it for its own draws).
    void track(const Object3D& object) { entry(object); }
    /// Ids of objects named by earlier draw lists that no longer exist (valid
    /// until the next call); forgets them.
    std::span<const std::uint64_t> sweep();

    // frame::FrameSources
    frame::VertexStreams vertexStreams(const frame::VertexRef& ref) override;
    frame::SkinInputs skinInputs(const frame::VertexRef& ref) override;
    frame::MorphInputs morphInputs(const frame::VertexRef& ref) override;
    void triangles(const frame::IndexRef& ref, std::vector<std::uint32_t>& out) override;
    void texels(const frame::TextureRef& ref, std::vector<std::uint8_t>& rgba, int& width, int& height) override;

    FrameBuilder(const FrameBuilder&) = delete;
    FrameBuilder& operator=(const FrameBuilder&) = delete;

private:
    using Signature = std::array<std::uint64_t, 12>;
    /// A deformed mesh's colour and texture-coordinate streams from its
    /// VertexBuffer, in the deformed order, for these arrays and this order.
    struct Statics {
        bool valid = false;
        Signature signature{};
        std::uint64_t order = 0;
        std::array<std::vector<float>, frame::STREAM_COUNT - frame::COLORS> streams;
    };
    struct Entry {
        WeakRef<Object3D> owner;
        // Vertex data (a VertexBuffer, or a deforming Mesh):
        std::unique_ptr<MeshDeformer> deformer;
        Signature signature{};
        std::uint64_t version = 0, inputVersion = 0, inputStamp = 0;
        std::uint64_t call = 0;  ///< the build() that last refreshed it
        frame::VertexSource source = frame::VertexSource::Plain;
        VertexLayout layout;
        Statics statics;
    };
    /// The entry of `object`, made on first use. Consecutive draws mostly
    /// share their vertex and index data, so the last two entries found are
    /// kept at hand (entries never move; sweep() drops the shortcuts).
    Entry& entry(const Object3D& object);
    /// Refreshes `e` for this call and fills `ref`.
    void prepareVertices(Entry& e, const VertexBuffer& vb, const Mesh* mesh, bool gpuDeform, frame::VertexRef& ref);
    /// prepareVertices' part for a mesh deformed on the CPU or the GPU
    /// (not a rigid one): its source and layout, and whether they changed.
    void prepareDeformed(Entry& e, const VertexBuffer& vb, const Mesh& mesh, bool gpuDeform, bool sigChanged,
                         bool& changed);
    const Object3D* object(std::uint64_t id) const;

    std::unordered_map<std::uint64_t, Entry> entries_;
    std::array<std::pair<std::uint64_t, Entry*>, 2> recent_{};
    std::uint64_t call_ = 0;
    std::vector<std::uint64_t> released_;
    std::array<std::vector<float>, frame::STREAM_COUNT> scratch_;
    std::vector<float> reordered_;  // vertexStreams' scratch
};

}  // namespace m3g::detail
