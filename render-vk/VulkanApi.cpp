// The public functions of <m3g/vk/Vulkan.h>: devices, validation, debug
// views, statistics.
#include <m3g/vk/Vulkan.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <mutex>

#include "Context.h"
#include "Instance.h"

namespace m3g::vk {


std::vector<DeviceInfo> listDevices() {
    if (Context::exists()) {
        std::vector<DeviceInfo> out;
        for (auto pd : physicalDevices(Context::get().instance())) out.push_back(describe(pd));
        return out;
    }
    bool validation = false;
    VkInstance instance = createInstance(false, validation);
    std::vector<DeviceInfo> out;
    for (auto pd : physicalDevices(instance)) out.push_back(describe(pd));
    vkDestroyInstance(instance, nullptr);
    return out;
}

DeviceInfo currentDevice() { return Context::get().info(); }

bool requestValidation(bool enable) {
    return Context::beforeCreation([&] { gValidationRequest = enable ? 1 : 0; });
}

bool requestWindowExtensions(const std::vector<std::string>& instanceExtensions) {
    return Context::beforeCreation([&] { gWindowExtensions = instanceExtensions; });
}

void useDevice(const ExternalDevice& device) { Context::adopt(device); }

void releaseDevice() { Context::release(); }

bool validationEnabled() { return Context::exists() && Context::get().validation(); }
std::uint64_t validationMessageCount() { return gValidationMessages.load(); }

namespace {
std::atomic<bool> gWireframe{false}, gUnlit{false};
}

void setDebugView(const DebugView& view) noexcept {
    gWireframe = view.wireframe;
    gUnlit = view.unlit;
}

DebugView debugView() noexcept { return DebugView{gWireframe.load(), gUnlit.load()}; }

namespace {
std::atomic<bool>& clampLitFlag() noexcept {
    static std::atomic<bool> flag{[] {
        const char* v = std::getenv("M3G_CLAMP_LIGHTING");
        return v != nullptr && std::string_view(v) == "1";
    }()};
    return flag;
}
}  // namespace

void setLitColorClamping(bool clamp) noexcept { clampLitFlag() = clamp; }
bool litColorClamping() noexcept { return clampLitFlag().load(); }

namespace {
std::atomic<bool> gCountShaders{false};
}

void setShaderInvocationCounting(bool on) noexcept { gCountShaders = on; }
bool shaderInvocationCounting() noexcept { return gCountShaders.load(); }
bool shaderInvocationCountingSupported() noexcept {
    const std::shared_ptr<Context> c = Context::existing();
    return c && c->pipelineStatisticsSupported();
}
std::string lastValidationMessage() {
    std::lock_guard lock(gMessageMutex);
    return gLastMessage;
}

RenderStats renderStats() {
    RenderStats s;
    if (!Context::exists()) return s;
    Context& c = Context::get();
    s.pipelinesCreated = c.pipelinesCreated;
    s.pipelinesEvicted = c.pipelinesEvicted;
    s.livePipelines = static_cast<std::uint64_t>(std::max<std::int64_t>(0, c.livePipelines));
    s.draws = c.draws;
    s.bufferUploads = c.bufferUploads;
    s.textureUploads = c.textureUploads;
    s.frames = c.frames;
    s.computeDispatches = c.computeDispatches;
    s.liveBuffers = static_cast<std::uint64_t>(std::max<std::int64_t>(0, c.liveBuffers));
    s.liveTextures = static_cast<std::uint64_t>(std::max<std::int64_t>(0, c.liveTextures));
    s.deviceMemoryBytes = static_cast<std::uint64_t>(std::max<std::int64_t>(0, c.memoryBytes));
    s.pipelineCacheBytesLoaded = c.pipelineCacheBytesLoaded;
    s.pipelineCacheSaves = c.pipelineCacheSaves;
    s.frameWaitNanoseconds = c.frameWaitNanos;
    s.readBackNanoseconds = c.readBackNanos;
    s.countedFrames = c.countedFrames;
    s.vertexShaderInvocations = c.vertexInvocations;
    s.fragmentShaderInvocations = c.fragmentInvocations;
    return s;
}

}  // namespace m3g::vk
