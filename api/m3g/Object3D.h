// javax.microedition.m3g.Object3D: the base of every scene object
// (JSR-184 1.1, Object3D).
#pragma once

#include <m3g/Export.h>

#include <any>
#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <m3g/Exception.h>
#include <m3g/Forward.h>
#include <m3g/Ref.h>

namespace m3g {

namespace detail {
class AnimationPlan;
}

/// User parameters read from a file: parameter ID -> bytes. The Loader stores
/// a `std::shared_ptr<const UserParameters>` in the user object (the Java
/// Hashtable<Integer, byte[]>).
using UserParameters = std::map<int, std::vector<std::uint8_t>>;

class M3G_API Object3D : public RefCounted {
public:
    ~Object3D() override;

    /// Applies the animation tracks of this object and of every object
    /// reachable from it at `worldTime`; returns the validity interval in ms
    /// (0x7FFFFFFF = indefinitely). JSR-184 1.1, Object3D.animate.
    /// The objects and tracks reached are found on the first call and kept
    /// until an object reached changes its references or tracks; later calls
    /// only sample and blend, and do not allocate.
    int animate(int worldTime);

    /// A copy of this object: components are shared, node subtrees are copied,
    /// references inside a copied subtree are remapped to the copies.
    /// JSR-184 1.1, Object3D.duplicate.
    Ref<Object3D> duplicate() const;

    /// This object if its user ID matches, else the first match among the
    /// objects reachable through getReferences (depth first, in reference
    /// order), else null.
    Ref<Object3D> find(int userID) const;

    /// Number of direct references. If `references` is non-null (data() !=
    /// nullptr) it receives them; IllegalArgumentException if it is too short.
    /// Order: animation tracks first, then the class-specific references in
    /// the order each class documents.
    int getReferences(std::span<Ref<Object3D>> references = {}) const;

    void setUserID(int userID) noexcept { userID_ = userID; }
    int getUserID() const noexcept { return userID_; }

    /// Any value (Java Object). Copied by duplicate() (a shared_ptr inside
    /// stays shared, as in Java).
    void setUserObject(std::any userObject) { userObject_ = std::move(userObject); }
    const std::any& getUserObject() const noexcept { return userObject_; }

    /// NPE if null; IAE if this class cannot animate the track's property, if
    /// the track is already attached, or if an attached track on the same
    /// property has a different component count.
    void addAnimationTrack(AnimationTrack* animationTrack);
    /// IndexOutOfBoundsException unless 0 <= index < getAnimationTrackCount().
    Ref<AnimationTrack> getAnimationTrack(int index) const;
    /// Ignores null and tracks not attached.
    void removeAnimationTrack(AnimationTrack* animationTrack);
    int getAnimationTrackCount() const noexcept { return static_cast<int>(tracks_.size()); }

    // ---- Engine interface (not Java API) ----

    /// Unique for the life of the process; never reused (unlike addresses).
    std::uint64_t getObjectId() const noexcept { return objectId_; }
    /// Incremented by every change that a renderer mirror or a cache must see.
    std::uint32_t getRevision() const noexcept { return revision_; }
    /// The user parameters a file gave this object: the user object when it
    /// holds a `std::shared_ptr<const UserParameters>` (what the Loader sets),
    /// a `std::shared_ptr<UserParameters>` or a `UserParameters` value; else null.
    const UserParameters* getUserParameters() const noexcept;

    /// The class name, as in Java ("Mesh").
    virtual const char* getClassName() const noexcept = 0;

    /// True if an AnimationTrack on `property` (AnimationTrack::ALPHA...) may
    /// be attached to this class (the property table of JSR-184 1.1,
    /// AnimationTrack).
    virtual bool isAnimatable(int property) const noexcept;
    /// Writes an animated value with the setter semantics of JSR-184 1.1,
    /// Object3D.animate and AnimationTrack (clamping, renormalising,
    /// thresholds). `value` holds the blended components.
    virtual void updateProperty(int property, std::span<const float> value);

    /// Maps objects of a duplicated subtree to their copies.
    using DuplicateMap = std::unordered_map<const Object3D*, Object3D*>;

protected:
    Object3D();
    /// Copies user ID, user object and (shared) animation tracks; the copy has
    /// a new object ID and revision 0.
    Object3D(const Object3D& other);
    Object3D& operator=(const Object3D&) = delete;

    /// Appends the class-specific direct references (not animation tracks),
    /// null entries omitted. Subclasses call their base first.
    virtual void collectReferences(std::vector<Object3D*>& out) const;

    /// Creates the copy for duplicate(): `new X(*this)` plus copies of owned
    /// subtrees; must record `map[this] = copy` for nodes.
    virtual Object3D* duplicateImpl(DuplicateMap& map) const = 0;
    /// Called on every copy once the whole subtree has been copied, to point
    /// references at copies where the original target was copied too.
    virtual void remapReferences(const DuplicateMap& map);
    /// Duplicates `source` (a node of a copied subtree) and records it in `map`.
    static Object3D* duplicateInto(const Object3D* source, DuplicateMap& map);
    /// The attached tracks, as stored (each is an AnimationTrack).
    const std::vector<Ref<Object3D>>& animationTracks() const noexcept { return tracks_; }

    /// Direct references in getReferences order: animation tracks, then
    /// collectReferences.
    void directReferences(std::vector<Object3D*>& out) const;
    /// Visits this object and every object reachable through getReferences,
    /// each once, depth first in reference order, until `visit` returns false.
    /// Shared objects and reference cycles are visited a single time.
    template <class Visit>
    void forEachReachable(Visit&& visit) const;

    /// Marks the object changed (bumps the revision).
    void touch() noexcept { ++revision_; }
    /// Called by every method that changes what getReferences returns (the
    /// attached tracks, an AnimationTrack's controller, children, components)
    /// unless the references in question can only be to classes with neither
    /// animatable properties nor references of their own (Image2D,
    /// VertexArray, CompositingMode, PolygonMode): the cached animate() plans
    /// that may have reached this object are rebuilt on their next use.
    void referencesChanged() noexcept;

    friend class Group;
    friend class Node;
    friend class detail::AnimationPlan;

private:
    std::uint64_t objectId_;
    std::uint32_t revision_ = 0;
    int userID_ = 0;
    std::any userObject_;
    // Held as Object3D so this header needs no AnimationTrack definition.
    std::vector<Ref<Object3D>> tracks_;  // sorted by target property
    // What animate() called on this object reaches (created by the first
    // call; not copied by duplicate()).
    std::unique_ptr<detail::AnimationPlan> animationPlan_;
    // Set once some animate() plan has reached this object: only then can a
    // change of its references make a plan stale.
    bool inAnimationPlan_ = false;
};

template <class Visit>
void Object3D::forEachReachable(Visit&& visit) const {
    std::unordered_set<const Object3D*> seen;
    std::vector<Object3D*> stack{const_cast<Object3D*>(this)};
    std::vector<Object3D*> refs;
    while (!stack.empty()) {
        Object3D* o = stack.back();
        stack.pop_back();
        if (!seen.insert(o).second) continue;
        if (!visit(*o)) return;
        refs.clear();
        o->directReferences(refs);
        for (auto it = refs.rbegin(); it != refs.rend(); ++it)
            if (!seen.count(*it)) stack.push_back(*it);
    }
}

/// Java-style checked downcast of a Ref: null if `p` is not a T.
template <class T, class U>
Ref<T> dynamicCast(const Ref<U>& p) {
    return Ref<T>(dynamic_cast<T*>(p.get()));
}

}  // namespace m3g
