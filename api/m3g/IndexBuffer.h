// javax.microedition.m3g.IndexBuffer (JSR-184 1.1, IndexBuffer).
#pragma once

#include <m3g/Export.h>

#include <span>
#include <vector>

#include <m3g/Object3D.h>

namespace m3g {

/// Abstract: the triangles of a submesh. Every subclass exposes them as a
/// triangle list with consistent winding (what getIndices returns).
class M3G_API IndexBuffer : public Object3D {
public:
    ~IndexBuffer() override;

    /// (1.1) Number of indices of the triangle list (3 per triangle,
    /// degenerate triangles included).
    int getIndexCount() const noexcept { return static_cast<int>(triangles_.size()); }
    /// (1.1) Writes the triangle list. NPE if `indices` is null; IAE if it is
    /// shorter than getIndexCount().
    void getIndices(std::span<int> indices) const;

    // ---- Engine interface ----
    /// The triangle list (getIndexCount() entries, 3 per triangle).
    std::span<const int> triangleIndices() const noexcept { return triangles_; }
    /// Largest index referenced (a VertexBuffer needs more vertices than
    /// this), or -1 if there are no triangles.
    int maxIndex() const noexcept { return maxIndex_; }

protected:
    IndexBuffer();
    IndexBuffer(const IndexBuffer& other);
    /// Sets the triangle list (called by subclass constructors).
    void setTriangles(std::vector<int> triangles);

private:
    std::vector<int> triangles_;
    int maxIndex_ = -1;
};

}  // namespace m3g
