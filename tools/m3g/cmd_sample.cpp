// m3g sample: writes the project's sample scene as an .m3g file.
#include <cstdio>
#include <string>

#include <m3g/m3g.h>

#include "Commands.h"
#include "SampleScene.h"

namespace m3gcli {

int cmdSample(std::span<const std::string_view> args) {
    std::string out;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if ((args[i] == "-o" || args[i] == "--output") && i + 1 < args.size()) out = args[++i];
        else {
            std::fprintf(stderr, "m3g: sample: usage: m3g sample -o OUT.m3g\n");
            return 2;
        }
    }
    if (out.empty()) {
        std::fprintf(stderr, "m3g: sample: usage: m3g sample -o OUT.m3g\n");
        return 2;
    }
    try {
        m3g::Ref<m3g::World> world = buildSampleScene();
        m3g::Object3D* roots[] = {world.get()};
        m3g::Saver::save(out, roots);
        std::fprintf(stderr, "m3g: wrote the sample scene to %s\n", out.c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "m3g: sample: %s\n", e.what());
        return 1;
    }
}

}  // namespace m3gcli
