// Group::pick (JSR-184 1.1, Group.pick and RayIntersection; behaviour studied
// in Nokia's m3gPick3D, m3gPick2D, m3gMeshRayIntersectInternal and
// m3gSpriteRayIntersect).
//
// The ray is carried into each candidate's local space by the inverse of the
// candidate-to-group transform; that transform is affine (Node transforms
// have a (0, 0, 0, 1) bottom row), so o + t d keeps its parameter t and the
// distances of all candidates compare directly.
#include <m3g/Group.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <m3g/Appearance.h>
#include <m3g/Camera.h>
#include <m3g/CompositingMode.h>
#include <m3g/Image2D.h>
#include <m3g/IndexBuffer.h>
#include <m3g/Mesh.h>
#include <m3g/PolygonMode.h>
#include <m3g/RayIntersection.h>
#include <m3g/Sprite3D.h>
#include <m3g/Texture2D.h>
#include <m3g/VertexArray.h>
#include <m3g/VertexBuffer.h>

#include <m3g/MorphingMesh.h>
#include <m3g/SkinnedMesh.h>

#include "Check.h"
#include "PropertyUtil.h"
#include "MathUtil.h"
#include "MeshDeformer.h"
#include "SpriteProjection.h"

namespace m3g {

namespace {

constexpr const char* kWhere = "Group::pick";

/// Inverse of an affine or projective matrix, computed in double;
/// ArithmeticException naming `what` if it is singular.
glm::mat4 inverseOrThrow(const glm::mat4& m, const char* what) {
    const glm::dmat4 d(m);
    const double det = glm::determinant(d);
    if (det == 0.0 || !std::isfinite(det))
        throw ArithmeticException(detail::str(kWhere, ": ", what, " is singular (determinant 0)"));
    const glm::mat4 inv(glm::inverse(d));
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(inv[c][r]))
                throw ArithmeticException(detail::str(kWhere, ": ", what, " is singular (inverse not finite)"));
    return inv;
}

/// False only if the ray o + t d, 0 <= t <= tMax, certainly misses the box
/// [lo, hi] (padded a little, so that hits on its faces are never lost).
bool rayMayHitBox(const glm::vec3& o, const glm::vec3& d, glm::vec3 lo, glm::vec3 hi, float tMax) {
    const glm::vec3 pad = 1e-4f * (hi - lo) + glm::vec3(1e-6f) * glm::max(glm::abs(lo), glm::abs(hi));
    lo -= pad;
    hi += pad;
    float t0 = 0.0f, t1 = tMax;
    for (int c = 0; c < 3; ++c) {
        if (d[c] == 0.0f) {
            if (o[c] < lo[c] || o[c] > hi[c]) return false;
            continue;
        }
        const float inv = 1.0f / d[c];
        float a = (lo[c] - o[c]) * inv, b = (hi[c] - o[c]) * inv;
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
        if (t0 > t1) return false;
    }
    return true;
}

/// Extra state of the camera variant.
struct CameraRay {
    glm::mat4 projection{1.0f};
    glm::mat4 groupToCamera{1.0f};
    float ndcX = 0, ndcY = 0;
    float nearZ = 0, farZ = 0;  // camera-space z at distance 0 and 1
};

struct Hit {
    Node* node = nullptr;
    float t = std::numeric_limits<float>::infinity();
    int submesh = 0;
    std::array<float, kMaxTextureUnits> s{}, tc{};
    glm::vec3 normal{0, 0, 1};
};

/// Alpha (0..255) of pixel (x, y) of `image`; 255 for formats without alpha.
int texelAlpha(const Image2D& image, int x, int y) {
    const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(image.getWidth()) +
                          static_cast<std::size_t>(x);
    const auto px = image.pixels();
    switch (image.getFormat()) {
    case Image2D::ALPHA: return px[i];
    case Image2D::LUMINANCE_ALPHA: return px[i * 2 + 1];
    case Image2D::RGBA: return px[i * 4 + 3];
    default: return 255;
    }
}

/// One traversal of a pick: candidates in child order, depth first.
class Picker {
public:
    Picker(int scope, const glm::vec3& origin, const glm::vec3& direction, const CameraRay* camera)
        : scope_(scope), origin_(origin), direction_(direction), camera_(camera) {}

