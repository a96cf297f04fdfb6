// javax.microedition.m3g.Camera (JSR-184 1.1, Camera).
#pragma once

#include <m3g/Export.h>

#include <array>

#include <m3g/Node.h>

namespace m3g {

/// A camera node looking down its local -Z with +Y up. Projection matrices
/// are OpenGL style (NDC z in [-1, 1]); the renderer adapts them to Vulkan.
class M3G_API Camera : public Node {
public:
    static constexpr int GENERIC = 48;
    static constexpr int PARALLEL = 49;
    static constexpr int PERSPECTIVE = 50;

    /// GENERIC projection with the identity matrix.
    Camera();
    ~Camera() override;

    /// IAE unless 0 < fovy < 180, aspectRatio > 0, near > 0 and far > 0.
    void setPerspective(float fovy, float aspectRatio, float near, float far);
    /// IAE unless height > 0 and aspectRatio > 0; near and far are free.
    void setParallel(float height, float aspectRatio, float near, float far);
    /// NPE if null.
    void setGeneric(const Transform* transform);
    /// The projection type; fills `transform` with the matrix if non-null.
    /// ArithmeticException if near == far for PERSPECTIVE or PARALLEL.
    int getProjection(Transform* transform) const;
    /// The projection type; for PERSPECTIVE/PARALLEL fills {fovy or height,
    /// aspect, near, far} if `params` is non-null; IAE if shorter than 4.
    int getProjection(std::span<float> params) const;

    const char* getClassName() const noexcept override { return "Camera"; }
    bool isAnimatable(int property) const noexcept override;
    void updateProperty(int property, std::span<const float> value) override;

protected:
    Camera(const Camera& other) = default;
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    int type_ = GENERIC;
    std::array<float, 4> params_{0, 0, 0, 0};  // fovy|height, aspect, near, far
    Transform generic_;
};

}  // namespace m3g
