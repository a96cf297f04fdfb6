// examples/ObjectDump (m3g info reporting): JSON dump of every getter value,
// scene tree, counts by class. The JSON is parsed with a strict checker.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <m3g/m3g.h>

#include "ObjectDump.h"

using namespace m3g;
using m3gcli::countByClass;
using m3gcli::dumpJson;
using m3gcli::dumpTree;

namespace {

// ---------------------------------------------------------------------------
// A strict JSON parser (RFC 8259 grammar; no NaN/Infinity, no trailing commas,
// no leading zeros). Throws std::runtime_error on invalid input.

struct J {
    enum Kind { Null, Bool, Number, String, Array, Object } kind = Null;
    bool b = false;
    double num = 0;
    std::string str;
    std::vector<J> arr;
    std::vector<std::pair<std::string, J>> obj;

    const J& operator[](const std::string& key) const {
        if (kind != Object) throw std::runtime_error("not an object looking up " + key);
        for (const auto& [k, v] : obj)
            if (k == key) return v;
        throw std::runtime_error("no key " + key);
    }
    const J& operator[](std::size_t i) const {
        if (kind != Array || i >= arr.size()) throw std::runtime_error("bad array index");
        return arr[i];
    }
    bool has(const std::string& key) const {
        for (const auto& [k, v] : obj)
            if (k == key) return true;
        return false;
    }
    bool isNull() const { return kind == Null; }
    int asInt() const {
        if (kind != Number) throw std::runtime_error("not a number");
        return static_cast<int>(num);
    }
    double asNum() const {
        if (kind != Number) throw std::runtime_error("not a number");
        return num;
    }
    const std::string& asStr() const {
        if (kind != String) throw std::runtime_error("not a string");
        return str;
    }
    bool asBool() const {
        if (kind != Bool) throw std::runtime_error("not a bool");
        return b;
    }
    std::vector<double> nums() const {
        std::vector<double> v;
        for (const auto& e : arr) v.push_back(e.asNum());
        return v;
    }
};

class Parser {
public:
    explicit Parser(const std::string& s) : s_(s) {}
    J parseDocument() {
        J v = value();
        ws();
        if (p_ != s_.size()) fail("trailing characters");
        return v;
    }

private:
    [[noreturn]] void fail(const std::string& what) {
        throw std::runtime_error("JSON: " + what + " at offset " + std::to_string(p_));
    }
    void ws() {
        while (p_ < s_.size() && (s_[p_] == ' ' || s_[p_] == '\n' || s_[p_] == '\r' || s_[p_] == '\t')) ++p_;
    }
    char peek() {
        if (p_ >= s_.size()) fail("unexpected end");
        return s_[p_];
    }
    void expect(char c) {
        if (peek() != c) fail(std::string("expected '") + c + "'");
        ++p_;
    }
    bool literal(const char* lit) {
        const std::string l(lit);
        if (s_.compare(p_, l.size(), l) == 0) {
            p_ += l.size();
            return true;
        }
        return false;
    }
    J value() {
        ws();
        J v;
        const char c = peek();
        if (c == '{') {
            v.kind = J::Object;
            ++p_;
            ws();
            if (peek() == '}') {
                ++p_;
                return v;
            }
            for (;;) {
                ws();
                std::string key = string();
                ws();
                expect(':');
                J member = value();
                for (const auto& [k, unused] : v.obj)
                    if (k == key) fail("duplicate key " + key);
                v.obj.emplace_back(std::move(key), std::move(member));
                ws();
                if (peek() == ',') {
                    ++p_;
                    continue;
                }
                expect('}');
                return v;
            }
        }
        if (c == '[') {
            v.kind = J::Array;
            ++p_;
            ws();
            if (peek() == ']') {
                ++p_;
                return v;
            }
            for (;;) {
                v.arr.push_back(value());
                ws();
                if (peek() == ',') {
                    ++p_;
                    continue;
                }
                expect(']');
                return v;
            }
        }
        if (c == '"') {
            v.kind = J::String;
            v.str = string();
            return v;
        }
        if (literal("true")) {
            v.kind = J::Bool;
            v.b = true;
            return v;
        }
        if (literal("false")) {
            v.kind = J::Bool;
            return v;
        }
        if (literal("null")) return v;
        v.kind = J::Number;
        v.num = number();
        return v;
    }
    std::string string() {
        expect('"');
        std::string out;
        for (;;) {
            const char c = peek();
            ++p_;
            if (c == '"') return out;
            if (static_cast<unsigned char>(c) < 0x20) fail("control character in string");
            if (c != '\\') {
                out += c;
                continue;
            }
            const char e = peek();
            ++p_;
            switch (e) {
            case '"': out += '"'; break;
            case '\\': out += '\\'; break;
            case '/': out += '/'; break;
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'n': out += '\n'; break;
            case 'r': out += '\r'; break;
            case 't': out += '\t'; break;
            case 'u': {
                if (p_ + 4 > s_.size()) fail("short \\u escape");
                const int code = std::stoi(s_.substr(p_, 4), nullptr, 16);
                p_ += 4;
                if (code >= 0x80) fail("test parser only decodes ASCII escapes");
                out += static_cast<char>(code);
                break;
            }
            default: fail("bad escape");
            }
        }
    }
    double number() {
        const std::size_t start = p_;
        auto digit = [&] { return p_ < s_.size() && s_[p_] >= '0' && s_[p_] <= '9'; };
        if (p_ < s_.size() && s_[p_] == '-') ++p_;
        if (!digit()) fail("bad number");
        if (s_[p_] == '0') {
            ++p_;
            if (digit()) fail("leading zero");
        } else {
            while (digit()) ++p_;
        }
        if (p_ < s_.size() && s_[p_] == '.') {
            ++p_;
            if (!digit()) fail("bad fraction");
            while (digit()) ++p_;
        }
        if (p_ < s_.size() && (s_[p_] == 'e' || s_[p_] == 'E')) {
            ++p_;
            if (p_ < s_.size() && (s_[p_] == '+' || s_[p_] == '-')) ++p_;
            if (!digit()) fail("bad exponent");
            while (digit()) ++p_;
        }
        return std::stod(s_.substr(start, p_ - start));
    }

