// tools/m3g/cmd_pick: `m3g pick` argument parsing and report on an in-memory
// World with a hand-computed hit.
#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include <m3g/m3g.h>

#include "CliArgs.h"
#include "CliErrors.h"
#include "cmd_pick.h"

using namespace m3g;

namespace {

m3gcli::PickArgs parse(std::initializer_list<std::string_view> args) {
    const std::vector<std::string_view> v(args);
    return m3gcli::parsePickArgs(std::span<const std::string_view>(v));
}

/// A World whose active camera (perspective 90, 1, 1, 10, at the origin)
/// looks at a triangle (-50,-50,-5) (100,-50,-5) (-50,100,-5) (userID 7, a
/// second object) with texture coordinates 0.01 * (x, y) on unit 0.
Ref<World> scene(bool withCamera = true) {
    Ref<World> w = new World();
    Ref<Camera> c = new Camera();
    c->setPerspective(90, 1, 1, 10);
    w->addChild(c);
    if (withCamera) w->setActiveCamera(c);
    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<VertexArray> pos = new VertexArray(3, 3, 2);
    const std::int16_t p[] = {-50, -50, -5, 100, -50, -5, -50, 100, -5};
    pos->set(0, 3, p);
    vb->setPositions(pos, 1.0f, {});
    Ref<VertexArray> tex = new VertexArray(3, 2, 2);
    const std::int16_t t[] = {-50, -50, 100, -50, -50, 100};
    tex->set(0, 3, t);
    vb->setTexCoords(0, tex, 0.01f, {});
    const int lengths[] = {3};
    Ref<Mesh> m = new Mesh(vb, new TriangleStripArray(0, lengths), new Appearance());
    m->setUserID(7);
    w->addChild(m);
    return w;
}

std::string report(Object3D* root, float x, float y, bool json, int time = 0) {
    Object3D* roots[] = {root};
    return m3gcli::pickReport(roots, time, x, y, json);
}

}  // namespace

TEST(CmdPick, Arguments) {
    const m3gcli::PickArgs a = parse({"w.m3g", "0.25", "0.75", "--time", "40", "--json", "--lenient"});
    EXPECT_EQ(a.file, "w.m3g");
    EXPECT_EQ(a.x, "0.25");
    EXPECT_EQ(a.y, "0.75");
    EXPECT_EQ(a.time, "40");
    EXPECT_TRUE(a.json);
    EXPECT_TRUE(a.lenient);
    EXPECT_EQ(parse({"w.m3g", "0", "1", "--time=-5"}).time, "-5");
    // Negative coordinates are operands, not options.
    const m3gcli::PickArgs n = parse({"w.m3g", "-0.5", "-1e-3"});
    EXPECT_EQ(n.x, "-0.5");
    EXPECT_EQ(n.y, "-1e-3");
    EXPECT_THROW(parse({"w.m3g", "0.5"}), m3gcli::CliError);
    EXPECT_THROW(parse({"w.m3g", "0.5", "0.5", "0.5"}), m3gcli::CliError);
    EXPECT_THROW(parse({"w.m3g", "0.5", "0.5", "--compress"}), m3gcli::CliError);
    EXPECT_THROW(parse({"w.m3g", "0.5", "0.5", "-x"}), m3gcli::CliError);
    // Values are checked when the command runs: X must be a number (usage error).
    m3gcli::PickArgs bad = n;
    bad.x = "middle";
    EXPECT_THROW(m3gcli::runPick(bad), m3gcli::CliError);
    EXPECT_EQ(m3gcli::parseFloat("-0.25"), -0.25f);
    EXPECT_EQ(m3gcli::parseFloat("+2"), 2.0f);
    EXPECT_FALSE(m3gcli::parseFloat("1.5x"));
    EXPECT_FALSE(m3gcli::parseFloat("+-1"));
    EXPECT_FALSE(m3gcli::parseFloat("inf"));
    EXPECT_FALSE(m3gcli::parseFloat(""));
}

