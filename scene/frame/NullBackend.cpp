#include "NullBackend.h"

#include <algorithm>

namespace m3g::detail {

void NullBackend::refresh(const frame::Draw& draw, frame::FrameSources& sources) {
    for (const frame::TextureRef& t : draw.textures) {
        if (!t.id) continue;
        auto [it, fresh] = versions_.try_emplace(t.id, t.revision);
        if (!fresh && it->second == t.revision) continue;
        it->second = t.revision;
        std::vector<std::uint8_t> rgba;
        int w = 0, h = 0;
        sources.texels(t, rgba, w, h);
        ++uploads_.textures;
    }
    if (draw.kind != frame::Draw::Kind::Submesh) return;
    const frame::VertexRef& v = draw.vertices;
    auto [vit, vfresh] = versions_.try_emplace(v.owner, v.version);
    if (vfresh || vit->second != v.version) {
        vit->second = v.version;
        const frame::VertexStreams s = sources.vertexStreams(v);
        auto& copy = streams_[v.owner];
        copy.assign(frame::STREAM_COUNT, {});
        for (int i = 0; i < frame::STREAM_COUNT; ++i)
            copy[static_cast<std::size_t>(i)].assign(s.streams[static_cast<std::size_t>(i)].begin(),
                                                     s.streams[static_cast<std::size_t>(i)].end());
        ++uploads_.vertices;
        // A GPU kernel's inputs are read at every new version (the pose).
        if (v.source == frame::VertexSource::GpuSkinned) uploads_.skinVertices += sources.skinInputs(v).vertexCount;
        if (v.source == frame::VertexSource::GpuMorphed) uploads_.morphVertices += sources.morphInputs(v).vertexCount;
    }
    const IndexKey key{draw.indices.id, draw.indices.vertexOrder};
    const std::pair<std::uint32_t, std::uint64_t> version{draw.indices.revision, draw.indices.orderVersion};
    auto [iit, ifresh] = indexVersions_.try_emplace(key, version);
    if (ifresh || iit->second != version) {
        iit->second = version;
        sources.triangles(draw.indices, triangles_[key]);
        ++uploads_.indices;
    }
}

void NullBackend::refresh(const frame::DrawList& list, frame::FrameSources& sources) {
    for (const frame::Draw& d : list.draws) refresh(d, sources);
    if (list.clear.hasImage) refresh(list.clear.image, sources);
}

void NullBackend::clear(const frame::Target& target, const frame::ViewState& view, const frame::DrawList& list,
                        frame::FrameSources& sources) {
    refresh(list, sources);
    calls_.push_back({Call::Kind::Clear, target, view, list, {}});
}

void NullBackend::draw(const frame::Target& target, const frame::ViewState& view, const frame::DrawList& list,
                       frame::FrameSources& sources) {
    refresh(list, sources);
    calls_.push_back({Call::Kind::Draw, target, view, list, {}});
}

void NullBackend::release(const frame::Target& target, std::span<const std::uint64_t> released) {
    for (std::uint64_t id : released) {
        versions_.erase(id);
        streams_.erase(id);
    }
    // Index copies go with their IndexBuffer and with the mesh whose vertex
    // order they follow.
    auto gone = [&](std::uint64_t id) {
        return id && std::find(released.begin(), released.end(), id) != released.end();
    };
    for (auto it = indexVersions_.begin(); it != indexVersions_.end();) {
        if (gone(it->first.first) || gone(it->first.second)) {
            triangles_.erase(it->first);
            it = indexVersions_.erase(it);
        } else {
            ++it;
        }
    }
    calls_.push_back({Call::Kind::Release, target, {}, {}, {released.begin(), released.end()}});
}

}  // namespace m3g::detail
