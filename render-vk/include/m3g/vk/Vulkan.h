// m3g-vk's Vulkan back end as seen from an application: which device it
// uses, its validation counters and statistics. Graphics3D creates the
// device on its first clear() or render(); nothing here is needed to draw.
//
// Environment variables (read when the device is created):
//   M3G_VK_DEVICE      index (as listed by `m3g info --devices`) or a
//                      case-insensitive substring of the device name;
//                      default: the first discrete GPU, else integrated,
//                      else virtual, else a CPU device (lavapipe).
//   M3G_VK_VALIDATION  1 = enable VK_LAYER_KHRONOS_validation, 0 = disable;
//                      default: on in Debug builds, off otherwise.
//   M3G_VK_DEPTH_BITS  32 = prefer a 32-bit float depth buffer; default a
//                      16-bit one, as Nokia's engine had (docs/rendering.md).
#pragma once

#include <m3g/Export.h>

#include <cstdint>
#include <string>
#include <vector>

#include <m3g/Exception.h>

namespace m3g::vk {

/// Thrown when Vulkan cannot be used at all (no loader, no ICD, no device,
/// device creation failed) or a Vulkan call fails. The message says what
/// failed and what to install.
class M3G_API VulkanError : public IllegalStateException {
public:
    using IllegalStateException::IllegalStateException;
};

struct DeviceInfo {
    std::string name;
    std::string type;         ///< "discrete", "integrated", "virtual", "cpu", "other"
    std::uint32_t apiVersion = 0;
    std::uint32_t vendorID = 0;
    std::uint32_t deviceID = 0;
};

/// Every physical device the loader reports (creates a bare instance;
/// throws VulkanError when there is no loader).
M3G_API std::vector<DeviceInfo> listDevices();

/// The device Graphics3D renders with (creates it if needed).
M3G_API DeviceInfo currentDevice();

/// Turns the validation layer on or off; only before the device exists
/// (overrides M3G_VK_VALIDATION). Returns false if too late.
M3G_API bool requestValidation(bool enable);
/// Instance extensions a windowed application needs (e.g. from
/// glfwGetRequiredInstanceExtensions); enables VK_KHR_swapchain on the
/// device. Only before the device exists; returns false if too late.
M3G_API bool requestWindowExtensions(const std::vector<std::string>& instanceExtensions);
/// Whether the device was created with the validation layer.
M3G_API bool validationEnabled();
/// Messages (warnings and errors) the validation layer has reported so far.
M3G_API std::uint64_t validationMessageCount();
/// The last validation message, or "" (for test failure output).
M3G_API std::string lastValidationMessage();

/// Diagnostic drawing for viewers (an m3g-vk extension, off by default):
/// applies to every Graphics3D from the next draw on.
struct DebugView {
    bool wireframe = false;  ///< meshes as triangle edges (when the device has fillModeNonSolid)
    bool unlit = false;      ///< lighting off: Material ignored, vertex colours or white
};
M3G_API void setDebugView(const DebugView& view) noexcept;
M3G_API DebugView debugView() noexcept;

/// Whether lit vertex colours are clamped to [0, 1] before they are
/// interpolated (applies to every Graphics3D from the next frame on).
/// Off by default, matching the reference renders (Nokia's M3G engine on
/// Mesa's OpenGL ES 1.1, docs/rendering.md): Mesa clamps vertex
/// colours only in desktop compatibility contexts, so a vertex lit above 1
/// (e.g. a directional light plus an ambient light on a white Material)
/// brightens a MODULATE texture and the colours interpolated towards it;
/// the colour is clamped only when written to the target. On, the lit colour
/// is clamped per vertex as the OpenGL ES 1.1 specification describes
/// (JSR-184 1.1, Light and Material, via GL ES lighting). Environment variable
/// M3G_CLAMP_LIGHTING=1 turns it on at start-up.
M3G_API void setLitColorClamping(bool clamp) noexcept;
M3G_API bool litColorClamping() noexcept;

/// Shader invocation counting, an m3g-vk extension for profiling content
/// (JSR-184 has no such query), off by default: while on, each frame that
/// reaches the device is measured with a Vulkan pipeline-statistics query,
/// and RenderStats::countedFrames, vertexShaderInvocations and
/// fragmentShaderInvocations grow (`m3g bench render --invocations`). It
/// applies to every Graphics3D from its next frame on, and only where
/// shaderInvocationCountingSupported() is true; elsewhere it counts nothing.
/// What a device counts is its own (docs/rendering.md, "Measuring"): a
/// vertex shared by triangles may be shaded more than once, and lavapipe
/// counts fragments in whole 4x4 blocks.
M3G_API void setShaderInvocationCounting(bool on) noexcept;
M3G_API bool shaderInvocationCounting() noexcept;
/// Whether the device Graphics3D renders with can count shader invocations:
/// it has the pipelineStatisticsQuery feature, which m3g-vk enables on the
/// devices it creates (on an application's device,
/// ExternalDevice::pipelineStatisticsQuery says whether it was enabled).
/// False while no device exists; never creates one.
M3G_API bool shaderInvocationCountingSupported() noexcept;

/// Counters since the device was created.
struct RenderStats {
    std::uint64_t pipelinesCreated = 0;
    /// Pipelines destroyed because their renderer's cache was full (each
    /// renderer keeps at most its most recently used ones, see
    /// docs/rendering.md "Pipeline cache").
    std::uint64_t pipelinesEvicted = 0;
    std::uint64_t livePipelines = 0;  ///< graphics pipelines alive now, all renderers
    std::uint64_t draws = 0;
    std::uint64_t bufferUploads = 0;
    std::uint64_t textureUploads = 0;
    std::uint64_t frames = 0;       ///< releaseTarget calls that flushed work
    /// Compute dispatches of skinning/morphing (Graphics3D::SKINNING_COMPUTE):
    /// one per deformed SkinnedMesh, one per morphed attribute.
    std::uint64_t computeDispatches = 0;
    std::uint64_t liveBuffers = 0;  ///< GPU mirrors of buffers alive now
    std::uint64_t liveTextures = 0; ///< GPU mirrors of images alive now
    std::uint64_t deviceMemoryBytes = 0;  ///< bytes allocated now
    /// The pipeline cache file (docs/rendering.md "Pipeline cache"): bytes
    /// of it renderers were seeded with, and how many times it was written.
    std::uint64_t pipelineCacheBytesLoaded = 0;
    std::uint64_t pipelineCacheSaves = 0;
    /// Where a frame's fixed cost goes (docs/rendering.md "Measuring"): wall
    /// time, summed over the frames counted in `frames`, from each frame's
    /// submit until its fence signalled (the device's work and the driver's
    /// round trip), and copying each finished frame into its target's memory
    /// (a Graphics surface, an Image2D or a window's screenshot: the
    /// read-back's conversion; frames that are not read back, as a window's
    /// or a Vulkan image target's, add nothing to it).
    std::uint64_t frameWaitNanoseconds = 0;
    std::uint64_t readBackNanoseconds = 0;
    /// Shader invocation counting (setShaderInvocationCounting): frames
    /// counted, and the vertex and fragment shader invocations the device
    /// reported for them (the frame's draws, Background images and sprites;
    /// clears and skinning or morphing on the device are not shading).
    std::uint64_t countedFrames = 0;
    std::uint64_t vertexShaderInvocations = 0;
    std::uint64_t fragmentShaderInvocations = 0;
};
M3G_API RenderStats renderStats();

}  // namespace m3g::vk
