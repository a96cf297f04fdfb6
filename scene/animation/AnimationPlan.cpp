// Building and applying an animation plan (AnimationPlan.h).
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
#include "AnimationPlan.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <span>

#include <m3g/AnimationController.h>
#include <m3g/AnimationTrack.h>
#include <m3g/KeyframeSequence.h>
#include <m3g/Object3D.h>

#include "KeyframeSampler.h"

namespace m3g::detail {

namespace {

constexpr double kForever = 0x7FFFFFFF;

// Bumped whenever an object some plan reached changes its references or
// tracks. Starts at 1 so that a plan's 0 means "never built". Relaxed
// atomics suffice: a graph is used by one thread at a time
// (docs/threading.md), so a change and the animate() that must see it are
// ordered by that thread or by the hand-over between threads; another
// thread's bump only makes a plan rebuild once more than needed.
std::atomic<std::uint64_t> gGeneration{1};

/// A set of object pointers (open addressing, linear probing) whose storage
/// is kept from one use to the next.
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

/// The walk's working storage, shared by the plans built on one thread.
struct WalkScratch {
    PointerSet seen;
    std::vector<Object3D*> stack, refs;
    std::size_t lastReachable = 0;
    bool busy = false;
};

thread_local WalkScratch tlsWalk;

const AnimationTrack& asTrack(const Ref<Object3D>& t) { return static_cast<const AnimationTrack&>(*t); }

// World milliseconds for which a sample stays valid, given how far it stays
// valid in sequence time in each direction and the controller speed.
double worldValidity(const SampleValidity& v, float speed) {
    if (speed == 0.0f) return kForever;
    const double seq = speed > 0.0f ? v.forward : v.backward;
    if (std::isinf(seq)) return kForever;
    return std::floor(seq / std::fabs(double(speed)));
}

}  // namespace

void AnimationPlan::invalidateAll() noexcept { gGeneration.fetch_add(1, std::memory_order_relaxed); }

bool AnimationPlan::current() const noexcept { return generation_ == gGeneration.load(std::memory_order_relaxed); }

void AnimationPlan::build(Object3D& root) {
    // Read first: a change made while walking (by another thread, on
    // another graph) leaves this plan stale rather than wrongly current.
    const std::uint64_t generation = gGeneration.load(std::memory_order_relaxed);
    generation_ = 0;
    targets_.clear();
    properties_.clear();
    tracks_.clear();
    std::size_t widest = 0, sampleFloats = 0;

    WalkScratch local;  // only if a walk is re-entered (not expected)
    WalkScratch& s = tlsWalk.busy ? local : tlsWalk;
    struct Busy {
        WalkScratch& s;
        explicit Busy(WalkScratch& x) : s(x) { s.busy = true; }
        ~Busy() { s.busy = false; }
    } busy(s);

    s.seen.reset(s.lastReachable);
    s.stack.clear();
    s.stack.push_back(&root);
    while (!s.stack.empty()) {
        Object3D* o = s.stack.back();
        s.stack.pop_back();
        if (!s.seen.insert(o)) continue;
        o->inAnimationPlan_ = true;

        const std::vector<Ref<Object3D>>& tracks = o->tracks_;  // sorted by property
        const auto firstProperty = static_cast<std::uint32_t>(properties_.size());
        for (std::size_t i = 0; i < tracks.size();) {
            const int property = asTrack(tracks[i]).getTargetProperty();
            const auto firstTrack = static_cast<std::uint32_t>(tracks_.size());
            int components = 0;
            for (; i < tracks.size() && asTrack(tracks[i]).getTargetProperty() == property; ++i) {
                tracks[i]->inAnimationPlan_ = true;  // its setController makes this plan stale
                const AnimationTrack& track = asTrack(tracks[i]);
                // The getters' references are dropped at once: the track
                // holds both for as long as this plan is current.
                const KeyframeSequence* sequence = track.getKeyframeSequence().get();
                components = sequence->getComponentCount();  // the same for every track on a property
                if (const AnimationController* c = track.getController().get()) {
                    tracks_.push_back(
                        {sequence, c, 0, kNotPrepared, {}, nullptr, static_cast<std::uint32_t>(sampleFloats), 0.0f, nullptr});
                    sampleFloats += std::size_t(components);
                }
            }
            if (tracks_.size() > firstTrack) {
                properties_.push_back(
                    {property, components, firstTrack, static_cast<std::uint32_t>(tracks_.size())});
                widest = std::max(widest, std::size_t(components));
            }
        }
        if (properties_.size() > firstProperty)
            targets_.push_back({o, firstProperty, static_cast<std::uint32_t>(properties_.size())});

        s.refs.clear();
        o->collectReferences(s.refs);
        for (auto it = s.refs.rbegin(); it != s.refs.rend(); ++it) s.stack.push_back(*it);
    }
    s.lastReachable = s.seen.size();
    if (sum_.size() < widest) sum_.resize(widest);
    if (samples_.size() < sampleFloats) samples_.resize(sampleFloats);
    squads_.reserve(tracks_.size());  // at most one deferred sample a track: apply() never allocates
    generation_ = generation;
}

int AnimationPlan::apply(int worldTime) {
    // Two passes: every track is sampled first (SQUAD samples together at
    // the end of it), then each property blended and applied. The samples
    // of different tracks do not depend on one another (no animatable
    // property is read by sampling: controllers and sequences have none),
    // so with nothing between them the core overlaps their arithmetic (a
    // SQUAD sample is a long chain of dependent float operations) instead of
    // waiting for each, then for the setter.
    double validity = kForever;
    squads_.clear();
    for (Track& track : tracks_) {
        track.weight = 0.0f;
        const AnimationController& c = *track.controller;
        const int start = c.getActiveIntervalStart(), stop = c.getActiveIntervalEnd();
        if (!c.isActive(worldTime)) {
            if (worldTime < start) validity = std::min(validity, double(start) - double(worldTime));
            continue;
        }
        const float weight = c.getWeight();
        if (!(weight > 0.0f)) continue;

        const KeyframeSequence& seq = *track.sequence;
        if (track.revision != seq.getRevision()) {
            track.view = preparedViewOf(seq);  // throws for a sequence that cannot be sampled
            track.revision = seq.getRevision();
            track.constant = constantValue(track.view);
        }
        track.weight = weight;
        float* const sample = samples_.data() + track.sampleOffset;
        track.value = sample;
        // With the validity settled at 0, a constant track's sample is all
        // there is to know: the value it would sample, read in place.
        if (track.constant && !(validity > 0.0)) {
            track.value = track.constant;
            continue;
        }
        const SampleValidity sv = sampleKeyframesDeferringSquad(
            track.view, double(c.getPosition(worldTime)), std::span<float>(sample, std::size_t(track.view.components)),
            &track.segment, squads_);
        // Every term is >= 0: once it is 0 the minimum is settled.
        if (validity > 0.0) {
            validity = std::min(validity, worldValidity(sv, c.getSpeed()));
            if (start != stop) validity = std::min(validity, double(stop) - double(worldTime));
        }
    }
    // The SQUAD samples, interleaved (sampleSquads).
    sampleSquads(squads_);
    for (const Target& target : targets_) {
        for (std::uint32_t p = target.firstProperty; p < target.endProperty; ++p) {
            const Property& property = properties_[p];
            const std::size_t components = std::size_t(property.components);
            float* const sum = sum_.data();
            // The first contributing track's sample weighted (0 + w s is w
            // s), later ones added weighted, in the object's track order.
            // A lone track of weight 1 (the usual property) is applied from
            // its sample as it is: the sum would be a copy of it.
            const float* value = nullptr;
            for (std::uint32_t t = property.firstTrack; t < property.endTrack; ++t) {
                const Track& track = tracks_[t];
                const float weight = track.weight;
                if (!(weight > 0.0f)) continue;
                const float* sample = track.value;
                if (!value) {
                    if (weight != 1.0f) {
                        for (std::size_t k = 0; k < components; ++k) sum[k] = sample[k] * weight;
                        value = sum;
                    } else {
                        value = sample;
                    }
                } else {
                    if (value != sum) {
                        for (std::size_t k = 0; k < components; ++k) sum[k] = value[k];
                        value = sum;
                    }
                    for (std::size_t k = 0; k < components; ++k) sum[k] += weight * sample[k];
                }
            }
            if (value) target.object->updateProperty(property.property, std::span<const float>(value, components));
        }
    }
    return static_cast<int>(std::clamp(validity, 0.0, kForever));
}

}  // namespace m3g::detail
