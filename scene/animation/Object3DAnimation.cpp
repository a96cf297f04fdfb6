// Object3D's animation services: the track list and animate() (JSR-184 1.1,
// Object3D.animate, KeyframeSequence and AnimationController). animate()
// resolves what it reaches into an AnimationPlan, which samples and blends.
#include <m3g/Object3D.h>

#include <algorithm>
#include <memory>

#include <m3g/AnimationController.h>
#include <m3g/AnimationTrack.h>
#include <m3g/KeyframeSequence.h>

#include "AnimationPlan.h"
#include "Check.h"

namespace m3g {

namespace {

const AnimationTrack& asTrack(const Ref<Object3D>& t) { return static_cast<const AnimationTrack&>(*t); }

int componentCount(const AnimationTrack& t) { return t.getKeyframeSequence()->getComponentCount(); }

}  // namespace

void Object3D::addAnimationTrack(AnimationTrack* animationTrack) {
    const char* where = "Object3D::addAnimationTrack";
    detail::requireNonNull(animationTrack, where, "animationTrack");
    const int property = animationTrack->getTargetProperty();
    if (!isAnimatable(property))
        throw IllegalArgumentException(
            detail::str(where, ": property ", property, " cannot be animated in class ", getClassName()));
    const int comps = componentCount(*animationTrack);
    for (const auto& t : tracks_) {
        if (t.get() == animationTrack)
            throw IllegalArgumentException(detail::str(where, ": the track is already attached to this object"));
        if (asTrack(t).getTargetProperty() == property && componentCount(asTrack(t)) != comps)
            throw IllegalArgumentException(
                detail::str(where, ": a track with ", componentCount(asTrack(t)), " components already animates property ",
                            property, "; this one has ", comps));
    }
    // Sorted by property; a new track goes after those on the same property.
    const auto pos = std::upper_bound(tracks_.begin(), tracks_.end(), property,
                                      [](int p, const Ref<Object3D>& t) { return p < asTrack(t).getTargetProperty(); });
    tracks_.insert(pos, Ref<Object3D>(animationTrack));
    referencesChanged();
    touch();
}

Ref<AnimationTrack> Object3D::getAnimationTrack(int index) const {
    detail::requireIndex(index, static_cast<long long>(tracks_.size()), "Object3D::getAnimationTrack", "index");
    return static_cast<AnimationTrack*>(tracks_[std::size_t(index)].get());
}

void Object3D::removeAnimationTrack(AnimationTrack* animationTrack) {
    if (!animationTrack) return;
    const auto it = std::find_if(tracks_.begin(), tracks_.end(),
                                 [&](const Ref<Object3D>& t) { return t.get() == animationTrack; });
    if (it == tracks_.end()) return;
    tracks_.erase(it);
    referencesChanged();
    touch();
}

int Object3D::animate(int worldTime) {
    detail::AnimationPlan* plan = animationPlan_.get();
    if (!plan) {
        animationPlan_ = std::make_unique<detail::AnimationPlan>();
        plan = animationPlan_.get();
    }
    if (!plan->current()) plan->build(*this);
    return plan->apply(worldTime);
}

}  // namespace m3g
