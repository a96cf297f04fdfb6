// The m3g command-line tool. Subcommands grow with the project.
#include <cstdio>
#include <cstring>

#include <m3g/Version.h>

int main(int argc, char** argv) {
    if (argc < 2 || std::strcmp(argv[1], "version") == 0) {
        std::printf("m3g-vk %s\n", m3g::kVersionString);
        return 0;
    }
    std::fprintf(stderr, "m3g: unknown command '%s'\n", argv[1]);
    return 2;
}
