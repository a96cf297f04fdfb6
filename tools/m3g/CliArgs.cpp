#include "CliArgs.h"

#include <charconv>
#include <cmath>
#include <system_error>

namespace m3gcli {

namespace {

struct CommandSpec {
    std::string_view name;
    int minFiles;
    int maxFiles;
    bool json, lenient, time, compress;  // options the command takes
};

constexpr CommandSpec kCommands[] = {
    {"info", 0, 1, true, true, true, false},
    {"convert", 2, 2, false, true, false, true},
    {"pick", 3, 3, true, true, true, false},
    {"version", 0, 0, false, false, false, false},
    {"help", 0, 0, false, false, false, false},
};

const CommandSpec* findCommand(std::string_view name) {
    for (const auto& c : kCommands)
        if (c.name == name) return &c;
    return nullptr;
}

std::string quoted(std::string_view s) { return "'" + std::string(s) + "'"; }

void requireOption(bool allowed, std::string_view option, const CommandSpec& cmd) {
    if (!allowed)
        throw CliError("option " + std::string(option) + " does not apply to '" + std::string(cmd.name) + "'");
}

}  // namespace

std::optional<int> parseInt(std::string_view text) {
    if (text.empty()) return std::nullopt;
    std::string_view digits = text;
    const bool plus = digits.front() == '+';  // from_chars takes '-' but not '+'
    if (plus) digits.remove_prefix(1);
    if (digits.empty() || (plus && digits.front() == '-')) return std::nullopt;
    int value = 0;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
    return value;
}

bool parseSize(std::string_view text, int& width, int& height) {
    const auto x = text.find('x');
    if (x == std::string_view::npos) return false;
    const auto w = parseInt(text.substr(0, x)), h = parseInt(text.substr(x + 1));
    if (!w || !h || *w <= 0 || *h <= 0) return false;
    width = *w;
    height = *h;
    return true;
}

std::optional<float> parseFloat(std::string_view text) {
    if (text.empty()) return std::nullopt;
    std::string_view digits = text;
    if (digits.front() == '+') {  // from_chars takes '-' but not '+'
        digits.remove_prefix(1);
        if (digits.empty() || digits.front() == '-' || digits.front() == '+') return std::nullopt;
    }
    float value = 0.0f;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec != std::errc() || end != digits.data() + digits.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

std::string usageText() {
    return "usage: m3g <command> [options]\n"
           "  info [FILE] [--json] [--lenient] [--time T]\n"
           "            without FILE: the library version and Graphics3D::getProperties();\n"
           "            with FILE: header, object counts, scene tree, warnings;\n"
           "            --json dumps every object's properties, --time T animates to T ms first\n"
           "  convert IN OUT [--compress] [--lenient]\n"
           "            load IN and save it as OUT (zlib sections with --compress)\n"
           "  render FILE -o OUT.png [--size WxH] [--time MS] [--align] [--lenient]\n"
           "         [--frames N [--fps F] | --turntable N] [--camera-index I]\n"
           "         [--background RRGGBBAA|transparent] [--reference REF.png [--threshold T]]\n"
           "            render the World to a PNG (auto-framed when it has no active camera);\n"
           "            -o - writes the PNG to stdout; sequences write OUT_{frame}.png\n"
           "            ({frame} in -o is replaced, zero padded; default out_{frame}.png);\n"
           "            --turntable orbits the camera around the scene's vertical axis;\n"
           "            --reference: exit status 0 when the image matches as in compare\n"
           "  render DIR|GAME.jar -o OUTDIR [options]\n"
           "            every M3G file (by its identifier bytes, any name) in a folder or a\n"
           "            J2ME .jar; progress bar, summary of failures and skipped files\n"
           "  compare A.png B.png [--threshold 8] [--max-share 0.01] [--min-psnr DB] [--diff OUT.png]\n"
           "            share of pixels whose largest channel difference exceeds the threshold,\n"
           "            and PSNR; exit status 0 when within the limits\n"
           "  sample -o OUT.m3g\n"
           "            write the project's sample scene (built in code) with the writer\n"
           "  export FILE -o OUT.glb|OUT.gltf [--time MS] [--lenient] [--separate-bin] [--quiet]\n"
           "            glTF 2.0 export of the scene as posed at MS (default 0) with its\n"
           "            animations; warnings list what glTF cannot express (docs/export.md)\n"
           "  pick FILE X Y [--time T] [--json] [--lenient]\n"
           "            animate the World to T ms (default 0) and pick through its active\n"
           "            camera at viewport point (X, Y), (0, 0) top left, (1, 1) bottom right\n"
           "  bench render FILE... [--size WxH] [--frames N]\n"
           "            rendering speed: first frame, ms per frame, fps, CPU per draw, pipelines\n"
           "  view [FILE] [--size WxH] [--time MS] [--camera-index I] [--no-ui] [--lenient]\n"
           "       [--frames N --screenshot OUT.png] [--script FILE] [--no-vsync] [--no-headlight]\n"
           "            the desktop viewer (.m3g, .png, .jpg or a game .jar; needs a display);\n"
           "            --frames/--screenshot/--script run it unattended (docs/viewer.md)\n"
           "  bench soak FILE [--frames N] [--reload K] [--size WxH] [--report R] [--warmup C]\n"
           "            memory over a long run, reloading FILE every K frames: resident and\n"
           "            GPU memory per cycle and a verdict (flat after the warm-up or not)\n"
           "  version   print the library version\n"
           "  help      print this text\n";
}

CliArgs parseCliArgs(std::span<const std::string_view> args) {
    CliArgs out;
    if (args.empty()) throw CliError("no command given");
    // --help / -h anywhere (before "--") wins over everything else.
    for (std::string_view a : args) {
        if (a == "--") break;
        if (a == "--help" || a == "-h") {
            out.command = "help";
            return out;
        }
    }
    const std::string_view cmdName = args[0];
    if (!cmdName.empty() && cmdName.front() == '-' && cmdName != "-")
        throw CliError("expected a command before option " + quoted(cmdName));
    const CommandSpec* cmd = findCommand(cmdName);
    if (!cmd) throw CliError("unknown command " + quoted(cmdName));
    out.command = std::string(cmdName);

    bool optionsEnded = false;
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string_view a = args[i];
        // A negative number ("-0.5") is an operand, not an option.
        const bool isOption = !optionsEnded && a.size() > 1 && a.front() == '-' && !parseFloat(a);
        if (!isOption) {
            out.files.emplace_back(a);
            continue;
        }
        if (a == "--") {
            optionsEnded = true;
            continue;
        }
        std::string_view name = a;
        std::optional<std::string_view> inlineValue;
        if (auto eq = a.find('='); eq != std::string_view::npos && a.starts_with("--")) {
            name = a.substr(0, eq);
            inlineValue = a.substr(eq + 1);
        }
        auto flag = [&](bool allowed, bool& target) {
            requireOption(allowed, name, *cmd);
            if (inlineValue) throw CliError("option " + std::string(name) + " takes no value");
            target = true;
        };
        if (name == "--json") {
            flag(cmd->json, out.json);
        } else if (name == "--lenient") {
            flag(cmd->lenient, out.lenient);
        } else if (name == "--compress") {
            flag(cmd->compress, out.compress);
        } else if (name == "--time") {
            requireOption(cmd->time, name, *cmd);
            if (out.time) throw CliError("option --time given more than once");
            std::string_view value;
            if (inlineValue) {
                value = *inlineValue;
            } else {
                if (i + 1 >= args.size()) throw CliError("option --time needs a value (world time in ms)");
                value = args[++i];
            }
            const auto t = parseInt(value);
            if (!t) throw CliError("option --time expects an integer (world time in ms), got " + quoted(value));
            out.time = *t;
        } else {
            throw CliError("unknown option " + quoted(a));
        }
    }

    const int n = static_cast<int>(out.files.size());
    if (n < cmd->minFiles) {
        if (out.command == "convert")
            throw CliError(n == 0 ? "convert needs an input and an output file" : "convert needs an output file");
        if (out.command == "pick") throw CliError("pick needs a file and the viewport coordinates X Y");
        throw CliError("'" + out.command + "' needs a file");
    }
    if (n > cmd->maxFiles)
        throw CliError("unexpected argument " + quoted(out.files[static_cast<std::size_t>(cmd->maxFiles)]) +
                       " for '" + out.command + "'");
    return out;
}

CliArgs parseCliArgs(int argc, const char* const* argv) {
    std::vector<std::string_view> args;
    for (int i = 1; i < argc; ++i) args.emplace_back(argv[i]);
    return parseCliArgs(std::span<const std::string_view>(args));
}

}  // namespace m3gcli
