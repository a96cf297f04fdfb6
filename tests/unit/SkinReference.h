// Double-precision skinning reference for the tests, derived from the spec
// text (JSR-184 1.1, SkinnedMesh) independently of skin/: per vertex, the addTransform
// records' weights are summed per bone, the N largest kept (ties: the bone
// added first), normalised; positions go through (bone -> mesh) x (at rest),
// normals through its inverse transpose (Gauss-Jordan, not cofactors) and
// are renormalised.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <random>
#include <span>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "../bench/SkinBaseline.h"

namespace m3gtest {

using m3gbench::WeightedTransform;
using Mat4d = std::array<double, 16>;

inline Mat4d mul(const Mat4d& a, const Mat4d& b) {
    Mat4d m{};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            for (int k = 0; k < 4; ++k) m[r * 4 + c] += a[r * 4 + k] * b[k * 4 + c];
    return m;
}

/// Inverse transpose of the upper 3x3 (row-major 3x3) by Gauss-Jordan
/// elimination with partial pivoting.
inline std::array<double, 9> inverseTranspose3(const Mat4d& m) {
    double a[3][6];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 6; ++c) a[r][c] = c < 3 ? m[r * 4 + c] : (c - 3 == r ? 1.0 : 0.0);
    for (int col = 0; col < 3; ++col) {
        int pivot = col;
        for (int r = col + 1; r < 3; ++r)
            if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
        for (int c = 0; c < 6; ++c) std::swap(a[col][c], a[pivot][c]);
        const double p = a[col][col];
        for (int c = 0; c < 6; ++c) a[col][c] /= p;
        for (int r = 0; r < 3; ++r) {
            if (r == col) continue;
            const double f = a[r][col];
            for (int c = 0; c < 6; ++c) a[r][c] -= f * a[col][c];
        }
    }
    std::array<double, 9> out{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out[r * 3 + c] = a[c][3 + r];  // transpose of the inverse
    return out;
}

/// The kept (bone, normalised weight) pairs of vertex v.
inline std::vector<std::pair<int, double>> referenceInfluences(std::span<const WeightedTransform> list, int n, long v) {
    std::map<int, long long> sums;  // ordered by bone index
    for (const auto& r : list)
        if (v >= r.firstVertex && v < static_cast<long>(r.firstVertex) + r.vertexCount) sums[r.bone] += r.weight;
    std::vector<std::pair<int, long long>> all(sums.begin(), sums.end());
    // Stable: among equal weights the lower bone index stays first.
    std::stable_sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    if (all.size() > static_cast<std::size_t>(n)) all.resize(static_cast<std::size_t>(n));
    long long total = 0;
    for (const auto& [b, w] : all) total += w;
    std::vector<std::pair<int, double>> out;
    for (const auto& [b, w] : all) out.emplace_back(b, static_cast<double>(w) / static_cast<double>(total));
    return out;
}

struct ReferenceResult {
    std::vector<double> positions, normals;
};

/// boneToMesh / atRest: 16 values per bone (row-major); positions in mesh
/// space (xyz); normals xyz or empty.
inline ReferenceResult referenceSkin(std::span<const WeightedTransform> list, int n, std::span<const double> boneToMesh,
                                     std::span<const double> atRest, std::size_t vertexCount,
                                     std::span<const double> positions, std::span<const double> normals) {
    const std::size_t bones = boneToMesh.size() / 16;
    std::vector<Mat4d> pm(bones);
    std::vector<std::array<double, 9>> nm(bones);
    for (std::size_t b = 0; b < bones; ++b) {
        Mat4d a, r;
        std::copy_n(boneToMesh.begin() + static_cast<long>(b * 16), 16, a.begin());
        std::copy_n(atRest.begin() + static_cast<long>(b * 16), 16, r.begin());
        pm[b] = mul(a, r);
        nm[b] = inverseTranspose3(pm[b]);
    }
    ReferenceResult out;
    out.positions.assign(vertexCount * 3, 0.0);
    if (!normals.empty()) out.normals.assign(vertexCount * 3, 0.0);
    for (std::size_t v = 0; v < vertexCount; ++v) {
        const auto infl = referenceInfluences(list, n, static_cast<long>(v));
        const double* p = &positions[v * 3];
        double* op = &out.positions[v * 3];
        if (infl.empty()) {
            std::copy_n(p, 3, op);
        } else {
            for (const auto& [b, w] : infl)
                for (int r = 0; r < 3; ++r)
                    op[r] += w * (pm[b][r * 4] * p[0] + pm[b][r * 4 + 1] * p[1] + pm[b][r * 4 + 2] * p[2] +
                                  pm[b][r * 4 + 3]);
        }
        if (normals.empty()) continue;
        const double* nn = &normals[v * 3];
        double* on = &out.normals[v * 3];
        if (infl.empty()) {
            std::copy_n(nn, 3, on);
        } else {
            for (const auto& [b, w] : infl)
                for (int r = 0; r < 3; ++r)
                    on[r] += w * (nm[b][r * 3] * nn[0] + nm[b][r * 3 + 1] * nn[1] + nm[b][r * 3 + 2] * nn[2]);
        }
        const double len = std::sqrt(on[0] * on[0] + on[1] * on[1] + on[2] * on[2]);
        if (len > 0)
            for (int c = 0; c < 3; ++c) on[c] /= len;
    }
    return out;
}

/// Every xyz of `actual` within `rel` of `expected`, relative to the
/// expected vector's length (at least 1).
template <class A, class E>
::testing::AssertionResult closeXyz(const A& actual, const E& expected, double rel = 1e-5) {
    if (actual.size() != expected.size())
        return ::testing::AssertionFailure() << "sizes " << actual.size() << " vs " << expected.size();
    for (std::size_t v = 0; v + 2 < expected.size(); v += 3) {
        const double len = std::sqrt(double(expected[v]) * expected[v] + double(expected[v + 1]) * expected[v + 1] +
                                     double(expected[v + 2]) * expected[v + 2]);
        const double tol = rel * std::max(1.0, len);
        for (int c = 0; c < 3; ++c) {
            const double d = std::abs(double(actual[v + c]) - double(expected[v + c]));
            if (!(d <= tol))
                return ::testing::AssertionFailure()
                       << "vertex " << v / 3 << " component " << c << ": " << actual[v + c] << " vs "
                       << expected[v + c] << " (difference " << d << ", tolerance " << tol << ")";
        }
    }
    return ::testing::AssertionSuccess();
}

/// A random affine bone matrix: rotation (random axis and angle) x
/// non-uniform scale in [0.5, 2] + translation in [-5, 5].
inline std::array<float, 16> randomAffine(std::mt19937& rng, bool nonUniform = true) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    double ax = u(rng), ay = u(rng), az = u(rng);
    const double len = std::sqrt(ax * ax + ay * ay + az * az) + 1e-9;
    ax /= len, ay /= len, az /= len;
    const double angle = 3.14159265358979 * u(rng);
    const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
    const double rot[9] = {t * ax * ax + c,      t * ax * ay - s * az, t * ax * az + s * ay,
                           t * ax * ay + s * az, t * ay * ay + c,      t * ay * az - s * ax,
                           t * ax * az - s * ay, t * ay * az + s * ax, t * az * az + c};
    std::uniform_real_distribution<double> sc(0.5, 2.0);
    const double k = sc(rng);
    const double scale[3] = {nonUniform ? sc(rng) : k, nonUniform ? sc(rng) : k, nonUniform ? sc(rng) : k};
    std::array<float, 16> m{};
    for (int r = 0; r < 3; ++r) {
        for (int col = 0; col < 3; ++col) m[r * 4 + col] = static_cast<float>(rot[r * 3 + col] * scale[col]);
        m[r * 4 + 3] = static_cast<float>(5.0 * u(rng));
    }
    m[15] = 1.0f;
    return m;
}

/// A random rotation (random axis and angle) times `scale`, plus a random
/// translation: randomAffine's uniform case brought to the given scale.
inline std::array<float, 16> randomScaledRotation(std::mt19937& rng, float scale) {
    std::array<float, 16> m = randomAffine(rng, false);
    const float k = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) m[static_cast<std::size_t>(r * 4 + c)] *= scale / k;
    return m;
}

}  // namespace m3gtest
