// javax.microedition.m3g.CompositingMode (JSR-184 1.1, CompositingMode).
#pragma once

#include <m3g/Export.h>

#include <m3g/Object3D.h>

namespace m3g {

/// Per-fragment operations: alpha test, depth test/write, blending, color and
/// alpha write masks, depth offset. Not animatable; no references.
class M3G_API CompositingMode : public Object3D {
public:
    static constexpr int ALPHA = 64;
    static constexpr int ALPHA_ADD = 65;
    static constexpr int MODULATE = 66;
    static constexpr int MODULATE_X2 = 67;
    static constexpr int REPLACE = 68;

    /// REPLACE, alpha threshold 0, depth test, depth write, color write and
    /// alpha write on, depth offset (0, 0).
    CompositingMode();
    ~CompositingMode() override;

    /// One of ALPHA, ALPHA_ADD, MODULATE, MODULATE_X2, REPLACE, else IAE.
    void setBlending(int mode);
    int getBlending() const noexcept { return blending_; }
    /// threshold in [0, 1], else IAE. 0 disables the alpha test.
    void setAlphaThreshold(float threshold);
    float getAlphaThreshold() const noexcept { return alphaThreshold_; }
    void setDepthTestEnable(bool enable) noexcept;
    bool isDepthTestEnabled() const noexcept { return depthTest_; }
    void setDepthWriteEnable(bool enable) noexcept;
    bool isDepthWriteEnabled() const noexcept { return depthWrite_; }
    void setColorWriteEnable(bool enable) noexcept;
    bool isColorWriteEnabled() const noexcept { return colorWrite_; }
    void setAlphaWriteEnable(bool enable) noexcept;
    bool isAlphaWriteEnabled() const noexcept { return alphaWrite_; }
    /// Polygon offset (glPolygonOffset factor, units); any values.
    void setDepthOffset(float factor, float units) noexcept;
    float getDepthOffsetFactor() const noexcept { return depthOffsetFactor_; }
    float getDepthOffsetUnits() const noexcept { return depthOffsetUnits_; }

    const char* getClassName() const noexcept override { return "CompositingMode"; }

protected:
    CompositingMode(const CompositingMode& other);
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    int blending_ = REPLACE;
    float alphaThreshold_ = 0.0f;
    bool depthTest_ = true;
    bool depthWrite_ = true;
    bool colorWrite_ = true;
    bool alphaWrite_ = true;
    float depthOffsetFactor_ = 0.0f;
    float depthOffsetUnits_ = 0.0f;
};

}  // namespace m3g
