// javax.microedition.m3g.Group (JSR-184 1.1, Group).
#pragma once

#include <m3g/Export.h>

#include <vector>

#include <m3g/Node.h>

namespace m3g {

class M3G_API Group : public Node {
public:
    Group();
    ~Group() override;

    /// NPE if null; IAE if `child` is this group, a World, an ancestor of this
    /// group, or already has a different parent. Re-adding a child is a no-op.
    void addChild(Node* child);
    /// Ignores null and non-children; IAE if removing `child` would cut a bone
    /// from the SkinnedMesh that uses it.
    void removeChild(Node* child);
    int getChildCount() const noexcept { return static_cast<int>(children_.size()); }
    /// IOOBE unless 0 <= index < getChildCount().
    Ref<Node> getChild(int index) const;
    /// Child `index` without range check or reference count (engine use).
    Node* childAt(int index) const noexcept { return children_[static_cast<std::size_t>(index)].get(); }

    /// Picks along the ray o + t d (this group's coordinates), JSR-184
    /// 1.1, Group.pick. Candidates are the Meshes (MorphingMesh and
    /// SkinnedMesh on their deformed vertices) below this group, reached through nodes whose
    /// picking is enabled (this group included), with getScope() & scope != 0;
    /// submeshes with a null Appearance are skipped, PolygonMode culling and
    /// winding are honoured (CULL_NONE: both sides; no PolygonMode: CULL_BACK,
    /// WINDING_CCW), degenerate triangles are ignored. Sprites are never hit.
    /// The closest hit with t > 0 wins; its distance is t (in units of |d|).
    /// Returns true on a hit and then fills `ri` if non-null (node, distance,
    /// submesh, per-unit S/T after scale, bias and the Texture2D transform, the
    /// interpolated unit normal in the mesh's coordinates, the ray); `ri` is
    /// untouched on a miss. IAE if d is zero; ISE if a candidate mesh has no
    /// vertex positions or an index past its vertex count; ArithmeticException
    /// if a candidate's transform to this group is singular.
    bool pick(int scope, float ox, float oy, float oz, float dx, float dy, float dz, RayIntersection* ri);
    /// Picks through `camera` at (x, y) in normalised viewport coordinates
    /// ((0, 0) top left, (1, 1) bottom right; values outside are allowed),
    /// JSR-184 1.1, Group.pick: the ray runs from the near plane (distance 0) to the
    /// far plane (distance 1) through NDC (2x - 1, 1 - 2y) and is reported in
    /// this group's coordinates. Meshes as for the ray variant; scaled
    /// Sprite3Ds (with an Appearance) are hit as their screen rectangle
    /// (detail::projectSprite), except where the texel's alpha is below the
    /// CompositingMode's alpha threshold; unscaled sprites are never hit. A
    /// sprite hit reports submesh 0, unit 0 S/T in [0, 1] over the image
    /// (t = 0 at the top), other units 0, normal (0, 0, 1). NPE if camera is
    /// null; ISE if camera and this group are not in the same scene graph;
    /// ArithmeticException if the projection (or a transform) is singular;
    /// otherwise as the ray variant.
    bool pick(int scope, float x, float y, Camera* camera, RayIntersection* ri);

    const char* getClassName() const noexcept override { return "Group"; }
    void collectChildren(std::vector<Node*>& out) const override;

protected:
    Group(const Group& other);  // copies no children; duplicateImpl copies them
    /// Order: children.
    void collectReferences(std::vector<Object3D*>& out) const override;
    Object3D* duplicateImpl(DuplicateMap& map) const override;
    /// Duplicates the children of `source` into this group.
    void duplicateChildrenFrom(const Group& source, DuplicateMap& map);

private:
    std::vector<Ref<Node>> children_;
};

}  // namespace m3g
