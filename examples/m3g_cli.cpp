// The m3g command-line tool. Subcommands grow with the project:
//   m3g info        library version and Graphics3D::getProperties()
//   m3g version     the version alone
#include <cstdio>
#include <cstring>
#include <string>
#include <type_traits>
#include <variant>

#include <m3g/m3g.h>

namespace {

int usage(std::FILE* out) {
    std::fprintf(out,
                 "usage: m3g <command>\n"
                 "  info      print the library version and Graphics3D::getProperties()\n"
                 "  version   print the library version\n");
    return out == stderr ? 2 : 0;
}

int info() {
    std::printf("m3g-vk %s: M3G 1.1 (JSR-184) object model\n", m3g::kVersionString);
    std::printf("Graphics3D.getProperties():\n");
    for (const auto& [key, value] : m3g::Graphics3D::getProperties()) {
        std::visit(
            [&](const auto& v) {
                using T = std::decay_t<decltype(v)>;
                if constexpr (std::is_same_v<T, bool>)
                    std::printf("  %-30s %s\n", key.c_str(), v ? "true" : "false");
                else if constexpr (std::is_same_v<T, int>)
                    std::printf("  %-30s %d\n", key.c_str(), v);
                else
                    std::printf("  %-30s %s\n", key.c_str(), v.c_str());
            },
            value);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) return usage(stderr);
    const std::string cmd = argv[1];
    if (cmd == "info") return info();
    if (cmd == "version") {
        std::printf("%s\n", m3g::kVersionString);
        return 0;
    }
    if (cmd == "help" || cmd == "--help" || cmd == "-h") return usage(stdout);
    std::fprintf(stderr, "m3g: unknown command '%s'\n", cmd.c_str());
    return usage(stderr);
}
