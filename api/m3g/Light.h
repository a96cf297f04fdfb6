// javax.microedition.m3g.Light (JSR-184 1.1, Light).
#pragma once

#include <m3g/Export.h>

#include <m3g/Node.h>

namespace m3g {

/// A light source node. Directional and spot lights shine along their local
/// -Z axis; omni and spot lights are positioned at their local origin.
class M3G_API Light : public Node {
public:
    static constexpr int AMBIENT = 128;
    static constexpr int DIRECTIONAL = 129;
    static constexpr int OMNI = 130;
    static constexpr int SPOT = 131;

    /// DIRECTIONAL, color 0xFFFFFF, intensity 1, attenuation (1, 0, 0),
    /// spot angle 45, spot exponent 0.
    Light();
    ~Light() override;

    /// AMBIENT, DIRECTIONAL, OMNI or SPOT, else IAE.
    void setMode(int mode);
    int getMode() const noexcept { return mode_; }
    /// 0xRRGGBB; the top byte is ignored (stored as 0).
    void setColor(int RGB) noexcept;
    int getColor() const noexcept { return color_; }
    /// Any value, negative included.
    void setIntensity(float intensity) noexcept;
    float getIntensity() const noexcept { return intensity_; }
    /// Degrees in [0, 90], else IAE.
    void setSpotAngle(float angle);
    float getSpotAngle() const noexcept { return spotAngle_; }
    /// [0, 128], else IAE.
    void setSpotExponent(float exponent);
    float getSpotExponent() const noexcept { return spotExponent_; }
    /// All >= 0 and not all zero, else IAE.
    void setAttenuation(float constant, float linear, float quadratic);
    float getConstantAttenuation() const noexcept { return attenuation_[0]; }
    float getLinearAttenuation() const noexcept { return attenuation_[1]; }
    float getQuadraticAttenuation() const noexcept { return attenuation_[2]; }

    const char* getClassName() const noexcept override { return "Light"; }
    /// COLOR, INTENSITY, SPOT_ANGLE, SPOT_EXPONENT plus the Node properties.
    bool isAnimatable(int property) const noexcept override;
    /// COLOR clamped to [0, 1] per channel; SPOT_ANGLE clamped to [0, 90];
    /// SPOT_EXPONENT clamped to [0, 128]; INTENSITY unclamped.
    void updateProperty(int property, std::span<const float> value) override;

protected:
    Light(const Light& other) = default;
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    int mode_ = DIRECTIONAL;
    int color_ = 0xFFFFFF;
    float intensity_ = 1.0f;
    float spotAngle_ = 45.0f;
    float spotExponent_ = 0.0f;
    float attenuation_[3] = {1.0f, 0.0f, 0.0f};
};

}  // namespace m3g
