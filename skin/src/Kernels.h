// Internal: the per-ISA kernel entry points behind SkinningJob and MorphJob.
// Each processes a sub-range of an already validated job.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include <m3g/skin/Morph.h>
#include <m3g/skin/Palette.h>
#include <m3g/skin/Skinning.h>

namespace m3g::skin::detail {

/// Listed vertices [begin, end) of `job` (job.vertices indices).
void skinScalar(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept;
/// Vertex v of `job` by the plain formula, skipping slots whose bone index is
/// outside the palette: the SIMD paths' fallback for such vertices.
void skinVertexChecked(const SkinningJob& job, std::size_t v) noexcept;
/// Elements [begin, end) of `job` (float indices into base/output); with
/// job.normalize, begin and end are multiples of 3.
void morphScalar(const MorphJob& job, std::size_t begin, std::size_t end) noexcept;

#if defined(__x86_64__) || defined(__i386__)
#define M3G_SKIN_X86 1
void skinSse2(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept;
void skinAvx2(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept;
/// Positions [begin, end) of an already validated job's run sequence, each
/// run's entries blended once (from its first vertex's slots) and applied
/// eight (AVX2) or four (SSE2) lanes at a time. False (nothing done) for the
/// cases they do not cover: no normals, or no influence.
bool skinRunsAvx2(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept;
bool skinRunsSse2(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept;
/// The same sixteen lanes at a time (Isa::Avx512), for packed arrays
/// (strides 3) only: false (nothing done) otherwise, as skinRunsAvx2.
bool skinRunsAvx512(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept;
/// Positions [begin, end) of a validated job's bone-run sequence, sixteen
/// lanes at a time: the run's palette entries weighted per lane. False
/// (nothing done) for what it does not cover: no normals, no influence,
/// other strides than 3.
bool skinBoneRunsAvx512(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept;
/// The same eight lanes at a time for a run's whole eights, its last
/// vertices through the list kernel (false, as skinBoneRunsAvx512).
bool skinBoneRunsAvx2(const SkinningJob& job, std::size_t begin, std::size_t end) noexcept;
/// Elements [begin, end) of a validated MorphJob; with job.normalize, each
/// xyz triple renormalised before it is stored (four or eight lanes at a
/// time; the last triples in a padded block, through the same lane
/// operations).
void morphSse2(const MorphJob& job, std::size_t begin, std::size_t end) noexcept;
void morphAvx2(const MorphJob& job, std::size_t begin, std::size_t end) noexcept;
/// PaletteJob::run's loop on an already validated job, in single
/// precision: AVX2 + FMA two bones at a time, SSE2 one at a time.
void paletteAvx2(const PaletteJob& job) noexcept;
void paletteSse2(const PaletteJob& job) noexcept;
/// The largest of `count` indices (0 for none), eight at a time: the
/// vertex-list check of SkinningJob::validate on a large list.
std::uint32_t maxIndexAvx2(const std::uint32_t* indices, std::size_t count) noexcept;
#endif

/// True for a position scale of 1 and a bias of 0, which leave positions as
/// they are: the palette then folds nothing into its rows, the run kernel
/// nothing into a run's.
inline bool isIdentityScaleBias(float scale, const std::array<float, 3>& bias) noexcept {
    return scale == 1.0f && bias[0] == 0.0f && bias[1] == 0.0f && bias[2] == 0.0f;
}

/// The bounds of a palette's Gram matrices (the 3x3s' rows dotted with
/// each other): what PaletteJob::conformal is decided from. A scaled
/// rotation's is s^2 I.
struct GramBounds {
    float minDiagonal = HUGE_VALF, maxDiagonal = 0.0f;  // squared row lengths
    float maxOff = 0.0f;                                // |dot of two rows|
    float sum = 0.0f;  // of every dot: not finite where an element is not
    /// Adds three rows of four floats (xyz used), as PaletteEntry::position.
    void add(const float* rows) noexcept {
        auto dot = [](const float* a, const float* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
        const float g00 = dot(rows, rows), g11 = dot(rows + 4, rows + 4), g22 = dot(rows + 8, rows + 8);
        const float g01 = dot(rows, rows + 4), g02 = dot(rows, rows + 8), g12 = dot(rows + 4, rows + 8);
        minDiagonal = std::min({minDiagonal, g00, g11, g22});
        maxDiagonal = std::max({maxDiagonal, g00, g11, g22});
        maxOff = std::max({maxOff, std::abs(g01), std::abs(g02), std::abs(g12)});
        sum += g00 + g11 + g22 + g01 + g02 + g12;
    }
    /// Every 3x3 added a rotation times one common scale (to within
    /// kConformalTolerance of s^2), and `positionScale` positive.
    bool conformal(float positionScale) const noexcept {
        return std::isfinite(sum) && positionScale > 0.0f && minDiagonal > 0.0f &&
               maxDiagonal - minDiagonal <= kConformalTolerance * minDiagonal &&
               maxOff <= kConformalTolerance * minDiagonal;
    }
};

/// True when every per-vertex array of `job` is packed xyz (strides 3): what
/// the kernels' whole-block loads and stores of consecutive vertices need.
inline bool isPacked(const SkinningJob& job) noexcept {
    return job.inPositionStride == 3 && job.inNormalStride == 3 && job.outPositionStride == 3 &&
           job.outNormalStride == 3;
}

/// True when the lane kernels read `job`'s input planes
/// (SkinningJob::inPositionPlanes): both given, and the arrays packed.
inline bool readsPlanes(const SkinningJob& job) noexcept {
    return !job.inPositionPlanes.empty() && !job.inNormalPlanes.empty() && isPacked(job);
}

/// f(std::bool_constant<job.normalsFromPositions>, std::bool_constant<readsPlanes(job)>):
/// the bone-run kernels' two compile-time choices (AVX2, AVX-512), made
/// once per call rather than per block.
template <class F>
inline void withBoneRunChoices(const SkinningJob& job, F&& f) {
    const bool planes = readsPlanes(job);
    if (job.normalsFromPositions) {
        if (planes) f(std::true_type{}, std::true_type{});
        else f(std::true_type{}, std::false_type{});
    } else {
        if (planes) f(std::false_type{}, std::true_type{});
        else f(std::false_type{}, std::false_type{});
    }
}

/// The palette entries (as floats) of a bone run's K slots, `bi` being its
/// first vertex's bones; false when one is outside the palette (the run then
/// goes vertex by vertex through skinVertexChecked). Shared by the AVX2 and
/// AVX-512 bone-run kernels.
template <int K>
inline bool boneRunEntries(const SkinningJob& job, const std::int32_t* bi, const float* (&e)[4]) noexcept {
    const std::size_t bones = job.palette.size();
    bool bad = false;
    for (int k = 0; k < K; ++k) {
        const auto b = static_cast<std::uint32_t>(bi[k]);
        bad |= b >= bones;
        e[k] = reinterpret_cast<const float*>(job.palette.data() + (b < bones ? b : 0));
    }
    return !bad;
}

/// The run holding position `position` of a validated run sequence (which
/// has one: position < the runs' total count). Empty runs share the next
/// run's start and come before it, so the last run starting at or before
/// `position` is the one.
inline const InfluenceRun* findRun(std::span<const InfluenceRun> runs, std::size_t position) noexcept {
    std::size_t lo = 0, hi = runs.size();  // first run with start > position, in [lo, hi]
    while (lo < hi) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (runs[mid].start <= position)
            lo = mid + 1;
        else
            hi = mid;
    }
    return runs.data() + (lo - 1);
}

/// The pieces of a validated run sequence that cover its positions
/// [begin, end), in order: each a run's first vertex (whose slots the run
/// uses) and a range of that run's vertices. Every kernel walks runs so.
class RunPieces {
public:
    RunPieces(std::span<const InfluenceRun> runs, std::size_t begin, std::size_t end) noexcept
        : run_(begin < end ? findRun(runs, begin) : nullptr), position_(begin), end_(end) {}
    /// The next piece: vertices [first, first + count) of the run starting
    /// at `runFirst`; false when the range is done.
    bool next(std::size_t& runFirst, std::size_t& first, std::size_t& count) noexcept {
        while (position_ < end_) {
            const InfluenceRun& r = *run_++;
            const std::size_t offset = position_ - r.start;
            const std::size_t left = r.vertexCount - offset;
            const std::size_t n = left < end_ - position_ ? left : end_ - position_;
            position_ += n;
            if (n == 0) continue;  // an empty run
            runFirst = r.firstVertex;
            runLength_ = r.vertexCount;
            first = r.firstVertex + offset;
            count = n;
            return true;
        }
        return false;
    }
    /// The vertex count of the last piece's run (all of it, not the piece).
    std::size_t runLength() const noexcept { return runLength_; }

private:
    const InfluenceRun* run_;
    std::size_t position_, end_;
    std::size_t runLength_ = 0;
};

/// x / |x| for an xyz triple in place (each component divided by the
/// length); a zero-length (or NaN) triple is left as it is. Shared by the scalar paths and the tails.
inline void normalize3(float* n) noexcept {
    const float len2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if (len2 > 0.0f) {
        const float len = std::sqrt(len2);
        n[0] /= len;
        n[1] /= len;
        n[2] /= len;
    }
}

}  // namespace m3g::skin::detail
