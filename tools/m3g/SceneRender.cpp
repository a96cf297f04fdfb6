#include "SceneRender.h"

#include "UpAxis.h"

#include <stdexcept>
#include <vector>

namespace m3gcli {

using namespace m3g;

RgbaImage renderWorldImage(World& world, int width, int height, bool keepAlpha) {
    Graphics3D* g = Graphics3D::getInstance();
    Ref<Graphics> surface;
    Ref<Image2D> image;
    if (keepAlpha) {
        image = new Image2D(Image2D::RGBA, width, height);
        g->bindTarget(image.get(), true, 0);
    } else {
        surface = new Graphics(width, height);
        g->bindTarget(surface.get(), true, 0);
    }
    try {
        g->setViewport(0, 0, width, height);
        g->render(&world);
    } catch (...) {
        g->releaseTarget();
        throw;
    }
    g->releaseTarget();
    if (!keepAlpha) return fromGraphics(*surface);
    RgbaImage out;
    out.width = width;
    out.height = height;
    image->getPixelsRGBA8(out.pixels);
    return out;
}

void overrideBackground(World& world, std::uint32_t argb) {
    Ref<Background> bg(new Background());
    bg->setColor(static_cast<int>(argb));
    bg->setColorClearEnable(true);
    bg->setDepthClearEnable(true);
    world.setBackground(bg.get());
}

CameraOrbit::CameraOrbit(Camera& camera, World& world, const std::array<float, 3>& center)
    : CameraOrbit(camera, world, center, sceneUp(world)) {}

CameraOrbit::CameraOrbit(Camera& camera, World& world, const std::array<float, 3>& center,
                         const std::array<float, 3>& up)
    : camera_(&camera), center_(center), up_(up) {
    if (!camera.getTransformTo(&world, &cameraToWorld_))
        throw std::invalid_argument("CameraOrbit: the camera is not in the World");
    if (Node* parent = camera.getParent().get()) {
        parent->getTransformTo(&world, &worldToParent_);
        worldToParent_.invert();  // ArithmeticException for a singular parent: no orbit then
    }
}

void CameraOrbit::setAngle(float degrees) {
    if (degrees == 0.0f && !moved_) return;
    Transform local = worldToParent_;
    local.postTranslate(center_[0], center_[1], center_[2]);
    local.postRotate(degrees, up_[0], up_[1], up_[2]);
    local.postTranslate(-center_[0], -center_[1], -center_[2]);
    local.postMultiply(&cameraToWorld_);
    camera_->setTranslation(0.0f, 0.0f, 0.0f);
    camera_->setOrientation(0.0f, 0.0f, 0.0f, 1.0f);
    camera_->setScale(1.0f, 1.0f, 1.0f);
    camera_->setTransform(&local);
    moved_ = true;
}

}  // namespace m3gcli
