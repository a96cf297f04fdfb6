// SQUAD samples four at a time (SquadLanes.h).
//
// Why lanes: a SQUAD sample is three SLERPs in a row, one long chain of
// dependent float operations (three polynomial sines and cosines, a
// polynomial arctangent, two square roots, two divisions). A skinned
// character samples one per animated joint each frame (otokka_jump2: 20),
// and side by side in SSE registers four chains cost about what one did.
// SSE2 is part of x86-64, so no CPU check is needed. Every operation is
// Slerp.h's, in its order, unfused (SSE2 has no fused multiply-add and the
// intrinsics are not contracted), so each lane rounds exactly as the
// scalar formula does: a sample has the same bits whichever path, and
// whatever lanes beside it.
#include "SquadLanes.h"

#include "Slerp.h"

#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#include <xmmintrin.h>
#endif

namespace m3g::detail {

#if defined(__SSE2__)

namespace {

/// Four quaternions, one per lane, as x, y, z, w registers.
struct Lanes4 {
    __m128 x, y, z, w;
};

Lanes4 transposed(const float* a, const float* b, const float* c, const float* d) noexcept {
    __m128 r0 = _mm_loadu_ps(a), r1 = _mm_loadu_ps(b), r2 = _mm_loadu_ps(c), r3 = _mm_loadu_ps(d);
    _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
    return {r0, r1, r2, r3};
}

__m128 splat(float v) noexcept { return _mm_set1_ps(v); }
__m128 mul(__m128 a, __m128 b) noexcept { return _mm_mul_ps(a, b); }
__m128 add(__m128 a, __m128 b) noexcept { return _mm_add_ps(a, b); }
__m128 sub(__m128 a, __m128 b) noexcept { return _mm_sub_ps(a, b); }
/// mask ? a : b per lane.
__m128 select(__m128 mask, __m128 a, __m128 b) noexcept {
    return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b));
}

/// slerp_impl::dot: ((x x' + y y') + z z') + w w'.
__m128 dot(const Lanes4& a, const Lanes4& b) noexcept {
    return add(add(add(mul(a.x, b.x), mul(a.y, b.y)), mul(a.z, b.z)), mul(a.w, b.w));
}

/// slerp_impl::combine: wa a + wb b.
Lanes4 combine(__m128 wa, const Lanes4& a, __m128 wb, const Lanes4& b) noexcept {
    return {add(mul(wa, a.x), mul(wb, b.x)), add(mul(wa, a.y), mul(wb, b.y)), add(mul(wa, a.z), mul(wb, b.z)),
            add(mul(wa, a.w), mul(wb, b.w))};
}

/// arcAt for circle arcs: slerp_impl::cosSinHalfTurn(2 u half), then
/// cos a + sin v.
Lanes4 circlePoint(const Lanes4& a, const Lanes4& v, __m128 half, __m128 u) noexcept {
    using namespace slerp_impl;
    const __m128 theta = mul(mul(splat(2.0f), u), half);
    const __m128 x = sub(mul(splat(0.5f), theta), splat(kQuarterPi));
    const __m128 z = mul(x, x);
    __m128 sinX = add(mul(splat(-1.9515295891e-4f), z), splat(8.3321608736e-3f));
    sinX = sub(mul(sinX, z), splat(1.6666654611e-1f));
    sinX = add(mul(mul(sinX, z), x), x);
    __m128 cosX = sub(mul(splat(2.443315711809948e-5f), z), splat(1.388731625493765e-3f));
    cosX = add(mul(cosX, z), splat(4.166664568298827e-2f));
    cosX = add(sub(mul(mul(cosX, z), z), mul(splat(0.5f), z)), splat(1.0f));
    const __m128 c = mul(mul(splat(-2.0f), sinX), cosX);
    const __m128 s = sub(splat(1.0f), mul(mul(splat(2.0f), sinX), sinX));
    return combine(c, a, s, v);
}

/// arcAt for circle or (lanes of `linear`) Linear arcs: a + u v there.
Lanes4 arcPoint(const Lanes4& a, const Lanes4& v, __m128 half, __m128 u, __m128 linear) noexcept {
    const Lanes4 c = circlePoint(a, v, half, u);
    const Lanes4 l = combine(splat(1.0f), a, u, v);
    return {select(linear, l.x, c.x), select(linear, l.y, c.y), select(linear, l.z, c.z), select(linear, l.w, c.w)};
}

/// slerp_impl::atan2Positive.
__m128 atan2Positive(__m128 d, __m128 p) noexcept {
    using namespace slerp_impl;
    const __m128 t8 = splat(kTanEighthPi);
    const __m128 low = _mm_cmple_ps(d, mul(t8, p));
    const __m128 high = _mm_cmpgt_ps(mul(t8, d), p);
    const __m128 negP = _mm_xor_ps(p, splat(-0.0f));
    const __m128 num = select(low, d, select(high, negP, sub(d, p)));
    const __m128 den = select(low, p, select(high, d, add(d, p)));
    const __m128 base = select(low, _mm_setzero_ps(), select(high, splat(kHalfPi), splat(kQuarterPi)));
    const __m128 r = _mm_div_ps(num, den);
    const __m128 z = mul(r, r);
    __m128 t = sub(mul(splat(8.05374449538e-2f), z), splat(1.38776856032e-1f));
    t = add(mul(t, z), splat(1.99777106478e-1f));
    t = sub(mul(t, z), splat(3.33329491539e-1f));
    t = add(mul(mul(t, z), r), r);
    return add(base, t);
}

