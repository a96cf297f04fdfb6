#include "cmd_pick.h"

#include <algorithm>
#include <climits>
#include <cstdio>
#include <memory>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include <m3g/m3g.h>

#include "CliArgs.h"
#include "Commands.h"
#include "InputFile.h"
#include "ObjectDump.h"

namespace m3gcli {

namespace {

// Insertion-ordered members, single-precision numbers (shortest form that
// reads back as the same float), as in ObjectDump.
using Json = nlohmann::basic_json<nlohmann::ordered_map, std::vector, std::string, bool, std::int64_t,
                                  std::uint64_t, float>;

std::string fmt(float v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

}  // namespace

std::string pickReport(std::span<m3g::Object3D* const> roots, int time, float x, float y, bool json) {
    m3g::World* world = nullptr;
    for (m3g::Object3D* r : roots)
        if ((world = dynamic_cast<m3g::World*>(r))) break;
    if (!world) throw PickError("the file has no World to pick in");
    world->animate(time);
    const m3g::Ref<m3g::Camera> camera = world->getActiveCamera();
    if (!camera) throw PickError("the World has no active camera");
    if (camera->root() != world)
        throw PickError("the World's active camera is not in the World (Group::pick needs both in one scene graph)");

    m3g::RayIntersection ri;
    const bool hit = world->pick(-1, x, y, camera, &ri);
    const std::vector<m3g::Object3D*> objects = collectObjects(roots);
    int id = -1;
    m3g::Node* node = ri.getIntersected().get();
    if (hit) {
        const auto it = std::find(objects.begin(), objects.end(), static_cast<m3g::Object3D*>(node));
        if (it != objects.end()) id = static_cast<int>(it - objects.begin());
    }
    const int units = m3g::getLimits().numTextureUnits;
    float rayValues[6];
    ri.getRay(rayValues);

    if (json) {
        Json doc = Json::object();
        doc["time"] = time;
        doc["x"] = x;
        doc["y"] = y;
        doc["hit"] = hit;
        if (hit) {
            Json n = Json::object();
            n["id"] = id;
            n["class"] = node->getClassName();
            n["userID"] = node->getUserID();
            doc["node"] = std::move(n);
            doc["distance"] = ri.getDistance();
            doc["submesh"] = ri.getSubmeshIndex();
            Json tex = Json::array();
            for (int u = 0; u < units; ++u) {
                Json t = Json::object();
                t["unit"] = u;
                t["s"] = ri.getTextureS(u);
                t["t"] = ri.getTextureT(u);
                tex.push_back(std::move(t));
            }
            doc["textureCoordinates"] = std::move(tex);
            doc["normal"] = Json::array({ri.getNormalX(), ri.getNormalY(), ri.getNormalZ()});
            Json r = Json::object();
            r["origin"] = Json::array({rayValues[0], rayValues[1], rayValues[2]});
            r["direction"] = Json::array({rayValues[3], rayValues[4], rayValues[5]});
            doc["ray"] = std::move(r);
        }
        return doc.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
    }

    std::ostringstream os;
    os << "pick at (" << fmt(x) << ", " << fmt(y) << ") through the active camera, world time " << time
       << " ms\n";
    if (!hit) {
        os << "no hit\n";
        return os.str();
    }
    os << "hit: " << node->getClassName() << " #" << id << " userID=" << node->getUserID() << "\n";
    os << "distance: " << fmt(ri.getDistance()) << " (0 at the near plane, 1 at the far plane)\n";
    os << "submesh: " << ri.getSubmeshIndex() << "\n";
    for (int u = 0; u < units; ++u)
        os << "texture unit " << u << ": S=" << fmt(ri.getTextureS(u)) << " T=" << fmt(ri.getTextureT(u)) << "\n";
    os << "normal: (" << fmt(ri.getNormalX()) << ", " << fmt(ri.getNormalY()) << ", " << fmt(ri.getNormalZ())
       << ")\n";
    os << "ray: origin (" << fmt(rayValues[0]) << ", " << fmt(rayValues[1]) << ", " << fmt(rayValues[2])
       << ") direction (" << fmt(rayValues[3]) << ", " << fmt(rayValues[4]) << ", " << fmt(rayValues[5]) << ")\n";
    return os.str();
}

void addPickOptions(CLI::App& app, PickArgs& args) {
    app.add_option("file", args.file, "an .m3g file with a World and an active camera")->type_name("FILE")->required();
    app.add_option("x", args.x, "viewport X: 0 left, 1 right (numbers outside pick outside)")->type_name("X")->required();
    app.add_option("y", args.y, "viewport Y: 0 top, 1 bottom")->type_name("Y")->required();
    app.add_option("--time", args.time, "animate the World to world time T (ms) first (default 0)")->type_name("T");
    app.add_flag("--json", args.json, "print the RayIntersection as JSON");
    app.add_flag("--lenient", args.lenient, "accept the exporter faults seen in real files (LoaderOptions.lenient)");
}

PickArgs parsePickArgs(std::span<const std::string_view> args) {
    CLI::App app("", "pick");
    PickArgs out;
    addPickOptions(app, out);
    parseArgs(app, std::vector<std::string>(args.begin(), args.end()));
    return out;
}

void addPickCommand(CLI::App& parent, CommandTable& table) {
    CLI::App* app = addCommandApp(parent, "pick",
                                  "pick through the World's active camera at viewport point (X, Y)");
    auto args = std::make_shared<PickArgs>();
    addPickOptions(*app, *args);
    table[app] = [args] { return runPick(*args); };
}

int runPick(const PickArgs& args) {
    const auto x = parseFloat(args.x);
    const auto y = parseFloat(args.y);
    if (!x || !y)
        throw CliError("X and Y must be numbers (normalised viewport coordinates), got '" + args.x + "' '" + args.y + "'");
    const int time = args.time.empty() ? 0 : parseIntOption("--time", args.time, INT_MIN, "an integer (world time in ms)");
    const m3g::LoadResult result = loadInput(args.file, args.lenient);
    std::vector<m3g::Object3D*> roots;
    for (const auto& r : result.roots) roots.push_back(r.get());
    try {
        std::printf("%s", pickReport(roots, time, *x, *y, args.json).c_str());
    } catch (const PickError& e) {
        throw InputError(withPath(args.file, e.what()));
    } catch (const m3g::Exception& e) {
        throw InputError(withPath(args.file, e.what()));
    }
    return kExitOk;
}

}  // namespace m3gcli
