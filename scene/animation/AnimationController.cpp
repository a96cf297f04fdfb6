#include <m3g/AnimationController.h>

#include "Check.h"

namespace m3g {

AnimationController::AnimationController() = default;

AnimationController::~AnimationController() = default;

Object3D* AnimationController::duplicateImpl(DuplicateMap&) const { return new AnimationController(*this); }

void AnimationController::setActiveInterval(int start, int end) {
    if (start > end)
        throw IllegalArgumentException(detail::str("AnimationController::setActiveInterval: start ", start,
                                                   " is greater than end ", end));
    start_ = start;
    end_ = end;
    touch();
}

void AnimationController::setSpeed(float speed, int worldTime) {
    refSequenceTime_ = getPosition(worldTime);
    refWorldTime_ = worldTime;
    speed_ = speed;
    touch();
}

void AnimationController::setPosition(float sequenceTime, int worldTime) {
    refSequenceTime_ = sequenceTime;
    refWorldTime_ = worldTime;
    touch();
}

void AnimationController::setWeight(float weight) {
    if (!(weight >= 0.0f))
        throw IllegalArgumentException(
            detail::str("AnimationController::setWeight: weight ", weight, " must be >= 0"));
    weight_ = weight;
    touch();
}

}  // namespace m3g
