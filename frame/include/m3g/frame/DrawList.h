// What scene hands a back end for each Graphics3D::clear and render call:
// plain data only. Resources are named by (object id, revision) and read
// through FrameSources when the back end's copy is stale; no pointer to a
// scene object crosses into the back end. docs/architecture.md shows where
// this sits in the frame.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <m3g/frame/DrawUniforms.h>
#include <m3g/frame/PipelineKey.h>

namespace m3g::frame {

/// Pixels in target coordinates (x right, y down from the top-left).
struct Rect {
    int x = 0, y = 0, w = 0, h = 0;
    bool empty() const noexcept { return w <= 0 || h <= 0; }
    friend bool operator==(const Rect&, const Rect&) = default;
};

/// Where a call draws: the viewport (Graphics3D::setViewport, moved by the
/// Graphics translation), the pixels it may touch (viewport ∩ Graphics clip
/// ∩ target) and the depth range (Graphics3D::setDepthRange).
struct ViewState {
    Rect viewport;
    Rect scissor;
    float depthNear = 0.0f, depthFar = 1.0f;
};

/// Sampler state of a texture unit, packed: bit 0 S clamps, bit 1 T clamps,
/// bit 2 linear image filter, bits 3-4 level filter (0 base level,
/// 1 nearest, 2 linear). JSR-184 1.1, Texture2D.setWrapping / setFiltering.
/// Made by makeSampler (scene) and read by the sampler* accessors (a back end).
using SamplerKey = std::uint32_t;
enum class LevelFilter : std::uint32_t { Base = 0, Nearest = 1, Linear = 2 };

constexpr SamplerKey makeSampler(bool clampS, bool clampT, bool linear, LevelFilter level) noexcept {
    return static_cast<SamplerKey>(clampS) | (static_cast<SamplerKey>(clampT) << 1) |
           (static_cast<SamplerKey>(linear) << 2) | (static_cast<SamplerKey>(level) << 3);
}
constexpr bool samplerClampsS(SamplerKey k) noexcept { return (k & 1u) != 0; }
constexpr bool samplerClampsT(SamplerKey k) noexcept { return (k & 2u) != 0; }
constexpr bool samplerLinear(SamplerKey k) noexcept { return (k & 4u) != 0; }
constexpr LevelFilter samplerLevel(SamplerKey k) noexcept { return static_cast<LevelFilter>((k >> 3) & 3u); }
/// Clamped, nearest, base level: sprites, background images, the prior contents.
inline constexpr SamplerKey kNearestClampSampler = makeSampler(true, true, false, LevelFilter::Base);

/// An Image2D used as a texture. id 0: the unit is unused (a white texel).
struct TextureRef {
    std::uint64_t id = 0;
    std::uint32_t revision = 0;
    bool mipmaps = false;  ///< the texture needs its mip chain
    SamplerKey sampler = 0;
};

/// How a draw's vertex streams are produced.
enum class VertexSource : std::uint8_t {
    Plain,       ///< a VertexBuffer's arrays as they are (scale and bias in the shader)
    Deformed,    ///< a SkinnedMesh or MorphingMesh deformed on the CPU by scene
    GpuSkinned,  ///< a SkinnedMesh the back end skins (FrameSources::skinInputs)
    GpuMorphed,  ///< a MorphingMesh the back end morphs (FrameSources::morphInputs)
};

/// Stream indices of a draw's vertex data: five float streams.
enum Stream : int { POSITIONS = 0, NORMALS, COLORS, TEXCOORDS0, TEXCOORDS1, STREAM_COUNT };
/// Floats per vertex of each stream (colours are RGBA, texture coordinates
/// padded to 3).
inline constexpr std::array<int, STREAM_COUNT> kStreamComponents{3, 3, 4, 3, 3};

/// The vertex data of a draw. `owner` is the VertexBuffer's id, or the
/// deforming Mesh's id; the back end refreshes its copy when `version`
/// changed (a different VertexBuffer, array or revision, or a new
/// deformation).
struct VertexRef {
    std::uint64_t owner = 0;
    std::uint64_t version = 0;
    /// For GpuSkinned / GpuMorphed: changes only when the kernel's static
    /// inputs changed (arrays, influence table, targets), not the pose.
    std::uint64_t inputVersion = 0;
    VertexSource source = VertexSource::Plain;
    int vertexCount = 0;
    std::array<bool, STREAM_COUNT> present{};
};

/// A triangle list made from an IndexBuffer (FrameSources::triangles).
struct IndexRef {
    std::uint64_t id = 0;
    std::uint32_t revision = 0;
    /// 0: the indices name the VertexBuffer's vertices. Otherwise the owner
    /// of the draw's VertexRef, whose CPU-deformed vertices come in an order
    /// of their own (a SkinnedMesh's, grouped by influence set): the
    /// triangles are remapped to it, and a back end keeps one copy per
    /// (id, vertexOrder), made again when `orderVersion` changes.
    std::uint64_t vertexOrder = 0;
    std::uint64_t orderVersion = 0;
};

/// Dynamic rasterizer state of a draw (PolygonMode, CompositingMode).
struct RasterState {
    std::uint8_t cull = 2;       ///< 0 none, 1 front, 2 back
    std::uint8_t clockwise = 0;  ///< 1: WINDING_CW front faces
    std::uint8_t depthTest = 1;  ///< 0: ALWAYS (depth is still written, JSR-184 1.1 CompositingMode)
    std::uint8_t depthWrite = 1;
    float depthOffsetFactor = 0.0f, depthOffsetUnits = 0.0f;
    friend bool operator==(const RasterState&, const RasterState&) = default;
};

/// A screen-space rectangle (sprite, background image): two triangles in
/// NDC at depth `z` (x right, y up), texture coordinates (s0, t0) at the
/// top-left corner and (s1, t1) at the bottom-right one. Drawn without
/// culling.
struct Quad {
    float x0 = -1, y0 = -1, x1 = 1, y1 = 1, z = 0;
    float s0 = 0, t0 = 0, s1 = 1, t1 = 1;
};

struct Draw {
    enum class Kind : std::uint8_t { Submesh, Quad };
    Kind kind = Kind::Submesh;
    PipelineKey pipeline;
    RasterState raster;
    std::uint32_t uniforms = 0;  ///< index into DrawList::uniforms
    std::array<TextureRef, 2> textures{};
    VertexRef vertices;          ///< Submesh only
    IndexRef indices;            ///< Submesh only
    Quad quad;                   ///< Quad only
};

/// Graphics3D::clear, or the clear that render(World) does with the World's
/// Background (JSR-184 1.1, Background). The back end clears colour and/or
/// depth inside ViewState::scissor, then draws `image` when it is set.
struct Clear {
    bool color = true;  ///< colour buffer cleared to `rgba`
    bool depth = true;  ///< depth buffer cleared to far
    float rgba[4] = {0, 0, 0, 0};
    /// The scissor is the whole target (a clear that may become the load
    /// operation of a render pass).
    bool wholeTarget = false;
    /// The background image quad writes every pixel of the scissor (no
    /// BORDER parts), so a colour clear under it is moot.
    bool imageCovers = false;
    bool hasImage = false;
    Draw image;  ///< a Quad with its uniforms in DrawList::uniforms
};

/// The draws of one render call, in drawing order (already sorted by the
/// JSR-184 rules: layer, then opaque before blended, then scene order), or
/// the commands of one clear call.
struct DrawList {
    std::vector<Draw> draws;
    std::vector<DrawUniforms> uniforms;
    Clear clear;  ///< valid for a clear call only

    void reset() {
        draws.clear();
        uniforms.clear();
        clear = Clear{};
    }
};

}  // namespace m3g::frame
