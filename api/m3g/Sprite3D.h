// javax.microedition.m3g.Sprite3D (JSR-184 1.1, Sprite3D).
#pragma once

#include <m3g/Export.h>

#include <m3g/Node.h>

namespace m3g {

/// A screen-aligned image drawn at the projected origin of the node, scaled
/// (1x1 local units) or unscaled (crop size in pixels). Only the
/// Appearance's CompositingMode and Fog (and its layer) are used.
class M3G_API Sprite3D : public Node {
public:
    /// NPE if image is null; appearance may be null (the sprite is then
    /// neither rendered nor picked). The crop is the whole image.
    Sprite3D(bool scaled, Image2D* image, Appearance* appearance);
    ~Sprite3D() override;

    bool isScaled() const noexcept { return scaled_; }
    void setAppearance(Appearance* appearance);
    Ref<Appearance> getAppearance() const;
    /// NPE if null. Resets the crop to (0, 0, width, height) of the image.
    void setImage(Image2D* image);
    Ref<Image2D> getImage() const;
    /// IAE if |width| or |height| > Limits::maxSpriteCropDimension. Negative
    /// width/height mirror the image in X/Y; x, y are unrestricted.
    void setCrop(int cropX, int cropY, int width, int height);
    int getCropX() const noexcept { return cropX_; }
    int getCropY() const noexcept { return cropY_; }
    int getCropWidth() const noexcept { return cropWidth_; }
    int getCropHeight() const noexcept { return cropHeight_; }

    const char* getClassName() const noexcept override { return "Sprite3D"; }
    /// CROP plus the Node properties.
    bool isAnimatable(int property) const noexcept override;
    /// CROP: 2 components set x, y; 4 set x, y, width, height. Values are
    /// rounded to the nearest integer (halves up); width and height are then
    /// clamped to [-maxSpriteCropDimension, maxSpriteCropDimension].
    void updateProperty(int property, std::span<const float> value) override;

protected:
    Sprite3D(const Sprite3D& other);
    /// Order: image, appearance.
    void collectReferences(std::vector<Object3D*>& out) const override;
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    bool scaled_;
    Ref<Image2D> image_;
    Ref<Appearance> appearance_;
    int cropX_ = 0, cropY_ = 0, cropWidth_ = 0, cropHeight_ = 0;
};

}  // namespace m3g
