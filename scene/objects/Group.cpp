#include <m3g/Group.h>

#include <algorithm>

#include <m3g/World.h>

#include "Check.h"

namespace m3g {

Group::Group() = default;

Group::Group(const Group& other) : Node(other) {}

Group::~Group() {
    // Children may outlive this group through other references.
    for (auto& c : children_) c->setParent(nullptr);
}

void Group::addChild(Node* child) {
    detail::requireNonNull(child, "Group::addChild", "child");
    if (child == this) throw IllegalArgumentException("Group::addChild: a group cannot be its own child");
    if (dynamic_cast<World*>(child))
        throw IllegalArgumentException("Group::addChild: a World cannot be a child of another node");
    if (child->parentNode() == this) return;
    if (child->parentNode())
        throw IllegalArgumentException(detail::str("Group::addChild: the ", child->getClassName(),
                                                   " already has a parent (remove it from that first)"));
    if (isDescendantOf(child))
        throw IllegalArgumentException("Group::addChild: the child is an ancestor of this group (would form a cycle)");
    children_.emplace_back(child);
    child->setParent(this);
    referencesChanged();
    touch();
}

namespace {
// True if removing `child` would take a bone out of the subtree of the
// SkinnedMesh that uses it.
bool cutsBone(const Node* child) {
    std::vector<const Node*> stack{child};
    std::vector<Node*> kids;
    while (!stack.empty()) {
        const Node* n = stack.back();
        stack.pop_back();
        for (const Node* owner : n->boneOwners()) {
            if (!owner->isDescendantOf(child)) return true;
        }
        kids.clear();
        n->collectChildren(kids);
        stack.insert(stack.end(), kids.begin(), kids.end());
    }
    return false;
}
}  // namespace

void Group::removeChild(Node* child) {
    if (!child || child->parentNode() != this) return;
    if (cutsBone(child))
        throw IllegalArgumentException(
            "Group::removeChild: the node is or contains a bone of a SkinnedMesh above it (removing it would break the skin)");
    auto it = std::find_if(children_.begin(), children_.end(), [&](const Ref<Node>& c) { return c.get() == child; });
    Ref<Node> keep = *it;  // keep alive until the parent pointer is cleared
    children_.erase(it);
    child->setParent(nullptr);
    referencesChanged();
    touch();
}

Ref<Node> Group::getChild(int index) const {
    detail::requireIndex(index, getChildCount(), "Group::getChild", "index");
    return children_[index];
}

void Group::collectChildren(std::vector<Node*>& out) const {
    for (const auto& c : children_) out.push_back(c.get());
}

void Group::collectReferences(std::vector<Object3D*>& out) const {
    Node::collectReferences(out);
    for (const auto& c : children_) out.push_back(c.get());
}

void Group::duplicateChildrenFrom(const Group& source, DuplicateMap& map) {
    for (const auto& c : source.children_) {
        Node* copy = static_cast<Node*>(duplicateInto(c.get(), map));
        children_.emplace_back(copy);
        copy->setParent(this);
    }
}

Object3D* Group::duplicateImpl(DuplicateMap& map) const {
    auto* g = new Group(*this);
    g->duplicateChildrenFrom(*this, map);
    return g;
}

}  // namespace m3g
