// javax.microedition.m3g.VertexArray (JSR-184 1.1, VertexArray; and
// Transform.transform(VertexArray, float[], boolean)).
#pragma once

#include <m3g/Export.h>

#include <cstdint>
#include <span>
#include <vector>

#include <m3g/Object3D.h>

namespace m3g {

/// An array of integer vectors (2 to 4 signed byte or short components per
/// vertex). The values are raw integers; scale, bias and normalisation are
/// applied by the VertexBuffer that uses the array.
class M3G_API VertexArray : public Object3D {
public:
    /// IAE unless 1 <= numVertices <= 65535, 2 <= numComponents <= 4 and
    /// componentSize is 1 (byte) or 2 (short). All components start at 0.
    VertexArray(int numVertices, int numComponents, int componentSize);
    ~VertexArray() override;

    /// Copies numVertices * getComponentCount() values into vertices
    /// [firstVertex, firstVertex + numVertices). Checks, in this order:
    /// NPE if `values` is null; ISE if the component size is not 1;
    /// IAE if numVertices < 0; IOOBE if firstVertex < 0 or
    /// firstVertex + numVertices > getVertexCount(); IAE if `values` is too short.
    void set(int firstVertex, int numVertices, std::span<const std::int8_t> values);
    /// As the byte version, with ISE if the component size is not 2.
    void set(int firstVertex, int numVertices, std::span<const std::int16_t> values);
    /// (1.1) Reads values back; same checks as set().
    void get(int firstVertex, int numVertices, std::span<std::int8_t> values) const;
    /// (1.1) Reads values back; same checks as set().
    void get(int firstVertex, int numVertices, std::span<std::int16_t> values) const;

    /// (1.1) 2, 3 or 4.
    int getComponentCount() const noexcept { return components_; }
    /// (1.1) 1 (byte) or 2 (short).
    int getComponentType() const noexcept { return componentSize_; }
    /// (1.1)
    int getVertexCount() const noexcept { return vertices_; }

    const char* getClassName() const noexcept override { return "VertexArray"; }

    // ---- Engine interface ----
    /// The tightly packed values: getVertexCount() * getComponentCount()
    /// elements of std::int8_t (type 1) or std::int16_t (type 2).
    const void* data() const noexcept;
    /// Writes the raw values of vertices [first, first + count) as floats
    /// (count * getComponentCount() floats). IOOBE if the range is outside
    /// the array, IAE if `out` is too short.
    void getFloats(int first, int count, std::span<float> out) const;
    /// Raw value of component `c` of vertex `v` (no checks).
    int value(int v, int c) const noexcept {
        const std::size_t i = static_cast<std::size_t>(v) * components_ + c;
        return componentSize_ == 1 ? bytes_[i] : shorts_[i];
    }

protected:
    VertexArray(const VertexArray& other);
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    void checkAccess(const char* where, int componentSize, int first, int count, std::size_t length,
                     bool isNull) const;

    int vertices_;
    int components_;
    int componentSize_;
    std::vector<std::int8_t> bytes_;    // used when componentSize_ == 1
    std::vector<std::int16_t> shorts_;  // used when componentSize_ == 2
};

}  // namespace m3g
