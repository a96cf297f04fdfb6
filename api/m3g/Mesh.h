// javax.microedition.m3g.Mesh (JSR-184 1.1, Mesh).
#pragma once

#include <m3g/Export.h>

#include <span>
#include <vector>

#include <m3g/Appearance.h>
#include <m3g/IndexBuffer.h>
#include <m3g/Node.h>
#include <m3g/VertexBuffer.h>

namespace m3g {

/// A VertexBuffer shared by one or more submeshes, each an IndexBuffer with
/// an Appearance (a submesh with a null appearance is neither rendered nor
/// picked).
class M3G_API Mesh : public Node {
public:
    /// One submesh. NPE if `vertices` or `submesh` is null; `appearance` may be null.
    Mesh(VertexBuffer* vertices, IndexBuffer* submesh, Appearance* appearance);
    /// NPE if `vertices` or `submeshes` is null (data() == nullptr) or an
    /// element of `submeshes` is null; IAE if `submeshes` is empty or
    /// `appearances` is non-null and shorter than `submeshes`. A null
    /// `appearances` means no appearance for any submesh; extra entries are
    /// ignored.
    Mesh(VertexBuffer* vertices, std::span<const Ref<IndexBuffer>> submeshes,
         std::span<const Ref<Appearance>> appearances);
    ~Mesh() override;

    /// IOOBE unless 0 <= index < getSubmeshCount(); `appearance` may be null.
    void setAppearance(int index, Appearance* appearance);
    /// IOOBE unless 0 <= index < getSubmeshCount().
    Ref<Appearance> getAppearance(int index) const;
    /// IOOBE unless 0 <= index < getSubmeshCount().
    Ref<IndexBuffer> getIndexBuffer(int index) const;
    Ref<VertexBuffer> getVertexBuffer() const noexcept { return vertexBuffer_; }
    int getSubmeshCount() const noexcept { return static_cast<int>(submeshes_.size()); }

    const char* getClassName() const noexcept override { return "Mesh"; }

    // ---- Engine interface ----
    VertexBuffer* vertexBuffer() const noexcept { return vertexBuffer_.get(); }
    IndexBuffer* indexBuffer(int index) const noexcept { return submeshes_[index].get(); }
    Appearance* appearance(int index) const noexcept { return appearances_[index].get(); }

protected:
    /// Shares the vertex buffer, index buffers and appearances.
    Mesh(const Mesh& other);
    /// Order: alignment references (Node), vertex buffer, then for each
    /// submesh its index buffer followed by its appearance (null appearances omitted).
    void collectReferences(std::vector<Object3D*>& out) const override;
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    Ref<VertexBuffer> vertexBuffer_;
    std::vector<Ref<IndexBuffer>> submeshes_;
    std::vector<Ref<Appearance>> appearances_;  // same size as submeshes_
};

}  // namespace m3g
