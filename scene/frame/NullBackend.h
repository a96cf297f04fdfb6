// A back end that draws nothing and records what it was asked (bgfx's and
// Filament's no-op drivers play this part): Graphics3D's whole frame path
// runs and is tested on a machine without Vulkan. Like a real back end it
// keeps a copy per resource and reads FrameSources only when a draw names a
// newer version, so tests also see what would be uploaded when.
#pragma once

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include <m3g/frame/FrameBackend.h>

namespace m3g::detail {

class NullBackend final : public frame::FrameBackend {
public:
    struct Call {
        enum class Kind { Clear, Draw, Release } kind = Kind::Draw;
        frame::Target target;
        frame::ViewState view;
        frame::DrawList list;  ///< a copy
        std::vector<std::uint64_t> released;
    };
    /// What a real back end would have uploaded.
    struct Uploads {
        int vertices = 0, indices = 0, textures = 0;
        long skinVertices = 0, morphVertices = 0;  ///< vertices given to GPU kernels
    };

    frame::DrawOptions options() const noexcept override { return options_; }
    void clear(const frame::Target& target, const frame::ViewState& view, const frame::DrawList& list,
               frame::FrameSources& sources) override;
    void draw(const frame::Target& target, const frame::ViewState& view, const frame::DrawList& list,
              frame::FrameSources& sources) override;
    void release(const frame::Target& target, std::span<const std::uint64_t> released) override;

    void setOptions(const frame::DrawOptions& options) noexcept { options_ = options; }
    const std::vector<Call>& calls() const noexcept { return calls_; }
    void clearCalls() noexcept { calls_.clear(); }
    const Uploads& uploads() const noexcept { return uploads_; }
    /// The last vertex streams read for `owner` (floats per stream).
    const std::vector<std::vector<float>>& lastStreams(std::uint64_t owner) const { return streams_.at(owner); }
    /// The last triangle list read for index buffer `id` (remapped to the
    /// vertex order of mesh `vertexOrder`, IndexRef::vertexOrder).
    const std::vector<std::uint32_t>& lastTriangles(std::uint64_t id, std::uint64_t vertexOrder = 0) const {
        return triangles_.at({id, vertexOrder});
    }
    /// How many resource copies are held (freed by release's ids).
    std::size_t resident() const noexcept { return versions_.size() + indexVersions_.size(); }

private:
    void refresh(const frame::DrawList& list, frame::FrameSources& sources);
    void refresh(const frame::Draw& draw, frame::FrameSources& sources);

    frame::DrawOptions options_;
    std::vector<Call> calls_;
    Uploads uploads_;
    std::map<std::uint64_t, std::uint64_t> versions_;  // id -> version (or revision) held
    std::map<std::uint64_t, std::vector<std::vector<float>>> streams_;
    // Index copies per (IndexBuffer, vertex order): (revision, order version).
    using IndexKey = std::pair<std::uint64_t, std::uint64_t>;
    std::map<IndexKey, std::pair<std::uint32_t, std::uint64_t>> indexVersions_;
    std::map<IndexKey, std::vector<std::uint32_t>> triangles_;
};

}  // namespace m3g::detail
