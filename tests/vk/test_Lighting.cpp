// Golden tests of the fixed-function lighting (JSR-184 1.1, Light and
// Material), vertex colours and shading, and fog (JSR-184 1.1, Fog). Scenes
// are flat quads facing +Z under an identity camera, so every expected level
// follows from the formulas:
// colour = emissive + sum_i att_i spot_i (L_i ambient_m + max(N.L, 0) L_i
// diffuse_m + (N.L > 0 ? max(N.H, 0)^shininess : 0) L_i specular_m), clamped
// to [0, 1] when written (interpolated unclamped, as the reference renders).
#include "SceneKit.h"
#include "VkTestSupport.h"

#include <array>
#include <cmath>

using namespace m3g;
using m3gtest::begin;
using m3gtest::level;
using m3gtest::makeQuad;
using m3gtest::Quad;
using m3gtest::Rgba;
using m3gtest::VkTest;

namespace {

constexpr double kCos60 = 0.5;
const double kCos30 = std::sqrt(3.0) / 2.0;

/// Quadrant quads of the 64x64 viewport: 0 top-left, 1 top-right, 2
/// bottom-left, 3 bottom-right; centre pixels and NDC centres.
Quad quadrant(int q) {
    const float x0 = (q % 2 == 0) ? -1.0f : 0.0f, y0 = (q < 2) ? 0.0f : -1.0f;
    return makeQuad(x0, y0, x0 + 1.0f, y0 + 1.0f);
}
constexpr int kCentreX[4] = {16, 48, 16, 48};
constexpr int kCentreY[4] = {16, 16, 48, 48};
constexpr float kNdcX[4] = {-0.5f, 0.5f, -0.5f, 0.5f};
constexpr float kNdcY[4] = {0.5f, 0.5f, -0.5f, -0.5f};

Ref<Light> light(int mode, std::uint32_t rgb = 0xFFFFFF, float intensity = 1.0f) {
    Ref<Light> l(new Light());
    l->setMode(mode);
    l->setColor(static_cast<int>(rgb));
    l->setIntensity(intensity);
    return l;
}

/// A light's node transform rotated `degrees` about X (the light then
/// shines along (0, sin, -cos): 60 degrees gives N.L = 0.5 on a +Z quad).
Transform rotX(float degrees) {
    Transform t;
    t.postRotate(degrees, 1, 0, 0);
    return t;
}

Ref<Material> material(std::uint32_t ambient, std::uint32_t diffuse, std::uint32_t emissive = 0,
                       std::uint32_t specular = 0, float shininess = 0.0f) {
    Ref<Material> m(new Material());
    m->setColor(Material::AMBIENT, static_cast<int>(ambient));
    m->setColor(Material::DIFFUSE, static_cast<int>(diffuse));
    m->setColor(Material::EMISSIVE, static_cast<int>(emissive));
    m->setColor(Material::SPECULAR, static_cast<int>(specular));
    m->setShininess(shininess);
    return m;
}

Ref<Appearance> appearance(Material* m, PolygonMode* pm = nullptr) {
    Ref<Appearance> a(new Appearance());
    a->setMaterial(m);
    a->setPolygonMode(pm);
    return a;
}

double c8(int v) { return v / 255.0; }

Rgba grey(double v, int alpha = -1) { return {level(v), level(v), level(v), alpha}; }

}  // namespace

TEST_F(VkTest, LightingAmbient) {
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    // Material ambient 0x808080 under an ambient light 0xFF8040: ambient x light, diffuse unused.
    Ref<Light> amb = light(Light::AMBIENT, 0xFF8040);
    g->addLight(amb.get(), nullptr);
    Quad q = makeQuad(-1, -1, 1, 1);
    auto app = appearance(material(0x808080, 0xFFFFFFFF).get());
    g->render(q.vb.get(), q.ib.get(), app.get(), nullptr);
    g->releaseTarget();
    const double a = c8(0x80);
    EXPECT_PIXEL(*img, 32, 32, Rgba{level(a * 1.0), level(a * c8(0x80)), level(a * c8(0x40)), 255});
    expectGolden(*img, "lighting_ambient", 3, 0.0);
}

TEST_F(VkTest, LightingDirectional) {
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    auto app = appearance(material(0x000000, 0xFFCCCCCC).get());  // diffuse 0.8
    // Left: white light along the normal (N.L = 1): 0.8 -> 204.
    Ref<Light> head = light(Light::DIRECTIONAL);
    g->addLight(head.get(), nullptr);
    Quad left = makeQuad(-1, -1, 0, 1);
    g->render(left.vb.get(), left.ib.get(), app.get(), nullptr);
    // Right: an orange light at 60 degrees to the normal: 0.8 cos 60 x colour.
    g->resetLights();
    Ref<Light> slanted = light(Light::DIRECTIONAL, 0xFF8000);
    const Transform t = rotX(60);
    g->addLight(slanted.get(), &t);
    Quad right = makeQuad(0, -1, 1, 1);
    g->render(right.vb.get(), right.ib.get(), app.get(), nullptr);
    g->releaseTarget();
    EXPECT_PIXEL(*img, 16, 32, grey(0.8, 255));
    EXPECT_PIXEL(*img, 48, 32, Rgba{level(0.8 * kCos60), level(0.8 * kCos60 * c8(0x80)), 0, 255});  // ~102, 51, 0
    EXPECT_PIXEL(*img, 40, 5, Rgba{level(0.8 * kCos60), -1, -1, -1});
    expectGolden(*img, "lighting_directional", 3, 0.0);
}

