#include <m3g/Mesh.h>

#include "Check.h"

namespace m3g {

Mesh::Mesh(VertexBuffer* vertices, IndexBuffer* submesh, Appearance* appearance) {
    detail::requireNonNull(vertices, "Mesh::Mesh", "vertices");
    detail::requireNonNull(submesh, "Mesh::Mesh", "submesh");
    vertexBuffer_ = vertices;
    submeshes_.emplace_back(submesh);
    appearances_.emplace_back(appearance);
}

Mesh::Mesh(VertexBuffer* vertices, std::span<const Ref<IndexBuffer>> submeshes,
           std::span<const Ref<Appearance>> appearances) {
    const char* where = "Mesh::Mesh";
    detail::requireNonNull(vertices, where, "vertices");
    if (submeshes.data() == nullptr) detail::throwNull(where, "submeshes");
    for (std::size_t i = 0; i < submeshes.size(); ++i)
        if (!submeshes[i]) throw NullPointerException(detail::str(where, ": submeshes[", i, "] is null"));
    if (submeshes.empty()) detail::throwIAE(detail::str(where, ": submeshes is empty"));
    if (appearances.data() != nullptr && appearances.size() < submeshes.size())
        detail::throwIAE(detail::str(where, ": appearances has length ", appearances.size(), ", needs at least ",
                                     submeshes.size(), " (one per submesh)"));
    vertexBuffer_ = vertices;
    submeshes_.assign(submeshes.begin(), submeshes.end());
    if (appearances.data() != nullptr)
        appearances_.assign(appearances.begin(), appearances.begin() + static_cast<std::ptrdiff_t>(submeshes.size()));
    else
        appearances_.resize(submeshes.size());
}

Mesh::Mesh(const Mesh& other) = default;

Mesh::~Mesh() = default;

Object3D* Mesh::duplicateImpl(DuplicateMap&) const { return new Mesh(*this); }

void Mesh::setAppearance(int index, Appearance* appearance) {
    detail::requireIndex(index, getSubmeshCount(), "Mesh::setAppearance", "index");
    if (appearances_[index].get() != appearance) referencesChanged();
    appearances_[index] = appearance;
    touch();
}

Ref<Appearance> Mesh::getAppearance(int index) const {
    detail::requireIndex(index, getSubmeshCount(), "Mesh::getAppearance", "index");
    return appearances_[index];
}

Ref<IndexBuffer> Mesh::getIndexBuffer(int index) const {
    detail::requireIndex(index, getSubmeshCount(), "Mesh::getIndexBuffer", "index");
    return submeshes_[index];
}

void Mesh::collectReferences(std::vector<Object3D*>& out) const {
    Node::collectReferences(out);
    out.push_back(vertexBuffer_.get());
    for (std::size_t i = 0; i < submeshes_.size(); ++i) {
        out.push_back(submeshes_[i].get());
        if (appearances_[i]) out.push_back(appearances_[i].get());
    }
}

}  // namespace m3g
