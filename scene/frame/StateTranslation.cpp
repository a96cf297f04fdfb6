#include "StateTranslation.h"

#include <algorithm>
#include <array>
#include <cstring>

#include <glm/glm.hpp>

#include <m3g/Appearance.h>
#include <m3g/Background.h>
#include <m3g/CompositingMode.h>
#include <m3g/Fog.h>
#include <m3g/Graphics.h>
#include <m3g/Graphics3D.h>
#include <m3g/Image2D.h>
#include <m3g/Light.h>
#include <m3g/Material.h>
#include <m3g/PolygonMode.h>
#include <m3g/Sprite3D.h>
#include <m3g/Texture2D.h>
#include <m3g/TriangleStripArray.h>
#include <m3g/VertexBuffer.h>
#include <m3g/frame/UniformHelpers.h>

#include "RenderQueue.h"
#include "SpriteProjection.h"

namespace m3g::detail {

using frame::DrawUniforms;

void argbToFloats(std::uint32_t c, float* out, bool withAlpha) noexcept {
    out[0] = static_cast<float>((c >> 16) & 0xFF) / 255.0f;
    out[1] = static_cast<float>((c >> 8) & 0xFF) / 255.0f;
    out[2] = static_cast<float>(c & 0xFF) / 255.0f;
    out[3] = withAlpha ? static_cast<float>((c >> 24) & 0xFF) / 255.0f : 1.0f;
}

void toColumns(const Transform& t, float* out) noexcept {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) out[c * 4 + r] = t.at(r, c);
}

Transform vulkanProjection(const Transform& gl) {
    // frame::vulkanClipFix is the one definition of the fix (column major).
    float columns[16];
    frame::vulkanClipFix(columns);
    std::array<float, 16> rows{};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) rows[static_cast<std::size_t>(r * 4 + c)] = columns[c * 4 + r];
    return Transform::fromRows(rows) * gl;
}

bool formatHasColor(int format) noexcept { return format != Image2D::ALPHA; }

bool formatHasAlpha(int format) noexcept {
    return format == Image2D::ALPHA || format == Image2D::LUMINANCE_ALPHA || format == Image2D::RGBA;
}

std::int32_t shaderTexFunc(int blending) noexcept {
    switch (blending) {
    case Texture2D::FUNC_REPLACE: return frame::TEX_REPLACE;
    case Texture2D::FUNC_MODULATE: return frame::TEX_MODULATE;
    case Texture2D::FUNC_DECAL: return frame::TEX_DECAL;
    case Texture2D::FUNC_BLEND: return frame::TEX_BLEND;
    case Texture2D::FUNC_ADD: return frame::TEX_ADD;
    default: return frame::TEX_MODULATE;
    }
}

frame::SamplerKey samplerKey(int wrapS, int wrapT, int imageFilter, int levelFilter) noexcept {
    using frame::LevelFilter;
    const LevelFilter level = levelFilter == Texture2D::FILTER_BASE_LEVEL ? LevelFilter::Base
                              : levelFilter == Texture2D::FILTER_NEAREST  ? LevelFilter::Nearest
                                                                          : LevelFilter::Linear;
    return frame::makeSampler(wrapS == Texture2D::WRAP_CLAMP, wrapT == Texture2D::WRAP_CLAMP,
                              imageFilter == Texture2D::FILTER_LINEAR, level);
}

frame::SamplerKey nearestClampSampler() noexcept { return frame::kNearestClampSampler; }

