#include "SampleScene.h"

#include <array>
#include <cmath>
#include <vector>

namespace m3gcli {

using namespace m3g;

namespace {

/// A 32x32 checkerboard in two colours (RGB).
Ref<Image2D> checker() {
    std::vector<std::uint8_t> px(32 * 32 * 3);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            const bool on = ((x / 8) + (y / 8)) % 2 == 0;
            const std::uint8_t c[3] = {static_cast<std::uint8_t>(on ? 240 : 40), static_cast<std::uint8_t>(on ? 200 : 90),
                                       static_cast<std::uint8_t>(on ? 60 : 160)};
            for (int k = 0; k < 3; ++k) px[(y * 32 + x) * 3 + k] = c[k];
        }
    return Ref<Image2D>(new Image2D(Image2D::RGB, 32, 32, px));
}

/// A round, soft-edged spot of light (RGBA) for the sprite.
Ref<Image2D> glow() {
    std::vector<std::uint8_t> px(16 * 16 * 4);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const float dx = (static_cast<float>(x) - 7.5f) / 7.5f, dy = (static_cast<float>(y) - 7.5f) / 7.5f;
            const float a = std::max(0.0f, 1.0f - std::sqrt(dx * dx + dy * dy));
            std::uint8_t* p = &px[(y * 16 + x) * 4];
            p[0] = 255;
            p[1] = 230;
            p[2] = 140;
            p[3] = static_cast<std::uint8_t>(255.0f * a);
        }
    return Ref<Image2D>(new Image2D(Image2D::RGBA, 16, 16, px));
}

}  // namespace