TEST_F(VkTest, LightingOmniAttenuation) {
    // An omni light 0.5 above each quadrant's centre: every corner is at
    // d = sqrt(0.5 + 0.25) with N.L = 0.5 / d, so the quad is uniform.
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    auto app = appearance(material(0x000000, 0xFFFFFFFF).get());
    const float att[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    const double d = std::sqrt(0.75), nDotL = 0.5 / d;
    Ref<Light> omni = light(Light::OMNI);
    for (int q = 0; q < 4; ++q) {
        omni->setAttenuation(att[q][0], att[q][1], att[q][2]);
        g->resetLights();
        const Transform t = m3gtest::translation(kNdcX[q], kNdcY[q], 0.5f);
        g->addLight(omni.get(), &t);
        Quad quad = quadrant(q);
        g->render(quad.vb.get(), quad.ib.get(), app.get(), nullptr);
    }
    g->releaseTarget();
    for (int q = 0; q < 4; ++q) {
        const double a = 1.0 / (att[q][0] + att[q][1] * d + att[q][2] * d * d);
        SCOPED_TRACE(q);
        EXPECT_PIXEL(*img, kCentreX[q], kCentreY[q], grey(a * nDotL, 255));  // 147, 170, 196, 56
    }
    expectGolden(*img, "lighting_omni_attenuation", 3, 0.0);
}

TEST_F(VkTest, LightingSpotCutoffAndExponent) {
    // A spot 0.5 above each quadrant's centre shining down -Z: every corner
    // sees it at cos(theta) = 0.5 / sqrt(0.75) (theta = 54.7 degrees).
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    auto app = appearance(material(0x000000, 0xFFFFFFFF).get());
    const float angle[4] = {60, 50, 60, 90}, exponent[4] = {0, 0, 2, 1};
    const double cosT = 0.5 / std::sqrt(0.75);
    Ref<Light> spot = light(Light::SPOT);
    for (int q = 0; q < 4; ++q) {
        spot->setSpotAngle(angle[q]);
        spot->setSpotExponent(exponent[q]);
        g->resetLights();
        const Transform t = m3gtest::translation(kNdcX[q], kNdcY[q], 0.5f);
        g->addLight(spot.get(), &t);
        Quad quad = quadrant(q);
        g->render(quad.vb.get(), quad.ib.get(), app.get(), nullptr);
    }
    g->releaseTarget();
    for (int q = 0; q < 4; ++q) {
        const double inside = std::acos(cosT) * 180.0 / 3.14159265358979 <= angle[q] ? 1.0 : 0.0;
        SCOPED_TRACE(q);
        // 147 (cone wide enough), 0 (corners outside the 50-degree cone), 49, 85
        EXPECT_PIXEL(*img, kCentreX[q], kCentreY[q], grey(inside * std::pow(cosT, exponent[q]) * cosT, 255));
    }
    expectGolden(*img, "lighting_spot", 3, 0.0);
}

TEST_F(VkTest, LightingMaterialComponents) {
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Light> amb = light(Light::AMBIENT, 0x404040);
    Ref<Light> head = light(Light::DIRECTIONAL);
    Ref<Light> slanted = light(Light::DIRECTIONAL);
    const Transform r60 = rotX(60);
    Ref<Material> m[4] = {
        material(0x000000, 0xFF000000, 0x102030),                 // emissive only
        material(0xFF8000, 0xFF000000),                           // ambient only
        material(0x000000, 0xFFC08040),                           // diffuse only
        material(0x000000, 0xFF000000, 0x000000, 0x808080, 10.0f)  // specular, shininess 10
    };
    for (int q = 0; q < 4; ++q) {
        g->resetLights();
        g->addLight(amb.get(), nullptr);
        if (q < 3) g->addLight(head.get(), nullptr);
        else g->addLight(slanted.get(), &r60);
        auto app = appearance(m[q].get());
        Quad quad = quadrant(q);
        g->render(quad.vb.get(), quad.ib.get(), app.get(), nullptr);
    }
    g->releaseTarget();
    const double la = c8(0x40);
    EXPECT_PIXEL(*img, kCentreX[0], kCentreY[0], Rgba{0x10, 0x20, 0x30, 255});  // emissive only
    EXPECT_PIXEL(*img, kCentreX[1], kCentreY[1], Rgba{level(la), level(la * c8(0x80)), 0, -1});
    EXPECT_PIXEL(*img, kCentreX[2], kCentreY[2], Rgba{0xC0, 0x80, 0x40, 255});
    // Specular: H halfway between L (60 degrees) and the viewer +Z: N.H = cos 30.
    EXPECT_PIXEL(*img, kCentreX[3], kCentreY[3], grey(std::pow(kCos30, 10.0) * c8(0x80), 255));  // ~30
    expectGolden(*img, "lighting_material", 3, 0.0);
}

TEST_F(VkTest, LightingVertexColorTracking) {
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Light> amb = light(Light::AMBIENT, 0x404040);
    Ref<Light> head = light(Light::DIRECTIONAL);
    g->addLight(amb.get(), nullptr);
    g->addLight(head.get(), nullptr);
    // Left: tracking on, vertex colour 0x804080C0 stands for ambient and diffuse (alpha too).
    Ref<Material> tracking = material(0x333333, 0xFFCCCCCC);
    tracking->setVertexColorTrackingEnable(true);
    Quad left = makeQuad(-1, -1, 0, 1);
    m3gtest::setColors(*left.vb, {0x804080C0u, 0x804080C0u, 0x804080C0u, 0x804080C0u});
    g->render(left.vb.get(), left.ib.get(), appearance(tracking.get()).get(), nullptr);
    // Right: the same colours, tracking off: the material's 0.2 ambient and 0.8 diffuse.
    Ref<Material> plain = material(0x333333, 0xFFCCCCCC);
    Quad right = makeQuad(0, -1, 1, 1);
    m3gtest::setColors(*right.vb, {0x804080C0u, 0x804080C0u, 0x804080C0u, 0x804080C0u});
    g->render(right.vb.get(), right.ib.get(), appearance(plain.get()).get(), nullptr);
    g->releaseTarget();
    const double k = 1.0 + c8(0x40);  // ambient light 0.25 + directional 1.0
    EXPECT_PIXEL(*img, 16, 32, Rgba{level(c8(0x40) * k), level(c8(0x80) * k), level(c8(0xC0) * k), 0x80});
    EXPECT_PIXEL(*img, 48, 32, grey(0.2 * c8(0x40) + 0.8, 255));
    expectGolden(*img, "lighting_color_tracking", 3, 0.0);
}

namespace {

/// LightingTwoSided's four quadrants: a directional light behind the quads
/// (shining along +Z, L = -Z) or in front; winding CW makes the
/// counter-clockwise quads back faces. Returns the expected grey levels.
std::array<double, 4> renderTwoSidedCases(Graphics3D* g, int shading) {
    Ref<Light> behind = light(Light::DIRECTIONAL);
    Ref<Light> front = light(Light::DIRECTIONAL);
    const Transform flip = rotX(180);
    auto mat = material(0x000000, 0xFFCCCCCC);
    struct Case {
        int winding;
        bool twoSided;
        bool lightBehind;
        double expected;
    } cases[4] = {
        {PolygonMode::WINDING_CW, false, true, 0.0},    // back face, one-sided: front colour (N.L = -1)
        {PolygonMode::WINDING_CW, true, true, 0.8},     // back face lit with -N
        {PolygonMode::WINDING_CCW, true, true, 0.0},    // front face keeps +N
        {PolygonMode::WINDING_CW, true, false, 0.0},    // back face, light in front: -N faces away
    };
    std::array<double, 4> expected{};
    for (int q = 0; q < 4; ++q) {
        Ref<PolygonMode> pm(new PolygonMode());
        pm->setCulling(PolygonMode::CULL_NONE);
        pm->setShading(shading);
        pm->setWinding(cases[q].winding);
        pm->setTwoSidedLightingEnable(cases[q].twoSided);
        g->resetLights();
        if (cases[q].lightBehind) g->addLight(behind.get(), &flip);
        else g->addLight(front.get(), nullptr);
        Quad quad = quadrant(q);
        g->render(quad.vb.get(), quad.ib.get(), appearance(mat.get(), pm.get()).get(), nullptr);
        expected[static_cast<std::size_t>(q)] = cases[q].expected;
    }
    return expected;
}

}  // namespace

TEST_F(VkTest, LightingTwoSided) {
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    const auto expected = renderTwoSidedCases(g, PolygonMode::SHADE_SMOOTH);
    g->releaseTarget();
    for (int q = 0; q < 4; ++q) {
        SCOPED_TRACE(q);
        EXPECT_PIXEL(*img, kCentreX[q], kCentreY[q], grey(expected[static_cast<std::size_t>(q)], 255));
    }
    expectGolden(*img, "lighting_two_sided", 3, 0.0);
}

TEST_F(VkTest, LightingTwoSidedFlat) {
    // The same four cases with SHADE_FLAT: the colours come from the flat
    // outputs (m3g.vert writes only the outputs m3g.frag reads: flat front
    // and back here), with the same hand values since the normals are
    // uniform; a second pixel per quad, off the centre.
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    const auto expected = renderTwoSidedCases(g, PolygonMode::SHADE_FLAT);
    g->releaseTarget();
    for (int q = 0; q < 4; ++q) {
        SCOPED_TRACE(q);
        EXPECT_PIXEL(*img, kCentreX[q], kCentreY[q], grey(expected[static_cast<std::size_t>(q)], 255));
        EXPECT_PIXEL(*img, kCentreX[q] - 12, kCentreY[q] + 12, grey(expected[static_cast<std::size_t>(q)], 255));
    }
}

TEST_F(VkTest, LightingScopeInWorld) {
    // Light scope against mesh scope (not the camera's): white light scope 2,
    // red light scope 4; meshes with scope 1, 2 and 6. A third light (scope
    // 1) is under a group with rendering disabled, so it is not collected.
    auto img = target(64, 64);
    Ref<World> world(new World());
    Ref<Camera> cam(new Camera());
    world->addChild(cam.get());
    world->setActiveCamera(cam.get());
    Ref<Light> white = light(Light::DIRECTIONAL, 0x808080);
    white->setScope(2);
    Ref<Light> red = light(Light::DIRECTIONAL, 0x800000);
    red->setScope(4);
    world->addChild(white.get());
    world->addChild(red.get());
    Ref<Group> disabled(new Group());
    disabled->setRenderingEnable(false);
    Ref<Light> hidden = light(Light::DIRECTIONAL);
    hidden->setScope(1);
    disabled->addChild(hidden.get());
    world->addChild(disabled.get());
    auto app = appearance(material(0x000000, 0xFFCCCCCC).get());
    const int scopes[3] = {1, 2, 6};
    std::vector<Ref<Mesh>> meshes;
    for (int i = 0; i < 3; ++i) {
        Quad q = m3gtest::pixelQuad(i * 21, 0, i * 21 + 21, 64, 64);
        Ref<Mesh> mesh(new Mesh(q.vb.get(), q.ib.get(), app.get()));
        mesh->setScope(scopes[i]);
        world->addChild(mesh.get());
        meshes.push_back(mesh);
    }
    Graphics3D* g = Graphics3D::getInstance();
    g->bindTarget(img.get());
    g->render(world.get());
    g->releaseTarget();
    const double w = 0.8 * c8(0x80);
    EXPECT_PIXEL(*img, 10, 32, Rgba{0, 0, 0, 255});
    EXPECT_PIXEL(*img, 31, 32, grey(w, 255));
    EXPECT_PIXEL(*img, 52, 32, Rgba{level(2 * w), level(w), level(w), 255});
    expectGolden(*img, "lighting_scope_world", 3, 0.0);
}

TEST_F(VkTest, LightingEightLights) {
    // Eight ambient lights of 4, 8, ..., 32 levels sum to 144; a ninth
    // (80 levels) is beyond maxLights = 8 and, as in Nokia's engine, the
    // first eight in order are used.
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    std::vector<Ref<Light>> lights;
    for (int i = 0; i < 9; ++i) {
        const std::uint32_t v = i < 8 ? 4u * (i + 1) : 0x50u;
        lights.push_back(light(Light::AMBIENT, (v << 16) | (v << 8) | v));
    }
    auto app = appearance(material(0xFFFFFF, 0xFF000000).get());
    for (int i = 0; i < 8; ++i) g->addLight(lights[i].get(), nullptr);
    Quad left = makeQuad(-1, -1, 0, 1);
    g->render(left.vb.get(), left.ib.get(), app.get(), nullptr);
    g->addLight(lights[8].get(), nullptr);
    Quad right = makeQuad(0, -1, 1, 1);
    g->render(right.vb.get(), right.ib.get(), app.get(), nullptr);
    g->releaseTarget();
    EXPECT_PIXEL(*img, 16, 32, Rgba{144, 144, 144, -1});
    EXPECT_PIXEL(*img, 48, 32, Rgba{144, 144, 144, -1});
    expectGolden(*img, "lighting_eight_lights", 3, 0.0);
}

TEST_F(VkTest, LightingMixedModesInOneDraw) {
    // Four lights of four modes in one draw, in two orders (each light's
    // mode is compiled into the pipeline by its index, PipelineKey): a red
    // spot (intensity 0.5) and a green omni 0.5 above the quadrant's centre,
    // a blue ambient light (0.25) and a red directional one at 60 degrees
    // (intensity 0.5). Every corner sees the point lights at
    // cos = 0.5 / sqrt(0.75) (inside the 60-degree cone), so
    // red = 0.5 cos + 0.5 cos 60, green = cos, blue = 0.25.
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    auto app = appearance(material(0xFFFFFF, 0xFFFFFFFF).get());
    Ref<Light> spot = light(Light::SPOT, 0xFF0000, 0.5f);
    spot->setSpotAngle(60);
    Ref<Light> omni = light(Light::OMNI, 0x00FF00);
    Ref<Light> ambient = light(Light::AMBIENT, 0x0000FF, 0.25f);
    Ref<Light> directional = light(Light::DIRECTIONAL, 0xFF0000, 0.5f);
    const Transform slant = rotX(60);
    for (int q : {0, 3}) {
        g->resetLights();
        const Transform above = m3gtest::translation(kNdcX[q], kNdcY[q], 0.5f);
        if (q == 0) {
            g->addLight(spot.get(), &above);
            g->addLight(ambient.get(), nullptr);
            g->addLight(omni.get(), &above);
            g->addLight(directional.get(), &slant);
        } else {
            g->addLight(directional.get(), &slant);
            g->addLight(omni.get(), &above);
            g->addLight(ambient.get(), nullptr);
            g->addLight(spot.get(), &above);
        }
        Quad quad = quadrant(q);
        g->render(quad.vb.get(), quad.ib.get(), app.get(), nullptr);
    }
    g->releaseTarget();
    const double cosT = 0.5 / std::sqrt(0.75);
    const Rgba want{level(0.5 * cosT + 0.5 * kCos60), level(cosT), level(0.25), 255};  // 137, 147, 64
    EXPECT_PIXEL(*img, kCentreX[0], kCentreY[0], want);
    EXPECT_PIXEL(*img, kCentreX[3], kCentreY[3], want);
    EXPECT_PIXEL(*img, kCentreX[1], kCentreY[1], Rgba{0, 0, 0, -1});  // not drawn: the clear
}

TEST_F(VkTest, LightingRenormalisedNormals) {
    // Normals are renormalised after the inverse-transpose transform: short
    // normals under a uniform scale still give N.L = 1; a tilted normal
    // (0, 1, 1) under scale (1, 2, 1) becomes (0, 0.5, 1), i.e. N.L = 2/sqrt(5).
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Light> head = light(Light::DIRECTIONAL);
    g->addLight(head.get(), nullptr);
    auto app = appearance(material(0x000000, 0xFFCCCCCC).get());
    Quad shortNormals = makeQuad(-1, -1, 1, 1, 0.0f, {0, 0, 64});
    Transform half;
    half.postTranslate(-0.5f, 0, 0);
    half.postScale(0.5f, 0.5f, 0.5f);
    g->render(shortNormals.vb.get(), shortNormals.ib.get(), app.get(), &half);
    Quad tilted = makeQuad(-0.5f, -0.25f, 0.5f, 0.25f, 0.0f, {0, 90, 90});
    Transform stretch;
    stretch.postTranslate(0.5f, 0, 0);
    stretch.postScale(1, 2, 1);
    g->render(tilted.vb.get(), tilted.ib.get(), app.get(), &stretch);
    g->releaseTarget();
    EXPECT_PIXEL(*img, 16, 32, grey(0.8, 255));
    EXPECT_PIXEL(*img, 48, 32, grey(0.8 * 2.0 / std::sqrt(5.0), 255));  // 182
    EXPECT_PIXEL(*img, 48, 8, Rgba{0, 0, 0, 0});                        // outside the stretched quad
    expectGolden(*img, "lighting_renormalised_normals", 3, 0.0);
}

TEST_F(VkTest, LightingIntensityAboveOneAndNegative) {
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    struct Case {
        float directional;  // intensity of a white directional light along the normal
        bool ambient;       // plus a white ambient light of intensity 1
        std::uint32_t diffuse;
        double expected;
    } cases[4] = {
        {2.0f, false, 0xFF666666, 2.0 * 0.4},   // 204
        {3.0f, false, 0xFFCCCCCC, 1.0},         // clamped
        {-0.5f, true, 0xFFCCCCCC, 0.8 - 0.4},   // ambient 0.8 minus 0.4
        {-1.0f, false, 0xFFCCCCCC, 0.0},        // clamped at 0
    };
    Ref<Light> amb = light(Light::AMBIENT);
    for (int q = 0; q < 4; ++q) {
        Ref<Light> dir = light(Light::DIRECTIONAL, 0xFFFFFF, cases[q].directional);
        g->resetLights();
        g->addLight(dir.get(), nullptr);
        if (cases[q].ambient) g->addLight(amb.get(), nullptr);
        auto app = appearance(material(0xCCCCCC, cases[q].diffuse).get());
        Quad quad = quadrant(q);
        g->render(quad.vb.get(), quad.ib.get(), app.get(), nullptr);
    }
    g->releaseTarget();
    for (int q = 0; q < 4; ++q) {
        SCOPED_TRACE(q);
        EXPECT_PIXEL(*img, kCentreX[q], kCentreY[q], grey(cases[q].expected, 255));
    }
    expectGolden(*img, "lighting_intensity", 3, 0.0);
}

TEST_F(VkTest, UnlitVertexColorsAndDefaultColor) {
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Appearance> app(new Appearance());  // no Material: lighting off
    Quad left = makeQuad(-1, -1, 0, 1);
    m3gtest::setColors(*left.vb, {0x80FF8040u, 0x80FF8040u, 0x80FF8040u, 0x80FF8040u});
    g->render(left.vb.get(), left.ib.get(), app.get(), nullptr);
    Quad right = makeQuad(0, -1, 1, 1);
    right.vb->setDefaultColor(static_cast<int>(0xC0204080u));
    g->render(right.vb.get(), right.ib.get(), app.get(), nullptr);
    g->releaseTarget();
    EXPECT_PIXEL_TOL(*img, 16, 32, 0, Rgba{0xFF, 0x80, 0x40, 0x80});
    EXPECT_PIXEL_TOL(*img, 48, 32, 0, Rgba{0x20, 0x40, 0x80, 0xC0});
    expectGolden(*img, "unlit_colors", 3, 0.0);
}

TEST_F(VkTest, FlatShadingUsesLastVertexSmoothInterpolates) {
    // Vertices (strip order) red, green, blue, white. Smooth on the left;
    // flat on the right: triangle (v0 v1 v2) takes v2 (blue), triangle
    // (v1 v2 v3) takes v3 (white), as OpenGL ES's provoking vertex.
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    const std::initializer_list<std::uint32_t> colors = {0xFFFF0000u, 0xFF00FF00u, 0xFF0000FFu, 0xFFFFFFFFu};
    Ref<Appearance> smooth(new Appearance());
    Quad left = makeQuad(-1, -1, 0, 1);
    m3gtest::setColors(*left.vb, colors);
    g->render(left.vb.get(), left.ib.get(), smooth.get(), nullptr);
    Ref<PolygonMode> pm(new PolygonMode());
    pm->setShading(PolygonMode::SHADE_FLAT);
    Ref<Appearance> flat(new Appearance());
    flat->setPolygonMode(pm.get());
    Quad right = makeQuad(0, -1, 1, 1);
    m3gtest::setColors(*right.vb, colors);
    g->render(right.vb.get(), right.ib.get(), flat.get(), nullptr);
    g->releaseTarget();
    // Smooth, in triangle 0 (BL red, BR green, TL blue) at pixel (8, 40):
    // u = 8.5 / 32 across, v = (64 - 40.5) / 64 up.
    {
        const double u = 8.5 / 32, v = 23.5 / 64;
        EXPECT_PIXEL(*img, 8, 40, Rgba{level(1 - u - v), level(u), level(v), 255});
    }
    // Smooth, in triangle 1 (BR green, TL blue, TR white) at pixel (24, 8).
    {
        const double u = 24.5 / 32, v = 55.5 / 64, w = u + v - 1;
        EXPECT_PIXEL(*img, 24, 8, Rgba{level(w), level(1 - v + w), level(1 - u + w), 255});
    }
    EXPECT_PIXEL_TOL(*img, 34, 61, 0, Rgba{0, 0, 255, 255});
    EXPECT_PIXEL_TOL(*img, 40, 40, 0, Rgba{0, 0, 255, 255});
    EXPECT_PIXEL_TOL(*img, 61, 2, 0, Rgba{255, 255, 255, 255});
    EXPECT_PIXEL_TOL(*img, 56, 24, 0, Rgba{255, 255, 255, 255});
    expectGolden(*img, "shading_flat_smooth", 3, 0.002);
}

TEST_F(VkTest, FogLinearAndExponential) {
    // Parallel camera (2 units tall, near 0.1, far 100); red quads at eye
    // depth 10 (left) and 20 (right); blue fog. Top: LINEAR 5..25, f =
    // (25 - z) / 20; bottom: EXPONENTIAL density 0.05, f = exp(-0.05 z).
    auto img = target(64, 64);
    Ref<Camera> cam = m3gtest::parallelCamera();
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Fog> linear(new Fog());
    linear->setMode(Fog::LINEAR);
    linear->setLinear(5.0f, 25.0f);
    linear->setColor(0x0000FF);
    Ref<Fog> exponential(new Fog());
    exponential->setMode(Fog::EXPONENTIAL);
    exponential->setDensity(0.05f);
    exponential->setColor(0x0000FF);
    const float depth[4] = {10, 20, 10, 20};
    double f[4];
    for (int q = 0; q < 4; ++q) {
        const bool lin = q < 2;
        f[q] = lin ? (25.0 - depth[q]) / 20.0 : std::exp(-0.05 * depth[q]);
        Ref<Appearance> app(new Appearance());
        app->setFog(lin ? linear.get() : exponential.get());
        const float x0 = (q % 2 == 0) ? -1.0f : 0.0f, y0 = lin ? 0.0f : -1.0f;
        Quad quad = makeQuad(x0, y0, x0 + 1, y0 + 1, -depth[q]);
        quad.vb->setDefaultColor(static_cast<int>(0xFFFF0000u));
        g->render(quad.vb.get(), quad.ib.get(), app.get(), nullptr);
    }
    g->releaseTarget();
    for (int q = 0; q < 4; ++q) {
        SCOPED_TRACE(q);
        EXPECT_PIXEL(*img, kCentreX[q], kCentreY[q], Rgba{level(f[q]), 0, level(1 - f[q]), 255});
    }
    expectGolden(*img, "fog_linear_exponential", 3, 0.0);
}

namespace {

/// Pixel (x, y) of world point p seen by `camera` placed by `cameraToWorld`
/// in a size x size viewport.
std::array<int, 2> projectToPixel(const Camera& camera, Transform cameraToWorld, float x, float y, float z, int size) {
    Transform projection;
    camera.getProjection(&projection);
    cameraToWorld.invert();
    const Transform m = projection * cameraToWorld;
    float v[4] = {x, y, z, 1};
    m.transform(v);
    const double nx = v[0] / v[3], ny = v[1] / v[3];
    return {static_cast<int>(std::floor((nx + 1) / 2 * size)), static_cast<int>(std::floor((1 - ny) / 2 * size))};
}

}  // namespace

TEST_F(VkTest, LightingStaysInWorldUnderMovingCamera) {
    // render(World) with a perspective camera moved and turned 15 degrees
    // about Y: lights are placed in the World, so a directional light along
    // -Z still gives N.L = 1 on the left quad (scope 1) and an omni light
    // 0.5 above the right quad's centre still gives N.L = 0.5 / sqrt(0.75)
    // at every corner (scope 2). Lights taken in camera space would differ.
    auto img = target(64, 64);
    Ref<World> world(new World());
    Ref<Camera> cam(new Camera());
    cam->setPerspective(60, 1, 0.5f, 50);
    cam->setTranslation(0.5f, 0.25f, 0.5f);
    cam->setOrientation(15, 0, 1, 0);
    world->addChild(cam.get());
    world->setActiveCamera(cam.get());
    Ref<Light> dir = light(Light::DIRECTIONAL);
    dir->setScope(1);
    Ref<Light> omni = light(Light::OMNI);
    omni->setScope(2);
    omni->setTranslation(0.625f, 0, -3.5f);
    world->addChild(dir.get());
    world->addChild(omni.get());
    auto app = appearance(material(0x000000, 0xFFCCCCCC).get());
    Quad left = makeQuad(-1.125f, -0.5f, -0.125f, 0.5f, -4.0f), right = makeQuad(0.125f, -0.5f, 1.125f, 0.5f, -4.0f);
    Ref<Mesh> leftMesh(new Mesh(left.vb.get(), left.ib.get(), app.get()));
    leftMesh->setScope(1);
    Ref<Mesh> rightMesh(new Mesh(right.vb.get(), right.ib.get(), app.get()));
    rightMesh->setScope(2);
    world->addChild(leftMesh.get());
    world->addChild(rightMesh.get());
    Graphics3D* g = Graphics3D::getInstance();
    g->bindTarget(img.get());
    g->render(world.get());
    g->releaseTarget();
    Transform camToWorld;
    cam->getCompositeTransform(&camToWorld);
    const auto l = projectToPixel(*cam, camToWorld, -0.625f, 0, -4, 64);
    const auto r = projectToPixel(*cam, camToWorld, 0.625f, 0, -4, 64);
    EXPECT_PIXEL(*img, l[0], l[1], grey(0.8, 255));
    EXPECT_PIXEL(*img, r[0], r[1], grey(0.8 * 0.5 / std::sqrt(0.75), 255));
    expectGolden(*img, "lighting_moving_camera", 3, 0.01);
}

TEST_F(VkTest, FlatShadingLitUsesLastVertex) {
    // Lit quads, light along the normal, diffuse 0.8; vertex 2 (top-left) has
    // a normal tilted 45 degrees (0.8 cos 45 = 144), the others face +Z (204).
    // Smooth on the left; flat on the right: triangle (v0 v1 v2) takes
    // vertex 2's colour, triangle (v1 v2 v3) vertex 3's.
    auto img = target(64, 64);
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img.get(), cam.get());
    g->clear(nullptr);
    Ref<Light> head = light(Light::DIRECTIONAL);
    g->addLight(head.get(), nullptr);
    Ref<VertexArray> normals(new VertexArray(4, 3, 1));
    const std::int8_t n[] = {0, 0, 127, 0, 0, 127, 0, 90, 90, 0, 0, 127};
    normals->set(0, 4, std::span<const std::int8_t>(n));
    Ref<Material> mat = material(0x000000, 0xFFCCCCCC);
    Quad left = makeQuad(-1, -1, 0, 1), right = makeQuad(0, -1, 1, 1);
    left.vb->setNormals(normals.get());
    right.vb->setNormals(normals.get());
    g->render(left.vb.get(), left.ib.get(), appearance(mat.get()).get(), nullptr);
    Ref<PolygonMode> pm(new PolygonMode());
    pm->setShading(PolygonMode::SHADE_FLAT);
    g->render(right.vb.get(), right.ib.get(), appearance(mat.get(), pm.get()).get(), nullptr);
    g->releaseTarget();
    const double tilted = 0.8 * std::sqrt(0.5);
    {
        const double v = 23.5 / 64;  // weight of vertex 2 at pixel (8, 40)
        EXPECT_PIXEL(*img, 8, 40, grey(0.8 * (1 - v) + tilted * v, 255));
    }
    EXPECT_PIXEL(*img, 40, 40, grey(tilted, 255));
    EXPECT_PIXEL(*img, 34, 61, grey(tilted, 255));
    EXPECT_PIXEL(*img, 56, 24, grey(0.8, 255));
    EXPECT_PIXEL(*img, 61, 2, grey(0.8, 255));
    expectGolden(*img, "shading_flat_lit", 3, 0.002);
}