    void run(Group& root) {
        if (!root.isPickingEnabled()) return;
        struct Item {
            Node* node;
            glm::mat4 toGroup;
        };
        std::vector<Item> stack;
        std::vector<Node*> kids;
        auto pushChildren = [&](const Node& parent, const glm::mat4& parentToGroup) {
            kids.clear();
            parent.collectChildren(kids);
            // Reverse, so that children are visited in order (ties: first wins).
            for (auto it = kids.rbegin(); it != kids.rend(); ++it)
                stack.push_back({*it, parentToGroup * detail::toGlm((*it)->compositeTransform())});
        };
        pushChildren(root, glm::mat4(1.0f));
        while (!stack.empty()) {
            const Item item = stack.back();
            stack.pop_back();
            Node& node = *item.node;
            if (!node.isPickingEnabled()) continue;  // hierarchical: the subtree is out
            if (auto* mesh = dynamic_cast<Mesh*>(&node)) intersectMesh(*mesh, item.toGroup);
            else if (auto* sprite = dynamic_cast<Sprite3D*>(&node)) intersectSprite(*sprite, item.toGroup);
            pushChildren(node, item.toGroup);
        }
    }

    const Hit& hit() const noexcept { return hit_; }

private:
    void intersectMesh(Mesh& mesh, const glm::mat4& toGroup);
    void intersectSprite(Sprite3D& sprite, const glm::mat4& toGroup);
    void recordMeshHit(Mesh& mesh, int submesh, float t, const int idx[3], float b1, float b2);

    int scope_;
    glm::vec3 origin_, direction_;
    const CameraRay* camera_;
    Hit hit_;

