// Spherical linear interpolation of unit quaternions in single precision, for
// keyframe sampling (JSR-184 1.1, KeyframeSequence: SLERP, and the three
// SLERPs of each SQUAD sample). Internal to m3g_scene.
//
// Why not the textbook formula in double (acos, then three sines): animate()
// samples every SLERP and SQUAD track of a World each frame, and four libm
// calls in double per SLERP (twelve per SQUAD sample) were a large share of a
// skinned model's frame. Here half the angle comes from one polynomial
// arctangent of |a - b| / |a + b|, and the point on the arc from one
// polynomial sine and cosine; both stay accurate at every angle (no acos
// near 1, no division by a small sine of the whole angle near the opposite
// quaternion). The result agrees with the double formula (on a and b
// normalised in double) to about 4e-7 per component: test_Slerp.cpp bounds
// it over random pairs, far inside the 1e-4 on transforms that the
// conformance comparisons allow. Inline, so that the two independent SLERPs
// of a SQUAD sample can overlap; the rare cases are out of line.
#pragma once

#include <cmath>

namespace m3g::detail {

/// A quaternion (x, y, z, w), w the scalar part.
struct Quatf {
    float x, y, z, w;
};

namespace slerp_impl {

constexpr float kHalfPi = 1.57079632679489662f;
constexpr float kQuarterPi = 0.785398163397448310f;
constexpr float kTanEighthPi = 0.414213562373095049f;
// The double formula's switch to the normalised linear interpolation (cosine
// above 1 - 1e-9), written as |a - b|^2 = 2 - 2 cos, which float computes
// accurately there (the cosine itself would round to 1).
constexpr float kNearlyEqual = 2e-9f;
// |a + b|^2 below which the direction of the arc is formed in double
// (slerpNearlyOpposite): cosine below -0.98, 168 degrees apart.
constexpr float kOppositeBand = 0.04f;

inline float dot(const Quatf& a, const Quatf& b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }

/// wa a + wb b.
inline Quatf combine(float wa, const Quatf& a, float wb, const Quatf& b) {
    return {wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z, wa * a.w + wb * b.w};
}

/// atan2(d, p) for d, p >= 0, not both 0, with one division: Cephes'
/// single-precision reduction to |r| <= tan(pi/8) (atan x = pi/4 +
/// atan((x - 1)/(x + 1)) and atan x = pi/2 - atan(1/x), written on d and p)
/// and its minimax polynomial (relative error about 2e-7).
inline float atan2Positive(float d, float p) {
    const bool low = d <= kTanEighthPi * p;  // d/p <= tan(pi/8)
    const bool high = kTanEighthPi * d > p;  // d/p > tan(3 pi/8)
    const float num = low ? d : high ? -p : d - p;
    const float den = low ? p : high ? d : d + p;
    const float base = low ? 0.0f : high ? kHalfPi : kQuarterPi;
    const float r = num / den;
    const float z = r * r;
    return base + ((((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z - 3.33329491539e-1f) *
                       z * r +
                   r);
}

/// (cos theta, sin theta) for theta in [0, pi]: the sine and cosine of
/// psi = theta/2 - pi/4 in [-pi/4, pi/4] by Cephes' single-precision
/// minimax polynomials (about 1 ulp there), then the double angle:
/// theta = 2 psi + pi/2, so cos theta = -sin 2 psi = -2 sin psi cos psi
/// and sin theta = cos 2 psi = 1 - 2 sin^2 psi.
struct CosSin {
    float c, s;
};
inline CosSin cosSinHalfTurn(float theta) {
    const float x = 0.5f * theta - kQuarterPi;
    const float z = x * x;
    const float sinX = ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * x + x;
    const float cosX = ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z -
                       0.5f * z + 1.0f;
    return {-2.0f * sinX * cosX, 1.0f - 2.0f * sinX * sinX};
}

}  // namespace slerp_impl

/// The part of slerp(a, b, u) that does not depend on u, so that a sampler
/// can compute it once per keyframe segment: the direction of the arc and
/// half its angle.
struct Arc {
    enum Kind : int {
        Circle,       // cos theta a + sin theta v, v the unit direction
        Linear,       // a + u v, v = b - a (nearly equal a, b)
        Renormalise,  // as Circle, then normalised (nearly opposite a, b)
    };
    Quatf v;
    float half;  // half the angle between a and b (Circle, Renormalise)
    Kind kind;
};

namespace slerp_impl {
/// arcOf for a and b more than 168 degrees apart on the 4D sphere, with the
/// direction of the arc formed in double (Slerp.cpp says why).
Arc arcNearlyOpposite(const Quatf& a, const Quatf& b, float d, float p) noexcept;
/// cos theta a + sin theta v normalised, theta = 2 u half.
Quatf renormalisedArcPoint(const Quatf& a, const Quatf& v, float half, float u) noexcept;
}  // namespace slerp_impl

/// The arc from `a` to `b` (unit quaternions) as given: no sign flip towards
/// the shorter arc, as Nokia's M3G implementation (reference) does. Nearly
/// equal quaternions (cosine above 1 - 1e-9) take the linear interpolation
/// (unit to float resolution there); exactly opposite ones (cosine below
/// -1 + 1e-9) turn through a quaternion perpendicular to `a`,
/// (-a.y, a.x, -a.w, a.z), so the path is still a half circle.
inline Arc arcOf(const Quatf& a, const Quatf& b) noexcept {
    using namespace slerp_impl;
    const Quatf diff{b.x - a.x, b.y - a.y, b.z - a.z, b.w - a.w};
    const Quatf sum{a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w};
    const float d2 = dot(diff, diff);  // |a - b|^2 = 4 sin^2(omega/2) = 2 - 2 cos omega
    const float p2 = dot(sum, sum);    // |a + b|^2 = 4 cos^2(omega/2) = 2 + 2 cos omega
    if (d2 < kNearlyEqual) [[unlikely]]
        return {diff, 0.0f, Arc::Linear};
    const float d = std::sqrt(d2), p = std::sqrt(p2);
    if (p2 < kOppositeBand) [[unlikely]]
        return arcNearlyOpposite(a, b, d, p);
    // The direction from a towards b in their plane, b - (a.b) a, written
    // as (b - a) + (1 - a.b) a with 1 - a.b = |a - b|^2 / 2 when a and b are
    // close (or a + b - (1 + a.b) a when they are far apart), so that it
    // does not cancel: its rounding error is then about 1e-7 of |a - b|,
    // and the arc scales it by sin(u omega), which is no larger. Its length
    // is sin omega = 2 sin(omega/2) cos(omega/2) = d p / 2.
    const Quatf v = d2 <= p2 ? combine(1.0f, diff, 0.5f * d2, a) : combine(1.0f, sum, -0.5f * p2, a);
    const float scale = 2.0f / (d * p);
    return {{v.x * scale, v.y * scale, v.z * scale, v.w * scale}, atan2Positive(d, p), Arc::Circle};
}

/// The point at fraction `u` (0..1) of `arc`, which starts at `a`. Unit
/// length to float rounding (Circle is not renormalised: within about 4e-7
/// of 1).
inline Quatf arcAt(const Quatf& a, const Arc& arc, float u) noexcept {
    using namespace slerp_impl;
    if (arc.kind == Arc::Circle) [[likely]] {
        const CosSin t = cosSinHalfTurn(2.0f * u * arc.half);
        return combine(t.c, a, t.s, arc.v);
    }
    // |a + u (b - a)|^2 = 1 - u (1 - u) |a - b|^2 for unit a and b, and
    // |a - b|^2 < 2e-9 here: within 3e-10 of 1, below float's resolution,
    // so renormalising would change nothing. Frequent: a bone that keeps
    // its rotation from one key to the next.
    if (arc.kind == Arc::Linear) return combine(1.0f, a, u, arc.v);
    return renormalisedArcPoint(a, arc.v, arc.half, u);
}

/// The point at fraction `u` (0..1) of the great arc from `a` to `b`:
/// arcAt(a, arcOf(a, b), u).
inline Quatf slerp(const Quatf& a, const Quatf& b, float u) noexcept { return arcAt(a, arcOf(a, b), u); }

/// SQUAD between q0 and q1 with control quaternions a (outgoing at q0) and
/// b (incoming at q1): slerp(slerp(q0, q1, u), slerp(a, b, u), 2u(1 - u)).
inline Quatf squad(const Quatf& q0, const Quatf& q1, const Quatf& a, const Quatf& b, float u) noexcept {
    return slerp(slerp(q0, q1, u), slerp(a, b, u), 2.0f * u * (1.0f - u));
}

}  // namespace m3g::detail
