// javax.microedition.m3g.Material (JSR-184 1.1, Material; the lighting
// equation in Light and Material).
#pragma once

#include <m3g/Export.h>

#include <m3g/Object3D.h>

namespace m3g {

/// Lighting material: ambient, diffuse (with alpha), emissive and specular
/// colors, shininess and vertex color tracking. No references.
class M3G_API Material : public Object3D {
public:
    static constexpr int AMBIENT = 1024;
    static constexpr int DIFFUSE = 2048;
    static constexpr int EMISSIVE = 4096;
    static constexpr int SPECULAR = 8192;

    /// Ambient 0x333333, diffuse 0xFFCCCCCC, emissive 0x000000, specular
    /// 0x000000, shininess 0, vertex color tracking off.
    Material();
    ~Material() override;

    /// Sets every color named in `target` (an OR of AMBIENT, DIFFUSE,
    /// EMISSIVE, SPECULAR). Only DIFFUSE keeps the alpha byte; the others are
    /// stored as 0x00RRGGBB. IAE if target is 0 or has other bits.
    void setColor(int target, int ARGB);
    /// `target` must be exactly one of the four flags, else IAE. Non-diffuse
    /// colors are returned with alpha 0 (as Nokia's implementation).
    int getColor(int target) const;
    /// shininess in [0, 128], else IAE.
    void setShininess(float shininess);
    float getShininess() const noexcept { return shininess_; }
    /// Ambient and diffuse follow the per-vertex color when enabled.
    void setVertexColorTrackingEnable(bool enable) noexcept;
    bool isVertexColorTrackingEnabled() const noexcept { return vertexColorTracking_; }

    const char* getClassName() const noexcept override { return "Material"; }
    /// ALPHA, AMBIENT_COLOR, DIFFUSE_COLOR, EMISSIVE_COLOR, SPECULAR_COLOR, SHININESS.
    bool isAnimatable(int property) const noexcept override;
    /// Colors and ALPHA are clamped to [0, 1] and stored as bytes rounded to
    /// the nearest of v * 255; ALPHA sets the diffuse alpha, DIFFUSE_COLOR
    /// keeps it; SHININESS is clamped to [0, 128].
    void updateProperty(int property, std::span<const float> value) override;

protected:
    Material(const Material& other);
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    int ambient_ = 0x00333333;
    int diffuse_ = static_cast<int>(0xFFCCCCCCu);
    int emissive_ = 0x00000000;
    int specular_ = 0x00000000;
    float shininess_ = 0.0f;
    bool vertexColorTracking_ = false;
};

}  // namespace m3g
