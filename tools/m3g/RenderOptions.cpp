#include "RenderOptions.h"

#include "UpAxis.h"

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

void addRenderOptions(CLI::App& app, RenderFlags& f) {
    app.add_option("input", f.input, "an .m3g (or PNG/JPEG) file; a folder or a J2ME .jar renders every M3G file in it")
        ->type_name("FILE|DIR|GAME.jar")
        ->required();
    app.add_option("-o,--output", f.output,
                   "the image: .png, or .jpg/.jpeg; - for a PNG on stdout; a sequence's pattern ({frame} is "
                   "replaced, default out_{frame}.png); the output folder in batch mode")
        ->type_name("OUT");
    app.add_option("--size", f.size, "image size in pixels (default 320x240; at most the renderer's maxViewportWidth x "
                                     "maxViewportHeight)")
        ->type_name("WxH");
    app.add_option("--time", f.time, "world time of the (first) frame in ms (default 0)")->type_name("MS");
    app.add_flag("--align", f.align, "apply the World's node alignment (World.align) before each frame");
    app.add_flag("--lenient", f.lenient, "accept the exporter faults seen in real files (LoaderOptions.lenient)");
    app.add_option("--frames", f.frames, "an animation sequence of N frames")->type_name("N");
    app.add_option("--fps", f.fps, "frames per second of the sequence (default 30): frame k at time + k*1000/F")
        ->type_name("F");
    app.add_option("--turntable", f.turntable, "N frames orbiting the camera around the scene's up axis")
        ->type_name("N");
    app.add_option("--up", f.up, "the scene's up axis for --turntable: auto (the active camera's up, default) or "
                                 "+X, -X, +Y, -Y, +Z, -Z")
        ->type_name("AXIS");
    app.add_option("--camera-index", f.cameraIndex, "render through the file's I-th Camera (0-based, file order)")
        ->type_name("I");
    app.add_option("--background", f.background,
                   "clear to this colour instead of the World's Background (hex RRGGBBAA, or transparent); writes RGBA")
        ->type_name("RRGGBBAA|transparent");
    app.add_option("--reference", f.reference,
                   "compare the image with REF.png as `m3g compare` does: exit code 0 within the limits, 1 not")
        ->type_name("REF.png");
    app.add_option("--threshold", f.threshold, "with --reference: a pixel differs when a channel is off by more "
                                               "than T (0..255, default 8)")
        ->type_name("T");
    app.add_option("--max-share", f.maxShare, "with --reference: largest share of differing pixels (default 0.01)")
        ->type_name("S");
    app.add_option("--min-psnr", f.minPsnr, "with --reference: smallest PSNR in dB (default 0)")->type_name("DB");
}

RenderOptions finishRenderOptions(const RenderFlags& f) {
    RenderOptions r;
    r.input = f.input;
    r.output = f.output;
    auto nonNegative = [](const char* name, const std::string& v) {
        const auto x = parseFloat(v);
        if (!x || *x < 0) throw CliError(std::string(name) + " takes a non-negative number, not '" + v + "'");
        return static_cast<double>(*x);
    };
    if (!f.size.empty()) parseSizeOption("--size", f.size, r.width, r.height);
    if (!f.time.empty()) {
        const auto t = parseInt(f.time);
        if (!t) throw CliError("--time takes an integer number of milliseconds, not '" + f.time + "'");
        r.time = *t;
    }
    r.align = f.align;
    r.lenient = f.lenient;
    if (!f.frames.empty()) r.frames = parseIntOption("--frames", f.frames, 1, "a positive integer");
    if (!f.fps.empty()) {
        const auto x = parseFloat(f.fps);
        if (!x || *x <= 0) throw CliError("--fps takes a positive number, not '" + f.fps + "'");
        r.fps = *x;
    }
    if (!f.turntable.empty()) r.turntable = parseIntOption("--turntable", f.turntable, 1, "a positive integer");
    r.up = parseUpOption(f.up);
    if (!f.cameraIndex.empty())
        r.cameraIndex = parseIntOption("--camera-index", f.cameraIndex, 0, "a Camera's index (0, 1, ...)");
    if (!f.background.empty()) {
        r.background = parseBackgroundColor(f.background);
        if (!r.background)
            throw CliError("--background takes RRGGBBAA (hex) or 'transparent', not '" + f.background + "'");
    }
    r.reference = f.reference;
    if (!f.threshold.empty()) {
        const auto t = parseInt(f.threshold);
        if (!t || *t < 0 || *t > 255)
            throw CliError("--threshold takes an integer in [0, 255], not '" + f.threshold + "'");
        r.threshold = *t;
    }
    if (!f.maxShare.empty()) r.maxShare = nonNegative("--max-share", f.maxShare);
    if (!f.minPsnr.empty()) r.minPsnr = nonNegative("--min-psnr", f.minPsnr);
    if (r.frames > 0 && r.turntable > 0) throw CliError("--frames and --turntable exclude each other");
    if (!r.reference.empty() && r.sequence())
        throw CliError("--reference compares one image; it does not combine with --frames or --turntable");
    if (r.reference.empty() && (!f.threshold.empty() || !f.maxShare.empty() || !f.minPsnr.empty()))
        throw CliError("--threshold, --max-share and --min-psnr need --reference REF.png");
    if (r.output == "-" && r.sequence()) throw CliError("a sequence cannot be written to stdout (-o -)");
    return r;
}

RenderOptions parseRenderOptions(std::span<const std::string_view> args) {
    CLI::App app("", "render");
    RenderFlags flags;
    addRenderOptions(app, flags);
    parseArgs(app, std::vector<std::string>(args.begin(), args.end()));
    return finishRenderOptions(flags);
}

}  // namespace m3gcli
