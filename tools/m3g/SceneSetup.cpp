#include "SceneSetup.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace m3gcli {

using namespace m3g;

namespace {

constexpr double kPi = 3.14159265358979323846;

bool enabledPath(const Node* node) {
    for (; node; node = node->parentNode())
        if (!node->isRenderingEnabled()) return false;
    return true;
}

void boundsOf(World& world, Node& node, float* lo, float* hi, bool& any) {
    if (auto* mesh = dynamic_cast<Mesh*>(&node); mesh && enabledPath(mesh)) {
        VertexBuffer* vb = mesh->vertexBuffer();
        float scaleBias[4] = {1, 0, 0, 0};
        Ref<VertexArray> positions = vb ? vb->getPositions(scaleBias) : nullptr;
        Transform toWorld;
        if (positions && mesh->getTransformTo(&world, &toWorld)) {
            for (int v = 0; v < positions->getVertexCount(); ++v) {
                float p[4] = {scaleBias[0] * static_cast<float>(positions->value(v, 0)) + scaleBias[1],
                              scaleBias[0] * static_cast<float>(positions->value(v, 1)) + scaleBias[2],
                              scaleBias[0] * static_cast<float>(positions->value(v, 2)) + scaleBias[3], 1.0f};
                toWorld.transform(p);
                for (int k = 0; k < 3; ++k) {
                    const float c = p[3] != 0.0f ? p[k] / p[3] : p[k];
                    lo[k] = std::min(lo[k], c);
                    hi[k] = std::max(hi[k], c);
                }
                any = true;
            }
        }
    }
    // Group children only: a SkinnedMesh's skeleton is not traversed.
    if (auto* group = dynamic_cast<Group*>(&node))
        for (int i = 0; i < group->getChildCount(); ++i) boundsOf(world, *group->getChild(i), lo, hi, any);
}

bool contributes(const Node& node) {
    if (auto* light = dynamic_cast<const Light*>(&node))
        if (enabledPath(light) && (light->getColor() & 0xFFFFFF) != 0 && light->getIntensity() != 0.0f) return true;
    if (auto* group = dynamic_cast<const Group*>(&node))
        for (int i = 0; i < group->getChildCount(); ++i)
            if (contributes(*group->getChild(i))) return true;
    if (auto* skinned = dynamic_cast<const SkinnedMesh*>(&node))
        if (skinned->getSkeleton() && contributes(*skinned->getSkeleton())) return true;
    return false;
}

}  // namespace

void sceneBounds(World& world, std::array<float, 3>& center, float& radius) {
    float lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
        lo[k] = std::numeric_limits<float>::infinity();
        hi[k] = -std::numeric_limits<float>::infinity();
    }
    bool any = false;
    boundsOf(world, world, lo, hi, any);
    if (!any) {
        center = {0, 0, 0};
        radius = 1.0f;
        return;
    }
    double r2 = 0.0;
    for (int k = 0; k < 3; ++k) {
        center[k] = (lo[k] + hi[k]) * 0.5f;
        r2 += static_cast<double>(hi[k] - lo[k]) * (hi[k] - lo[k]);
    }
    radius = static_cast<float>(std::sqrt(r2) * 0.5);
    if (radius == 0.0f) radius = 1.0f;
}

bool hasContributingLight(const World& world) { return contributes(world); }

