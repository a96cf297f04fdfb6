// The uniform block of one draw: the C++ mirror of shaders/draw_uniforms.glsl
// (std140). Scene fills it (frame preparation, StateTranslation), a back end
// copies it to the GPU unchanged. Matrices are column major, as GLSL reads
// them.
#pragma once

#include <cstddef>
#include <cstdint>

namespace m3g::frame {

struct alignas(16) LightUniforms {
    float position[4];
    float color[4];        // a = mode
    float spot[4];         // w = cos cutoff
    float attenuation[4];  // w = spot exponent
};

enum DrawFlags : std::int32_t {
    F_LIGHTING = 1,
    F_COLOR_TRACKING = 2,
    F_TWO_SIDED = 4,
    F_FLAT = 8,
    F_HAS_NORMALS = 16,
    F_HAS_COLORS = 32,
    F_LOCAL_CAMERA = 64,
    F_CLIP_SPACE = 128,
    F_CLAMP_LIT = 256,  ///< clamp lit vertex colours (setLitColorClamping)
};

/// Texture environment functions as the shader numbers them.
enum TexFunc : std::int32_t { TEX_OFF = 0, TEX_REPLACE, TEX_MODULATE, TEX_DECAL, TEX_BLEND, TEX_ADD };

struct alignas(16) DrawUniforms {
    /// x indexes the shader's one-element array: always 0 (see draw_uniforms.glsl).
    std::int32_t index[4];
    float modelView[16];
    float projection[16];
    float normalMatrix[16];
    float texMatrix[2][16];
    float positionScaleBias[4];
    float texScaleBias[2][4];
    float matAmbient[4];
    float matDiffuse[4];
    float matEmissive[4];
    float matSpecular[4];
    float defaultColor[4];
    float fogColor[4];
    float fogParams[4];
    float texBlendColor[2][4];
    std::int32_t texEnv[2][4];
    std::int32_t flags[4];
    float misc[4];
    LightUniforms lights[8];
};

static_assert(offsetof(DrawUniforms, texMatrix) == 208);
static_assert(offsetof(DrawUniforms, positionScaleBias) == 336);
static_assert(offsetof(DrawUniforms, matAmbient) == 384);
static_assert(offsetof(DrawUniforms, texEnv) == 528);
static_assert(offsetof(DrawUniforms, misc) == 576);
static_assert(offsetof(DrawUniforms, lights) == 592);
static_assert(sizeof(DrawUniforms) == 1104);

}  // namespace m3g::frame
