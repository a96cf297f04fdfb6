// javax.microedition.m3g.MorphingMesh (JSR-184 1.1, MorphingMesh).
#pragma once

#include <m3g/Export.h>

#include <span>
#include <vector>

#include <m3g/Mesh.h>

namespace m3g {

/// A Mesh whose vertices are B + sum_i w_i (T_i - B) for a base buffer B and
/// morph targets T_i. This class stores the targets and weights; the
/// deformation itself is done by the renderer/kernels.
class M3G_API MorphingMesh : public Mesh {
public:
    /// Mesh checks, then NPE if `targets` is null or has a null element and
    /// IAE if `targets` is empty. All weights start at 0.
    MorphingMesh(VertexBuffer* base, std::span<const Ref<VertexBuffer>> targets, IndexBuffer* submesh,
                 Appearance* appearance);
    MorphingMesh(VertexBuffer* base, std::span<const Ref<VertexBuffer>> targets,
                 std::span<const Ref<IndexBuffer>> submeshes, std::span<const Ref<Appearance>> appearances);
    ~MorphingMesh() override;

    /// IOOBE unless 0 <= index < getMorphTargetCount().
    Ref<VertexBuffer> getMorphTarget(int index) const;
    int getMorphTargetCount() const noexcept { return static_cast<int>(targets_.size()); }
    /// Copies the first getMorphTargetCount() values (any real value is
    /// allowed). NPE if null; IAE if shorter than getMorphTargetCount().
    void setWeights(std::span<const float> weights);
    /// NPE if null; IAE if shorter than getMorphTargetCount().
    void getWeights(std::span<float> weights) const;

    const char* getClassName() const noexcept override { return "MorphingMesh"; }
    /// MORPH_WEIGHTS besides the Node properties.
    bool isAnimatable(int property) const noexcept override;
    /// MORPH_WEIGHTS: value[i] -> weight i; with fewer components than
    /// targets the remaining weights become 0, extra components are ignored.
    void updateProperty(int property, std::span<const float> value) override;

    // ---- Engine interface ----
    std::span<const float> weights() const noexcept { return weights_; }
    VertexBuffer* morphTarget(int index) const noexcept { return targets_[index].get(); }

protected:
    /// Shares the targets, copies the weights.
    MorphingMesh(const MorphingMesh& other);
    /// Order: Mesh references, then the morph targets in order.
    void collectReferences(std::vector<Object3D*>& out) const override;
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    void initTargets(std::span<const Ref<VertexBuffer>> targets);

    std::vector<Ref<VertexBuffer>> targets_;
    std::vector<float> weights_;
};

}  // namespace m3g
