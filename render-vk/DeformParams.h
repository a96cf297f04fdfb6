// C++ mirror of shaders/deform_params.glsl: the push constants of
// skin.comp and morph.comp. Offsets are in 32-bit elements.
#pragma once

#include <cstdint>

namespace m3g::vk {

constexpr std::uint32_t kNoStream = 0xFFFFFFFFu;
constexpr std::uint32_t kDeformGroupSize = 64;  // DEFORM_GROUP_SIZE

struct SkinParams {
    float positionBias[4];
    float positionScale;
    std::uint32_t vertexCount;
    std::uint32_t tableVertices;
    std::uint32_t stride;
    std::uint32_t boneCount;
    std::uint32_t bonesIn;
    std::uint32_t weightsIn;
    std::uint32_t positionsIn;
    std::uint32_t normalsIn;
    std::uint32_t positionsOut;
    std::uint32_t normalsOut;
    std::uint32_t pad;  // the struct's std430 size is a multiple of its vec4's alignment
};
static_assert(sizeof(SkinParams) == 64, "SkinParams must match deform_params.glsl");

enum MorphFlags : std::uint32_t { MORPH_CLAMP = 1, MORPH_NORMALIZE = 2 };

struct MorphParams {
    std::uint32_t vertexCount;
    std::uint32_t components;
    std::uint32_t targetCount;
    std::uint32_t valuesIn;
    std::uint32_t valuesOut;
    std::uint32_t outStride;
    std::uint32_t flags;
};
static_assert(sizeof(MorphParams) == 28, "MorphParams must match deform_params.glsl");

}  // namespace m3g::vk
