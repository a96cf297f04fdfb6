// Draws Dear ImGui's draw lists with our own small pipeline. The Debian
// libimgui's Vulkan backend calls vk* as linked functions, which clash with
// volk's function pointers of the same names, so only ImGui's core and GLFW
// backend are used and the drawing is done here.
#include <m3g/vk/ImGuiOverlay.h>

#include <algorithm>
#include <cstring>
#include <unordered_map>
#include <vector>

#include <imgui.h>

#include <m3g/Exception.h>
#include <m3g/Image2D.h>

#include "Context.h"
#include "Swapchain.h"
#include "imgui_frag.h"
#include "imgui_vert.h"

namespace m3g::vk {

namespace {

struct UiTexture {
    Image image;
    VkDescriptorSet set = VK_NULL_HANDLE;         // bilinear
    VkDescriptorSet nearestSet = VK_NULL_HANDLE;  // nearest-neighbour, made on first use
    std::uint32_t revision = 0;
};

}  // namespace

struct ImGuiOverlay::Impl {
    std::shared_ptr<Context> ctx = Context::shared();
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkFormat pipelineFormat = VK_FORMAT_UNDEFINED;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkSampler sampler = VK_NULL_HANDLE;
    VkSampler nearestSampler = VK_NULL_HANDLE;
    UiTexture font;
    std::unordered_map<std::uint64_t, UiTexture> images;  // by Image2D object id
    Buffer vertices, indices;

