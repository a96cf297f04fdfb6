// Scene-building helpers for the frame-preparation tests
// (test_StateTranslation, test_RenderQueue, test_Graphics3DNullBackend):
// vertex data with integer positions (hand-checkable values), a triangle-list
// IndexBuffer whose triangles can change (IndexBuffer's protected
// setTriangles), and a Graphics3D drawing into scene's recording NullBackend.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <span>
#include <vector>

#include <m3g/m3g.h>

#include "NullBackend.h"

namespace frametest {

/// A generic triangle list (not a strip): what IndexBuffer's subclasses
/// other than TriangleStripArray give the renderer. `set` replaces the
/// triangles (and bumps the revision, as IndexBuffer::setTriangles does).
class TriangleList final : public m3g::IndexBuffer {
public:
    explicit TriangleList(std::vector<int> triangles) { setTriangles(std::move(triangles)); }
    void set(std::vector<int> triangles) { setTriangles(std::move(triangles)); }
    const char* getClassName() const noexcept override { return "TriangleList"; }

protected:
    m3g::Object3D* duplicateImpl(DuplicateMap&) const override { return new TriangleList(*this); }
};

/// A short VertexArray of `components` values per vertex.
inline m3g::Ref<m3g::VertexArray> shorts(int components, std::initializer_list<int> values) {
    const int n = static_cast<int>(values.size()) / components;
    m3g::Ref<m3g::VertexArray> a(new m3g::VertexArray(n, components, 2));
    std::vector<std::int16_t> v;
    for (int x : values) v.push_back(static_cast<std::int16_t>(x));
    a->set(0, n, std::span<const std::int16_t>(v));
    return a;
}

/// A byte VertexArray of `components` values per vertex (colours: 0..255).
inline m3g::Ref<m3g::VertexArray> bytes(int components, std::initializer_list<int> values) {
    const int n = static_cast<int>(values.size()) / components;
    m3g::Ref<m3g::VertexArray> a(new m3g::VertexArray(n, components, 1));
    std::vector<std::int8_t> v;
    for (int x : values) v.push_back(static_cast<std::int8_t>(static_cast<std::uint8_t>(x)));
    a->set(0, n, std::span<const std::int8_t>(v));
    return a;
}

/// A VertexBuffer with the given integer positions, scale and bias.
inline m3g::Ref<m3g::VertexBuffer> vertexBuffer(std::initializer_list<int> xyz, float scale = 1.0f,
                                                std::array<float, 3> bias = {0, 0, 0}) {
    m3g::Ref<m3g::VertexBuffer> vb(new m3g::VertexBuffer());
    vb->setPositions(shorts(3, xyz).get(), scale, bias);
    return vb;
}

/// A unit quad in the XY plane at z = `z` (positions (-1,-1), (1,-1),
/// (-1,1), (1,1) in strip order) as one strip of four vertices.
struct Quad {
    m3g::Ref<m3g::VertexBuffer> vb;
    m3g::Ref<m3g::IndexBuffer> ib;
};
inline Quad quad(int z = 0) {
    Quad q;
    q.vb = vertexBuffer({-1, -1, z, 1, -1, z, -1, 1, z, 1, 1, z});
    const int lengths[] = {4};
    q.ib = new m3g::TriangleStripArray(0, lengths);
    return q;
}

/// A Mesh of a fresh quad with `app`.
inline m3g::Ref<m3g::Mesh> quadMesh(m3g::Appearance* app, int z = 0) {
    Quad q = quad(z);
    return m3g::Ref<m3g::Mesh>(new m3g::Mesh(q.vb.get(), q.ib.get(), app));
}

/// An Appearance in `layer` with a CompositingMode of `blending`.
inline m3g::Ref<m3g::Appearance> appearance(int layer = 0, int blending = m3g::CompositingMode::REPLACE) {
    m3g::Ref<m3g::Appearance> a(new m3g::Appearance());
    a->setLayer(layer);
    m3g::Ref<m3g::CompositingMode> cm(new m3g::CompositingMode());
    cm->setBlending(blending);
    a->setCompositingMode(cm.get());
    return a;
}

/// A mutable image of `format` (every byte `fill`).
inline m3g::Ref<m3g::Image2D> image(int format, int w, int h, std::uint8_t fill = 0x80) {
    std::vector<std::uint8_t> px(static_cast<std::size_t>(w) * h * m3g::Image2D::bytesPerPixel(format), fill);
    m3g::Ref<m3g::Image2D> img(new m3g::Image2D(format, w, h));
    img->set(0, 0, w, h, px);
    return img;
}

/// A World with an identity active camera (GENERIC, identity projection).
inline m3g::Ref<m3g::World> worldWithCamera() {
    m3g::Ref<m3g::World> world(new m3g::World());
    m3g::Ref<m3g::Camera> cam(new m3g::Camera());
    world->addChild(cam.get());
    world->setActiveCamera(cam.get());
    return world;
}

inline m3g::Transform translation(float x, float y, float z) {
    m3g::Transform t;
    t.postTranslate(x, y, z);
    return t;
}

inline m3g::Ref<m3g::Light> light(int mode, int rgb = 0xFFFFFF, float intensity = 1.0f, int scope = -1) {
    m3g::Ref<m3g::Light> l(new m3g::Light());
    l->setMode(mode);
    l->setColor(rgb);
    l->setIntensity(intensity);
    l->setScope(scope);
    return l;
}

/// A Graphics3D of its own (Graphics3D::create) drawing into a NullBackend
/// it keeps a pointer to.
struct NullFrame {
    std::unique_ptr<m3g::Graphics3D> g = m3g::Graphics3D::create();
    m3g::detail::NullBackend* backend = nullptr;

    NullFrame() {
        auto b = std::make_unique<m3g::detail::NullBackend>();
        backend = b.get();
        g->useBackend(std::move(b));
    }
    const std::vector<m3g::detail::NullBackend::Call>& calls() const { return backend->calls(); }
    /// The last call (which must exist).
    const m3g::detail::NullBackend::Call& last() const { return backend->calls().back(); }
};

inline const char* kindName(m3g::detail::NullBackend::Call::Kind k) {
    using K = m3g::detail::NullBackend::Call::Kind;
    return k == K::Clear ? "Clear" : k == K::Draw ? "Draw" : "Release";
}

}  // namespace frametest
