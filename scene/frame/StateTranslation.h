// The M3G state of a draw translated into what a back end records: pipeline
// key, rasterizer state and uniform block (JSR-184 1.1: Appearance,
// CompositingMode, PolygonMode, Material, Light, Fog, Texture2D, Background,
// Sprite3D; the OpenGL ES 1.1 fixed function they map to). Pure functions of
// scene objects and plain data, tested without a device
// (tests/unit/test_StateTranslation.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include <m3g/frame/DrawList.h>
#include <m3g/frame/FrameBackend.h>

#include <m3g/Forward.h>
#include <m3g/Transform.h>
#include <m3g/skin/Palette.h>

namespace m3g::detail {

struct RenderItem;
struct RenderQueue;

/// 0xAARRGGBB to RGBA floats in [0, 1]; alpha 1 unless `withAlpha`.
void argbToFloats(std::uint32_t argb, float* out, bool withAlpha) noexcept;
/// A Transform as 16 floats, column major.
void toColumns(const Transform& t, float* out) noexcept;
/// `gl` followed by the OpenGL-to-Vulkan clip-space fix (y down, z in [0, w]).
Transform vulkanProjection(const Transform& gl);

/// Whether an Image2D format has colour / alpha channels as a texture
/// (JSR-184 1.1, Texture2D: ALPHA has no colour; ALPHA, LUMINANCE_ALPHA and
/// RGBA have alpha).
bool formatHasColor(int format) noexcept;
bool formatHasAlpha(int format) noexcept;

/// Texture2D.FUNC_* to the shader's TexFunc numbering.
std::int32_t shaderTexFunc(int blending) noexcept;
/// The packed sampler state of wrapping and filtering modes.
frame::SamplerKey samplerKey(int wrapS, int wrapT, int imageFilter, int levelFilter) noexcept;
/// Clamped, nearest, base level: sprites, background images.
frame::SamplerKey nearestClampSampler() noexcept;

/// Blending and colour write mask of `cm` (null: REPLACE, every channel)
/// on top of the features `u` uses.
frame::PipelineKey pipelineKey(const frame::DrawUniforms& u, const CompositingMode* cm) noexcept;
/// Culling and winding of `pm` (null: back faces culled, CCW), depth test,
/// write and offset of `cm` (null: test and write, no offset).
frame::RasterState rasterState(const PolygonMode* pm, const CompositingMode* cm) noexcept;
/// Fog colour, mode and distances (JSR-184 1.1, Fog); no fog: left zero.
void fillFog(frame::DrawUniforms& u, const Fog* fog) noexcept;

/// What a submesh's vertex data provides: which streams exist and whether
/// positions arrive already scaled and biased (deformed meshes).
struct VertexLayout {
    std::array<bool, frame::STREAM_COUNT> present{};
    bool deformed = false;
    /// A rigidly bound SkinnedMesh drawn from its undeformed vertices
    /// (DeformedVertices::rigid): its bone's palette entry, multiplied into
    /// the model-view (raw positions: the entry holds the scale and bias)
    /// and the normal matrix, so that the draw places every vertex where
    /// skinning it would have.
    bool rigid = false;
    skin::PaletteEntry rigidTransform{};
};

/// The uniforms, textures, pipeline key and rasterizer state of one
/// submesh draw. `projection`: the queue's projection in uniform form
/// (column major, clip-space fix applied), `numTextureUnits` the limit in
/// force (Graphics3D::getProperties).
void translateSubmesh(const RenderQueue& queue, const RenderItem& item, const VertexLayout& layout,
                      const float* projection, const frame::DrawOptions& options, int numTextureUnits,
                      frame::DrawUniforms& u, frame::Draw& draw);

/// The screen-aligned quad of a Sprite3D (JSR-184 1.1, Sprite3D), or false
/// when it is not visible. `viewport` in pixels.
bool translateSprite(const RenderQueue& queue, const RenderItem& item, int viewportWidth, int viewportHeight,
                     bool vulkanClip, frame::DrawUniforms& u, frame::Draw& draw);

/// Graphics3D::clear(background) over `view` of a target of `width` x
/// `height` (JSR-184 1.1, Background): colour and depth clear flags and
/// colour, and the background image quad (its uniforms appended to
/// `uniforms`) with its crop and REPEAT/BORDER modes.
frame::Clear translateClear(const Background* background, const frame::ViewState& view, int width, int height,
                            bool vulkanClip, std::vector<frame::DrawUniforms>& uniforms);

/// A triangle list of `ib`, each triangle rotated so that the vertex
/// OpenGL ES takes for flat shading (a strip triangle's last) comes first,
/// keeping the winding.
void triangleList(const IndexBuffer& ib, std::vector<std::uint32_t>& out);

/// The viewport and scissor of `g3d`'s bound target (viewport moved by the
/// Graphics translation, scissor = viewport ∩ clip ∩ target).
frame::ViewState viewState(const Graphics3D& g3d);

}  // namespace m3g::detail
