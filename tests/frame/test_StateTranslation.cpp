// scene/frame/StateTranslation: each piece of M3G state (JSR-184 1.1:
// CompositingMode, PolygonMode, Material, Light, Fog, Texture2D, Background,
// Sprite3D, Graphics3D viewport) to the pipeline key bits, rasterizer state
// and uniforms a back end records, without a device. Expected values follow
// from the specification and the layouts in frame/DrawList.h,
// DrawUniforms.h and PipelineKey.h, worked out by hand in the comments.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include <m3g/frame/UniformHelpers.h>

#include "FrameTestKit.h"
#include "RenderQueue.h"
#include "StateTranslation.h"

using namespace m3g;
using namespace m3g::frame;
using m3g::detail::RenderQueue;
using m3g::detail::VertexLayout;
using frametest::quad;

namespace {

constexpr float kEps = 1e-6f;

float c8(int v) { return static_cast<float>(v) / 255.0f; }

/// What translateSubmesh produced for one immediate-mode submesh.
struct Translated {
    DrawUniforms u{};
    Draw draw;
};

struct LightAt {
    Light* light;
    Transform lightToEye;
};

/// The layout of a plain VertexBuffer (what FrameBuilder gives one).
VertexLayout plainLayout(const VertexBuffer& vb) {
    VertexLayout l;
    l.present = {true, vb.normals() != nullptr, vb.colors() != nullptr, vb.texCoords(0) != nullptr,
                 vb.texCoords(1) != nullptr};
    return l;
}

/// One submesh through RenderQueue (identity camera, every light in scope)
/// and translateSubmesh.
Translated translate(VertexBuffer* vb, IndexBuffer* ib, Appearance* app, const Transform& modelView = Transform(),
                     const DrawOptions& options = DrawOptions(), std::vector<LightAt> lights = {}, int units = 2,
                     const VertexLayout* layout = nullptr, float alphaFactor = 1.0f) {
    Ref<Camera> cam(new Camera());
    RenderQueue q;
    q.reset(*cam, 8);
    for (const LightAt& l : lights) q.addLight(*l.light, l.lightToEye);
    q.addSubmesh(vb, ib, app, modelView, -1, nullptr, 0, alphaFactor);
    float projection[16];
    m3g::detail::toColumns(m3g::detail::vulkanProjection(q.projection), projection);
    Translated t;
    const VertexLayout l = layout ? *layout : plainLayout(*vb);
    m3g::detail::translateSubmesh(q, q.items[0], l, projection, options, units, t.u, t.draw);
    return t;
}

Translated translate(Appearance* app, const DrawOptions& options = DrawOptions(), std::vector<LightAt> lights = {}) {
    frametest::Quad q = quad();
    return translate(q.vb.get(), q.ib.get(), app, Transform(), options, std::move(lights));
}

Ref<Appearance> withCompositing(CompositingMode* cm) {
    Ref<Appearance> a(new Appearance());
    a->setCompositingMode(cm);
    return a;
}

Ref<Appearance> withPolygonMode(PolygonMode* pm, Material* m = nullptr) {
    Ref<Appearance> a(new Appearance());
    a->setPolygonMode(pm);
    a->setMaterial(m);
    return a;
}

Ref<Appearance> lit(Material* m = nullptr) {
    Ref<Appearance> a(new Appearance());
    a->setMaterial(m ? m : Ref<Material>(new Material()).get());
    return a;
}

/// A quad with texture coordinates on the units of `units` (2 components,
/// scale 0.5, bias (0.25, 0.125)).
frametest::Quad texturedQuad(std::initializer_list<int> units) {
    frametest::Quad q = quad();
    const float bias[3] = {0.25f, 0.125f, 0.0f};
    for (int u : units) q.vb->setTexCoords(u, frametest::shorts(2, {0, 0, 1, 0, 0, 1, 1, 1}).get(), 0.5f, bias);
    return q;
}

Ref<Texture2D> texture(int format = Image2D::RGB, int w = 4, int h = 4) {
    return Ref<Texture2D>(new Texture2D(frametest::image(format, w, h).get()));
}

void expectRgba(const float* got, float r, float g, float b, float a) {
    EXPECT_NEAR(got[0], r, kEps);
    EXPECT_NEAR(got[1], g, kEps);
    EXPECT_NEAR(got[2], b, kEps);
    EXPECT_NEAR(got[3], a, kEps);
}

}  // namespace

// ---- Small conversions ----

TEST(StateTranslation, ArgbToFloatsKeepsAlphaOnlyWhenAsked) {
    float c[4];
    m3g::detail::argbToFloats(0x80FF4000u, c, true);
    expectRgba(c, 1.0f, c8(0x40), 0.0f, c8(0x80));
    m3g::detail::argbToFloats(0x80FF4000u, c, false);
    expectRgba(c, 1.0f, c8(0x40), 0.0f, 1.0f);
}

TEST(StateTranslation, VulkanProjectionFlipsYAndHalvesDepth) {
    // Vulkan clip space: y down, z in [0, w]: (x, y, z, w) -> (x, -y, (z + w) / 2, w).
    const Transform v = m3g::detail::vulkanProjection(Transform());
    float p[4] = {0.25f, 0.5f, -1.0f, 1.0f};
    v.transform(p);
    EXPECT_FLOAT_EQ(p[0], 0.25f);
    EXPECT_FLOAT_EQ(p[1], -0.5f);
    EXPECT_FLOAT_EQ(p[2], 0.0f);  // the near plane at depth 0
    EXPECT_FLOAT_EQ(p[3], 1.0f);
    float q[4] = {0, 0, 1, 1};
    v.transform(q);
    EXPECT_FLOAT_EQ(q[2], 1.0f);  // the far plane at depth 1
}

TEST(StateTranslation, ImageFormatChannels) {
    // JSR-184 1.1, Texture2D: ALPHA has no colour; ALPHA, LUMINANCE_ALPHA and RGBA have alpha.
    EXPECT_FALSE(m3g::detail::formatHasColor(Image2D::ALPHA));
    EXPECT_TRUE(m3g::detail::formatHasAlpha(Image2D::ALPHA));
    EXPECT_TRUE(m3g::detail::formatHasColor(Image2D::LUMINANCE));
    EXPECT_FALSE(m3g::detail::formatHasAlpha(Image2D::LUMINANCE));
    EXPECT_TRUE(m3g::detail::formatHasColor(Image2D::LUMINANCE_ALPHA));
    EXPECT_TRUE(m3g::detail::formatHasAlpha(Image2D::LUMINANCE_ALPHA));
    EXPECT_TRUE(m3g::detail::formatHasColor(Image2D::RGB));
    EXPECT_FALSE(m3g::detail::formatHasAlpha(Image2D::RGB));
    EXPECT_TRUE(m3g::detail::formatHasColor(Image2D::RGBA));
    EXPECT_TRUE(m3g::detail::formatHasAlpha(Image2D::RGBA));
}