    const std::string& s_;
    std::size_t p_ = 0;
};

J parse(const std::string& s) { return Parser(s).parseDocument(); }

std::string dump(Object3D* root, const m3gcli::DumpOptions& opt = {}) {
    Object3D* roots[] = {root};
    return dumpJson(roots, opt);
}

/// The object with `id` (checks that ids are the array positions).
const J& object(const J& doc, int id) {
    const J& o = doc["objects"][static_cast<std::size_t>(id)];
    if (o["id"].asInt() != id) throw std::runtime_error("ids are not positions");
    return o;
}

/// The first object of class `cls` with user ID `userID`.
const J& find(const J& doc, const std::string& cls, int userID) {
    for (const J& o : doc["objects"].arr)
        if (o["class"].asStr() == cls && o["userID"].asInt() == userID) return o;
    throw std::runtime_error("no " + cls + " with userID " + std::to_string(userID));
}

int count(const std::string& text, const std::string& needle) {
    int n = 0;
    for (std::size_t p = text.find(needle); p != std::string::npos; p = text.find(needle, p + 1)) ++n;
    return n;
}

// ---------------------------------------------------------------------------
// A scene using every common class.

struct Scene {
    Ref<World> world = new World();
    Ref<Camera> camera = new Camera();
    Ref<Light> light = new Light();
    Ref<Background> background = new Background();
    Ref<VertexArray> positions = new VertexArray(4, 3, 2);
    Ref<VertexArray> normals = new VertexArray(4, 3, 1);
    Ref<VertexArray> colors = new VertexArray(4, 4, 1);
    Ref<VertexArray> texCoords = new VertexArray(4, 2, 2);
    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<TriangleStripArray> strip;
    Ref<Material> material = new Material();
    Ref<CompositingMode> compositing = new CompositingMode();
    Ref<PolygonMode> polygon = new PolygonMode();
    Ref<Fog> fog = new Fog();
    Ref<Image2D> image;
    Ref<Texture2D> texture;
    Ref<Appearance> appearance = new Appearance();
    Ref<Mesh> mesh1;
    Ref<Mesh> mesh2;
    Ref<Group> group = new Group();
    Ref<KeyframeSequence> sequence = new KeyframeSequence(2, 3, KeyframeSequence::LINEAR);
    Ref<AnimationController> controller = new AnimationController();
    Ref<AnimationTrack> track;

