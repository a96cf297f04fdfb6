// javax.microedition.m3g.KeyframeSequence (JSR-184 1.1, KeyframeSequence).
#pragma once

#include <m3g/Export.h>

#include <span>
#include <vector>

#include <m3g/Object3D.h>

namespace m3g {

/// Keyframes (time, value) with an interpolation type, a duration, a repeat
/// mode and a valid range. Sampled by the animation tracks that use it.
class M3G_API KeyframeSequence : public Object3D {
public:
    static constexpr int LINEAR = 176;
    static constexpr int SLERP = 177;
    static constexpr int SPLINE = 178;
    static constexpr int SQUAD = 179;
    static constexpr int STEP = 180;
    static constexpr int CONSTANT = 192;
    static constexpr int LOOP = 193;

    /// IAE if numKeyframes < 1, numComponents < 1, interpolation is not one
    /// of LINEAR, SLERP, SPLINE, SQUAD, STEP, or SLERP/SQUAD with
    /// numComponents != 4. Keyframes start at time 0 with value 0; duration 0
    /// (must be set before the sequence is sampled); CONSTANT; valid range
    /// [0, numKeyframes - 1].
    KeyframeSequence(int numKeyframes, int numComponents, int interpolation);
    ~KeyframeSequence() override;

    /// NPE if `value` is null; IOOBE unless 0 <= index < getKeyframeCount();
    /// IAE if time < 0 or value is shorter than getComponentCount().
    /// SLERP/SQUAD keyframes are normalised (a zero quaternion becomes the
    /// identity).
    void setKeyframe(int index, int time, std::span<const float> value);
    /// (1.1) Returns the time of keyframe `index` and copies its value into
    /// `value` unless that is null. IOOBE on the index; IAE if `value` is
    /// non-null and shorter than getComponentCount().
    int getKeyframe(int index, std::span<float> value) const;

    /// IOOBE unless both are in [0, getKeyframeCount() - 1]. first > last
    /// wraps around the end of the keyframe array.
    void setValidRange(int first, int last);
    int getValidRangeFirst() const noexcept { return first_; }  // (1.1)
    int getValidRangeLast() const noexcept { return last_; }    // (1.1)

    /// IAE unless duration > 0.
    void setDuration(int duration);
    int getDuration() const noexcept { return duration_; }
    /// CONSTANT or LOOP, else IAE.
    void setRepeatMode(int mode);
    int getRepeatMode() const noexcept { return repeatMode_; }

    int getComponentCount() const noexcept { return components_; }   // (1.1)
    int getInterpolationType() const noexcept { return interpolation_; }  // (1.1)
    int getKeyframeCount() const noexcept { return keyCount_; }      // (1.1)

    const char* getClassName() const noexcept override { return "KeyframeSequence"; }

    // ---- Engine interface ----
    /// Keyframe times, getKeyframeCount() entries.
    std::span<const int> keyTimes() const noexcept { return times_; }
    /// Keyframe values, getKeyframeCount() * getComponentCount() floats.
    std::span<const float> keyValues() const noexcept { return values_; }
    /// Throws IllegalStateException unless the duration is set, the key times
    /// are non-decreasing along the valid range and the last valid key time
    /// is <= the duration. The result is cached until the next change.
    void validate() const;
    /// SQUAD sequences: the control quaternions of every valid keyframe
    /// (8 floats per key, valid-range order; detail::squadControls), computed
    /// on the first call after a change instead of for every sample. Empty
    /// for other interpolations. Call after validate().
    std::span<const float> squadControls() const;
    /// SLERP and SQUAD sequences: the part of each segment's SLERPs that
    /// does not depend on the time (detail::keyframeArcs: 8 floats per arc,
    /// one per valid key for SLERP, two for SQUAD), computed on the first
    /// call after a change. Empty for other interpolations. Call after
    /// validate().
    std::span<const float> quaternionArcs() const;
    /// SPLINE sequences: the Hermite tangents of every segment
    /// (detail::splineTangents: 2 * getComponentCount() floats per valid
    /// key), computed on the first call after a change. Empty for other
    /// interpolations. Call after validate().
    std::span<const float> splineTangents() const;
    /// Every interpolation but STEP: one byte per valid key, 1 where the
    /// segment to the next key holds key j's value throughout
    /// (detail::flatSegments), computed on the first call after a change.
    /// Call after validate().
    std::span<const unsigned char> flatSegments() const;

protected:
    KeyframeSequence(const KeyframeSequence& other);
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    void changed() noexcept;

    int keyCount_;
    int components_;
    int interpolation_;
    int duration_ = 0;
    int repeatMode_ = CONSTANT;
    int first_ = 0;
    int last_;
    std::vector<int> times_;
    std::vector<float> values_;
    mutable bool validated_ = false;
    void prepareSampling() const;
    mutable std::vector<float> squad_;     // squadControls(), while samplingReady_
    mutable std::vector<float> arcs_;      // quaternionArcs(), while samplingReady_
    mutable std::vector<float> tangents_;  // splineTangents(), while samplingReady_
    mutable std::vector<unsigned char> flat_;  // flatSegments(), while samplingReady_
    mutable bool samplingReady_ = false;
};

}  // namespace m3g