    // Per mesh: positions (scale and bias applied) and the deformer state.
    detail::MeshDeformer deformer_;
    bool deformed_ = false;
    std::vector<float> scratch_;
    const float* positions_ = nullptr;
};

void Picker::intersectMesh(Mesh& mesh, const glm::mat4& toGroup) {
    if ((mesh.getScope() & scope_) == 0) return;
    const VertexBuffer& vb = *mesh.vertexBuffer();
    const VertexArray* pos = vb.positions();
    if (!pos)
        throw IllegalStateException(detail::str(kWhere, ": a ", mesh.getClassName(), " (userID ", mesh.getUserID(),
                                                ") has a VertexBuffer without positions"));
    const int vertexCount = vb.getVertexCount();
    bool anyAppearance = false;
    for (int i = 0; i < mesh.getSubmeshCount(); ++i) {
        if (!mesh.appearance(i)) continue;
        anyAppearance = true;
        const int maxIndex = mesh.indexBuffer(i)->maxIndex();
        if (maxIndex >= vertexCount)
            throw IllegalStateException(detail::str(kWhere, ": submesh ", i, " of a ", mesh.getClassName(),
                                                    " (userID ", mesh.getUserID(), ") uses vertex index ", maxIndex,
                                                    ", out of range [0, ", vertexCount, ")"));
    }
    if (!anyAppearance) return;

    const glm::mat4 toMesh = inverseOrThrow(toGroup, "the transform from a picked Mesh to the group");
    const glm::vec4 p0 = toMesh * glm::vec4(origin_, 1.0f);
    const glm::vec4 p1 = toMesh * glm::vec4(origin_ + direction_, 1.0f);
    const glm::vec3 o = glm::vec3(p0) / p0.w;
    const glm::vec3 d = glm::vec3(p1) / p1.w - o;

    // Positions in mesh space: deformed, or the VertexArray with scale and bias.
    try {
        // update() reports a change, not whether the mesh deforms.
        deformer_.update(mesh);
        deformed_ = dynamic_cast<const SkinnedMesh*>(&mesh) != nullptr || dynamic_cast<const MorphingMesh*>(&mesh) != nullptr;
    } catch (const IllegalStateException& e) {
        throw IllegalStateException(detail::str(kWhere, ": ", e.what()));
    } catch (const ArithmeticException& e) {
        throw ArithmeticException(detail::str(kWhere, ": ", e.what()));
    }
    if (deformed_) {
        positions_ = deformer_.vertices().positions.data();
    } else {
        scratch_.resize(static_cast<std::size_t>(vertexCount) * 3);
        pos->getFloats(0, vertexCount, scratch_);
        const float scale = vb.positionScale();
        const auto& bias = vb.positionBias();
        for (std::size_t i = 0; i < scratch_.size(); i += 3)
            for (int c = 0; c < 3; ++c) scratch_[i + c] = scale * scratch_[i + c] + bias[c];
        positions_ = scratch_.data();
    }
    // Deformed vertices may come in an order of their own (a SkinnedMesh's,
    // DeformedVertices::order): mesh vertex i is at its slot.
    const detail::DeformedVertices* def = deformed_ ? &deformer_.vertices() : nullptr;
    auto vertex = [&](int i) {
        const std::size_t at = def ? def->slotOf(static_cast<std::uint32_t>(i)) : static_cast<std::size_t>(i);
        return glm::vec3(positions_[at * 3], positions_[at * 3 + 1], positions_[at * 3 + 2]);
    };

    // Skip the triangles when the ray misses the vertices' bounding box (or
    // meets it only beyond the closest hit so far).
    glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
    for (int i = 0; i < vertexCount; ++i) {
        const glm::vec3 v = vertex(i);
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    if (!rayMayHitBox(o, d, lo, hi, hit_.t)) return;

    const float dd = glm::dot(d, d);
    constexpr float kParallel = 1e-14f;  // (det / max|det|)^2 below this: ray in the plane or sliver
    for (int sub = 0; sub < mesh.getSubmeshCount(); ++sub) {
        const Appearance* app = mesh.appearance(sub);
        if (!app) continue;
        // Which apparent orientation may be hit: det > 0 means the triangle is
        // counter-clockwise as seen from the ray origin.
        bool ccwOk = true, cwOk = false;  // default: CULL_BACK, WINDING_CCW
        if (const Ref<PolygonMode> pm = app->getPolygonMode()) {
            const bool ccwIsFront = pm->getWinding() == PolygonMode::WINDING_CCW;
            switch (pm->getCulling()) {
            case PolygonMode::CULL_NONE: ccwOk = cwOk = true; break;
            case PolygonMode::CULL_FRONT: ccwOk = !ccwIsFront; cwOk = ccwIsFront; break;
            default: ccwOk = ccwIsFront; cwOk = !ccwIsFront; break;
            }
        }
        const std::span<const int> idx = mesh.indexBuffer(sub)->triangleIndices();
        for (std::size_t k = 0; k + 2 < idx.size(); k += 3) {
            const int tri[3] = {idx[k], idx[k + 1], idx[k + 2]};
            if (tri[0] == tri[1] || tri[0] == tri[2] || tri[1] == tri[2]) continue;  // degenerate
            const glm::vec3 v0 = vertex(tri[0]);
            const glm::vec3 e1 = vertex(tri[1]) - v0;
            const glm::vec3 e2 = vertex(tri[2]) - v0;
            // Moller-Trumbore.
            const glm::vec3 pvec = glm::cross(d, e2);
            const float det = glm::dot(e1, pvec);
            if (det > 0.0f ? !ccwOk : !cwOk) continue;
            if (det * det <= kParallel * dd * glm::dot(e1, e1) * glm::dot(e2, e2)) continue;
            const float inv = 1.0f / det;
            const glm::vec3 tvec = o - v0;
            const float u = glm::dot(tvec, pvec) * inv;
            if (u < 0.0f || u > 1.0f) continue;
            const glm::vec3 qvec = glm::cross(tvec, e1);
            const float v = glm::dot(d, qvec) * inv;
            if (v < 0.0f || u + v > 1.0f) continue;
            const float t = glm::dot(e2, qvec) * inv;
            if (!(t > 0.0f) || t >= hit_.t) continue;
            recordMeshHit(mesh, sub, t, tri, u, v);
        }
    }
}

void Picker::recordMeshHit(Mesh& mesh, int submesh, float t, const int idx[3], float b1, float b2) {
    const float w[3] = {1.0f - b1 - b2, b1, b2};
    const VertexBuffer& vb = *mesh.vertexBuffer();
    const Appearance& app = *mesh.appearance(submesh);
    hit_.node = &mesh;
    hit_.t = t;
    hit_.submesh = submesh;

    // Normal: deformed, or the VertexArray's integers mapped as GL maps
    // normalised signed integers ((2c + 1) / (2^bits - 1)).
    hit_.normal = glm::vec3(0, 0, 1);
    const detail::DeformedVertices* def = deformed_ ? &deformer_.vertices() : nullptr;
    if (def && !def->normals.empty()) {
        glm::vec3 n(0.0f);
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c)
                n[c] += w[k] * def->normals[std::size_t{def->slotOf(static_cast<std::uint32_t>(idx[k]))} * 3 + c];
        hit_.normal = n;
    } else if (const VertexArray* normals = vb.normals(); normals && !def) {
        const int size = normals->getComponentType();
        glm::vec3 n(0.0f);
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) n[c] += w[k] * detail::normalComponent(normals->value(idx[k], c), size);
        hit_.normal = n;
    }

