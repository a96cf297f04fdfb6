// Keyframe sampling (JSR-184 1.1, KeyframeSequence) on plain data, so that it can be
// tested without the object model. Internal to m3g_scene.
#pragma once

#include <limits>
#include <span>
#include <string>
#include <vector>

namespace m3g {
class KeyframeSequence;
}

namespace m3g::detail {

/// The data of a KeyframeSequence needed to sample it.
struct KeyframeView {
    int interpolation;   // KeyframeSequence::LINEAR ... STEP
    int repeatMode;      // KeyframeSequence::CONSTANT or LOOP
    int duration;        // > 0 for a valid sequence
    int components;      // floats per keyframe
    int keyCount;        // keyframes in the arrays
    int first, last;     // valid range; first > last wraps
    std::span<const int> times;     // keyCount entries
    std::span<const float> values;  // keyCount * components entries
    /// SQUAD: the control quaternions A_j, B_j of each valid key j (8
    /// floats per key, x y z w each, in valid-range order) as
    /// squadControls() computes them; empty: computed per sample.
    std::span<const float> squad = {};
    /// SLERP and SQUAD: the part of each segment's SLERPs that does not
    /// depend on the time (keyframeArcs: kArcFloats floats per arc, one arc
    /// per valid key for SLERP, two for SQUAD), as
    /// KeyframeSequence::quaternionArcs() computes them; empty: computed per
    /// sample, with the same result.
    std::span<const float> arcs = {};
    /// SPLINE: the Hermite tangents of every segment (2 * components floats
    /// per valid key j: the outgoing tangent at j, then the incoming one at
    /// the next key), as splineTangents() computes them; empty: computed per
    /// sample.
    std::span<const float> tangents = {};
    /// Every interpolation but STEP: one byte per valid key j, 1 where the
    /// segment from j to the next key samples to key j's value at every
    /// time (flatSegments says when), as KeyframeSequence::flatSegments()
    /// computes them; empty: every segment interpolated.
    std::span<const unsigned char> flat = {};
    /// 1 / duration, for mapping looping time without a division (viewOf
    /// sets it); 0: divided per sample.
    double inverseDuration = 0.0;
};

/// Floats per arc in KeyframeView::arcs.
inline constexpr int kArcFloats = 8;

/// View of a sequence (no copy; valid while the sequence is unchanged).
KeyframeView viewOf(const KeyframeSequence& sequence) noexcept;

/// The view animate() samples: the sequence validated (throws
/// IllegalStateException, as KeyframeSequence::validate), with its kept SQUAD
/// controls, arcs and SPLINE tangents. Valid while the sequence is unchanged
/// (its revision the same: every setter bumps it).
KeyframeView preparedViewOf(const KeyframeSequence& sequence);

/// Empty string if the view can be sampled, else the reason: duration not
/// set, times decreasing along the valid range, last valid time > duration.
std::string keyframeProblem(const KeyframeView& k);

/// How far (in sequence time) the sampled value is guaranteed to stay the
/// same when the sequence time moves forward / backward from the sample
/// point. Infinity when it never changes in that direction, 0 when it
/// changes continuously.
struct SampleValidity {
    double forward = std::numeric_limits<double>::infinity();
    double backward = std::numeric_limits<double>::infinity();
};

/// The SQUAD control quaternions of every valid key of a valid SQUAD view,
/// into `out` (8 floats per key): what sampleKeyframes would compute for
/// each segment, once per change of the sequence instead of per sample.
/// Computed in double (logarithms and exponentials of quaternions), rounded
/// to float once.
void squadControls(const KeyframeView& k, std::vector<float>& out);

/// The arcs of every valid key of a valid SLERP or SQUAD view into `out`
/// (KeyframeView::arcs; nothing for other interpolations): for SLERP the arc
/// of the segment from key j to the next; for SQUAD that one, then the arc
/// from the control quaternion A_j to B of the next key (from k.squad, or
/// computed as squadControls would). Once per change of the sequence
/// instead of per sample: a sample then needs only a sine and a cosine per
/// SLERP it takes from here (two of the three of a SQUAD sample).
void keyframeArcs(const KeyframeView& k, std::vector<float>& out);

/// The Hermite tangents of every segment of a valid SPLINE view into `out`
/// (KeyframeView::tangents; nothing for other interpolations): the scaled
/// central differences of JSR-184 1.1, KeyframeSequence, computed in double
/// from the keys and rounded to float once per change of the sequence
/// instead of per sample (which took two divisions and eight key reads per
/// sample). Sampling with them differs from computing them per sample by
/// that rounding only: about 1e-7 of the tangent, times a Hermite weight of
/// at most 4/27.
void splineTangents(const KeyframeView& k, std::vector<float>& out);

/// The flat segments of a valid view into `out` (KeyframeView::flat, one
/// byte per valid key; nothing for STEP, which copies keys anyway): segment
/// j is flat when everything its samples read is key j's value bit for bit,
/// so that each would compute that value again. LINEAR and SLERP: key j and
/// the next equal. SPLINE: also both tangents (from k.tangents, or computed
/// as splineTangents would) exactly 0. SQUAD: also the control quaternions
/// A_j and B of the next key (k.squad, or computed) equal to key j.
/// Exported clips hold bones still between equal keys for long stretches
/// (otokka_jump2.m3g: a third of its SQUAD time, nearly all of its SPLINE
/// and LINEAR time); sampling copies the key there instead of three SLERPs
/// or a Hermite blend in double. The result is the same value (a -0
/// component may come back as +0 from the arithmetic, never from the copy).
void flatSegments(const KeyframeView& k, std::vector<unsigned char>& out);

/// Samples a valid view (see keyframeProblem) at sequence time `time` into
/// `out` (at least k.components floats). Quaternion results (SLERP, SQUAD)
/// are unit length, interpolated in float (Slerp.h); SLERP does not flip to
/// the shortest arc (Nokia).
///
/// `segment`, if not null, is a guess at the segment holding `time` (an
/// index along the valid range, as left there by the previous call) and
/// receives the segment used. The guess and the one after it are tried
/// before a binary search, so a caller whose time moves forward a little per
/// call (animate() once per frame) finds its segment in one or two
/// comparisons. Any value is safe: a wrong or stale guess (the sequence
/// changed) only costs the search, and the result is the same as without it.
SampleValidity sampleKeyframes(const KeyframeView& k, double time, std::span<float> out, int* segment = nullptr);

/// The one value every sample of a prepared view gives, or null: non-null
/// when every valid key holds the same bits and every segment is flat
/// (KeyframeView::flat: its samples copy its key, so SPLINE tangents and
/// SQUAD controls add nothing); for STEP when every valid key is the same.
/// Exported clips carry many such tracks (a bone's scale, a translation
/// that never moves). Points into the view's values.
const float* constantValue(const KeyframeView& k);

/// A SQUAD sample inside a segment of a view with kept controls and arcs,
/// not yet computed: its key, its control A_j, the two arcs (kArcFloats
/// floats each), the fraction u and where the unit quaternion goes.
struct SquadSample {
    const float* key;
    const float* keyArc;
    const float* control;
    const float* controlArc;
    float u;
    float* out;
};

/// As sampleKeyframes, except that a sample that would compute a SQUAD
/// inside a segment from the view's kept controls and arcs is left to
/// sampleSquads: its inputs are appended to `deferred` and `out` is not
/// written. Same validity, same segment.
SampleValidity sampleKeyframesDeferringSquad(const KeyframeView& k, double time, std::span<float> out, int* segment,
                                             std::vector<SquadSample>& deferred);

/// Computes SQUAD samples (sampleKeyframes' own go through here too, one
/// at a time, so deferred ones are the same bits). Four at a time in SSE
/// lanes (SquadLanes.h): a sample is one long chain of dependent float
/// operations (square roots, divisions, polynomials), and the chains of
/// four tracks side by side cost about what one did.
void sampleSquads(std::span<const SquadSample> samples) noexcept;

/// The derivative of the sampled value with respect to sequence time at
/// `time` (k.components floats into `out`) for a valid SPLINE or LINEAR
/// view: from the segment that ends at `time` when `fromLeft`, else from the
/// one that starts there (at a keyframe the incoming and outgoing Hermite
/// tangents differ, JSR-184 1.1, KeyframeSequence). 0 where the value is held (before
/// the first / after the last key of a CONSTANT sequence, one keyframe,
/// zero-length segments) and for the other interpolations. Used to convert
/// SPLINE tangents (glTF export).
void sampleKeyframeSlope(const KeyframeView& k, double time, bool fromLeft, std::span<float> out);

}  // namespace m3g::detail
