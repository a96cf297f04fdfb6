// javax.microedition.m3g.PolygonMode (JSR-184 1.1, PolygonMode).
#pragma once

#include <m3g/Export.h>

#include <m3g/Object3D.h>

namespace m3g {

/// Polygon-level state: culling, shading, winding, two-sided lighting and the
/// local-camera-lighting and perspective-correction hints. Not animatable; no
/// references.
class M3G_API PolygonMode : public Object3D {
public:
    static constexpr int CULL_BACK = 160;
    static constexpr int CULL_FRONT = 161;
    static constexpr int CULL_NONE = 162;
    static constexpr int SHADE_FLAT = 164;
    static constexpr int SHADE_SMOOTH = 165;
    static constexpr int WINDING_CCW = 168;
    static constexpr int WINDING_CW = 169;

    /// CULL_BACK, SHADE_SMOOTH, WINDING_CCW, two-sided lighting off, local
    /// camera lighting off, perspective correction off.
    PolygonMode();
    ~PolygonMode() override;

    /// CULL_BACK, CULL_FRONT or CULL_NONE, else IAE.
    void setCulling(int mode);
    int getCulling() const noexcept { return culling_; }
    /// SHADE_FLAT or SHADE_SMOOTH, else IAE.
    void setShading(int mode);
    int getShading() const noexcept { return shading_; }
    /// WINDING_CCW or WINDING_CW, else IAE.
    void setWinding(int mode);
    int getWinding() const noexcept { return winding_; }
    void setTwoSidedLightingEnable(bool enable) noexcept;
    bool isTwoSidedLightingEnabled() const noexcept { return twoSided_; }
    /// Hint.
    void setLocalCameraLightingEnable(bool enable) noexcept;
    bool isLocalCameraLightingEnabled() const noexcept { return localCamera_; }
    /// Hint.
    void setPerspectiveCorrectionEnable(bool enable) noexcept;
    bool isPerspectiveCorrectionEnabled() const noexcept { return perspectiveCorrection_; }

    const char* getClassName() const noexcept override { return "PolygonMode"; }

protected:
    PolygonMode(const PolygonMode& other);
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    int culling_ = CULL_BACK;
    int shading_ = SHADE_SMOOTH;
    int winding_ = WINDING_CCW;
    bool twoSided_ = false;
    bool localCamera_ = false;
    bool perspectiveCorrection_ = false;
};

}  // namespace m3g
