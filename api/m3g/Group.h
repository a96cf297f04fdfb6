// javax.microedition.m3g.Group (spec digest §4.4, §5.13).
#pragma once

#include <vector>

#include <m3g/Node.h>

namespace m3g {

class Group : public Node {
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
