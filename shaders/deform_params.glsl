// Push constants of skin.comp and morph.comp (std430 push-constant layout:
// scalars and a vec4, no implicit padding). Mirrored by
// render-vk/DeformParams.h; keep both in step. Offsets are in 32-bit
// elements into the bound buffers; NO_STREAM marks an absent stream.

const uint NO_STREAM = 0xFFFFFFFFu;
#define DEFORM_GROUP_SIZE 64

struct SkinParams {
    vec4 positionBias;     // xyz = VertexBuffer position bias (vertices without bones;
    float positionScale;   // the palette has both folded in for the others)
    uint vertexCount;
    uint tableVertices;    // vertices the influence table covers
    uint stride;           // influence slots per vertex (maxTransformsPerVertex)
    uint boneCount;        // palette entries
    uint bonesIn;          // int offsets into InputInts
    uint weightsIn;        // float offsets into InputFloats
    uint positionsIn;
    uint normalsIn;        // NO_STREAM: no normals
    uint positionsOut;     // float offsets into Output
    uint normalsOut;
    uint pad;              // the size is a multiple of 16 (the vec4) anyway
};

const uint MORPH_CLAMP = 1u;
const uint MORPH_NORMALIZE = 2u;

struct MorphParams {
    uint vertexCount;
    uint components;       // 1..4 values per vertex
    uint targetCount;
    uint valuesIn;         // float offset of the base in Values
    uint valuesOut;        // float offset of the stream in Output
    uint outStride;        // floats per vertex in the stream: 3 or 4 (>= components)
    uint flags;            // MORPH_CLAMP | MORPH_NORMALIZE
};
