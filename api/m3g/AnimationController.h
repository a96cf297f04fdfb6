// javax.microedition.m3g.AnimationController (JSR-184 1.1, AnimationController).
#pragma once

#include <m3g/Export.h>

#include <m3g/Object3D.h>

namespace m3g {

/// Maps world time to sequence time for the tracks that use it, and gives
/// them an active interval and a blending weight:
/// position(t) = refSequenceTime + speed * (t - refWorldTime).
class M3G_API AnimationController : public Object3D {
public:
    /// Active interval [0, 0] (always active), speed 1, weight 1, reference
    /// point (world 0, sequence 0).
    AnimationController();
    ~AnimationController() override;

    /// IAE if start > end. start == end means always active; otherwise the
    /// controller is active for start <= t < end.
    void setActiveInterval(int start, int end);
    int getActiveIntervalStart() const noexcept { return start_; }
    int getActiveIntervalEnd() const noexcept { return end_; }

    /// Moves the reference point to (worldTime, getPosition(worldTime)) so the
    /// position is continuous there, then sets the speed (any value).
    void setSpeed(float speed, int worldTime);
    float getSpeed() const noexcept { return speed_; }

    /// Sets the reference point: getPosition(worldTime) == sequenceTime.
    void setPosition(float sequenceTime, int worldTime);
    /// refSequenceTime + speed * (worldTime - refWorldTime).
    /// In double: the world time difference may not fit an int or a float.
    /// Inline, as isActive: animate() asks once per track and frame.
    float getPosition(int worldTime) const noexcept {
        return float(double(refSequenceTime_) + double(speed_) * (double(worldTime) - double(refWorldTime_)));
    }
    /// (1.1) The world time of the reference point.
    int getRefWorldTime() const noexcept { return refWorldTime_; }

    /// IAE if weight < 0.
    void setWeight(float weight);
    float getWeight() const noexcept { return weight_; }

    const char* getClassName() const noexcept override { return "AnimationController"; }

    // ---- Engine interface ----
    /// start == end, or start <= worldTime < end.
    bool isActive(int worldTime) const noexcept {
        return start_ == end_ || (worldTime >= start_ && worldTime < end_);
    }

protected:
    AnimationController(const AnimationController& other) = default;
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    int start_ = 0;
    int end_ = 0;
    float speed_ = 1.0f;
    float weight_ = 1.0f;
    int refWorldTime_ = 0;
    float refSequenceTime_ = 0.0f;
};

}  // namespace m3g
