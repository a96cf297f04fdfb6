#include <m3g/World.h>

#include <m3g/Background.h>
#include <m3g/Camera.h>

#include "Check.h"

namespace m3g {

World::World() = default;
World::~World() = default;
World::World(const World& other) : Group(other), activeCamera_(other.activeCamera_), background_(other.background_) {}

void World::setActiveCamera(Camera* camera) {
    detail::requireNonNull(camera, "World::setActiveCamera", "camera");
    if (activeCamera_.get() != camera) referencesChanged();
    activeCamera_ = camera;
    touch();
}

Ref<Camera> World::getActiveCamera() const noexcept { return activeCamera_; }

void World::setBackground(Background* background) noexcept {
    if (background_.get() != background) referencesChanged();
    background_ = background;
    touch();
}

Ref<Background> World::getBackground() const noexcept { return background_; }

void World::collectReferences(std::vector<Object3D*>& out) const {
    Group::collectReferences(out);
    if (activeCamera_) out.push_back(activeCamera_.get());
    if (background_) out.push_back(background_.get());
}

Object3D* World::duplicateImpl(DuplicateMap& map) const {
    auto* w = new World(*this);
    w->duplicateChildrenFrom(*this, map);
    return w;
}

void World::remapReferences(const DuplicateMap& map) {
    Group::remapReferences(map);
    if (auto it = map.find(activeCamera_.get()); activeCamera_ && it != map.end())
        activeCamera_ = static_cast<Camera*>(it->second);
}

}  // namespace m3g