namespace {

std::uint8_t blendIndex(const CompositingMode* cm) noexcept {
    if (!cm) return 0;
    switch (cm->getBlending()) {
    case CompositingMode::ALPHA: return 1;
    case CompositingMode::ALPHA_ADD: return 2;
    case CompositingMode::MODULATE: return 3;
    case CompositingMode::MODULATE_X2: return 4;
    default: return 0;
    }
}

std::uint8_t writeMask(const CompositingMode* cm) noexcept {
    const int rgb = (!cm || cm->isColorWriteEnabled()) ? (frame::WRITE_R | frame::WRITE_G | frame::WRITE_B) : 0;
    const int a = (!cm || cm->isAlphaWriteEnabled()) ? frame::WRITE_A : 0;
    return static_cast<std::uint8_t>(rgb | a);
}

void fillLights(DrawUniforms& u, const RenderQueue& queue, const RenderItem& item) noexcept {
    for (int i = 0; i < item.lightCount; ++i) {
        const RenderLight& l = queue.lights[item.lights[i]];
        frame::LightUniforms& lu = u.lights[i];
        std::copy(l.position.begin(), l.position.end(), lu.position);
        lu.color[0] = l.color[0];
        lu.color[1] = l.color[1];
        lu.color[2] = l.color[2];
        lu.color[3] = static_cast<float>(l.mode - Light::AMBIENT);
        lu.spot[0] = l.spotDirection[0];
        lu.spot[1] = l.spotDirection[1];
        lu.spot[2] = l.spotDirection[2];
        lu.spot[3] = l.spotCosCutoff;
        lu.attenuation[0] = l.attenuation[0];
        lu.attenuation[1] = l.attenuation[1];
        lu.attenuation[2] = l.attenuation[2];
        lu.attenuation[3] = l.spotExponent;
    }
    u.flags[1] = item.lightCount;
}

/// The inverse transpose of the model-view's upper 3x3 (the matrix itself
/// when singular), in a 4x4 column-major block.
void normalMatrix(const Transform& modelView, float* out) {
    glm::mat3 mv;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) mv[c][r] = modelView.at(r, c);
    const float det = glm::determinant(mv);
    const glm::mat3 n = det != 0.0f ? glm::transpose(glm::inverse(mv)) : mv;
    frame::identity(out);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) out[c * 4 + r] = n[c][r];
}

/// `modelView` and `normals` (column major, 4x4; null: left alone)
/// multiplied on the right by a palette entry's position rows and normal
/// rows: what the draw of an undeformed rigid mesh needs to match the
/// skinned one, where the vertex shader applies the model-view to the
/// skinned position and the normal matrix to the skinned normal (both
/// products in double, rounded once).
void withRigidTransform(const skin::PaletteEntry& e, float* modelView, float* normals) {
    // The entry's three rows as a 4x4 matrix with the bottom row (0, 0, 0,
    // 1); the normal rows' fourth elements are 0.
    auto multiply = [](float* m, const float* rows) {
        float out[16];
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) {
                double sum = c == 3 ? double{m[12 + r]} : 0.0;
                for (int k = 0; k < 3; ++k) sum += double{m[k * 4 + r]} * rows[k * 4 + c];
                out[c * 4 + r] = static_cast<float>(sum);
            }
        std::memcpy(m, out, sizeof(out));
    };
    multiply(modelView, e.position);
    if (normals) multiply(normals, e.normal);
}

}  // namespace

frame::PipelineKey pipelineKey(const DrawUniforms& u, const CompositingMode* cm) noexcept {
    frame::PipelineKey key = frame::pipelineFeatures(u);
    key.blend = blendIndex(cm);
    key.writeMask = writeMask(cm);
    return key;
}

frame::RasterState rasterState(const PolygonMode* pm, const CompositingMode* cm) noexcept {
    frame::RasterState r;
    const int culling = pm ? pm->getCulling() : PolygonMode::CULL_BACK;
    r.cull = culling == PolygonMode::CULL_NONE ? 0 : culling == PolygonMode::CULL_FRONT ? 1 : 2;
    // The y flip of the clip-space fix keeps on-screen orientation, so CCW stays CCW.
    r.clockwise = (pm && pm->getWinding() == PolygonMode::WINDING_CW) ? 1 : 0;
    r.depthTest = (!cm || cm->isDepthTestEnabled()) ? 1 : 0;
    r.depthWrite = (!cm || cm->isDepthWriteEnabled()) ? 1 : 0;
    r.depthOffsetFactor = cm ? cm->getDepthOffsetFactor() : 0.0f;
    r.depthOffsetUnits = cm ? cm->getDepthOffsetUnits() : 0.0f;
    return r;
}

void fillFog(DrawUniforms& u, const Fog* fog) noexcept {
    if (!fog) return;
    argbToFloats(static_cast<std::uint32_t>(fog->getColor()), u.fogColor, false);
    u.fogParams[0] = fog->getMode() == Fog::LINEAR ? 1.0f : 2.0f;
    u.fogParams[1] = fog->getNearDistance();
    u.fogParams[2] = fog->getFarDistance();
    u.fogParams[3] = fog->getDensity();
}

