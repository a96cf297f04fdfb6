// m3g compare: the share of pixels whose largest channel difference exceeds
// a threshold, and PSNR; the exit code is the verdict against the limits
// (1 over them, images of different sizes included).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "CliArgs.h"
#include "Commands.h"
#include "ImageIO.h"
#include "InputFile.h"

namespace m3gcli {

namespace {

struct CompareArgs {
    std::string a, b, diff, threshold, maxShare, minPsnr;
};

double nonNegative(const char* name, const std::string& v, double fallback) {
    if (v.empty()) return fallback;
    char* end = nullptr;
    const double d = std::strtod(v.c_str(), &end);
    if (*end != '\0' || !std::isfinite(d) || d < 0)
        throw CliError(std::string(name) + " takes a non-negative number, not '" + v + "'");
    return d;
}

int compare(const CompareArgs& args) {
    int threshold = 8;
    if (!args.threshold.empty()) {
        const auto t = parseInt(args.threshold);
        if (!t || *t < 0 || *t > 255) throw CliError("--threshold takes an integer in [0, 255], not '" + args.threshold + "'");
        threshold = *t;
    }
    const double maxShare = nonNegative("--max-share", args.maxShare, 0.01);
    const double minPsnr = nonNegative("--min-psnr", args.minPsnr, 0.0);
    if (!args.diff.empty()) imageFormatFor(args.diff);  // refused before the work
    const RgbaImage ia = readPngInput(args.a), ib = readPngInput(args.b);
    if (ia.width != ib.width || ia.height != ib.height) {
        std::printf("FAIL: the images differ in size: %dx%d and %dx%d\n", ia.width, ia.height, ib.width, ib.height);
        return kExitMismatch;
    }
    const Comparison c = compareImages(ia, ib, threshold);
    std::printf("%s", comparisonReport(c, threshold, maxShare, minPsnr).c_str());
    if (!args.diff.empty()) writeImage(args.diff, diffImage(ia, ib, threshold), false);
    return withinLimits(c, maxShare, minPsnr) ? kExitOk : kExitMismatch;
}

}  // namespace

void addCompareCommand(CLI::App& parent, CommandTable& table) {
    CLI::App* app = addCommandApp(parent, "compare",
                                  "compare two PNG images (share of differing pixels, PSNR); exit code 1 over the "
                                  "limits");
    auto args = std::make_shared<CompareArgs>();
    app->add_option("a", args->a, "the first image")->type_name("A.png")->required();
    app->add_option("b", args->b, "the second image, of the same size")->type_name("B.png")->required();
    app->add_option("--threshold", args->threshold, "a pixel differs when a channel is off by more than N (0..255, default 8)")
        ->type_name("N");
    app->add_option("--max-share", args->maxShare, "largest share of differing pixels that passes (default 0.01)")
        ->type_name("S");
    app->add_option("--min-psnr", args->minPsnr, "smallest PSNR in dB that passes (default 0)")->type_name("DB");
    app->add_option("--diff", args->diff, "write a diff image: grey A, differing pixels red (.png or .jpg)")
        ->type_name("OUT.png");
    table[app] = [args] { return compare(*args); };
}

}  // namespace m3gcli
