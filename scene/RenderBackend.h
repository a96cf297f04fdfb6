// What Graphics3D asks of a renderer. The object model knows only this
// interface; render-vk implements it (architecture guide §1: the collect
// step builds a RenderQueue of plain data, the back end uploads and records).
#pragma once

namespace m3g {
class Background;
class Graphics3D;
}  // namespace m3g

namespace m3g::detail {

struct RenderQueue;

class RenderBackend {
public:
    virtual ~RenderBackend() = default;
    /// Graphics3D::clear on the bound target (spec §5.9); null = black, far depth.
    virtual void clear(Graphics3D& g3d, const Background* background) = 0;
    /// Draws a sorted queue into the bound target with Graphics3D's viewport
    /// and depth range.
    virtual void render(Graphics3D& g3d, const RenderQueue& queue) = 0;
    /// Finishes the work for the bound target and writes the pixels back into
    /// it (Image2D or Graphics). Called by releaseTarget.
    virtual void release(Graphics3D& g3d) = 0;
};

}  // namespace m3g::detail
