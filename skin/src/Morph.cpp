#include <m3g/skin/Morph.h>

#include <m3g/skin/ThreadPool.h>

#include "Kernels.h"

namespace m3g::skin {

namespace {

void runRange(const MorphJob& job, Isa isa, std::size_t begin, std::size_t end) noexcept {
    switch (isa) {
#ifdef M3G_SKIN_X86
        // The SIMD paths renormalise each block before storing it.
        case Isa::Sse2: detail::morphSse2(job, begin, end); return;
        case Isa::Avx2:
        case Isa::Avx512: detail::morphAvx2(job, begin, end); return;
#endif
        default:
            detail::morphScalar(job, begin, end);
            if (job.normalize)
                for (std::size_t i = begin; i < end; i += 3) detail::normalize3(job.output.data() + i);
            return;
    }
}

}  // namespace

bool MorphJob::validate() const noexcept {
    if (!isaSupported(isa)) return false;
    if (targets.size() != weights.size()) return false;
    const std::size_t n = base.size();
    if (output.size() < n) return false;
    for (const auto& t : targets)
        if (t.size() < n) return false;
    if (clamp && !(clampMin <= clampMax)) return false;
    if (normalize && n % 3 != 0) return false;
    return true;
}

bool MorphJob::run() const noexcept {
    if (!validate()) return false;
    runRange(*this, resolveIsa(isa), 0, base.size());
    return true;
}

bool MorphJob::runParallel(ThreadPool& pool, std::size_t grainVertices) const noexcept {
    if (!validate()) return false;
    const std::size_t grain = (grainVertices == 0 ? 1 : grainVertices) * 12;  // whole xyz / rgba triples
    struct Context {
        const MorphJob* job;
        Isa isa;
        std::size_t grain;
        std::size_t total;
    } context{this, resolveIsa(isa), grain, base.size()};
    pool.run(
        (base.size() + grain - 1) / grain,
        [](void* c, std::size_t chunk) {
            const auto& ctx = *static_cast<const Context*>(c);
            const std::size_t begin = chunk * ctx.grain;
            const std::size_t end = begin + ctx.grain < ctx.total ? begin + ctx.grain : ctx.total;
            runRange(*ctx.job, ctx.isa, begin, end);
        },
        &context);
    return true;
}

namespace detail {

void morphScalar(const MorphJob& j, std::size_t begin, std::size_t end) noexcept {
    const std::size_t targets = j.targets.size();
    const float* base = j.base.data();
    float* out = j.output.data();
    for (std::size_t i = begin; i < end; ++i) {
        const float b = base[i];
        float acc = b;
        for (std::size_t t = 0; t < targets; ++t) acc += j.weights[t] * (j.targets[t][i] - b);
        if (j.clamp) acc = acc < j.clampMin ? j.clampMin : (acc > j.clampMax ? j.clampMax : acc);
        out[i] = acc;
    }
}

}  // namespace detail

}  // namespace m3g::skin
