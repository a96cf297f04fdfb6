// javax.microedition.m3g.Background (JSR-184 1.1, Background).
#pragma once

#include <m3g/Export.h>

#include <m3g/Object3D.h>

namespace m3g {

/// How the viewport is cleared: color, optional image with crop and
/// BORDER/REPEAT modes, color and depth clear enables.
class M3G_API Background : public Object3D {
public:
    static constexpr int BORDER = 32;
    static constexpr int REPEAT = 33;

    /// Color 0x00000000, no image, BORDER/BORDER, crop (0, 0, 0, 0), both clears on.
    Background();
    ~Background() override;

    void setColor(int ARGB) noexcept;
    int getColor() const noexcept;
    /// RGB or RGBA image, or null; IAE for other formats. Resets the crop to
    /// the whole image.
    void setImage(Image2D* image);
    Ref<Image2D> getImage() const;
    /// BORDER or REPEAT, else IAE.
    void setImageMode(int modeX, int modeY);
    int getImageModeX() const noexcept;
    int getImageModeY() const noexcept;
    /// IAE if width or height is negative or larger than maxViewportDimension.
    void setCrop(int cropX, int cropY, int width, int height);
    int getCropX() const noexcept;
    int getCropY() const noexcept;
    int getCropWidth() const noexcept;
    int getCropHeight() const noexcept;
    void setColorClearEnable(bool enable) noexcept;
    bool isColorClearEnabled() const noexcept;
    void setDepthClearEnable(bool enable) noexcept;
    bool isDepthClearEnabled() const noexcept;

    const char* getClassName() const noexcept override { return "Background"; }
    bool isAnimatable(int property) const noexcept override;
    void updateProperty(int property, std::span<const float> value) override;

protected:
    Background(const Background& other);
    /// Order: image.
    void collectReferences(std::vector<Object3D*>& out) const override;
    Object3D* duplicateImpl(DuplicateMap& map) const override;

private:
    int color_ = 0x00000000;
    Ref<Image2D> image_;
    int modeX_ = BORDER;
    int modeY_ = BORDER;
    int cropX_ = 0, cropY_ = 0, cropWidth_ = 0, cropHeight_ = 0;
    bool colorClear_ = true;
    bool depthClear_ = true;
};

}  // namespace m3g
