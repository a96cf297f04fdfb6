#include "ViewerScript.h"

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace m3gview {

namespace {

// Argument counts of each command: {least, most} (kMany: no limit).
constexpr std::size_t kMany = 64;
struct Arity {
    std::size_t least, most;
};
const std::map<std::string, Arity>& arity() {
    static const std::map<std::string, Arity> a{
        {"frames", {1, 1}},     {"time", {1, 1}},          {"play", {0, 0}},       {"pause", {0, 0}},
        {"drag", {5, 5}},       {"scroll", {1, 1}},        {"click", {2, 2}},      {"key", {1, 1}},
        {"camera", {1, 1}},     {"screenshot", {0, 1}},    {"screenshot-ui", {1, 1}}, {"expect-pick", {1, 1}},
        {"quit", {0, 0}},       {"select", {1, 1}},        {"edit", {3, kMany}},   {"expect", {3, kMany}},
        {"undo", {0, 0}},       {"redo", {0, 0}},          {"save", {1, 1}},       {"panels", {1, 1}},
        {"layout", {0, 0}},     {"expect-view", {4, 4}},   {"splitter", {2, 2}},
        {"expect-pixel", {4, 4}},
        {"browse", {0, 1}},     {"browse-list", {0, 1}},   {"browse-open", {1, 1}}, {"browse-up", {0, 0}},
        {"browse-close", {0, 0}}, {"recent", {0, 1}},      {"drop", {1, 1}},       {"expect-error", {1, kMany}},
        {"expect-scene", {1, 1}}, {"inspect", {1, 2}},     {"inspect-close", {0, 0}}, {"texel", {2, 3}},
        {"hover", {2, 3}}};
    return a;
}

}  // namespace

Script Script::parse(const std::string& text, const std::string& name) {
    Script s;
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        std::istringstream words(line);
        ScriptCommand c;
        c.line = number;
        if (!(words >> c.name)) continue;
        for (std::string w; words >> w;) c.args.push_back(w);
        const auto it = arity().find(c.name);
        if (it == arity().end())
            throw std::runtime_error(name + ":" + std::to_string(number) + ": unknown command '" + c.name + "'");
        const Arity n = it->second;
        if (c.args.size() < n.least || c.args.size() > n.most) {
            const std::string count = n.least == n.most ? std::to_string(n.least)
                                      : n.most == kMany ? "at least " + std::to_string(n.least)
                                                        : std::to_string(n.least) + " to " + std::to_string(n.most);
            throw std::runtime_error(name + ":" + std::to_string(number) + ": '" + c.name + "' takes " + count +
                                     " argument(s), got " + std::to_string(c.args.size()));
        }
        s.commands_.push_back(std::move(c));
    }
    return s;
}

Script Script::load(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read script " + path);
    std::stringstream text;
    text << in.rdbuf();
    return parse(text.str(), path);
}

int Script::run(const std::function<int(const ScriptCommand&)>& apply) const {
    for (const auto& c : commands_) {
        if (c.name == "quit") return 0;
        if (const int rc = apply(c); rc != 0) return rc;
    }
    return 0;
}

}  // namespace m3gview
