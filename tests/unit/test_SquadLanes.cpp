// sampleSquads' four-lane path (scene/animation/SquadLanes.cpp) against
// Slerp.h's scalar functions composed as a SQUAD sample is: the inner
// SLERPs from the kept arcs, then the outer arc between their points at
// 2u(1 - u). Bit for bit (both are the same unfused operations), over
// random quaternions and fractions, in batches of every size from 1 to 9,
// with lanes whose arcs are not circles (a held key: Linear, still in
// lanes; nearly opposite keys: Renormalise; inner points equal or
// opposite, so that the outer arc is not a circle) mixed among circle ones.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "KeyframeSampler.h"
#include "Slerp.h"
#include "SquadLanes.h"

using m3g::detail::Arc;
using m3g::detail::kArcFloats;
using m3g::detail::Quatf;
using m3g::detail::SquadSample;

namespace {

Quatf unit(std::mt19937& rng) {
    std::normal_distribution<float> n(0.0f, 1.0f);
    Quatf q{n(rng), n(rng), n(rng), n(rng)};
    const float len = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
    return {q.x / len, q.y / len, q.z / len, q.w / len};
}

Quatf negated(const Quatf& q) { return {-q.x, -q.y, -q.z, -q.w}; }

/// An arc in the kept layout (KeyframeView::arcs): v, half, kind, 0, 0.
std::array<float, kArcFloats> kept(const Arc& a) {
    return {a.v.x, a.v.y, a.v.z, a.v.w, a.half, float(int(a.kind)), 0.0f, 0.0f};
}

Arc arcOfKept(const std::array<float, kArcFloats>& a) {
    return {{a[0], a[1], a[2], a[3]}, a[4], static_cast<Arc::Kind>(int(a[5]))};
}

/// One sample's inputs: key q0 with its arc to q1, control A with its arc
/// to B, and u.
struct Inputs {
    Quatf key, control;
    std::array<float, kArcFloats> keyArc, controlArc;
    float u;
};

Inputs make(const Quatf& q0, const Quatf& q1, const Quatf& a, const Quatf& b, float u) {
    return {q0, a, kept(m3g::detail::arcOf(q0, q1)), kept(m3g::detail::arcOf(a, b)), u};
}

/// The scalar composition.
Quatf expected(const Inputs& in) {
    using namespace m3g::detail;
    const Quatf k = arcAt(in.key, arcOfKept(in.keyArc), in.u);
    const Quatf c = arcAt(in.control, arcOfKept(in.controlArc), in.u);
    return arcAt(k, arcOf(k, c), 2.0f * in.u * (1.0f - in.u));
}

void expectSame(const Quatf& got, const Quatf& want, const std::string& what) {
    const float g[4] = {got.x, got.y, got.z, got.w}, w[4] = {want.x, want.y, want.z, want.w};
    for (int c = 0; c < 4; ++c) {
#ifdef __FP_FAST_FMAF
        EXPECT_NEAR(g[c], w[c], 1e-6f) << what << " component " << c;
#else
        std::uint32_t gb, wb;
        std::memcpy(&gb, &g[c], 4);
        std::memcpy(&wb, &w[c], 4);
        EXPECT_EQ(gb, wb) << what << " component " << c << ": " << g[c] << " vs " << w[c];
#endif
    }
}

/// Runs sampleSquads over `inputs` and compares every sample.
void check(const std::vector<Inputs>& inputs, const std::string& what) {
    std::vector<std::array<float, 4>> out(inputs.size(), {-7.0f, -7.0f, -7.0f, -7.0f});
    std::vector<SquadSample> samples;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const Inputs& in = inputs[i];
        samples.push_back({&in.key.x, in.keyArc.data(), &in.control.x, in.controlArc.data(), in.u, out[i].data()});
    }
    m3g::detail::sampleSquads(samples);
    for (std::size_t i = 0; i < inputs.size(); ++i)
        expectSame({out[i][0], out[i][1], out[i][2], out[i][3]}, expected(inputs[i]),
                   what + ", sample " + std::to_string(i));
}

}  // namespace