    Scene() {
        world->setUserID(1);
        camera->setUserID(2);
        camera->setPerspective(60.0f, 1.5f, 0.25f, 100.0f);
        camera->setTranslation(0.0f, 1.0f, 10.0f);
        world->addChild(camera);
        world->setActiveCamera(camera);
        light->setUserID(3);
        light->setMode(Light::OMNI);
        light->setColor(0x123456);
        light->setIntensity(2.5f);
        light->setAttenuation(1.0f, 0.5f, 0.25f);
        world->addChild(light);
        background->setColor(static_cast<int>(0x80FF0000u));
        world->setBackground(background);

        const std::int16_t pos[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, -7};
        positions->set(0, 4, std::span<const std::int16_t>(pos));
        const float bias[] = {1.0f, 2.0f, 3.0f};
        vb->setPositions(positions, 0.5f, bias);
        const std::int8_t nrm[] = {0, 0, 127, 0, 0, 127, 0, 0, 127, 0, 0, -128};
        normals->set(0, 4, std::span<const std::int8_t>(nrm));
        vb->setNormals(normals);
        vb->setColors(colors);
        const float tcBias[] = {0.25f, 0.75f};
        vb->setTexCoords(0, texCoords, 2.0f, tcBias);
        vb->setDefaultColor(static_cast<int>(0xFF102030u));
        const int lengths[] = {4};
        strip = new TriangleStripArray(0, lengths);

        material->setColor(Material::DIFFUSE, static_cast<int>(0x80112233u));
        material->setColor(Material::SPECULAR, 0x00445566);
        material->setShininess(12.5f);
        material->setVertexColorTrackingEnable(true);
        compositing->setBlending(CompositingMode::ALPHA);
        compositing->setAlphaThreshold(0.5f);
        compositing->setDepthOffset(-1.0f, 2.0f);
        polygon->setCulling(PolygonMode::CULL_NONE);
        polygon->setTwoSidedLightingEnable(true);
        fog->setMode(Fog::EXPONENTIAL);
        fog->setDensity(0.125f);
        const std::uint8_t pixels[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
        image = new Image2D(Image2D::RGB, 2, 2, pixels);
        texture = new Texture2D(image);
        texture->setBlending(Texture2D::FUNC_DECAL);
        texture->setWrapping(Texture2D::WRAP_CLAMP, Texture2D::WRAP_REPEAT);
        texture->setBlendColor(0x00ABCDEF);
        appearance->setLayer(-3);
        appearance->setMaterial(material);
        appearance->setCompositingMode(compositing);
        appearance->setPolygonMode(polygon);
        appearance->setFog(fog);
        appearance->setTexture(0, texture);

        // Two meshes sharing the vertex buffer, index buffer and appearance.
        mesh1 = new Mesh(vb, strip, appearance);
        mesh1->setUserID(10);
        mesh2 = new Mesh(vb, strip, appearance);
        mesh2->setUserID(11);
        mesh2->setRenderingEnable(false);
        mesh2->setAlphaFactor(0.5f);
        mesh2->setScope(6);
        group->setUserID(20);
        group->addChild(mesh1);
        group->addChild(mesh2);
        world->addChild(group);

        const float k0[] = {0.0f, 0.0f, 0.0f};
        const float k1[] = {10.0f, 20.0f, 30.0f};
        sequence->setKeyframe(0, 0, k0);
        sequence->setKeyframe(1, 100, k1);
        sequence->setDuration(200);
        sequence->setRepeatMode(KeyframeSequence::LOOP);
        controller->setActiveInterval(0, 1000);
        controller->setSpeed(2.0f, 0);
        track = new AnimationTrack(sequence, AnimationTrack::TRANSLATION);
        track->setController(controller);
        group->addAnimationTrack(track);
    }
};

}  // namespace

// ---------------------------------------------------------------------------

TEST(ObjectDump, TestParserIsStrict) {
    for (const char* bad : {"[1,]", "{\"a\": NaN}", "[Infinity]", "[01]", "{\"a\" 1}", "[1] x", "\"\x01\"",
                            "{\"a\": 1, \"a\": 2}", "[-]", "[1.]"})
        EXPECT_THROW(parse(bad), std::runtime_error) << bad;
    EXPECT_EQ(parse("{\"a\": [1, -2.5e3, null, true, \"x\\ny\"]}")["a"][1].asNum(), -2500.0);
}

TEST(ObjectDump, JsonIsValidAndListsEveryObjectOnce) {
    Scene s;
    const std::string text = dump(s.world);
    const J doc = parse(text);
    const auto& objects = doc["objects"].arr;
    ASSERT_EQ(doc["objectCount"].asInt(), static_cast<int>(objects.size()));
    ASSERT_EQ(doc["roots"].arr.size(), 1u);
    EXPECT_EQ(doc["roots"][0].asInt(), 0);
    EXPECT_EQ(object(doc, 0)["class"].asStr(), "World");
    // World, Camera, Light, Background, Group, AnimationTrack, KeyframeSequence,
    // AnimationController, 2 Mesh, VertexBuffer, 4 VertexArray, TriangleStripArray,
    // Appearance, CompositingMode, Fog, PolygonMode, Material, Texture2D, Image2D.
    EXPECT_EQ(objects.size(), 23u);
    for (std::size_t i = 0; i < objects.size(); ++i) EXPECT_EQ(objects[i]["id"].asInt(), static_cast<int>(i));
    // Every reference is an existing id.
    for (const J& o : objects)
        for (const J& r : o["references"].arr) {
            ASSERT_FALSE(r.isNull());
            EXPECT_LT(r.asInt(), static_cast<int>(objects.size()));
        }
    // Depth-first order of first visit: World's references are its children
    // (camera, light, group), then the active camera (seen) and the background.
    EXPECT_EQ(object(doc, 1)["class"].asStr(), "Camera");
    EXPECT_EQ(object(doc, 2)["class"].asStr(), "Light");
    EXPECT_EQ(object(doc, 3)["class"].asStr(), "Group");
    EXPECT_EQ(object(doc, 4)["class"].asStr(), "AnimationTrack");  // tracks come first
    EXPECT_EQ(object(doc, 5)["class"].asStr(), "KeyframeSequence");
    EXPECT_EQ(object(doc, 6)["class"].asStr(), "AnimationController");
    EXPECT_EQ(object(doc, 7)["class"].asStr(), "Mesh");
    EXPECT_EQ(objects.back()["class"].asStr(), "Background");

    const auto counts = countByClass(std::span<Object3D* const>(std::vector<Object3D*>{s.world.get()}));
    EXPECT_EQ(counts.at("Mesh"), 2);
    EXPECT_EQ(counts.at("VertexArray"), 4);
    EXPECT_EQ(counts.at("Appearance"), 1);
    EXPECT_EQ(counts.at("Material"), 1);
    int total = 0;
    for (const auto& [cls, n] : counts) total += n;
    EXPECT_EQ(total, 23);
}

TEST(ObjectDump, NodeAndCameraAndLightValues) {
    Scene s;
    const J doc = parse(dump(s.world));
    const J& world = find(doc, "World", 1);
    const J& camera = find(doc, "Camera", 2);
    const J& light = find(doc, "Light", 3);
    const J& group = find(doc, "Group", 20);
    EXPECT_EQ(world["activeCamera"].asInt(), camera["id"].asInt());
    EXPECT_EQ(object(doc, world["background"].asInt())["class"].asStr(), "Background");
    EXPECT_EQ(world["childCount"].asInt(), 3);
    EXPECT_EQ(world["children"][2].asInt(), group["id"].asInt());
    EXPECT_TRUE(world["parent"].isNull());

    EXPECT_EQ(camera["projection"].asStr(), "PERSPECTIVE");
    EXPECT_EQ(camera["projectionParams"].nums(), (std::vector<double>{60.0, 1.5, 0.25, 100.0}));
    EXPECT_EQ(camera["projectionMatrix"].arr.size(), 16u);
    EXPECT_EQ(camera["translation"].nums(), (std::vector<double>{0.0, 1.0, 10.0}));
    EXPECT_EQ(camera["scale"].nums(), (std::vector<double>{1.0, 1.0, 1.0}));
    EXPECT_EQ(camera["compositeTransform"].nums()[7], 1.0);   // row 1, column 3 = ty
    EXPECT_EQ(camera["compositeTransform"].nums()[11], 10.0);  // tz
    EXPECT_EQ(camera["parent"].asInt(), 0);
    EXPECT_TRUE(camera["renderingEnabled"].asBool());
    EXPECT_EQ(camera["scope"].asInt(), -1);
    EXPECT_EQ(camera["alignment"]["zTarget"].asStr(), "NONE");
    EXPECT_TRUE(camera["alignment"]["zReference"].isNull());

    EXPECT_EQ(light["mode"].asStr(), "OMNI");
    EXPECT_EQ(light["color"].asStr(), "0x00123456");
    EXPECT_EQ(light["intensity"].asNum(), 2.5);
    EXPECT_EQ(light["attenuation"].nums(), (std::vector<double>{1.0, 0.5, 0.25}));
    EXPECT_EQ(light["spotAngle"].asNum(), 45.0);

    const J& mesh2 = find(doc, "Mesh", 11);
    EXPECT_FALSE(mesh2["renderingEnabled"].asBool());
    EXPECT_TRUE(mesh2["pickingEnabled"].asBool());
    EXPECT_EQ(mesh2["alphaFactor"].asNum(), 0.5);
    EXPECT_EQ(mesh2["scope"].asInt(), 6);
    EXPECT_EQ(mesh2["parent"].asInt(), group["id"].asInt());

    const J& bg = object(doc, world["background"].asInt());
    EXPECT_EQ(bg["color"].asStr(), "0x80FF0000");
    EXPECT_EQ(bg["imageModeX"].asStr(), "BORDER");
    EXPECT_TRUE(bg["image"].isNull());
    EXPECT_TRUE(bg["depthClearEnabled"].asBool());
}

TEST(ObjectDump, MeshComponentsAreSharedAndDumpedOnce) {
    Scene s;
    const std::string text = dump(s.world);
    const J doc = parse(text);
    const J& m1 = find(doc, "Mesh", 10);
    const J& m2 = find(doc, "Mesh", 11);
    EXPECT_EQ(m1["vertexBuffer"].asInt(), m2["vertexBuffer"].asInt());
    EXPECT_EQ(m1["submeshCount"].asInt(), 1);
    EXPECT_EQ(m1["submeshes"][0]["appearance"].asInt(), m2["submeshes"][0]["appearance"].asInt());
    EXPECT_EQ(m1["submeshes"][0]["indexBuffer"].asInt(), m2["submeshes"][0]["indexBuffer"].asInt());
    EXPECT_EQ(count(text, "\"class\": \"Appearance\""), 1);
    EXPECT_EQ(count(text, "\"class\": \"VertexBuffer\""), 1);

    const J& vb = object(doc, m1["vertexBuffer"].asInt());
    EXPECT_EQ(vb["vertexCount"].asInt(), 4);
    EXPECT_EQ(vb["positions"]["scale"].asNum(), 0.5);
    EXPECT_EQ(vb["positions"]["bias"].nums(), (std::vector<double>{1.0, 2.0, 3.0}));
    EXPECT_EQ(vb["defaultColor"].asStr(), "0xFF102030");
    EXPECT_EQ(vb["texCoords"][0]["scale"].asNum(), 2.0);
    EXPECT_EQ(vb["texCoords"][0]["bias"].nums(), (std::vector<double>{0.25, 0.75}));
    EXPECT_TRUE(vb["texCoords"][1].isNull());

    const J& pos = object(doc, vb["positions"]["array"].asInt());
    EXPECT_EQ(pos["class"].asStr(), "VertexArray");
    EXPECT_EQ(pos["componentCount"].asInt(), 3);
    EXPECT_EQ(pos["componentType"].asInt(), 2);
    EXPECT_EQ(pos["values"][3].nums(), (std::vector<double>{1.0, 1.0, -7.0}));
    EXPECT_FALSE(pos["truncated"].asBool());
    const J& nrm = object(doc, vb["normals"].asInt());
    EXPECT_EQ(nrm["values"][3].nums(), (std::vector<double>{0.0, 0.0, -128.0}));

    const J& ib = object(doc, m1["submeshes"][0]["indexBuffer"].asInt());
    EXPECT_EQ(ib["class"].asStr(), "TriangleStripArray");
    EXPECT_EQ(ib["indexCount"].asInt(), 6);
    EXPECT_EQ(ib["indices"].nums(), (std::vector<double>{0, 1, 2, 1, 3, 2}));
    EXPECT_EQ(ib["stripLengths"].nums(), (std::vector<double>{4}));

    const J& ap = object(doc, m1["submeshes"][0]["appearance"].asInt());
    EXPECT_EQ(ap["layer"].asInt(), -3);
    const J& mat = object(doc, ap["material"].asInt());
    EXPECT_EQ(mat["diffuseColor"].asStr(), "0x80112233");
    EXPECT_EQ(mat["ambientColor"].asStr(), "0x00333333");
    EXPECT_EQ(mat["specularColor"].asStr(), "0x00445566");
    EXPECT_EQ(mat["emissiveColor"].asStr(), "0x00000000");
    EXPECT_EQ(mat["shininess"].asNum(), 12.5);
    EXPECT_TRUE(mat["vertexColorTrackingEnabled"].asBool());
    const J& cm = object(doc, ap["compositingMode"].asInt());
    EXPECT_EQ(cm["blending"].asStr(), "ALPHA");
    EXPECT_EQ(cm["alphaThreshold"].asNum(), 0.5);
    EXPECT_EQ(cm["depthOffsetFactor"].asNum(), -1.0);
    EXPECT_EQ(cm["depthOffsetUnits"].asNum(), 2.0);
    const J& pm = object(doc, ap["polygonMode"].asInt());
    EXPECT_EQ(pm["culling"].asStr(), "CULL_NONE");
    EXPECT_EQ(pm["shading"].asStr(), "SHADE_SMOOTH");
    EXPECT_EQ(pm["winding"].asStr(), "WINDING_CCW");
    EXPECT_TRUE(pm["twoSidedLightingEnabled"].asBool());
    const J& fog = object(doc, ap["fog"].asInt());
    EXPECT_EQ(fog["mode"].asStr(), "EXPONENTIAL");
    EXPECT_EQ(fog["density"].asNum(), 0.125);
    const J& tex = object(doc, ap["textures"][0].asInt());
    EXPECT_EQ(tex["blending"].asStr(), "FUNC_DECAL");
    EXPECT_EQ(tex["wrappingS"].asStr(), "WRAP_CLAMP");
    EXPECT_EQ(tex["wrappingT"].asStr(), "WRAP_REPEAT");
    EXPECT_EQ(tex["levelFilter"].asStr(), "FILTER_BASE_LEVEL");
    EXPECT_EQ(tex["blendColor"].asStr(), "0x00ABCDEF");
    EXPECT_EQ(tex["translation"].nums(), (std::vector<double>{0, 0, 0}));
    const J& img = object(doc, tex["image"].asInt());
    EXPECT_EQ(img["format"].asStr(), "RGB");
    EXPECT_EQ(img["width"].asInt(), 2);
    EXPECT_EQ(img["height"].asInt(), 2);
    EXPECT_FALSE(img["mutable"].asBool());
    EXPECT_EQ(img["pixelBytes"].asInt(), 12);
    EXPECT_EQ(img["pixelChecksum"].asStr().size(), 10u);
    EXPECT_TRUE(ap["textures"][1].isNull());
}

TEST(ObjectDump, AnimationValuesAndAnimatedState) {
    Scene s;
    s.world->animate(25);  // controller speed 2: sequence time 50, halfway
    m3gcli::DumpOptions opt;
    opt.worldTime = 25;
    const J doc = parse(dump(s.world, opt));
    const J& group = find(doc, "Group", 20);
    ASSERT_EQ(group["animationTracks"].arr.size(), 1u);
    const J& track = object(doc, group["animationTracks"][0].asInt());
    EXPECT_EQ(track["class"].asStr(), "AnimationTrack");
    EXPECT_EQ(track["targetProperty"].asStr(), "TRANSLATION");
    const J& seq = object(doc, track["keyframeSequence"].asInt());
    EXPECT_EQ(seq["keyframeCount"].asInt(), 2);
    EXPECT_EQ(seq["componentCount"].asInt(), 3);
    EXPECT_EQ(seq["interpolation"].asStr(), "LINEAR");
    EXPECT_EQ(seq["repeatMode"].asStr(), "LOOP");
    EXPECT_EQ(seq["duration"].asInt(), 200);
    EXPECT_EQ(seq["validRange"].nums(), (std::vector<double>{0, 1}));
    EXPECT_EQ(seq["keyframeTimes"].nums(), (std::vector<double>{0, 100}));
    EXPECT_EQ(seq["keyframeValues"][1].nums(), (std::vector<double>{10, 20, 30}));
    const J& ctl = object(doc, track["controller"].asInt());
    EXPECT_EQ(ctl["activeInterval"].nums(), (std::vector<double>{0, 1000}));
    EXPECT_EQ(ctl["speed"].asNum(), 2.0);
    EXPECT_EQ(ctl["weight"].asNum(), 1.0);
    EXPECT_EQ(ctl["position"].asNum(), 50.0);
    EXPECT_TRUE(ctl["active"].asBool());
    EXPECT_EQ(group["translation"].nums(), (std::vector<double>{5, 10, 15}));

    // Without a world time the controller has no position/active fields.
    const J plain = parse(dump(s.world));
    EXPECT_FALSE(object(plain, track["controller"].asInt()).has("position"));
}

TEST(ObjectDump, SkinnedMeshBonesAndSkeleton) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    vb->setPositions(new VertexArray(8, 3, 2), 1.0f, {});
    const int lengths[] = {8};
    Ref<TriangleStripArray> ib = new TriangleStripArray(0, lengths);
    Ref<Group> skeleton = new Group();
    Ref<Group> upper = new Group();
    Ref<Group> lower = new Group();
    upper->setUserID(100);
    lower->setUserID(101);
    skeleton->addChild(upper);
    upper->addChild(lower);
    lower->setTranslation(0.0f, 2.0f, 0.0f);
    Ref<SkinnedMesh> mesh = new SkinnedMesh(vb, ib, nullptr, skeleton);
    mesh->addTransform(lower, 1, 0, 3);
    mesh->addTransform(upper, 1, 2, 6);

