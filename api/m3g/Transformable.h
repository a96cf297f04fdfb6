// javax.microedition.m3g.Transformable (JSR-184 1.1, Transformable).
#pragma once

#include <m3g/Export.h>

#include <array>
#include <span>

#include <m3g/Object3D.h>
#include <m3g/Transform.h>

namespace m3g {

/// Translation T, orientation R (unit quaternion), scale S and a generic
/// matrix M, composed as C = T R S M.
class M3G_API Transformable : public Object3D {
public:
    /// R = rotation of `angle` degrees about (ax, ay, az); IAE if the axis is
    /// zero and angle != 0. The axis need not be unit length.
    void setOrientation(float angle, float ax, float ay, float az);
    /// R = R * Rnew.
    void postRotate(float angle, float ax, float ay, float az);
    /// R = Rnew * R.
    void preRotate(float angle, float ax, float ay, float az);
    /// {angle, ax, ay, az}; NPE if null, IAE if shorter than 4.
    void getOrientation(std::span<float> angleAxis) const;

    void setScale(float sx, float sy, float sz);
    /// Component-wise multiply.
    void scale(float sx, float sy, float sz);
    /// NPE if null, IAE if shorter than 3.
    void getScale(std::span<float> xyz) const;

    void setTranslation(float tx, float ty, float tz);
    void translate(float tx, float ty, float tz);
    void getTranslation(std::span<float> xyz) const;

    /// M = transform (null resets to identity). For Nodes the bottom row must
    /// be (0, 0, 0, 1), else IllegalArgumentException.
    void setTransform(const Transform* transform);
    /// M; NPE if null.
    void getTransform(Transform* transform) const;
    /// C = T R S M; NPE if null.
    void getCompositeTransform(Transform* transform) const;

    // ---- Engine interface ----
    /// C = T R S M as a value.
    Transform compositeTransform() const noexcept;
    /// Orientation quaternion (x, y, z, w).
    const std::array<float, 4>& orientationQuat() const noexcept { return q_; }
    /// Sets the orientation quaternion directly (normalised; zero -> identity).
    void setOrientationQuat(float qx, float qy, float qz, float qw) noexcept;

    bool isAnimatable(int property) const noexcept override;
    void updateProperty(int property, std::span<const float> value) override;

protected:
    Transformable();
    Transformable(const Transformable& other) = default;
    /// Called when any component changes (nodes use it to invalidate caches).
    virtual void transformChanged() noexcept { touch(); }
    /// Whether setTransform must reject matrices whose bottom row is not (0,0,0,1).
    virtual bool requiresAffineTransform() const noexcept { return false; }

private:
    std::array<float, 3> t_{0, 0, 0};
    std::array<float, 4> q_{0, 0, 0, 1};
    std::array<float, 3> s_{1, 1, 1};
    Transform m_;
    bool hasM_ = false;  // M != identity: skips a matrix product
};

}  // namespace m3g
