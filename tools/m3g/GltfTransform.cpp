#include "GltfTransform.h"

#include <algorithm>
#include <cmath>

#include <m3g/Transform.h>

namespace m3gcli::gltf {

namespace {

using Mat3 = std::array<std::array<double, 3>, 3>;  // [row][col]

Mat3 upper3x3(const m3g::Transform& m) {
    Mat3 a{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) a[r][c] = m.at(r, c);
    return a;
}

double det3(const Mat3& a) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

std::array<double, 9> flat(const Mat3& a) {
    return {a[0][0], a[0][1], a[0][2], a[1][0], a[1][1], a[1][2], a[2][0], a[2][1], a[2][2]};
}

/// Eigen-decomposition of a symmetric 3x3 by cyclic Jacobi rotations:
/// `a` becomes diagonal (the eigenvalues), the columns of `v` the eigenvectors.
void jacobi(Mat3& a, Mat3& v) {
    v = Mat3{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    for (int sweep = 0; sweep < 50; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        if (off < 1e-30) return;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (std::abs(a[p][q]) < 1e-300) continue;
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 3; ++k) {  // a = a * J
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) {  // a = Jᵀ * a
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {  // v = v * J
                    const double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    }
}

std::array<double, 3> column(const Mat3& m, int c) { return {m[0][c], m[1][c], m[2][c]}; }

std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

bool isIdentity(const m3g::Transform& m) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            if (m.at(r, c) != (r == c ? 1.0f : 0.0f)) return false;
    return true;
}

std::array<float, 4> normalizedQuaternion(const std::array<float, 4>& q) {
    const double len = std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] + double(q[2]) * q[2] + double(q[3]) * q[3]);
    if (!(len > 0.0) || !std::isfinite(len)) return {0.0f, 0.0f, 0.0f, 1.0f};
    return {float(q[0] / len), float(q[1] / len), float(q[2] / len), float(q[3] / len)};
}

std::array<float, 4> quaternionFromRotation(const std::array<double, 9>& m) {
    // Shepperd's method: pick the largest of w, x, y, z to divide by.
    const double trace = m[0] + m[4] + m[8];
    double x, y, z, w;
    if (trace > 0.0) {
        const double s = std::sqrt(trace + 1.0) * 2.0;
        w = 0.25 * s;
        x = (m[7] - m[5]) / s;
        y = (m[2] - m[6]) / s;
        z = (m[3] - m[1]) / s;
    } else if (m[0] > m[4] && m[0] > m[8]) {
        const double s = std::sqrt(1.0 + m[0] - m[4] - m[8]) * 2.0;
        w = (m[7] - m[5]) / s;
        x = 0.25 * s;
        y = (m[1] + m[3]) / s;
        z = (m[2] + m[6]) / s;
    } else if (m[4] > m[8]) {
        const double s = std::sqrt(1.0 + m[4] - m[0] - m[8]) * 2.0;
        w = (m[2] - m[6]) / s;
        x = (m[1] + m[3]) / s;
        y = 0.25 * s;
        z = (m[5] + m[7]) / s;
    } else {
        const double s = std::sqrt(1.0 + m[8] - m[0] - m[4]) * 2.0;
        w = (m[3] - m[1]) / s;
        x = (m[2] + m[6]) / s;
        y = (m[5] + m[7]) / s;
        z = 0.25 * s;
    }
    return normalizedQuaternion({float(x), float(y), float(z), float(w)});
}

MatrixNodes matrixNodes(const m3g::Transform& m) {
    MatrixNodes out;
    out.projectiveDropped = m.at(3, 0) != 0.0f || m.at(3, 1) != 0.0f || m.at(3, 2) != 0.0f || m.at(3, 3) != 1.0f;
    // With a projective row, keep the affine part (w = 1 at the origin when
    // m33 is not 0: divide the affine part by it).
    const double w = (out.projectiveDropped && m.at(3, 3) != 0.0f) ? m.at(3, 3) : 1.0;
    Mat3 a = upper3x3(m);
    for (auto& row : a)
        for (double& v : row) v /= w;
    const std::array<float, 3> t{float(m.at(0, 3) / w), float(m.at(1, 3) / w), float(m.at(2, 3) / w)};

    // TRS test: orthogonal columns (then A = R * diag(s)).
    double scale = 0.0;
    for (const auto& row : a)
        for (double v : row) scale = std::max(scale, std::abs(v));
    std::array<double, 3> s{};
    for (int c = 0; c < 3; ++c) {
        const auto col = column(a, c);
        s[static_cast<std::size_t>(c)] = std::sqrt(col[0] * col[0] + col[1] * col[1] + col[2] * col[2]);
    }
    bool orthogonal = scale > 0.0 && s[0] > 1e-6 * scale && s[1] > 1e-6 * scale && s[2] > 1e-6 * scale;
    if (orthogonal) {
        for (int i = 0; i < 3 && orthogonal; ++i)
            for (int j = i + 1; j < 3; ++j) {
                const auto ci = column(a, i), cj = column(a, j);
                const double d = (ci[0] * cj[0] + ci[1] * cj[1] + ci[2] * cj[2]) / (s[i] * s[j]);
                if (std::abs(d) > 1e-5) orthogonal = false;
            }
    }
    if (orthogonal) {
        out.asMatrix = true;
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) out.columnMajor[static_cast<std::size_t>(c * 4 + r)] = float(a[r][c]);
        for (int r = 0; r < 3; ++r) out.columnMajor[static_cast<std::size_t>(12 + r)] = t[static_cast<std::size_t>(r)];
        out.columnMajor[15] = 1.0f;
        return out;
    }

