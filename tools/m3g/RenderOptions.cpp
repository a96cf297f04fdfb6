#include "RenderOptions.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "CliArgs.h"

namespace m3gcli {

namespace {

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

}  // namespace

std::optional<std::uint32_t> parseBackgroundColor(std::string_view text) {
    if (text == "transparent") return 0x00000000u;
    if (text.size() != 8) return std::nullopt;
    std::uint32_t rgba = 0;
    for (char c : text) {
        const int d = hexDigit(c);
        if (d < 0) return std::nullopt;
        rgba = (rgba << 4) | static_cast<std::uint32_t>(d);
    }
    return (rgba >> 8) | (rgba << 24);  // RRGGBBAA -> AARRGGBB
}

std::string frameFileName(const std::string& pattern, int frame, int count) {
    int width = 4;
    for (int n = std::max(count - 1, 0); n >= 10000; n /= 10) ++width;
    std::string number = std::to_string(frame);
    if (static_cast<int>(number.size()) < width) number.insert(0, static_cast<std::size_t>(width) - number.size(), '0');
    const std::string token = "{frame}";
    std::string out = pattern;
    if (const auto at = out.find(token); at != std::string::npos) {
        for (auto pos = at; pos != std::string::npos; pos = out.find(token, pos + number.size()))
            out.replace(pos, token.size(), number);
        return out;
    }
    // No token: before the extension of the file name (not of a folder).
    const std::filesystem::path p(pattern);
    const std::string ext = p.extension().string();
    return out.substr(0, out.size() - ext.size()) + "_" + number + ext;
}

RenderOptions parseRenderOptions(std::span<const std::string_view> args) {
    RenderOptions r;
    bool haveThreshold = false, haveShare = false, havePsnr = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view a = args[i];
        auto value = [&](const char* name) -> std::string_view {
            if (i + 1 >= args.size()) throw CliError(std::string("render: ") + name + " needs a value");
            return args[++i];
        };
        auto positiveInt = [&](const char* name) {
            const std::string_view v = value(name);
            const auto n = parseInt(v);
            if (!n || *n <= 0)
                throw CliError(std::string("render: ") + name + " takes a positive integer, not '" + std::string(v) + "'");
            return *n;
        };
        auto nonNegative = [&](const char* name) {
            const std::string_view v = value(name);
            const auto f = parseFloat(v);
            if (!f || *f < 0)
                throw CliError(std::string("render: ") + name + " takes a non-negative number, not '" + std::string(v) + "'");
            return static_cast<double>(*f);
        };
        if (a == "-o" || a == "--output") {
            r.output = value("-o");
        } else if (a == "--size") {
            if (!parseSize(value("--size"), r.width, r.height)) throw CliError("render: --size takes WxH, e.g. 320x240");
        } else if (a == "--time") {
            auto t = parseInt(value("--time"));
            if (!t) throw CliError("render: --time takes an integer number of milliseconds");
            r.time = *t;
        } else if (a == "--align") {
            r.align = true;
        } else if (a == "--lenient") {
            r.lenient = true;
        } else if (a == "--frames") {
            r.frames = positiveInt("--frames");
        } else if (a == "--fps") {
            const std::string_view v = value("--fps");
            const auto f = parseFloat(v);
            if (!f || *f <= 0) throw CliError("render: --fps takes a positive number, not '" + std::string(v) + "'");
            r.fps = *f;
        } else if (a == "--turntable") {
            r.turntable = positiveInt("--turntable");
        } else if (a == "--camera-index") {
            const std::string_view v = value("--camera-index");
            const auto n = parseInt(v);
            if (!n || *n < 0)
                throw CliError("render: --camera-index takes a Camera's index (0, 1, ...), not '" + std::string(v) + "'");
            r.cameraIndex = *n;
        } else if (a == "--background") {
            const std::string_view v = value("--background");
            r.background = parseBackgroundColor(v);
            if (!r.background)
                throw CliError("render: --background takes RRGGBBAA (hex) or 'transparent', not '" + std::string(v) + "'");
        } else if (a == "--reference") {
            r.reference = value("--reference");
        } else if (a == "--threshold") {
            const std::string_view v = value("--threshold");
            const auto t = parseInt(v);
            if (!t || *t < 0 || *t > 255)
                throw CliError("render: --threshold takes an integer in [0, 255], not '" + std::string(v) + "'");
            r.threshold = *t;
            haveThreshold = true;
        } else if (a == "--max-share") {
            r.maxShare = nonNegative("--max-share");
            haveShare = true;
        } else if (a == "--min-psnr") {
            r.minPsnr = nonNegative("--min-psnr");
            havePsnr = true;
        } else if (!a.empty() && a[0] == '-' && a != "-") {
            throw CliError("render: unknown option " + std::string(a));
        } else if (r.input.empty()) {
            r.input = a;
        } else {
            throw CliError("render: unexpected operand " + std::string(a));
        }
    }
    if (r.input.empty()) throw CliError("render: no input file");
    if (r.frames > 0 && r.turntable > 0) throw CliError("render: --frames and --turntable exclude each other");
    if (!r.reference.empty() && r.sequence())
        throw CliError("render: --reference compares one image; it does not combine with --frames or --turntable");
    if (r.reference.empty() && (haveThreshold || haveShare || havePsnr))
        throw CliError("render: --threshold, --max-share and --min-psnr need --reference REF.png");
    if (r.output == "-" && r.sequence()) throw CliError("render: a sequence cannot be written to stdout (-o -)");
    return r;
}

}  // namespace m3gcli