TEST(StateTranslation, SamplerKeyBits) {
    // bit 0 S clamps, bit 1 T clamps, bit 2 linear image filter, bits 3-4 level filter.
    using T = Texture2D;
    EXPECT_EQ(m3g::detail::samplerKey(T::WRAP_REPEAT, T::WRAP_REPEAT, T::FILTER_NEAREST, T::FILTER_BASE_LEVEL), 0u);
    EXPECT_EQ(m3g::detail::samplerKey(T::WRAP_CLAMP, T::WRAP_REPEAT, T::FILTER_NEAREST, T::FILTER_BASE_LEVEL), 1u);
    EXPECT_EQ(m3g::detail::samplerKey(T::WRAP_REPEAT, T::WRAP_CLAMP, T::FILTER_NEAREST, T::FILTER_BASE_LEVEL), 2u);
    EXPECT_EQ(m3g::detail::samplerKey(T::WRAP_REPEAT, T::WRAP_REPEAT, T::FILTER_LINEAR, T::FILTER_BASE_LEVEL), 4u);
    EXPECT_EQ(m3g::detail::samplerKey(T::WRAP_REPEAT, T::WRAP_REPEAT, T::FILTER_NEAREST, T::FILTER_NEAREST), 8u);
    EXPECT_EQ(m3g::detail::samplerKey(T::WRAP_REPEAT, T::WRAP_REPEAT, T::FILTER_NEAREST, T::FILTER_LINEAR), 16u);
    EXPECT_EQ(m3g::detail::samplerKey(T::WRAP_CLAMP, T::WRAP_CLAMP, T::FILTER_LINEAR, T::FILTER_LINEAR), 23u);
    EXPECT_EQ(m3g::detail::nearestClampSampler(), 3u);
}

// ---- CompositingMode ----

TEST(StateTranslation, EveryBlendingModeToKeyBlend) {
    const std::pair<int, int> modes[] = {{CompositingMode::REPLACE, 0},
                                         {CompositingMode::ALPHA, 1},
                                         {CompositingMode::ALPHA_ADD, 2},
                                         {CompositingMode::MODULATE, 3},
                                         {CompositingMode::MODULATE_X2, 4}};
    for (auto [mode, index] : modes) {
        Ref<CompositingMode> cm(new CompositingMode());
        cm->setBlending(mode);
        EXPECT_EQ(translate(withCompositing(cm.get()).get()).draw.pipeline.blend, index) << "mode " << mode;
    }
    // No CompositingMode: REPLACE (JSR-184 1.1, Appearance defaults).
    EXPECT_EQ(translate(Ref<Appearance>(new Appearance()).get()).draw.pipeline.blend, 0);
}

TEST(StateTranslation, ColourAndAlphaWriteToWriteMask) {
    struct Case {
        bool color, alpha;
        int mask;
    };
    for (const Case c : {Case{true, true, 15}, Case{false, true, WRITE_A}, Case{true, false, 7}, Case{false, false, 0}}) {
        Ref<CompositingMode> cm(new CompositingMode());
        cm->setColorWriteEnable(c.color);
        cm->setAlphaWriteEnable(c.alpha);
        EXPECT_EQ(translate(withCompositing(cm.get()).get()).draw.pipeline.writeMask, c.mask)
            << "colour " << c.color << " alpha " << c.alpha;
    }
    EXPECT_EQ(translate(Ref<Appearance>(new Appearance()).get()).draw.pipeline.writeMask, WRITE_RGBA);
}

TEST(StateTranslation, AlphaThresholdToMiscAndDiscard) {
    Ref<CompositingMode> cm(new CompositingMode());
    Translated none = translate(withCompositing(cm.get()).get());
    EXPECT_EQ(none.u.misc[1], 0.0f);
    EXPECT_EQ(none.draw.pipeline.discard, 0);  // threshold 0 passes everything: no discard compiled in
    cm->setAlphaThreshold(0.625f);
    Translated t = translate(withCompositing(cm.get()).get());
    EXPECT_EQ(t.u.misc[1], 0.625f);
    EXPECT_EQ(t.draw.pipeline.discard, 1);
}

TEST(StateTranslation, DepthTestWriteAndOffsetToRasterState) {
    Ref<CompositingMode> cm(new CompositingMode());
    cm->setDepthTestEnable(false);
    cm->setDepthWriteEnable(true);
    cm->setDepthOffset(2.5f, -3.0f);
    RasterState r = translate(withCompositing(cm.get()).get()).draw.raster;
    EXPECT_EQ(r.depthTest, 0);
    EXPECT_EQ(r.depthWrite, 1);
    EXPECT_EQ(r.depthOffsetFactor, 2.5f);
    EXPECT_EQ(r.depthOffsetUnits, -3.0f);
    cm->setDepthTestEnable(true);
    cm->setDepthWriteEnable(false);
    r = translate(withCompositing(cm.get()).get()).draw.raster;
    EXPECT_EQ(r.depthTest, 1);
    EXPECT_EQ(r.depthWrite, 0);
    // Defaults without a CompositingMode: test and write, no offset.
    r = m3g::detail::rasterState(nullptr, nullptr);
    EXPECT_EQ(r.depthTest, 1);
    EXPECT_EQ(r.depthWrite, 1);
    EXPECT_EQ(r.depthOffsetFactor, 0.0f);
    EXPECT_EQ(r.depthOffsetUnits, 0.0f);
}

// ---- PolygonMode ----

TEST(StateTranslation, CullingToRasterCull) {
    const std::pair<int, int> modes[] = {
        {PolygonMode::CULL_NONE, 0}, {PolygonMode::CULL_FRONT, 1}, {PolygonMode::CULL_BACK, 2}};
    for (auto [mode, cull] : modes) {
        Ref<PolygonMode> pm(new PolygonMode());
        pm->setCulling(mode);
        EXPECT_EQ(translate(withPolygonMode(pm.get()).get()).draw.raster.cull, cull) << "mode " << mode;
    }
    // No PolygonMode: back faces culled, counter-clockwise front faces.
    const RasterState r = translate(Ref<Appearance>(new Appearance()).get()).draw.raster;
    EXPECT_EQ(r.cull, 2);
    EXPECT_EQ(r.clockwise, 0);
}

TEST(StateTranslation, WindingToRasterClockwise) {
    Ref<PolygonMode> pm(new PolygonMode());
    pm->setWinding(PolygonMode::WINDING_CW);
    EXPECT_EQ(translate(withPolygonMode(pm.get()).get()).draw.raster.clockwise, 1);
    pm->setWinding(PolygonMode::WINDING_CCW);
    EXPECT_EQ(translate(withPolygonMode(pm.get()).get()).draw.raster.clockwise, 0);
}

TEST(StateTranslation, FlatShadingSetsFlagAndKey) {
    Ref<PolygonMode> pm(new PolygonMode());
    pm->setShading(PolygonMode::SHADE_FLAT);
    Translated t = translate(withPolygonMode(pm.get()).get());
    EXPECT_TRUE(t.u.flags[0] & F_FLAT);
    EXPECT_EQ(t.draw.pipeline.flat, 1);
    pm->setShading(PolygonMode::SHADE_SMOOTH);
    t = translate(withPolygonMode(pm.get()).get());
    EXPECT_FALSE(t.u.flags[0] & F_FLAT);
    EXPECT_EQ(t.draw.pipeline.flat, 0);
}

TEST(StateTranslation, TwoSidedAndLocalCameraLightingNeedAMaterial) {
    Ref<PolygonMode> pm(new PolygonMode());
    pm->setTwoSidedLightingEnable(true);
    pm->setLocalCameraLightingEnable(true);
    Ref<Material> m(new Material());
    Translated t = translate(withPolygonMode(pm.get(), m.get()).get());
    EXPECT_TRUE(t.u.flags[0] & F_TWO_SIDED);
    EXPECT_TRUE(t.u.flags[0] & F_LOCAL_CAMERA);
    EXPECT_EQ(t.draw.pipeline.lighting, 3);  // bit 0 lighting, bit 1 two-sided
    // Without a Material there is no lighting, so neither applies.
    t = translate(withPolygonMode(pm.get()).get());
    EXPECT_FALSE(t.u.flags[0] & F_TWO_SIDED);
    EXPECT_FALSE(t.u.flags[0] & F_LOCAL_CAMERA);
    EXPECT_EQ(t.draw.pipeline.lighting, 0);
    // One-sided lighting: bit 0 only.
    pm->setTwoSidedLightingEnable(false);
    t = translate(withPolygonMode(pm.get(), m.get()).get());
    EXPECT_FALSE(t.u.flags[0] & F_TWO_SIDED);
    EXPECT_EQ(t.draw.pipeline.lighting, 1);
}

