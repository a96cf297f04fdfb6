// Morph-target blending (JSR-184 1.1, MorphingMesh): out = B + sum_i w_i (T_i - B),
// element-wise over float arrays (positions, normals, colours, texture
// coordinates alike). ozz-style job: spans, validate(), run(), no memory.
#pragma once

#include <cstddef>
#include <span>

#include <m3g/skin/Isa.h>

namespace m3g::skin {

class ThreadPool;

struct MorphJob {
    /// B: the base values (any number of components per vertex).
    std::span<const float> base;
    /// T_i: one span per target, each at least base.size() long.
    std::span<const std::span<const float>> targets;
    /// w_i: one per target (any real value).
    std::span<const float> weights;
    /// At least base.size() long; may not overlap the inputs.
    std::span<float> output;

    /// Clamp each result to [clampMin, clampMax] (colours: [0, 1]).
    bool clamp = false;
    float clampMin = 0.0f;
    float clampMax = 1.0f;
    /// Renormalise each xyz triple after blending (normals); a zero-length
    /// result stays zero. Needs base.size() % 3 == 0.
    bool normalize = false;

    Isa isa = Isa::Auto;

    /// Checks sizes (targets and weights counts equal, every target and the
    /// output at least base.size()), clampMin <= clampMax, the normalise
    /// rule, and that the ISA is supported.
    bool validate() const noexcept;
    /// validate(), then blends. Returns validate(). Each element is computed
    /// by the same sequence of operations in every path position (vector
    /// lanes and tails alike), so the output does not depend on how the
    /// array is split.
    bool run() const noexcept;
    /// validate() once, then blends in chunks of `grainVertices` * 12 floats
    /// on `pool`; bit-identical to run() for any thread count.
    bool runParallel(ThreadPool& pool, std::size_t grainVertices = 8192) const noexcept;
};

}  // namespace m3g::skin
