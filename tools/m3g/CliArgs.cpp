#include "CliArgs.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <system_error>

#include <m3g/Limits.h>

namespace m3gcli {

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

std::optional<std::string> sizeLimitError(std::string_view option, int width, int height, int maxWidth,
                                          int maxHeight) {
    if (width <= maxWidth && height <= maxHeight) return std::nullopt;
    return std::string(option) + " " + std::to_string(width) + "x" + std::to_string(height) +
           " exceeds the renderer's limit of " + std::to_string(maxWidth) + "x" + std::to_string(maxHeight) +
           " (Graphics3D.getProperties(): maxViewportWidth x maxViewportHeight)";
}

void parseSizeOption(std::string_view option, std::string_view text, int& width, int& height) {
    int w = 0, h = 0;
    if (!parseSize(text, w, h))
        throw CliError(std::string(option) + " takes WxH (two positive integers, e.g. 320x240), not '" +
                       std::string(text) + "'");
    const m3g::Limits& limits = m3g::getLimits();
    if (auto e = sizeLimitError(option, w, h, limits.maxViewportWidth, limits.maxViewportHeight)) throw CliError(*e);
    width = w;
    height = h;
}

std::string lowerExtension(std::string_view path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

int parseIntOption(std::string_view option, std::string_view text, int min, std::string_view what) {
    const auto n = parseInt(text);
    if (!n || *n < min)
        throw CliError(std::string(option) + " takes " + std::string(what) + ", not '" + std::string(text) + "'");
    return *n;
}

}  // namespace m3gcli