// ---- Material ----

TEST(StateTranslation, MaterialColoursDiffuseKeepsAlpha) {
    Ref<Material> m(new Material());
    m->setColor(Material::AMBIENT, static_cast<int>(0x80402010u));
    m->setColor(Material::DIFFUSE, static_cast<int>(0x80FF0000u));
    m->setColor(Material::EMISSIVE, static_cast<int>(0x40112233u));
    m->setColor(Material::SPECULAR, static_cast<int>(0x20FFFFFFu));
    m->setShininess(42.0f);
    const Translated t = translate(lit(m.get()).get());
    // Only the diffuse alpha counts (JSR-184 1.1, Material); the others take 1.
    expectRgba(t.u.matAmbient, c8(0x40), c8(0x20), c8(0x10), 1.0f);
    expectRgba(t.u.matDiffuse, 1.0f, 0.0f, 0.0f, c8(0x80));
    expectRgba(t.u.matEmissive, c8(0x11), c8(0x22), c8(0x33), 1.0f);
    // The specular block carries the shininess in w.
    expectRgba(t.u.matSpecular, 1.0f, 1.0f, 1.0f, 42.0f);
    EXPECT_TRUE(t.u.flags[0] & F_LIGHTING);
    EXPECT_EQ(t.draw.pipeline.specular, 1);
}

TEST(StateTranslation, MaterialDefaultsAndBlackSpecular) {
    // JSR-184 1.1 Material defaults: ambient 0x333333, diffuse 0xFFCCCCCC,
    // emissive and specular black, shininess 0.
    const Translated t = translate(lit().get());
    expectRgba(t.u.matAmbient, c8(0x33), c8(0x33), c8(0x33), 1.0f);
    expectRgba(t.u.matDiffuse, c8(0xCC), c8(0xCC), c8(0xCC), 1.0f);
    expectRgba(t.u.matEmissive, 0, 0, 0, 1.0f);
    expectRgba(t.u.matSpecular, 0, 0, 0, 0.0f);
    EXPECT_EQ(t.draw.pipeline.specular, 0);  // black specular: no specular term compiled in
    EXPECT_FALSE(t.u.flags[0] & F_COLOR_TRACKING);
}

TEST(StateTranslation, VertexColorTrackingFlag) {
    Ref<Material> m(new Material());
    m->setVertexColorTrackingEnable(true);
    EXPECT_TRUE(translate(lit(m.get()).get()).u.flags[0] & F_COLOR_TRACKING);
}

TEST(StateTranslation, NoMaterialMeansNoLightingEvenWithLights) {
    Ref<Light> l = frametest::light(Light::AMBIENT);
    const Translated t = translate(Ref<Appearance>(new Appearance()).get(), DrawOptions(), {{l.get(), Transform()}});
    EXPECT_FALSE(t.u.flags[0] & F_LIGHTING);
    EXPECT_EQ(t.u.flags[1], 0);  // no lights handed to the shader
    EXPECT_EQ(t.draw.pipeline.lighting, 0);
    EXPECT_EQ(t.draw.pipeline.lightCount, 0);
    expectRgba(t.u.matDiffuse, 0, 0, 0, 0);
}

TEST(StateTranslation, UnlitOptionDropsTheMaterial) {
    Ref<Light> l = frametest::light(Light::AMBIENT);
    DrawOptions o;
    o.unlit = true;
    const Translated t = translate(lit().get(), o, {{l.get(), Transform()}});
    EXPECT_FALSE(t.u.flags[0] & F_LIGHTING);
    EXPECT_EQ(t.u.flags[1], 0);
    EXPECT_EQ(t.draw.pipeline.lighting, 0);
}

TEST(StateTranslation, ClampLitOnlyWithLighting) {
    DrawOptions o;
    o.clampLit = true;
    EXPECT_TRUE(translate(lit().get(), o).u.flags[0] & F_CLAMP_LIT);
    EXPECT_FALSE(translate(Ref<Appearance>(new Appearance()).get(), o).u.flags[0] & F_CLAMP_LIT);
    EXPECT_FALSE(translate(lit().get()).u.flags[0] & F_CLAMP_LIT);  // off by default
}

TEST(StateTranslation, WireframeOptionToKey) {
    DrawOptions o;
    o.wireframe = true;
    EXPECT_EQ(translate(lit().get(), o).draw.pipeline.wireframe, 1);
    EXPECT_EQ(translate(lit().get()).draw.pipeline.wireframe, 0);
}

// ---- Lights ----

TEST(StateTranslation, LightModesColoursAndKey) {
    // Light i's mode in key bits 2i..2i+1 and colour.a: AMBIENT 0,
    // DIRECTIONAL 1, OMNI 2, SPOT 3. Colour = intensity x RGB.
    Ref<Light> spot = frametest::light(Light::SPOT, 0x804020, 2.0f);
    Ref<Light> ambient = frametest::light(Light::AMBIENT, 0x0000FF, 0.5f);
    Ref<Light> omni = frametest::light(Light::OMNI, 0x00FF00);
    Ref<Light> directional = frametest::light(Light::DIRECTIONAL, 0xFF0000, -1.0f);
    const Translated t = translate(lit().get(), DrawOptions(),
                                   {{spot.get(), Transform()},
                                    {ambient.get(), Transform()},
                                    {omni.get(), Transform()},
                                    {directional.get(), Transform()}});
    EXPECT_EQ(t.u.flags[1], 4);
    EXPECT_EQ(t.draw.pipeline.lightCount, 4);
    EXPECT_EQ(t.draw.pipeline.lightModes, 3 | (0 << 2) | (2 << 4) | (1 << 6));
    expectRgba(t.u.lights[0].color, 2 * c8(0x80), 2 * c8(0x40), 2 * c8(0x20), 3.0f);
    expectRgba(t.u.lights[1].color, 0, 0, 0.5f, 0.0f);
    expectRgba(t.u.lights[2].color, 0, 1, 0, 2.0f);
    expectRgba(t.u.lights[3].color, -1, 0, 0, 1.0f);  // negative intensity subtracts light
}

TEST(StateTranslation, DirectionalLightPositionIsTheDirectionTowardsIt) {
    // A light shines along its local -Z (JSR-184 1.1, Light). Unrotated: the
    // vector towards the light is +Z, w = 0. Rotated 90 degrees about X,
    // -Z becomes (0, 1, 0) (y' = y cos - z sin = 1), so the vector towards
    // it is (0, -1, 0). A translation changes nothing.
    Ref<Light> d = frametest::light(Light::DIRECTIONAL);
    Transform rot = frametest::translation(5, 6, 7);
    rot.postRotate(90, 1, 0, 0);
    const Translated t =
        translate(lit().get(), DrawOptions(), {{d.get(), Transform()}, {d.get(), rot}});
    expectRgba(t.u.lights[0].position, 0, 0, 1, 0);
    EXPECT_NEAR(t.u.lights[1].position[0], 0.0f, 1e-6f);
    EXPECT_NEAR(t.u.lights[1].position[1], -1.0f, 1e-6f);
    EXPECT_NEAR(t.u.lights[1].position[2], 0.0f, 1e-6f);
    EXPECT_EQ(t.u.lights[1].position[3], 0.0f);
    // Not attenuated, no cone.
    expectRgba(t.u.lights[1].attenuation, 1, 0, 0, 0);
    EXPECT_EQ(t.u.lights[1].spot[3], -1.0f);
}

