// javax.microedition.m3g.Fog (JSR-184 1.1, Fog).
#pragma once

#include <m3g/Export.h>

#include <m3g/Object3D.h>

namespace m3g {

/// Linear or exponential fog. No references.
class M3G_API Fog : public Object3D {
public:
    static constexpr int EXPONENTIAL = 80;
    static constexpr int LINEAR = 81;

    /// LINEAR, color 0x000000, density 1, near 0, far 1.
    Fog();
    ~Fog() override;

    /// EXPONENTIAL or LINEAR, else IAE.
    void setMode(int mode);
    int getMode() const noexcept { return mode_; }
    /// Any values (near == far and near > far are accepted).
    void setLinear(float nearDistance, float farDistance) noexcept;
    float getNearDistance() const noexcept { return near_; }
    float getFarDistance() const noexcept { return far_; }
    /// density >= 0, else IAE.
    void setDensity(float density);
    float getDensity() const noexcept { return density_; }
    /// 0x00RRGGBB; the top byte is cleared.
    void setColor(int RGB) noexcept;
    int getColor() const noexcept { return color_; }

    const char* getClassName() const noexcept override { return "Fog"; }
    /// COLOR, DENSITY, NEAR_DISTANCE, FAR_DISTANCE.
    bool isAnimatable(int property) const noexcept override;
    /// COLOR clamped to [0, 1] per channel and stored as bytes (round(v * 255));
    /// DENSITY clamped to >= 0; NEAR_DISTANCE / FAR_DISTANCE unrestricted.
    void updateProperty(int property, std::span<const float> value) override;

protected:
    Fog(const Fog& other);
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    int mode_ = LINEAR;
    int color_ = 0x000000;
    float density_ = 1.0f;
    float near_ = 0.0f;
    float far_ = 1.0f;
};

}  // namespace m3g
