#include <m3g/Graphics3D.h>

#include <m3g/Version.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "Check.h"
#include "FrameState.h"

namespace m3g {

namespace {
constexpr int kAllHints = Graphics3D::ANTIALIAS | Graphics3D::DITHER | Graphics3D::TRUE_COLOR | Graphics3D::OVERWRITE;

/// M3G_SKINNING: "cpu" or "compute" (case-insensitive); unset or empty: CPU.
/// Anything else is reported on stderr once and means CPU: a test setting
/// a wrong value must see why its choice did not take.
int skinningModeFromEnvironment() {
    const char* value = std::getenv("M3G_SKINNING");
    if (!value || !*value) return Graphics3D::SKINNING_CPU;
    std::string v(value);
    for (char& c : v) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (v == "cpu") return Graphics3D::SKINNING_CPU;
    if (v == "compute") return Graphics3D::SKINNING_COMPUTE;
    std::fprintf(stderr, "m3g-vk: M3G_SKINNING=\"%s\" is not cpu or compute; skinning on the CPU\n", value);
    return Graphics3D::SKINNING_CPU;
}

}  // namespace

Graphics3D::Graphics3D()
    : skinningMode_(skinningModeFromEnvironment()) {}

void Graphics3D::setSkinningMode(int mode) {
    if (mode != SKINNING_CPU && mode != SKINNING_COMPUTE)
        throw IllegalArgumentException(detail::str("Graphics3D::setSkinningMode: mode ", mode,
                                                   " is not SKINNING_CPU (0) or SKINNING_COMPUTE (1)"));
    skinningMode_ = mode;
}

Graphics3D::~Graphics3D() { releaseRenderer(); }

std::unique_ptr<Graphics3D> Graphics3D::create() { return std::unique_ptr<Graphics3D>(new Graphics3D()); }

void Graphics3D::requireTarget(const char* where) const {
    if (!target_) throw IllegalStateException(detail::str(where, ": no target is bound (call bindTarget first)"));
}

Graphics3D* Graphics3D::getInstance() {
    static Graphics3D instance;
    return &instance;
}

std::map<std::string, Graphics3D::Property> Graphics3D::getProperties() {
    const Limits& l = getLimits();
    return {
        {"supportAntialiasing", l.supportAntialiasing},
        {"supportTrueColor", l.supportTrueColor},
        {"supportDithering", l.supportDithering},
        {"supportMipmapping", l.supportMipmapping},
        {"supportPerspectiveCorrection", l.supportPerspectiveCorrection},
        {"supportLocalCameraLighting", l.supportLocalCameraLighting},
        {"maxLights", l.maxLights},
        {"maxViewportWidth", l.maxViewportWidth},
        {"maxViewportHeight", l.maxViewportHeight},
        {"maxViewportDimension", l.maxViewportDimension},
        {"maxTextureDimension", l.maxTextureDimension},
        {"maxSpriteCropDimension", l.maxSpriteCropDimension},
        {"maxTransformsPerVertex", l.maxTransformsPerVertex},
        {"numTextureUnits", l.numTextureUnits},
        {"m3gRelease", std::string("m3g-vk ") + kVersionString},
    };
}

void Graphics3D::bindCommon(RefCounted* target, int width, int height, bool depthBuffer, int hints,
                            const char* where) {
    if (target_) throw IllegalStateException(detail::str(where, ": a target is already bound (call releaseTarget first)"));
    if (hints & ~kAllHints)
        throw IllegalArgumentException(detail::str(where, ": hints 0x", std::hex, hints,
                                                   " has bits other than ANTIALIAS|DITHER|TRUE_COLOR|OVERWRITE (0x1e)"));
    const Limits& l = getLimits();
    if (width > l.maxViewportWidth || height > l.maxViewportHeight)
        throw IllegalArgumentException(detail::str(where, ": target size ", width, " x ", height,
                                                   " exceeds maxViewportWidth x maxViewportHeight = ",
                                                   l.maxViewportWidth, " x ", l.maxViewportHeight));
    target_ = target;
    targetWidth_ = width;
    targetHeight_ = height;
    depthBuffer_ = depthBuffer;
    hints_ = hints;
}

void Graphics3D::bindTarget(Graphics* target, bool depthBuffer, int hints) {
    const char* where = "Graphics3D::bindTarget";
    detail::requireNonNull(target, where, "target");
    bindCommon(target, target->getWidth(), target->getHeight(), depthBuffer, hints, where);
    targetGraphics_ = target;
    // The default viewport is the clip rectangle, in translated coordinates.
    viewport_[0] = target->getClipX();
    viewport_[1] = target->getClipY();
    viewport_[2] = target->getClipWidth();
    viewport_[3] = target->getClipHeight();
}

void Graphics3D::bindTarget(Image2D* target, bool depthBuffer, int hints) {
    const char* where = "Graphics3D::bindTarget";
    detail::requireNonNull(target, where, "target");
    if (!target->isMutable())
        throw IllegalArgumentException("Graphics3D::bindTarget: the Image2D is immutable (a target must be mutable)");
    if (target->getFormat() != Image2D::RGB && target->getFormat() != Image2D::RGBA)
        throw IllegalArgumentException(detail::str("Graphics3D::bindTarget: Image2D format ", target->getFormat(),
                                                   " is not RGB (99) or RGBA (100)"));
    bindCommon(target, target->getWidth(), target->getHeight(), depthBuffer, hints, where);
    targetImage_ = target;
    viewport_[0] = 0;
    viewport_[1] = 0;
    viewport_[2] = target->getWidth();
    viewport_[3] = target->getHeight();
}

void Graphics3D::releaseTarget() {
    if (!target_) return;
    // Unbind even if the flush throws (a lost device must not leave the target bound).
    struct Unbind {
        Graphics3D& g;
        ~Unbind() {
            g.target_ = nullptr;
            g.targetImage_ = nullptr;
            g.targetGraphics_ = nullptr;
            g.targetWidth_ = g.targetHeight_ = 0;
            g.depthBuffer_ = false;
            g.hints_ = 0;
            if (g.frame_) {
                g.frame_->imagePixels.reset();
                g.frame_->graphicsPixels.reset();
            }
        }
    } unbind{*this};
    if (frame_ && frame_->backend) frame_->backend->release(frameTarget(), frame_->builder.sweep());
}

void Graphics3D::releaseRenderer() noexcept {
    try {
        releaseTarget();
    } catch (...) {
        // The renderer goes anyway.
    }
    if (frame_) frame_->backend.reset();
}

void Graphics3D::setViewport(int x, int y, int width, int height) {
    const Limits& l = getLimits();
    detail::requireRange(width, 1, l.maxViewportWidth, "Graphics3D::setViewport", "width");
    detail::requireRange(height, 1, l.maxViewportHeight, "Graphics3D::setViewport", "height");
    viewport_[0] = x;
    viewport_[1] = y;
    viewport_[2] = width;
    viewport_[3] = height;
}

void Graphics3D::setDepthRange(float near, float far) {
    detail::requireRange(near, 0.0f, 1.0f, "Graphics3D::setDepthRange", "near");
    detail::requireRange(far, 0.0f, 1.0f, "Graphics3D::setDepthRange", "far");
    depthNear_ = near;
    depthFar_ = far;
}

void Graphics3D::setCamera(Camera* camera, const Transform* transform) {
    Transform toWorld = transform ? *transform : Transform();
    Transform inverse = toWorld;
    if (camera) {
        try {
            inverse.invert();
        } catch (const ArithmeticException&) {
            throw ArithmeticException("Graphics3D::setCamera: the camera-to-world transform is singular");
        }
    }
    camera_ = camera;
    cameraToWorld_ = toWorld;
    worldToCamera_ = inverse;
}

Ref<Camera> Graphics3D::getCamera(Transform* transform) const {
    if (transform && camera_) *transform = cameraToWorld_;
    return camera_;
}

int Graphics3D::addLight(Light* light, const Transform* transform) {
    detail::requireNonNull(light, "Graphics3D::addLight", "light");
    lights_.push_back({light, transform ? *transform : Transform()});
    return static_cast<int>(lights_.size()) - 1;
}

void Graphics3D::setLight(int index, Light* light, const Transform* transform) {
    detail::requireIndex(index, getLightCount(), "Graphics3D::setLight", "index");
    lights_[index] = {light, transform ? *transform : Transform()};
}

void Graphics3D::resetLights() noexcept { lights_.clear(); }

Ref<Light> Graphics3D::getLight(int index, Transform* transform) const {
    detail::requireIndex(index, getLightCount(), "Graphics3D::getLight", "index");
    if (transform && lights_[index].light) *transform = lights_[index].toWorld;
    return lights_[index].light;
}

}  // namespace m3g
