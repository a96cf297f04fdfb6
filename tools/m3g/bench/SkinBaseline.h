// The founding paper's baseline: skinning as the paper (§4.1, Table 1)
// describes Nokia's JSR-184 engine doing it, reimplemented to be measured
// against (tests and benchmarks only, never used by the library).
//
//  - addTransform() appends a weighted-transform record WT (bone, weight,
//    first vertex, vertex count) to a list L; nothing per vertex is stored.
//  - At every render, for each bone the position transform PT (bone -> mesh
//    now x at rest) and the normal transform NT (its inverse transpose) are
//    computed as 4x4 matrices.
//  - For each vertex, the whole list L is searched for the records that
//    include the vertex; their weights are summed per bone and divided by the
//    vertex's weight sum (normalisation at render time), and the vertex
//    position and normal are accumulated through PT and NT of each bone.
//
// The spec's limit of N bones per vertex (the N largest accumulated weights,
// ties to the bone added first) is applied during that per-vertex search too,
// so that the baseline computes the same function as the library and the two
// can be compared. Normals are renormalised; vertices that no record
// includes stay in mesh space (their normal renormalised), like the library.
// Single precision throughout, plain loops.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace m3gbench {

/// One addTransform call: the paper's WT record.
struct WeightedTransform {
    int bone;  ///< dense bone index
    int weight;
    int firstVertex;
    int vertexCount;
};

class SkinBaseline {
public:
    explicit SkinBaseline(int maxInfluences = 4) : n_(maxInfluences) {}

    /// Skins vertexCount vertices. boneToMesh and atRest: 16 floats per bone,
    /// row-major 4x4 (M3G Transform order). positions: xyz per vertex in mesh
    /// space (scale and bias already applied); normals: xyz per vertex or
    /// empty (then outNormals is not written).
    void deform(std::span<const WeightedTransform> list, std::size_t boneCount, std::span<const float> boneToMesh,
                std::span<const float> atRest, std::size_t vertexCount, std::span<const float> positions,
                std::span<const float> normals, std::span<float> outPositions, std::span<float> outNormals) {
        // Per bone, per render: PT and NT (4x4).
        pt_.resize(boneCount * 16);
        nt_.resize(boneCount * 16);
        for (std::size_t b = 0; b < boneCount; ++b) {
            float* pt = &pt_[b * 16];
            mul4(&boneToMesh[b * 16], &atRest[b * 16], pt);
            inverseTranspose3(pt, &nt_[b * 16]);
        }
        for (std::size_t v = 0; v < vertexCount; ++v) {
            // Search L for the records that include v; sum weights per bone.
            hits_.clear();
            for (const WeightedTransform& wt : list) {
                if (static_cast<long long>(v) < wt.firstVertex ||
                    static_cast<long long>(v) >= static_cast<long long>(wt.firstVertex) + wt.vertexCount)
                    continue;
                auto it = std::find_if(hits_.begin(), hits_.end(), [&](const Hit& h) { return h.bone == wt.bone; });
                if (it != hits_.end())
                    it->weight += wt.weight;
                else
                    hits_.push_back({wt.bone, wt.weight});
            }
            const float* p = &positions[v * 3];
            float* op = &outPositions[v * 3];
            const bool hasNormals = !normals.empty();
            if (hits_.empty()) {
                op[0] = p[0];
                op[1] = p[1];
                op[2] = p[2];
                if (hasNormals) normalizeInto(&normals[v * 3], &outNormals[v * 3]);
                continue;
            }
            if (hits_.size() > static_cast<std::size_t>(n_)) {
                std::partial_sort(hits_.begin(), hits_.begin() + n_, hits_.end(), [](const Hit& a, const Hit& b) {
                    return a.weight != b.weight ? a.weight > b.weight : a.bone < b.bone;
                });
                hits_.resize(static_cast<std::size_t>(n_));
            }
            long long sum = 0;
            for (const Hit& h : hits_) sum += h.weight;
            float acc[3] = {0, 0, 0}, nacc[3] = {0, 0, 0};
            for (const Hit& h : hits_) {
                const float w = static_cast<float>(h.weight) / static_cast<float>(sum);
                const float* pt = &pt_[static_cast<std::size_t>(h.bone) * 16];
                for (int r = 0; r < 3; ++r)
                    acc[r] += w * (pt[r * 4] * p[0] + pt[r * 4 + 1] * p[1] + pt[r * 4 + 2] * p[2] + pt[r * 4 + 3]);
                if (hasNormals) {
                    const float* n = &normals[v * 3];
                    const float* nt = &nt_[static_cast<std::size_t>(h.bone) * 16];
                    for (int r = 0; r < 3; ++r)
                        nacc[r] += w * (nt[r * 4] * n[0] + nt[r * 4 + 1] * n[1] + nt[r * 4 + 2] * n[2]);
                }
            }
            op[0] = acc[0];
            op[1] = acc[1];
            op[2] = acc[2];
            if (hasNormals) normalizeInto(nacc, &outNormals[v * 3]);
        }
    }

private:
    struct Hit {
        int bone;
        long long weight;
    };

    static void mul4(const float* a, const float* b, float* out) {
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) {
                float s = 0.0f;
                for (int k = 0; k < 4; ++k) s += a[r * 4 + k] * b[k * 4 + c];
                out[r * 4 + c] = s;
            }
    }
    // 4x4 with the inverse transpose of m's upper 3x3 (adjugate / det).
    static void inverseTranspose3(const float* m, float* out) {
        auto at = [&](int r, int c) { return m[r * 4 + c]; };
        float cof[3][3];
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
                cof[r][c] = at(r1, c1) * at(r2, c2) - at(r1, c2) * at(r2, c1);
            }
        const float det = at(0, 0) * cof[0][0] + at(0, 1) * cof[0][1] + at(0, 2) * cof[0][2];
        const float inv = det != 0.0f ? 1.0f / det : 1.0f;
        for (int i = 0; i < 16; ++i) out[i] = i == 15 ? 1.0f : 0.0f;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) out[r * 4 + c] = cof[r][c] * inv;
    }
    static void normalizeInto(const float* n, float* out) {
        const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int c = 0; c < 3; ++c) out[c] = len > 0.0f ? n[c] / len : n[c];
    }

    int n_;
    std::vector<float> pt_, nt_;
    std::vector<Hit> hits_;
};

}  // namespace m3gbench
