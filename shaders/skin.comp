#version 450
// Linear blend skinning on the GPU (JSR-184 1.1, SkinnedMesh): the compute path of
// render-vk (ComputeDeformer), the same formula and inputs as the CPU kernel
// skin::SkinningJob (skin/src/Skinning.cpp, skinOne):
//   p' = (sum_k w_k P[b_k]) * (s * p + bias)
//   n' = normalise((sum_k w_k N[b_k]) * n)
// over the InfluenceTable's structure of arrays (bone indices and already
// normalised weights, `stride` slots per vertex, filled from slot 0, -1 =
// empty) and the bone palette (skin::PaletteEntry, std430). A vertex with no
// influence (or beyond the table) stays in mesh space: s * p + bias, its
// normal renormalised. A slot whose bone is outside the palette contributes
// nothing. One invocation per vertex; results go straight into the vertex
// buffer the draw reads (float streams, xyz per vertex).
#extension GL_GOOGLE_include_directive : require
#include "deform_params.glsl"

layout(local_size_x = DEFORM_GROUP_SIZE) in;

struct PaletteEntry {
    vec4 position[3];  // rows 0..2 of bone -> mesh now x at rest
    vec4 normal[3];    // rows 0..2 of its inverse transpose (w = 0)
};

layout(std430, set = 0, binding = 0) readonly buffer Palette { PaletteEntry palette[]; };
// The static inputs: one buffer seen as floats and as ints (bone indices).
layout(std430, set = 0, binding = 1) readonly buffer InputFloats { float inF[]; };
layout(std430, set = 0, binding = 2) readonly buffer InputInts { int inI[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Output { float outF[]; };

layout(push_constant) uniform Params { SkinParams p; };

// The palette is read straight from the storage buffer: it is small and
// read by every vertex, so a GPU keeps it in cache. (Copying it into shared
// memory per work group first was measured no faster on lavapipe, where
// both are per-lane gathers: about 0.9 us of CPU per vertex either way.)
vec4 paletteRow(uint b, uint r) {
    return r < 3u ? palette[b].position[r] : palette[b].normal[r - 3u];
}

vec3 load3(uint offset, uint v) {
    const uint i = offset + v * 3u;
    return vec3(inF[i], inF[i + 1u], inF[i + 2u]);
}

void store3(uint offset, uint v, vec3 x) {
    const uint i = offset + v * 3u;
    outF[i] = x.x;
    outF[i + 1u] = x.y;
    outF[i + 2u] = x.z;
}

// x / |x|; a zero-length (or NaN) vector is left as it is (skin::detail::normalize3).
vec3 renormalise(vec3 n) {
    const float len2 = dot(n, n);
    return len2 > 0.0 ? n / sqrt(len2) : n;
}

void main() {
    const uint v = gl_GlobalInvocationID.x;
    if (v >= p.vertexCount) return;
    const bool normals = p.normalsIn != NO_STREAM;
    // The palette has the position scale and bias folded into its position
    // rows (skin::PaletteJob::positionScale): only a vertex without bones
    // applies them here.
    const vec3 raw = load3(p.positionsIn, v);

    // Blend the matrices over the filled slots (leading slots with a bone
    // index >= 0), then apply the blend once, as the CPU kernel does.
    vec4 m0 = vec4(0.0), m1 = vec4(0.0), m2 = vec4(0.0);
    vec4 n0 = vec4(0.0), n1 = vec4(0.0), n2 = vec4(0.0);
    bool influenced = false;
    if (v < p.tableVertices) {
        const uint slots = v * p.stride;
        for (uint k = 0u; k < p.stride; ++k) {
            const int index = inI[p.bonesIn + slots + k];
            if (index < 0) break;
            influenced = true;
            const uint b = uint(index);
            if (b >= p.boneCount) continue;  // outside the palette: contributes nothing
            const float w = inF[p.weightsIn + slots + k];
            m0 += w * paletteRow(b, 0u);
            m1 += w * paletteRow(b, 1u);
            m2 += w * paletteRow(b, 2u);
            if (normals) {
                n0 += w * paletteRow(b, 3u);
                n1 += w * paletteRow(b, 4u);
                n2 += w * paletteRow(b, 5u);
            }
        }
    }
    if (!influenced) {  // no bone: mesh space
        store3(p.positionsOut, v, p.positionScale * raw + p.positionBias.xyz);
        if (normals) store3(p.normalsOut, v, renormalise(load3(p.normalsIn, v)));
        return;
    }
    const vec4 ph = vec4(raw, 1.0);
    store3(p.positionsOut, v, vec3(dot(m0, ph), dot(m1, ph), dot(m2, ph)));
    if (normals) {
        const vec3 n = load3(p.normalsIn, v);
        store3(p.normalsOut, v, renormalise(vec3(dot(n0.xyz, n), dot(n1.xyz, n), dot(n2.xyz, n))));
    }
}
