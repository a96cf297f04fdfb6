// The screen geometry of a Sprite3D (JSR-184 1.1, Sprite3D; Nokia's
// m3gGetSpriteCoordinates), shared by the renderer (to draw sprites) and by
// Group::pick (to hit scaled sprites).
#pragma once

#include <m3g/Forward.h>

namespace m3g::detail {

/// Where a sprite lands on screen.
///
/// The crop rectangle is (cropX, cropY, |cropWidth|, |cropHeight|) in image
/// pixels (rows from the top); a negative width or height mirrors the
/// displayed image horizontally or vertically. The sprite origin projects to
/// the centre of the *whole* crop rectangle; only the part of the crop that
/// lies inside the image is drawn, at the place it would have inside the whole
/// (mirrored) crop rectangle, so the drawn rectangle is off-centre when the
/// crop sticks out of the image.
///
/// Size of one crop pixel on screen: unscaled sprites 1 viewport pixel;
/// scaled sprites 1/|cropWidth| (1/|cropHeight|) of the projected width
/// (height) of a 1 x 1 square in the sprite's local XY plane, measured with the
/// eye-space lengths of the local half axes (0.5, 0, 0) and (0, 0.5, 0) laid
/// along eye X and eye Y at the origin's depth and then projected (so the
/// sprite stays screen aligned whatever its rotation).
///
/// When the origin is in front of the camera (clipW > 0) and crop ∩ image is
/// not empty, every field is filled even if `visible` is false because the
/// origin lies outside the near..far range (ndcZ outside [-1, 1]): picking uses
/// the rectangle regardless of depth, as it does for meshes.
struct SpriteRect {
    bool visible = false;   // false when the origin is behind the camera/outside near..far, or the rectangle is empty
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // the drawn rectangle in NDC (x right, y up), x0 < x1, y0 < y1: only the part showing crop ∩ image
    float ndcZ = 0;         // NDC depth of the sprite origin (OpenGL convention -1..1); the whole sprite has this depth
    float clipW = 1;        // clip-space w of the origin
    float eyeDepth = 0;     // -z of the origin in eye space (fog distance)
    float s0 = 0, t0 = 0, s1 = 0, t1 = 0;  // normalised image coordinates (t = 0 at the top row) at the corner (x0, y1) and at the corner (x1, y0); negative crop sizes flip
};

/// spriteToEye: model-view of the sprite node; projection: camera projection
/// (Camera::getProjection); viewport size in pixels (unscaled sprites are
/// |cropWidth| x |cropHeight| pixels).
SpriteRect projectSprite(const Sprite3D& sprite, const Transform& spriteToEye, const Transform& projection,
                         int viewportWidth, int viewportHeight);

}  // namespace m3g::detail
