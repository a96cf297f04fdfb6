// Small pure functions on DrawUniforms shared by scene (which translates M3G
// state) and a back end (which draws its own quads, e.g. render-vk's prior
// contents under multisampling).
#pragma once

#include <cstdint>
#include <cstring>

#include <m3g/frame/DrawUniforms.h>
#include <m3g/frame/PipelineKey.h>

namespace m3g::frame {

/// A 4x4 identity, column major.
inline void identity(float* out) noexcept {
    std::memset(out, 0, 16 * sizeof(float));
    out[0] = out[5] = out[10] = out[15] = 1.0f;
}

/// The matrix from OpenGL clip space (y up, z in [-w, w]) to Vulkan's (y
/// down, z in [0, w]), column major.
inline void vulkanClipFix(float* out) noexcept {
    identity(out);
    out[5] = -1.0f;   // y
    out[10] = 0.5f;   // z scale
    out[14] = 0.5f;   // z += 0.5 w
}

/// The pipeline features `u` uses (fragment-shader specialisations,
/// lighting): everything of the key but blending, write mask, samples and
/// wireframe.
inline PipelineKey pipelineFeatures(const DrawUniforms& u) noexcept {
    PipelineKey key;
    key.discard = (u.misc[1] > 0.0f || u.texEnv[0][3] != 0 || u.texEnv[1][3] != 0) ? 1 : 0;
    for (int unit = 0; unit < 2; ++unit) {
        key.texFunc[unit] = static_cast<std::uint8_t>(u.texEnv[unit][0]);
        key.texFormat[unit] = static_cast<std::uint8_t>((u.texEnv[unit][1] ? 1 : 0) | (u.texEnv[unit][2] ? 2 : 0));
        // Column-major: the bottom row is elements 3, 7, 11, 15.
        const float* m = u.texMatrix[unit];
        const bool affine = m[3] == 0.0f && m[7] == 0.0f && m[11] == 0.0f && m[15] == 1.0f;
        key.texProjective[unit] = key.texFunc[unit] != 0 && !affine ? 1 : 0;
    }
    key.fog = u.fogParams[0] != 0.0f ? 1 : 0;
    key.flat = (u.flags[0] & F_FLAT) ? 1 : 0;
    if (u.flags[0] & F_LIGHTING) {
        key.lighting = (u.flags[0] & F_TWO_SIDED) ? 3 : 1;
        key.lightCount = static_cast<std::uint8_t>(u.flags[1]);
        for (int i = 0; i < u.flags[1]; ++i)
            key.lightModes =
                static_cast<std::uint16_t>(key.lightModes | (static_cast<int>(u.lights[i].color[3]) << (2 * i)));
        key.specular = (u.matSpecular[0] != 0.0f || u.matSpecular[1] != 0.0f || u.matSpecular[2] != 0.0f) ? 1 : 0;
    }
    return key;
}

/// Uniforms of a screen-space textured quad (sprite, background image,
/// prior contents): positions already in NDC (identity model-view, only
/// the clip-space fix when `vulkanClip`), unit 0 applies `func` with an
/// image of the given channels, white vertex colour, alpha factor 1, no
/// fixed fog depth.
inline void quadUniforms(DrawUniforms& u, std::int32_t func, bool hasColor, bool hasAlpha, bool vulkanClip) noexcept {
    std::memset(&u, 0, sizeof(u));
    identity(u.modelView);
    if (vulkanClip) vulkanClipFix(u.projection);
    else identity(u.projection);
    identity(u.normalMatrix);
    identity(u.texMatrix[0]);
    identity(u.texMatrix[1]);
    u.positionScaleBias[3] = 1.0f;
    u.texScaleBias[0][3] = u.texScaleBias[1][3] = 1.0f;
    u.flags[0] = F_CLIP_SPACE;
    u.texEnv[0][0] = func;
    u.texEnv[0][1] = hasColor ? 1 : 0;
    u.texEnv[0][2] = hasAlpha ? 1 : 0;
    u.defaultColor[0] = u.defaultColor[1] = u.defaultColor[2] = u.defaultColor[3] = 1.0f;
    u.misc[0] = 1.0f;   // alpha factor
    u.misc[2] = -1.0f;  // no fixed fog depth
}

}  // namespace m3g::frame
