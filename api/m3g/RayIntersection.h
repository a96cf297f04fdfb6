// javax.microedition.m3g.RayIntersection: the result of Group::pick
// (JSR-184 1.1, RayIntersection and Group.pick).
#pragma once

#include <m3g/Export.h>

#include <array>
#include <span>

#include <m3g/Limits.h>
#include <m3g/Node.h>

namespace m3g {

class M3G_API RayIntersection {
public:
    /// No node, distance 0, submesh 0, texture coordinates 0, normal (0, 0, 1),
    /// ray origin (0, 0, 0) and direction (0, 0, 1).
    RayIntersection();

    /// The picked Mesh or Sprite3D, or null.
    Ref<Node> getIntersected() const noexcept { return intersected_; }
    /// Distance along the ray in units of the ray direction's length.
    float getDistance() const noexcept { return distance_; }
    int getSubmeshIndex() const noexcept { return submesh_; }
    /// IOOBE unless 0 <= index < numTextureUnits.
    float getTextureS(int index) const;
    float getTextureT(int index) const;
    float getNormalX() const noexcept { return normal_[0]; }
    float getNormalY() const noexcept { return normal_[1]; }
    float getNormalZ() const noexcept { return normal_[2]; }
    /// {ox, oy, oz, dx, dy, dz}; NPE if null, IAE if shorter than 6.
    void getRay(std::span<float> ray) const;

    // ---- Engine interface (used by picking) ----
    void setIntersected(Node* node, float distance, int submesh) noexcept;
    void setTextureCoords(int index, float s, float t) noexcept;
    void setNormal(float x, float y, float z) noexcept;
    void setRay(float ox, float oy, float oz, float dx, float dy, float dz) noexcept;

private:
    Ref<Node> intersected_;
    float distance_ = 0.0f;
    int submesh_ = 0;
    std::array<float, kMaxTextureUnits> s_{}, t_{};
    std::array<float, 3> normal_{0, 0, 1};
    std::array<float, 6> ray_{0, 0, 0, 0, 0, 1};
};

}  // namespace m3g