void translateSubmesh(const RenderQueue& queue, const RenderItem& item, const VertexLayout& layout,
                      const float* projection, const frame::DrawOptions& options, int numTextureUnits,
                      DrawUniforms& u, frame::Draw& draw) {
    const VertexBuffer& vb = *item.vertices;
    const Appearance* app = item.appearance;
    std::memset(&u, 0, sizeof(u));
    toColumns(item.modelView, u.modelView);
    std::memcpy(u.projection, projection, sizeof(u.projection));
    normalMatrix(item.modelView, u.normalMatrix);
    if (layout.rigid) {
        // Without normals the shader lights OpenGL's default normal, which
        // skinning leaves alone (it only has the model-view's normal matrix).
        withRigidTransform(layout.rigidTransform, u.modelView,
                           layout.present[frame::NORMALS] ? u.normalMatrix : nullptr);
        u.positionScaleBias[3] = 1.0f;
    } else if (layout.deformed) {
        u.positionScaleBias[3] = 1.0f;
    } else {
        const auto& b = vb.positionBias();
        u.positionScaleBias[0] = b[0];
        u.positionScaleBias[1] = b[1];
        u.positionScaleBias[2] = b[2];
        u.positionScaleBias[3] = vb.positionScale();
    }
    argbToFloats(static_cast<std::uint32_t>(vb.getDefaultColor()), u.defaultColor, true);

    // Texture units: a unit is used when it has both a texture and coordinates.
    draw.textures = {};
    const int units = std::min(2, numTextureUnits);
    for (int unit = 0; unit < units; ++unit) {
        frame::identity(u.texMatrix[unit]);
        u.texScaleBias[unit][3] = 1.0f;
        Texture2D* t = app->getTexture(unit).get();
        if (!t || !vb.texCoords(unit) || !layout.present[frame::TEXCOORDS0 + unit]) continue;
        const Image2D* image = t->getImage().get();
        frame::TextureRef& ref = draw.textures[static_cast<std::size_t>(unit)];
        ref.id = image->getObjectId();
        ref.revision = image->getRevision();
        ref.mipmaps = t->getLevelFilter() != Texture2D::FILTER_BASE_LEVEL;
        ref.sampler = samplerKey(t->getWrappingS(), t->getWrappingT(), t->getImageFilter(), t->getLevelFilter());
        toColumns(t->compositeTransform(), u.texMatrix[unit]);
        const auto& b = vb.texCoordBias(unit);
        u.texScaleBias[unit][0] = b[0];
        u.texScaleBias[unit][1] = b[1];
        u.texScaleBias[unit][2] = b[2];
        u.texScaleBias[unit][3] = vb.texCoordScale(unit);
        u.texEnv[unit][0] = shaderTexFunc(t->getBlending());
        u.texEnv[unit][1] = formatHasColor(image->getFormat()) ? 1 : 0;
        u.texEnv[unit][2] = formatHasAlpha(image->getFormat()) ? 1 : 0;
        argbToFloats(static_cast<std::uint32_t>(t->getBlendColor()), u.texBlendColor[unit], false);
    }

    const PolygonMode* pm = app->getPolygonMode().get();
    const Material* material = options.unlit ? nullptr : app->getMaterial().get();
    std::int32_t flags = 0;
    if (layout.present[frame::NORMALS]) flags |= frame::F_HAS_NORMALS;
    if (layout.present[frame::COLORS]) flags |= frame::F_HAS_COLORS;
    if (pm && pm->getShading() == PolygonMode::SHADE_FLAT) flags |= frame::F_FLAT;
    if (material) {
        flags |= frame::F_LIGHTING;
        if (options.clampLit) flags |= frame::F_CLAMP_LIT;
        if (material->isVertexColorTrackingEnabled()) flags |= frame::F_COLOR_TRACKING;
        if (pm && pm->isTwoSidedLightingEnabled()) flags |= frame::F_TWO_SIDED;
        if (pm && pm->isLocalCameraLightingEnabled()) flags |= frame::F_LOCAL_CAMERA;
        argbToFloats(static_cast<std::uint32_t>(material->getColor(Material::AMBIENT)), u.matAmbient, false);
        argbToFloats(static_cast<std::uint32_t>(material->getColor(Material::DIFFUSE)), u.matDiffuse, true);
        argbToFloats(static_cast<std::uint32_t>(material->getColor(Material::EMISSIVE)), u.matEmissive, false);
        argbToFloats(static_cast<std::uint32_t>(material->getColor(Material::SPECULAR)), u.matSpecular, false);
        u.matSpecular[3] = material->getShininess();
        fillLights(u, queue, item);
    }
    u.flags[0] = flags;
    fillFog(u, app->getFog().get());
    const CompositingMode* cm = app->getCompositingMode().get();
    u.misc[0] = item.alphaFactor;
    u.misc[1] = cm ? cm->getAlphaThreshold() : 0.0f;
    u.misc[2] = -1.0f;

    draw.kind = frame::Draw::Kind::Submesh;
    draw.pipeline = pipelineKey(u, cm);
    draw.pipeline.wireframe = options.wireframe ? 1 : 0;
    draw.raster = rasterState(pm, cm);
}