TEST(SquadLanes, RandomCircleSamplesHaveTheScalarBitsInEveryBatchSize) {
    std::mt19937 rng(2024);
    std::uniform_real_distribution<float> fraction(0.0f, 1.0f);
    for (int batch = 1; batch <= 9; ++batch)
        for (int round = 0; round < 40; ++round) {
            std::vector<Inputs> in;
            for (int i = 0; i < batch; ++i) in.push_back(make(unit(rng), unit(rng), unit(rng), unit(rng), fraction(rng)));
            check(in, "batch " + std::to_string(batch));
        }
}

TEST(SquadLanes, RareArcsAmongCircleLanesTakeTheScalarPathWithTheSameBits) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> fraction(0.0f, 1.0f);
    for (int round = 0; round < 50; ++round) {
        const Quatf q = unit(rng), r = unit(rng);
        Quatf nearly = q;
        nearly.x += 1e-6f;
        std::vector<Inputs> in;
        in.push_back(make(unit(rng), unit(rng), unit(rng), unit(rng), fraction(rng)));
        in.push_back(make(q, q, unit(rng), unit(rng), fraction(rng)));                 // held key: Linear
        in.push_back(make(q, negated(nearly), unit(rng), unit(rng), fraction(rng)));  // Renormalise
        in.push_back(make(q, r, q, r, fraction(rng)));         // inner points equal: outer arc Linear
        in.push_back(make(q, r, negated(q), negated(r), fraction(rng)));  // opposite: outer arc not a circle
        in.push_back(make(unit(rng), unit(rng), unit(rng), unit(rng), 0.0f));
        in.push_back(make(unit(rng), unit(rng), unit(rng), unit(rng), 1.0f));
        check(in, "round " + std::to_string(round));
    }
}

TEST(SquadLanes, CircleLanesAreComputedSideBySideAndRareOnesLeftToTheCaller) {
    std::mt19937 rng(99);
    const Quatf q = unit(rng), r = unit(rng);
    Quatf nearly = q;
    nearly.x += 1e-6f;
    std::vector<Inputs> in{make(unit(rng), unit(rng), unit(rng), unit(rng), 0.3f),
                           make(q, negated(nearly), unit(rng), unit(rng), 0.4f),  // Renormalise key arc
                           make(q, q, unit(rng), unit(rng), 0.5f),                // Linear key arc: in lanes
                           make(q, r, q, r, 0.6f)};                               // outer arc Linear
    std::vector<std::array<float, 4>> out(in.size(), {-7.0f, -7.0f, -7.0f, -7.0f});
    std::vector<SquadSample> samples;
    for (std::size_t i = 0; i < in.size(); ++i)
        samples.push_back({&in[i].key.x, in[i].keyArc.data(), &in[i].control.x, in[i].controlArc.data(), in[i].u,
                           out[i].data()});
    const SquadSample* lanes[4] = {&samples[0], &samples[1], &samples[2], &samples[3]};
    const unsigned done = m3g::detail::squadLanes(lanes, 4);
#if defined(__SSE2__)
    EXPECT_EQ(done, 0b0101u);
    expectSame({out[0][0], out[0][1], out[0][2], out[0][3]}, expected(in[0]), "lane 0");
    expectSame({out[2][0], out[2][1], out[2][2], out[2][3]}, expected(in[2]), "lane 2 (held key)");
#else
    EXPECT_EQ(done, 0u);
#endif
    // What the lanes leave is not written.
    EXPECT_EQ(out[1][0], -7.0f);
    EXPECT_EQ(out[3][0], -7.0f);
    // Fewer lanes than four: only those are read and written.
    const unsigned two = m3g::detail::squadLanes(lanes, 1);
#if defined(__SSE2__)
    EXPECT_EQ(two, 1u);
#else
    EXPECT_EQ(two, 0u);
#endif
}