    const J doc = parse(dump(mesh));
    const J& m = object(doc, 0);
    EXPECT_EQ(m["class"].asStr(), "SkinnedMesh");
    EXPECT_EQ(object(doc, m["skeleton"].asInt())["class"].asStr(), "Group");
    EXPECT_TRUE(m["submeshes"][0]["appearance"].isNull());
    ASSERT_EQ(m["bones"].arr.size(), 2u);
    const J& b0 = m["bones"][0];  // bone index order: lower was added first
    EXPECT_EQ(object(doc, b0["bone"].asInt())["userID"].asInt(), 101);
    EXPECT_EQ(b0["vertexCount"].asInt(), 3);
    EXPECT_EQ(b0["atRestTransform"].nums()[7], -2.0);  // mesh -> bone space: ty = -2
    const J& b1 = m["bones"][1];
    EXPECT_EQ(object(doc, b1["bone"].asInt())["userID"].asInt(), 100);
    EXPECT_EQ(b1["vertexCount"].asInt(), 6);
    EXPECT_EQ(object(doc, m["skeleton"].asInt())["parent"].asInt(), 0);
    EXPECT_EQ(doc["objectCount"].asInt(), 7);  // mesh, vb, array, strips, skeleton, upper, lower
}

TEST(ObjectDump, BonesAndAlignmentTargetsOutsideReferencesAreIncluded) {
    // An alignment reference to a node that nothing else references.
    Ref<Group> root = new Group();
    Ref<Group> child = new Group();
    Ref<Camera> outside = new Camera();
    outside->setUserID(77);
    root->addChild(child);
    child->setAlignment(outside, Node::ORIGIN, nullptr, Node::NONE);
    const J doc = parse(dump(root));
    ASSERT_EQ(doc["objectCount"].asInt(), 3);
    const J& c = object(doc, 1);
    EXPECT_EQ(c["alignment"]["zTarget"].asStr(), "ORIGIN");
    EXPECT_EQ(c["alignment"]["yTarget"].asStr(), "NONE");
    EXPECT_EQ(object(doc, c["alignment"]["zReference"].asInt())["userID"].asInt(), 77);
    EXPECT_TRUE(c["references"].arr.empty());  // getReferences does not list it
}