/// A unit cube (positions as shorts scaled by 1/64), normals per face,
/// texture coordinates 0..1, six strips of four vertices.
Ref<Mesh> makeCube(Appearance* appearance) {
    struct Face { int n[3]; int u[3]; int v[3]; };
    const Face faces[6] = {{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
                           {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                           {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}};
    std::vector<std::int16_t> pos;
    std::vector<std::int8_t> nrm;
    std::vector<std::int16_t> tex;
    for (const Face& f : faces) {
        const int corners[4][2] = {{-1, -1}, {1, -1}, {-1, 1}, {1, 1}};  // strip order, counter-clockwise
        for (const auto& c : corners) {
            for (int k = 0; k < 3; ++k) pos.push_back(static_cast<std::int16_t>(64 * (f.n[k] + c[0] * f.u[k] + c[1] * f.v[k])));
            for (int k = 0; k < 3; ++k) nrm.push_back(static_cast<std::int8_t>(127 * f.n[k]));
            tex.push_back(static_cast<std::int16_t>(c[0] > 0 ? 1 : 0));
            tex.push_back(static_cast<std::int16_t>(c[1] > 0 ? 0 : 1));
        }
    }
    Ref<VertexArray> positions(new VertexArray(24, 3, 2));
    positions->set(0, 24, std::span<const std::int16_t>(pos));
    Ref<VertexArray> normals(new VertexArray(24, 3, 1));
    normals->set(0, 24, std::span<const std::int8_t>(nrm));
    Ref<VertexArray> texcoords(new VertexArray(24, 2, 2));
    texcoords->set(0, 24, std::span<const std::int16_t>(tex));
    Ref<VertexBuffer> vb(new VertexBuffer());
    const float noBias[3] = {0, 0, 0};
    vb->setPositions(positions.get(), 1.0f / 64.0f, noBias);
    vb->setNormals(normals.get());
    vb->setTexCoords(0, texcoords.get(), 1.0f, noBias);
    const int lengths[6] = {4, 4, 4, 4, 4, 4};
    Ref<IndexBuffer> strips(new TriangleStripArray(0, lengths));
    return Ref<Mesh>(new Mesh(vb.get(), strips.get(), appearance));
}

/// A flat ground grid of 8x8 quads with per-vertex colours, unlit.
Ref<Mesh> makeGround() {
    const int n = 9;
    std::vector<std::int16_t> pos;
    std::vector<std::int8_t> col;
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
            pos.insert(pos.end(), {static_cast<std::int16_t>(x - 4), 0, static_cast<std::int16_t>(z - 4)});
            const bool dark = (x + z) % 2 == 0;
            col.insert(col.end(), {static_cast<std::int8_t>(dark ? 40 : 70), static_cast<std::int8_t>(dark ? 90 : 120),
                                   static_cast<std::int8_t>(dark ? 50 : 60)});
        }
    Ref<VertexArray> positions(new VertexArray(n * n, 3, 2));
    positions->set(0, n * n, std::span<const std::int16_t>(pos));
    Ref<VertexArray> colors(new VertexArray(n * n, 3, 1));
    colors->set(0, n * n, std::span<const std::int8_t>(col));
    Ref<VertexBuffer> vb(new VertexBuffer());
    const float bias[3] = {0, -1.2f, 0};
    vb->setPositions(positions.get(), 1.0f, bias);
    vb->setColors(colors.get());
    // One strip per row of quads, from far to near.
    std::vector<int> indices, lengths;
    for (int z = 0; z + 1 < n; ++z) {
        for (int x = 0; x < n; ++x) {
            indices.push_back((z + 1) * n + x);
            indices.push_back(z * n + x);
        }
        lengths.push_back(2 * n);
    }
    Ref<IndexBuffer> strips(new TriangleStripArray(indices, lengths));
    Ref<Appearance> app(new Appearance());
    Ref<PolygonMode> pm(new PolygonMode());
    pm->setCulling(PolygonMode::CULL_NONE);
    pm->setShading(PolygonMode::SHADE_FLAT);
    app->setPolygonMode(pm.get());
    return Ref<Mesh>(new Mesh(vb.get(), strips.get(), app.get()));
}

Ref<World> buildSampleScene() {
    Ref<World> world(new World());
    Ref<Background> bg(new Background());
    bg->setColor(static_cast<int>(0xFF1E2838u));
    world->setBackground(bg.get());

    Ref<Camera> camera(new Camera());
    camera->setPerspective(50.0f, 4.0f / 3.0f, 0.5f, 50.0f);
    camera->setTranslation(0.0f, 1.4f, 5.0f);
    camera->setOrientation(-15.0f, 1.0f, 0.0f, 0.0f);
    world->addChild(camera.get());
    world->setActiveCamera(camera.get());

    Ref<Light> sun(new Light());
    sun->setMode(Light::DIRECTIONAL);
    sun->setOrientation(-40.0f, 1.0f, 1.0f, 0.0f);
    world->addChild(sun.get());
    Ref<Light> ambient(new Light());
    ambient->setMode(Light::AMBIENT);
    ambient->setIntensity(0.35f);
    world->addChild(ambient.get());

    Ref<Fog> fog(new Fog());
    fog->setMode(Fog::LINEAR);
    fog->setLinear(4.0f, 12.0f);
    fog->setColor(0x1E2838);

    Ref<Appearance> cubeLook(new Appearance());
    Ref<Material> material(new Material());
    material->setColor(Material::SPECULAR, static_cast<int>(0xFF808080u));
    material->setShininess(24.0f);
    cubeLook->setMaterial(material.get());
    Ref<Texture2D> texture(new Texture2D(checker().get()));
    texture->setFiltering(Texture2D::FILTER_LINEAR, Texture2D::FILTER_LINEAR);
    cubeLook->setTexture(0, texture.get());
    cubeLook->setFog(fog.get());
    Ref<Mesh> cube = makeCube(cubeLook.get());
    cube->setUserID(1);
    world->addChild(cube.get());

    Ref<Mesh> ground = makeGround();
    ground->getAppearance(0)->setFog(fog.get());
    ground->setUserID(2);
    world->addChild(ground.get());

    Ref<Appearance> spriteLook(new Appearance());
    Ref<CompositingMode> additive(new CompositingMode());
    additive->setBlending(CompositingMode::ALPHA_ADD);
    additive->setDepthWriteEnable(false);
    spriteLook->setCompositingMode(additive.get());
    spriteLook->setLayer(1);
    Ref<Sprite3D> sprite(new Sprite3D(true, glow().get(), spriteLook.get()));
    sprite->setTranslation(1.6f, 1.3f, -1.0f);
    sprite->setScale(1.2f, 1.2f, 1.2f);
    sprite->setUserID(3);
    world->addChild(sprite.get());

    // The cube turns once every 4 s (SLERP between five orientations).
    Ref<KeyframeSequence> spin(new KeyframeSequence(5, 4, KeyframeSequence::SLERP));
    for (int i = 0; i < 5; ++i) {
        const float half = static_cast<float>(i) * 3.14159265f / 4.0f;  // quarter turns about (0.3, 1, 0.2)
        const float ax = 0.3f, ay = 1.0f, az = 0.2f, len = std::sqrt(ax * ax + ay * ay + az * az);
        const float q[4] = {std::sin(half) * ax / len, std::sin(half) * ay / len, std::sin(half) * az / len, std::cos(half)};
        spin->setKeyframe(i, i * 1000, q);
    }
    spin->setDuration(4000);
    spin->setRepeatMode(KeyframeSequence::LOOP);
    Ref<AnimationController> controller(new AnimationController());
    Ref<AnimationTrack> track(new AnimationTrack(spin.get(), AnimationTrack::ORIENTATION));
    track->setController(controller.get());
    cube->addAnimationTrack(track.get());
    return world;
}

}  // namespace m3gcli
