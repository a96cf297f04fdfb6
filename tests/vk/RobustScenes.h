// Scenes for the robustness device tests (test_InFlight, test_Threading):
// a World that exercises every kind of GPU mirror the renderer keeps
// (vertex and index buffers, textures of a lit mesh, a sprite image and a
// background image) and an immediate-mode draw built afresh every frame.
// `variant` changes colours and placement, so that two threads rendering
// two variants produce different, recognisable images.
#pragma once

#include <cstdint>
#include <vector>

#include <m3g/m3g.h>

#include "SceneKit.h"

namespace m3gtest {

/// An RGBA image of `w` x `h` texels, texel (x, y) = (x*64+seed, y*64+2*seed, seed*3, 255) mod 256.
inline m3g::Ref<m3g::Image2D> patternImage(int w, int h, int seed) {
    std::vector<std::uint8_t> v;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            v.insert(v.end(), {static_cast<std::uint8_t>(x * 64 + seed), static_cast<std::uint8_t>(y * 64 + 2 * seed),
                               static_cast<std::uint8_t>(seed * 3), 255});
    return m3g::Ref<m3g::Image2D>(new m3g::Image2D(m3g::Image2D::RGBA, w, h, std::span<const std::uint8_t>(v)));
}

/// A World under an identity camera (NDC = world coordinates): a
/// background with an RGBA image in its left half, a lit, textured quad
/// (directional light, Material), an alpha-blended vertex-coloured quad and
/// an unscaled sprite. Render into an RGBA target.
inline m3g::Ref<m3g::World> robustWorld(int variant) {
    using namespace m3g;
    Ref<World> world(new World());
    Ref<Camera> cam(new Camera());
    world->addChild(cam.get());
    world->setActiveCamera(cam.get());

    Ref<Background> bg(new Background());
    bg->setColor(static_cast<int>(0xFF000000u | static_cast<std::uint32_t>(variant * 40)));
    bg->setImage(patternImage(4, 4, 7 + variant).get());
    bg->setImageMode(Background::BORDER, Background::BORDER);
    bg->setCrop(0, 0, 8, 4);  // the image covers the left half; the colour shows on the right
    world->setBackground(bg.get());

    Ref<Light> light(new Light());
    light->setMode(Light::DIRECTIONAL);
    light->setColor(0xFFFFFF);
    world->addChild(light.get());  // shines down -Z: onto the quads' +Z faces

    Quad lit = makeQuad(-0.75f, -0.75f + 0.1f * static_cast<float>(variant), 0.25f, 0.25f);
    Ref<Appearance> litApp(new Appearance());
    Ref<Material> material(new Material());
    material->setColor(Material::DIFFUSE, static_cast<int>(0xFFC0C0C0u - static_cast<std::uint32_t>(variant) * 0x202000u));
    litApp->setMaterial(material.get());
    Ref<Texture2D> texture(new Texture2D(patternImage(4, 4, 20 * variant + 1).get()));
    texture->setFiltering(Texture2D::FILTER_BASE_LEVEL, Texture2D::FILTER_NEAREST);
    litApp->setTexture(0, texture.get());
    Ref<Mesh> litMesh(new Mesh(lit.vb.get(), lit.ib.get(), litApp.get()));
    world->addChild(litMesh.get());

    Quad blended = makeQuad(-0.25f, -0.25f, 0.75f, 0.75f - 0.1f * static_cast<float>(variant), 0.5f);
    setColors(*blended.vb, {0x80FF0000u, 0x8000FF00u, 0x800000FFu, 0x80FFFFFFu - static_cast<std::uint32_t>(variant)});
    Ref<Appearance> blendApp(new Appearance());
    Ref<CompositingMode> cm(new CompositingMode());
    cm->setBlending(CompositingMode::ALPHA);
    blendApp->setCompositingMode(cm.get());
    Ref<Mesh> blendMesh(new Mesh(blended.vb.get(), blended.ib.get(), blendApp.get()));
    world->addChild(blendMesh.get());

    Ref<Appearance> spriteApp(new Appearance());
    Ref<Sprite3D> sprite(new Sprite3D(false, patternImage(8, 8, 90 + variant).get(), spriteApp.get()));
    sprite->setTranslation(0.5f, -0.5f - 0.125f * static_cast<float>(variant), 0.25f);
    world->addChild(sprite.get());
    return world;
}

/// An immediate-mode draw made of objects created for this frame alone: a
/// textured, vertex-coloured quad whose place and texture follow `frame`.
struct ImmediateDraw {
    Quad quad;
    m3g::Ref<m3g::Appearance> appearance;
};

inline ImmediateDraw immediateDraw(int frame, int size) {
    using namespace m3g;
    const int x = (frame * 5) % (size - 8);
    ImmediateDraw d{pixelQuad(x, size - 10, x + 8, size - 2, size), new Appearance()};
    setColors(*d.quad.vb, {0xFFFFFFFFu, 0xFFFFFF00u, 0xFF00FFFFu, 0xFFFF00FFu});
    Ref<Texture2D> t(new Texture2D(patternImage(2, 2, frame * 13).get()));
    t->setFiltering(Texture2D::FILTER_BASE_LEVEL, Texture2D::FILTER_NEAREST);
    d.appearance->setTexture(0, t.get());
    return d;
}

}  // namespace m3gtest
