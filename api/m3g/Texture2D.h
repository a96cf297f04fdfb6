// javax.microedition.m3g.Texture2D (JSR-184 1.1, Texture2D).
#pragma once

#include <m3g/Export.h>

#include <m3g/Transformable.h>

namespace m3g {

/// A texture: an Image2D plus filtering, wrapping, blending function and
/// blend color. Its Transformable part is the texture-coordinate transform and
/// may be any (projective) matrix.
class M3G_API Texture2D : public Transformable {
public:
    static constexpr int FILTER_BASE_LEVEL = 208;
    static constexpr int FILTER_LINEAR = 209;
    static constexpr int FILTER_NEAREST = 210;
    static constexpr int FUNC_ADD = 224;
    static constexpr int FUNC_BLEND = 225;
    static constexpr int FUNC_DECAL = 226;
    static constexpr int FUNC_MODULATE = 227;
    static constexpr int FUNC_REPLACE = 228;
    static constexpr int WRAP_CLAMP = 240;
    static constexpr int WRAP_REPEAT = 241;

    /// Blend color 0x000000, FUNC_MODULATE, WRAP_REPEAT/WRAP_REPEAT,
    /// FILTER_BASE_LEVEL/FILTER_NEAREST, identity transform. NPE/IAE as setImage.
    explicit Texture2D(Image2D* image);
    ~Texture2D() override;

    /// NPE if null; IAE unless width and height are powers of two and at most
    /// Limits::maxTextureDimension. A mutable image may be used; later changes
    /// to it are seen by the texture.
    void setImage(Image2D* image);
    Ref<Image2D> getImage() const;

    /// levelFilter in {FILTER_BASE_LEVEL, FILTER_NEAREST, FILTER_LINEAR},
    /// imageFilter in {FILTER_NEAREST, FILTER_LINEAR}, else IAE.
    void setFiltering(int levelFilter, int imageFilter);
    int getLevelFilter() const noexcept { return levelFilter_; }
    int getImageFilter() const noexcept { return imageFilter_; }
    /// Each of WRAP_CLAMP or WRAP_REPEAT, else IAE.
    void setWrapping(int wrapS, int wrapT);
    int getWrappingS() const noexcept { return wrapS_; }
    int getWrappingT() const noexcept { return wrapT_; }
    /// One of FUNC_ADD, FUNC_BLEND, FUNC_DECAL, FUNC_MODULATE, FUNC_REPLACE, else IAE.
    void setBlending(int func);
    int getBlending() const noexcept { return blending_; }
    /// 0x00RRGGBB; the top byte is cleared.
    void setBlendColor(int RGB) noexcept;
    int getBlendColor() const noexcept { return blendColor_; }

    const char* getClassName() const noexcept override { return "Texture2D"; }
    /// COLOR (the blend color) plus the Transformable properties.
    bool isAnimatable(int property) const noexcept override;
    /// COLOR: 3 components clamped to [0, 1], stored as bytes (round(v * 255)).
    void updateProperty(int property, std::span<const float> value) override;

protected:
    Texture2D(const Texture2D& other);
    /// Order: image.
    void collectReferences(std::vector<Object3D*>& out) const override;
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    Ref<Image2D> image_;
    int blendColor_ = 0x000000;
    int blending_ = FUNC_MODULATE;
    int wrapS_ = WRAP_REPEAT;
    int wrapT_ = WRAP_REPEAT;
    int levelFilter_ = FILTER_BASE_LEVEL;
    int imageFilter_ = FILTER_NEAREST;
};

}  // namespace m3g