TEST(StateTranslation, OmniLightPositionAndAttenuation) {
    Ref<Light> o = frametest::light(Light::OMNI);
    o->setAttenuation(0.5f, 0.25f, 0.125f);
    const Translated t = translate(lit().get(), DrawOptions(), {{o.get(), frametest::translation(1, 2, 3)}});
    expectRgba(t.u.lights[0].position, 1, 2, 3, 1);
    expectRgba(t.u.lights[0].attenuation, 0.5f, 0.25f, 0.125f, 0.0f);
    // An ambient light ignores its attenuation (JSR-184 1.1: only OMNI and SPOT attenuate).
    Ref<Light> a = frametest::light(Light::AMBIENT);
    a->setAttenuation(0.5f, 0.25f, 0.125f);
    const Translated ta = translate(lit().get(), DrawOptions(), {{a.get(), Transform()}});
    expectRgba(ta.u.lights[0].attenuation, 1, 0, 0, 0);
}

TEST(StateTranslation, SpotLightCutoffExponentAndDirection) {
    Ref<Light> s = frametest::light(Light::SPOT);
    s->setSpotAngle(60.0f);
    s->setSpotExponent(5.0f);
    s->setAttenuation(1.0f, 0.5f, 0.0f);
    Transform at = frametest::translation(0, 0, 2);
    at.postRotate(90, 1, 0, 0);  // shines along +Y
    const Translated t = translate(lit().get(), DrawOptions(), {{s.get(), at}});
    const LightUniforms& l = t.u.lights[0];
    expectRgba(l.position, 0, 0, 2, 1);
    EXPECT_NEAR(l.spot[0], 0.0f, 1e-6f);
    EXPECT_NEAR(l.spot[1], 1.0f, 1e-6f);
    EXPECT_NEAR(l.spot[2], 0.0f, 1e-6f);
    EXPECT_NEAR(l.spot[3], 0.5f, 1e-6f);  // cos 60
    EXPECT_EQ(l.attenuation[3], 5.0f);    // the exponent
    EXPECT_EQ(l.attenuation[1], 0.5f);
}

// ---- Fog ----

TEST(StateTranslation, LinearFog) {
    Ref<Fog> fog(new Fog());
    fog->setMode(Fog::LINEAR);
    fog->setLinear(2.0f, 10.0f);
    fog->setColor(0x336699);
    Ref<Appearance> a(new Appearance());
    a->setFog(fog.get());
    const Translated t = translate(a.get());
    expectRgba(t.u.fogColor, c8(0x33), c8(0x66), c8(0x99), 1.0f);
    EXPECT_EQ(t.u.fogParams[0], 1.0f);
    EXPECT_EQ(t.u.fogParams[1], 2.0f);
    EXPECT_EQ(t.u.fogParams[2], 10.0f);
    EXPECT_EQ(t.draw.pipeline.fog, 1);
}

TEST(StateTranslation, ExponentialFog) {
    Ref<Fog> fog(new Fog());
    fog->setMode(Fog::EXPONENTIAL);
    fog->setDensity(0.75f);
    fog->setColor(static_cast<int>(0xFF000080u));  // the alpha byte is not part of the fog colour
    Ref<Appearance> a(new Appearance());
    a->setFog(fog.get());
    const Translated t = translate(a.get());
    EXPECT_EQ(t.u.fogParams[0], 2.0f);
    EXPECT_EQ(t.u.fogParams[3], 0.75f);
    expectRgba(t.u.fogColor, 0, 0, c8(0x80), 1.0f);
    EXPECT_EQ(t.draw.pipeline.fog, 1);
}

TEST(StateTranslation, NoFogLeavesFogOff) {
    const Translated t = translate(Ref<Appearance>(new Appearance()).get());
    expectRgba(t.u.fogParams, 0, 0, 0, 0);
    EXPECT_EQ(t.draw.pipeline.fog, 0);
}

// ---- Texture2D ----

TEST(StateTranslation, EveryTextureFunctionToTexEnvAndKey) {
    const std::pair<int, int> funcs[] = {{Texture2D::FUNC_REPLACE, TEX_REPLACE},
                                         {Texture2D::FUNC_MODULATE, TEX_MODULATE},
                                         {Texture2D::FUNC_DECAL, TEX_DECAL},
                                         {Texture2D::FUNC_BLEND, TEX_BLEND},
                                         {Texture2D::FUNC_ADD, TEX_ADD}};
    EXPECT_EQ(TEX_REPLACE, 1);
    EXPECT_EQ(TEX_ADD, 5);
    frametest::Quad q = texturedQuad({0});
    for (auto [func, shader] : funcs) {
        Ref<Texture2D> tex = texture();
        tex->setBlending(func);
        Ref<Appearance> a(new Appearance());
        a->setTexture(0, tex.get());
        const Translated t = translate(q.vb.get(), q.ib.get(), a.get());
        EXPECT_EQ(t.u.texEnv[0][0], shader) << "func " << func;
        EXPECT_EQ(t.draw.pipeline.texFunc[0], shader) << "func " << func;
        EXPECT_EQ(m3g::detail::shaderTexFunc(func), shader);
    }
}

TEST(StateTranslation, ImageFormatsToTexEnvAndKeyFormat) {
    // Key format: bit 0 colour, bit 1 alpha.
    struct Case {
        int format, color, alpha, key;
    };
    const Case cases[] = {{Image2D::ALPHA, 0, 1, 2},
                          {Image2D::LUMINANCE, 1, 0, 1},
                          {Image2D::LUMINANCE_ALPHA, 1, 1, 3},
                          {Image2D::RGB, 1, 0, 1},
                          {Image2D::RGBA, 1, 1, 3}};
    frametest::Quad q = texturedQuad({1});
    for (const Case& c : cases) {
        Ref<Appearance> a(new Appearance());
        a->setTexture(1, texture(c.format).get());
        const Translated t = translate(q.vb.get(), q.ib.get(), a.get());
        EXPECT_EQ(t.u.texEnv[1][1], c.color) << "format " << c.format;
        EXPECT_EQ(t.u.texEnv[1][2], c.alpha) << "format " << c.format;
        EXPECT_EQ(t.draw.pipeline.texFormat[1], c.key) << "format " << c.format;
        EXPECT_EQ(t.draw.pipeline.texFunc[0], 0);  // unit 0 stays off
    }
}

TEST(StateTranslation, TextureRefNamesTheImageAndItsSampler) {
    frametest::Quad q = texturedQuad({0});
    Ref<Texture2D> tex = texture();
    tex->setWrapping(Texture2D::WRAP_CLAMP, Texture2D::WRAP_REPEAT);
    tex->setFiltering(Texture2D::FILTER_NEAREST, Texture2D::FILTER_LINEAR);
    Ref<Appearance> a(new Appearance());
    a->setTexture(0, tex.get());
    const Translated t = translate(q.vb.get(), q.ib.get(), a.get());
    const TextureRef& ref = t.draw.textures[0];
    EXPECT_EQ(ref.id, tex->getImage()->getObjectId());
    EXPECT_EQ(ref.revision, tex->getImage()->getRevision());
    EXPECT_TRUE(ref.mipmaps);                 // level filter NEAREST needs the mip chain
    EXPECT_EQ(ref.sampler, 1u | 4u | 8u);     // S clamps, linear image filter, nearest level
    EXPECT_EQ(t.draw.textures[1].id, 0u);     // unit 1: no texture
    // Base level only: no mip chain.
    tex->setFiltering(Texture2D::FILTER_BASE_LEVEL, Texture2D::FILTER_NEAREST);
    const Translated base = translate(q.vb.get(), q.ib.get(), a.get());
    EXPECT_FALSE(base.draw.textures[0].mipmaps);
    EXPECT_EQ(base.draw.textures[0].sampler, 1u);
}

