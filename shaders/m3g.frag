#version 450
// Fragment stage of the fixed-function emulation: texture environment per
// unit (the texture function table of JSR-184 1.1, Texture2D), fog (JSR-184
// 1.1, Fog), alpha test (JSR-184 1.1, CompositingMode).
#extension GL_GOOGLE_include_directive : require
#include "draw_uniforms.glsl"

layout(set = 1, binding = 0) uniform sampler2D textures[2];

layout(location = 0) in vec4 inFront;
layout(location = 1) in vec4 inBack;
layout(location = 2) flat in vec4 inFlatFront;
layout(location = 3) flat in vec4 inFlatBack;
layout(location = 4) in vec4 inTex0;
layout(location = 5) in vec4 inTex1;
layout(location = 6) in float inFogDepth;

layout(location = 0) out vec4 outColor;

// The features a draw uses (render-vk/Pipelines.h, PipelineKey): what a
// draw does not use compiles away instead of running masked (llvmpipe runs
// both sides of a uniform branch). MAY_DISCARD is false for draws with no
// alpha threshold and no Background BORDER, so depth can also be tested
// before shading. TEXn: the unit's function (0 = off, 1 REPLACE, 2 MODULATE,
// 3 DECAL, 4 BLEND, 5 ADD); TEXn_FORMAT: bit 0 the image has colour
// channels, bit 1 alpha.
layout(constant_id = 0) const bool MAY_DISCARD = true;
layout(constant_id = 1) const int TEX0 = 0;
layout(constant_id = 2) const int TEX1 = 0;
layout(constant_id = 3) const bool FOG = true;
layout(constant_id = 4) const int TEX0_FORMAT = 3;
layout(constant_id = 5) const int TEX1_FORMAT = 3;
layout(constant_id = 6) const bool FLAT = false;
layout(constant_id = 7) const bool TWO_SIDED = true;
// Per unit: the texture matrix's bottom row is not (0, 0, 0, 1), so q may
// differ from 1 and s, t are divided by it. Texture2D's own transforms are
// affine; only a general matrix (setTransform) can make them projective.
// Affine units interpolate s and t only and skip the division.
layout(constant_id = 8) const bool TEX0_PROJECTIVE = true;
layout(constant_id = 9) const bool TEX1_PROJECTIVE = true;

vec4 applyUnit(vec4 cf, int unit, int func, int format, bool projective, vec4 tc) {
    vec2 st = projective ? tc.xy / tc.w : tc.xy;
    if (MAY_DISCARD) {
        int border = u.texEnv[unit].w;
        bool outsideS = (border & 1) != 0 && (st.x < 0.0 || st.x > 1.0);
        bool outsideT = (border & 2) != 0 && (st.y < 0.0 || st.y > 1.0);
        if (outsideS || outsideT) discard;
    }
    vec4 t = texture(textures[unit], st);
    bool hasColor = (format & 1) != 0;
    bool hasAlpha = (format & 2) != 0;
    vec3 c = cf.rgb;
    float a = cf.a;
    if (func == 1) {  // REPLACE
        if (hasColor) c = t.rgb;
        if (hasAlpha) a = t.a;
    } else if (func == 2) {  // MODULATE (texels were expanded with 1 for missing channels)
        c = cf.rgb * t.rgb;
        a = cf.a * t.a;
    } else if (func == 3) {  // DECAL (RGB: C_t; RGBA: mix by A_t)
        c = hasAlpha ? mix(cf.rgb, t.rgb, t.a) : t.rgb;
    } else if (func == 4) {  // BLEND
        if (hasColor) c = mix(cf.rgb, u.texBlendColor[unit].rgb, t.rgb);
        a = cf.a * t.a;
    } else if (func == 5) {  // ADD
        if (hasColor) c = clamp(cf.rgb + t.rgb, 0.0, 1.0);
        a = cf.a * t.a;
    }
    return vec4(c, a);
}

void main() {
    bool back = TWO_SIDED && !gl_FrontFacing;
    vec4 color = FLAT ? (back ? inFlatBack : inFlatFront) : (back ? inBack : inFront);
    if (TEX0 != 0) color = applyUnit(color, 0, TEX0, TEX0_FORMAT, TEX0_PROJECTIVE, inTex0);
    if (TEX1 != 0) color = applyUnit(color, 1, TEX1, TEX1_FORMAT, TEX1_PROJECTIVE, inTex1);

    // Alpha test: pass if A >= threshold (off at 0).
    if (MAY_DISCARD && u.misc.y > 0.0 && color.a < u.misc.y) discard;

    if (FOG) {  // PipelineKey::fog: fogParams.x != 0
        int fogMode = int(u.fogParams.x);
        float z = inFogDepth;
        float f = fogMode == 1 ? (u.fogParams.z - z) / (u.fogParams.z - u.fogParams.y) : exp(-u.fogParams.w * z);
        f = clamp(f, 0.0, 1.0);
        color.rgb = mix(u.fogColor.rgb, color.rgb, f);
    }
    outColor = color;
}
