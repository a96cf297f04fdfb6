// javax.microedition.m3g.Node (JSR-184 1.1, Node).
#pragma once

#include <m3g/Export.h>

#include <vector>

#include <m3g/Transformable.h>

namespace m3g {

/// A scene-graph node: rendering/picking enables, alpha factor, scope and
/// alignment. Parents hold children strongly; the parent pointer is raw.
class M3G_API Node : public Transformable {
public:
    static constexpr int NONE = 144;
    static constexpr int ORIGIN = 145;
    static constexpr int X_AXIS = 146;
    static constexpr int Y_AXIS = 147;
    static constexpr int Z_AXIS = 148;

    ~Node() override;

    /// The parent Group, or the SkinnedMesh owning this skeleton, or null.
    Ref<Node> getParent() const noexcept { return parent_; }

    /// Fills `transform` with the matrix from this node's coordinates to
    /// `target`'s and returns true; returns false (transform untouched) if the
    /// two are not in the same scene graph. NPE if either is null;
    /// ArithmeticException if a needed inverse is singular.
    bool getTransformTo(const Node* target, Transform* transform) const;

    /// Targets in {NONE, ORIGIN, X_AXIS, Y_AXIS, Z_AXIS}; null references mean
    /// "the node passed to align()". IAE on other targets, if a reference is
    /// this node, or if zRef == yRef with zTarget == yTarget != NONE. A
    /// reference whose target is NONE is discarded.
    void setAlignment(Node* zRef, int zTarget, Node* yRef, int yTarget);
    /// Applies the alignment of this node and all its descendants
    /// (JSR-184 1.1, Node.align).
    /// IAE if `reference` is in another scene graph; ISE if a reference is a
    /// descendant of the aligned node or in another scene graph, or if a null
    /// reference must be resolved and `reference` is null.
    void align(Node* reference);
    /// axis is Y_AXIS or Z_AXIS, else IAE. Null if none or if the referenced
    /// node no longer exists (references are weak, see setAlignment).
    Ref<Node> getAlignmentReference(int axis) const;
    int getAlignmentTarget(int axis) const;

    /// alpha in [0, 1], else IAE.
    void setAlphaFactor(float alpha);
    float getAlphaFactor() const noexcept { return alphaFactor_; }
    void setRenderingEnable(bool enable) noexcept;
    bool isRenderingEnabled() const noexcept { return renderingEnabled_; }
    void setPickingEnable(bool enable) noexcept;
    bool isPickingEnabled() const noexcept { return pickingEnabled_; }
    void setScope(int scope) noexcept;
    int getScope() const noexcept { return scope_; }

    // ---- Engine interface ----
    Node* parentNode() const noexcept { return parent_; }
    /// The top-most ancestor (this node if it has no parent).
    const Node* root() const noexcept;
    /// True if this node is `ancestor` or lies below it.
    bool isDescendantOf(const Node* ancestor) const noexcept;
    /// Transform from this node to the root of its graph (product of composites).
    Transform toRootTransform() const noexcept;
    /// Child nodes (Group children, SkinnedMesh skeleton); empty for leaves.
    virtual void collectChildren(std::vector<Node*>& out) const;
    /// Number of SkinnedMeshes using this node as a bone (removeChild rule).
    int boneUseCount() const noexcept { return static_cast<int>(boneOwners_.size()); }
    /// The SkinnedMeshes using this node as a bone.
    const std::vector<const Node*>& boneOwners() const noexcept { return boneOwners_; }

    bool isAnimatable(int property) const noexcept override;
    void updateProperty(int property, std::span<const float> value) override;

protected:
    Node();
    /// Copies everything but the parent (the copy is a root).
    Node(const Node& other);
    bool requiresAffineTransform() const noexcept override { return true; }
    void collectReferences(std::vector<Object3D*>& out) const override;
    void remapReferences(const DuplicateMap& map) override;

    /// Sets the parent pointer (Group::addChild, SkinnedMesh skeleton).
    void setParent(Node* parent) noexcept { parent_ = parent; }
    /// Bone bookkeeping, called by SkinnedMesh.
    void addBoneOwner(const Node* mesh);
    void removeBoneOwner(const Node* mesh) noexcept;

    friend class Group;
    friend class SkinnedMesh;

private:
    Node* parent_ = nullptr;
    float alphaFactor_ = 1.0f;
    bool renderingEnabled_ = true;
    bool pickingEnabled_ = true;
    int scope_ = -1;
    int zTarget_ = NONE;
    int yTarget_ = NONE;
    // Weak: an alignment reference to an ancestor would otherwise be a cycle.
    WeakRef<Node> zRef_;
    WeakRef<Node> yRef_;
    std::vector<const Node*> boneOwners_;  // SkinnedMeshes using this node as a bone
};

}  // namespace m3g
