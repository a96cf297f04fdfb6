#include <m3g/skin/Palette.h>

#include <cmath>

#include <m3g/skin/Isa.h>

#include "Kernels.h"

namespace m3g::skin {

namespace {

/// PaletteJob::conformal from the entries written (the Scalar and SSE2
/// paths; the AVX2 path measures its rows in registers). The position rows
/// are the 3x3 times the position scale, which scales every Gram matrix
/// alike.
void reportConformal(const PaletteJob& job) noexcept {
    if (!job.conformal) return;
    detail::GramBounds bounds;
    for (std::size_t b = 0; b < job.boneCount; ++b) bounds.add(job.output[b].position);
    *job.conformal = bounds.conformal(job.positionScale);
}

}  // namespace

bool PaletteJob::validate() const noexcept {
    const std::size_t floats = boneCount * 16;
    return boneToMesh.size() >= floats && atRest.size() >= floats && output.size() >= boneCount &&
           isaSupported(isa);
}

bool PaletteJob::run() const noexcept {
    if (!validate()) return false;
#ifdef M3G_SKIN_X86
    switch (resolveIsa(isa)) {
        case Isa::Avx2:
        case Isa::Avx512: detail::paletteAvx2(*this); return true;
        case Isa::Sse2:
            detail::paletteSse2(*this);
            reportConformal(*this);
            return true;
        default: break;
    }
#endif
    for (std::size_t b = 0; b < boneCount; ++b) {
        const float* a = boneToMesh.data() + b * 16;
        const float* r = atRest.data() + b * 16;
        // m = a * r on the top three rows (both matrices affine).
        double m[3][4];
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 4; ++j) {
                double sum = j == 3 ? static_cast<double>(a[i * 4 + 3]) : 0.0;
                for (int k = 0; k < 3; ++k)
                    sum += static_cast<double>(a[i * 4 + k]) * static_cast<double>(r[k * 4 + j]);
                m[i][j] = sum;
            }
        }
        // Cofactors of the 3x3: cof[i][j] = (-1)^(i+j) minor(i, j). The
        // inverse transpose is cof / det.
        double cof[3][3];
        for (int i = 0; i < 3; ++i) {
            const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
            for (int j = 0; j < 3; ++j) {
                const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
                // Cyclic indices give the signed cofactor directly.
                cof[i][j] = m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1];
            }
        }
        const double det = m[0][0] * cof[0][0] + m[0][1] * cof[0][1] + m[0][2] * cof[0][2];
        const double scale = det != 0.0 && std::isfinite(det) ? 1.0 / det : 1.0;
        PaletteEntry& e = output[b];
        for (int i = 0; i < 3; ++i) {
            // m (s p + bias): the columns scaled by s, m . bias added to the translation.
            double t = m[i][3];
            for (int j = 0; j < 3; ++j) {
                const double bj = positionBias[static_cast<std::size_t>(j)];
                if (bj != 0.0) t += m[i][j] * bj;  // (a non-finite row stays as it is for bias 0)
            }
            for (int j = 0; j < 3; ++j) e.position[i * 4 + j] = static_cast<float>(m[i][j] * positionScale);
            e.position[i * 4 + 3] = static_cast<float>(t);
            for (int j = 0; j < 3; ++j) e.normal[i * 4 + j] = static_cast<float>(cof[i][j] * scale);
            e.normal[i * 4 + 3] = 0.0f;
        }
    }
    reportConformal(*this);
    return true;
}

}  // namespace m3g::skin
