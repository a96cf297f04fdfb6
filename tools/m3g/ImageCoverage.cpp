#include "ImageCoverage.h"

#include <cstdio>
#include <stdexcept>

namespace m3gcli {

bool isCovered(const std::uint8_t* pixel, const CoverageKey& key) {
    if (!key) return pixel[3] != 0;
    return pixel[0] != (*key)[0] || pixel[1] != (*key)[1] || pixel[2] != (*key)[2];
}

CoverageComparison compareCoverage(const RgbaImage& a, const RgbaImage& b, const CoverageKey& key) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                    " and " + std::to_string(b.width) + "x" + std::to_string(b.height));
    CoverageComparison c;
    c.total = static_cast<long long>(a.width) * a.height;
    for (long long i = 0; i < c.total; ++i) {
        const bool inA = isCovered(&a.pixels[static_cast<std::size_t>(i) * 4], key);
        const bool inB = isCovered(&b.pixels[static_cast<std::size_t>(i) * 4], key);
        c.coveredA += inA;
        c.coveredB += inB;
        c.both += inA && inB;
        c.differing += inA != inB;
    }
    c.share = c.total ? static_cast<double>(c.differing) / static_cast<double>(c.total) : 0.0;
    const long long either = c.both + c.differing;
    c.iou = either ? static_cast<double>(c.both) / static_cast<double>(either) : 1.0;
    return c;
}

bool withinCoverageLimits(const CoverageComparison& c, double maxShare, double minIou) {
    return c.share <= maxShare && c.iou >= minIou;
}

std::string coverageReport(const CoverageComparison& c, const CoverageKey& key, double maxShare, double minIou) {
    char background[32];
    if (key)
        std::snprintf(background, sizeof background, "colour %02X%02X%02X", (*key)[0], (*key)[1], (*key)[2]);
    else
        std::snprintf(background, sizeof background, "alpha 0");
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "covered pixels (background: %s): %lld in A, %lld in B, %lld in both\n"
                  "covered in one image only: %lld of %lld (%.3f%%)\n"
                  "intersection over union: %.4f\n"
                  "%s (limits: share <= %.3f%%, IoU >= %.4f)\n",
                  background, c.coveredA, c.coveredB, c.both, c.differing, c.total, 100.0 * c.share, c.iou,
                  withinCoverageLimits(c, maxShare, minIou) ? "PASS" : "FAIL", 100.0 * maxShare, minIou);
    return buf;
}

RgbaImage coverageDiffImage(const RgbaImage& a, const RgbaImage& b, const CoverageKey& key) {
    RgbaImage out = a;
    const std::size_t n = static_cast<std::size_t>(a.width) * a.height;
    for (std::size_t i = 0; i < n; ++i) {
        const bool inA = isCovered(&a.pixels[i * 4], key), inB = isCovered(&b.pixels[i * 4], key);
        static constexpr std::uint8_t kBoth[3] = {255, 255, 255}, kOnlyA[3] = {255, 0, 0}, kOnlyB[3] = {0, 255, 0},
                                      kNeither[3] = {40, 40, 40};
        const std::uint8_t* rgb = inA ? (inB ? kBoth : kOnlyA) : (inB ? kOnlyB : kNeither);
        std::uint8_t* p = &out.pixels[i * 4];
        p[0] = rgb[0];
        p[1] = rgb[1];
        p[2] = rgb[2];
        p[3] = 255;
    }
    return out;
}

CoverageKey parseKeyColor(const std::string& text) {
    if (text.size() != 6) return std::nullopt;
    std::array<std::uint8_t, 3> rgb{};
    for (int k = 0; k < 3; ++k) {
        int value = 0;
        for (int d = 0; d < 2; ++d) {
            const char ch = text[static_cast<std::size_t>(k * 2 + d)];
            int v;
            if (ch >= '0' && ch <= '9') v = ch - '0';
            else if (ch >= 'a' && ch <= 'f') v = ch - 'a' + 10;
            else if (ch >= 'A' && ch <= 'F') v = ch - 'A' + 10;
            else return std::nullopt;
            value = value * 16 + v;
        }
        rgb[static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(value);
    }
    return rgb;
}

}  // namespace m3gcli
