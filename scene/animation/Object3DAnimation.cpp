// Object3D's animation services: the track list and animate() (JSR-184 1.1,
// Object3D.animate, KeyframeSequence and AnimationController).
//
// animate() validity interval: the number of world milliseconds from
// worldTime during which every applied value is known not to change, i.e.
// animate(t') gives the same result for t' in [worldTime, worldTime + v).
// 0x7FFFFFFF when nothing is animated or every sample is constant from here
// on. It is the minimum over all contributing tracks of
//  - the sequence-time span over which the sample holds (before the first key
//    or after the last key of a CONSTANT sequence, within a STEP segment,
//    forever for a single valid key; 0 inside an interpolated segment),
//    divided by |speed| in the direction the controller moves (speed 0:
//    forever), rounded down;
//  - the time until the controller's active interval ends (start != end);
// and, for tracks whose controller is not yet active, the time until it
// becomes active. Tracks without a controller or with weight 0 only change
// through API calls and do not limit it. 0 therefore means "changes
// continuously" (or within the next millisecond).
#include <m3g/Object3D.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <m3g/AnimationController.h>
#include <m3g/AnimationTrack.h>
#include <m3g/KeyframeSequence.h>

#include "Check.h"
#include "KeyframeSampler.h"

namespace m3g {

namespace {

constexpr double kForever = 0x7FFFFFFF;

/// A set of object pointers (open addressing, linear probing) whose storage
/// is kept from one use to the next, so that a steady-state animate() does
/// not allocate.
class PointerSet {
public:
    /// Empties the set, keeping (or growing to) room for `expected` entries.
    void reset(std::size_t expected) {
        std::size_t capacity = 64;
        while (capacity < 2 * expected) capacity *= 2;
        if (slots_.size() < capacity) slots_.assign(capacity, nullptr);
        else std::fill(slots_.begin(), slots_.end(), nullptr);
        count_ = 0;
    }
    /// True if `p` was not in the set (and is now).
    bool insert(const void* p) {
        if (2 * (count_ + 1) > slots_.size()) grow();
        if (place(slots_, p)) {
            ++count_;
            return true;
        }
        return false;
    }
    std::size_t size() const noexcept { return count_; }

private:
    static bool place(std::vector<const void*>& slots, const void* p) {
        const std::size_t mask = slots.size() - 1;
        // Fibonacci hashing of the address (low bits are alignment zeros).
        std::size_t i = static_cast<std::size_t>((reinterpret_cast<std::uintptr_t>(p) >> 4) *
                                                 std::uint64_t{0x9E3779B97F4A7C15ull} >> 20) & mask;
        while (slots[i]) {
            if (slots[i] == p) return false;
            i = (i + 1) & mask;
        }
        slots[i] = p;
        return true;
    }
    void grow() {
        std::vector<const void*> bigger(std::max<std::size_t>(64, slots_.size() * 2), nullptr);
        for (const void* p : slots_)
            if (p) place(bigger, p);
        slots_.swap(bigger);
    }

    std::vector<const void*> slots_;
    std::size_t count_ = 0;
};

/// Working storage of animate(), reused by later calls on the same thread.
struct AnimateScratch {
    PointerSet seen;
    std::vector<Object3D*> stack, refs;
    std::vector<float> sum, sample;
    std::size_t lastReachable = 0;
    bool busy = false;
};

thread_local AnimateScratch tlsScratch;

const AnimationTrack& asTrack(const Ref<Object3D>& t) { return static_cast<const AnimationTrack&>(*t); }

int componentCount(const AnimationTrack& t) { return t.getKeyframeSequence()->getComponentCount(); }

// World milliseconds for which a sample stays valid, given how far it stays
// valid in sequence time in each direction and the controller speed.
double worldValidity(const detail::SampleValidity& v, float speed) {
    if (speed == 0.0f) return kForever;
    const double seq = speed > 0.0f ? v.forward : v.backward;
    if (std::isinf(seq)) return kForever;
    return std::floor(seq / std::fabs(double(speed)));
}

// Blends and applies the tracks of one object. `validity` is lowered to the
// world time for which the applied values are known not to change.
void applyTracks(Object3D& target, const std::vector<Ref<Object3D>>& tracks, int worldTime, double& validity,
                 std::vector<float>& sum, std::vector<float>& sample) {
    std::size_t i = 0;
    while (i < tracks.size()) {
        const int property = asTrack(tracks[i]).getTargetProperty();
        const int comps = componentCount(asTrack(tracks[i]));
        std::size_t end = i;
        while (end < tracks.size() && asTrack(tracks[end]).getTargetProperty() == property) ++end;

        sum.assign(std::size_t(comps), 0.0f);
        sample.assign(std::size_t(comps), 0.0f);
        double totalWeight = 0.0;
        for (std::size_t j = i; j < end; ++j) {
            const AnimationTrack& track = asTrack(tracks[j]);
            const Ref<AnimationController> c = track.getController();
            if (!c) continue;  // inactive until a controller is set
            const int start = c->getActiveIntervalStart(), stop = c->getActiveIntervalEnd();
            if (!c->isActive(worldTime)) {
                if (worldTime < start) validity = std::min(validity, double(start) - double(worldTime));
                continue;
            }
            const float weight = c->getWeight();
            if (!(weight > 0.0f)) continue;

            const Ref<KeyframeSequence> seq = track.getKeyframeSequence();
            seq->validate();
            detail::KeyframeView view = detail::viewOf(*seq);
            view.squad = seq->squadControls();  // empty unless SQUAD
            const detail::SampleValidity sv = detail::sampleKeyframes(view, double(c->getPosition(worldTime)), sample);
            validity = std::min(validity, worldValidity(sv, c->getSpeed()));
            if (start != stop) validity = std::min(validity, double(stop) - double(worldTime));

            for (int k = 0; k < comps; ++k) sum[std::size_t(k)] += weight * sample[std::size_t(k)];
            totalWeight += weight;
        }
        if (totalWeight > 0.0) target.updateProperty(property, sum);
        i = end;
    }
}

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
    touch();
}

int Object3D::animate(int worldTime) {
    // The traversal of forEachReachable (each reachable object once, depth
    // first in getReferences order) on per-thread storage kept between calls,
    // except that animation tracks are not followed: a track reaches only its
    // KeyframeSequence and AnimationController, and none of the three has an
    // animatable property, so none can carry tracks of its own.
    AnimateScratch local;  // only if animate() is re-entered (not expected)
    AnimateScratch& s = tlsScratch.busy ? local : tlsScratch;
    struct Busy {
        AnimateScratch& s;
        explicit Busy(AnimateScratch& x) : s(x) { s.busy = true; }
        ~Busy() { s.busy = false; }
    } busy(s);

    double validity = kForever;
    s.seen.reset(s.lastReachable);
    s.stack.clear();
    s.stack.push_back(this);
    while (!s.stack.empty()) {
        Object3D* o = s.stack.back();
        s.stack.pop_back();
        if (!s.seen.insert(o)) continue;
        if (!o->tracks_.empty()) applyTracks(*o, o->tracks_, worldTime, validity, s.sum, s.sample);
        s.refs.clear();
        o->collectReferences(s.refs);
        for (auto it = s.refs.rbegin(); it != s.refs.rend(); ++it) s.stack.push_back(*it);
    }
    s.lastReachable = s.seen.size();
    return static_cast<int>(std::clamp(validity, 0.0, kForever));
}

}  // namespace m3g
