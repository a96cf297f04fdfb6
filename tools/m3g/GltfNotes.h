// Warnings of `m3g export`: what could not be carried into glTF or was
// approximated. Each distinct message is kept once with a count, in the
// order first met. Part of the `m3g export` tool.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace m3gcli::gltf {

class Notes {
public:
    void add(const std::string& message) {
        for (auto& [text, count] : entries_)
            if (text == message) {
                ++count;
                return;
            }
        entries_.emplace_back(message, 1);
    }
    /// "message" or "message (N times)", in first-met order.
    std::vector<std::string> lines() const {
        std::vector<std::string> out;
        for (const auto& [text, count] : entries_)
            out.push_back(count > 1 ? text + " (" + std::to_string(count) + " times)" : text);
        return out;
    }
    bool contains(const std::string& fragment) const {
        for (const auto& e : entries_)
            if (e.first.find(fragment) != std::string::npos) return true;
        return false;
    }

private:
    std::vector<std::pair<std::string, int>> entries_;
};

}  // namespace m3gcli::gltf
