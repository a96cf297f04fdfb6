#include "ViewerSettings.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace m3gview {

std::string Settings::path() {
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) return std::string(xdg) + "/m3g-vk/viewer.ini";
    if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.config/m3g-vk/viewer.ini";
    return "";
}

Settings Settings::load() {
    Settings s;
    const std::string file = path();
    if (file.empty()) return s;
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        const auto eq = line.find('=');
        if (eq == std::string::npos) continue;
        const std::string key = line.substr(0, eq), value = line.substr(eq + 1);
        try {
            if (key == "width") s.width = std::clamp(std::stoi(value), 64, 8192);
            else if (key == "height") s.height = std::clamp(std::stoi(value), 64, 8192);
            else if (key == "lastFile") s.lastFile = value;
            else if (key == "recent" && !value.empty() && s.recent.size() < kMaxRecent) s.recent.push_back(value);
            else if (key == "leftColumn") s.layout.left = std::stof(value);
            else if (key == "rightColumn") s.layout.right = std::stof(value);
            else if (key == "leftSplit") s.layout.leftSplit = std::stof(value);
            else if (key == "rightSplit1") s.layout.rightSplit1 = std::stof(value);
            else if (key == "rightSplit2") s.layout.rightSplit2 = std::stof(value);
        } catch (const std::exception&) {
            // A hand-edited value that is not a number: keep the default.
        }
    }
    return s;
}

void Settings::remember(const std::string& file) {
    if (file.empty()) return;
    // "game.jar!entry": the archive's path is made absolute, the entry kept.
    const auto bang = file.find(".jar!");
    const std::string disk = bang == std::string::npos ? file : file.substr(0, bang + 4);
    std::error_code ec;
    std::string absolute = std::filesystem::absolute(disk, ec).lexically_normal().string();
    if (ec) absolute = disk;
    if (bang != std::string::npos) absolute += file.substr(bang + 4);
    recent.erase(std::remove(recent.begin(), recent.end(), absolute), recent.end());
    recent.insert(recent.begin(), absolute);
    if (recent.size() > kMaxRecent) recent.resize(kMaxRecent);
}

void Settings::save() const {
    const std::string file = path();
    if (file.empty()) return;
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(file).parent_path(), ec);
    std::ofstream out(file);
    out << "width=" << width << "\nheight=" << height << "\nlastFile=" << lastFile << "\nleftColumn=" << layout.left
        << "\nrightColumn=" << layout.right << "\nleftSplit=" << layout.leftSplit << "\nrightSplit1=" << layout.rightSplit1
        << "\nrightSplit2=" << layout.rightSplit2 << "\n";
    for (const std::string& r : recent) out << "recent=" << r << "\n";
    if (!out) std::fprintf(stderr, "m3g: view: could not save settings to %s\n", file.c_str());
}

}  // namespace m3gview
