// The one way a back end reads scene data: asked only when its copy of a
// resource is missing or stale (a DrawList names resources by id and
// version). Implemented by scene's frame preparation; every call answers
// from state prepared before the draw list was handed over, so none of
// them deforms, allocates GPU objects or throws.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <m3g/frame/DeformInputs.h>
#include <m3g/frame/DrawList.h>

namespace m3g::frame {

/// Float streams of a VertexRef (kStreamComponents floats per vertex); a
/// span is empty where the stream is absent or, for GPU-deformed sources,
/// written by the back end's kernel.
struct VertexStreams {
    std::array<std::span<const float>, STREAM_COUNT> streams;
};

class FrameSources {
public:
    virtual ~FrameSources() = default;
    /// The streams of `ref` (valid until the next call to any method).
    virtual VertexStreams vertexStreams(const VertexRef& ref) = 0;
    /// GpuSkinned: the skinning kernel's inputs.
    virtual SkinInputs skinInputs(const VertexRef& ref) = 0;
    /// GpuMorphed: the morphing kernel's inputs.
    virtual MorphInputs morphInputs(const VertexRef& ref) = 0;
    /// The triangle list of `ref`, each triangle's provoking vertex first
    /// (the last vertex of the triangle as OpenGL ES draws the strip, because
    /// Vulkan's flat shading uses the first).
    virtual void triangles(const IndexRef& ref, std::vector<std::uint32_t>& out) = 0;
    /// The texels of image `ref` as RGBA8 rows from the top, width x height.
    virtual void texels(const TextureRef& ref, std::vector<std::uint8_t>& rgba, int& width, int& height) = 0;
};

}  // namespace m3g::frame