    // Texture coordinates: scale * raw + bias (raw morphed for a
    // MorphingMesh), interpolated, then the texture's matrix and 1/q.
    const int units = getLimits().numTextureUnits;
    for (int u = 0; u < kMaxTextureUnits; ++u) {
        hit_.s[u] = hit_.tc[u] = 0.0f;
        if (u >= units) continue;
        const VertexArray* tex = vb.texCoords(u);
        if (!tex) continue;
        const int comps = tex->getComponentCount();
        const bool morphed = def && !def->texCoords[u].empty();
        glm::vec4 str(0.0f, 0.0f, 0.0f, 1.0f);
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < comps; ++c) {
                const float raw = morphed ? def->texCoords[u][std::size_t{def->slotOf(static_cast<std::uint32_t>(idx[k]))} * comps + c]
                                          : static_cast<float>(tex->value(idx[k], c));
                str[c] += w[k] * raw;
            }
        const float scale = vb.texCoordScale(u);
        const auto& bias = vb.texCoordBias(u);
        for (int c = 0; c < comps; ++c) str[c] = scale * str[c] + bias[c];
        if (const Ref<Texture2D> texture = app.getTexture(u)) {
            str = detail::toGlm(texture->compositeTransform()) * str;
            str /= str.w;
        }
        hit_.s[u] = str.x;
        hit_.tc[u] = str.y;
    }
}

void Picker::intersectSprite(Sprite3D& sprite, const glm::mat4& toGroup) {
    // Only the camera variant hits sprites, and only scaled ones (Nokia).
    if (!camera_ || !sprite.isScaled() || (sprite.getScope() & scope_) == 0) return;
    const Ref<Appearance> app = sprite.getAppearance();
    if (!app) return;
    const detail::SpriteRect r = detail::projectSprite(sprite, detail::fromGlm(camera_->groupToCamera * toGroup),
                                                       detail::fromGlm(camera_->projection), 256, 256);
    if (!(r.clipW > 0.0f) || !(r.x0 < r.x1) || !(r.y0 < r.y1)) return;
    const float x = camera_->ndcX, y = camera_->ndcY;
    if (x < r.x0 || x > r.x1 || y < r.y0 || y > r.y1) return;
    // Distance: where the sprite's depth lies between the ray's ends.
    const float span = camera_->farZ - camera_->nearZ;
    if (span == 0.0f) return;
    const float distance = (-r.eyeDepth - camera_->nearZ) / span;
    if (!(distance > 0.0f) || distance >= hit_.t) return;

    const float fx = (x - r.x0) / (r.x1 - r.x0);
    const float fy = (r.y1 - y) / (r.y1 - r.y0);
    const float s = r.s0 + fx * (r.s1 - r.s0);
    const float t = r.t0 + fy * (r.t1 - r.t0);

    // Alpha test on the texel under the point (kept inside crop ∩ image).
    const Image2D& image = *sprite.getImage();
    const float w = static_cast<float>(image.getWidth()), h = static_cast<float>(image.getHeight());
    const int colLo = static_cast<int>(std::lround(std::min(r.s0, r.s1) * w));
    const int colHi = static_cast<int>(std::lround(std::max(r.s0, r.s1) * w)) - 1;
    const int rowLo = static_cast<int>(std::lround(std::min(r.t0, r.t1) * h));
    const int rowHi = static_cast<int>(std::lround(std::max(r.t0, r.t1) * h)) - 1;
    const int col = std::clamp(static_cast<int>(std::floor(s * w)), colLo, colHi);
    const int row = std::clamp(static_cast<int>(std::floor(t * h)), rowLo, rowHi);
    const Ref<CompositingMode> cm = app->getCompositingMode();
    const float threshold = cm ? cm->getAlphaThreshold() : 0.0f;
    if (static_cast<float>(texelAlpha(image, col, row)) / 255.0f < threshold) return;  // the ray passes through

    hit_.node = &sprite;
    hit_.t = distance;
    hit_.submesh = 0;
    hit_.s.fill(0.0f);
    hit_.tc.fill(0.0f);
    hit_.s[0] = s;
    hit_.tc[0] = t;
    hit_.normal = glm::vec3(0, 0, 1);
}

