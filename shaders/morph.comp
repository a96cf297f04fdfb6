#version 450
// Morph-target blending on the GPU (JSR-184 1.1, MorphingMesh): the compute path of
// render-vk (ComputeDeformer), the formula of the CPU kernel skin::MorphJob
// (skin/src/Morph.cpp, morphScalar):
//   out = B + sum_i w_i (T_i - B)
// for one attribute (positions, normals, colours or texture coordinates) per
// dispatch, `components` values per vertex. Targets with weight 0 contribute
// nothing (the CPU path leaves them out). Colours are clamped to [0, 1];
// normals are renormalised (a zero-length result stays zero). The result is
// written into the vertex buffer stream the draw reads, `outStride` floats
// per vertex; components beyond `components` are written as 0 (texture
// coordinate streams hold 3).
#extension GL_GOOGLE_include_directive : require
#include "deform_params.glsl"

layout(local_size_x = DEFORM_GROUP_SIZE) in;

layout(std430, set = 0, binding = 0) readonly buffer Weights { float weights[]; };
// Base then the targets, each vertexCount * components floats.
layout(std430, set = 0, binding = 1) readonly buffer Values { float values[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Output { float outF[]; };

layout(push_constant) uniform Params { MorphParams p; };

// The `components` values at element i, zeros beyond (branches on a
// push constant: the same for every invocation).
vec4 load(uint i) {
    vec4 x = vec4(values[i], 0.0, 0.0, 0.0);
    if (p.components > 1u) x.y = values[i + 1u];
    if (p.components > 2u) x.z = values[i + 2u];
    if (p.components > 3u) x.w = values[i + 3u];
    return x;
}

void main() {
    const uint v = gl_GlobalInvocationID.x;
    if (v >= p.vertexCount) return;
    const uint elements = p.vertexCount * p.components;
    const uint i = p.valuesIn + v * p.components;
    // Per component the CPU's sequence: acc = b; acc += w_t * (T_t - b).
    const vec4 b = load(i);
    vec4 acc = b;
    for (uint t = 0u; t < p.targetCount; ++t) {
        const float w = weights[t];
        if (w != 0.0) acc += w * (load(i + (t + 1u) * elements) - b);
    }
    if ((p.flags & MORPH_CLAMP) != 0u) acc = clamp(acc, 0.0, 1.0);
    if ((p.flags & MORPH_NORMALIZE) != 0u) {
        const float len2 = dot(acc.xyz, acc.xyz);
        if (len2 > 0.0) acc.xyz /= sqrt(len2);
    }
    // Components beyond `components` are 0 (texture coordinate streams hold 3).
    const uint o = p.valuesOut + v * p.outStride;
    outF[o] = acc.x;
    outF[o + 1u] = acc.y;
    outF[o + 2u] = acc.z;
    if (p.outStride > 3u) outF[o + 3u] = acc.w;
}
