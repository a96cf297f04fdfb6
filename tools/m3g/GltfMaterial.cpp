#include "GltfMaterial.h"

#include <array>
#include <cmath>

#include <m3g/Appearance.h>
#include <m3g/CompositingMode.h>
#include <m3g/Fog.h>
#include <m3g/Image2D.h>
#include <m3g/Limits.h>
#include <m3g/Material.h>
#include <m3g/PolygonMode.h>
#include <m3g/Texture2D.h>
#include <m3g/VertexBuffer.h>

#include "ImageIO.h"

namespace m3gcli::gltf {

namespace {

using m3g::CompositingMode;
using m3g::Image2D;
using m3g::PolygonMode;
using m3g::Texture2D;

/// 0xAARRGGBB -> RGBA in [0, 1]; `withAlpha` false gives alpha 1.
std::array<double, 4> unpack(int argb, bool withAlpha) {
    const auto v = static_cast<std::uint32_t>(argb);
    return {((v >> 16) & 0xFF) / 255.0, ((v >> 8) & 0xFF) / 255.0, (v & 0xFF) / 255.0,
            withAlpha ? ((v >> 24) & 0xFF) / 255.0 : 1.0};
}

const char* functionName(int f) {
    switch (f) {
    case Texture2D::FUNC_ADD: return "FUNC_ADD";
    case Texture2D::FUNC_BLEND: return "FUNC_BLEND";
    case Texture2D::FUNC_DECAL: return "FUNC_DECAL";
    case Texture2D::FUNC_REPLACE: return "FUNC_REPLACE";
    default: return "FUNC_MODULATE";
    }
}

const char* blendingName(int b) {
    switch (b) {
    case CompositingMode::ALPHA: return "ALPHA";
    case CompositingMode::ALPHA_ADD: return "ALPHA_ADD";
    case CompositingMode::MODULATE: return "MODULATE";
    case CompositingMode::MODULATE_X2: return "MODULATE_X2";
    default: return "REPLACE";
    }
}

bool hasAlpha(int format) {
    return format == Image2D::ALPHA || format == Image2D::LUMINANCE_ALPHA || format == Image2D::RGBA;
}

}  // namespace

int MaterialWriter::image(const Image2D& img) {
    if (const auto it = images_.find(&img); it != images_.end()) return it->second;
    RgbaImage rgba;
    rgba.width = img.getWidth();
    rgba.height = img.getHeight();
    img.getPixelsRGBA8(rgba.pixels);
    const auto png = encodePng(rgba, hasAlpha(img.getFormat()));
    std::string name = "Image2D";
    if (img.getUserID() != 0) name += " " + std::to_string(img.getUserID());
    const int index = doc_.addPngImage(png, name);
    images_[&img] = index;
    return index;
}

int MaterialWriter::texture(const Texture2D& tex) {
    const int imageIndex = image(*tex.getImage());
    // Sampler (§3.8.4): M3G's level filter picks the mipmap mode.
    const bool linear = tex.getImageFilter() == Texture2D::FILTER_LINEAR;
    const int mag = linear ? 9729 : 9728;  // LINEAR : NEAREST
    int min = mag;
    if (tex.getLevelFilter() == Texture2D::FILTER_NEAREST) min = linear ? 9985 : 9984;  // *_MIPMAP_NEAREST
    if (tex.getLevelFilter() == Texture2D::FILTER_LINEAR) min = linear ? 9987 : 9986;   // *_MIPMAP_LINEAR
    auto wrap = [](int w) { return w == Texture2D::WRAP_CLAMP ? 33071 : 10497; };  // CLAMP_TO_EDGE : REPEAT
    const Json sampler = {{"magFilter", mag}, {"minFilter", min}, {"wrapS", wrap(tex.getWrappingS())},
                          {"wrapT", wrap(tex.getWrappingT())}};
    const std::string key = sampler.dump();
    int samplerIndex;
    if (const auto it = samplers_.find(key); it != samplers_.end())
        samplerIndex = it->second;
    else
        samplerIndex = samplers_[key] = doc_.add("samplers", sampler);
    const auto tk = std::make_pair(imageIndex, samplerIndex);
    if (const auto it = textures_.find(tk); it != textures_.end()) return it->second;
    return textures_[tk] = doc_.add("textures", {{"sampler", samplerIndex}, {"source", imageIndex}});
}

PrimitiveLook MaterialWriter::look(const m3g::Appearance& a, const m3g::VertexBuffer& vb, float alphaFactor) {
    PrimitiveLook out;
    const m3g::Material* mat = a.getMaterial().get();
    const bool lit = mat != nullptr;
    const bool colorArray = vb.getColors() != nullptr;

    // Base colour: what OpenGL ES 1.1 feeds the texture stage (JSR-184 1.1,
    // Texture2D: texture application).
    std::array<double, 4> base{1, 1, 1, 1};
    if (lit && !mat->isVertexColorTrackingEnabled()) {
        base = unpack(mat->getColor(m3g::Material::DIFFUSE), true);
    } else if (colorArray) {
        out.vertexColors = true;
    } else {
        base = unpack(vb.getDefaultColor(), true);
    }

    // The first unit with a texture and coordinates becomes baseColorTexture.
    int textureIndex = -1;
    bool unlitByTexture = false;
    for (int u = 0; u < m3g::getLimits().numTextureUnits; ++u) {
        const Texture2D* tex = a.getTexture(u).get();
        if (!tex || !vb.texCoords(u)) continue;
        if (out.textureUnit >= 0) {
            notes_.add("texture unit " + std::to_string(u) +
                       " dropped: glTF has one base colour texture per material (the first unit is kept)");
            continue;
        }
        out.textureUnit = u;
        out.texture = tex;
        textureIndex = texture(*tex);
        const int func = tex->getBlending();
        const int format = tex->getImage()->getFormat();
        if (func == Texture2D::FUNC_REPLACE) {
            // The texture replaces the lit colour: unlit, colour (and alpha
            // when the image has it) from the texture alone.
            unlitByTexture = true;
            if (format != Image2D::ALPHA) {
                base[0] = base[1] = base[2] = 1.0;
                out.vertexColors = false;
            }
            if (hasAlpha(format)) base[3] = 1.0;
        } else if (func != Texture2D::FUNC_MODULATE) {
            notes_.add(std::string("texture function ") + functionName(func) + " approximated as FUNC_MODULATE");
        }
    }
    base[3] *= std::clamp(static_cast<double>(alphaFactor), 0.0, 1.0);

    Json pbr = Json::object();
    pbr["baseColorFactor"] = base;
    if (textureIndex >= 0) pbr["baseColorTexture"] = {{"index", textureIndex}};
    pbr["metallicFactor"] = 0.0;
    Json material = Json::object();
    const bool unlit = !lit || unlitByTexture;
    if (!unlit) {
        // Blinn-Phong shininess to roughness (the usual sqrt(2 / (n + 2))); no
        // specular colour means no highlight at all: fully rough.
        const auto spec = unpack(mat->getColor(m3g::Material::SPECULAR), false);
        const bool specular = spec[0] > 0 || spec[1] > 0 || spec[2] > 0;
        pbr["roughnessFactor"] = specular ? std::sqrt(2.0 / (mat->getShininess() + 2.0)) : 1.0;
        const auto emissive = unpack(mat->getColor(m3g::Material::EMISSIVE), false);
        if (emissive[0] > 0 || emissive[1] > 0 || emissive[2] > 0)
            material["emissiveFactor"] = {emissive[0], emissive[1], emissive[2]};
    } else {
        pbr["roughnessFactor"] = 1.0;
        material["extensions"] = {{"KHR_materials_unlit", Json::object()}};
        doc_.useExtension("KHR_materials_unlit");
    }
    material["pbrMetallicRoughness"] = std::move(pbr);

    // Alpha (§3.9.4): blending -> BLEND, alpha test -> MASK.
    const CompositingMode* cm = a.getCompositingMode().get();
    const int blending = cm ? cm->getBlending() : CompositingMode::REPLACE;
    const float threshold = cm ? cm->getAlphaThreshold() : 0.0f;
    if (blending != CompositingMode::REPLACE) {
        material["alphaMode"] = "BLEND";
        if (blending != CompositingMode::ALPHA)
            notes_.add(std::string("CompositingMode blending ") + blendingName(blending) +
                       " approximated as glTF BLEND (alpha blending)");
        if (threshold > 0.0f) notes_.add("alpha threshold together with blending: glTF BLEND has no alpha test");
    } else if (threshold > 0.0f) {
        material["alphaMode"] = "MASK";
        material["alphaCutoff"] = threshold;
    }
    if (cm && (!cm->isDepthTestEnabled() || !cm->isDepthWriteEnabled() || !cm->isColorWriteEnabled() ||
               cm->getDepthOffsetFactor() != 0.0f || cm->getDepthOffsetUnits() != 0.0f))
        notes_.add("CompositingMode depth test/write, colour write and depth offset have no glTF equivalent");

    // Faces (§3.7.2.1): glTF culls back faces unless doubleSided.
    const PolygonMode* pm = a.getPolygonMode().get();
    const int culling = pm ? pm->getCulling() : PolygonMode::CULL_BACK;
    const bool cw = pm && pm->getWinding() == PolygonMode::WINDING_CW;
    if (culling == PolygonMode::CULL_NONE) material["doubleSided"] = true;
    out.flipWinding = cw != (culling == PolygonMode::CULL_FRONT);
    if (pm && pm->getShading() == PolygonMode::SHADE_FLAT) notes_.add("flat shading (SHADE_FLAT) exported as smooth");
    if (culling == PolygonMode::CULL_NONE && !(pm && pm->isTwoSidedLightingEnabled()) && lit)
        notes_.add("CULL_NONE without two-sided lighting: glTF doubleSided also lights back faces with the flipped normal");
    if (a.getFog()) notes_.add("Fog has no glTF equivalent (dropped)");

    const std::string key = material.dump();
    if (const auto it = materials_.find(key); it != materials_.end()) {
        out.material = it->second;
    } else {
        out.material = materials_[key] = doc_.add("materials", material);
    }
    return out;
}

}  // namespace m3gcli::gltf
