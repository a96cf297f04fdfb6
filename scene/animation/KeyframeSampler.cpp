#include "KeyframeSampler.h"
#include "SquadLanes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <m3g/KeyframeSequence.h>

#include "Check.h"
#include "Slerp.h"

namespace m3g::detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- Quaternions (x, y, z, w): the SQUAD control points in double, once
// per change of a sequence; samples in float (Slerp.h) ----

struct Quat {
    double x, y, z, w;
};
struct Vec3 {
    double x, y, z;
};

Quat quatAt(const float* p) { return {p[0], p[1], p[2], p[3]}; }

Quat mul(const Quat& a, const Quat& b) {
    return {a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w,
            a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}

Quat conjugate(const Quat& q) { return {-q.x, -q.y, -q.z, q.w}; }

double dot(const Quat& a, const Quat& b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }

Quat normalized(const Quat& q) {
    const double len = std::sqrt(dot(q, q));
    if (!(len > 0.0)) return {0, 0, 0, 1};
    return {q.x / len, q.y / len, q.z / len, q.w / len};
}

// log of a unit quaternion: (angle/2) * axis.
Vec3 logQuat(const Quat& q) {
    const double len = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
    if (len < 1e-12) return {0, 0, 0};
    const double s = std::atan2(len, q.w) / len;
    return {q.x * s, q.y * s, q.z * s};
}

// exp of a pure quaternion (v, 0).
Quat expQuat(const Vec3& v) {
    const double theta = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    const double s = theta > 1e-12 ? std::sin(theta) / theta : 1.0;
    return normalized({v.x * s, v.y * s, v.z * s, std::cos(theta)});
}

// log(a^-1 b)
Vec3 logDiff(const Quat& a, const Quat& b) { return logQuat(mul(conjugate(a), b)); }

Vec3 add(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3 sub(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3 scale(const Vec3& a, double s) { return {a.x * s, a.y * s, a.z * s}; }

// ---- The valid keyframes, indexed 0..count-1 along the valid range ----

class ValidKeys {
public:
    explicit ValidKeys(const KeyframeView& k)
        : k_(k),
          count_(k.first <= k.last ? k.last - k.first + 1 : k.keyCount - k.first + k.last + 1),
          loop_(k.repeatMode == KeyframeSequence::LOOP) {}

    int count() const { return count_; }
    int components() const { return k_.components; }
    bool loop() const { return loop_; }
    int arrayIndex(int j) const {
        int i = k_.first + j;
        return i >= k_.keyCount ? i - k_.keyCount : i;
    }
    double time(int j) const { return k_.times[arrayIndex(j)]; }
    const float* value(int j) const { return k_.values.data() + std::size_t(arrayIndex(j)) * k_.components; }
    int next(int j) const { return j == count_ - 1 ? 0 : j + 1; }
    int prev(int j) const { return j == 0 ? count_ - 1 : j - 1; }
    /// Length of the segment j -> next(j); the last one wraps to the first
    /// key through the end of the duration.
    double delta(int j) const {
        if (j == count_ - 1) return double(k_.duration) - time(count_ - 1) + time(0);
        return time(j + 1) - time(j);
    }
    /// Scales of the central difference for the incoming / outgoing tangent
    /// of key j (non-uniform spacing); 0 at the ends of a CONSTANT sequence.
    double inScale(int j) const { return tangentScale(j, delta(prev(j))); }
    double outScale(int j) const { return tangentScale(j, delta(j)); }

private:
    double tangentScale(int j, double side) const {
        if (!loop_ && (j == 0 || j == count_ - 1)) return 0.0;
        const double sum = delta(prev(j)) + delta(j);
        return sum > 0.0 ? 2.0 * side / sum : 0.0;
    }

    const KeyframeView& k_;
    int count_;
    bool loop_;
};

/// A looping sequence's time mapped into [t_first, t_first + duration).
///
/// time - q duration with q the floor of time / duration, the quotient
/// taken with the kept reciprocal, instead of fmod (a libm call) or a
/// division (either was the largest single cost of a LINEAR sample), with
/// fmod's bits: for |time| < 2^40, q duration is an exact integer and the
/// reciprocal's quotient is off by at most one, which the range check below
/// corrects. With the true q the remainder time - q duration is exactly
/// fmod's result (time >= 0; a remainder of two doubles is representable,
/// so the subtraction is exact) or fmod's result plus the duration, rounded
/// once, as the fmod path computes it (time < 0). When that rounding
/// reaches the duration itself, q + 1 gives fmod's negative remainder and
/// the fmod path's addition.
[[gnu::noinline]] double fmodOutOfLine(double time, double duration) { return std::fmod(time, duration); }

inline double loopTime(const ValidKeys& keys, double duration, double inverseDuration, double time) {
    double s;
    if (std::fabs(time) < 0x1p40) {
        const double x = time * (inverseDuration > 0.0 ? inverseDuration : 1.0 / duration);
        double q = double(static_cast<std::int64_t>(x));  // |x| < 2^40: floor without libm
        if (q > x) q -= 1.0;
        s = time - q * duration;
        if (s < 0.0)
            s = time - (q - 1.0) * duration;
        else if (s >= duration)
            s = time - (q + 1.0) * duration;
    } else {
        s = fmodOutOfLine(time, duration);
    }
    if (s < 0.0) s += duration;
    if (s < keys.time(0)) s += duration;
    return s;
}

/// The segment holding time s: the last of the n keys with time <= s, or
/// with time < s when `strict` (the left-hand limit at a key).
int segmentAt(const ValidKeys& keys, int n, double s, bool strict) {
    int lo = 0, hi = n - 1;
    while (lo < hi) {
        const int mid = (lo + hi + 1) / 2;
        if (strict ? keys.time(mid) < s : keys.time(mid) <= s)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

/// segmentAt(keys, n, s, false), trying `guess` and the segment after it
/// first. Valid keys are in non-decreasing time order, so a segment j with
/// time(j) <= s < time(j + 1) (or j the last key and time(j) <= s) is the
/// last key with time <= s: the binary search's answer.
int segmentFrom(const ValidKeys& keys, int n, double s, int guess) {
    const auto holds = [&](int j) { return keys.time(j) <= s && (j == n - 1 || keys.time(j + 1) > s); };
    if (guess >= 0 && guess < n) {
        if (holds(guess)) return guess;
        if (guess + 1 < n && holds(guess + 1)) return guess + 1;
    }
    return segmentAt(keys, n, s, false);
}

void copyKey(const ValidKeys& keys, int j, int components, std::span<float> out) {
    const float* v = keys.value(j);
    for (int c = 0; c < components; ++c) out[c] = v[c];  // a few floats: no memmove call
}

// Hermite tangent (central difference, scaled) at key j for component c.
double tangent(const ValidKeys& keys, int j, int c, double scaleFactor) {
    return scaleFactor * 0.5 * (double(keys.value(keys.next(j))[c]) - double(keys.value(keys.prev(j))[c]));
}

// The SQUAD control quaternions A_j (outgoing) and B_j (incoming).
Quat squadA(const ValidKeys& keys, int j) {
    const Quat prev = quatAt(keys.value(keys.prev(j)));
    const Quat cur = quatAt(keys.value(j));
    const Quat next = quatAt(keys.value(keys.next(j)));
    const Vec3 toNext = logDiff(cur, next);
    const Vec3 cfd = scale(add(toNext, logDiff(prev, cur)), 0.5);
    const Vec3 t = scale(sub(scale(cfd, keys.outScale(j)), toNext), 0.5);
    return mul(cur, expQuat(t));
}

Quat squadB(const ValidKeys& keys, int j) {
    const Quat prev = quatAt(keys.value(keys.prev(j)));
    const Quat cur = quatAt(keys.value(j));
    const Quat next = quatAt(keys.value(keys.next(j)));
    const Vec3 fromPrev = logDiff(prev, cur);
    const Vec3 cfd = scale(add(logDiff(cur, next), fromPrev), 0.5);
    const Vec3 t = scale(sub(fromPrev, scale(cfd, keys.inScale(j))), 0.5);
    return mul(cur, expQuat(t));
}

Quatf toFloat(const Quat& q) { return {float(q.x), float(q.y), float(q.z), float(q.w)}; }

Quatf quatfAt(const float* p) { return {p[0], p[1], p[2], p[3]}; }

/// Control quaternion `which` (0: A, 1: B) of valid key j from a view's
/// precomputed controls.
Quatf squadControl(const KeyframeView& k, int j, int which) {
    const float* c = k.squad.data() + std::size_t(j) * 8 + std::size_t(which) * 4;
    return {c[0], c[1], c[2], c[3]};
}

/// A_j and B_j of valid key j: the view's kept controls when it has them,
/// else computed (in double, rounded once) as squadControls would.
Quatf controlA(const KeyframeView& k, const ValidKeys& keys, int j) {
    return k.squad.empty() ? toFloat(squadA(keys, j)) : squadControl(k, j, 0);
}
Quatf controlB(const KeyframeView& k, const ValidKeys& keys, int j) {
    return k.squad.empty() ? toFloat(squadB(keys, j)) : squadControl(k, j, 1);
}

Arc arcFrom(std::span<const float> arcs, int index) {
    const float* a = arcs.data() + std::size_t(index) * kArcFloats;
    return {{a[0], a[1], a[2], a[3]}, a[4], static_cast<Arc::Kind>(int(a[5]))};
}

void putArc(const Arc& arc, float* out) {
    out[0] = arc.v.x, out[1] = arc.v.y, out[2] = arc.v.z, out[3] = arc.v.w;
    out[4] = arc.half;
    out[5] = float(int(arc.kind));
    out[6] = out[7] = 0.0f;
}

void writeQuat(const Quatf& q, std::span<float> out) {
    out[0] = q.x;
    out[1] = q.y;
    out[2] = q.z;
    out[3] = q.w;
}

// The samples of views without kept data (a view made by viewOf alone),
// out of line so that the kept-data path, animate()'s, stays small.

[[gnu::noinline]] void slerpPerSample(const float* p0, const float* p1, double u, std::span<float> out) {
    writeQuat(slerp(quatfAt(p0), quatfAt(p1), float(u)), out);
}

[[gnu::noinline]] void splinePerSample(const ValidKeys& keys, int j, double u, std::span<float> out) {
    const int comps = static_cast<int>(keys.components());
    const int j1 = keys.next(j);
    const double u2 = u * u, u3 = u2 * u;
    const double h00 = 2 * u3 - 3 * u2 + 1, h01 = -2 * u3 + 3 * u2;
    const double h10 = u3 - 2 * u2 + u, h11 = u3 - u2;
    // tangent(keys, j, c, sOut) and tangent(keys, j1, c, sIn) with the
    // neighbours' rows found once (next(j) is j1, prev(j1) is j) rather than
    // per component, where every store to `out` (which may alias the key
    // values, as far as the compiler knows) made it find them again.
    const double sOut = keys.outScale(j) * 0.5, sIn = keys.inScale(j1) * 0.5;
    const float* p0 = keys.value(j);
    const float* p1 = keys.value(j1);
    const float* before = keys.value(keys.prev(j));
    const float* after = keys.value(keys.next(j1));
    for (int c = 0; c < comps; ++c) {
        const double tanOut = sOut * (double(p1[c]) - double(before[c]));
        const double tanIn = sIn * (double(after[c]) - double(p0[c]));
        out[c] = float(h00 * p0[c] + h01 * p1[c] + h10 * tanOut + h11 * tanIn);
    }
}

[[gnu::noinline]] void squadPerSample(const KeyframeView& k, const ValidKeys& keys, int j, double u,
                                      std::span<float> out) {
    const int j1 = keys.next(j);
    const Quatf a = controlA(k, keys, j);
    const float uf = float(u);
    const float* p0 = keys.value(j);
    Quatf keyPoint, controlPoint;
    if (!k.arcs.empty()) {
        keyPoint = arcAt(quatfAt(p0), arcFrom(k.arcs, 2 * j), uf);
        controlPoint = arcAt(a, arcFrom(k.arcs, 2 * j + 1), uf);
    } else {
        const Quatf b = controlB(k, keys, j1);
        keyPoint = slerp(quatfAt(p0), quatfAt(keys.value(j1)), uf);
        controlPoint = slerp(a, b, uf);
    }
    writeQuat(slerp(keyPoint, controlPoint, 2.0f * uf * (1.0f - uf)), out);
}

}  // namespace

KeyframeView viewOf(const KeyframeSequence& s) noexcept {
    KeyframeView view{s.getInterpolationType(), s.getRepeatMode(),    s.getDuration(),
                      s.getComponentCount(),    s.getKeyframeCount(), s.getValidRangeFirst(),
                      s.getValidRangeLast(),    s.keyTimes(),         s.keyValues()};
    if (view.duration > 0) view.inverseDuration = 1.0 / double(view.duration);
    return view;
}

KeyframeView preparedViewOf(const KeyframeSequence& s) {
    s.validate();
    KeyframeView view = viewOf(s);
    view.squad = s.squadControls();
    view.arcs = s.quaternionArcs();
    view.tangents = s.splineTangents();
    view.flat = s.flatSegments();
    return view;
}

std::string keyframeProblem(const KeyframeView& k) {
    if (k.duration <= 0) return "the duration has not been set";
    const ValidKeys keys(k);
    for (int j = 0; j + 1 < keys.count(); ++j)
        if (keys.time(j + 1) < keys.time(j))
            return str("keyframe ", keys.arrayIndex(j + 1), " (time ", keys.time(j + 1), ") comes before keyframe ",
                       keys.arrayIndex(j), " (time ", keys.time(j),
                       ") in the valid range; times must be non-decreasing");
    const int lastTime = k.times[keys.arrayIndex(keys.count() - 1)];
    if (lastTime > k.duration)
        return str("the last valid keyframe time ", lastTime, " exceeds the duration ", k.duration);
    return {};
}

void squadControls(const KeyframeView& k, std::vector<float>& out) {
    const ValidKeys keys(k);
    out.resize(std::size_t(keys.count()) * 8);
    for (int j = 0; j < keys.count(); ++j) {
        const Quatf a = toFloat(squadA(keys, j)), b = toFloat(squadB(keys, j));
        float* c = out.data() + std::size_t(j) * 8;
        c[0] = a.x, c[1] = a.y, c[2] = a.z, c[3] = a.w;
        c[4] = b.x, c[5] = b.y, c[6] = b.z, c[7] = b.w;
    }
}

void keyframeArcs(const KeyframeView& k, std::vector<float>& out) {
    out.clear();
    const bool squad = k.interpolation == KeyframeSequence::SQUAD;
    if (!squad && k.interpolation != KeyframeSequence::SLERP) return;
    const ValidKeys keys(k);
    const int perKey = squad ? 2 : 1;
    out.resize(std::size_t(keys.count()) * perKey * kArcFloats);
    for (int j = 0; j < keys.count(); ++j) {
        const int j1 = keys.next(j);
        float* dst = out.data() + std::size_t(j) * perKey * kArcFloats;
        putArc(arcOf(quatfAt(keys.value(j)), quatfAt(keys.value(j1))), dst);
        if (squad) putArc(arcOf(controlA(k, keys, j), controlB(k, keys, j1)), dst + kArcFloats);
    }
}

void splineTangents(const KeyframeView& k, std::vector<float>& out) {
    out.clear();
    if (k.interpolation != KeyframeSequence::SPLINE) return;
    const ValidKeys keys(k);
    const int comps = k.components;
    out.resize(std::size_t(keys.count()) * 2 * std::size_t(comps));
    for (int j = 0; j < keys.count(); ++j) {
        const int j1 = keys.next(j);
        const double sOut = keys.outScale(j) * 0.5, sIn = keys.inScale(j1) * 0.5;
        const float* p0 = keys.value(j);
        const float* p1 = keys.value(j1);
        const float* before = keys.value(keys.prev(j));
        const float* after = keys.value(keys.next(j1));
        float* dst = out.data() + std::size_t(j) * 2 * std::size_t(comps);
        for (int c = 0; c < comps; ++c) {
            dst[c] = float(sOut * (double(p1[c]) - double(before[c])));
            dst[comps + c] = float(sIn * (double(after[c]) - double(p0[c])));
        }
    }
}

void flatSegments(const KeyframeView& k, std::vector<unsigned char>& out) {
    out.clear();
    if (k.interpolation == KeyframeSequence::STEP) return;
    const ValidKeys keys(k);
    const auto comps = std::size_t(k.components);
    const auto same = [comps](const float* a, const float* b) { return std::memcmp(a, b, comps * sizeof(float)) == 0; };
    out.resize(std::size_t(keys.count()));
    std::vector<float> tangents;
    if (k.interpolation == KeyframeSequence::SPLINE && k.tangents.empty()) splineTangents(k, tangents);
    const std::span<const float> tangent = k.tangents.empty() ? std::span<const float>(tangents) : k.tangents;
    for (int j = 0; j < keys.count(); ++j) {
        const int j1 = keys.next(j);
        const float* p0 = keys.value(j);
        bool flat = same(p0, keys.value(j1));
        if (flat && k.interpolation == KeyframeSequence::SPLINE) {
            const float* t = tangent.data() + std::size_t(j) * 2 * comps;
            for (std::size_t c = 0; c < 2 * comps; ++c) flat = flat && t[c] == 0.0f;
        }
        if (flat && k.interpolation == KeyframeSequence::SQUAD) {
            const Quatf a = controlA(k, keys, j), b = controlB(k, keys, j1);
            const float ab[8] = {a.x, a.y, a.z, a.w, b.x, b.y, b.z, b.w};
            flat = same(p0, ab) && same(p0, ab + 4);
        }
        out[std::size_t(j)] = flat ? 1 : 0;
    }
}

namespace {

/// sampleKeyframes and sampleKeyframesDeferringSquad (`deferred` null: compute).
SampleValidity sample(const KeyframeView& k, double time, std::span<float> out, int* segment,
                      std::vector<SquadSample>* deferred) {
    const ValidKeys keys(k);
    const int n = keys.count();
    const int comps = k.components;
    if (n == 1) {
        copyKey(keys, 0, comps, out);
        return {};
    }

    // Map the time onto the keyframes.
    double s = time;
    if (keys.loop()) {
        s = loopTime(keys, k.duration, k.inverseDuration, time);
    } else {
        if (s < keys.time(0)) {
            copyKey(keys, 0, comps, out);
            return {keys.time(0) - s, kInf};
        }
        if (s >= keys.time(n - 1)) {
            copyKey(keys, n - 1, comps, out);
            return {kInf, s - keys.time(n - 1)};
        }
    }

    // The last key with time <= s starts the segment (for CONSTANT that is
    // never the last key; for LOOP the last key starts the wrap segment).
    const int j = segment ? segmentFrom(keys, n, s, *segment) : segmentAt(keys, n, s, false);
    if (segment) *segment = j;
    const int j1 = keys.next(j);
    const double t0 = keys.time(j);
    const double delta = keys.delta(j);

    if (k.interpolation == KeyframeSequence::STEP) {
        copyKey(keys, j, comps, out);
        return {t0 + delta - s, s - t0};
    }
    if (s == t0 || !(delta > 0.0) || (!k.flat.empty() && k.flat[std::size_t(j)])) {
        copyKey(keys, j, comps, out);
        return {0.0, 0.0};
    }

    const double u = (s - t0) / delta;
    const float* p0 = keys.value(j);
    const float* p1 = keys.value(j1);
    switch (k.interpolation) {
    case KeyframeSequence::LINEAR:
        for (int c = 0; c < comps; ++c) out[c] = float((1.0 - u) * p0[c] + u * p1[c]);
        break;
    case KeyframeSequence::SLERP:
        if (k.arcs.empty())
            slerpPerSample(p0, p1, u, out);
        else
            writeQuat(arcAt(quatfAt(p0), arcFrom(k.arcs, j), float(u)), out);
        break;
    case KeyframeSequence::SPLINE: {
        if (k.tangents.empty()) {
            splinePerSample(keys, j, u, out);
            break;
        }
        const double u2 = u * u, u3 = u2 * u;
        const double h00 = 2 * u3 - 3 * u2 + 1, h01 = -2 * u3 + 3 * u2;
        const double h10 = u3 - 2 * u2 + u, h11 = u3 - u2;
        const float* tangent = k.tangents.data() + std::size_t(j) * 2 * std::size_t(comps);
        for (int c = 0; c < comps; ++c)
            out[c] = float(h00 * p0[c] + h01 * p1[c] + h10 * double(tangent[c]) + h11 * double(tangent[comps + c]));
        break;
    }
    case KeyframeSequence::SQUAD: {
        // slerp(slerp(q0, q1, u), slerp(A_j, B_j1, u), 2u(1 - u)), the two
        // inner arcs from the view when it has them.
        if (k.squad.empty() || k.arcs.empty()) {
            squadPerSample(k, keys, j, u, out);
            break;
        }
        // One formula for both: sampleSquads, now or later.
        const float* arcs = k.arcs.data() + std::size_t(2 * j) * kArcFloats;
        const SquadSample q{p0, arcs, k.squad.data() + std::size_t(j) * 8, arcs + kArcFloats, float(u), out.data()};
        if (deferred)
            deferred->push_back(q);
        else
            sampleSquads(std::span(&q, 1));
        break;
    }
    default:
        break;
    }
    return {0.0, 0.0};
}

}  // namespace

SampleValidity sampleKeyframes(const KeyframeView& k, double time, std::span<float> out, int* segment) {
    return sample(k, time, out, segment, nullptr);
}

const float* constantValue(const KeyframeView& k) {
    const ValidKeys keys(k);
    if (k.interpolation != KeyframeSequence::STEP) {
        // One flag per valid key, the wrap segment included: all flat means
        // every key equal and every segment a copy of its key.
        if (k.flat.empty()) return nullptr;
        for (const unsigned char f : k.flat)
            if (!f) return nullptr;
        return keys.value(0);
    }
    const auto bytes = std::size_t(k.components) * sizeof(float);
    for (int j = 1; j < keys.count(); ++j)
        if (std::memcmp(keys.value(0), keys.value(j), bytes) != 0) return nullptr;
    return keys.value(0);
}

SampleValidity sampleKeyframesDeferringSquad(const KeyframeView& k, double time, std::span<float> out, int* segment,
                                             std::vector<SquadSample>& deferred) {
    return sample(k, time, out, segment, &deferred);
}

void sampleSquads(std::span<const SquadSample> samples) noexcept {
    // Four at a time in SSE lanes (SquadLanes.h: the same operations, so
    // the same bits); what the lanes leave (nearly opposite keys, inner
    // points equal or opposite) by the functions themselves.
    for (std::size_t first = 0; first < samples.size(); first += 4) {
        const int n = int(std::min<std::size_t>(4, samples.size() - first));
        const SquadSample* lanes[4];
        for (int i = 0; i < n; ++i) lanes[i] = &samples[first + std::size_t(i)];
        const unsigned done = squadLanes(lanes, n);
        for (int i = 0; i < n; ++i) {
            if (done & (1u << i)) continue;
            const SquadSample& q = *lanes[i];
            const Quatf keyPoint =
                arcAt(quatfAt(q.key), arcFrom(std::span<const float>(q.keyArc, kArcFloats), 0), q.u);
            const Quatf controlPoint =
                arcAt(quatfAt(q.control), arcFrom(std::span<const float>(q.controlArc, kArcFloats), 0), q.u);
            const Quatf r = arcAt(keyPoint, arcOf(keyPoint, controlPoint), 2.0f * q.u * (1.0f - q.u));
            q.out[0] = r.x;
            q.out[1] = r.y;
            q.out[2] = r.z;
            q.out[3] = r.w;
        }
    }
}

void sampleKeyframeSlope(const KeyframeView& k, double time, bool fromLeft, std::span<float> out) {
    const ValidKeys keys(k);
    const int n = keys.count();
    const int comps = k.components;
    std::fill(out.begin(), out.begin() + comps, 0.0f);
    if (n == 1) return;
    if (k.interpolation != KeyframeSequence::SPLINE && k.interpolation != KeyframeSequence::LINEAR) return;

    double s = time;
    if (keys.loop()) {
        s = loopTime(keys, k.duration, k.inverseDuration, time);
        if (fromLeft && s == keys.time(0)) s += k.duration;  // the wrap segment ends here
    } else {
        if (fromLeft ? s <= keys.time(0) : s < keys.time(0)) return;
        if (fromLeft ? s > keys.time(n - 1) : s >= keys.time(n - 1)) return;
    }
    // The segment: the last key before s (from the left) or at/before s.
    const int j = segmentAt(keys, n, s, fromLeft);
    const int j1 = keys.next(j);
    const double delta = keys.delta(j);
    if (!(delta > 0.0)) return;
    const double u = std::clamp((s - keys.time(j)) / delta, 0.0, 1.0);
    const float* p0 = keys.value(j);
    const float* p1 = keys.value(j1);
    if (k.interpolation == KeyframeSequence::LINEAR) {
        for (int c = 0; c < comps; ++c) out[c] = float((double(p1[c]) - p0[c]) / delta);
        return;
    }
    // d/du of the Hermite basis, then d/ds = (d/du) / delta.
    const double d00 = 6 * u * u - 6 * u, d01 = -6 * u * u + 6 * u;
    const double d10 = 3 * u * u - 4 * u + 1, d11 = 3 * u * u - 2 * u;
    const double sOut = keys.outScale(j), sIn = keys.inScale(j1);
    for (int c = 0; c < comps; ++c)
        out[c] = float((d00 * p0[c] + d01 * p1[c] + d10 * tangent(keys, j, c, sOut) + d11 * tangent(keys, j1, c, sIn)) /
                       delta);
}

}  // namespace m3g::detail