TEST(StateTranslation, TextureMatrixScaleBiasAndBlendColour) {
    frametest::Quad q = texturedQuad({0});
    Ref<Texture2D> tex = texture();
    tex->setTranslation(0.5f, 0.25f, 0.0f);
    tex->setScale(2.0f, 4.0f, 1.0f);
    tex->setBlendColor(0x8040FF);
    Ref<Appearance> a(new Appearance());
    a->setTexture(0, tex.get());
    const Translated t = translate(q.vb.get(), q.ib.get(), a.get());
    // T S, column major: diagonal 2, 4, 1, 1; translation in elements 12, 13.
    const float* m = t.u.texMatrix[0];
    EXPECT_EQ(m[0], 2.0f);
    EXPECT_EQ(m[5], 4.0f);
    EXPECT_EQ(m[10], 1.0f);
    EXPECT_EQ(m[12], 0.5f);
    EXPECT_EQ(m[13], 0.25f);
    EXPECT_EQ(m[15], 1.0f);
    // (bias, scale) of the coordinates as set in texturedQuad.
    expectRgba(t.u.texScaleBias[0], 0.25f, 0.125f, 0.0f, 0.5f);
    expectRgba(t.u.texBlendColor[0], c8(0x80), c8(0x40), 1.0f, 1.0f);
    EXPECT_EQ(t.draw.pipeline.texProjective[0], 0);
}

TEST(StateTranslation, ProjectiveTextureMatrixToKey) {
    frametest::Quad q = texturedQuad({0, 1});
    Ref<Texture2D> projective = texture();
    // Bottom row (0, 0.5, 0, 1): q depends on t, so s and t must be divided by q.
    const Transform m = Transform::fromRows({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0.5f, 0, 1});
    projective->setTransform(&m);
    Ref<Appearance> a(new Appearance());
    a->setTexture(0, projective.get());
    a->setTexture(1, texture().get());
    const Translated t = translate(q.vb.get(), q.ib.get(), a.get());
    EXPECT_EQ(t.u.texMatrix[0][7], 0.5f);  // row 3, column 1
    EXPECT_EQ(t.draw.pipeline.texProjective[0], 1);
    EXPECT_EQ(t.draw.pipeline.texProjective[1], 0);
}

TEST(StateTranslation, UnitWithoutTextureCoordinatesIsUnused) {
    // The texture is on unit 1 but the VertexBuffer only has coordinates for unit 0.
    frametest::Quad q = texturedQuad({0});
    Ref<Appearance> a(new Appearance());
    a->setTexture(1, texture().get());
    Translated t = translate(q.vb.get(), q.ib.get(), a.get());
    EXPECT_EQ(t.draw.textures[1].id, 0u);
    EXPECT_EQ(t.u.texEnv[1][0], TEX_OFF);
    EXPECT_EQ(t.draw.pipeline.texFunc[1], 0);
    // Coordinates present in the VertexBuffer but not in the layout (a
    // deformed mesh that produced none): also unused.
    frametest::Quad both = texturedQuad({0, 1});
    VertexLayout layout = plainLayout(*both.vb);
    layout.present[TEXCOORDS1] = false;
    t = translate(both.vb.get(), both.ib.get(), a.get(), Transform(), DrawOptions(), {}, 2, &layout);
    EXPECT_EQ(t.draw.textures[1].id, 0u);
    EXPECT_EQ(t.draw.pipeline.texFunc[1], 0);
}

TEST(StateTranslation, NumTextureUnitsLimitsTheUnitsUsed) {
    frametest::Quad q = texturedQuad({0, 1});
    Ref<Appearance> a(new Appearance());
    a->setTexture(0, texture().get());
    a->setTexture(1, texture().get());
    const Translated two = translate(q.vb.get(), q.ib.get(), a.get());
    EXPECT_NE(two.draw.textures[1].id, 0u);
    EXPECT_EQ(two.draw.pipeline.texFunc[1], TEX_MODULATE);  // Texture2D's default function
    const Translated one = translate(q.vb.get(), q.ib.get(), a.get(), Transform(), DrawOptions(), {}, 1);
    EXPECT_NE(one.draw.textures[0].id, 0u);
    EXPECT_EQ(one.draw.textures[1].id, 0u);
    EXPECT_EQ(one.draw.pipeline.texFunc[1], 0);
}

// ---- Geometry uniforms ----

TEST(StateTranslation, PositionScaleBiasPlainAndDeformed) {
    Ref<VertexBuffer> vb = frametest::vertexBuffer({0, 0, 0, 1, 0, 0, 0, 1, 0}, 0.25f, {1.0f, -2.0f, 3.0f});
    const int lengths[] = {3};
    Ref<IndexBuffer> ib(new TriangleStripArray(0, lengths));
    Ref<Appearance> a(new Appearance());
    const Translated plain = translate(vb.get(), ib.get(), a.get());
    expectRgba(plain.u.positionScaleBias, 1.0f, -2.0f, 3.0f, 0.25f);
    // Deformed positions arrive scaled and biased: scale 1, bias 0.
    VertexLayout deformed = plainLayout(*vb);
    deformed.deformed = true;
    const Translated d = translate(vb.get(), ib.get(), a.get(), Transform(), DrawOptions(), {}, 2, &deformed);
    expectRgba(d.u.positionScaleBias, 0, 0, 0, 1);
}

TEST(StateTranslation, ModelViewProjectionColumnsAndMisc) {
    frametest::Quad q = quad();
    q.vb->setDefaultColor(static_cast<int>(0x80FF8000u));
    Transform mv = frametest::translation(1, 2, 3);
    mv.postScale(2, 2, 2);
    const Translated t = translate(q.vb.get(), q.ib.get(), Ref<Appearance>(new Appearance()).get(), mv,
                                   DrawOptions(), {}, 2, nullptr, 0.375f);
    // Column major: the translation in elements 12..14.
    EXPECT_EQ(t.u.modelView[0], 2.0f);
    EXPECT_EQ(t.u.modelView[12], 1.0f);
    EXPECT_EQ(t.u.modelView[13], 2.0f);
    EXPECT_EQ(t.u.modelView[14], 3.0f);
    EXPECT_EQ(t.u.modelView[15], 1.0f);
    // Identity camera with the Vulkan clip-space fix.
    float fix[16];
    vulkanClipFix(fix);
    for (int i = 0; i < 16; ++i) EXPECT_EQ(t.u.projection[i], fix[i]) << i;
    expectRgba(t.u.defaultColor, 1.0f, c8(0x80), 0.0f, c8(0x80));
    EXPECT_EQ(t.u.misc[0], 0.375f);  // alpha factor
    EXPECT_EQ(t.u.misc[2], -1.0f);   // no fixed fog depth
    EXPECT_EQ(t.draw.kind, Draw::Kind::Submesh);
}