TEST(ObjectDump, UserParametersAsHex) {
    Ref<Group> g = new Group();
    auto params = std::make_shared<UserParameters>();
    (*params)[7] = {0x00, 0xAB, 0x10};
    (*params)[-2] = {};
    g->setUserObject(std::shared_ptr<const UserParameters>(params));
    Ref<Group> other = new Group();
    other->setUserObject(42);
    g->addChild(other);
    const J doc = parse(dump(g));
    EXPECT_EQ(object(doc, 0)["userObject"].asStr(), "UserParameters");
    EXPECT_EQ(object(doc, 0)["userParameters"]["7"].asStr(), "00ab10");
    EXPECT_EQ(object(doc, 0)["userParameters"]["-2"].asStr(), "");
    EXPECT_EQ(object(doc, 1)["userObject"].asStr(), "other");
    EXPECT_TRUE(object(doc, 1)["userParameters"].isNull());
}

TEST(ObjectDump, NonFiniteFloatsAreNull) {
    Ref<Group> g = new Group();
    Ref<Light> light = new Light();
    light->setIntensity(std::numeric_limits<float>::infinity());
    Ref<Fog> fog = new Fog();
    fog->setLinear(std::numeric_limits<float>::quiet_NaN(), -std::numeric_limits<float>::infinity());
    Ref<Appearance> ap = new Appearance();
    ap->setFog(fog);
    Ref<Sprite3D> sprite = new Sprite3D(true, new Image2D(Image2D::RGBA, 4, 2), ap);
    sprite->setCrop(1, 0, -2, 2);
    g->addChild(light);
    g->addChild(sprite);
    const std::string text = dump(g);
    EXPECT_EQ(text.find("nan"), std::string::npos);
    EXPECT_EQ(text.find("inf"), std::string::npos);
    const J doc = parse(text);
    EXPECT_TRUE(find(doc, "Light", 0)["intensity"].isNull());
    const J& f = find(doc, "Fog", 0);
    EXPECT_TRUE(f["nearDistance"].isNull());
    EXPECT_TRUE(f["farDistance"].isNull());
    const J& sp = find(doc, "Sprite3D", 0);
    EXPECT_TRUE(sp["scaled"].asBool());
    EXPECT_EQ(sp["crop"].nums(), (std::vector<double>{1, 0, -2, 2}));
    const J& img = object(doc, sp["image"].asInt());
    EXPECT_EQ(img["format"].asStr(), "RGBA");
    EXPECT_TRUE(img["mutable"].asBool());
}

