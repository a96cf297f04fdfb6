#include "SpriteProjection.h"

#include <algorithm>
#include <cmath>

#include <m3g/Image2D.h>
#include <m3g/Sprite3D.h>

#include "MathUtil.h"

namespace m3g::detail {

namespace {

glm::vec3 dehomogenise(const glm::vec4& v) noexcept { return glm::vec3(v) / v.w; }

}  // namespace

SpriteRect projectSprite(const Sprite3D& sprite, const Transform& spriteToEye, const Transform& projection,
                         int viewportWidth, int viewportHeight) {
    SpriteRect r;
    const Image2D* image = sprite.getImage().get();
    if (!image) return r;
    const long long imageW = image->getWidth(), imageH = image->getHeight();

    // Crop rectangle (absolute size, flips separate) and its part inside the image.
    const long long cropX = sprite.getCropX(), cropY = sprite.getCropY();
    const long long cropW = std::llabs(sprite.getCropWidth()), cropH = std::llabs(sprite.getCropHeight());
    const bool flipX = sprite.getCropWidth() < 0, flipY = sprite.getCropHeight() < 0;
    if (cropW == 0 || cropH == 0) return r;
    const long long ix0 = std::max(cropX, 0LL), ix1 = std::min(cropX + cropW, imageW);
    const long long iy0 = std::max(cropY, 0LL), iy1 = std::min(cropY + cropH, imageH);
    if (ix1 <= ix0 || iy1 <= iy0) return r;

    const glm::mat4 modelView = toGlm(spriteToEye);
    const glm::mat4 proj = toGlm(projection);
    const glm::vec3 eye = dehomogenise(modelView * glm::vec4(0, 0, 0, 1));
    const glm::vec4 clip = proj * glm::vec4(eye, 1.0f);
    r.eyeDepth = -eye.z;
    r.clipW = clip.w;
    if (!(clip.w > 0.0f)) return r;  // behind the camera (or degenerate)
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    r.ndcZ = ndc.z;

    // NDC size of one crop pixel.
    float texelW, texelH;
    if (sprite.isScaled()) {
        const float halfX = glm::length(dehomogenise(modelView * glm::vec4(0.5f, 0, 0, 1)) - eye);
        const float halfY = glm::length(dehomogenise(modelView * glm::vec4(0, 0.5f, 0, 1)) - eye);
        const glm::vec4 px = proj * glm::vec4(eye.x + halfX, eye.y, eye.z, 1.0f);
        const glm::vec4 py = proj * glm::vec4(eye.x, eye.y + halfY, eye.z, 1.0f);
        const float ndcHalfX = glm::length(dehomogenise(px) - ndc);
        const float ndcHalfY = glm::length(dehomogenise(py) - ndc);
        texelW = 2.0f * ndcHalfX / static_cast<float>(cropW);
        texelH = 2.0f * ndcHalfY / static_cast<float>(cropH);
    } else {
        if (viewportWidth <= 0 || viewportHeight <= 0) return r;
        texelW = 2.0f / static_cast<float>(viewportWidth);
        texelH = 2.0f / static_cast<float>(viewportHeight);
    }

    // Offset (in crop pixels, image axes) of the visible part's centre from the
    // crop centre; mirrored along a flipped axis; image y grows downwards.
    const double dx = 0.5 * static_cast<double>(ix0 + ix1) - (static_cast<double>(cropX) + 0.5 * cropW);
    const double dy = 0.5 * static_cast<double>(iy0 + iy1) - (static_cast<double>(cropY) + 0.5 * cropH);
    const float cx = ndc.x + static_cast<float>(flipX ? -dx : dx) * texelW;
    const float cy = ndc.y + static_cast<float>(flipY ? dy : -dy) * texelH;
    const float halfW = 0.5f * static_cast<float>(ix1 - ix0) * texelW;
    const float halfH = 0.5f * static_cast<float>(iy1 - iy0) * texelH;
    r.x0 = cx - halfW;
    r.x1 = cx + halfW;
    r.y0 = cy - halfH;
    r.y1 = cy + halfH;

    const float w = static_cast<float>(imageW), h = static_cast<float>(imageH);
    r.s0 = static_cast<float>(flipX ? ix1 : ix0) / w;
    r.s1 = static_cast<float>(flipX ? ix0 : ix1) / w;
    r.t0 = static_cast<float>(flipY ? iy1 : iy0) / h;  // top edge (y1)
    r.t1 = static_cast<float>(flipY ? iy0 : iy1) / h;  // bottom edge (y0)

    const bool finite = std::isfinite(r.x0) && std::isfinite(r.x1) && std::isfinite(r.y0) && std::isfinite(r.y1);
    r.visible = finite && r.x0 < r.x1 && r.y0 < r.y1 && r.ndcZ >= -1.0f && r.ndcZ <= 1.0f;
    return r;
}

}  // namespace m3g::detail
