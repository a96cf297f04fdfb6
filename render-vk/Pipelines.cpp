#include "Pipelines.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

#include "PipelineCacheFile.h"

#include "m3g_frag.h"  // generated from shaders/ by glslangValidator at build time
#include "m3g_vert.h"

namespace m3g::vk {

namespace {

// JSR-184 1.1, CompositingMode: the same factors on colour and alpha.
VkPipelineColorBlendAttachmentState blendState(std::uint8_t blend, std::uint8_t mask) {
    VkPipelineColorBlendAttachmentState b{};
    b.colorWriteMask = mask;
    b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
    auto factors = [&](VkBlendFactor src, VkBlendFactor dst) {
        b.blendEnable = VK_TRUE;
        b.srcColorBlendFactor = b.srcAlphaBlendFactor = src;
        b.dstColorBlendFactor = b.dstAlphaBlendFactor = dst;
    };
    switch (blend) {
    case 1: factors(VK_BLEND_FACTOR_SRC_ALPHA, VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA); break;
    case 2: factors(VK_BLEND_FACTOR_SRC_ALPHA, VK_BLEND_FACTOR_ONE); break;
    case 3: factors(VK_BLEND_FACTOR_DST_COLOR, VK_BLEND_FACTOR_ZERO); break;
    case 4: factors(VK_BLEND_FACTOR_DST_COLOR, VK_BLEND_FACTOR_SRC_COLOR); break;
    default: b.blendEnable = VK_FALSE; break;
    }
    return b;
}

}  // namespace

Pipelines::Pipelines(Context& ctx, std::size_t capacity) : ctx_(ctx), capacity_(std::max<std::size_t>(1, capacity)) {
    VkDevice device = ctx.device();
    VkDescriptorSetLayoutBinding ub{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1,
                                    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo li{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    li.bindingCount = 1;
    li.pBindings = &ub;
    check(vkCreateDescriptorSetLayout(device, &li, nullptr, &uniformSet_), "vkCreateDescriptorSetLayout");
    VkDescriptorSetLayoutBinding tb{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
    li.pBindings = &tb;
    check(vkCreateDescriptorSetLayout(device, &li, nullptr, &textureSet_), "vkCreateDescriptorSetLayout");
    std::array<VkDescriptorSetLayout, 2> sets{uniformSet_, textureSet_};
    VkPipelineLayoutCreateInfo pl{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pl.setLayoutCount = 2;
    pl.pSetLayouts = sets.data();
    check(vkCreatePipelineLayout(device, &pl, nullptr, &layout_), "vkCreatePipelineLayout");
    vert_ = createShaderModule(device, m3g_vert, sizeof(m3g_vert));
    frag_ = createShaderModule(device, m3g_frag, sizeof(m3g_frag));
    cachePath_ = pipelineCachePath(ctx.properties());
    onDisk_ = readPipelineCache(cachePath_, ctx.properties());
    const std::vector<std::uint8_t>& seed = onDisk_;
    VkPipelineCacheCreateInfo ci{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
    ci.initialDataSize = seed.size();
    ci.pInitialData = seed.empty() ? nullptr : seed.data();
    if (vkCreatePipelineCache(device, &ci, nullptr, &cache_) != VK_SUCCESS) {
        // A driver may refuse data it wrote itself once updated: start empty.
        ci.initialDataSize = 0;
        ci.pInitialData = nullptr;
        check(vkCreatePipelineCache(device, &ci, nullptr, &cache_), "vkCreatePipelineCache");
    }
    ctx.pipelineCacheBytesLoaded += seed.size();
}

void Pipelines::saveCache() noexcept {
    if (cachePath_.empty() || unsaved_ == 0) return;
    std::size_t size = 0;
    if (vkGetPipelineCacheData(ctx_.device(), cache_, &size, nullptr) != VK_SUCCESS || size == 0) return;
    std::vector<std::uint8_t> data;
    try {
        data.resize(size);
    } catch (...) {
        return;
    }
    if (vkGetPipelineCacheData(ctx_.device(), cache_, &size, data.data()) != VK_SUCCESS) return;
    data.resize(size);
    // Nothing new for the file: lavapipe's cache data is its header alone
    // whatever was compiled, so every `m3g render` process after the first
    // wrote the same 32 bytes through a temporary file and a rename.
    if (data != onDisk_ && writePipelineCache(cachePath_, data)) {
        ++ctx_.pipelineCacheSaves;
        onDisk_ = std::move(data);
    }
    unsaved_ = 0;
    lastSave_ = std::chrono::steady_clock::now();
}

Pipelines::~Pipelines() {
    VkDevice device = ctx_.device();
    saveCache();
    for (auto& [key, entry] : pipelines_) destroy(entry.pipeline);
    vkDestroyPipelineCache(device, cache_, nullptr);
    vkDestroyShaderModule(device, vert_, nullptr);
    vkDestroyShaderModule(device, frag_, nullptr);
    vkDestroyPipelineLayout(device, layout_, nullptr);
    vkDestroyDescriptorSetLayout(device, uniformSet_, nullptr);
    vkDestroyDescriptorSetLayout(device, textureSet_, nullptr);
}

VkPipeline Pipelines::get(const PipelineKey& key) {
    auto it = pipelines_.find(key.packed());
    if (it == pipelines_.end()) {
        it = pipelines_.emplace(key.packed(), Entry{create(key), 0}).first;
        ++unsaved_;
    }
    it->second.lastFrame = frame_;
    return it->second.pipeline;
}

void Pipelines::destroy(VkPipeline pipeline) noexcept {
    vkDestroyPipeline(ctx_.device(), pipeline, nullptr);
    --ctx_.livePipelines;
}

void Pipelines::endFrame() {
    if (pipelines_.size() > capacity_) {
        // Oldest first; this frame's stay even beyond the capacity (a frame
        // that needs them all would otherwise recreate them every frame).
        std::vector<std::pair<std::uint64_t, std::uint64_t>> byAge;  // (lastFrame, key)
        for (const auto& [key, entry] : pipelines_)
            if (entry.lastFrame < frame_) byAge.emplace_back(entry.lastFrame, key);
        const std::size_t excess = std::min(pipelines_.size() - capacity_, byAge.size());
        std::partial_sort(byAge.begin(), byAge.begin() + static_cast<std::ptrdiff_t>(excess), byAge.end());
        for (std::size_t i = 0; i < excess; ++i) {
            auto it = pipelines_.find(byAge[i].second);
            destroy(it->second.pipeline);
            pipelines_.erase(it);
            ++ctx_.pipelinesEvicted;
        }
        if (excess > 0 && createdThroughCache_ > 4 * capacity_) {
            // Every pipeline is independent of the cache it was made with.
            VkPipelineCache fresh = VK_NULL_HANDLE;
            VkPipelineCacheCreateInfo ci{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
            check(vkCreatePipelineCache(ctx_.device(), &ci, nullptr, &fresh), "vkCreatePipelineCache");
            vkDestroyPipelineCache(ctx_.device(), cache_, nullptr);
            cache_ = fresh;
            createdThroughCache_ = 0;
            ++cacheResets_;
        }
    }
    // New pipelines reach the file after the frame that made them (a
    // one-frame `m3g render` process saves once), at most every 2 s while
    // a viewer keeps meeting new states, and when the renderer goes.
    if (unsaved_ > 0 && (lastSave_ == std::chrono::steady_clock::time_point{} ||
                         std::chrono::steady_clock::now() - lastSave_ > std::chrono::seconds(2)))
        saveCache();
    ++frame_;
}

void Pipelines::prewarm(std::uint8_t samples) {
    // Every blend mode, unlit and lit by the commonest light setups (none,
    // one directional light, an ambient and a directional light; no
    // specular), untextured and with an RGB texture modulated on unit 0
    // (the commonest textured draw). The light setup is part of the key
    // (m3g.vert's LIGHT_COUNT and LIGHT_MODES), so other setups are created
    // at their first draw.
    struct LightSetup {
        std::uint8_t lighting, count;
        std::uint16_t modes;
    };
    constexpr LightSetup kSetups[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {1, 2, 0 | (1 << 2)}};
    std::vector<PipelineKey> keys;
    for (std::uint8_t blend = 0; blend < 5; ++blend) {
        for (const LightSetup& setup : kSetups) {
            PipelineKey key;
            key.blend = blend;
            key.samples = samples;
            key.lighting = setup.lighting;
            key.lightCount = setup.count;
            key.lightModes = setup.modes;
            key.specular = 0;
            keys.push_back(key);
            key.texFunc[0] = 2;  // TEX_MODULATE
            key.texFormat[0] = 1;
            keys.push_back(key);
        }
    }
    createMissing(keys);
    for (const PipelineKey& key : keys) get(key);
}

VkPipeline Pipelines::create(const PipelineKey& key) {
    const VkPipeline pipeline = build(key);
    ++createdThroughCache_;
    return pipeline;
}

void Pipelines::createMissing(std::span<const PipelineKey> keys) {
    std::vector<PipelineKey> missing;
    std::uint64_t last = ~0ull;
    for (const PipelineKey& key : keys) {
        const std::uint64_t packed = key.packed();
        if (packed == last) continue;  // runs of draws in one state: one look-up
        last = packed;
        if (pipelines_.count(packed) != 0) continue;
        bool listed = false;
        for (const PipelineKey& m : missing) listed = listed || m.packed() == packed;
        if (!listed) missing.push_back(key);
    }
    if (missing.size() < 2) return;  // get() creates a lone one where it is needed
    std::vector<VkPipeline> made(missing.size(), VK_NULL_HANDLE);
    std::vector<std::exception_ptr> errors(missing.size());
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        for (std::size_t i; (i = next++) < missing.size();) {
            try {
                made[i] = build(missing[i]);
            } catch (...) {
                errors[i] = std::current_exception();
            }
        }
    };
    const std::size_t threads = std::min<std::size_t>(missing.size(), std::max(1u, std::thread::hardware_concurrency()));
    std::vector<std::thread> helpers;
    for (std::size_t t = 1; t < threads; ++t) {
        try {
            helpers.emplace_back(work);
        } catch (const std::system_error&) {
            break;  // no more threads: the ones running (and this one) do the rest
        }
    }
    work();
    for (std::thread& t : helpers) t.join();
    std::exception_ptr first;
    for (std::size_t i = 0; i < missing.size(); ++i) {
        if (made[i] != VK_NULL_HANDLE) {
            pipelines_.emplace(missing[i].packed(), Entry{made[i], frame_});
            ++unsaved_;
            ++createdThroughCache_;
        }
        if (errors[i] && !first) first = errors[i];
    }
    if (first) std::rethrow_exception(first);
}

VkPipeline Pipelines::build(const PipelineKey& key) const {
    std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
    // m3g.vert's constant_ids 0..8: LIGHTING, TWO_SIDED, LIGHT_COUNT,
    // LIGHT_MODES, SPECULAR, then the outputs m3g.frag reads: TEX0_USED,
    // TEX1_USED, FOG_USED, FLAT (all 32-bit; VkBool32 for the booleans).
    const std::array<std::uint32_t, 9> vertexFeatures{(key.lighting & 1u) ? 1u : 0u,
                                                      (key.lighting & 2u) ? 1u : 0u,
                                                      key.lightCount,
                                                      key.lightModes,
                                                      key.specular,
                                                      key.texFunc[0] != 0 ? 1u : 0u,
                                                      key.texFunc[1] != 0 ? 1u : 0u,
                                                      key.fog,
                                                      key.flat};
    std::array<VkSpecializationMapEntry, 9> vertexEntries{};
    for (std::uint32_t i = 0; i < vertexEntries.size(); ++i)
        vertexEntries[i] = {i, static_cast<std::uint32_t>(i * sizeof(std::uint32_t)), sizeof(std::uint32_t)};
    const VkSpecializationInfo vertSpec{static_cast<std::uint32_t>(vertexEntries.size()), vertexEntries.data(),
                                        sizeof(vertexFeatures), vertexFeatures.data()};
    stages[0] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_VERTEX_BIT, vert_, "main", &vertSpec};
    // m3g.frag's constant_ids 0..9 (all 32-bit).
    const std::array<std::uint32_t, 10> features{key.discard,      key.texFunc[0],       key.texFunc[1],
                                                 key.fog,          key.texFormat[0],     key.texFormat[1],
                                                 key.flat,         (key.lighting & 2u) ? 1u : 0u,
                                                 key.texProjective[0], key.texProjective[1]};
    std::array<VkSpecializationMapEntry, 10> entries{};
    for (std::uint32_t i = 0; i < entries.size(); ++i)
        entries[i] = {i, static_cast<std::uint32_t>(i * sizeof(std::uint32_t)), sizeof(std::uint32_t)};
    const VkSpecializationInfo fragSpec{static_cast<std::uint32_t>(entries.size()), entries.data(), sizeof(features),
                                        features.data()};
    stages[1] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_FRAGMENT_BIT, frag_, "main", &fragSpec};

    // Five streams: position, normal, colour, texcoord 0, texcoord 1. Strides
    // are dynamic so that a missing array binds a dummy buffer with stride 0.
    std::array<VkVertexInputBindingDescription, 5> bindings{};
    std::array<VkVertexInputAttributeDescription, 5> attributes{};
    const VkFormat formats[5] = {VK_FORMAT_R32G32B32_SFLOAT, VK_FORMAT_R32G32B32_SFLOAT, VK_FORMAT_R32G32B32A32_SFLOAT,
                                 VK_FORMAT_R32G32B32_SFLOAT, VK_FORMAT_R32G32B32_SFLOAT};
    const std::uint32_t strides[5] = {12, 12, 16, 12, 12};
    for (std::uint32_t i = 0; i < 5; ++i) {
        bindings[i] = {i, strides[i], VK_VERTEX_INPUT_RATE_VERTEX};
        attributes[i] = {i, i, formats[i], 0};
    }
    VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vi.vertexBindingDescriptionCount = 5;
    vi.pVertexBindingDescriptions = bindings.data();
    vi.vertexAttributeDescriptionCount = 5;
    vi.pVertexAttributeDescriptions = attributes.data();
    VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    vp.viewportCount = 1;
    vp.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    rs.polygonMode = key.wireframe && ctx_.wireframeSupported() ? VK_POLYGON_MODE_LINE : VK_POLYGON_MODE_FILL;
    rs.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    ms.rasterizationSamples = static_cast<VkSampleCountFlagBits>(key.samples);
    VkPipelineDepthStencilStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    ds.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    const VkPipelineColorBlendAttachmentState attachment = blendState(key.blend, key.writeMask);
    VkPipelineColorBlendStateCreateInfo cb{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    cb.attachmentCount = 1;
    cb.pAttachments = &attachment;
    const VkDynamicState dynamic[] = {
        VK_DYNAMIC_STATE_VIEWPORT,          VK_DYNAMIC_STATE_SCISSOR,           VK_DYNAMIC_STATE_CULL_MODE,
        VK_DYNAMIC_STATE_FRONT_FACE,        VK_DYNAMIC_STATE_DEPTH_TEST_ENABLE, VK_DYNAMIC_STATE_DEPTH_WRITE_ENABLE,
        VK_DYNAMIC_STATE_DEPTH_COMPARE_OP,  VK_DYNAMIC_STATE_DEPTH_BIAS_ENABLE, VK_DYNAMIC_STATE_DEPTH_BIAS,
        VK_DYNAMIC_STATE_VERTEX_INPUT_BINDING_STRIDE,
    };
    VkPipelineDynamicStateCreateInfo dy{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dy.dynamicStateCount = static_cast<std::uint32_t>(std::size(dynamic));
    dy.pDynamicStates = dynamic;
    const VkFormat colorFormat = VK_FORMAT_R8G8B8A8_UNORM;
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachmentFormats = &colorFormat;
    rendering.depthAttachmentFormat = ctx_.depthFormat();

    VkGraphicsPipelineCreateInfo gi{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    gi.pNext = &rendering;
    gi.stageCount = 2;
    gi.pStages = stages.data();
    gi.pVertexInputState = &vi;
    gi.pInputAssemblyState = &ia;
    gi.pViewportState = &vp;
    gi.pRasterizationState = &rs;
    gi.pMultisampleState = &ms;
    gi.pDepthStencilState = &ds;
    gi.pColorBlendState = &cb;
    gi.pDynamicState = &dy;
    gi.layout = layout_;
    VkPipeline pipeline;
    check(vkCreateGraphicsPipelines(ctx_.device(), cache_, 1, &gi, nullptr, &pipeline), "vkCreateGraphicsPipelines");
    ++ctx_.pipelinesCreated;
    ++ctx_.livePipelines;
    return pipeline;
}

}  // namespace m3g::vk
