#version 450
// Vertex stage of the OpenGL ES 1.1 fixed-function emulation: transform,
// per-vertex lighting (JSR-184 1.1, Light and Material), texture coordinate
// pipeline (JSR-184 1.1, Texture2D).
#extension GL_GOOGLE_include_directive : require
#include "draw_uniforms.glsl"

layout(location = 0) in vec3 inPosition;  // raw values: scale and bias applied here
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inColor;
layout(location = 3) in vec3 inTex0;      // raw (s, t, r); r = 0 for 2-component arrays
layout(location = 4) in vec3 inTex1;

layout(location = 0) out vec4 outFront;
layout(location = 1) out vec4 outBack;
layout(location = 2) flat out vec4 outFlatFront;
layout(location = 3) flat out vec4 outFlatBack;
layout(location = 4) out vec4 outTex0;    // (s, t, r, q) after the texture matrix
layout(location = 5) out vec4 outTex1;
layout(location = 6) out float outFogDepth;

// Features of the pipeline (render-vk/Pipelines.h, PipelineKey::lighting
// and the lights): lighting that a draw does not use compiles away, and so
// does every light mode but each light's own (llvmpipe would run all of them
// under lane masks, for every light of a loop with a dynamic count).
layout(constant_id = 0) const bool LIGHTING = true;
layout(constant_id = 1) const bool TWO_SIDED = true;
// The number of lights (0..8) and their modes, light i's in bits 2i..2i+1:
// 0 ambient, 1 directional, 2 omni, 3 spot (Light uniform's color.a).
layout(constant_id = 2) const int LIGHT_COUNT = 0;
layout(constant_id = 3) const int LIGHT_MODES = 0;
// The material's specular colour is not black.
layout(constant_id = 4) const bool SPECULAR = true;
// The outputs m3g.frag reads (its TEX0, TEX1 != 0, FOG, FLAT): the others
// are not written, so that llvmpipe's vertex stage neither computes nor
// stores them.
layout(constant_id = 5) const bool TEX0_USED = true;
layout(constant_id = 6) const bool TEX1_USED = true;
layout(constant_id = 7) const bool FOG_USED = true;
layout(constant_id = 8) const bool FLAT = false;

bool has(int bit) { return (u.flags.x & bit) != 0; }

vec3 lightContribution(int i, vec3 eyePos, vec3 n, vec4 ambient, vec4 diffuse) {
    const int mode = (LIGHT_MODES >> (2 * i)) & 3;
    Light l = u.lights[i];
    if (mode == 0) return l.color.rgb * ambient.rgb;
    vec3 L;
    float att = 1.0;
    if (mode == 1) {
        L = l.position.xyz;
    } else {
        vec3 d = l.position.xyz - eyePos;
        float dist = length(d);
        L = dist > 0.0 ? d / dist : vec3(0.0, 0.0, 1.0);
        att = 1.0 / max(l.attenuation.x + l.attenuation.y * dist + l.attenuation.z * dist * dist, 1e-30);
        if (mode == 3) {
            float c = dot(-L, l.spot.xyz);
            att *= c < l.spot.w ? 0.0 : pow(max(c, 0.0), l.attenuation.w);
        }
    }
    float nDotL = dot(n, L);
    vec3 contribution = max(nDotL, 0.0) * l.color.rgb * diffuse.rgb;
    if (SPECULAR && nDotL > 0.0) {
        vec3 eyeDir = has(F_LOCAL_CAMERA) ? normalize(-eyePos) : vec3(0.0, 0.0, 1.0);
        vec3 h = normalize(L + eyeDir);
        float nDotH = max(dot(n, h), 0.0);
        float s = u.matSpecular.w > 0.0 ? pow(nDotH, u.matSpecular.w) : 1.0;
        contribution += s * l.color.rgb * u.matSpecular.rgb;
    }
    return att * contribution;
}

