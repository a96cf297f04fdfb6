// javax.microedition.m3g.AnimationTrack (JSR-184 1.1, AnimationTrack).
#pragma once

#include <m3g/Export.h>

#include <m3g/Object3D.h>

namespace m3g {

/// Binds a KeyframeSequence to one animatable property of the object the
/// track is attached to, under an AnimationController.
class M3G_API AnimationTrack : public Object3D {
public:
    static constexpr int ALPHA = 256;
    static constexpr int AMBIENT_COLOR = 257;
    static constexpr int COLOR = 258;
    static constexpr int CROP = 259;
    static constexpr int DENSITY = 260;
    static constexpr int DIFFUSE_COLOR = 261;
    static constexpr int EMISSIVE_COLOR = 262;
    static constexpr int FAR_DISTANCE = 263;
    static constexpr int FIELD_OF_VIEW = 264;
    static constexpr int INTENSITY = 265;
    static constexpr int MORPH_WEIGHTS = 266;
    static constexpr int NEAR_DISTANCE = 267;
    static constexpr int ORIENTATION = 268;
    static constexpr int PICKABILITY = 269;
    static constexpr int SCALE = 270;
    static constexpr int SHININESS = 271;
    static constexpr int SPECULAR_COLOR = 272;
    static constexpr int SPOT_ANGLE = 273;
    static constexpr int SPOT_EXPONENT = 274;
    static constexpr int TRANSLATION = 275;
    static constexpr int VISIBILITY = 276;

    /// NPE if `sequence` is null; IAE if `property` is not in [256, 276] or
    /// the sequence's component count does not fit the property
    /// (JSR-184 1.1, AnimationTrack(KeyframeSequence, int)).
    AnimationTrack(KeyframeSequence* sequence, int property);
    ~AnimationTrack() override;

    /// Null makes the track inactive.
    void setController(AnimationController* controller);
    Ref<AnimationController> getController() const;
    Ref<KeyframeSequence> getKeyframeSequence() const;
    int getTargetProperty() const noexcept { return property_; }

    const char* getClassName() const noexcept override { return "AnimationTrack"; }

protected:
    AnimationTrack(const AnimationTrack& other);
    /// Order: keyframe sequence, controller.
    void collectReferences(std::vector<Object3D*>& out) const override;
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    // Held as Object3D so that this header needs no definition of the two
    // classes; they are always a KeyframeSequence and an AnimationController.
    Ref<Object3D> sequence_;
    Ref<Object3D> controller_;
    int property_;
};

}  // namespace m3g
