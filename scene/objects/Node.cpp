#include <m3g/Node.h>

#include <algorithm>
#include <cmath>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtx/quaternion.hpp>

#include <m3g/AnimationTrack.h>

#include "Check.h"
#include "MathUtil.h"

namespace m3g {

Node::Node() = default;

Node::Node(const Node& other)
    : Transformable(other),
      parent_(nullptr),
      alphaFactor_(other.alphaFactor_),
      renderingEnabled_(other.renderingEnabled_),
      pickingEnabled_(other.pickingEnabled_),
      scope_(other.scope_),
      zTarget_(other.zTarget_),
      yTarget_(other.yTarget_),
      zRef_(other.zRef_),
      yRef_(other.yRef_) {}

Node::~Node() = default;

const Node* Node::root() const noexcept {
    const Node* n = this;
    while (n->parent_) n = n->parent_;
    return n;
}

bool Node::isDescendantOf(const Node* ancestor) const noexcept {
    for (const Node* n = this; n; n = n->parent_)
        if (n == ancestor) return true;
    return false;
}

Transform Node::toRootTransform() const noexcept {
    Transform t = compositeTransform();
    for (const Node* n = parent_; n; n = n->parent_) t = n->compositeTransform() * t;
    return t;
}

void Node::collectChildren(std::vector<Node*>&) const {}

bool Node::getTransformTo(const Node* target, Transform* transform) const {
    detail::requireNonNull(target, "Node::getTransformTo", "target");
    detail::requireNonNull(transform, "Node::getTransformTo", "transform");
    if (root() != target->root()) return false;
    // Through the nearest common ancestor A: this->A, inverse(target->A).
    const Node* common = this;
    while (!target->isDescendantOf(common)) common = common->parent_;
    Transform up;  // this -> common
    for (const Node* n = this; n != common; n = n->parent_) up = n->compositeTransform() * up;
    if (common == target) {
        // The target is an ancestor (a bone to its SkinnedMesh, a node to
        // its World): no inverse (a double-precision 4x4 inversion of the
        // identity was most of such a call).
        *transform = up;
        return true;
    }
    Transform down;  // target -> common
    for (const Node* n = target; n != common; n = n->parent_) down = n->compositeTransform() * down;
    try {
        down.invert();
    } catch (const ArithmeticException&) {
        throw ArithmeticException("Node::getTransformTo: the transform from the target to the common ancestor is singular");
    }
    *transform = down * up;
    return true;
}

void Node::setAlignment(Node* zRef, int zTarget, Node* yRef, int yTarget) {
    const char* where = "Node::setAlignment";
    detail::requireEnum(zTarget, {NONE, ORIGIN, X_AXIS, Y_AXIS, Z_AXIS}, where, "zTarget");
    detail::requireEnum(yTarget, {NONE, ORIGIN, X_AXIS, Y_AXIS, Z_AXIS}, where, "yTarget");
    if (zRef == this || yRef == this)
        throw IllegalArgumentException("Node::setAlignment: a node cannot be its own alignment reference");
    if (zRef == yRef && zTarget == yTarget && zTarget != NONE)
        throw IllegalArgumentException(detail::str(
            "Node::setAlignment: zRef and yRef are the same node with the same target ", zTarget,
            " (the two axes would coincide)"));
    zTarget_ = zTarget;
    yTarget_ = yTarget;
    zRef_ = zTarget == NONE ? nullptr : zRef;
    yRef_ = yTarget == NONE ? nullptr : yRef;
    touch();
}

Ref<Node> Node::getAlignmentReference(int axis) const {
    detail::requireEnum(axis, {Y_AXIS, Z_AXIS}, "Node::getAlignmentReference", "axis");
    return axis == Z_AXIS ? zRef_.get() : yRef_.get();
}

int Node::getAlignmentTarget(int axis) const {
    detail::requireEnum(axis, {Y_AXIS, Z_AXIS}, "Node::getAlignmentTarget", "axis");
    return axis == Z_AXIS ? zTarget_ : yTarget_;
}

namespace {

// The target vector of one alignment axis, in the parent space of `node`.
glm::vec3 alignmentVector(const Node& node, const Node& ref, int target) {
    Transform toParent;
    ref.getTransformTo(node.parentNode(), &toParent);
    if (target == Node::ORIGIN) {
        float t[3];
        node.getTranslation(t);
        return glm::vec3(toParent.at(0, 3) - t[0], toParent.at(1, 3) - t[1], toParent.at(2, 3) - t[2]);
    }
    const int c = target - Node::X_AXIS;  // column of the axis
    return glm::vec3(toParent.at(0, c), toParent.at(1, c), toParent.at(2, c));
}

const Node* resolveReference(const Node& node, const WeakRef<Node>& ref, const Node* argument, const char* axis) {
    if (ref.expired())
        throw IllegalStateException(detail::str("Node::align: the ", axis,
                                                " alignment reference no longer exists (references are weak)"));
    const Node* r = ref.get() ? ref.get() : argument;
    if (!r)
        throw IllegalStateException(detail::str("Node::align: the ", axis,
                                                " alignment reference is null and align() was given null"));
    if (r->isDescendantOf(&node))
        throw IllegalStateException(detail::str("Node::align: the ", axis,
                                                " alignment reference is the aligned node or one of its descendants"));
    if (r->root() != node.root())
        throw IllegalStateException(
            detail::str("Node::align: the ", axis, " alignment reference is not in the same scene graph"));
    return r;
}

}  // namespace

void Node::align(Node* reference) {
    if (reference && reference->root() != root())
        throw IllegalArgumentException("Node::align: reference is not in the same scene graph as this node");
    // Top-down so that each node sees its ancestors already aligned.
    std::vector<Node*> stack{this};
    std::vector<Node*> kids;
    while (!stack.empty()) {
        Node* n = stack.back();
        stack.pop_back();
        if (n->zTarget_ != NONE || n->yTarget_ != NONE) {
            glm::quat q(1, 0, 0, 0);
            bool haveZ = false;
            if (n->zTarget_ != NONE) {
                const Node* r = resolveReference(*n, n->zRef_, reference, "Z");
                glm::vec3 v = alignmentVector(*n, *r, n->zTarget_);
                if (glm::dot(v, v) > 1e-12f) {
                    q = glm::rotation(glm::vec3(0, 0, 1), glm::normalize(v));
                    haveZ = true;
                } else {
                    const auto& cur = n->orientationQuat();
                    q = glm::quat(cur[3], cur[0], cur[1], cur[2]);
                    haveZ = true;
                }
            }
            if (n->yTarget_ != NONE) {
                const Node* r = resolveReference(*n, n->yRef_, reference, "Y");
                glm::vec3 v = alignmentVector(*n, *r, n->yTarget_);
                if (haveZ) {
                    const glm::vec3 local = glm::inverse(q) * v;  // in the Z-aligned frame
                    const float xy2 = local.x * local.x + local.y * local.y;
                    if (xy2 >= 1e-5f) {
                        const float angle = std::atan2(-local.x, local.y);
                        q = q * glm::angleAxis(angle, glm::vec3(0, 0, 1));
                    }
                } else if (glm::dot(v, v) > 1e-12f) {
                    q = glm::rotation(glm::vec3(0, 1, 0), glm::normalize(v));
                } else {
                    const auto& cur = n->orientationQuat();
                    q = glm::quat(cur[3], cur[0], cur[1], cur[2]);
                }
            }
            n->setOrientationQuat(q.x, q.y, q.z, q.w);
        }
        kids.clear();
        n->collectChildren(kids);
        for (auto it = kids.rbegin(); it != kids.rend(); ++it) stack.push_back(*it);
    }
}

void Node::setAlphaFactor(float alpha) {
    detail::requireRange(alpha, 0.0f, 1.0f, "Node::setAlphaFactor", "alpha");
    alphaFactor_ = alpha;
    touch();
}

void Node::setRenderingEnable(bool enable) noexcept {
    renderingEnabled_ = enable;
    touch();
}

void Node::setPickingEnable(bool enable) noexcept {
    pickingEnabled_ = enable;
    touch();
}

void Node::setScope(int scope) noexcept {
    scope_ = scope;
    touch();
}

void Node::addBoneOwner(const Node* mesh) {
    if (std::find(boneOwners_.begin(), boneOwners_.end(), mesh) == boneOwners_.end()) boneOwners_.push_back(mesh);
}

void Node::removeBoneOwner(const Node* mesh) noexcept {
    boneOwners_.erase(std::remove(boneOwners_.begin(), boneOwners_.end(), mesh), boneOwners_.end());
}

void Node::collectReferences(std::vector<Object3D*>& out) const {
    // Alignment references are deliberately not listed: they may point up or
    // across the scene graph (often at an ancestor or the camera), and
    // animate(), find() and duplicate() follow getReferences downwards only.
    Transformable::collectReferences(out);
}

void Node::remapReferences(const DuplicateMap& map) {
    Transformable::remapReferences(map);
    if (auto it = map.find(zRef_.get()); zRef_.get() && it != map.end()) zRef_ = static_cast<Node*>(it->second);
    if (auto it = map.find(yRef_.get()); yRef_.get() && it != map.end()) yRef_ = static_cast<Node*>(it->second);
}

bool Node::isAnimatable(int property) const noexcept {
    return property == AnimationTrack::ALPHA || property == AnimationTrack::PICKABILITY ||
           property == AnimationTrack::VISIBILITY || Transformable::isAnimatable(property);
}

void Node::updateProperty(int property, std::span<const float> v) {
    switch (property) {
    case AnimationTrack::ALPHA:
        alphaFactor_ = std::clamp(v[0], 0.0f, 1.0f);
        touch();
        return;
    case AnimationTrack::PICKABILITY:
        pickingEnabled_ = v[0] >= 0.5f;
        touch();
        return;
    case AnimationTrack::VISIBILITY:
        renderingEnabled_ = v[0] >= 0.5f;
        touch();
        return;
    default:
        Transformable::updateProperty(property, v);
    }
}

}  // namespace m3g
