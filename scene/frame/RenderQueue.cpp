#include "RenderQueue.h"

#include <algorithm>
#include <cmath>

#include <m3g/Appearance.h>
#include <m3g/Camera.h>
#include <m3g/CompositingMode.h>
#include <m3g/Light.h>
#include <m3g/Mesh.h>
#include <m3g/Sprite3D.h>

namespace m3g::detail {

namespace {

std::array<float, 4> apply(const Transform& t, float x, float y, float z, float w) {
    std::array<float, 4> out{};
    for (int r = 0; r < 4; ++r) out[r] = t.at(r, 0) * x + t.at(r, 1) * y + t.at(r, 2) * z + t.at(r, 3) * w;
    return out;
}

bool isBlended(const Appearance* app) {
    const CompositingMode* cm = app ? app->getCompositingMode().get() : nullptr;
    return cm && cm->getBlending() != CompositingMode::REPLACE;
}

}  // namespace

void RenderQueue::reset(const Camera& camera, int maxLightsPerDraw) {
    camera.getProjection(&projection);
    cameraScope = camera.getScope();
    maxLights = std::clamp(maxLightsPerDraw, 0, 8);
    lights.clear();
    items.clear();
    order_ = 0;
}

void RenderQueue::addLight(const Light& light, const Transform& lightToEye) {
    RenderLight l;
    l.mode = light.getMode();
    const auto rgb = static_cast<std::uint32_t>(light.getColor());
    const float intensity = light.getIntensity();
    l.color = {intensity * static_cast<float>((rgb >> 16) & 0xFF) / 255.0f,
               intensity * static_cast<float>((rgb >> 8) & 0xFF) / 255.0f,
               intensity * static_cast<float>(rgb & 0xFF) / 255.0f};
    const auto origin = apply(lightToEye, 0, 0, 0, 1);
    auto dir = apply(lightToEye, 0, 0, -1, 0);  // the light shines along its -Z (JSR-184 1.1, Light)
    const float len = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    if (len > 0.0f)
        for (int i = 0; i < 3; ++i) dir[i] /= len;
    if (l.mode == Light::DIRECTIONAL) {
        l.position = {-dir[0], -dir[1], -dir[2], 0.0f};
    } else {
        const float w = origin[3] != 0.0f ? origin[3] : 1.0f;
        l.position = {origin[0] / w, origin[1] / w, origin[2] / w, 1.0f};
    }
    l.spotDirection = {dir[0], dir[1], dir[2]};
    if (l.mode == Light::SPOT) {
        l.spotCosCutoff = std::cos(light.getSpotAngle() * 3.14159265358979f / 180.0f);
        l.spotExponent = light.getSpotExponent();
    }
    if (l.mode == Light::OMNI || l.mode == Light::SPOT)
        l.attenuation = {light.getConstantAttenuation(), light.getLinearAttenuation(), light.getQuadraticAttenuation()};
    l.scope = light.getScope();
    lights.push_back(l);
}

void collectLights(const Node& root, const Transform& rootToWorld, std::vector<Graphics3D::LightEntry>& out) {
    if (!root.isRenderingEnabled()) return;
    if (const auto* light = dynamic_cast<const Light*>(&root)) out.push_back({const_cast<Light*>(light), rootToWorld});
    forEachChild(root, [&](Node& child) { collectLights(child, rootToWorld * child.compositeTransform(), out); });
}

void RenderQueue::collectNode(const Node& node, const Transform& nodeToEye, float alphaFactor) {
    if (!node.isRenderingEnabled()) return;
    const float alpha = alphaFactor * node.getAlphaFactor();
    const bool inScope = (node.getScope() & cameraScope) != 0;
    if (const auto* mesh = dynamic_cast<const Mesh*>(&node)) {
        if (inScope)
            for (int i = 0; i < mesh->getSubmeshCount(); ++i)
                if (Appearance* app = mesh->appearance(i))
                    addSubmesh(mesh->vertexBuffer(), mesh->indexBuffer(i), app, nodeToEye, node.getScope(), mesh, i,
                               alpha);
    } else if (const auto* sprite = dynamic_cast<const Sprite3D*>(&node)) {
        Appearance* app = sprite->getAppearance().get();
        if (inScope && app) {
            RenderItem item;
            item.kind = RenderItem::Kind::Sprite;
            item.node = sprite;
            item.appearance = app;
            item.modelView = nodeToEye;
            item.alphaFactor = alpha;
            item.sortKey = nextSortKey(*app);
            items.push_back(item);
        }
    }
    // Children (Group) and a SkinnedMesh's skeleton render as part of the subtree.
    forEachChild(node, [&](Node& child) { collectNode(child, nodeToEye * child.compositeTransform(), alpha); });
}

std::uint64_t RenderQueue::nextSortKey(const Appearance& app) {
    // Layer (-63..63, offset to stay positive), then blended after opaque,
    // then the order of collection.
    const auto layer = static_cast<std::uint64_t>(app.getLayer() + 64);
    return (layer << 40) | (static_cast<std::uint64_t>(isBlended(&app)) << 32) | order_++;
}

void RenderQueue::selectLights(RenderItem& item, int scope) const {
    // The first maxLights lights whose scope meets the mesh's, in collection
    // order (Nokia m3gSelectGLLights).
    item.lightCount = 0;
    for (std::size_t i = 0; i < lights.size() && item.lightCount < maxLights; ++i)
        if ((lights[i].scope & scope) != 0) item.lights[item.lightCount++] = static_cast<std::uint8_t>(i);
}

void RenderQueue::addSubmesh(VertexBuffer* vb, IndexBuffer* ib, Appearance* app, const Transform& modelView, int scope,
                             const Node* node, int submesh, float alphaFactor) {
    RenderItem item;
    item.kind = RenderItem::Kind::Submesh;
    item.node = node;
    item.vertices = vb;
    item.indices = ib;
    item.appearance = app;
    item.submesh = submesh;
    item.modelView = modelView;
    item.alphaFactor = alphaFactor;
    if (lights.size() > 255) lights.resize(255);
    selectLights(item, scope);
    item.sortKey = nextSortKey(*app);
    items.push_back(item);
}

void RenderQueue::sort() {
    std::sort(items.begin(), items.end(), [](const RenderItem& a, const RenderItem& b) { return a.sortKey < b.sortKey; });
}

}  // namespace m3g::detail