TEST(CmdPick, TextReport) {
    Ref<World> w = scene();
    // Centre: the ray (0,0,-1) -> (0,0,-10) meets z = -5 at t = 4/9 at (0, 0).
    const std::string text = report(w, 0.5f, 0.5f, false);
    EXPECT_NE(text.find("hit: Mesh #2 userID=7\n"), std::string::npos) << text;
    EXPECT_NE(text.find("distance: 0.444444"), std::string::npos) << text;
    EXPECT_NE(text.find("submesh: 0\n"), std::string::npos) << text;
    EXPECT_NE(text.find("texture unit 0: S="), std::string::npos) << text;  // ~0 after rounding
    EXPECT_NE(text.find("texture unit 1: S=0 T=0\n"), std::string::npos) << text;  // no coordinates
    EXPECT_NE(text.find("normal: (0, 0, 1)\n"), std::string::npos) << text;
    EXPECT_NE(text.find("ray: origin (0, 0, -1) direction (0, 0, -9)\n"), std::string::npos) << text;
    // (5, -5) -> NDC (9, 11): at z = -5 the ray is at (45, 55), past x + y = 50.
    EXPECT_NE(report(w, 5, -5, false).find("no hit\n"), std::string::npos);
}

TEST(CmdPick, JsonReport) {
    Ref<World> w = scene();
    // (0.75, 0.25) -> NDC (0.5, 0.5): the ray (0.5,0.5,-1) -> (5,5,-10) meets
    // z = -5 at (2.5, 2.5): S = T = 0.025.
    const auto doc = nlohmann::json::parse(report(w, 0.75f, 0.25f, true, 30));
    EXPECT_EQ(doc["time"], 30);
    EXPECT_EQ(doc["hit"], true);
    EXPECT_EQ(doc["node"]["class"], "Mesh");
    EXPECT_EQ(doc["node"]["id"], 2);
    EXPECT_EQ(doc["node"]["userID"], 7);
    EXPECT_NEAR(doc["distance"].get<double>(), 4.0 / 9.0, 1e-6);
    EXPECT_EQ(doc["submesh"], 0);
    ASSERT_EQ(doc["textureCoordinates"].size(), static_cast<std::size_t>(getLimits().numTextureUnits));
    EXPECT_NEAR(doc["textureCoordinates"][0]["s"].get<double>(), 0.025, 1e-5);
    EXPECT_NEAR(doc["textureCoordinates"][0]["t"].get<double>(), 0.025, 1e-5);
    EXPECT_NEAR(doc["ray"]["origin"][0].get<double>(), 0.5, 1e-5);
    EXPECT_NEAR(doc["ray"]["direction"][2].get<double>(), -9.0, 1e-4);
    EXPECT_EQ(doc["normal"], nlohmann::json::parse("[0.0, 0.0, 1.0]"));
    const auto miss = nlohmann::json::parse(report(w, 5, -5, true));
    EXPECT_EQ(miss["hit"], false);
    EXPECT_FALSE(miss.contains("node"));
}

TEST(CmdPick, AnimatesBeforePicking) {
    Ref<World> w = scene();
    // Translation track moving the triangle by (200, 0, 0) from t = 100 on.
    Ref<KeyframeSequence> s = new KeyframeSequence(2, 3, KeyframeSequence::STEP);
    const float a[] = {0, 0, 0}, b[] = {200, 0, 0};
    s->setKeyframe(0, 0, a);
    s->setKeyframe(1, 100, b);
    s->setDuration(200);
    Ref<AnimationTrack> t = new AnimationTrack(s, AnimationTrack::TRANSLATION);
    t->setController(new AnimationController());
    w->getChild(1)->addAnimationTrack(t);
    EXPECT_NE(report(w, 0.5f, 0.5f, false, 0).find("hit: Mesh"), std::string::npos);
    EXPECT_NE(report(w, 0.5f, 0.5f, false, 150).find("no hit"), std::string::npos);
}

TEST(CmdPick, Errors) {
    Ref<Group> g = new Group();
    EXPECT_THROW(report(g, 0.5f, 0.5f, false), m3gcli::PickError);
    EXPECT_THROW(report(scene(false), 0.5f, 0.5f, false), m3gcli::PickError);
    Ref<World> w = scene();
    Ref<Camera> outside = new Camera();
    w->setActiveCamera(outside);
    try {
        report(w, 0.5f, 0.5f, false);
        ADD_FAILURE() << "no exception";
    } catch (const m3gcli::PickError& e) {
        EXPECT_NE(std::string(e.what()).find("not in the World"), std::string::npos) << e.what();
    }
}
