// Graphics3D's clear() and render() (JSR-184 1.1, Graphics3D): the checks,
// the collect step (RenderQueue), frame preparation (FrameBuilder: deform,
// translate state) and the hand-over of a plain DrawList to the back end.
#include <cstdlib>

#include <m3g/Appearance.h>
#include <m3g/Background.h>
#include <m3g/Graphics3D.h>
#include <m3g/Group.h>
#include <m3g/Image2D.h>
#include <m3g/IndexBuffer.h>
#include <m3g/Mesh.h>
#include <m3g/Sprite3D.h>
#include <m3g/VertexBuffer.h>
#include <m3g/World.h>

#include "Check.h"
#include "FrameState.h"
#include "NullBackend.h"

namespace m3g {

namespace {

/// The Image2D format the target's pixels have (RGB for a Graphics surface).
int targetFormat(const Graphics3D& g) { return g.targetImage() ? g.targetImage()->getFormat() : Image2D::RGB; }

bool backgroundMatches(const Graphics3D& g, const Background* background) {
    const Image2D* image = background ? background->getImage().get() : nullptr;
    return !image || image->getFormat() == targetFormat(g);
}

}  // namespace

detail::FrameState& Graphics3D::frame() {
    if (!frame_) frame_ = std::make_unique<detail::FrameState>();
    if (!frame_->backend) {
        const frame::BackendFactory factory = frame::backendFactory();
        frame_->backend = factory ? factory() : std::make_unique<detail::NullBackend>();
        // Free GPU state before the driver's and the validation layer's own
        // static destructors run (they were set up before this handler).
        static const bool registered = [] {
            std::atexit([] { Graphics3D::getInstance()->releaseRenderer(); });
            return true;
        }();
        (void)registered;
    }
    detail::FrameState& f = *frame_;
    if (targetImage_ && !f.imagePixels) f.imagePixels.emplace(*targetImage_);
    if (targetGraphics_ && !f.graphicsPixels) f.graphicsPixels.emplace(*targetGraphics_);
    return f;
}

frame::Target Graphics3D::frameTarget() const {
    frame::Target t;
    t.width = targetWidth_;
    t.height = targetHeight_;
    t.depthBuffer = depthBuffer_;
    t.hints = hints_;
    if (frame_ && targetImage_ && frame_->imagePixels) t.pixels = &*frame_->imagePixels;
    if (frame_ && targetGraphics_ && frame_->graphicsPixels) t.pixels = &*frame_->graphicsPixels;
    t.identity = targetGraphics_ ? static_cast<const void*>(targetGraphics_) : static_cast<const void*>(targetImage_);
    return t;
}

void Graphics3D::useBackend(std::unique_ptr<frame::FrameBackend> backend) {
    releaseTarget();
    if (!frame_) frame_ = std::make_unique<detail::FrameState>();
    frame_->backend = std::move(backend);
}

void Graphics3D::drawClear(const Background* background) {
    detail::FrameState& f = frame();
    const frame::ViewState view = detail::viewState(*this);
    frame::DrawList& list = f.clearList;
    list.reset();
    const frame::DrawOptions options = f.backend->options();
    list.clear = detail::translateClear(background, view, targetWidth_, targetHeight_, options.vulkanClipSpace,
                                        list.uniforms);
    if (list.clear.hasImage) f.builder.track(*background->getImage());
    f.backend->clear(frameTarget(), view, list, f.builder);
}

void Graphics3D::prepareQueue() {
    detail::FrameState& f = frame();
    f.view = detail::viewState(*this);
    f.builder.build(f.queue, f.view, skinningMode_ == SKINNING_COMPUTE, f.backend->options(), f.list);
}

void Graphics3D::drawPrepared() {
    detail::FrameState& f = *frame_;  // prepareQueue made it
    f.backend->draw(frameTarget(), f.view, f.list, f.builder);
}

void Graphics3D::clear(Background* background) {
    requireTarget("Graphics3D::clear");
    if (!backgroundMatches(*this, background))
        throw IllegalArgumentException(detail::str("Graphics3D::clear: the background image format ",
                                                   background->getImage()->getFormat(),
                                                   " is not the target's format ", targetFormat(*this)));
    drawClear(background);
}

void Graphics3D::render(World* world) {
    const char* where = "Graphics3D::render(World)";
    detail::requireNonNull(world, where, "world");
    requireTarget(where);
    Ref<Camera> camera = world->getActiveCamera();
    if (!camera) throw IllegalStateException(detail::str(where, ": the World has no active camera"));
    if (camera->root() != world)
        throw IllegalStateException(detail::str(where, ": the active camera is not in this World"));
    Background* background = world->getBackground().get();
    if (!backgroundMatches(*this, background))
        throw IllegalStateException(detail::str(where, ": the background image format ", background->getImage()->getFormat(),
                                                " is not the target's format ", targetFormat(*this)));
    Transform cameraToWorld;
    camera->getTransformTo(world, &cameraToWorld);
    // As setCamera, and as Nokia's engine (its m3gSetCamera raises an
    // arithmetic error): a camera whose transform has no inverse (a zero
    // scale on its path) gives no view.
    try {
        setCamera(camera.get(), &cameraToWorld);
    } catch (const ArithmeticException&) {
        throw ArithmeticException(detail::str(where, ": the active camera's transform to the World is singular"));
    }

    // The World's lights replace Graphics3D's (JSR-184 1.1, Graphics3D.render(World)).
    std::vector<LightEntry> found;
    detail::collectLights(*world, Transform(), found);
    lights_ = std::move(found);

    detail::FrameState& f = frame();
    detail::RenderQueue& q = f.queue;
    q.reset(*camera, getLimits().maxLights);
    for (const LightEntry& l : lights_) q.addLight(*l.light, worldToCamera_ * l.toWorld);
    // Positions relative to the World, as the camera's getTransformTo(world): the
    // World's own transformation cancels out.
    q.collectNode(*world, worldToCamera_);
    q.sort();
    // The draws first: vertex data a draw cannot use throws before the
    // clear reaches the back end.
    prepareQueue();
    drawClear(background);
    drawPrepared();
}

void Graphics3D::render(Node* node, const Transform* transform) {
    const char* where = "Graphics3D::render(Node, Transform)";
    detail::requireNonNull(node, where, "node");
    if (!dynamic_cast<Mesh*>(node) && !dynamic_cast<Sprite3D*>(node) && !dynamic_cast<Group*>(node))
        throw IllegalArgumentException(detail::str(where, ": a ", node->getClassName(),
                                                   " cannot be rendered (Mesh, Sprite3D or Group only)"));
    requireTarget(where);
    if (!camera_) throw IllegalStateException(detail::str(where, ": no current camera (call setCamera first)"));
    detail::RenderQueue& q = frame().queue;
    q.reset(*camera_, getLimits().maxLights);
    for (const LightEntry& l : lights_)
        if (l.light) q.addLight(*l.light, worldToCamera_ * l.toWorld);
    const Transform nodeToWorld = transform ? *transform : Transform();
    q.collectNode(*node, worldToCamera_ * nodeToWorld);
    q.sort();
    prepareQueue();
    drawPrepared();
}

void Graphics3D::render(VertexBuffer* vertices, IndexBuffer* triangles, Appearance* appearance,
                        const Transform* transform, int scope) {
    const char* where = "Graphics3D::render(VertexBuffer, IndexBuffer, Appearance, Transform)";
    detail::requireNonNull(vertices, where, "vertices");
    detail::requireNonNull(triangles, where, "triangles");
    detail::requireNonNull(appearance, where, "appearance");
    requireTarget(where);
    if (!camera_) throw IllegalStateException(detail::str(where, ": no current camera (call setCamera first)"));
    if (!vertices->positions())
        throw IllegalStateException(detail::str(where, ": the VertexBuffer has no positions"));
    if (triangles->maxIndex() >= vertices->getVertexCount())
        throw IllegalStateException(detail::str(where, ": index ", triangles->maxIndex(), " is out of range [0, ",
                                                vertices->getVertexCount(), ") of the VertexBuffer"));
    detail::RenderQueue& q = frame().queue;
    q.reset(*camera_, getLimits().maxLights);
    if ((scope & camera_->getScope()) == 0) return;
    for (const LightEntry& l : lights_)
        if (l.light) q.addLight(*l.light, worldToCamera_ * l.toWorld);
    const Transform modelToWorld = transform ? *transform : Transform();
    q.addSubmesh(vertices, triangles, appearance, worldToCamera_ * modelToWorld, scope);
    prepareQueue();
    drawPrepared();
}

}  // namespace m3g