bool translateSprite(const RenderQueue& queue, const RenderItem& item, int viewportWidth, int viewportHeight,
                     bool vulkanClip, DrawUniforms& u, frame::Draw& draw) {
    // Only the CompositingMode and Fog of the Appearance apply; the image acts
    // as a texture (colour x alpha factor), JSR-184 1.1 Sprite3D.
    const auto& sprite = static_cast<const Sprite3D&>(*item.node);
    const SpriteRect r = projectSprite(sprite, item.modelView, queue.projection, viewportWidth, viewportHeight);
    if (!r.visible) return false;
    const Image2D* image = sprite.getImage().get();
    frame::quadUniforms(u, frame::TEX_MODULATE, formatHasColor(image->getFormat()), formatHasAlpha(image->getFormat()),
                        vulkanClip);
    const Appearance* app = item.appearance;
    const CompositingMode* cm = app->getCompositingMode().get();
    fillFog(u, app->getFog().get());
    u.misc[0] = item.alphaFactor;
    u.misc[1] = cm ? cm->getAlphaThreshold() : 0.0f;
    u.misc[2] = r.eyeDepth;  // sprites are fogged at their origin's depth
    draw.kind = frame::Draw::Kind::Quad;
    draw.pipeline = pipelineKey(u, cm);
    draw.raster = rasterState(nullptr, cm);
    draw.raster.cull = 0;
    draw.raster.depthOffsetFactor = draw.raster.depthOffsetUnits = 0.0f;  // quads take no depth offset
    draw.textures = {};
    draw.textures[0] = {image->getObjectId(), image->getRevision(), false, nearestClampSampler()};
    draw.quad = {r.x0, r.y0, r.x1, r.y1, r.ndcZ, r.s0, r.t0, r.s1, r.t1};
    return true;
}

frame::Clear translateClear(const Background* background, const frame::ViewState& view, int width, int height,
                            bool vulkanClip, std::vector<DrawUniforms>& uniforms) {
    frame::Clear c;
    c.color = !background || background->isColorClearEnabled();
    c.depth = !background || background->isDepthClearEnabled();
    if (background) argbToFloats(static_cast<std::uint32_t>(background->getColor()), c.rgba, true);
    const frame::Rect& area = view.scissor;
    c.wholeTarget = area.x == 0 && area.y == 0 && area.w == width && area.h == height;

    // The image: the crop rectangle covers the viewport exactly.
    const Image2D* image = c.color && background ? background->getImage().get() : nullptr;
    if (image && (background->getCropWidth() <= 0 || background->getCropHeight() <= 0)) image = nullptr;
    if (!image) return c;
    const bool repeatX = background->getImageModeX() == Background::REPEAT;
    const bool repeatY = background->getImageModeY() == Background::REPEAT;
    // A BORDER axis shows the background colour where the crop leaves the
    // image (a discard in the quad's shader). A crop inside the image maps
    // every pixel centre at least half a pixel's step inside [0, 1], so the
    // discard can go when that step is well above float rounding.
    auto inside = [](int cropPos, int cropSize, int imageSize, int viewportSize) {
        return cropPos >= 0 && cropPos + cropSize <= imageSize &&
               0.5 * cropSize / imageSize / std::max(viewportSize, 1) > 1e-5;
    };
    const bool borderX =
        !repeatX && !inside(background->getCropX(), background->getCropWidth(), image->getWidth(), view.viewport.w);
    const bool borderY =
        !repeatY && !inside(background->getCropY(), background->getCropHeight(), image->getHeight(), view.viewport.h);
    c.imageCovers = !borderX && !borderY;
    c.hasImage = true;

    DrawUniforms& u = uniforms.emplace_back();
    frame::quadUniforms(u, frame::TEX_REPLACE, formatHasColor(image->getFormat()), formatHasAlpha(image->getFormat()),
                        vulkanClip);
    u.texEnv[0][3] = (borderX ? 1 : 0) | (borderY ? 2 : 0);
    frame::Draw& d = c.image;
    d.kind = frame::Draw::Kind::Quad;
    d.uniforms = static_cast<std::uint32_t>(uniforms.size() - 1);
    d.pipeline = pipelineKey(u, nullptr);
    d.raster = rasterState(nullptr, nullptr);
    d.raster.cull = 0;
    d.raster.depthTest = d.raster.depthWrite = 0;
    d.textures[0] = {image->getObjectId(), image->getRevision(), false,
                     samplerKey(repeatX ? Texture2D::WRAP_REPEAT : Texture2D::WRAP_CLAMP,
                                repeatY ? Texture2D::WRAP_REPEAT : Texture2D::WRAP_CLAMP, Texture2D::FILTER_NEAREST,
                                Texture2D::FILTER_BASE_LEVEL)};
    // Nearest sampling takes texel floor(crop + (pixel + 0.5) * crop size /
    // viewport size), ties included (Nokia's renders repeat the texel after
    // an edge that falls on a pixel centre). Where a pixel centre lies is a
    // multiple of 1 / (2 * viewport) texels, so a shift of a quarter of that
    // changes no other pixel, and makes a tie land on the texel after the
    // edge on a GPU whose interpolation ends a hair below it (docs/gpu.md).
    const double iw = image->getWidth(), ih = image->getHeight();
    const double shiftS = 0.25 / std::max(view.viewport.w, 1), shiftT = 0.25 / std::max(view.viewport.h, 1);
    const double s0 = background->getCropX() + shiftS, t0 = background->getCropY() + shiftT;
    d.quad = {-1.0f,
              -1.0f,
              1.0f,
              1.0f,
              0.0f,
              static_cast<float>(s0 / iw),
              static_cast<float>(t0 / ih),
              static_cast<float>((s0 + background->getCropWidth()) / iw),
              static_cast<float>((t0 + background->getCropHeight()) / ih)};
    return c;
}

