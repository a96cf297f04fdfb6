// What Object3D::animate reaches, resolved once per change of the scene
// graph instead of once per frame. Internal to m3g_scene.
//
// animate(t) applies the tracks of every object reachable from the one it is
// called on (JSR-184 1.1, Object3D.animate). Finding those objects is a walk
// of the whole graph through getReferences, and reading a track's sequence
// and controller goes through reference-counted getters: on a skinned corpus
// model that was as costly as the sampling itself. A plan records, in the
// walk's order, each object that has tracks with a controller, and per
// property its tracks' sequences and controllers as plain pointers; later
// animate() calls only sample and blend them.
//
// When it is rebuilt: a process-wide generation counter is bumped by every
// change of an object's references or tracks (Object3D::referencesChanged:
// add/removeAnimationTrack, AnimationTrack::setController, Group::addChild
// and removeChild, World::setActiveCamera and setBackground,
// Mesh::setAppearance, Sprite3D::setAppearance, Appearance::setMaterial,
// setFog and setTexture), when the reference actually changes and only if
// that object was ever reached by a plan's walk: an object no plan reached
// cannot change what a plan reaches. A plan is used only while the counter
// still has the value it was built at. Replacing an Image2D, a VertexArray,
// a CompositingMode or a PolygonMode does not bump it: those classes have no
// animatable property and no references, so they never change what a plan
// records (a game that swaps a sprite's image every frame keeps its plan).
// What a plan does not record is read live at every animate(): controller
// weights, speeds, positions and active intervals, keyframes, durations,
// valid ranges, repeat modes. None of that can change what is reachable. (A
// track keeps its sequence's sampling view, but only while the sequence's
// revision is the one it was built at.)
#pragma once

#include <cstdint>
#include <vector>

#include "KeyframeSampler.h"

namespace m3g {
class Object3D;
class KeyframeSequence;
class AnimationController;
}  // namespace m3g

namespace m3g::detail {

class AnimationPlan {
public:
    /// True if no object that any plan reached has changed its references
    /// or tracks since this plan was built.
    bool current() const noexcept;

    /// Walks everything reachable from `root` through getReferences (each
    /// object once, depth first in getReferences order; animation tracks
    /// lead only to a sequence and a controller, which have no tracks of
    /// their own, and are not followed), marks each object reached, and
    /// records the animated ones. Keeps its storage: rebuilding a plan of
    /// the same size does not allocate.
    void build(Object3D& root);

    /// Samples, blends and applies the recorded tracks at `worldTime`, as
    /// JSR-184 1.1, Object3D.animate specifies; returns the validity interval
    /// (AnimationPlan.cpp says how it is computed). Throws
    /// IllegalStateException for a sequence that cannot be sampled, when a
    /// track that uses it is active.
    int apply(int worldTime);

    /// Makes every plan stale (called by Object3D::referencesChanged).
    static void invalidateAll() noexcept;

private:
    // An animated object and its range of properties.
    struct Target {
        Object3D* object;
        std::uint32_t firstProperty, endProperty;
    };
    // One animated property of a target and its range of tracks, in the
    // order the object holds them (the blend adds them in that order).
    struct Property {
        int property;
        int components;
        std::uint32_t firstTrack, endTrack;
    };
    // A track with a controller (tracks without one contribute nothing
    // until setController, which makes the plan stale).
    struct Track {
        const KeyframeSequence* sequence;
        const AnimationController* controller;
        int segment;  // keyframe segment of the last sample: the next one's first guess
        // The sequence as last sampled (validated, with its kept controls,
        // arcs and tangents), while its revision is `revision`: every
        // setter of the sequence bumps it, so one compare per sample stands
        // for the validation and cache checks. kNotPrepared: not yet.
        std::uint64_t revision;
        KeyframeView view;
        // The one value the view samples to at every time (constantValue),
        // else null: apply() copies it once the validity is settled at 0.
        const float* constant;
        std::uint32_t sampleOffset;  // its sample in samples_
        float weight;                // apply()'s first pass: > 0 when it contributes this time
        const float* value;          // apply()'s first pass: its sample, or `constant` read in place
    };
    static constexpr std::uint64_t kNotPrepared = ~std::uint64_t{0};

    std::vector<Target> targets_;
    std::vector<Property> properties_;
    std::vector<Track> tracks_;
    std::vector<float> sum_;      // the widest property's components
    std::vector<float> samples_;  // every track's sample (its property's components)
    std::vector<SquadSample> squads_;  // apply()'s SQUAD samples, computed after the others
    std::uint64_t generation_ = 0;     // 0: never built
};

}  // namespace m3g::detail