namespace {

/// Draws the lit-colour range scene into a 64x64 target: top half a
/// quad textured with a 0x808080 RGB texel (MODULATE), bottom half an
/// untextured quad tracking vertex colours white (left edge) to black (right
/// edge); both under a white Material, a directional light along the normal
/// (N.L = 1) and an ambient light of intensity 0.5.
void drawLitRangeScene(Image2D* img) {
    Ref<Camera> cam(new Camera());
    Graphics3D* g = begin(img, cam.get());
    g->clear(nullptr);
    Ref<Light> dir = light(Light::DIRECTIONAL);
    Ref<Light> amb = light(Light::AMBIENT, 0xFFFFFF, 0.5f);
    g->addLight(dir.get(), nullptr);
    g->addLight(amb.get(), nullptr);
    Ref<Texture2D> tex(new Texture2D(m3gtest::solidImage(Image2D::RGB, 2, 2, {0x80, 0x80, 0x80}).get()));
    tex->setBlending(Texture2D::FUNC_MODULATE);
    auto texturedApp = appearance(material(0xFFFFFF, 0xFFFFFFFF).get());
    texturedApp->setTexture(0, tex.get());
    Quad top = makeQuad(-1, 0, 1, 1);
    g->render(top.vb.get(), top.ib.get(), texturedApp.get(), nullptr);
    Ref<Material> tracking = material(0xFFFFFF, 0xFFFFFFFF);
    tracking->setVertexColorTrackingEnable(true);
    auto trackingApp = appearance(tracking.get());
    Quad bottom = makeQuad(-1, -1, 1, 0);  // vertices BL, BR, TL, TR
    m3gtest::setColors(*bottom.vb, {0xFFFFFFFFu, 0xFF000000u, 0xFFFFFFFFu, 0xFF000000u});
    g->render(bottom.vb.get(), bottom.ib.get(), trackingApp.get(), nullptr);
    g->releaseTarget();
}

}  // namespace

