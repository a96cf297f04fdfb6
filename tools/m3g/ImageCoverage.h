// Coverage comparison for `m3g compare --coverage`: which pixels two images
// cover, not their colours. Made for images from different renderers of the
// same geometry (an exported glTF in another viewer against `m3g render`),
// where shading legitimately differs but silhouettes must not. Part of
// m3g_cli_support.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "ImageIO.h"

namespace m3gcli {

/// What marks a pixel as background: a key colour (RGB) or, without one,
/// alpha 0.
using CoverageKey = std::optional<std::array<std::uint8_t, 3>>;

struct CoverageComparison {
    long long coveredA = 0, coveredB = 0;  ///< covered pixels of each image
    long long both = 0;                    ///< covered in both
    long long differing = 0;               ///< covered in exactly one
    long long total = 0;
    double share = 0.0;  ///< differing / total
    double iou = 1.0;    ///< both / covered in either (1 when neither covers a pixel)
};

/// True when `pixel` (RGBA8) is covered: its RGB is not the key or, without
/// a key, its alpha is not 0.
bool isCovered(const std::uint8_t* pixel, const CoverageKey& key);

/// Compares the coverage of two images of the same size (throws
/// std::invalid_argument otherwise).
CoverageComparison compareCoverage(const RgbaImage& a, const RgbaImage& b, const CoverageKey& key);

/// The verdict of `m3g compare --coverage`: share <= maxShare and iou >= minIou.
bool withinCoverageLimits(const CoverageComparison& c, double maxShare, double minIou);

/// The report of `m3g compare --coverage` (several lines, ends with a newline):
/// covered pixels of each, pixels covered by one only, intersection over
/// union, then PASS or FAIL with the limits.
std::string coverageReport(const CoverageComparison& c, const CoverageKey& key, double maxShare, double minIou);

/// A coverage diff image: white where both cover, red where only `a` does,
/// green where only `b` does, dark grey where neither.
RgbaImage coverageDiffImage(const RgbaImage& a, const RgbaImage& b, const CoverageKey& key);

/// "RRGGBB" (hex, any case) as a key colour; nullopt for anything else.
CoverageKey parseKeyColor(const std::string& text);

}  // namespace m3gcli
