// javax.microedition.m3g.TriangleStripArray (JSR-184 1.1, TriangleStripArray).
#pragma once

#include <m3g/Export.h>

#include <span>
#include <vector>

#include <m3g/IndexBuffer.h>

namespace m3g {

/// Independent triangle strips, with implicit (consecutive) or explicit indices.
///
/// As a triangle list (getIndices), strip s0 s1 s2 ... s(n-1) gives the
/// triangles (s(j), s(j+1), s(j+2)) for even j and (s(j), s(j+2), s(j+1)) for
/// odd j (2nd and 3rd index swapped, so that every triangle has the winding
/// of the first one), strips one after the other. Degenerate triangles
/// (repeated indices) are kept, so getIndexCount() = 3 * sum(length - 2).
class M3G_API TriangleStripArray : public IndexBuffer {
public:
    /// Implicit indices: strip k uses the next stripLengths[k] indices,
    /// counting from firstIndex. NPE if stripLengths is null; IAE if it is
    /// empty or a length is < 3; IOOBE if firstIndex < 0 or
    /// firstIndex + sum(stripLengths) > 65535.
    TriangleStripArray(int firstIndex, std::span<const int> stripLengths);
    /// Explicit indices: strip k uses the next stripLengths[k] entries of
    /// `indices`. NPE if either is null; IAE if stripLengths is empty, a
    /// length is < 3 or indices.length < sum(stripLengths); IOOBE if one of
    /// the sum(stripLengths) indices used is < 0 or > 65535 (entries past
    /// the sum are ignored, as in the reference core).
    TriangleStripArray(std::span<const int> indices, std::span<const int> stripLengths);
    ~TriangleStripArray() override;

    const char* getClassName() const noexcept override { return "TriangleStripArray"; }

    // ---- Engine interface ----
    /// The strip indices, strips concatenated (sum(stripLengths) entries).
    std::span<const int> stripIndices() const noexcept { return stripIndices_; }
    std::span<const int> stripLengths() const noexcept { return stripLengths_; }

protected:
    TriangleStripArray(const TriangleStripArray& other);
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    void build();

    std::vector<int> stripIndices_;
    std::vector<int> stripLengths_;
};

}  // namespace m3g
