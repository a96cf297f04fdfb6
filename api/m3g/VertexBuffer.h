// javax.microedition.m3g.VertexBuffer (JSR-184 1.1, VertexBuffer).
#pragma once

#include <m3g/Export.h>

#include <array>
#include <cstdint>
#include <span>

#include <m3g/Limits.h>
#include <m3g/Object3D.h>
#include <m3g/VertexArray.h>

namespace m3g {

/// Positions, normals, colors and texture coordinates of a set of vertices,
/// each a VertexArray (all sharing one vertex count), plus the scale and bias
/// of positions and texture coordinates and a default color.
///
/// Vertex count: 0 while no array is set; otherwise the count of the arrays.
/// Setting an array whose count differs from that of the *other* arrays
/// throws IAE (replacing the only array may change the count); removing every
/// array resets the count to 0.
class M3G_API VertexBuffer : public Object3D {
public:
    /// No arrays, default color 0xFFFFFFFF, vertex count 0.
    VertexBuffer();
    ~VertexBuffer() override;

    int getVertexCount() const noexcept { return vertexCount_; }

    /// `positions` must have 3 components (else IAE); null removes the array.
    /// `bias` may be null (0, 0, 0), else IAE if shorter than 3 (checked only
    /// when positions is non-null). The bias is reset to 0 when positions or
    /// bias is null; the scale is stored as given.
    void setPositions(VertexArray* positions, float scale, std::span<const float> bias);
    /// IOOBE unless 0 <= index < getLimits().numTextureUnits. `texCoords`
    /// must have 2 or 3 components (IAE); `bias` null (zeros) or at least the
    /// component count long (IAE). Bias/scale storage as for setPositions.
    void setTexCoords(int index, VertexArray* texCoords, float scale, std::span<const float> bias);
    /// 3 components, else IAE; null removes the array.
    void setNormals(VertexArray* normals);
    /// Byte arrays with 3 or 4 components, else IAE; null removes the array.
    void setColors(VertexArray* colors);

    /// The position array (may be null). If `scaleBias` is non-null it
    /// receives {scale, bx, by, bz}; IAE if it is shorter than 4.
    Ref<VertexArray> getPositions(std::span<float> scaleBias = {}) const;
    /// IOOBE unless 0 <= index < numTextureUnits. If the array is set and
    /// `scaleBias` is non-null it receives {scale, bs, bt[, br]}; IAE if it is
    /// shorter than componentCount + 1. Untouched when no array is set.
    Ref<VertexArray> getTexCoords(int index, std::span<float> scaleBias = {}) const;
    Ref<VertexArray> getNormals() const noexcept { return normals_; }
    Ref<VertexArray> getColors() const noexcept { return colors_; }

    /// 0xAARRGGBB, used for every vertex when there is no color array.
    void setDefaultColor(int ARGB) noexcept;
    int getDefaultColor() const noexcept { return static_cast<int>(defaultColor_); }

    const char* getClassName() const noexcept override { return "VertexBuffer"; }
    /// COLOR (RGB of the default color) and ALPHA (its alpha), besides the
    /// Object3D ones. Values are clamped to [0, 1] and stored as round(255 v).
    bool isAnimatable(int property) const noexcept override;
    void updateProperty(int property, std::span<const float> value) override;

    // ---- Engine interface ----
    VertexArray* positions() const noexcept { return positions_.get(); }
    float positionScale() const noexcept { return positionScale_; }
    const std::array<float, 3>& positionBias() const noexcept { return positionBias_; }
    VertexArray* texCoords(int unit) const noexcept { return texCoords_[unit].get(); }
    float texCoordScale(int unit) const noexcept { return texCoordScale_[unit]; }
    const std::array<float, 3>& texCoordBias(int unit) const noexcept { return texCoordBias_[unit]; }
    VertexArray* normals() const noexcept { return normals_.get(); }
    VertexArray* colors() const noexcept { return colors_.get(); }

protected:
    VertexBuffer(const VertexBuffer& other);
    /// Order: positions, normals, colors, texture coordinates by unit (nulls omitted).
    void collectReferences(std::vector<Object3D*>& out) const override;
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    /// Checks `array` against the vertex count of the arrays other than
    /// `current` (IAE on mismatch); call before assigning.
    void checkCount(const VertexArray* array, const VertexArray* current, const char* where) const;
    /// Recomputes the vertex count from the arrays now set.
    void updateCount() noexcept;

    Ref<VertexArray> positions_;
    Ref<VertexArray> normals_;
    Ref<VertexArray> colors_;
    std::array<Ref<VertexArray>, kMaxTextureUnits> texCoords_;
    float positionScale_ = 1.0f;
    std::array<float, 3> positionBias_{0, 0, 0};
    std::array<float, kMaxTextureUnits> texCoordScale_;
    std::array<std::array<float, 3>, kMaxTextureUnits> texCoordBias_{};
    std::uint32_t defaultColor_ = 0xFFFFFFFFu;
    int vertexCount_ = 0;
};

}  // namespace m3g
