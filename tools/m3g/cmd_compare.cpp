// m3g compare: the share of pixels whose largest channel difference exceeds
// a threshold, and PSNR; or, with --coverage, which pixels each image covers
// (ImageCoverage.h). The exit code is the verdict against the limits (1 over
// them, images of different sizes included).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "CliArgs.h"
#include "Commands.h"
#include "ImageCoverage.h"
#include "ImageIO.h"
#include "InputFile.h"

namespace m3gcli {

namespace {

struct CompareArgs {
    std::string a, b, diff, threshold, maxShare, minPsnr, key, minIou;
    bool coverage = false;
};

double nonNegative(const char* name, const std::string& v, double fallback) {
    if (v.empty()) return fallback;
    char* end = nullptr;
    const double d = std::strtod(v.c_str(), &end);
    if (*end != '\0' || !std::isfinite(d) || d < 0)
        throw CliError(std::string(name) + " takes a non-negative number, not '" + v + "'");
    return d;
}

// The two images of a comparison, or nothing after printing the FAIL verdict
// for images of different sizes. The --diff name is checked first, so a bad
// one is refused before the work.
std::optional<std::pair<RgbaImage, RgbaImage>> readSameSize(const CompareArgs& args) {
    if (!args.diff.empty()) imageFormatFor(args.diff);
    RgbaImage ia = readPngInput(args.a), ib = readPngInput(args.b);
    if (ia.width != ib.width || ia.height != ib.height) {
        std::printf("FAIL: the images differ in size: %dx%d and %dx%d\n", ia.width, ia.height, ib.width, ib.height);
        return std::nullopt;
    }
    return std::pair{std::move(ia), std::move(ib)};
}

int compareCoverageOf(const CompareArgs& args) {
    // Colour limits mean nothing here: refused rather than silently ignored.
    if (!args.threshold.empty() || !args.minPsnr.empty())
        throw CliError("--threshold and --min-psnr compare colours; --coverage compares covered pixels (use --max-share, "
                       "--min-iou)");
    CoverageKey key;
    if (!args.key.empty()) {
        key = parseKeyColor(args.key);
        if (!key) throw CliError("--key takes a colour RRGGBB (hex), not '" + args.key + "'");
    }
    const double maxShare = nonNegative("--max-share", args.maxShare, 0.01);
    const double minIou = nonNegative("--min-iou", args.minIou, 0.0);
    if (minIou > 1.0) throw CliError("--min-iou takes a number in [0, 1], not '" + args.minIou + "'");
    const auto images = readSameSize(args);
    if (!images) return kExitMismatch;
    const auto& [ia, ib] = *images;
    const CoverageComparison c = compareCoverage(ia, ib, key);
    std::printf("%s", coverageReport(c, key, maxShare, minIou).c_str());
    if (!args.diff.empty()) writeImage(args.diff, coverageDiffImage(ia, ib, key), false);
    return withinCoverageLimits(c, maxShare, minIou) ? kExitOk : kExitMismatch;
}

int compare(const CompareArgs& args) {
    if (args.coverage) return compareCoverageOf(args);
    if (!args.key.empty() || !args.minIou.empty()) throw CliError("--key and --min-iou need --coverage");
    int threshold = 8;
    if (!args.threshold.empty()) {
        const auto t = parseInt(args.threshold);
        if (!t || *t < 0 || *t > 255) throw CliError("--threshold takes an integer in [0, 255], not '" + args.threshold + "'");
        threshold = *t;
    }
    const double maxShare = nonNegative("--max-share", args.maxShare, 0.01);
    const double minPsnr = nonNegative("--min-psnr", args.minPsnr, 0.0);
    const auto images = readSameSize(args);
    if (!images) return kExitMismatch;
    const auto& [ia, ib] = *images;
    const Comparison c = compareImages(ia, ib, threshold);
    std::printf("%s", comparisonReport(c, threshold, maxShare, minPsnr).c_str());
    if (!args.diff.empty()) writeImage(args.diff, diffImage(ia, ib, threshold), false);
    return withinLimits(c, maxShare, minPsnr) ? kExitOk : kExitMismatch;
}

}  // namespace

void addCompareCommand(CLI::App& parent, CommandTable& table) {
    CLI::App* app = addCommandApp(parent, "compare",
                                  "compare two PNG images (share of differing pixels, PSNR; or covered pixels with --coverage); "
                                  "exit code 1 over the limits");
    auto args = std::make_shared<CompareArgs>();
    app->add_option("a", args->a, "the first image")->type_name("A.png")->required();
    app->add_option("b", args->b, "the second image, of the same size")->type_name("B.png")->required();
    app->add_option("--threshold", args->threshold, "a pixel differs when a channel is off by more than N (0..255, default 8)")
        ->type_name("N");
    app->add_option("--max-share", args->maxShare, "largest share of differing pixels that passes (default 0.01)")
        ->type_name("S");
    app->add_option("--min-psnr", args->minPsnr, "smallest PSNR in dB that passes (default 0)")->type_name("DB");
    app->add_option("--diff", args->diff,
                    "write a diff image: grey A, differing pixels red (.png or .jpg); with --coverage: white both, red A "
                    "only, green B only")
        ->type_name("OUT.png");
    app->add_flag("--coverage", args->coverage,
                  "compare which pixels the images cover, not their colours (renders of one scene by different "
                  "renderers): --max-share limits the pixels covered in one image only");
    app->add_option("--key", args->key, "with --coverage: the background colour; without it, alpha 0 is background")
        ->type_name("RRGGBB");
    app->add_option("--min-iou", args->minIou,
                    "with --coverage: smallest intersection over union of the covered pixels that passes (0..1, default 0)")
        ->type_name("F");
    table[app] = [args] { return compare(*args); };
}

}  // namespace m3gcli
