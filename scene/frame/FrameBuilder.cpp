#include "FrameBuilder.h"

#include <algorithm>

#include <m3g/Appearance.h>
#include <m3g/Image2D.h>
#include <m3g/IndexBuffer.h>
#include <m3g/Mesh.h>
#include <m3g/MorphingMesh.h>
#include <m3g/SkinnedMesh.h>
#include <m3g/Sprite3D.h>
#include <m3g/Texture2D.h>
#include <m3g/VertexArray.h>
#include <m3g/VertexBuffer.h>

#include "Check.h"
#include "PropertyUtil.h"
#include "RenderQueue.h"

namespace m3g::detail {

namespace {

using frame::VertexSource;

void rawStream(const VertexArray* a, int outComponents, std::vector<float>& out) {
    const int n = a->getVertexCount(), c = a->getComponentCount();
    out.assign(static_cast<std::size_t>(n) * outComponents, 0.0f);
    for (int v = 0; v < n; ++v)
        for (int k = 0; k < std::min(c, outComponents); ++k) out[v * outComponents + k] = static_cast<float>(a->value(v, k));
}

// OpenGL's signed-integer normal mapping (normalComponent).
void normalStream(const VertexArray* a, std::vector<float>& out) {
    const int n = a->getVertexCount(), size = a->getComponentType();
    out.resize(static_cast<std::size_t>(n) * 3);
    for (int v = 0; v < n; ++v)
        for (int k = 0; k < 3; ++k) out[v * 3 + k] = normalComponent(a->value(v, k), size);
}

// Colour bytes are unsigned; 3-component colours get alpha 1.
void colorStream(const VertexArray* a, std::vector<float>& out) {
    const int n = a->getVertexCount(), c = a->getComponentCount();
    out.resize(static_cast<std::size_t>(n) * 4);
    for (int v = 0; v < n; ++v)
        for (int k = 0; k < 4; ++k) out[v * 4 + k] = k < c ? static_cast<float>(a->value(v, k) & 0xFF) / 255.0f : 1.0f;
}

/// Identity and revision of the VertexBuffer's arrays, and its identity.
/// The VertexBuffer's own revision is left out: what else it holds (scale,
/// bias, default colour) goes into the uniforms, not the streams, so an
/// animated default colour does not copy the vertices again.
std::array<std::uint64_t, 12> signatureOf(const VertexBuffer& vb) {
    std::array<std::uint64_t, 12> sig{};
    sig[0] = vb.getObjectId();
    const Object3D* arrays[5] = {vb.positions(), vb.normals(), vb.colors(), vb.texCoords(0), vb.texCoords(1)};
    for (int i = 0; i < 5; ++i) {
        sig[2 + i * 2] = arrays[i] ? arrays[i]->getObjectId() : 0;
        sig[3 + i * 2] = arrays[i] ? arrays[i]->getRevision() : 0;
    }
    return sig;
}

bool deforms(const Mesh* mesh) {
    return mesh && (dynamic_cast<const SkinnedMesh*>(mesh) || dynamic_cast<const MorphingMesh*>(mesh));
}

}  // namespace

FrameBuilder::FrameBuilder() = default;
FrameBuilder::~FrameBuilder() = default;

FrameBuilder::Entry& FrameBuilder::entry(const Object3D& object) {
    const std::uint64_t id = object.getObjectId();
    for (const auto& [recentId, e] : recent_)
        if (recentId == id) return *e;
    Entry& e = entries_[id];
    if (!e.owner.get()) e.owner = const_cast<Object3D*>(&object);
    recent_[1] = recent_[0];
    recent_[0] = {id, &e};
    return e;
}

const Object3D* FrameBuilder::object(std::uint64_t id) const {
    const auto it = entries_.find(id);
    return it == entries_.end() ? nullptr : it->second.owner.get();
}

void FrameBuilder::prepareVertices(Entry& e, const VertexBuffer& vb, const Mesh* mesh, bool gpuDeform,
                                   frame::VertexRef& ref) {
    if (e.call != call_) {
        e.call = call_;
        const auto sig = signatureOf(vb);
        const bool sigChanged = sig != e.signature;
        bool changed = sigChanged;
        e.signature = sig;
        VertexLayout& layout = e.layout;
        auto plainLayout = [&] {
            layout.deformed = false;
            layout.present = {true, vb.normals() != nullptr, vb.colors() != nullptr, vb.texCoords(0) != nullptr,
                              vb.texCoords(1) != nullptr};
        };
        layout.rigid = false;
        if (!mesh) {
            e.source = VertexSource::Plain;
            plainLayout();
        } else {
            if (!e.deformer) e.deformer = std::make_unique<MeshDeformer>();
            MeshDeformer& d = *e.deformer;
            const bool deformedChanged =
                d.update(*mesh, gpuDeform ? MeshDeformer::Output::InputsOnly : MeshDeformer::Output::Vertices,
                         MeshDeformer::Rigid::AsTransform);
            if (d.vertices().rigid) {
                // The VertexBuffer's own vertices, drawn through the bone's
                // transform (translateSubmesh): uploaded once, not per pose.
                changed |= e.source != VertexSource::Plain;
                e.source = VertexSource::Plain;
                plainLayout();
                layout.rigid = true;
                layout.rigidTransform = d.vertices().rigidTransform;
            } else {
                changed |= deformedChanged;
                prepareDeformed(e, vb, *mesh, gpuDeform, sigChanged, changed);
            }
        }
        if (changed || e.version == 0) ++e.version;
    }
    ref.owner = e.owner.get()->getObjectId();
    ref.version = e.version;
    ref.inputVersion = e.inputVersion;
    ref.source = e.source;
    ref.vertexCount = vb.getVertexCount();
    ref.present = e.layout.present;
}

void FrameBuilder::prepareDeformed(Entry& e, const VertexBuffer& vb, const Mesh& mesh, bool gpuDeform,
                                   bool sigChanged, bool& changed) {
    const MeshDeformer& d = *e.deformer;
    VertexLayout& layout = e.layout;
    const bool skinned = dynamic_cast<const SkinnedMesh*>(&mesh) != nullptr;
    const VertexSource source =
        !gpuDeform ? VertexSource::Deformed : skinned ? VertexSource::GpuSkinned : VertexSource::GpuMorphed;
    const bool sourceChanged = source != e.source;
    changed |= sourceChanged;
    e.source = source;
    layout.deformed = true;
    auto& p = layout.present;
    p[frame::POSITIONS] = true;
    if (source == VertexSource::Deformed) {
        const DeformedVertices& out = d.vertices();
        p[frame::NORMALS] = !out.normals.empty();
        p[frame::COLORS] = !out.colors.empty() || vb.colors();
        for (int u = 0; u < 2; ++u)
            p[frame::TEXCOORDS0 + u] = !out.texCoords[static_cast<std::size_t>(u)].empty() || vb.texCoords(u);
    } else if (skinned) {
        p[frame::NORMALS] = !d.skinInputs().normals.empty();
        p[frame::COLORS] = vb.colors() != nullptr;
        for (int u = 0; u < 2; ++u) p[frame::TEXCOORDS0 + u] = vb.texCoords(u) != nullptr;
    } else {
        p[frame::NORMALS] = d.morphAttribute(MeshDeformer::kMorphNormals).components > 0;
        p[frame::COLORS] = d.morphAttribute(MeshDeformer::kMorphColors).components > 0;
        for (int u = 0; u < 2; ++u)
            p[frame::TEXCOORDS0 + u] = d.morphAttribute(MeshDeformer::kMorphTexCoords + u).components > 0;
    }
    // The kernel's static inputs, or the streams the host writes
    // beside its outputs, changed.
    if (source != VertexSource::Deformed &&
        (sigChanged || sourceChanged || d.inputStamp() != e.inputStamp || e.inputVersion == 0)) {
        ++e.inputVersion;
        e.inputStamp = d.inputStamp();
    }
}

void FrameBuilder::build(const RenderQueue& queue, const frame::ViewState& view, bool gpuDeform,
                         const frame::DrawOptions& options, frame::DrawList& out) {
    out.reset();
    ++call_;
    if (view.scissor.empty()) return;
    float projection[16];
    toColumns(options.vulkanClipSpace ? vulkanProjection(queue.projection) : queue.projection, projection);
    const int units = getLimits().numTextureUnits;
    out.draws.reserve(queue.items.size());
    out.uniforms.reserve(queue.items.size());
    for (const RenderItem& item : queue.items) {
        frame::Draw draw;
        frame::DrawUniforms& u = out.uniforms.emplace_back();
        if (item.kind == RenderItem::Kind::Sprite) {
            if (!translateSprite(queue, item, view.viewport.w, view.viewport.h, options.vulkanClipSpace, u, draw)) {
                out.uniforms.pop_back();
                continue;
            }
            entry(*static_cast<const Sprite3D&>(*item.node).getImage());
        } else {
            const VertexBuffer& vb = *item.vertices;
            if (!vb.positions())
                throw IllegalStateException("Graphics3D::render: the VertexBuffer has no positions (invalid vertex data)");
            const auto* mesh = dynamic_cast<const Mesh*>(item.node);
            if (!deforms(mesh)) mesh = nullptr;
            Entry& e = entry(mesh ? static_cast<const Object3D&>(*mesh) : vb);
            prepareVertices(e, vb, mesh, gpuDeform, draw.vertices);
            const IndexBuffer& ib = *item.indices;
            if (ib.getIndexCount() == 0) {
                out.uniforms.pop_back();
                continue;
            }
            if (ib.maxIndex() >= vb.getVertexCount())
                throw IllegalStateException(str("Graphics3D::render: an IndexBuffer refers to vertex ", ib.maxIndex(),
                                                " but the VertexBuffer has ", vb.getVertexCount(), " vertices"));
            entry(ib);
            draw.indices = {ib.getObjectId(), ib.getRevision()};
            // CPU-deformed vertices in an order of their own: the triangles
            // go through it (triangles()).
            if (e.source == VertexSource::Deformed && !e.deformer->vertices().order.empty()) {
                draw.indices.vertexOrder = draw.vertices.owner;
                draw.indices.orderVersion = e.deformer->orderStamp();
            }
            translateSubmesh(queue, item, e.layout, projection, options, units, u, draw);
            for (int unit = 0; unit < 2; ++unit)
                if (draw.textures[static_cast<std::size_t>(unit)].id)
                    entry(*item.appearance->getTexture(unit)->getImage());
        }
        draw.uniforms = static_cast<std::uint32_t>(out.uniforms.size() - 1);
        out.draws.push_back(draw);
    }
}

std::span<const std::uint64_t> FrameBuilder::sweep() {
    released_.clear();
    recent_ = {};
    for (auto it = entries_.begin(); it != entries_.end();) {
        if (!it->second.owner.get()) {
            released_.push_back(it->first);
            it = entries_.erase(it);
        } else {
            ++it;
        }
    }
    return released_;
}

frame::VertexStreams FrameBuilder::vertexStreams(const frame::VertexRef& ref) {
    frame::VertexStreams s;
    const auto it = entries_.find(ref.owner);
    const Object3D* owner = it == entries_.end() ? nullptr : it->second.owner.get();
    if (!owner) return s;
    const auto* mesh = dynamic_cast<const Mesh*>(owner);
    const VertexBuffer* vb = mesh ? mesh->vertexBuffer() : dynamic_cast<const VertexBuffer*>(owner);
    if (!vb) return s;
    auto put = [&](int stream) { s.streams[static_cast<std::size_t>(stream)] = scratch_[static_cast<std::size_t>(stream)]; };
    if (ref.source == VertexSource::Plain) {
        if (vb->positions()) {
            rawStream(vb->positions(), 3, scratch_[frame::POSITIONS]);
            put(frame::POSITIONS);
        }
        if (vb->normals()) {
            normalStream(vb->normals(), scratch_[frame::NORMALS]);
            put(frame::NORMALS);
        }
    } else if (ref.source == VertexSource::Deformed && it->second.deformer) {
        const DeformedVertices& d = it->second.deformer->vertices();
        s.streams[frame::POSITIONS] = d.positions;
        if (!d.normals.empty()) s.streams[frame::NORMALS] = d.normals;
        if (!d.colors.empty()) s.streams[frame::COLORS] = d.colors;
        const int n = vb->getVertexCount();
        for (int u = 0; u < 2; ++u) {
            const auto& tc = d.texCoords[static_cast<std::size_t>(u)];
            if (tc.empty()) continue;
            const int c = d.texCoordComponents[static_cast<std::size_t>(u)];
            auto& dst = scratch_[static_cast<std::size_t>(frame::TEXCOORDS0 + u)];
            dst.assign(static_cast<std::size_t>(n) * 3, 0.0f);
            for (int v = 0; v < n; ++v)
                for (int k = 0; k < std::min(c, 3); ++k) dst[v * 3 + k] = tc[v * c + k];
            put(frame::TEXCOORDS0 + u);
        }
    }
    if (ref.source == VertexSource::GpuMorphed) return s;
    // The VertexBuffer's own colours and texture coordinates where the
    // deformation left them alone.
    auto fill = [&](int stream, std::vector<float>& out) {
        if (stream == frame::COLORS)
            colorStream(vb->colors(), out);
        else
            rawStream(vb->texCoords(stream - frame::TEXCOORDS0), 3, out);
    };
    auto needed = [&](int stream) {
        const VertexArray* a = stream == frame::COLORS ? vb->colors() : vb->texCoords(stream - frame::TEXCOORDS0);
        return a && s.streams[static_cast<std::size_t>(stream)].empty();
    };
    if (ref.source != VertexSource::Deformed || !it->second.deformer) {
        for (int stream = frame::COLORS; stream < frame::STREAM_COUNT; ++stream)
            if (needed(stream)) {
                fill(stream, scratch_[static_cast<std::size_t>(stream)]);
                put(stream);
            }
        return s;
    }
    // A deformed mesh is read again at every pose; these do not change with
    // it, so they are converted, and put in the deformed vertices' order
    // (DeformedVertices::order), once per change of the arrays or the order.
    Entry& e = it->second;
    Statics& st = e.statics;
    const std::uint64_t orderStamp = e.deformer->orderStamp();
    if (!st.valid || st.signature != e.signature || st.order != orderStamp) {
        const DeformedVertices& deformed = e.deformer->vertices();
        for (int stream = frame::COLORS; stream < frame::STREAM_COUNT; ++stream) {
            auto& values = st.streams[static_cast<std::size_t>(stream - frame::COLORS)];
            values.clear();
            if (!needed(stream)) continue;
            fill(stream, reordered_);
            deformed.inSlotOrder(reordered_, frame::kStreamComponents[static_cast<std::size_t>(stream)], values);
        }
        st.valid = true;
        st.signature = e.signature;
        st.order = orderStamp;
    }
    for (int stream = frame::COLORS; stream < frame::STREAM_COUNT; ++stream) {
        const auto& values = st.streams[static_cast<std::size_t>(stream - frame::COLORS)];
        if (needed(stream) && !values.empty()) s.streams[static_cast<std::size_t>(stream)] = values;
    }
    return s;
}

frame::SkinInputs FrameBuilder::skinInputs(const frame::VertexRef& ref) {
    const auto it = entries_.find(ref.owner);
    if (it == entries_.end() || !it->second.deformer) return {};
    return it->second.deformer->skinInputs();
}

frame::MorphInputs FrameBuilder::morphInputs(const frame::VertexRef& ref) {
    frame::MorphInputs in;
    const auto it = entries_.find(ref.owner);
    if (it == entries_.end() || !it->second.deformer) return in;
    const MeshDeformer& d = *it->second.deformer;
    in.vertexCount = ref.vertexCount;
    for (int a = 0; a < frame::kMorphAttributes; ++a) in.attributes[static_cast<std::size_t>(a)] = d.morphAttribute(a);
    in.weights = d.morphWeights();
    return in;
}

void FrameBuilder::triangles(const frame::IndexRef& ref, std::vector<std::uint32_t>& out) {
    out.clear();
    if (const auto* ib = dynamic_cast<const IndexBuffer*>(object(ref.id))) triangleList(*ib, out);
    if (!ref.vertexOrder) return;
    const auto it = entries_.find(ref.vertexOrder);
    if (it == entries_.end() || !it->second.deformer) return;
    // build() checked every index against the vertex count.
    const std::span<const std::uint32_t> location = it->second.deformer->vertices().location;
    if (location.empty()) return;
    for (std::uint32_t& i : out) i = i < location.size() ? location[i] : i;
}

void FrameBuilder::texels(const frame::TextureRef& ref, std::vector<std::uint8_t>& rgba, int& width, int& height) {
    rgba.clear();
    width = height = 0;
    if (const auto* image = dynamic_cast<const Image2D*>(object(ref.id))) {
        image->getPixelsRGBA8(rgba);
        width = image->getWidth();
        height = image->getHeight();
    }
}

}  // namespace m3g::detail