vec4 lightVertex(vec3 eyePos, vec3 n, vec4 ambient, vec4 diffuse) {
    vec3 color = u.matEmissive.rgb;
    // Unrolled by hand: each light's mode is then a constant.
    if (LIGHT_COUNT > 0) color += lightContribution(0, eyePos, n, ambient, diffuse);
    if (LIGHT_COUNT > 1) color += lightContribution(1, eyePos, n, ambient, diffuse);
    if (LIGHT_COUNT > 2) color += lightContribution(2, eyePos, n, ambient, diffuse);
    if (LIGHT_COUNT > 3) color += lightContribution(3, eyePos, n, ambient, diffuse);
    if (LIGHT_COUNT > 4) color += lightContribution(4, eyePos, n, ambient, diffuse);
    if (LIGHT_COUNT > 5) color += lightContribution(5, eyePos, n, ambient, diffuse);
    if (LIGHT_COUNT > 6) color += lightContribution(6, eyePos, n, ambient, diffuse);
    if (LIGHT_COUNT > 7) color += lightContribution(7, eyePos, n, ambient, diffuse);
    // The reference (Nokia's engine on Mesa's OpenGL ES 1.1) interpolates the
    // lit colour unclamped: Mesa enables vertex colour clamping only for
    // desktop compatibility contexts, so a vertex lit above 1 brightens a
    // MODULATE texture and the interpolation between vertices. The colour is
    // clamped only when written to the target. F_CLAMP_LIT clamps here instead,
    // as the OpenGL ES 1.1 specification says (colours are clamped after lighting).
    if (has(F_CLAMP_LIT)) color = clamp(color, 0.0, 1.0);
    return vec4(color, clamp(diffuse.a, 0.0, 1.0));
}

vec4 texCoord(vec3 raw, int unit) {
    vec4 st = vec4(raw * u.texScaleBias[unit].w + u.texScaleBias[unit].xyz, 1.0);
    return u.texMatrix[unit] * st;
}

void main() {
    vec4 eye;
    if (has(F_CLIP_SPACE)) {
        eye = vec4(inPosition, 1.0);
        gl_Position = u.projection * eye;
    } else {
        vec3 p = inPosition * u.positionScaleBias.w + u.positionScaleBias.xyz;
        eye = u.modelView * vec4(p, 1.0);
        gl_Position = u.projection * eye;
    }
    vec4 vertexColor = has(F_HAS_COLORS) ? inColor : u.defaultColor;

    vec4 front, back;
    if (LIGHTING) {  // PipelineKey::lighting comes from F_LIGHTING / F_TWO_SIDED
        vec3 eyePos = eye.xyz / eye.w;
        vec3 n = has(F_HAS_NORMALS) ? inNormal : vec3(0.0, 0.0, 1.0);
        n = mat3(u.normalMatrix) * n;
        float len = length(n);
        n = len > 0.0 ? n / len : n;  // GL_NORMALIZE
        bool track = has(F_COLOR_TRACKING);
        vec4 ambient = track ? vertexColor : u.matAmbient;
        vec4 diffuse = track ? vertexColor : u.matDiffuse;
        front = lightVertex(eyePos, n, ambient, diffuse);
        back = TWO_SIDED ? lightVertex(eyePos, -n, ambient, diffuse) : front;
    } else {
        front = back = clamp(vertexColor, 0.0, 1.0);
    }
    front.a *= u.misc.x;
    back.a *= u.misc.x;
    if (FLAT) {
        outFlatFront = front;
        if (TWO_SIDED) outFlatBack = back;
    } else {
        outFront = front;
        if (TWO_SIDED) outBack = back;
    }
    if (TEX0_USED) outTex0 = texCoord(inTex0, 0);
    if (TEX1_USED) outTex1 = texCoord(inTex1, 1);
    if (FOG_USED) outFogDepth = u.misc.z >= 0.0 ? u.misc.z : abs(eye.z / eye.w);
}
