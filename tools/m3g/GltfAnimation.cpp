#include "GltfAnimation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <m3g/KeyframeSequence.h>

#include "GltfTransform.h"
#include "KeyframeSampler.h"

namespace m3gcli::gltf {

namespace {

using m3g::KeyframeSequence;
using m3g::detail::KeyframeView;

/// Keyframe times along the valid range (first..last, wrapping).
std::vector<double> validTimes(const KeyframeView& k) {
    std::vector<double> out;
    const int count = k.first <= k.last ? k.last - k.first + 1 : k.keyCount - k.first + k.last + 1;
    for (int j = 0; j < count; ++j) {
        int i = k.first + j;
        if (i >= k.keyCount) i -= k.keyCount;
        out.push_back(k.times[static_cast<std::size_t>(i)]);
    }
    return out;
}

std::vector<float> sampleAt(const KeyframeView& k, double s) {
    std::vector<float> v(static_cast<std::size_t>(k.components));
    m3g::detail::sampleKeyframes(k, s, v);
    return v;
}

double quatDot(const float* a, const float* b) {
    return double(a[0]) * b[0] + double(a[1]) * b[1] + double(a[2]) * b[2] + double(a[3]) * b[3];
}

/// Strictly increasing float seconds (keys closer than a float step are
/// pushed apart by one ulp; glTF requires increasing inputs, §3.11).
std::vector<float> toSeconds(const std::vector<double>& worldMs) {
    std::vector<float> out;
    out.reserve(worldMs.size());
    for (double w : worldMs) {
        float t = static_cast<float>(std::max(w, 0.0) / 1000.0);
        if (!out.empty() && t <= out.back()) t = std::nextafter(out.back(), std::numeric_limits<float>::infinity());
        out.push_back(t);
    }
    return out;
}

}  // namespace

double channelEnd(const KeyframeSequence& sequence, const TimeMapping& mapping) {
    const KeyframeView k = m3g::detail::viewOf(sequence);
    if (!m3g::detail::keyframeProblem(k).empty() || mapping.speed == 0.0 || !std::isfinite(mapping.speed)) return 0.0;
    if (k.repeatMode == KeyframeSequence::LOOP) return k.duration / std::abs(mapping.speed);
    double end = 0.0;
    for (double t : validTimes(k)) end = std::max(end, mapping.worldTime(t));
    return end;
}

SamplerKeys convertSequence(const KeyframeSequence& sequence, const TimeMapping& mapping, double clipEnd,
                            bool rotation) {
    const KeyframeView k = m3g::detail::viewOf(sequence);
    if (const std::string problem = m3g::detail::keyframeProblem(k); !problem.empty())
        throw std::invalid_argument("KeyframeSequence cannot be sampled: " + problem);
    SamplerKeys out;
    out.components = k.components;
    const auto comps = static_cast<std::size_t>(k.components);
    clipEnd = std::max(clipEnd, 0.0);

    // A stopped controller holds one value.
    if (mapping.speed == 0.0 || !std::isfinite(mapping.speed)) {
        out.interpolation = "STEP";
        out.times = {0.0f};
        out.values = sampleAt(k, mapping.refSequenceTime);
        if (rotation) {
            const auto q = normalizedQuaternion({out.values[0], out.values[1], out.values[2], out.values[3]});
            out.values.assign(q.begin(), q.end());
        }
        return out;
    }

    // Breakpoints: keyframe times (sequence time) inside the window, plus its ends.
    const double s0 = mapping.sequenceTime(0.0), s1 = mapping.sequenceTime(clipEnd);
    const double sLo = std::min(s0, s1), sHi = std::max(s0, s1);
    std::vector<double> breaks{sLo, sHi};
    const std::vector<double> times = validTimes(k);
    if (k.repeatMode == KeyframeSequence::LOOP) {
        const double d = k.duration;
        for (double t : times) {
            for (double n = std::floor((sLo - t) / d); t + n * d <= sHi; n += 1.0) {
                const double s = t + n * d;
                if (s >= sLo) breaks.push_back(s);
                if (breaks.size() > kMaxChannelKeys) break;
            }
            if (breaks.size() > kMaxChannelKeys) break;
        }
    } else {
        for (double t : times)
            if (t >= sLo && t <= sHi) breaks.push_back(t);
    }
    if (breaks.size() > kMaxChannelKeys) {
        out.capped = true;
        std::sort(breaks.begin(), breaks.end());
        breaks.resize(kMaxChannelKeys);
    }
    // World times, ascending (a negative speed reverses the order).
    std::vector<double> world;
    world.reserve(breaks.size());
    for (double s : breaks) world.push_back(std::clamp(mapping.worldTime(s), 0.0, clipEnd));
    std::sort(world.begin(), world.end());
    world.erase(std::unique(world.begin(), world.end()), world.end());

    const int interpolation = k.interpolation;
    const bool resample = interpolation == KeyframeSequence::SQUAD ||
                          (interpolation == KeyframeSequence::SPLINE && rotation);
    if (resample && world.size() > 1) {
        std::vector<double> dense;
        for (std::size_t i = 0; i + 1 < world.size(); ++i)
            for (int j = 0; j < kResamplesPerSegment; ++j)
                dense.push_back(world[i] + (world[i + 1] - world[i]) * j / kResamplesPerSegment);
        dense.push_back(world.back());
        world.swap(dense);
    }

    if (interpolation == KeyframeSequence::STEP) {
        // glTF STEP holds key i's value until key i + 1: take the value in the
        // middle of that interval (right for either direction of play).
        out.interpolation = "STEP";
        for (std::size_t i = 0; i < world.size(); ++i) {
            const double w = i + 1 < world.size() ? 0.5 * (world[i] + world[i + 1]) : world[i];
            auto v = sampleAt(k, mapping.sequenceTime(w));
            if (rotation) {
                const auto q = normalizedQuaternion({v[0], v[1], v[2], v[3]});
                v.assign(q.begin(), q.end());
            }
            out.values.insert(out.values.end(), v.begin(), v.end());
        }
        out.times = toSeconds(world);
        return out;
    }

    if (interpolation == KeyframeSequence::SPLINE && !rotation && world.size() > 1) {
        // Hermite with the M3G tangents: value and one-sided slopes at each
        // key, converted from per sequence unit to per second of world time.
        out.interpolation = "CUBICSPLINE";
        const bool forward = mapping.speed > 0.0;
        const double perSecond = mapping.speed * 1000.0;
        std::vector<float> in(comps), right(comps);
        for (double w : world) {
            const double s = mapping.sequenceTime(w);
            const auto v = sampleAt(k, s);
            // In world time the incoming side is the sequence's left side
            // when playing forward, its right side when playing backward.
            m3g::detail::sampleKeyframeSlope(k, s, forward, in);
            m3g::detail::sampleKeyframeSlope(k, s, !forward, right);
            for (std::size_t c = 0; c < comps; ++c) out.values.push_back(float(in[c] * perSecond));
            out.values.insert(out.values.end(), v.begin(), v.end());
            for (std::size_t c = 0; c < comps; ++c) out.values.push_back(float(right[c] * perSecond));
        }
        // The first in-tangent and last out-tangent are unused by glTF; the
        // window ends cut the curve, so they are zeroed for tidiness.
        std::fill(out.values.begin(), out.values.begin() + static_cast<std::ptrdiff_t>(comps), 0.0f);
        std::fill(out.values.end() - static_cast<std::ptrdiff_t>(comps), out.values.end(), 0.0f);
        out.times = toSeconds(world);
        return out;
    }

    // LINEAR, SLERP, resampled SQUAD / SPLINE, and single keys.
    out.interpolation = "LINEAR";
    std::vector<std::vector<float>> values;
    for (double w : world) values.push_back(sampleAt(k, mapping.sequenceTime(w)));
    if (rotation) {
        // glTF interpolates rotations along the short arc: split every segment
        // whose ends are more than half a turn apart in quaternion space until
        // the short arc is the one M3G takes (a few halvings at most).
        for (std::size_t i = 0; i + 1 < world.size();) {
            if (quatDot(values[i].data(), values[i + 1].data()) >= 0.0 || world[i + 1] - world[i] < 1e-6) {
                ++i;
                continue;
            }
            const double mid = 0.5 * (world[i] + world[i + 1]);
            world.insert(world.begin() + static_cast<std::ptrdiff_t>(i + 1), mid);
            values.insert(values.begin() + static_cast<std::ptrdiff_t>(i + 1), sampleAt(k, mapping.sequenceTime(mid)));
        }
        for (auto& v : values) {
            const auto q = normalizedQuaternion({v[0], v[1], v[2], v[3]});
            v.assign(q.begin(), q.end());
        }
    }
    for (const auto& v : values) out.values.insert(out.values.end(), v.begin(), v.end());
    out.times = toSeconds(world);
    return out;
}

void reshapeComponents(SamplerKeys& keys, int to) {
    const int from = keys.components;
    if (from == to || from <= 0) return;
    std::vector<float> out;
    const std::size_t elements = keys.values.size() / static_cast<std::size_t>(from);
    out.reserve(elements * static_cast<std::size_t>(to));
    for (std::size_t e = 0; e < elements; ++e) {
        const float* v = keys.values.data() + e * static_cast<std::size_t>(from);
        for (int c = 0; c < to; ++c) out.push_back(from == 1 ? v[0] : (c < from ? v[c] : 0.0f));
    }
    keys.values.swap(out);
    keys.components = to;
}

}  // namespace m3gcli::gltf