    Impl();
    ~Impl();
    void buildPipeline(VkFormat format);
    UiTexture upload(std::uint32_t width, std::uint32_t height, const std::uint8_t* rgba, UiTexture texture);
    VkDescriptorSet allocateSet();
    void writeSet(VkDescriptorSet set, VkSampler with, VkImageView view);
    void ensureBuffers(std::size_t vertexBytes, std::size_t indexBytes);
};

ImGuiOverlay::Impl::Impl() {
    VkDevice device = ctx->device();
    VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                         VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo li{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    li.bindingCount = 1;
    li.pBindings = &binding;
    check(vkCreateDescriptorSetLayout(device, &li, nullptr, &setLayout), "vkCreateDescriptorSetLayout (UI)");
    VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, 4 * sizeof(float)};
    VkPipelineLayoutCreateInfo pli{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pli.setLayoutCount = 1;
    pli.pSetLayouts = &setLayout;
    pli.pushConstantRangeCount = 1;
    pli.pPushConstantRanges = &push;
    check(vkCreatePipelineLayout(device, &pli, nullptr, &layout), "vkCreatePipelineLayout (UI)");
    pool = createDescriptorPool(device, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 256, 1, "UI",
                                VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT);
    VkSamplerCreateInfo si{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    si.magFilter = si.minFilter = VK_FILTER_LINEAR;
    si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    si.maxLod = 0.0f;
    check(vkCreateSampler(device, &si, nullptr, &sampler), "vkCreateSampler (UI)");
    si.magFilter = si.minFilter = VK_FILTER_NEAREST;
    check(vkCreateSampler(device, &si, nullptr, &nearestSampler), "vkCreateSampler (UI, nearest)");
}

ImGuiOverlay::Impl::~Impl() {
    VkDevice device = ctx->device();
    ctx->waitIdle();
    ctx->destroy(font.image);
    for (auto& [id, t] : images) ctx->destroy(t.image);
    ctx->destroy(vertices);
    ctx->destroy(indices);
    vkDestroySampler(device, sampler, nullptr);
    vkDestroySampler(device, nearestSampler, nullptr);
    vkDestroyDescriptorPool(device, pool, nullptr);
    if (pipeline) vkDestroyPipeline(device, pipeline, nullptr);
    vkDestroyPipelineLayout(device, layout, nullptr);
    vkDestroyDescriptorSetLayout(device, setLayout, nullptr);
}

void ImGuiOverlay::Impl::buildPipeline(VkFormat format) {
    VkDevice device = ctx->device();
    if (pipeline) vkDestroyPipeline(device, pipeline, nullptr);
    VkShaderModule vert = createShaderModule(device, imgui_vert, sizeof(imgui_vert));
    VkShaderModule frag = createShaderModule(device, imgui_frag, sizeof(imgui_frag));
    VkPipelineShaderStageCreateInfo stages[2]{{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                              {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = vert;
    stages[0].pName = "main";
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = frag;
    stages[1].pName = "main";
    VkVertexInputBindingDescription binding{0, sizeof(ImDrawVert), VK_VERTEX_INPUT_RATE_VERTEX};
    VkVertexInputAttributeDescription attributes[3]{
        {0, 0, VK_FORMAT_R32G32_SFLOAT, static_cast<std::uint32_t>(offsetof(ImDrawVert, pos))},
        {1, 0, VK_FORMAT_R32G32_SFLOAT, static_cast<std::uint32_t>(offsetof(ImDrawVert, uv))},
        {2, 0, VK_FORMAT_R8G8B8A8_UNORM, static_cast<std::uint32_t>(offsetof(ImDrawVert, col))}};
    VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vi.vertexBindingDescriptionCount = 1;
    vi.pVertexBindingDescriptions = &binding;
    vi.vertexAttributeDescriptionCount = 3;
    vi.pVertexAttributeDescriptions = attributes;
    VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    vp.viewportCount = vp.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    rs.polygonMode = VK_POLYGON_MODE_FILL;
    rs.cullMode = VK_CULL_MODE_NONE;
    rs.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineColorBlendAttachmentState blend{};
    blend.blendEnable = VK_TRUE;
    blend.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
    blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    blend.colorBlendOp = VK_BLEND_OP_ADD;
    blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    blend.alphaBlendOp = VK_BLEND_OP_ADD;
    blend.colorWriteMask = 0xF;
    VkPipelineColorBlendStateCreateInfo cb{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    cb.attachmentCount = 1;
    cb.pAttachments = &blend;
    VkPipelineDepthStencilStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    const VkDynamicState dynamic[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dy{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dy.dynamicStateCount = 2;
    dy.pDynamicStates = dynamic;
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachmentFormats = &format;
    VkGraphicsPipelineCreateInfo ci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    ci.pNext = &rendering;
    ci.stageCount = 2;
    ci.pStages = stages;
    ci.pVertexInputState = &vi;
    ci.pInputAssemblyState = &ia;
    ci.pViewportState = &vp;
    ci.pRasterizationState = &rs;
    ci.pMultisampleState = &ms;
    ci.pDepthStencilState = &ds;
    ci.pColorBlendState = &cb;
    ci.pDynamicState = &dy;
    ci.layout = layout;
    const VkResult r = vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &ci, nullptr, &pipeline);
    vkDestroyShaderModule(device, vert, nullptr);
    vkDestroyShaderModule(device, frag, nullptr);
    check(r, "vkCreateGraphicsPipelines (UI)");
    pipelineFormat = format;
}

UiTexture ImGuiOverlay::Impl::upload(std::uint32_t width, std::uint32_t height, const std::uint8_t* rgba,
                                     UiTexture texture) {
    if (!texture.image.image || texture.image.width != width || texture.image.height != height) {
        ctx->waitIdle();
        ctx->destroy(texture.image);
        texture.image = ctx->createImage(width, height, VK_FORMAT_R8G8B8A8_UNORM,
                                         VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    }
    const VkDeviceSize bytes = static_cast<VkDeviceSize>(width) * height * 4;
    Buffer staging = ctx->createHostBuffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::memcpy(staging.mapped, rgba, bytes);
    const VkImage image = texture.image.image;
    ctx->submitNow([&](VkCommandBuffer cmd) {
        imageBarrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT);
        copyBufferToImage(cmd, staging.buffer, image, width, height);
        imageBarrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    });
    ctx->destroy(staging);
    if (!texture.set) texture.set = allocateSet();
    writeSet(texture.set, sampler, texture.image.view);
    // The image may be new (another size): the nearest set follows it.
    if (texture.nearestSet) writeSet(texture.nearestSet, nearestSampler, texture.image.view);
    return texture;
}

VkDescriptorSet ImGuiOverlay::Impl::allocateSet() {
    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = pool;
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &setLayout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    check(vkAllocateDescriptorSets(ctx->device(), &ai, &set), "vkAllocateDescriptorSets (UI)");
    return set;
}

void ImGuiOverlay::Impl::writeSet(VkDescriptorSet set, VkSampler with, VkImageView view) {
    VkDescriptorImageInfo ii{with, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w.pImageInfo = &ii;
    vkUpdateDescriptorSets(ctx->device(), 1, &w, 0, nullptr);
}

void ImGuiOverlay::Impl::ensureBuffers(std::size_t vertexBytes, std::size_t indexBytes) {
    // Frames are finished before the next one records, so one pair suffices.
    if (vertices.size < vertexBytes) {
        ctx->destroy(vertices);
        vertices = ctx->createHostBuffer(std::max<VkDeviceSize>(vertexBytes * 2, 64 * 1024),
                                         VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    }
    if (indices.size < indexBytes) {
        ctx->destroy(indices);
        indices = ctx->createHostBuffer(std::max<VkDeviceSize>(indexBytes * 2, 32 * 1024), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    }
}

ImGuiOverlay::ImGuiOverlay() : impl_(std::make_unique<Impl>()) {
    if (!ImGui::GetCurrentContext()) throw IllegalStateException("m3g::vk::ImGuiOverlay: no current ImGui context");
    uploadFonts();
}

void ImGuiOverlay::uploadFonts() {
    // Builds the atlas too: ImGui::NewFrame requires it built.
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    impl_->font = impl_->upload(static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(h), pixels, impl_->font);
    ImGui::GetIO().Fonts->SetTexID(impl_->font.set);
}

ImGuiOverlay::~ImGuiOverlay() = default;

void* ImGuiOverlay::texture(const Image2D& image, bool nearest) {
    UiTexture& t = impl_->images[image.getObjectId()];
    if (!t.image.image || t.revision != image.getRevision()) {
        std::vector<std::uint8_t> rgba;
        image.getPixelsRGBA8(rgba);
        t = impl_->upload(static_cast<std::uint32_t>(image.getWidth()), static_cast<std::uint32_t>(image.getHeight()),
                          rgba.data(), t);
        t.revision = image.getRevision();
    }
    if (!nearest) return t.set;
    if (!t.nearestSet) {
        t.nearestSet = impl_->allocateSet();
        impl_->writeSet(t.nearestSet, impl_->nearestSampler, t.image.view);
    }
    return t.nearestSet;
}

void ImGuiOverlay::record(void* cmdPointer, Swapchain& swapchain) {
    if (!ImGui::GetCurrentContext()) return;
    ImDrawData* data = ImGui::GetDrawData();
    if (!data || !data->Valid || data->TotalVtxCount == 0) return;
    auto cmd = static_cast<VkCommandBuffer>(cmdPointer);
    Impl& d = *impl_;
    if (d.pipelineFormat != swapchain.format()) d.buildPipeline(swapchain.format());

    d.ensureBuffers(static_cast<std::size_t>(data->TotalVtxCount) * sizeof(ImDrawVert),
                    static_cast<std::size_t>(data->TotalIdxCount) * sizeof(ImDrawIdx));
    auto* vtx = static_cast<ImDrawVert*>(d.vertices.mapped);
    auto* idx = static_cast<ImDrawIdx*>(d.indices.mapped);
    for (int n = 0; n < data->CmdListsCount; ++n) {
        const ImDrawList* list = data->CmdLists[n];
        std::memcpy(vtx, list->VtxBuffer.Data, static_cast<std::size_t>(list->VtxBuffer.Size) * sizeof(ImDrawVert));
        std::memcpy(idx, list->IdxBuffer.Data, static_cast<std::size_t>(list->IdxBuffer.Size) * sizeof(ImDrawIdx));
        vtx += list->VtxBuffer.Size;
        idx += list->IdxBuffer.Size;
    }

    const VkExtent2D extent = swapchain.extent();
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = swapchain.view();
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = {{0, 0}, extent};
    ri.layerCount = 1;
    ri.colorAttachmentCount = 1;
    ri.pColorAttachments = &color;
    vkCmdBeginRendering(cmd, &ri);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, d.pipeline);
    VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &d.vertices.buffer, &zero);
    vkCmdBindIndexBuffer(cmd, d.indices.buffer, 0, sizeof(ImDrawIdx) == 2 ? VK_INDEX_TYPE_UINT16 : VK_INDEX_TYPE_UINT32);
    const VkViewport viewport{0, 0, static_cast<float>(extent.width), static_cast<float>(extent.height), 0, 1};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    // ImGui's display rectangle onto the whole image (the swapchain may be
    // larger than the window in points on high-DPI screens).
    const float scale[2] = {2.0f / data->DisplaySize.x, 2.0f / data->DisplaySize.y};
    const float push[4] = {scale[0], scale[1], -1.0f - data->DisplayPos.x * scale[0],
                           -1.0f - data->DisplayPos.y * scale[1]};
    vkCmdPushConstants(cmd, d.layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(push), push);
    const float fx = static_cast<float>(extent.width) / data->DisplaySize.x;
    const float fy = static_cast<float>(extent.height) / data->DisplaySize.y;
    std::uint32_t vertexBase = 0, indexBase = 0;
    VkDescriptorSet bound = VK_NULL_HANDLE;
    for (int n = 0; n < data->CmdListsCount; ++n) {
        const ImDrawList* list = data->CmdLists[n];
        for (const ImDrawCmd& c : list->CmdBuffer) {
            if (c.UserCallback) {
                if (c.UserCallback != ImDrawCallback_ResetRenderState) c.UserCallback(list, &c);
                continue;
            }
            const float x0 = std::max(0.0f, (c.ClipRect.x - data->DisplayPos.x) * fx);
            const float y0 = std::max(0.0f, (c.ClipRect.y - data->DisplayPos.y) * fy);
            const float x1 = std::min(static_cast<float>(extent.width), (c.ClipRect.z - data->DisplayPos.x) * fx);
            const float y1 = std::min(static_cast<float>(extent.height), (c.ClipRect.w - data->DisplayPos.y) * fy);
            if (x1 <= x0 || y1 <= y0) continue;
            const VkRect2D scissor{{static_cast<std::int32_t>(x0), static_cast<std::int32_t>(y0)},
                                   {static_cast<std::uint32_t>(x1 - x0), static_cast<std::uint32_t>(y1 - y0)}};
            vkCmdSetScissor(cmd, 0, 1, &scissor);
            auto set = static_cast<VkDescriptorSet>(c.TextureId ? c.TextureId : d.font.set);
            if (set != bound) {
                vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, d.layout, 0, 1, &set, 0, nullptr);
                bound = set;
            }
            vkCmdDrawIndexed(cmd, c.ElemCount, 1, indexBase + c.IdxOffset,
                             static_cast<std::int32_t>(vertexBase + c.VtxOffset), 0);
        }
        vertexBase += static_cast<std::uint32_t>(list->VtxBuffer.Size);
        indexBase += static_cast<std::uint32_t>(list->IdxBuffer.Size);
    }
    vkCmdEndRendering(cmd);
}

}  // namespace m3g::vk
