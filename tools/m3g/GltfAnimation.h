// M3G keyframe animation as glTF animation samplers (glTF 2.0 §3.11).
//
// A track's value at world time w is its sequence sampled at sequence time
// s(w) = refSequenceTime + speed * (w - refWorldTime) (its controller:
// JSR-184 1.1, AnimationController). glTF keys are placed at world time w / 1000 seconds over
// [0, clipEnd]: at every keyframe (repeated for LOOP sequences) and at the
// ends of the window, so that both agree at every time the clip covers:
//   STEP, LINEAR          -> STEP, LINEAR (exact)
//   SLERP                 -> LINEAR (glTF slerps; segments longer than half a
//                            turn are split, Nokia does not take the short arc)
//   SPLINE                -> CUBICSPLINE, tangents in value per second (exact);
//                            on ORIENTATION resampled like SQUAD
//   SQUAD                 -> LINEAR, resampled (kResamplesPerSegment per key segment)
// Part of the `m3g export` tool.
#pragma once

#include <string>
#include <vector>

namespace m3g {
class KeyframeSequence;
}

namespace m3gcli::gltf {

/// Intermediate samples per keyframe segment when a curve glTF cannot
/// express is resampled (SQUAD, SPLINE on orientations).
inline constexpr int kResamplesPerSegment = 8;
/// Most keys one channel may get (LOOP sequences repeated over a long clip).
inline constexpr std::size_t kMaxChannelKeys = 100000;

/// An AnimationController's mapping from world time to sequence time.
struct TimeMapping {
    double refWorldTime = 0.0;     ///< ms
    double refSequenceTime = 0.0;  ///< sequence time units
    double speed = 1.0;
    /// Sequence time at world time `w` (ms).
    double sequenceTime(double w) const { return refSequenceTime + speed * (w - refWorldTime); }
    /// World time (ms) at sequence time `s`; speed must not be 0.
    double worldTime(double s) const { return refWorldTime + (s - refSequenceTime) / speed; }
};

/// What the glTF sampler of one channel holds.
struct SamplerKeys {
    std::string interpolation;  ///< "STEP", "LINEAR" or "CUBICSPLINE"
    int components = 0;         ///< floats per output element
    std::vector<float> times;   ///< seconds, strictly increasing, >= 0
    /// STEP/LINEAR: times.size() * components. CUBICSPLINE: per key the
    /// in-tangent, the value and the out-tangent (§3.11, Appendix C).
    std::vector<float> values;
    bool capped = false;        ///< kMaxChannelKeys reached: the clip end is not covered
};

/// The world time (ms, >= 0) a sequence needs to be shown completely: the
/// last keyframe's world time (CONSTANT), one period duration / |speed|
/// (LOOP), 0 when the controller is stopped (speed 0). The clip end of an
/// animation is the largest of its channels.
double channelEnd(const m3g::KeyframeSequence& sequence, const TimeMapping& mapping);

/// Converts `sequence` played through `mapping` over world time [0, clipEnd]
/// ms. `rotation` marks an ORIENTATION track (unit quaternions, short-arc
/// glTF slerp). Throws std::invalid_argument with the reason when the
/// sequence cannot be sampled (duration unset, times decreasing).
SamplerKeys convertSequence(const m3g::KeyframeSequence& sequence, const TimeMapping& mapping, double clipEnd,
                            bool rotation);

/// Re-shapes each output element from `from` to `to` components: one value
/// repeated (uniform SCALE -> VEC3), otherwise copied and zero-padded or
/// truncated (MORPH_WEIGHTS to the morph target count).
void reshapeComponents(SamplerKeys& keys, int to);

}  // namespace m3gcli::gltf
