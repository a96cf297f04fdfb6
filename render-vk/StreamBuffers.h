// Per-frame streaming memory of a renderer: the draws' uniform blocks (in
// host-visible chunks bound as dynamic uniform buffers) and the vertices of
// screen-space quads. Written while a frame is prepared; reused from the
// start once the frame has finished.
#pragma once

#include <cstdint>
#include <vector>

#include <m3g/frame/DrawList.h>

#include "Context.h"

namespace m3g::vk {

class StreamBuffers {
public:
    StreamBuffers(Context& ctx, VkDescriptorSetLayout uniformSetLayout);
    ~StreamBuffers();

    /// A slot holding a copy of `u`: the descriptor set and dynamic offset to bind.
    void uniforms(const frame::DrawUniforms& u, VkDescriptorSet& set, std::uint32_t& offset);
    /// The six vertices (position xyz, texcoord st, pad) of `quad`; returns
    /// the buffer and the byte offset of the first.
    VkBuffer quad(const frame::Quad& quad, VkDeviceSize& offset);
    /// A small zero-filled vertex buffer for absent streams.
    VkBuffer dummy() const noexcept { return dummy_.buffer; }

    /// A new frame starts writing at the beginning.
    void beginFrame() noexcept;
    /// The frame's GPU work has finished: grown-out-of buffers go.
    void endFrame() noexcept;

    StreamBuffers(const StreamBuffers&) = delete;
    StreamBuffers& operator=(const StreamBuffers&) = delete;

private:
    struct UniformChunk {
        Buffer buffer;
        VkDescriptorSet set = VK_NULL_HANDLE;
    };
    Context& ctx_;
    VkDescriptorSetLayout setLayout_;
    std::vector<UniformChunk> chunks_;
    std::size_t chunk_ = 0;
    std::uint32_t chunkOffset_ = 0;
    std::uint32_t stride_ = 0;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    Buffer quads_;
    std::vector<Buffer> retiredQuads_;
    VkDeviceSize quadOffset_ = 0;
    Buffer dummy_;
};

}  // namespace m3g::vk
