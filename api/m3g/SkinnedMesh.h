// javax.microedition.m3g.SkinnedMesh (JSR-184 1.1, SkinnedMesh).
#pragma once

#include <m3g/Export.h>

#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include <m3g/Group.h>
#include <m3g/Mesh.h>
#include <m3g/Transform.h>

namespace m3g::skin {
class InfluenceTable;
}  // namespace m3g::skin

namespace m3g {

/// A Mesh deformed by a skeleton of nodes (bones). The skeleton Group becomes
/// the mesh's only child: its getParent() is the mesh, and it is rendered,
/// picked, animated and duplicated as part of the mesh's subtree.
///
/// The per-vertex bookkeeping is done by addTransform, never at render time
/// (the founding paper's proposal): each bone node gets a dense bone index in
/// order of first use, its at-rest matrix (mesh space -> bone space) is
/// captured at that first use, and the weights go into a skin::InfluenceTable
/// with N = getLimits().maxTransformsPerVertex (value at construction).
class M3G_API SkinnedMesh : public Mesh {
public:
    /// Mesh checks, then NPE if `skeleton` is null and IAE if it already has
    /// a parent or is a World. On success the skeleton's parent is this mesh.
    SkinnedMesh(VertexBuffer* vertices, IndexBuffer* submesh, Appearance* appearance, Group* skeleton);
    SkinnedMesh(VertexBuffer* vertices, std::span<const Ref<IndexBuffer>> submeshes,
                std::span<const Ref<Appearance>> appearances, Group* skeleton);
    /// Unregisters this mesh from its bones and detaches the skeleton (its
    /// parent becomes null; it may outlive the mesh through other references).
    ~SkinnedMesh() override;

    /// Adds `weight` of `bone` to vertices [firstVertex, firstVertex + numVertices).
    /// NPE if bone is null; IAE if bone is not the skeleton or one of its
    /// descendants, if weight <= 0 or numVertices <= 0; IOOBE if
    /// firstVertex < 0 or firstVertex + numVertices > 65535.
    /// ArithmeticException if the at-rest matrix of a new bone is singular.
    void addTransform(Node* bone, int weight, int firstVertex, int numVertices);
    Ref<Group> getSkeleton() const noexcept { return skeleton_; }
    /// (1.1) The at-rest matrix of `bone` (mesh space -> bone space, captured
    /// by its first addTransform). NPE if either is null; IAE if bone is not
    /// in the skeleton. A bone of the skeleton that was never passed to
    /// addTransform leaves `transform` untouched (reference-core behaviour).
    void getBoneTransform(Node* bone, Transform* transform) const;
    /// (1.1) Number of vertices that `bone` influences (among the N kept
    /// influences of each vertex). Each non-null array receives, in vertex
    /// order, the vertex indices / normalised weights (weight divided by the
    /// sum of the vertex's kept weights); IAE if a non-null array is shorter
    /// than the count. NPE if bone is null; IAE if bone is not in the skeleton.
    /// A skeleton node never added returns 0.
    int getBoneVertices(Node* bone, std::span<int> indices = {}, std::span<float> weights = {}) const;

    const char* getClassName() const noexcept override { return "SkinnedMesh"; }
    /// The skeleton.
    void collectChildren(std::vector<Node*>& out) const override;

    // ---- Engine interface ----
    const skin::InfluenceTable& influenceTable() const noexcept { return *table_; }
    /// Bones in bone-index order (index = column of the influence table).
    int boneCount() const noexcept { return static_cast<int>(bones_.size()); }
    Node* bone(int index) const noexcept { return bones_[index].get(); }
    /// At-rest matrix (mesh space -> bone space) of bone `index`.
    const Transform& atRestTransform(int index) const noexcept { return atRest_[index]; }
    /// Bone index of `node`, or -1 if it was never added.
    int boneIndex(const Node* node) const noexcept;

    /// One successful addTransform call, as made (the Saver writes these as
    /// the transform references of the file: JSR-184 1.1 file format,
    /// section "Per-Class Data", SkinnedMesh).
    struct AddedTransform {
        int bone;         ///< bone index: the node is bone(bone)
        int weight;       ///< the integer weight as passed
        int firstVertex;
        int vertexCount;
    };
    /// Every successful addTransform call, in call order.
    std::span<const AddedTransform> addedTransforms() const noexcept { return added_; }

protected:
    /// Copies the bookkeeping; the skeleton is copied by duplicateImpl and
    /// the bones are remapped to the copies in remapReferences.
    SkinnedMesh(const SkinnedMesh& other);
    /// Order: Mesh references, then the skeleton.
    void collectReferences(std::vector<Object3D*>& out) const override;
    Object3D* duplicateImpl(DuplicateMap& map) const override;
    void remapReferences(const DuplicateMap& map) override;

private:
    void attachSkeleton(Group* skeleton);
    void requireInSkeleton(const Node* bone, const char* where) const;

    Ref<Group> skeleton_;
    std::vector<Ref<Node>> bones_;            // dense bone index -> node
    std::vector<Transform> atRest_;           // dense bone index -> at-rest matrix
    std::unordered_map<const Node*, int> boneIndex_;
    // Behind a pointer: the public headers include std and api only.
    std::unique_ptr<skin::InfluenceTable> table_;
    std::vector<AddedTransform> added_;       // addTransform calls, in order
};

}  // namespace m3g
