// Small scenes for the picking tests: triangle meshes from float-free short
// positions, appearances with culling, a perspective/parallel camera.
// Test-only.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <m3g/Appearance.h>
#include <m3g/Group.h>
#include <m3g/Mesh.h>
#include <m3g/PolygonMode.h>
#include <m3g/RayIntersection.h>
#include <m3g/TriangleStripArray.h>
#include <m3g/VertexArray.h>
#include <m3g/VertexBuffer.h>

namespace picktest {

using namespace m3g;

/// A short VertexArray with `components` values per vertex.
inline Ref<VertexArray> shortArray(const std::vector<std::int16_t>& values, int components) {
    Ref<VertexArray> a = new VertexArray(static_cast<int>(values.size()) / components, components, 2);
    a->set(0, a->getVertexCount(), values);
    return a;
}

/// Positions (xyz per vertex), scale 1, bias 0.
inline Ref<VertexBuffer> positionsVB(const std::vector<std::int16_t>& xyz, float scale = 1.0f,
                                     std::vector<float> bias = {}) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    vb->setPositions(shortArray(xyz, 3), scale, bias.empty() ? std::span<const float>() : std::span<const float>(bias));
    return vb;
}

/// Independent triangles: one strip of length 3 per triangle.
inline Ref<IndexBuffer> triangles(const std::vector<int>& indices) {
    std::vector<int> lengths(indices.size() / 3, 3);
    return new TriangleStripArray(indices, lengths);
}

/// An appearance with a PolygonMode (culling, winding).
inline Ref<Appearance> culled(int culling, int winding = PolygonMode::WINDING_CCW) {
    Ref<Appearance> a = new Appearance();
    Ref<PolygonMode> pm = new PolygonMode();
    pm->setCulling(culling);
    pm->setWinding(winding);
    a->setPolygonMode(pm);
    return a;
}

/// The right triangle (0,0,z) (10,0,z) (0,10,z): counter-clockwise seen from +z.
inline Ref<Mesh> triangleAt(std::int16_t z, Appearance* app = nullptr) {
    Ref<Appearance> a = app ? Ref<Appearance>(app) : Ref<Appearance>(new Appearance());
    return new Mesh(positionsVB({0, 0, z, 10, 0, z, 0, 10, z}), triangles({0, 1, 2}), a);
}

}  // namespace picktest