TEST(ObjectDump, LargeArraysAreTruncated) {
    Ref<VertexArray> big = new VertexArray(100, 2, 1);
    std::vector<std::int8_t> v(200);
    for (int i = 0; i < 200; ++i) v[static_cast<std::size_t>(i)] = static_cast<std::int8_t>(i - 100);
    big->set(0, 100, std::span<const std::int8_t>(v));
    Ref<KeyframeSequence> seq = new KeyframeSequence(70, 1, KeyframeSequence::STEP);
    std::vector<int> lengths(80, 3);
    Ref<TriangleStripArray> strips = new TriangleStripArray(0, lengths);
    Object3D* roots[] = {big.get(), seq.get(), strips.get()};
    const J doc = parse(dumpJson(roots));
    EXPECT_EQ(doc["roots"].nums(), (std::vector<double>{0, 1, 2}));
    const J& a = object(doc, 0);
    EXPECT_EQ(a["vertexCount"].asInt(), 100);
    EXPECT_EQ(a["values"].arr.size(), 64u);
    EXPECT_EQ(a["values"][63].nums(), (std::vector<double>{26, 27}));
    EXPECT_TRUE(a["truncated"].asBool());
    const J& k = object(doc, 1);
    EXPECT_EQ(k["keyframeTimes"].arr.size(), 64u);
    EXPECT_EQ(k["interpolation"].asStr(), "STEP");
    EXPECT_TRUE(k["truncated"].asBool());
    const J& t = object(doc, 2);
    EXPECT_EQ(t["indexCount"].asInt(), 240);
    EXPECT_EQ(t["indices"].arr.size(), 192u);
    EXPECT_TRUE(t["truncated"].asBool());
    EXPECT_EQ(t["stripCount"].asInt(), 80);

    m3gcli::DumpOptions opt;
    opt.maxVertices = 1000;
    const J full = parse(dumpJson(roots, opt));
    EXPECT_FALSE(object(full, 0)["truncated"].asBool());
    EXPECT_EQ(object(full, 0)["values"].arr.size(), 100u);
}

