// What a Graphics3D keeps for drawing: its back end, the collect step's
// queue, the frame preparation (FrameBuilder) and the draw list handed over
// per call.
#pragma once

#include <memory>
#include <optional>

#include <m3g/frame/FrameBackend.h>

#include "FrameBuilder.h"
#include "RenderQueue.h"
#include "TargetPixels.h"

namespace m3g::detail {

struct FrameState {
    std::unique_ptr<frame::FrameBackend> backend;
    RenderQueue queue;
    FrameBuilder builder;
    frame::DrawList list;       ///< the draws of the current render call
    frame::DrawList clearList;  ///< the current clear (render(World) prepares its draws first)
    frame::ViewState view;      ///< the viewport of the draws in `list`
    /// The bound target's pixel adapter (one of them), set at bindTarget.
    std::optional<ImageTargetPixels> imagePixels;
    std::optional<GraphicsTargetPixels> graphicsPixels;
};

}  // namespace m3g::detail
