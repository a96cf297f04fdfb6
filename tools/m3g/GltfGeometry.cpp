#include "GltfGeometry.h"

#include <cmath>

#include <m3g/IndexBuffer.h>
#include <m3g/SkinnedMesh.h>
#include <m3g/Transform.h>
#include <m3g/VertexArray.h>
#include <m3g/VertexBuffer.h>
#include <m3g/skin/InfluenceTable.h>

namespace m3gcli::gltf {

namespace {

/// The GL mapping of a signed byte/short normal component to [-1, 1]
/// (the same as the renderer's, docs/rendering.md).
float glNormal(int value, int componentSize) {
    return (2.0f * static_cast<float>(value) + 1.0f) / (componentSize == 1 ? 255.0f : 65535.0f);
}

std::vector<float> glNormals(const m3g::VertexArray& a) {
    const int n = a.getVertexCount();
    std::vector<float> out(static_cast<std::size_t>(n) * 3, 0.0f);
    const int comps = std::min(a.getComponentCount(), 3);
    for (int v = 0; v < n; ++v)
        for (int c = 0; c < comps; ++c)
            out[static_cast<std::size_t>(v) * 3 + c] = glNormal(a.value(v, c), a.getComponentType());
    return out;
}

}  // namespace

std::vector<std::uint32_t> triangleList(const m3g::IndexBuffer& indices, bool flip) {
    const auto tris = indices.triangleIndices();
    std::vector<std::uint32_t> out(tris.begin(), tris.end());
    if (flip)
        for (std::size_t i = 0; i + 2 < out.size(); i += 3) std::swap(out[i + 1], out[i + 2]);
    return out;
}

std::vector<float> positions(const m3g::VertexBuffer& vb) {
    const m3g::VertexArray* p = vb.positions();
    const int n = vb.getVertexCount();
    std::vector<float> out(static_cast<std::size_t>(n) * 3, 0.0f);
    if (!p) return out;
    const float s = vb.positionScale();
    const auto& bias = vb.positionBias();
    const int comps = std::min(p->getComponentCount(), 3);
    for (int v = 0; v < n; ++v)
        for (int c = 0; c < 3; ++c) {
            const float raw = c < comps ? static_cast<float>(p->value(v, c)) : 0.0f;
            out[static_cast<std::size_t>(v) * 3 + c] = s * raw + bias[static_cast<std::size_t>(c)];
        }
    return out;
}

std::vector<float> positionDeltas(const m3g::VertexBuffer& base, const m3g::VertexBuffer& target) {
    std::vector<float> out(static_cast<std::size_t>(base.getVertexCount()) * 3, 0.0f);
    const m3g::VertexArray* b = base.positions();
    const m3g::VertexArray* t = target.positions();
    if (!b || !t) return out;
    const float s = base.positionScale();  // bias cancels out in the difference
    const int n = std::min(b->getVertexCount(), t->getVertexCount());
    const int comps = std::min({b->getComponentCount(), t->getComponentCount(), 3});
    for (int v = 0; v < n; ++v)
        for (int c = 0; c < comps; ++c)
            out[static_cast<std::size_t>(v) * 3 + c] = s * static_cast<float>(t->value(v, c) - b->value(v, c));
    return out;
}

std::vector<float> normals(const m3g::VertexArray& array, int& degenerate) {
    std::vector<float> out = glNormals(array);
    degenerate = 0;
    for (std::size_t i = 0; i < out.size(); i += 3) {
        const double len = std::sqrt(double(out[i]) * out[i] + double(out[i + 1]) * out[i + 1] +
                                     double(out[i + 2]) * out[i + 2]);
        if (len < 1e-6) {
            out[i] = 0.0f;
            out[i + 1] = 0.0f;
            out[i + 2] = 1.0f;
            ++degenerate;
            continue;
        }
        for (int c = 0; c < 3; ++c) out[i + c] = static_cast<float>(out[i + c] / len);
    }
    return out;
}

std::vector<float> normalDeltas(const m3g::VertexArray& base, const m3g::VertexArray& target) {
    std::vector<float> b = glNormals(base);
    const std::vector<float> t = glNormals(target);
    for (std::size_t i = 0; i < b.size(); ++i) b[i] = i < t.size() ? t[i] - b[i] : 0.0f;
    return b;
}

std::vector<std::uint8_t> colors(const m3g::VertexArray& array) {
    const int n = array.getVertexCount();
    const int comps = array.getComponentCount();
    std::vector<std::uint8_t> out(static_cast<std::size_t>(n) * 4, 255);
    for (int v = 0; v < n; ++v)
        for (int c = 0; c < std::min(comps, 4); ++c)
            out[static_cast<std::size_t>(v) * 4 + c] = static_cast<std::uint8_t>(array.value(v, c) & 0xFF);
    return out;
}

std::vector<float> texCoords(const m3g::VertexBuffer& vb, int unit, const m3g::Transform& m) {
    const m3g::VertexArray* a = vb.texCoords(unit);
    const int n = vb.getVertexCount();
    std::vector<float> out(static_cast<std::size_t>(n) * 2, 0.0f);
    if (!a) return out;
    const float s = vb.texCoordScale(unit);
    const auto& bias = vb.texCoordBias(unit);
    const int comps = a->getComponentCount();
    for (int v = 0; v < n; ++v) {
        float in[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        for (int c = 0; c < std::min(comps, 3); ++c)
            in[c] = s * static_cast<float>(a->value(v, c)) + bias[static_cast<std::size_t>(c)];
        float r[4];
        for (int row = 0; row < 4; ++row)
            r[row] = m.at(row, 0) * in[0] + m.at(row, 1) * in[1] + m.at(row, 2) * in[2] + m.at(row, 3) * in[3];
        // A projective texture matrix: glTF has no q, so divide here (exact
        // at the vertices; interpolation between them becomes affine).
        const float q = (r[3] != 0.0f && std::isfinite(r[3])) ? r[3] : 1.0f;
        out[static_cast<std::size_t>(v) * 2] = r[0] / q;
        out[static_cast<std::size_t>(v) * 2 + 1] = r[1] / q;
    }
    return out;
}

SkinAttributes skinAttributes(const m3g::SkinnedMesh& mesh, int vertexCount, int restJoint) {
    const m3g::skin::InfluenceTable& table = mesh.influenceTable();
    const int n = table.maxInfluences();
    SkinAttributes out;
    out.sets = std::max(1, (n + 3) / 4);
    const std::size_t stride = static_cast<std::size_t>(out.sets) * 4;
    out.joints.assign(static_cast<std::size_t>(vertexCount) * stride, 0);
    out.weights.assign(static_cast<std::size_t>(vertexCount) * stride, 0.0f);
    for (int v = 0; v < vertexCount; ++v) {
        const std::size_t base = static_cast<std::size_t>(v) * stride;
        const int count = table.count(v);
        double sum = 0.0;
        int used = 0;
        for (int k = 0; k < count; ++k) {
            const int bone = table.bone(v, k);
            const float w = table.weight(v, k);
            if (bone < 0 || bone >= mesh.boneCount() || !(w > 0.0f)) continue;
            out.joints[base + static_cast<std::size_t>(used)] = static_cast<std::uint16_t>(bone);
            out.weights[base + static_cast<std::size_t>(used)] = w;
            sum += w;
            ++used;
        }
        if (used == 0) {
            out.joints[base] = static_cast<std::uint16_t>(restJoint);
            out.weights[base] = 1.0f;
            out.usesRestJoint = true;
            continue;
        }
        for (int k = 0; k < used; ++k) out.weights[base + static_cast<std::size_t>(k)] /= static_cast<float>(sum);
    }
    return out;
}

}  // namespace m3gcli::gltf
