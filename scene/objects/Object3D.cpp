#include <m3g/Object3D.h>

#include <atomic>
#include <memory>

#include "AnimationPlan.h"
#include "Check.h"

namespace m3g {

namespace {
std::uint64_t nextObjectId() noexcept {
    static std::atomic<std::uint64_t> counter{0};
    return ++counter;
}
}  // namespace

Object3D::Object3D() : objectId_(nextObjectId()) {}

Object3D::Object3D(const Object3D& other)
    : RefCounted(other),
      objectId_(nextObjectId()),
      userID_(other.userID_),
      userObject_(other.userObject_),
      tracks_(other.tracks_) {}

Object3D::~Object3D() = default;

void Object3D::referencesChanged() noexcept {
    if (inAnimationPlan_) detail::AnimationPlan::invalidateAll();
}

void Object3D::collectReferences(std::vector<Object3D*>&) const {}

void Object3D::remapReferences(const DuplicateMap&) {}

bool Object3D::isAnimatable(int) const noexcept { return false; }

void Object3D::updateProperty(int property, std::span<const float>) {
    throw IllegalArgumentException(
        detail::str(getClassName(), "::updateProperty: property ", property, " is not animatable in this class"));
}

void Object3D::directReferences(std::vector<Object3D*>& out) const {
    for (const auto& t : tracks_) out.push_back(t.get());
    collectReferences(out);
}

int Object3D::getReferences(std::span<Ref<Object3D>> references) const {
    std::vector<Object3D*> refs;
    refs.reserve(tracks_.size() + 4);
    directReferences(refs);
    if (references.data() != nullptr) {
        if (references.size() < refs.size())
            throw IllegalArgumentException(detail::str("Object3D::getReferences: array length ", references.size(),
                                                       " is shorter than the ", refs.size(), " references"));
        for (std::size_t i = 0; i < refs.size(); ++i) references[i] = refs[i];
    }
    return static_cast<int>(refs.size());
}

Ref<Object3D> Object3D::find(int userID) const {
    Ref<Object3D> found;
    forEachReachable([&](Object3D& o) {
        if (o.userID_ != userID) return true;
        found = &o;
        return false;
    });
    return found;
}

const UserParameters* Object3D::getUserParameters() const noexcept {
    if (auto* p = std::any_cast<std::shared_ptr<const UserParameters>>(&userObject_)) return p->get();
    if (auto* p = std::any_cast<std::shared_ptr<UserParameters>>(&userObject_)) return p->get();
    if (auto* p = std::any_cast<UserParameters>(&userObject_)) return p;
    return nullptr;
}

Object3D* Object3D::duplicateInto(const Object3D* source, DuplicateMap& map) {
    Object3D* copy = source->duplicateImpl(map);
    map[source] = copy;
    return copy;
}

Ref<Object3D> Object3D::duplicate() const {
    DuplicateMap map;
    Ref<Object3D> copy(duplicateInto(this, map));
    for (auto& [original, dup] : map) dup->remapReferences(map);
    return copy;
}

}  // namespace m3g
