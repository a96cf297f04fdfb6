#include "cmd_pick.h"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include <m3g/m3g.h>

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

int runPick(const CliArgs& args) {
    const auto x = parseFloat(args.files[1]);
    const auto y = parseFloat(args.files[2]);
    if (!x || !y) {
        std::fprintf(stderr, "m3g: pick: X and Y must be numbers (normalised viewport coordinates), got '%s' '%s'\n",
                     args.files[1].c_str(), args.files[2].c_str());
        return 2;
    }
    try {
        m3g::LoaderOptions options;
        options.lenient = args.lenient;
        const m3g::LoadResult result = m3g::Loader::loadDetailed(args.files[0], options);
        std::vector<m3g::Object3D*> roots;
        for (const auto& r : result.roots) roots.push_back(r.get());
        std::printf("%s", pickReport(roots, args.time.value_or(0), *x, *y, args.json).c_str());
        return 0;
    } catch (const PickError& e) {
        std::fprintf(stderr, "m3g: pick: %s: %s\n", args.files[0].c_str(), e.what());
    } catch (const m3g::Exception& e) {
        std::fprintf(stderr, "m3g: %s\n", e.what());
    }
    return 1;
}

}  // namespace m3gcli
