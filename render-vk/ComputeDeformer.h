// The compute-shader path of skinning and morphing (Graphics3D's m3g-vk
// extension SKINNING_COMPUTE): shaders/skin.comp and morph.comp run the
// formulas of skin::SkinningJob and skin::MorphJob on the device, from the
// inputs MeshDeformer prepares (Output::InputsOnly: change detection, the
// influence table, the palette once per bone), and write the float streams
// of a vertex mirror that the draw then reads.
//
// Synchronisation: the renderer records every deformation of a frame into
// one command buffer (frameCommands) submitted in the same batch as, and
// before, the frame's draws; finishFrame ends it with one barrier from
// compute-shader writes to vertex-attribute reads. A mirror or an input
// buffer is never rewritten while a recorded, unfinished frame reads it.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "Context.h"
#include "DeformParams.h"
#include <m3g/frame/DeformInputs.h>

namespace m3g::vk {

/// Per-mesh GPU state of the compute path (kept in ResourceCache's side
/// table, never in the scene object).
struct GpuDeformState {
    /// The static inputs: skinning: bone indices, weights, raw positions,
    /// normals; morphing: per attribute the base then the targets.
    Buffer inputs;
    std::uint64_t inputStamp = 0;  ///< MeshDeformer::inputStamp() of `inputs`
    bool hasInputs = false;
    /// Element offsets into `inputs` (kNoStream: absent).
    std::uint32_t bonesIn = 0, weightsIn = 0, positionsIn = 0, normalsIn = 0, tableVertices = 0;
    std::array<std::uint32_t, frame::kMorphAttributes> valuesIn{};
    /// The per-dispatch data: the palette or the morph weights.
    Buffer frameData;
    std::uint64_t frameDataUsed = 0;  ///< frame number that last recorded with frameData
};

class ComputeDeformer {
public:
    explicit ComputeDeformer(Context& ctx);
    ~ComputeDeformer();

    /// Element (float) offsets of the output streams in the mirror buffer;
    /// kNoStream = not written by this dispatch.
    struct Streams {
        std::uint32_t positions = kNoStream;
        std::uint32_t normals = kNoStream;
        std::uint32_t colors = kNoStream;  ///< RGBA per vertex
        std::array<std::uint32_t, 2> texCoords{kNoStream, kNoStream};  ///< 3 floats per vertex
    };

    /// Records skinning of `in` (MeshDeformer::skinInputs(), or plain arrays
    /// of the same layout) into `out`: positions (xyz, scale and bias
    /// applied) at streams.positions, normals (xyz, unit) at streams.normals
    /// when `in` has normals. Uploads the static inputs first when
    /// `inputStamp` differs from the state's. `out` needs STORAGE_BUFFER
    /// usage. Throws VulkanError when the mesh is larger than one dispatch.
    void recordSkin(VkCommandBuffer cmd, GpuDeformState& state, const frame::SkinInputs& in,
                    std::uint64_t inputStamp, const Buffer& out, const Streams& streams);

    /// Records morphing of every present attribute (`attributes` indexed as
    /// MeshDeformer::kMorph*, `weights` one per target) into `out`:
    /// positions and normals (renormalised) xyz, colours RGBA clamped to
    /// [0, 1], texture coordinates padded to 3 floats with zeros.
    void recordMorph(VkCommandBuffer cmd, GpuDeformState& state,
                     std::span<const frame::MorphAttributeInputs> attributes, std::span<const float> weights,
                     int vertexCount, std::uint64_t inputStamp, const Buffer& out, const Streams& streams);

    /// Compute-shader writes before vertex-attribute reads (and `dstStage` /
    /// `dstAccess` besides, e.g. host reads in tests).
    static void barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 dstStage = 0, VkAccessFlags2 dstAccess = 0);

    /// The command buffer of this frame's deformations, begun on first use.
    VkCommandBuffer frameCommands();
    /// Ends the frame's command buffer with barrier() and returns it, to be
    /// submitted before the draws; VK_NULL_HANDLE when nothing was recorded.
    VkCommandBuffer finishFrame();
    /// Once the GPU has finished the frame: frees replaced buffers and the
    /// frame's descriptor sets; the next recording starts a new frame.
    void endFrame();
    /// Frees `state`'s buffers once the current frame is finished.
    void release(GpuDeformState& state);

    ComputeDeformer(const ComputeDeformer&) = delete;
    ComputeDeformer& operator=(const ComputeDeformer&) = delete;

private:
    void retire(Buffer& buffer);
    /// `state.frameData` with at least `bytes`, not read by a recorded frame.
    void* frameData(GpuDeformState& state, std::size_t bytes);
    VkDescriptorSet descriptorSet(const Buffer& frameData, const Buffer& inputs, const Buffer& out);
    void dispatch(VkCommandBuffer cmd, VkPipeline pipeline, VkDescriptorSet set, const void* params,
                  std::uint32_t paramBytes, std::uint32_t vertexCount);

    Context& ctx_;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline skin_ = VK_NULL_HANDLE, morph_ = VK_NULL_HANDLE;
    std::vector<VkDescriptorPool> pools_;
    std::size_t pool_ = 0;          // pools_[pool_] is the one being filled
    std::uint32_t poolUsed_ = 0;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    bool recording_ = false;
    std::uint64_t frame_ = 1;
    std::vector<Buffer> retired_;
};

}  // namespace m3g::vk
