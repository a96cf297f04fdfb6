// m3g sample: writes the project's sample scene as an .m3g file.
#include <cstdio>
#include <memory>
#include <string>

#include <m3g/m3g.h>

#include "CliArgs.h"
#include "Commands.h"
#include "SampleScene.h"

namespace m3gcli {

void addSampleCommand(CLI::App& parent, CommandTable& table) {
    CLI::App* app = addCommandApp(parent, "sample", "write the project's sample scene (built in code) as an .m3g file");
    auto out = std::make_shared<std::string>();
    app->add_option("-o,--output", *out, "the .m3g file to write")->type_name("OUT.m3g")->required();
    table[app] = [out] {
        if (lowerExtension(*out) != ".m3g") throw CliError("sample writes M3G: name the output .m3g, not '" + *out + "'");
        m3g::Ref<m3g::World> world = buildSampleScene();
        m3g::Object3D* roots[] = {world.get()};
        try {
            m3g::Saver::save(*out, roots);
        } catch (const m3g::IOException& e) {
            throw OutputError(e.what());
        }
        std::fprintf(stderr, "m3g sample: wrote the sample scene to %s\n", out->c_str());
        return int(kExitOk);
    };
}

}  // namespace m3gcli