bool finish(const Hit& hit, const glm::vec3& o, const glm::vec3& d, RayIntersection* ri) {
    if (!hit.node) return false;
    if (ri) {
        ri->setIntersected(hit.node, hit.t, hit.submesh);
        for (int u = 0; u < kMaxTextureUnits; ++u) ri->setTextureCoords(u, hit.s[u], hit.tc[u]);
        const float len = glm::length(hit.normal);
        const glm::vec3 n = len > 0.0f && std::isfinite(len) ? hit.normal / len : glm::vec3(0, 0, 1);
        ri->setNormal(n.x, n.y, n.z);
        ri->setRay(o.x, o.y, o.z, d.x, d.y, d.z);
    }
    return true;
}

}  // namespace

bool Group::pick(int scope, float ox, float oy, float oz, float dx, float dy, float dz, RayIntersection* ri) {
    if (dx == 0.0f && dy == 0.0f && dz == 0.0f)
        throw IllegalArgumentException(
            "Group::pick: ray direction (0, 0, 0) is zero; it must be a non-zero vector");
    const glm::vec3 o(ox, oy, oz), d(dx, dy, dz);
    Picker picker(scope, o, d, nullptr);
    picker.run(*this);
    return finish(picker.hit(), o, d, ri);
}

bool Group::pick(int scope, float x, float y, Camera* camera, RayIntersection* ri) {
    detail::requireNonNull(camera, kWhere, "camera");
    if (camera->root() != root())
        throw IllegalStateException("Group::pick: the camera is not in the same scene graph as this group");
    Transform projection, cameraToGroup;
    try {
        camera->getProjection(&projection);
        camera->getTransformTo(this, &cameraToGroup);  // same root: always true
    } catch (const ArithmeticException& e) {
        throw ArithmeticException(detail::str(kWhere, ": ", e.what()));
    }
    CameraRay cam;
    cam.projection = detail::toGlm(projection);
    const glm::mat4 unproject = inverseOrThrow(cam.projection, "the camera's projection matrix");
    cam.ndcX = 2.0f * x - 1.0f;
    cam.ndcY = 1.0f - 2.0f * y;
    glm::vec4 nearC = unproject * glm::vec4(cam.ndcX, cam.ndcY, -1.0f, 1.0f);
    glm::vec4 farC = unproject * glm::vec4(cam.ndcX, cam.ndcY, 1.0f, 1.0f);
    nearC /= nearC.w;
    farC /= farC.w;
    cam.nearZ = nearC.z;
    cam.farZ = farC.z;

    const glm::mat4 toGroup = detail::toGlm(cameraToGroup);
    cam.groupToCamera = inverseOrThrow(toGroup, "the transform from the camera to the group");
    const glm::vec4 nearG = toGroup * nearC;
    const glm::vec4 farG = toGroup * farC;
    const glm::vec3 o = glm::vec3(nearG) / nearG.w;
    const glm::vec3 d = glm::vec3(farG) / farG.w - o;

    Picker picker(scope, o, d, &cam);
    picker.run(*this);
    return finish(picker.hit(), o, d, ri);
}

}  // namespace m3g
