// javax.microedition.m3g.Appearance (JSR-184 1.1, Appearance).
#pragma once

#include <m3g/Export.h>

#include <array>

#include <m3g/Limits.h>
#include <m3g/Object3D.h>

namespace m3g {

/// The rendering attributes of a submesh or sprite: layer, compositing mode,
/// fog, polygon mode, material and one texture per texture unit. A null
/// component means its defaults (null Material: lighting off; null Fog: no fog).
class M3G_API Appearance : public Object3D {
public:
    Appearance();
    ~Appearance() override;

    /// layer in [-63, 63], else IAE. Lower layers are drawn first.
    void setLayer(int layer);
    int getLayer() const noexcept;

    void setCompositingMode(CompositingMode* compositingMode);
    Ref<CompositingMode> getCompositingMode() const;
    void setFog(Fog* fog);
    Ref<Fog> getFog() const;
    void setPolygonMode(PolygonMode* polygonMode);
    Ref<PolygonMode> getPolygonMode() const;
    void setMaterial(Material* material);
    Ref<Material> getMaterial() const;
    /// IOOBE unless 0 <= index < numTextureUnits (Limits).
    void setTexture(int index, Texture2D* texture);
    Ref<Texture2D> getTexture(int index) const;

    const char* getClassName() const noexcept override { return "Appearance"; }

protected:
    Appearance(const Appearance& other);
    /// Order: compositing mode, fog, polygon mode, material, textures by unit.
    void collectReferences(std::vector<Object3D*>& out) const override;
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    int layer_ = 0;
    Ref<CompositingMode> compositingMode_;
    Ref<Fog> fog_;
    Ref<PolygonMode> polygonMode_;
    Ref<Material> material_;
    std::array<Ref<Texture2D>, kMaxTextureUnits> textures_;
};

}  // namespace m3g