/// The kind slot (index 5) of a kept arc: Circle or Linear (a held key, a
/// quarter of otokka_jump2's samples) go in lanes, Renormalise (nearly
/// opposite keys) one at a time.
bool inLanes(const float* arc) noexcept {
    return arc[5] == float(int(Arc::Circle)) || arc[5] == float(int(Arc::Linear));
}
float linearMask(const float* arc) noexcept {
    std::uint32_t bits = arc[5] == float(int(Arc::Linear)) ? ~0u : 0u;
    float mask;
    std::memcpy(&mask, &bits, sizeof mask);
    return mask;
}

}  // namespace

unsigned squadLanes(const SquadSample* const* lanes, int count) noexcept {
    using namespace slerp_impl;
    // Lanes past `count` repeat lane 0 and are not written.
    const SquadSample* s[4];
    unsigned usable = 0;
    for (int i = 0; i < 4; ++i) {
        s[i] = lanes[i < count ? i : 0];
        if (i < count && inLanes(s[i]->keyArc) && inLanes(s[i]->controlArc)) usable |= 1u << i;
    }
    if (!usable) return 0;
    const __m128 u = _mm_setr_ps(s[0]->u, s[1]->u, s[2]->u, s[3]->u);
    auto quats = [&](const float* SquadSample::*field, int offset) {
        return transposed(s[0]->*field + offset, s[1]->*field + offset, s[2]->*field + offset,
                          s[3]->*field + offset);
    };
    auto halves = [&](const float* SquadSample::*field) {
        return _mm_setr_ps((s[0]->*field)[4], (s[1]->*field)[4], (s[2]->*field)[4], (s[3]->*field)[4]);
    };
    auto linear = [&](const float* SquadSample::*field) {
        return _mm_setr_ps(linearMask(s[0]->*field), linearMask(s[1]->*field), linearMask(s[2]->*field),
                           linearMask(s[3]->*field));
    };
    // The two inner SLERPs (q0 to q1, A_j to B_j+1), from the kept arcs.
    const Lanes4 key = arcPoint(quats(&SquadSample::key, 0), quats(&SquadSample::keyArc, 0),
                                halves(&SquadSample::keyArc), u, linear(&SquadSample::keyArc));
    const Lanes4 control = arcPoint(quats(&SquadSample::control, 0), quats(&SquadSample::controlArc, 0),
                                    halves(&SquadSample::controlArc), u, linear(&SquadSample::controlArc));
    // arcOf(key, control), its circle case.
    const Lanes4 diff{sub(control.x, key.x), sub(control.y, key.y), sub(control.z, key.z), sub(control.w, key.w)};
    const Lanes4 sum{add(key.x, control.x), add(key.y, control.y), add(key.z, control.z), add(key.w, control.w)};
    const __m128 d2 = dot(diff, diff), p2 = dot(sum, sum);
    const __m128 rare = _mm_or_ps(_mm_cmplt_ps(d2, splat(kNearlyEqual)), _mm_cmplt_ps(p2, splat(kOppositeBand)));
    usable &= ~static_cast<unsigned>(_mm_movemask_ps(rare));
    if (!usable) return 0;
    const __m128 d = _mm_sqrt_ps(d2), p = _mm_sqrt_ps(p2);
    const __m128 near = _mm_cmple_ps(d2, p2);
    const Lanes4 towards = combine(splat(1.0f), diff, mul(splat(0.5f), d2), key);
    const Lanes4 away = combine(splat(1.0f), sum, mul(splat(-0.5f), p2), key);
    const __m128 scale = _mm_div_ps(splat(2.0f), mul(d, p));
    const Lanes4 v{mul(select(near, towards.x, away.x), scale), mul(select(near, towards.y, away.y), scale),
                   mul(select(near, towards.z, away.z), scale), mul(select(near, towards.w, away.w), scale)};
    const __m128 half = atan2Positive(d, p);
    // The outer SLERP at 2u(1 - u).
    Lanes4 q = circlePoint(key, v, half, mul(mul(splat(2.0f), u), sub(splat(1.0f), u)));
    _MM_TRANSPOSE4_PS(q.x, q.y, q.z, q.w);
    const __m128 rows[4] = {q.x, q.y, q.z, q.w};
    for (int i = 0; i < count; ++i)
        if (usable & (1u << i)) _mm_storeu_ps(s[i]->out, rows[i]);
    return usable;
}

#else

unsigned squadLanes(const SquadSample* const*, int) noexcept { return 0; }

#endif

}  // namespace m3g::detail
