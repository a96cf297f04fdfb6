#include "ViewerScript.h"

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace m3gview {

namespace {

// Argument count of each command (-1: one or more... none here).
const std::map<std::string, std::size_t>& arity() {
    static const std::map<std::string, std::size_t> a{
        {"frames", 1}, {"time", 1},  {"play", 0},   {"pause", 0},  {"drag", 5},       {"scroll", 1},
        {"click", 2},  {"key", 1},   {"camera", 1}, {"screenshot", 1}, {"screenshot-ui", 1}, {"expect-pick", 1}, {"quit", 0}};
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
        if (it->second != c.args.size())
            throw std::runtime_error(name + ":" + std::to_string(number) + ": '" + c.name + "' takes " +
                                     std::to_string(it->second) + " argument(s), got " + std::to_string(c.args.size()));
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
