// The rare cases of arcOf and arcAt (Slerp.h): nearly equal and nearly
// opposite quaternions.
#include "Slerp.h"

#include <cmath>

namespace m3g::detail::slerp_impl {

namespace {

Quatf normalized(const Quatf& q) {
    const float len2 = dot(q, q);
    if (!(len2 > 0.0f)) return {0, 0, 0, 1};
    const float inv = 1.0f / std::sqrt(len2);
    return {q.x * inv, q.y * inv, q.z * inv, q.w * inv};
}

}  // namespace

Quatf renormalisedArcPoint(const Quatf& a, const Quatf& v, float half, float u) noexcept {
    const CosSin t = cosSinHalfTurn(2.0f * u * half);
    return normalized(combine(t.c, a, t.s, v));
}

// Near the opposite quaternion the direction from a towards b, b - (a.b) a,
// is the short difference of two nearly opposite vectors: float's rounding
// of a.b, and of |a| and |b| around 1, would turn it by up to about
// 1e-7 / |a + b|. Formed in double instead (from a and b normalised there;
// products of floats are exact in double): a few multiplications, no
// trigonometry. The arc point is renormalised, since a is not.
Arc arcNearlyOpposite(const Quatf& a, const Quatf& b, float d, float p) noexcept {
    const double la = std::sqrt(double(a.x) * a.x + double(a.y) * a.y + double(a.z) * a.z + double(a.w) * a.w);
    const double lb = std::sqrt(double(b.x) * b.x + double(b.y) * b.y + double(b.z) * b.z + double(b.w) * b.w);
    const double ax = a.x / la, ay = a.y / la, az = a.z / la, aw = a.w / la;
    const double bx = b.x / lb, by = b.y / lb, bz = b.z / lb, bw = b.w / lb;
    const double c = ax * bx + ay * by + az * bz + aw * bw;
    if (c < -1.0 + 1e-9) {
        // Any great circle through a and -a will do: the one through a
        // quaternion perpendicular to a, half a turn.
        return {{float(-ay), float(ax), float(-aw), float(az)}, kHalfPi, Arc::Renormalise};
    }
    const double vx = bx - c * ax, vy = by - c * ay, vz = bz - c * az, vw = bw - c * aw;
    const double inv = 1.0 / std::sqrt(vx * vx + vy * vy + vz * vz + vw * vw);
    return {{float(vx * inv), float(vy * inv), float(vz * inv), float(vw * inv)}, atan2Positive(d, p),
            Arc::Renormalise};
}

}  // namespace m3g::detail::slerp_impl