PreparedScene prepareScene(const LoadResult& loaded, int width, int height) {
    PreparedScene s;
    for (const auto& o : loaded.objects)
        if (auto* w = dynamic_cast<World*>(o.get())) {
            s.world = w;
            break;
        }
    if (!s.world) {
        s.world = new World();
        s.createdWorld = true;
        for (const auto& r : loaded.roots)
            if (auto* node = dynamic_cast<Node*>(r.get()); node && !node->getParent()) s.world->addChild(node);
        s.notes.push_back("no World in the file: rendering a new World holding the " +
                          std::to_string(s.world->getChildCount()) + " root node(s)");
    }
    World& world = *s.world;
    Ref<Camera> active = world.getActiveCamera();
    if (active && active->root() != &world) {
        if (!active->getParent()) {
            world.addChild(active.get());
            s.cameraFixup = true;
            s.notes.push_back("the active camera is not in the World: added it to the World (camera fix-up)");
        }
    }
    if (!active) {
        s.autoFramed = true;
        sceneBounds(world, s.center, s.radius);
        const float r = s.radius;
        Ref<Camera> camera(new Camera());
        const float aspect = static_cast<float>(width) / static_cast<float>(height);
        camera->setPerspective(60.0f, aspect, 0.1f * r, 10.0f * r);
        const double h = width >= height ? 30.0 * kPi / 180.0 : std::atan(aspect * std::tan(30.0 * kPi / 180.0));
        const double d = r / std::sin(h);
        const double a20 = 20.0 * kPi / 180.0;
        camera->setTranslation(static_cast<float>(s.center[0]), static_cast<float>(s.center[1] + d * std::sin(a20)),
                               static_cast<float>(s.center[2] + d * std::cos(a20)));
        camera->setOrientation(-20.0f, 1.0f, 0.0f, 0.0f);
        world.addChild(camera.get());
        world.setActiveCamera(camera.get());
        s.notes.push_back("no active camera: auto-framed (centre " + std::to_string(s.center[0]) + ", " +
                          std::to_string(s.center[1]) + ", " + std::to_string(s.center[2]) + "; radius " +
                          std::to_string(r) + ")");
        if (!hasContributingLight(world)) {
            Ref<Light> sun(new Light());
            sun->setMode(Light::DIRECTIONAL);
            sun->setOrientation(54.7356103f, -1.0f, -1.0f, 0.0f);
            world.addChild(sun.get());
            Ref<Light> ambient(new Light());
            ambient->setMode(Light::AMBIENT);
            ambient->setIntensity(0.3f);
            world.addChild(ambient.get());
            s.lightsAdded = true;
            s.notes.push_back("no light contributes: added a directional and an ambient light");
        }
        if (!world.getBackground()) {
            Ref<Background> bg(new Background());
            bg->setColor(static_cast<int>(0xFF404040u));
            world.setBackground(bg.get());
            s.backgroundAdded = true;
        }
    }
    return s;
}

int longestSequence(const LoadResult& loaded) {
    int longest = 0;
    for (const auto& o : loaded.objects)
        if (const auto* k = dynamic_cast<const KeyframeSequence*>(o.get())) longest = std::max(longest, k->getDuration());
    return longest;
}

std::vector<Camera*> camerasInFileOrder(const LoadResult& loaded) {
    std::vector<Camera*> out;
    for (const auto& o : loaded.objects)
        if (auto* c = dynamic_cast<Camera*>(o.get())) out.push_back(c);
    return out;
}

void useCamera(PreparedScene& scene, const LoadResult& loaded, int index) {
    const std::vector<Camera*> cameras = camerasInFileOrder(loaded);
    if (index < 0 || static_cast<std::size_t>(index) >= cameras.size())
        throw std::out_of_range("camera index " + std::to_string(index) + " out of range: the file has " +
                                std::to_string(cameras.size()) + " Camera(s)");
    Camera* camera = cameras[static_cast<std::size_t>(index)];
    World& world = *scene.world;
    if (camera->root() != &world) {
        if (camera->getParent())
            throw std::invalid_argument("Camera " + std::to_string(index) +
                                        " belongs to a scene graph other than the rendered World");
        world.addChild(camera);
        scene.cameraFixup = true;
        scene.notes.push_back("Camera " + std::to_string(index) + " is not in the World: added it to the World");
    }
    world.setActiveCamera(camera);
    scene.notes.push_back("rendering through Camera " + std::to_string(index) + " of " + std::to_string(cameras.size()));
}

}  // namespace m3gcli
