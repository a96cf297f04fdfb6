// javax.microedition.m3g.Transform: a generic 4x4 float matrix (JSR-184 1.1, Transform).
#pragma once

#include <m3g/Export.h>

#include <array>
#include <span>

#include <m3g/Exception.h>
#include <m3g/Forward.h>

namespace m3g {

/// A 4x4 matrix. Vectors are columns (v' = M v); get/set use row-major order
/// (element index = row*4 + col). `postX` multiplies from the right: M = M X.
/// A value type (not an Object3D): pass by pointer where Java passes a
/// Transform reference that may be null.
class M3G_API Transform {
public:
    /// Identity. Inline, as fromRows: every node of every frame's bone paths
    /// and render queue makes a few of these.
    Transform() noexcept : m_{1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f} {}
    Transform(const Transform& other) noexcept = default;
    Transform& operator=(const Transform& other) noexcept = default;

    void setIdentity() noexcept;
    /// Copies `transform`; NullPointerException if null.
    void set(const Transform* transform);
    /// Sets from 16 row-major floats; NPE if null span, IAE if shorter than 16.
    void set(std::span<const float> matrix);
    /// Writes 16 row-major floats; NPE if null span, IAE if shorter than 16.
    void get(std::span<float> matrix) const;

    /// Inverts in place; ArithmeticException if the matrix is singular.
    void invert();
    void transpose() noexcept;

    /// M = M * transform; NPE if null.
    void postMultiply(const Transform* transform);
    void postScale(float sx, float sy, float sz) noexcept;
    /// M = M * R(angle degrees about axis); IAE if the axis is zero and angle != 0.
    void postRotate(float angle, float ax, float ay, float az);
    /// M = M * R(q) with q normalised; IAE if all four components are zero.
    void postRotateQuat(float qx, float qy, float qz, float qw);
    void postTranslate(float tx, float ty, float tz) noexcept;

    /// Multiplies every 4-vector of `vectors` in place; NPE if null, IAE if the
    /// length is not a multiple of 4.
    void transform(std::span<float> vectors) const;
    /// Transforms the raw integer components of `in` (no scale/bias): missing z
    /// is 0, w is 1 if `W` else 0; writes 4 floats per vertex to `out`.
    /// NPE if either is null; IAE if `in` has 4 components or `out` is shorter
    /// than 4 * vertexCount.
    void transform(const VertexArray* in, std::span<float> out, bool W) const;

    // ---- C++ conveniences (not in the Java API) ----
    /// Element at row r, column c.
    float at(int r, int c) const noexcept { return m_[r * 4 + c]; }
    float& at(int r, int c) noexcept { return m_[r * 4 + c]; }
    const std::array<float, 16>& rows() const noexcept { return m_; }
    /// Exact element-wise equality.
    bool operator==(const Transform& o) const noexcept { return m_ == o.m_; }
    /// this * other, as a new Transform.
    Transform operator*(const Transform& other) const noexcept;
    /// Builds a transform from 16 row-major values.
    static Transform fromRows(const std::array<float, 16>& rows) noexcept {
        Transform t;  // the identity's stores are dead once inlined
        t.m_ = rows;
        return t;
    }

private:
    std::array<float, 16> m_;
};

}  // namespace m3g