void triangleList(const IndexBuffer& ib, std::vector<std::uint32_t>& list) {
    list.clear();
    if (const auto* strips = dynamic_cast<const TriangleStripArray*>(&ib)) {
        // Strip triangle j is (s[j], s[j+1], s[j+2]) with alternating winding;
        // OpenGL's provoking vertex is s[j+2]. Rotations keep the winding.
        const auto idx = strips->stripIndices();
        std::size_t start = 0;
        for (int len : strips->stripLengths()) {
            const int* s = idx.data() + start;
            for (int j = 0; j + 2 < len; ++j) {
                const auto a = static_cast<std::uint32_t>(s[j]), b = static_cast<std::uint32_t>(s[j + 1]),
                           c = static_cast<std::uint32_t>(s[j + 2]);
                if (j % 2 == 0) list.insert(list.end(), {c, a, b});
                else list.insert(list.end(), {c, b, a});
            }
            start += static_cast<std::size_t>(len);
        }
        return;
    }
    // A generic triangle list: the third vertex provokes.
    const auto t = ib.triangleIndices();
    for (std::size_t i = 0; i + 2 < t.size(); i += 3)
        list.insert(list.end(), {static_cast<std::uint32_t>(t[i + 2]), static_cast<std::uint32_t>(t[i]),
                                 static_cast<std::uint32_t>(t[i + 1])});
}

frame::ViewState viewState(const Graphics3D& g3d) {
    const int width = g3d.targetWidth(), height = g3d.targetHeight();
    int ox = 0, oy = 0;
    frame::Rect clip{0, 0, width, height};
    if (const Graphics* g = g3d.targetGraphics()) {
        ox = g->getTranslateX();
        oy = g->getTranslateY();
        clip = {g->getClipX() + ox, g->getClipY() + oy, g->getClipWidth(), g->getClipHeight()};
    }
    frame::ViewState v;
    v.viewport = {g3d.getViewportX() + ox, g3d.getViewportY() + oy, g3d.getViewportWidth(), g3d.getViewportHeight()};
    const int x0 = std::max({v.viewport.x, clip.x, 0});
    const int y0 = std::max({v.viewport.y, clip.y, 0});
    const int x1 = std::min({v.viewport.x + v.viewport.w, clip.x + clip.w, width});
    const int y1 = std::min({v.viewport.y + v.viewport.h, clip.y + clip.h, height});
    v.scissor = {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
    v.depthNear = g3d.getDepthRangeNear();
    v.depthFar = g3d.getDepthRangeFar();
    return v;
}

}  // namespace m3g::detail
