#include <m3g/RayIntersection.h>

#include "Check.h"

namespace m3g {

RayIntersection::RayIntersection() = default;

float RayIntersection::getTextureS(int index) const {
    detail::requireIndex(index, getLimits().numTextureUnits, "RayIntersection::getTextureS", "index");
    return s_[index];
}

float RayIntersection::getTextureT(int index) const {
    detail::requireIndex(index, getLimits().numTextureUnits, "RayIntersection::getTextureT", "index");
    return t_[index];
}

void RayIntersection::getRay(std::span<float> ray) const {
    detail::requireArray(ray, 6, "RayIntersection::getRay", "ray");
    for (int i = 0; i < 6; ++i) ray[i] = ray_[i];
}

void RayIntersection::setIntersected(Node* node, float distance, int submesh) noexcept {
    intersected_ = node;
    distance_ = distance;
    submesh_ = submesh;
}

void RayIntersection::setTextureCoords(int index, float s, float t) noexcept {
    if (index < 0 || index >= kMaxTextureUnits) return;
    s_[index] = s;
    t_[index] = t;
}

void RayIntersection::setNormal(float x, float y, float z) noexcept { normal_ = {x, y, z}; }

void RayIntersection::setRay(float ox, float oy, float oz, float dx, float dy, float dz) noexcept {
    ray_ = {ox, oy, oz, dx, dy, dz};
}

}  // namespace m3g
