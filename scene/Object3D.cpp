#include <m3g/Object3D.h>

#include <atomic>
#include <unordered_set>

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

void Object3D::collectReferences(std::vector<Object3D*>&) const {}

void Object3D::remapReferences(const DuplicateMap&) {}

bool Object3D::isAnimatable(int) const noexcept { return false; }

void Object3D::updateProperty(int property, std::span<const float>) {
    throw IllegalArgumentException(
        detail::str(getClassName(), "::updateProperty: property ", property, " is not animatable in this class"));
}

int Object3D::getReferences(std::span<Ref<Object3D>> references) const {
    std::vector<Object3D*> refs;
    refs.reserve(tracks_.size() + 4);
    for (const auto& t : tracks_) refs.push_back(t.get());
    collectReferences(refs);
    if (references.data() != nullptr) {
        if (references.size() < refs.size())
            throw IllegalArgumentException(detail::str("Object3D::getReferences: array length ", references.size(),
                                                       " is shorter than the ", refs.size(), " references"));
        for (std::size_t i = 0; i < refs.size(); ++i) references[i] = refs[i];
    }
    return static_cast<int>(refs.size());
}

Ref<Object3D> Object3D::find(int userID) const {
    // Iterative depth-first search in reference order; the visited set guards
    // against shared objects and reference cycles.
    std::unordered_set<const Object3D*> visited;
    std::vector<const Object3D*> stack{this};
    std::vector<Object3D*> refs;
    while (!stack.empty()) {
        const Object3D* o = stack.back();
        stack.pop_back();
        if (!visited.insert(o).second) continue;
        if (o->userID_ == userID) return Ref<Object3D>(const_cast<Object3D*>(o));
        refs.clear();
        for (const auto& t : o->tracks_) refs.push_back(t.get());
        o->collectReferences(refs);
        for (auto it = refs.rbegin(); it != refs.rend(); ++it)
            if (!visited.count(*it)) stack.push_back(*it);
    }
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
