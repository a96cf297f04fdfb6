// What Graphics3D asks of a back end (JSR-184 1.1, Graphics3D): scene checks
// the arguments, collects, sorts and translates the M3G state into a
// DrawList; a back end only uploads what is stale, then records. render-vk
// is the Vulkan back end; scene's NullBackend records the calls for tests.
#pragma once

#include <m3g/frame/Export.h>

#include <cstdint>
#include <memory>
#include <span>

#include <m3g/frame/DrawList.h>
#include <m3g/frame/FrameSources.h>

namespace m3g::frame {

/// The bound target's pixels (an Image2D or a Graphics surface), read at
/// the start of a frame that keeps the prior contents and written when the
/// frame is released.
class TargetPixels {
public:
    virtual ~TargetPixels() = default;
    /// width x height RGBA8 texels, rows from the top, into `out`.
    virtual void read(std::span<std::uint8_t> out) const = 0;
    /// Stores the frame: RGBA8 texels (BGRA8 with `bgra`), rows from the top.
    virtual void write(const std::uint8_t* texels, bool bgra) = 0;
};

/// The bound target as a back end sees it.
struct Target {
    int width = 0, height = 0;
    bool depthBuffer = true;
    int hints = 0;                 ///< Graphics3D::ANTIALIAS | DITHER | TRUE_COLOR | OVERWRITE
    TargetPixels* pixels = nullptr;
    /// The bound object's address, as a key for back ends that know some
    /// targets themselves (render-vk's WindowTarget); never dereferenced.
    const void* identity = nullptr;
};

/// Viewer settings a back end holds (an m3g-vk extension): scene reads them
/// when it translates a call's state.
struct DrawOptions {
    bool wireframe = false;  ///< polygons as edges
    bool unlit = false;      ///< Material ignored
    bool clampLit = false;   ///< lit vertex colours clamped to [0, 1]
    /// Projections end in Vulkan's clip space (y down, z in [0, w]) rather
    /// than OpenGL's.
    bool vulkanClipSpace = true;
};

class FrameBackend {
public:
    virtual ~FrameBackend() = default;
    virtual DrawOptions options() const noexcept = 0;
    /// Graphics3D::clear, or the clear step of render(World).
    virtual void clear(const Target& target, const ViewState& view, const DrawList& list, FrameSources& sources) = 0;
    /// Draws `list` over what the target holds.
    virtual void draw(const Target& target, const ViewState& view, const DrawList& list, FrameSources& sources) = 0;
    /// Graphics3D::releaseTarget: finishes the frame and writes the pixels
    /// back. `released`: ids of objects that no longer exist, whose copies
    /// the back end may free.
    virtual void release(const Target& target, std::span<const std::uint64_t> released) = 0;
};

/// Makes the back end of a new Graphics3D's first draw. A back end library
/// installs its factory (render-vk does at load time); scene falls back to
/// NullBackend, which draws nothing.
using BackendFactory = std::unique_ptr<FrameBackend> (*)();
M3G_FRAME_API void setBackendFactory(BackendFactory factory) noexcept;
M3G_FRAME_API BackendFactory backendFactory() noexcept;

}  // namespace m3g::frame
