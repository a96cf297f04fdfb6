#include "UpAxis.h"

#include <cctype>
#include <cmath>

#include "CliArgs.h"

namespace m3gcli {

using namespace m3g;

Axis sceneUp(World& world) {
    Ref<Camera> camera = world.getActiveCamera();
    Transform toWorld;
    if (!camera || !camera->getTransformTo(&world, &toWorld)) return kUpY;
    // The camera's +Y in World space: the second column.
    const float up[3] = {toWorld.at(0, 1), toWorld.at(1, 1), toWorld.at(2, 1)};
    int best = 1;
    for (int k = 0; k < 3; ++k)
        if (std::fabs(up[k]) > std::fabs(up[best])) best = k;
    if (up[best] == 0.0f) return kUpY;
    Axis a{0.0f, 0.0f, 0.0f};
    a[static_cast<std::size_t>(best)] = up[best] > 0.0f ? 1.0f : -1.0f;
    return a;
}

std::optional<Axis> parseAxis(std::string_view text) {
    float sign = 1.0f;
    if (!text.empty() && (text[0] == '+' || text[0] == '-')) {
        sign = text[0] == '-' ? -1.0f : 1.0f;
        text.remove_prefix(1);
    }
    if (text.size() != 1) return std::nullopt;
    const char c = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
    if (c < 'x' || c > 'z') return std::nullopt;
    Axis a{0.0f, 0.0f, 0.0f};
    a[static_cast<std::size_t>(c - 'x')] = sign;
    return a;
}

std::optional<Axis> parseUpOption(const std::string& text) {
    if (text.empty() || text == "auto") return std::nullopt;
    if (const auto a = parseAxis(text)) return a;
    throw CliError("--up takes auto or an axis (+X, -X, +Y, -Y, +Z, -Z; the sign may be left out), not '" + text + "'");
}

std::string axisName(const Axis& axis) {
    for (int k = 0; k < 3; ++k)
        if (axis[static_cast<std::size_t>(k)] != 0.0f)
            return std::string(axis[static_cast<std::size_t>(k)] > 0.0f ? "+" : "-") + static_cast<char>('X' + k);
    return "+Y";
}

Transform upFromY(const Axis& up) {
    Transform t;
    if (up == kUpY) return t;
    if (up[1] < 0.0f) {
        t.postRotate(180.0f, 1.0f, 0.0f, 0.0f);
        return t;
    }
    // The rotation about +Y x up by 90 degrees takes +Y to up.
    const float ax = up[2], ay = 0.0f, az = -up[0];  // (0,1,0) x up
    t.postRotate(90.0f, ax, ay, az);
    return t;
}

}  // namespace m3gcli
