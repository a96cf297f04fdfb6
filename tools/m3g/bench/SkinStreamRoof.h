// The memory-bandwidth reference of the skinning benchmarks: a plain stream
// of the same bytes per vertex as the 4-influence positions + normals kernel
// moves (tests/bench/SkinWorkload.h's arrays), with next to no arithmetic, so
// that a kernel's figure reads as a share of what the machine can move.
//
// Two sizes. With `tables` (a loose vertex, the list path) it reads the
// vertex-list entry (4 bytes), the position and the normal (12 + 12), the
// N = 4 bone indices and weights (16 + 16), and writes the output position
// and normal (12 + 12): 84 bytes. Without (a vertex of a shared-influence
// run, whose influences are read once per run) only the position and normal
// in and out: 48 bytes. The palette, a few KiB, stays in L1 for both. The
// outputs are the inputs with the other words folded in by XOR, so no load
// is dead.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

#include <m3g/skin/ThreadPool.h>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define M3G_STREAM_X86 1
#endif

namespace m3gbench {

struct SkinStreamRoof {
    /// Bytes per vertex the stream (and the kernel) moves, with and without
    /// the list entry and influence table.
    static constexpr std::size_t kTableBytes = 4 + 16 + 16;
    static constexpr std::size_t kVertexBytes = 12 + 12 + 12 + 12;
    static constexpr std::size_t kBytesPerVertex = kTableBytes + kVertexBytes;

    /// Whether the list entry and influence table are streamed too.
    bool tables = true;
    std::size_t bytesPerVertex() const noexcept { return tables ? kBytesPerVertex : kVertexBytes; }

    std::span<const std::uint32_t> vertices;  // V entries
    std::span<const float> positions, normals;  // 3V
    std::span<const std::int32_t> boneIndices;  // 4V
    std::span<const float> boneWeights;         // 4V
    std::span<float> outPositions, outNormals;  // 3V

    /// Streams vertices [begin, end) (begin a multiple of 8).
    void run(std::size_t begin, std::size_t end) const noexcept {
#ifdef M3G_STREAM_X86
        if (__builtin_cpu_supports("avx2")) {
            runAvx2(begin, end);
            return;
        }
#endif
        runPlain(begin, end);
    }

    /// All vertices, on `pool` in chunks of `grain` when given.
    void frame(m3g::skin::ThreadPool* pool = nullptr, std::size_t grain = 4096) const noexcept {
        const std::size_t v = vertices.size();
        if (!pool) {
            run(0, v);
            return;
        }
        auto task = [&](std::size_t chunk) {
            const std::size_t begin = chunk * grain;
            run(begin, begin + grain < v ? begin + grain : v);
        };
        pool->parallelFor((v + grain - 1) / grain, task);
    }

private:
    void runPlain(std::size_t begin, std::size_t end) const noexcept {
        for (std::size_t i = begin; i < end; ++i) {
            std::uint32_t mix = tables ? vertices[i] : 0x5A5A5A5Au;
            for (int k = 0; tables && k < 4; ++k) {
                std::uint32_t w;
                std::memcpy(&w, &boneWeights[i * 4 + static_cast<std::size_t>(k)], 4);
                mix ^= static_cast<std::uint32_t>(boneIndices[i * 4 + static_cast<std::size_t>(k)]) ^ w;
            }
            for (int c = 0; c < 3; ++c) {
                const std::size_t e = i * 3 + static_cast<std::size_t>(c);
                std::uint32_t p, n;
                std::memcpy(&p, &positions[e], 4);
                std::memcpy(&n, &normals[e], 4);
                p ^= mix;
                n ^= mix;
                std::memcpy(&outPositions[e], &p, 4);
                std::memcpy(&outNormals[e], &n, 4);
            }
        }
    }

#ifdef M3G_STREAM_X86
    __attribute__((target("avx2"), always_inline)) static __m256i ld(const void* p) noexcept {
        return _mm256_loadu_si256(static_cast<const __m256i*>(p));
    }
    __attribute__((target("avx2"))) void runAvx2(std::size_t begin, std::size_t end) const noexcept {
        std::size_t i = begin;
        for (; i + 8 <= end; i += 8) {
            // 8 vertices: 1 + 4 + 4 + 3 + 3 loads of 32 bytes, 3 + 3 stores
            // (3 + 3 loads without the tables).
            __m256i mix = tables ? ld(vertices.data() + i) : _mm256_set1_epi32(0x5A5A5A5A);
            for (int q = 0; tables && q < 4; ++q) {
                mix = _mm256_xor_si256(mix, ld(boneIndices.data() + i * 4 + 8 * q));
                mix = _mm256_xor_si256(mix, ld(boneWeights.data() + i * 4 + 8 * q));
            }
            for (int q = 0; q < 3; ++q) {
                const std::size_t e = i * 3 + 8 * static_cast<std::size_t>(q);
                _mm256_storeu_si256(reinterpret_cast<__m256i*>(outPositions.data() + e),
                                    _mm256_xor_si256(mix, ld(positions.data() + e)));
                _mm256_storeu_si256(reinterpret_cast<__m256i*>(outNormals.data() + e),
                                    _mm256_xor_si256(mix, ld(normals.data() + e)));
            }
        }
        runPlain(i, end);
    }
#endif
};

}  // namespace m3gbench