    // A = U Σ Vᵀ: V and Σ² from the eigen-decomposition of AᵀA, U = A V Σ⁻¹.
    Mat3 ata{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) ata[i][j] += a[k][i] * a[k][j];
    Mat3 v;
    jacobi(ata, v);
    if (det3(v) < 0)
        for (int r = 0; r < 3; ++r) v[r][2] = -v[r][2];
    std::array<double, 3> sigma{};
    Mat3 u{};
    int zero = -1;
    for (int c = 0; c < 3; ++c) {
        sigma[static_cast<std::size_t>(c)] = std::sqrt(std::max(ata[c][c], 0.0));
        const auto vc = column(v, c);
        for (int r = 0; r < 3; ++r)
            u[r][c] = sigma[c] > 1e-12 * std::max(scale, 1e-30)
                          ? (a[r][0] * vc[0] + a[r][1] * vc[1] + a[r][2] * vc[2]) / sigma[c]
                          : 0.0;
        if (!(sigma[c] > 1e-12 * std::max(scale, 1e-30))) zero = c;
    }
    if (zero >= 0) {
        // A singular matrix: complete U with a unit vector orthogonal to the others.
        const int i = (zero + 1) % 3, j = (zero + 2) % 3;
        auto c = cross(column(u, i), column(u, j));
        double len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        if (len < 1e-12) c = {0, 0, 1}, len = 1;
        for (int r = 0; r < 3; ++r) u[r][zero] = c[static_cast<std::size_t>(r)] / len;
    }
    if (det3(u) < 0) {  // a reflection: carried by a negative scale
        for (int r = 0; r < 3; ++r) u[r][2] = -u[r][2];
        sigma[2] = -sigma[2];
    }
    Mat3 vt{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) vt[r][c] = v[c][r];
    Trs first, middle, last;
    first.t = t;
    first.r = quaternionFromRotation(flat(u));
    middle.s = {float(sigma[0]), float(sigma[1]), float(sigma[2])};
    last.r = quaternionFromRotation(flat(vt));
    out.chain = {first, middle, last};
    return out;
}

}  // namespace m3gcli::gltf
