// m3g compare: the share of pixels whose largest channel difference exceeds
// a threshold, and PSNR; the exit status is the verdict against the limits.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "CliArgs.h"
#include "Commands.h"
#include "ImageIO.h"

namespace m3gcli {

int cmdCompare(std::span<const std::string_view> args) {
    std::string a, b, diff;
    int threshold = 8;
    double maxShare = 0.01, minPsnr = 0.0;
    try {
        for (std::size_t i = 0; i < args.size(); ++i) {
            const std::string_view arg = args[i];
            auto value = [&](const char* name) -> std::string {
                if (i + 1 >= args.size()) throw CliError(std::string("compare: ") + name + " needs a value");
                return std::string(args[++i]);
            };
            auto number = [&](const char* name) {
                const std::string v = value(name);
                char* end = nullptr;
                const double d = std::strtod(v.c_str(), &end);
                if (v.empty() || *end != '\0' || !std::isfinite(d) || d < 0)
                    throw CliError(std::string("compare: ") + name + " takes a non-negative number, not " + v);
                return d;
            };
            if (arg == "--threshold") {
                auto t = parseInt(value("--threshold"));
                if (!t || *t < 0 || *t > 255) throw CliError("compare: --threshold takes an integer in [0, 255]");
                threshold = *t;
            } else if (arg == "--max-share") maxShare = number("--max-share");
            else if (arg == "--min-psnr") minPsnr = number("--min-psnr");
            else if (arg == "--diff") diff = value("--diff");
            else if (!arg.empty() && arg[0] == '-') throw CliError("compare: unknown option " + std::string(arg));
            else if (a.empty()) a = arg;
            else if (b.empty()) b = arg;
            else throw CliError("compare: takes exactly two images");
        }
        if (b.empty()) throw CliError("compare: takes exactly two images (A.png B.png)");
    } catch (const CliError& e) {
        std::fprintf(stderr, "m3g: %s\n", e.what());
        return 2;
    }
    try {
        const RgbaImage ia = readPng(a), ib = readPng(b);
        const Comparison c = compareImages(ia, ib, threshold);
        std::printf("%s", comparisonReport(c, threshold, maxShare, minPsnr).c_str());
        if (!diff.empty()) writePng(diff, diffImage(ia, ib, threshold), false);
        const bool pass = withinLimits(c, maxShare, minPsnr);
        return pass ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "m3g: compare: %s\n", e.what());
        return 1;
    }
}

}  // namespace m3gcli
