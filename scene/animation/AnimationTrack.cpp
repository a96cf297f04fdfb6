#include <m3g/AnimationTrack.h>

#include <m3g/AnimationController.h>
#include <m3g/KeyframeSequence.h>

#include "Check.h"

namespace m3g {

namespace {
// Component counts a property accepts (JSR-184 1.1, AnimationTrack).
bool validComponentCount(int property, int n) {
    switch (property) {
    case AnimationTrack::ALPHA:
    case AnimationTrack::DENSITY:
    case AnimationTrack::FAR_DISTANCE:
    case AnimationTrack::FIELD_OF_VIEW:
    case AnimationTrack::INTENSITY:
    case AnimationTrack::NEAR_DISTANCE:
    case AnimationTrack::PICKABILITY:
    case AnimationTrack::SHININESS:
    case AnimationTrack::SPOT_ANGLE:
    case AnimationTrack::SPOT_EXPONENT:
    case AnimationTrack::VISIBILITY:
        return n == 1;
    case AnimationTrack::CROP:
        return n == 2 || n == 4;
    case AnimationTrack::COLOR:
    case AnimationTrack::AMBIENT_COLOR:
    case AnimationTrack::DIFFUSE_COLOR:
    case AnimationTrack::EMISSIVE_COLOR:
    case AnimationTrack::SPECULAR_COLOR:
    case AnimationTrack::TRANSLATION:
        return n == 3;
    case AnimationTrack::ORIENTATION:
        return n == 4;
    case AnimationTrack::SCALE:
        return n == 1 || n == 3;
    case AnimationTrack::MORPH_WEIGHTS:
        return n >= 1;
    default:
        return false;
    }
}
}  // namespace

AnimationTrack::AnimationTrack(KeyframeSequence* sequence, int property) : property_(property) {
    const char* where = "AnimationTrack::AnimationTrack";
    detail::requireNonNull(sequence, where, "sequence");
    detail::requireRange(property, int(ALPHA), int(VISIBILITY), where, "property");
    if (!validComponentCount(property, sequence->getComponentCount()))
        throw IllegalArgumentException(detail::str(where, ": a sequence with ", sequence->getComponentCount(),
                                                   " components cannot animate property ", property));
    sequence_ = sequence;
}

AnimationTrack::AnimationTrack(const AnimationTrack& other)
    : Object3D(other), sequence_(other.sequence_), controller_(other.controller_), property_(other.property_) {}

AnimationTrack::~AnimationTrack() = default;

Object3D* AnimationTrack::duplicateImpl(DuplicateMap&) const { return new AnimationTrack(*this); }

void AnimationTrack::setController(AnimationController* controller) {
    if (controller_.get() != controller) referencesChanged();
    controller_ = controller;
    touch();
}

Ref<AnimationController> AnimationTrack::getController() const {
    return static_cast<AnimationController*>(controller_.get());
}

Ref<KeyframeSequence> AnimationTrack::getKeyframeSequence() const {
    return static_cast<KeyframeSequence*>(sequence_.get());
}

void AnimationTrack::collectReferences(std::vector<Object3D*>& out) const {
    Object3D::collectReferences(out);
    if (sequence_) out.push_back(sequence_.get());
    if (controller_) out.push_back(controller_.get());
}

}  // namespace m3g
