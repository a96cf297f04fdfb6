#include <m3g/KeyframeSequence.h>

#include <cmath>

#include "Check.h"
#include "KeyframeSampler.h"

namespace m3g {

KeyframeSequence::KeyframeSequence(int numKeyframes, int numComponents, int interpolation)
    : keyCount_(numKeyframes), components_(numComponents), interpolation_(interpolation), last_(numKeyframes - 1) {
    const char* where = "KeyframeSequence::KeyframeSequence";
    if (numKeyframes < 1)
        throw IllegalArgumentException(detail::str(where, ": numKeyframes ", numKeyframes, " must be >= 1"));
    if (numComponents < 1)
        throw IllegalArgumentException(detail::str(where, ": numComponents ", numComponents, " must be >= 1"));
    detail::requireEnum(interpolation, {LINEAR, SLERP, SPLINE, SQUAD, STEP}, where, "interpolation");
    if ((interpolation == SLERP || interpolation == SQUAD) && numComponents != 4)
        throw IllegalArgumentException(detail::str(where, ": SLERP and SQUAD need 4 components (a quaternion), got ",
                                                   numComponents));
    times_.assign(std::size_t(numKeyframes), 0);
    values_.assign(std::size_t(numKeyframes) * std::size_t(numComponents), 0.0f);
}

KeyframeSequence::KeyframeSequence(const KeyframeSequence& other)
    : Object3D(other),
      keyCount_(other.keyCount_),
      components_(other.components_),
      interpolation_(other.interpolation_),
      duration_(other.duration_),
      repeatMode_(other.repeatMode_),
      first_(other.first_),
      last_(other.last_),
      times_(other.times_),
      values_(other.values_),
      validated_(other.validated_) {}

KeyframeSequence::~KeyframeSequence() = default;

Object3D* KeyframeSequence::duplicateImpl(DuplicateMap&) const { return new KeyframeSequence(*this); }

void KeyframeSequence::changed() noexcept {
    validated_ = false;
    samplingReady_ = false;
    touch();
}

void KeyframeSequence::setKeyframe(int index, int time, std::span<const float> value) {
    const char* where = "KeyframeSequence::setKeyframe";
    if (value.data() == nullptr) detail::throwNull(where, "value");
    detail::requireIndex(index, keyCount_, where, "index");
    if (time < 0) throw IllegalArgumentException(detail::str(where, ": time ", time, " must be >= 0"));
    detail::requireArray(value, std::size_t(components_), where, "value");
    times_[std::size_t(index)] = time;
    float* dst = values_.data() + std::size_t(index) * std::size_t(components_);
    for (int c = 0; c < components_; ++c) dst[c] = value[std::size_t(c)];
    if (interpolation_ == SLERP || interpolation_ == SQUAD) {
        const double len = std::sqrt(double(dst[0]) * dst[0] + double(dst[1]) * dst[1] + double(dst[2]) * dst[2] +
                                     double(dst[3]) * dst[3]);
        if (len > 0.0 && std::isfinite(len)) {
            for (int c = 0; c < 4; ++c) dst[c] = float(dst[c] / len);
        } else {
            dst[0] = dst[1] = dst[2] = 0.0f;
            dst[3] = 1.0f;
        }
    }
    changed();
}

int KeyframeSequence::getKeyframe(int index, std::span<float> value) const {
    const char* where = "KeyframeSequence::getKeyframe";
    detail::requireIndex(index, keyCount_, where, "index");
    if (value.data() != nullptr) {
        detail::requireArray(value, std::size_t(components_), where, "value");
        const float* src = values_.data() + std::size_t(index) * std::size_t(components_);
        for (int c = 0; c < components_; ++c) value[std::size_t(c)] = src[c];
    }
    return times_[std::size_t(index)];
}

void KeyframeSequence::setValidRange(int first, int last) {
    const char* where = "KeyframeSequence::setValidRange";
    detail::requireIndex(first, keyCount_, where, "first");
    detail::requireIndex(last, keyCount_, where, "last");
    first_ = first;
    last_ = last;
    changed();
}

void KeyframeSequence::setDuration(int duration) {
    if (duration <= 0)
        throw IllegalArgumentException(
            detail::str("KeyframeSequence::setDuration: duration ", duration, " must be > 0"));
    duration_ = duration;
    changed();
}

void KeyframeSequence::setRepeatMode(int mode) {
    detail::requireEnum(mode, {CONSTANT, LOOP}, "KeyframeSequence::setRepeatMode", "mode");
    repeatMode_ = mode;
    changed();
}

void KeyframeSequence::prepareSampling() const {
    squad_.clear();
    arcs_.clear();
    tangents_.clear();
    flat_.clear();
    detail::KeyframeView view = detail::viewOf(*this);
    if (interpolation_ == SQUAD) {
        detail::squadControls(view, squad_);
        view.squad = squad_;
    }
    detail::keyframeArcs(view, arcs_);
    detail::splineTangents(view, tangents_);
    view.tangents = tangents_;  // flatSegments reads the kept tangents and controls
    detail::flatSegments(view, flat_);
    samplingReady_ = true;
}

std::span<const float> KeyframeSequence::squadControls() const {
    if (!samplingReady_) prepareSampling();
    return squad_;
}

std::span<const float> KeyframeSequence::quaternionArcs() const {
    if (!samplingReady_) prepareSampling();
    return arcs_;
}

std::span<const float> KeyframeSequence::splineTangents() const {
    if (!samplingReady_) prepareSampling();
    return tangents_;
}

std::span<const unsigned char> KeyframeSequence::flatSegments() const {
    if (!samplingReady_) prepareSampling();
    return flat_;
}

void KeyframeSequence::validate() const {
    if (validated_) return;
    const std::string problem = detail::keyframeProblem(detail::viewOf(*this));
    if (!problem.empty()) throw IllegalStateException("KeyframeSequence: cannot be sampled: " + problem);
    validated_ = true;
}

}  // namespace m3g
