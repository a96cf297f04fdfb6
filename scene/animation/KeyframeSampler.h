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
    /// doubles per key, x y z w each, in valid-range order) as
    /// squadControls() computes them; empty: computed per sample.
    std::span<const double> squad = {};
};

/// View of a sequence (no copy; valid while the sequence is unchanged).
KeyframeView viewOf(const KeyframeSequence& sequence) noexcept;

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
/// into `out` (8 doubles per key): what sampleKeyframes would compute for
/// each segment, once per change of the sequence instead of per sample.
void squadControls(const KeyframeView& k, std::vector<double>& out);

/// Samples a valid view (see keyframeProblem) at sequence time `time` into
/// `out` (at least k.components floats). Quaternion results (SLERP, SQUAD)
/// are unit length; SLERP does not flip to the shortest arc (Nokia).
SampleValidity sampleKeyframes(const KeyframeView& k, double time, std::span<float> out);

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