TEST(ObjectDump, DeterministicAndEqualForDuplicates) {
    Scene s;
    const std::string a = dump(s.world);
    EXPECT_EQ(a, dump(s.world));
    // A duplicate has the same structure and values (components shared, nodes copied).
    Ref<Object3D> copy = s.world->duplicate();
    EXPECT_EQ(a, dump(copy));
    // 2-space indentation, one member per line.
    EXPECT_EQ(a.substr(0, 20), "{\n  \"objectCount\": 2");
    EXPECT_NE(a.find("\n  \"objects\": [\n    {\n      \"id\": 0,\n      \"class\": \"World\",\n"), std::string::npos);
    EXPECT_EQ(a.back(), '\n');
}

TEST(ObjectDump, EmptyAndNullRoots) {
    Object3D* roots[] = {nullptr};
    const J doc = parse(dumpJson(roots));
    EXPECT_EQ(doc["objectCount"].asInt(), 0);
    EXPECT_TRUE(doc["objects"].arr.empty());
    EXPECT_EQ(dumpTree(roots), "");
    EXPECT_TRUE(countByClass(roots).empty());
}

TEST(ObjectDump, MorphingMeshWeightsAndTargets) {
    Ref<VertexBuffer> base = new VertexBuffer();
    base->setPositions(new VertexArray(3, 3, 1), 1.0f, {});
    std::vector<Ref<VertexBuffer>> targets = {new VertexBuffer(), new VertexBuffer()};
    const int lengths[] = {3};
    Ref<MorphingMesh> m = new MorphingMesh(base, targets, new TriangleStripArray(0, lengths), nullptr);
    const float w[] = {0.25f, -1.5f};
    m->setWeights(w);
    const J doc = parse(dump(m));
    const J& o = object(doc, 0);
    EXPECT_EQ(o["weights"].nums(), (std::vector<double>{0.25, -1.5}));
    ASSERT_EQ(o["morphTargets"].arr.size(), 2u);
    EXPECT_EQ(object(doc, o["morphTargets"][1].asInt())["class"].asStr(), "VertexBuffer");
    EXPECT_EQ(object(doc, o["morphTargets"][1].asInt())["vertexCount"].asInt(), 0);
}

