// A draw with every Vulkan object it needs already looked up or created
// (pipeline, descriptor sets, buffers): what Renderer's prepare step makes
// from a frame::Draw and Recorder records without failing or waiting.
#pragma once

#include <array>
#include <cstdint>

#include <m3g/frame/DrawList.h>

#include "Context.h"

namespace m3g::vk {

struct PreparedDraw {
    VkPipeline pipeline = VK_NULL_HANDLE;
    std::uint64_t pipelineKey = 0;
    VkDescriptorSet uniforms = VK_NULL_HANDLE;
    std::uint32_t uniformOffset = 0;
    VkDescriptorSet textures = VK_NULL_HANDLE;
    std::array<VkBuffer, frame::STREAM_COUNT> buffers{};
    std::array<VkDeviceSize, frame::STREAM_COUNT> offsets{}, strides{};
    VkBuffer indexBuffer = VK_NULL_HANDLE;  ///< null: a quad of 6 vertices, not indexed
    std::uint32_t count = 0;                ///< indices, or vertices of a quad
    frame::RasterState raster;
};

}  // namespace m3g::vk