TEST_F(VkTest, LitColourAboveOneIsInterpolatedUnclampedByDefault) {
    // As the reference renders (Nokia's engine on Mesa's OpenGL ES 1.1, which
    // clamps vertex colours only in desktop compatibility contexts): the lit
    // colour is 0.5 (ambient) + 1 (N.L) = 1.5 times the material colour and
    // stays 1.5 until the fragment is written.
    //   Top: 1.5 x 128/255 = 0.7529 -> 192 (clamped per vertex: 128).
    //   Bottom, pixel column x (centre at (x + 0.5) / 64 from the left edge):
    //   1.5 (1 - (x + 0.5) / 64): x = 16 -> 1.113 -> 255, x = 32 -> 0.7383
    //   -> 188, x = 48 -> 0.3633 -> 93. Clamped per vertex the left edge is 1:
    //   0.7422 -> 189, 0.4922 -> 126, 0.2422 -> 62.
    ASSERT_FALSE(vk::litColorClamping()) << "default is the reference behaviour (M3G_CLAMP_LIGHTING unset)";
    auto img = target(64, 64);
    drawLitRangeScene(img.get());
    EXPECT_PIXEL(*img, 32, 16, grey(1.5 * c8(0x80), 255));
    EXPECT_PIXEL(*img, 16, 48, grey(1.5 * (1.0 - 16.5 / 64.0), 255));
    EXPECT_PIXEL(*img, 32, 48, grey(1.5 * (1.0 - 32.5 / 64.0), 255));
    EXPECT_PIXEL(*img, 48, 48, grey(1.5 * (1.0 - 48.5 / 64.0), 255));
    expectGolden(*img, "lighting_lit_colour_unclamped", 3, 0.0);

    // The same scene with the GL ES 1.1 specification's per-vertex clamp.
    vk::setLitColorClamping(true);
    auto clamped = target(64, 64);
    drawLitRangeScene(clamped.get());
    vk::setLitColorClamping(false);
    EXPECT_PIXEL(*clamped, 32, 16, grey(c8(0x80), 255));
    EXPECT_PIXEL(*clamped, 16, 48, grey(1.0 - 16.5 / 64.0, 255));
    EXPECT_PIXEL(*clamped, 32, 48, grey(1.0 - 32.5 / 64.0, 255));
    EXPECT_PIXEL(*clamped, 48, 48, grey(1.0 - 48.5 / 64.0, 255));
}