TEST(StateTranslation, NormalMatrixIsTheInverseTranspose) {
    // Shear M = [[1, 1, 0], [0, 1, 0], [0, 0, 1]]: M^-1 = [[1, -1, 0], [0, 1, 0],
    // [0, 0, 1]], its transpose [[1, 0, 0], [-1, 1, 0], [0, 0, 1]]; column
    // major, element (row 1, column 0) is index 1.
    const Transform shear = Transform::fromRows({1, 1, 0, 5, 0, 1, 0, 6, 0, 0, 1, 7, 0, 0, 0, 1});
    frametest::Quad q = quad();
    Ref<Appearance> a(new Appearance());
    const Translated sheared = translate(q.vb.get(), q.ib.get(), a.get(), shear);
    const float* n = sheared.u.normalMatrix;
    const float want[16] = {1, -1, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(n[i], want[i], 1e-6f) << i;
    // A scale (2, 4, 0.5): the inverse transpose is (0.5, 0.25, 2).
    Transform scale;
    scale.postScale(2, 4, 0.5f);
    const Translated s = translate(q.vb.get(), q.ib.get(), a.get(), scale);
    EXPECT_NEAR(s.u.normalMatrix[0], 0.5f, 1e-6f);
    EXPECT_NEAR(s.u.normalMatrix[5], 0.25f, 1e-6f);
    EXPECT_NEAR(s.u.normalMatrix[10], 2.0f, 1e-6f);
}

TEST(StateTranslation, RigidTransformGoesIntoModelViewAndNormalMatrix) {
    // A rigid binding (VertexLayout::rigid): the palette entry P (position
    // rows) = translate (1, 2, 3) x scale (2, 1, 1), N (normal rows) = its
    // inverse transpose, diag(0.5, 1, 1); the model-view M = translate
    // (0, 0, -5) x rotate 90 degrees about z, which maps x to y and y to -x.
    // Model-view sent: M P, so raw (1, 0, 0) -> P (3, 2, 3) -> M (-2, 3, -2);
    // normal matrix: M's (the rotation itself) times N, so x -> 0.5 y.
    frametest::Quad q = quad();
    Ref<Appearance> a(new Appearance());
    VertexLayout rigid = plainLayout(*q.vb);
    rigid.present[NORMALS] = true;  // as with a normal array
    rigid.rigid = true;
    const float position[12] = {2, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3};
    const float normal[12] = {0.5f, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    std::memcpy(rigid.rigidTransform.position, position, sizeof position);
    std::memcpy(rigid.rigidTransform.normal, normal, sizeof normal);
    Transform mv = frametest::translation(0, 0, -5);
    mv.postRotate(90, 0, 0, 1);
    const Translated t = translate(q.vb.get(), q.ib.get(), a.get(), mv, DrawOptions(), {}, 2, &rigid);
    auto apply = [](const float* m, float x, float y, float z, float w, int row) {
        return m[row] * x + m[4 + row] * y + m[8 + row] * z + m[12 + row] * w;
    };
    EXPECT_NEAR(apply(t.u.modelView, 1, 0, 0, 1, 0), -2.0f, 1e-6f);
    EXPECT_NEAR(apply(t.u.modelView, 1, 0, 0, 1, 1), 3.0f, 1e-6f);
    EXPECT_NEAR(apply(t.u.modelView, 1, 0, 0, 1, 2), -2.0f, 1e-6f);
    EXPECT_NEAR(apply(t.u.modelView, 1, 0, 0, 1, 3), 1.0f, 1e-6f);
    EXPECT_NEAR(apply(t.u.normalMatrix, 1, 0, 0, 0, 0), 0.0f, 1e-6f);
    EXPECT_NEAR(apply(t.u.normalMatrix, 1, 0, 0, 0, 1), 0.5f, 1e-6f);
    EXPECT_NEAR(apply(t.u.normalMatrix, 0, 1, 0, 0, 0), -1.0f, 1e-6f);  // y -> -x, N leaves y
    // The entry holds the VertexBuffer's scale and bias: none in the uniforms.
    expectRgba(t.u.positionScaleBias, 0, 0, 0, 1);
    // Without normals the default normal is lit through the model-view's
    // normal matrix alone, as with the skinned vertices.
    rigid.present[NORMALS] = false;
    const Translated n = translate(q.vb.get(), q.ib.get(), a.get(), mv, DrawOptions(), {}, 2, &rigid);
    const Translated plain = translate(q.vb.get(), q.ib.get(), a.get(), mv);
    for (int i = 0; i < 16; ++i) EXPECT_EQ(n.u.normalMatrix[i], plain.u.normalMatrix[i]) << i;
    EXPECT_NEAR(apply(n.u.modelView, 1, 0, 0, 1, 1), 3.0f, 1e-6f);
}

TEST(StateTranslation, VertexStreamFlags) {
    frametest::Quad q = quad();
    Ref<Appearance> a(new Appearance());
    Translated t = translate(q.vb.get(), q.ib.get(), a.get());
    EXPECT_FALSE(t.u.flags[0] & F_HAS_NORMALS);
    EXPECT_FALSE(t.u.flags[0] & F_HAS_COLORS);
    q.vb->setNormals(frametest::bytes(3, {0, 0, 127, 0, 0, 127, 0, 0, 127, 0, 0, 127}).get());
    q.vb->setColors(frametest::bytes(3, {255, 0, 0, 255, 0, 0, 255, 0, 0, 255, 0, 0}).get());
    t = translate(q.vb.get(), q.ib.get(), a.get());
    EXPECT_TRUE(t.u.flags[0] & F_HAS_NORMALS);
    EXPECT_TRUE(t.u.flags[0] & F_HAS_COLORS);
}

// ---- Triangle lists ----

TEST(StateTranslation, TriangleListOfAStripPutsTheProvokingVertexFirst) {
    // Strip 0 1 2 3 4: triangles (0 1 2), (2 1 3) (odd: order swapped to
    // keep the winding), (2 3 4). OpenGL ES flat-shades a strip triangle with
    // its last vertex (2, 3, 4), which must come first; rotations keep the winding.
    const int lengths[] = {5};
    TriangleStripArray strip(0, lengths);
    std::vector<std::uint32_t> list;
    m3g::detail::triangleList(strip, list);
    EXPECT_EQ(list, (std::vector<std::uint32_t>{2, 0, 1, 3, 2, 1, 4, 2, 3}));
    // Two explicit strips: triangle numbering restarts in each.
    const int indices[] = {7, 8, 9, 10, 11, 12, 13};
    const int two[] = {3, 4};
    TriangleStripArray strips(indices, two);
    m3g::detail::triangleList(strips, list);
    EXPECT_EQ(list, (std::vector<std::uint32_t>{9, 7, 8, 12, 10, 11, 13, 12, 11}));
}

TEST(StateTranslation, TriangleListOfAPlainListRotatesEachTriangle) {
    frametest::TriangleList tl({0, 1, 2, 5, 4, 3});
    std::vector<std::uint32_t> list{99};
    m3g::detail::triangleList(tl, list);
    EXPECT_EQ(list, (std::vector<std::uint32_t>{2, 0, 1, 3, 5, 4}));
}

// ---- ViewState ----

TEST(StateTranslation, ViewStateOfAnImageTarget) {
    auto g = Graphics3D::create();
    Ref<Image2D> img(new Image2D(Image2D::RGBA, 16, 16));
    g->bindTarget(img.get());
    g->setViewport(-4, 2, 10, 20);
    g->setDepthRange(0.25f, 0.75f);
    const ViewState v = m3g::detail::viewState(*g);
    EXPECT_EQ(v.viewport, (Rect{-4, 2, 10, 20}));
    // x: [-4, 6) within [0, 16) -> [0, 6); y: [2, 22) within [0, 16) -> [2, 16).
    EXPECT_EQ(v.scissor, (Rect{0, 2, 6, 14}));
    EXPECT_EQ(v.depthNear, 0.25f);
    EXPECT_EQ(v.depthFar, 0.75f);
    g->releaseTarget();
}

TEST(StateTranslation, ViewStateOfAGraphicsMovesByTheTranslationAndClips) {
    // Graphics 200 x 100 translated (20, 10), clip (5, 5, 50, 40) in
    // translated coordinates = (25, 15, 50, 40) on the surface. Viewport
    // (-10, -5, 40, 30) -> (10, 5, 40, 30) on the surface. Scissor: x [25, 50),
    // y [15, 35).
    auto g = Graphics3D::create();
    Ref<Graphics> gr(new Graphics(200, 100));
    gr->translate(20, 10);
    gr->setClip(5, 5, 50, 40);
    g->bindTarget(gr.get());
    // The default viewport is the clip rectangle.
    EXPECT_EQ(m3g::detail::viewState(*g).viewport, (Rect{25, 15, 50, 40}));
    g->setViewport(-10, -5, 40, 30);
    const ViewState v = m3g::detail::viewState(*g);
    EXPECT_EQ(v.viewport, (Rect{10, 5, 40, 30}));
    EXPECT_EQ(v.scissor, (Rect{25, 15, 25, 20}));
    EXPECT_EQ(v.depthNear, 0.0f);
    EXPECT_EQ(v.depthFar, 1.0f);
    g->releaseTarget();
}

TEST(StateTranslation, ViewportOutsideTheTargetGivesAnEmptyScissor) {
    auto g = Graphics3D::create();
    Ref<Image2D> img(new Image2D(Image2D::RGB, 8, 8));
    g->bindTarget(img.get());
    g->setViewport(100, 100, 8, 8);
    const ViewState v = m3g::detail::viewState(*g);
    EXPECT_TRUE(v.scissor.empty());
    EXPECT_EQ(v.scissor.w, 0);
    EXPECT_EQ(v.scissor.h, 0);
    g->releaseTarget();
}

// ---- Background (translateClear) ----

namespace {

ViewState fullView(int w, int h) {
    ViewState v;
    v.viewport = v.scissor = {0, 0, w, h};
    return v;
}

}  // namespace

TEST(StateTranslation, ClearWithoutBackgroundIsTransparentBlackAndDepth) {
    std::vector<DrawUniforms> uniforms;
    const Clear c = m3g::detail::translateClear(nullptr, fullView(16, 8), 16, 8, true, uniforms);
    EXPECT_TRUE(c.color);
    EXPECT_TRUE(c.depth);
    expectRgba(c.rgba, 0, 0, 0, 0);
    EXPECT_TRUE(c.wholeTarget);
    EXPECT_FALSE(c.hasImage);
    EXPECT_TRUE(uniforms.empty());
    // A scissor smaller than the target is not the whole target.
    ViewState part = fullView(16, 8);
    part.scissor = {1, 0, 15, 8};
    EXPECT_FALSE(m3g::detail::translateClear(nullptr, part, 16, 8, true, uniforms).wholeTarget);
}

TEST(StateTranslation, ClearColourAndFlagsOfABackground) {
    Ref<Background> bg(new Background());
    bg->setColor(static_cast<int>(0x80FF4000u));
    std::vector<DrawUniforms> uniforms;
    Clear c = m3g::detail::translateClear(bg.get(), fullView(4, 4), 4, 4, true, uniforms);
    expectRgba(c.rgba, 1.0f, c8(0x40), 0.0f, c8(0x80));
    EXPECT_TRUE(c.color);
    EXPECT_TRUE(c.depth);
    bg->setColorClearEnable(false);
    c = m3g::detail::translateClear(bg.get(), fullView(4, 4), 4, 4, true, uniforms);
    EXPECT_FALSE(c.color);
    EXPECT_TRUE(c.depth);
    bg->setColorClearEnable(true);
    bg->setDepthClearEnable(false);
    c = m3g::detail::translateClear(bg.get(), fullView(4, 4), 4, 4, true, uniforms);
    EXPECT_TRUE(c.color);
    EXPECT_FALSE(c.depth);
}

TEST(StateTranslation, ClearImageIsDrawnOnlyWithTheColourClear) {
    Ref<Background> bg(new Background());
    bg->setImage(frametest::image(Image2D::RGB, 8, 4).get());
    bg->setColorClearEnable(false);
    std::vector<DrawUniforms> uniforms;
    const Clear c = m3g::detail::translateClear(bg.get(), fullView(8, 8), 8, 8, true, uniforms);
    EXPECT_FALSE(c.hasImage);
    EXPECT_TRUE(uniforms.empty());
    // A zero-sized crop shows no image either.
    bg->setColorClearEnable(true);
    bg->setCrop(0, 0, 0, 4);
    EXPECT_FALSE(m3g::detail::translateClear(bg.get(), fullView(8, 8), 8, 8, true, uniforms).hasImage);
}

TEST(StateTranslation, ClearImageQuadMapsTheCropOntoTheViewport) {
    // Image 8 x 4, crop (2, 1, 4, 2): s in [2/8, 6/8], t in [1/4, 3/4].
    Ref<Image2D> img = frametest::image(Image2D::RGB, 8, 4);
    Ref<Background> bg(new Background());
    bg->setImage(img.get());
    bg->setCrop(2, 1, 4, 2);
    std::vector<DrawUniforms> uniforms(2);  // earlier uniforms of the list stay
    const Clear c = m3g::detail::translateClear(bg.get(), fullView(8, 8), 8, 8, true, uniforms);
    ASSERT_TRUE(c.hasImage);
    const Quad& q = c.image.quad;
    EXPECT_EQ(q.x0, -1.0f);
    EXPECT_EQ(q.y0, -1.0f);
    EXPECT_EQ(q.x1, 1.0f);
    EXPECT_EQ(q.y1, 1.0f);
    // Shifted by a quarter of the pixel-centre spacing, 1 / (2 * 8) texels:
    // ties go to the texel after the edge on every device.
    constexpr float shift = 0.25f / 8;
    EXPECT_FLOAT_EQ(q.s0, (2 + shift) / 8);
    EXPECT_FLOAT_EQ(q.t0, (1 + shift) / 4);
    EXPECT_FLOAT_EQ(q.s1, (6 + shift) / 8);
    EXPECT_FLOAT_EQ(q.t1, (3 + shift) / 4);
    ASSERT_EQ(uniforms.size(), 3u);
    EXPECT_EQ(c.image.uniforms, 2u);
    EXPECT_EQ(c.image.kind, Draw::Kind::Quad);
    EXPECT_EQ(c.image.textures[0].id, img->getObjectId());
    EXPECT_EQ(c.image.textures[0].revision, img->getRevision());
    // The image replaces the colour (RGB: colour, no alpha); no culling, no depth test or write.
    const DrawUniforms& u = uniforms[2];
    EXPECT_EQ(u.texEnv[0][0], TEX_REPLACE);
    EXPECT_EQ(u.texEnv[0][1], 1);
    EXPECT_EQ(u.texEnv[0][2], 0);
    EXPECT_EQ(u.flags[0], F_CLIP_SPACE);
    EXPECT_EQ(c.image.pipeline.texFunc[0], TEX_REPLACE);
    EXPECT_EQ(c.image.raster.cull, 0);
    EXPECT_EQ(c.image.raster.depthTest, 0);
    EXPECT_EQ(c.image.raster.depthWrite, 0);
}

TEST(StateTranslation, ClearImageRepeatCoversAndRepeats) {
    // REPEAT on both axes: every pixel shows the image, wherever the crop lies.
    Ref<Background> bg(new Background());
    bg->setImage(frametest::image(Image2D::RGB, 8, 4).get());
    bg->setImageMode(Background::REPEAT, Background::REPEAT);
    bg->setCrop(-4, 2, 16, 8);
    std::vector<DrawUniforms> uniforms;
    const Clear c = m3g::detail::translateClear(bg.get(), fullView(8, 8), 8, 8, true, uniforms);
    ASSERT_TRUE(c.hasImage);
    EXPECT_TRUE(c.imageCovers);
    EXPECT_EQ(uniforms[0].texEnv[0][3], 0);  // no BORDER discard
    EXPECT_EQ(c.image.pipeline.discard, 0);
    EXPECT_EQ(c.image.textures[0].sampler, 0u);  // repeat, nearest, base level
    // The crop in texels over the image size, shifted by a quarter of the
    // spacing of pixel centres (1 / (2 * 8) texels on an 8-pixel viewport)
    // so ties fall on the texel after an edge on every device.
    constexpr float shift = 0.25f / 8;
    EXPECT_FLOAT_EQ(c.image.quad.s0, (-4 + shift) / 8);
    EXPECT_FLOAT_EQ(c.image.quad.s1, (12 + shift) / 8);
    EXPECT_FLOAT_EQ(c.image.quad.t0, (2 + shift) / 4);
    EXPECT_FLOAT_EQ(c.image.quad.t1, (10 + shift) / 4);
}

TEST(StateTranslation, ClearImageBorderInsideCoversOutsideDiscards) {
    Ref<Background> bg(new Background());
    bg->setImage(frametest::image(Image2D::RGBA, 8, 4).get());
    std::vector<DrawUniforms> uniforms;
    // BORDER (the default) with the crop inside the image: covers, clamped.
    bg->setCrop(1, 1, 6, 2);
    Clear c = m3g::detail::translateClear(bg.get(), fullView(8, 8), 8, 8, true, uniforms);
    EXPECT_TRUE(c.imageCovers);
    EXPECT_EQ(c.image.textures[0].sampler, 3u);
    EXPECT_EQ(c.image.pipeline.discard, 0);
    EXPECT_EQ(uniforms.back().texEnv[0][2], 1);  // RGBA has alpha
    // The crop leaves the image on x: the BORDER part shows the background colour.
    bg->setCrop(-2, 0, 8, 4);
    c = m3g::detail::translateClear(bg.get(), fullView(8, 8), 8, 8, true, uniforms);
    EXPECT_FALSE(c.imageCovers);
    EXPECT_EQ(uniforms.back().texEnv[0][3], 1);
    EXPECT_EQ(c.image.pipeline.discard, 1);
    // ... on y only, with x repeating: bit 1 only, S repeats, T clamps.
    bg->setImageMode(Background::REPEAT, Background::BORDER);
    bg->setCrop(0, 2, 8, 4);
    c = m3g::detail::translateClear(bg.get(), fullView(8, 8), 8, 8, true, uniforms);
    EXPECT_FALSE(c.imageCovers);
    EXPECT_EQ(uniforms.back().texEnv[0][3], 2);
    EXPECT_EQ(c.image.textures[0].sampler, 2u);
}

// ---- Sprite3D (translateSprite) ----

namespace {

struct SpriteDraw {
    bool visible = false;
    DrawUniforms u{};
    Draw draw;
    float alphaFactor = 0.0f;
};

/// A Sprite3D collected at eye-space translation `at` under an identity
/// camera and translated for a 64 x 64 viewport.
SpriteDraw spriteAt(Sprite3D& sprite, const Transform& at, float parentAlpha = 1.0f) {
    Ref<Camera> cam(new Camera());
    RenderQueue q;
    q.reset(*cam, 8);
    q.collectNode(sprite, at, parentAlpha);
    SpriteDraw s;
    if (q.items.empty()) return s;
    s.alphaFactor = q.items[0].alphaFactor;
    s.visible = m3g::detail::translateSprite(q, q.items[0], 64, 64, true, s.u, s.draw);
    return s;
}

}  // namespace

TEST(StateTranslation, UnscaledSpriteQuadFields) {
    // 16 x 8 image, unscaled: 16 x 8 pixels of a 64 x 64 viewport = 0.5 x 0.25
    // in NDC, centred on the origin's projection (0, 0). Identity camera at
    // eye z -0.5: NDC depth -0.5, fog depth 0.5.
    Ref<Image2D> img = frametest::image(Image2D::RGBA, 16, 8);
    Ref<Appearance> app = frametest::appearance(0, CompositingMode::ALPHA);
    Ref<Sprite3D> sprite(new Sprite3D(false, img.get(), app.get()));
    const SpriteDraw s = spriteAt(*sprite, frametest::translation(0, 0, -0.5f), 0.5f);
    ASSERT_TRUE(s.visible);
    const Quad& q = s.draw.quad;
    EXPECT_NEAR(q.x0, -0.25f, 1e-6f);
    EXPECT_NEAR(q.x1, 0.25f, 1e-6f);
    EXPECT_NEAR(q.y0, -0.125f, 1e-6f);
    EXPECT_NEAR(q.y1, 0.125f, 1e-6f);
    EXPECT_NEAR(q.z, -0.5f, 1e-6f);
    EXPECT_EQ(q.s0, 0.0f);
    EXPECT_EQ(q.t0, 0.0f);
    EXPECT_EQ(q.s1, 1.0f);
    EXPECT_EQ(q.t1, 1.0f);
    EXPECT_EQ(s.draw.kind, Draw::Kind::Quad);
    EXPECT_EQ(s.draw.textures[0].id, img->getObjectId());
    EXPECT_EQ(s.draw.textures[0].sampler, 3u);  // clamped, nearest, base level
    EXPECT_EQ(s.draw.pipeline.blend, 1);
    // The image modulates the colour (RGBA: colour and alpha) times the alpha factor.
    EXPECT_EQ(s.u.texEnv[0][0], TEX_MODULATE);
    EXPECT_EQ(s.draw.pipeline.texFormat[0], 3);
    EXPECT_EQ(s.u.misc[0], 0.5f);
    EXPECT_NEAR(s.u.misc[2], 0.5f, 1e-6f);
}

TEST(StateTranslation, SpriteTakesNoCullingOrDepthOffsetButItsFog) {
    Ref<Appearance> app(new Appearance());
    Ref<CompositingMode> cm(new CompositingMode());
    cm->setDepthOffset(4.0f, 8.0f);
    cm->setDepthWriteEnable(false);
    cm->setAlphaThreshold(0.5f);
    app->setCompositingMode(cm.get());
    Ref<PolygonMode> pm(new PolygonMode());
    pm->setCulling(PolygonMode::CULL_FRONT);
    app->setPolygonMode(pm.get());
    Ref<Fog> fog(new Fog());
    fog->setMode(Fog::LINEAR);
    fog->setLinear(0.0f, 4.0f);
    app->setFog(fog.get());
    Ref<Sprite3D> sprite(new Sprite3D(true, frametest::image(Image2D::RGB, 4, 4).get(), app.get()));
    const SpriteDraw s = spriteAt(*sprite, frametest::translation(0, 0, -0.75f));
    ASSERT_TRUE(s.visible);
    EXPECT_EQ(s.draw.raster.cull, 0);
    EXPECT_EQ(s.draw.raster.depthOffsetFactor, 0.0f);
    EXPECT_EQ(s.draw.raster.depthOffsetUnits, 0.0f);
    EXPECT_EQ(s.draw.raster.depthWrite, 0);  // the CompositingMode's depth state applies
    EXPECT_EQ(s.u.misc[1], 0.5f);
    EXPECT_EQ(s.draw.pipeline.discard, 1);
    EXPECT_EQ(s.u.fogParams[0], 1.0f);
    EXPECT_EQ(s.u.fogParams[2], 4.0f);
    EXPECT_EQ(s.draw.pipeline.fog, 1);
    EXPECT_NEAR(s.u.misc[2], 0.75f, 1e-6f);  // fogged at the origin's eye depth
    EXPECT_EQ(s.draw.pipeline.texFormat[0], 1);  // RGB
}

TEST(StateTranslation, SpriteOutsideTheViewVolumeIsNotDrawn) {
    Ref<Sprite3D> sprite(new Sprite3D(false, frametest::image(Image2D::RGB, 4, 4).get(),
                                      Ref<Appearance>(new Appearance()).get()));
    // Identity projection: NDC z = eye z; -2 lies beyond the far plane.
    EXPECT_FALSE(spriteAt(*sprite, frametest::translation(0, 0, -2.0f)).visible);
    EXPECT_TRUE(spriteAt(*sprite, frametest::translation(0, 0, -0.9f)).visible);
}
