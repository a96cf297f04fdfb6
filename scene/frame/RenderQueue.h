// The collect step (docs/architecture.md): from a World, a node or an
// immediate-mode submesh to a sorted list of draws, as plain data with no
// Vulkan in it. JSR-184 1.1, Graphics3D.render and Node (traversal, scope, lights, order).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <m3g/Graphics3D.h>
#include <m3g/Transform.h>

namespace m3g {
class Appearance;
class Camera;
class IndexBuffer;
class Light;
class Mesh;
class Node;
class Sprite3D;
class VertexBuffer;
}  // namespace m3g

namespace m3g::detail {

/// Calls `f(child)` for each child node of `node`: Group children and a
/// SkinnedMesh's skeleton (as Node::collectChildren, without allocating).
template <class F>
void forEachChild(const Node& node, F&& f);

/// A light in eye space, ready for the shader (JSR-184 1.1, Light).
struct RenderLight {
    int mode = 0;                          ///< Light::AMBIENT ... SPOT
    std::array<float, 3> color{};          ///< intensity x colour
    std::array<float, 4> position{};       ///< eye space; w = 0: direction towards the light
    std::array<float, 3> spotDirection{};  ///< unit, eye space
    float spotCosCutoff = -1.0f;
    std::array<float, 3> attenuation{1.0f, 0.0f, 0.0f};
    float spotExponent = 0.0f;
    int scope = -1;
};

/// Appends every Light under `root` whose path from `root` is
/// rendering-enabled, with its light-to-world transform (`rootToWorld`
/// includes root's own transform). JSR-184 1.1, Graphics3D.render(World): its lights.
void collectLights(const Node& root, const Transform& rootToWorld, std::vector<Graphics3D::LightEntry>& out);

struct RenderItem {
    enum class Kind : std::uint8_t { Submesh, Sprite };
    Kind kind = Kind::Submesh;
    const Node* node = nullptr;  ///< the Mesh or Sprite3D; null in immediate mode
    VertexBuffer* vertices = nullptr;
    IndexBuffer* indices = nullptr;
    Appearance* appearance = nullptr;
    int submesh = 0;
    Transform modelView;         ///< node -> eye
    float alphaFactor = 1.0f;    ///< product over the path (JSR-184 1.1, Node.setAlphaFactor)
    std::array<std::uint8_t, 8> lights{};  ///< indices into RenderQueue::lights
    int lightCount = 0;
    std::uint64_t sortKey = 0;   ///< layer, then opaque before blended, then order
};

struct RenderQueue {
    Transform projection;        ///< the camera's (OpenGL conventions)
    int cameraScope = -1;
    int maxLights = 8;
    std::vector<RenderLight> lights;
    std::vector<RenderItem> items;

    void reset(const Camera& camera, int maxLightsPerDraw);
    /// Adds a light given its light -> eye transform.
    void addLight(const Light& light, const Transform& lightToEye);
    /// Adds the draws of `node` and its descendants; `nodeToEye` already
    /// includes node's own transform (or not, for render(Node, Transform)).
    /// Honours rendering enable, scope against the camera, alpha factors.
    void collectNode(const Node& node, const Transform& nodeToEye, float alphaFactor = 1.0f);
    /// An immediate-mode submesh (render(VertexBuffer, IndexBuffer, ...)).
    void addSubmesh(VertexBuffer* vb, IndexBuffer* ib, Appearance* app, const Transform& modelView, int scope,
                    const Node* node = nullptr, int submesh = 0, float alphaFactor = 1.0f);
    /// Orders items: layer ascending, then opaque before blended, then
    /// collection order (stable): JSR-184 1.1, Graphics3D.render orders by
    /// layer; opaque before blended as Nokia's M3G implementation draws.
    void sort();

private:
    void selectLights(RenderItem& item, int scope) const;
    /// The sort key of the next item drawn with `app`.
    std::uint64_t nextSortKey(const Appearance& app);
    std::uint32_t order_ = 0;
};

}  // namespace m3g::detail

#include <m3g/Group.h>
#include <m3g/SkinnedMesh.h>

template <class F>
void m3g::detail::forEachChild(const Node& node, F&& f) {
    if (const auto* group = dynamic_cast<const Group*>(&node)) {
        for (int i = 0; i < group->getChildCount(); ++i) f(*group->childAt(i));
    } else if (const auto* skinned = dynamic_cast<const SkinnedMesh*>(&node)) {
        if (Group* skeleton = skinned->getSkeleton().get()) f(static_cast<Node&>(*skeleton));
    }
}
