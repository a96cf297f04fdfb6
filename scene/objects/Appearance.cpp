#include <m3g/Appearance.h>

#include <m3g/CompositingMode.h>
#include <m3g/Fog.h>
#include <m3g/Material.h>
#include <m3g/PolygonMode.h>
#include <m3g/Texture2D.h>

#include "Check.h"

namespace m3g {

Appearance::Appearance() = default;

// Components are shared with the original (Ref copies), per duplicate().
Appearance::Appearance(const Appearance& other) = default;

Appearance::~Appearance() = default;

Object3D* Appearance::duplicateImpl(DuplicateMap&) const { return new Appearance(*this); }

void Appearance::setLayer(int layer) {
    detail::requireRange(layer, -63, 63, "Appearance::setLayer", "layer");
    layer_ = layer;
    touch();
}

int Appearance::getLayer() const noexcept { return layer_; }

void Appearance::setCompositingMode(CompositingMode* compositingMode) {
    compositingMode_ = compositingMode;
    touch();
}

Ref<CompositingMode> Appearance::getCompositingMode() const { return compositingMode_; }

void Appearance::setFog(Fog* fog) {
    if (fog_.get() != fog) referencesChanged();
    fog_ = fog;
    touch();
}

Ref<Fog> Appearance::getFog() const { return fog_; }

void Appearance::setPolygonMode(PolygonMode* polygonMode) {
    polygonMode_ = polygonMode;
    touch();
}

Ref<PolygonMode> Appearance::getPolygonMode() const { return polygonMode_; }

void Appearance::setMaterial(Material* material) {
    if (material_.get() != material) referencesChanged();
    material_ = material;
    touch();
}

Ref<Material> Appearance::getMaterial() const { return material_; }

void Appearance::setTexture(int index, Texture2D* texture) {
    detail::requireIndex(index, getLimits().numTextureUnits, "Appearance::setTexture", "index");
    if (textures_[static_cast<std::size_t>(index)].get() != texture) referencesChanged();
    textures_[static_cast<std::size_t>(index)] = texture;
    touch();
}

Ref<Texture2D> Appearance::getTexture(int index) const {
    detail::requireIndex(index, getLimits().numTextureUnits, "Appearance::getTexture", "index");
    return textures_[static_cast<std::size_t>(index)];
}

void Appearance::collectReferences(std::vector<Object3D*>& out) const {
    Object3D::collectReferences(out);
    if (compositingMode_) out.push_back(compositingMode_.get());
    if (fog_) out.push_back(fog_.get());
    if (polygonMode_) out.push_back(polygonMode_.get());
    if (material_) out.push_back(material_.get());
    for (const auto& t : textures_)
        if (t) out.push_back(t.get());
}

}  // namespace m3g