TEST(ObjectDump, GenericCameraAndZeroDepthRange) {
    Ref<Group> g = new Group();
    Ref<Camera> generic = new Camera();
    Ref<Camera> flat = new Camera();
    flat->setParallel(2.0f, 1.0f, 5.0f, 5.0f);  // near == far: no matrix
    g->addChild(generic);
    g->addChild(flat);
    const J doc = parse(dump(g));
    EXPECT_EQ(object(doc, 1)["projection"].asStr(), "GENERIC");
    EXPECT_TRUE(object(doc, 1)["projectionParams"].isNull());
    EXPECT_EQ(object(doc, 1)["projectionMatrix"].nums()[0], 1.0);
    EXPECT_EQ(object(doc, 2)["projection"].asStr(), "PARALLEL");
    EXPECT_EQ(object(doc, 2)["projectionParams"].nums(), (std::vector<double>{2, 1, 5, 5}));
    EXPECT_TRUE(object(doc, 2)["projectionMatrix"].isNull());
}

TEST(ObjectDump, TreeLines) {
    Scene s;
    Object3D* roots[] = {s.world.get(), s.material.get()};
    const std::string tree = dumpTree(roots);
    std::vector<std::string> lines;
    for (std::size_t p = 0; p < tree.size();) {
        const std::size_t e = tree.find('\n', p);
        lines.push_back(tree.substr(p, e - p));
        p = e + 1;
    }
    ASSERT_EQ(lines.size(), 7u) << tree;
    EXPECT_EQ(lines[0], "World #0 userID=1 camera=#1 background=#22 children=3");
    EXPECT_EQ(lines[1], "  Camera #1 userID=2 PERSPECTIVE fovy=60 aspect=1.5 near=0.25 far=100");
    EXPECT_EQ(lines[2], "  Light #2 userID=3 OMNI color=0x00123456 intensity=2.5");
    EXPECT_EQ(lines[3], "  Group #3 userID=20 children=2 tracks=1");
    EXPECT_EQ(lines[4], "    Mesh #7 userID=10 submeshes=1 vertices=4 triangles=2");
    EXPECT_EQ(lines[5], "    Mesh #21 userID=11 submeshes=1 vertices=4 triangles=2 rendering=off alpha=0.5 scope=6");
    EXPECT_EQ(lines[6].substr(0, 10), "Material #");

    // A skinned mesh shows its skeleton, and the bones are marked.
    Ref<VertexBuffer> vb = new VertexBuffer();
    vb->setPositions(new VertexArray(3, 3, 2), 1.0f, {});
    const int lengths[] = {3};
    Ref<Group> skeleton = new Group();
    Ref<Group> bone = new Group();
    skeleton->addChild(bone);
    Ref<SkinnedMesh> sm = new SkinnedMesh(vb, new TriangleStripArray(0, lengths), nullptr, skeleton);
    sm->addTransform(bone, 1, 0, 3);
    Object3D* r2[] = {sm.get()};
    EXPECT_EQ(dumpTree(r2),
              "SkinnedMesh #0 submeshes=1 vertices=3 triangles=1 bones=1\n"
              "  (skeleton) Group #4 children=1\n"
              "    Group #5 children=0 bone\n");
}
