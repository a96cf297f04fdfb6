// Reference deformation (plain loops, no change detection): correct first;
// the skinning issue replaces the inner loops with skin/ kernels.
#include "MeshDeformer.h"

#include <algorithm>
#include <cmath>

#include <m3g/MorphingMesh.h>
#include <m3g/SkinnedMesh.h>
#include <m3g/VertexArray.h>
#include <m3g/VertexBuffer.h>

#include "Check.h"
#include "MathUtil.h"

namespace m3g::detail {

namespace {

/// Raw values of `array` as floats (componentCount per vertex).
std::vector<float> rawFloats(const VertexArray* array) {
    std::vector<float> out(static_cast<std::size_t>(array->getVertexCount()) * array->getComponentCount());
    array->getFloats(0, array->getVertexCount(), out);
    return out;
}

/// Positions with scale and bias applied, xyz per vertex.
void scaledPositions(const VertexBuffer& vb, std::vector<float>& out) {
    const VertexArray* p = vb.positions();
    const int n = vb.getVertexCount();
    out.assign(static_cast<std::size_t>(n) * 3, 0.0f);
    if (!p) return;
    const float s = vb.positionScale();
    const auto& b = vb.positionBias();
    for (int v = 0; v < n; ++v)
        for (int c = 0; c < 3; ++c) out[v * 3 + c] = s * static_cast<float>(p->value(v, c)) + b[c];
}

/// Normals as floats with the GL signed-integer mapping (2c + 1) / (2^bits - 1).
void floatNormals(const VertexArray* array, std::vector<float>& out) {
    out.clear();
    if (!array) return;
    const float range = array->getComponentType() == 1 ? 255.0f : 65535.0f;
    const int n = array->getVertexCount();
    out.resize(static_cast<std::size_t>(n) * 3);
    for (int v = 0; v < n; ++v)
        for (int c = 0; c < 3; ++c) out[v * 3 + c] = (2.0f * static_cast<float>(array->value(v, c)) + 1.0f) / range;
}

void normalize3(float* n) {
    const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (len > 0.0f)
        for (int c = 0; c < 3; ++c) n[c] /= len;
}

void skin(const SkinnedMesh& mesh, DeformedVertices& out) {
    const VertexBuffer& vb = *mesh.getVertexBuffer();
    const int n = vb.getVertexCount();
    std::vector<float> base, baseNormals;
    scaledPositions(vb, base);
    floatNormals(vb.normals(), baseNormals);

    // One palette entry per bone: (bone -> mesh now) x at-rest, and the
    // inverse transpose of its upper 3x3 for normals (spec §5.11).
    std::vector<glm::mat4> palette(mesh.boneCount());
    std::vector<glm::mat3> normalPalette(mesh.boneCount());
    for (int b = 0; b < mesh.boneCount(); ++b) {
        Transform boneToMesh;
        mesh.bone(b)->getTransformTo(&mesh, &boneToMesh);
        palette[b] = toGlm(boneToMesh) * toGlm(mesh.atRestTransform(b));
        normalPalette[b] = glm::transpose(glm::inverse(glm::mat3(palette[b])));
    }

    const skin::InfluenceTable& table = mesh.influenceTable();
    out.positions = base;
    out.normals = baseNormals;
    const int skinned = std::min(n, table.vertexCount());
    for (int v = 0; v < skinned; ++v) {
        const int count = table.count(v);
        if (count == 0) continue;  // no influence: stays in mesh space (Nokia)
        glm::vec3 p(0.0f), nn(0.0f);
        const glm::vec4 src(base[v * 3], base[v * 3 + 1], base[v * 3 + 2], 1.0f);
        for (int k = 0; k < count; ++k) {
            const int bone = table.bone(v, k);
            const float w = table.weight(v, k);
            p += w * glm::vec3(palette[bone] * src);
            if (!baseNormals.empty())
                nn += w * (normalPalette[bone] *
                           glm::vec3(baseNormals[v * 3], baseNormals[v * 3 + 1], baseNormals[v * 3 + 2]));
        }
        for (int c = 0; c < 3; ++c) out.positions[v * 3 + c] = p[c];
        if (!baseNormals.empty()) {
            for (int c = 0; c < 3; ++c) out.normals[v * 3 + c] = nn[c];
            normalize3(&out.normals[v * 3]);
        }
    }
    out.colors.clear();
    for (auto& t : out.texCoords) t.clear();
    out.texCoordComponents.fill(0);
}

/// B + sum_i w_i (T_i - B) over equally long float arrays.
void morphArrays(const std::vector<float>& base, const std::vector<std::vector<float>>& targets,
                 std::span<const float> weights, std::vector<float>& out) {
    out = base;
    for (std::size_t t = 0; t < targets.size(); ++t) {
        const float w = weights[t];
        if (w == 0.0f) continue;
        for (std::size_t i = 0; i < out.size(); ++i) out[i] += w * (targets[t][i] - base[i]);
    }
}

/// Colours as unsigned bytes 0..255 (RGBA per vertex; RGB arrays get 255).
std::vector<float> byteColors(const VertexBuffer& vb) {
    const int n = vb.getVertexCount();
    std::vector<float> out(static_cast<std::size_t>(n) * 4);
    const VertexArray* c = vb.colors();
    const auto argb = static_cast<std::uint32_t>(vb.getDefaultColor());
    for (int v = 0; v < n; ++v) {
        for (int k = 0; k < 4; ++k) {
            float value;
            if (c) value = k < c->getComponentCount() ? static_cast<float>(c->value(v, k) & 0xFF) : 255.0f;
            else value = static_cast<float>(k == 3 ? (argb >> 24) & 0xFF : (argb >> (16 - 8 * k)) & 0xFF);
            out[v * 4 + k] = value;
        }
    }
    return out;
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

void morph(const MorphingMesh& mesh, DeformedVertices& out) {
    const VertexBuffer& base = *mesh.getVertexBuffer();
    const int count = mesh.getMorphTargetCount();
    for (int t = 0; t < count; ++t) requireSameArrays(base, *mesh.morphTarget(t), t);
    const std::span<const float> weights = mesh.weights();
    std::vector<std::vector<float>> targets(count);

    // Positions: morph the raw values, then apply the base's scale and bias.
    if (base.positions()) {
        for (int t = 0; t < count; ++t) targets[t] = rawFloats(mesh.morphTarget(t)->positions());
        std::vector<float> raw;
        morphArrays(rawFloats(base.positions()), targets, weights, raw);
        const int comps = base.positions()->getComponentCount();
        const float s = base.positionScale();
        const auto& b = base.positionBias();
        out.positions.assign(static_cast<std::size_t>(out.vertexCount) * 3, 0.0f);
        for (int v = 0; v < out.vertexCount; ++v)
            for (int c = 0; c < 3 && c < comps; ++c) out.positions[v * 3 + c] = s * raw[v * comps + c] + b[c];
    } else {
        out.positions.clear();
    }

    out.normals.clear();
    if (base.normals()) {
        std::vector<float> b;
        floatNormals(base.normals(), b);
        for (int t = 0; t < count; ++t) floatNormals(mesh.morphTarget(t)->normals(), targets[t]);
        morphArrays(b, targets, weights, out.normals);
        for (int v = 0; v < out.vertexCount; ++v) normalize3(&out.normals[v * 3]);
    }

    // Colours (or the default colour when the base has none), clamped to 0..255.
    for (int t = 0; t < count; ++t) targets[t] = byteColors(*mesh.morphTarget(t));
    morphArrays(byteColors(base), targets, weights, out.colors);
    for (float& c : out.colors) c = std::clamp(c, 0.0f, 255.0f) / 255.0f;

    for (int u = 0; u < kMaxTextureUnits; ++u) {
        out.texCoords[u].clear();
        out.texCoordComponents[u] = 0;
        if (!base.texCoords(u)) continue;
        for (int t = 0; t < count; ++t) targets[t] = rawFloats(mesh.morphTarget(t)->texCoords(u));
        morphArrays(rawFloats(base.texCoords(u)), targets, weights, out.texCoords[u]);
        out.texCoordComponents[u] = base.texCoords(u)->getComponentCount();
    }
}

}  // namespace

bool MeshDeformer::update(const Mesh& mesh) {
    if (const auto* skinned = dynamic_cast<const SkinnedMesh*>(&mesh)) {
        out_.vertexCount = skinned->getVertexBuffer()->getVertexCount();
        skin(*skinned, out_);
    } else if (const auto* morphing = dynamic_cast<const MorphingMesh*>(&mesh)) {
        out_.vertexCount = morphing->getVertexBuffer()->getVertexCount();
        morph(*morphing, out_);
    } else {
        out_ = DeformedVertices{};
        return false;
    }
    ++stamp_;
    return true;
}

}  // namespace m3g::detail
