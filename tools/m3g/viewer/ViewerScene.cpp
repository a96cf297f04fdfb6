#include "ViewerScene.h"

#include "UpAxis.h"

#include <algorithm>

namespace m3gview {

using namespace m3g;

namespace {

void countMeshes(Node& node, SceneStats& s) {
    if (auto* mesh = dynamic_cast<Mesh*>(&node)) {
        ++s.meshes;
        s.skinned += dynamic_cast<SkinnedMesh*>(mesh) ? 1 : 0;
        s.morphing += dynamic_cast<MorphingMesh*>(mesh) ? 1 : 0;
        if (VertexBuffer* vb = mesh->vertexBuffer()) s.vertices += vb->getVertexCount();
        for (int i = 0; i < mesh->getSubmeshCount(); ++i) {
            ++s.submeshes;
            if (Ref<IndexBuffer> ib = mesh->getIndexBuffer(i)) s.triangles += ib->getIndexCount() / 3;
        }
        if (auto* skinned = dynamic_cast<SkinnedMesh*>(mesh))
            if (skinned->getSkeleton()) countMeshes(*skinned->getSkeleton(), s);
    }
    if (dynamic_cast<Sprite3D*>(&node)) ++s.sprites;
    if (auto* group = dynamic_cast<Group*>(&node))
        for (int i = 0; i < group->getChildCount(); ++i) countMeshes(*group->getChild(i), s);
}

/// A PNG or JPEG: a World showing the image as an unscaled sprite, pixel for pixel.
m3gcli::PreparedScene imageScene(const LoadResult& loaded) {
    m3gcli::PreparedScene p;
    p.world = Ref<World>(new World());
    p.createdWorld = true;
    Image2D* image = nullptr;
    for (const auto& o : loaded.objects)
        if ((image = dynamic_cast<Image2D*>(o.get()))) break;
    if (!image) throw IllegalArgumentException("the file holds no image");
    Ref<Appearance> appearance(new Appearance());
    Ref<CompositingMode> blend(new CompositingMode());
    blend->setBlending(CompositingMode::ALPHA);
    appearance->setCompositingMode(blend.get());
    Ref<Sprite3D> sprite(new Sprite3D(false, image, appearance.get()));
    sprite->setTranslation(0.0f, 0.0f, -1.0f);
    p.world->addChild(sprite.get());
    Ref<Camera> camera(new Camera());
    p.world->addChild(camera.get());
    p.world->setActiveCamera(camera.get());
    Ref<Background> background(new Background());
    background->setColor(static_cast<int>(0xFF404040u));
    p.world->setBackground(background.get());
    p.notes.push_back("showing the image as an unscaled sprite");
    return p;
}

}  // namespace

ViewerScene::ViewerScene(const std::string& path, int width, int height, bool lenient) : name_(path) {
    LoaderOptions options;
    options.lenient = lenient;
    loaded_ = Loader::loadDetailed(path, options);
    setup(width, height);
}

ViewerScene::ViewerScene(std::string name, LoadResult loaded, int width, int height)
    : name_(std::move(name)), loaded_(std::move(loaded)) {
    setup(width, height);
}

std::vector<Object3D*> ViewerScene::roots() const {
    std::vector<Object3D*> out;
    for (const auto& r : loaded_.roots) out.push_back(r.get());
    return out;
}

void ViewerScene::setup(int width, int height) {
    // Numbered before the viewer adds its own camera and light, as `m3g info` numbers the file.
    const std::vector<Object3D*> fileRoots = roots();
    numbering_ = std::make_unique<m3gcli::ObjectNumbering>(fileRoots);
    const bool image = loaded_.versionMajor == 0 && !loaded_.objects.empty() &&
                       dynamic_cast<Image2D*>(loaded_.objects.front().get()) != nullptr;
    for (const auto& o : loaded_.objects)
        if (auto* world = dynamic_cast<World*>(o.get())) {
            fileWorld_ = Ref<World>(world);
            for (int i = 0; i < world->getChildCount(); ++i) fileWorldChildren_.emplace_back(world->getChild(i));
            fileActiveCamera_ = world->getActiveCamera();
            fileBackground_ = world->getBackground();
            break;
        }
    prepared_ = image ? imageScene(loaded_) : m3gcli::prepareScene(loaded_, width, height);
    World& w = *prepared_.world;
    countMeshes(w, stats_);
    for (Camera* c : m3gcli::camerasInFileOrder(loaded_)) cameras_.emplace_back(c);
    for (const auto& o : loaded_.objects) {
        if (auto* a = dynamic_cast<AnimationController*>(o.get())) controllers_.emplace_back(a);
        if (auto* i = dynamic_cast<Image2D*>(o.get())) images_.emplace_back(i);
        if (auto* t = dynamic_cast<AnimationTrack*>(o.get())) tracks_.push_back({Ref<AnimationTrack>(t), t->getController()});
    }
    animationLength_ = m3gcli::longestSequence(loaded_);
    // A camera the auto-framing added is not in the file but is the view.
    if (Ref<Camera> active = w.getActiveCamera();
        active && std::find(cameras_.begin(), cameras_.end(), active) == cameras_.end()) {
        cameras_.insert(cameras_.begin(), active);
        autoCamera_ = true;
    }

    // The orbit turns about the scene's up, read from the file's view
    // before the orbit camera exists (UpAxis.h).
    orbit_.up = m3gcli::sceneUp(w);
    orbitCamera_ = Ref<Camera>(new Camera());
    w.addChild(orbitCamera_.get());
    headlight_ = Ref<Light>(new Light());
    headlight_->setMode(Light::DIRECTIONAL);
    w.addChild(headlight_.get());
    hasOwnLight_ = m3gcli::hasContributingLight(w);
    headlight_->setRenderingEnable(!hasOwnLight_);
    resetView(width, height);
    // The file's view first (its active camera, already set), as the
    // reference renders; the orbit camera when there is none.
    const auto it = std::find(cameras_.begin(), cameras_.end(), w.getActiveCamera());
    if (it != cameras_.end()) cameraIndex_ = static_cast<int>(it - cameras_.begin());
    else useCamera(-1);
}

bool ViewerScene::useCamera(int index) {
    cameraError_.clear();
    try {
        if (index >= 0 && !(autoCamera_ && index == 0)) {
            m3gcli::useCamera(prepared_, loaded_, index - (autoCamera_ ? 1 : 0));
            cameraIndex_ = index;
            return true;
        }
        if (index >= static_cast<int>(cameras_.size())) throw std::out_of_range("no camera " + std::to_string(index));
    } catch (const std::exception& e) {
        cameraError_ = e.what();
        index = -1;
    }
    cameraIndex_ = index;
    prepared_.world->setActiveCamera(index < 0 ? orbitCamera_.get() : cameras_.front().get());
    return cameraError_.empty();
}

void ViewerScene::resetView(int width, int height) {
    std::array<float, 3> center{};
    float radius = 1.0f;
    m3gcli::sceneBounds(*prepared_.world, center, radius);
    orbit_.frame(center, radius, 45.0f);
    applyOrbit(width, height);
}

void ViewerScene::applyOrbit(int width, int height) {
    const Transform t = orbit_.transform();
    orbitCamera_->setTransform(&t);
    orbitCamera_->setPerspective(orbit_.fovy, static_cast<float>(width) / static_cast<float>(std::max(1, height)),
                                 orbit_.nearPlane(), orbit_.farPlane());
}

void ViewerScene::setHeadlight(bool on) { headlight_->setRenderingEnable(on); }

void ViewerScene::followCamera() {
    Ref<Camera> camera = prepared_.world->getActiveCamera();
    Transform t;
    if (camera && camera->getTransformTo(prepared_.world.get(), &t)) headlight_->setTransform(&t);
}

void ViewerScene::animate(int timeMs) { prepared_.world->animate(timeMs); }

Object3D* ViewerScene::object(int id) const {
    for (const auto& o : loaded_.objects)
        if (numbering_->id(o.get()) == id) return o.get();
    // Objects the file reaches but does not list as loaded (none today): by the numbering too.
    for (Object3D* o : m3gcli::collectObjects(roots()))
        if (numbering_->id(o) == id) return o;
    return nullptr;
}

void ViewerScene::save(const std::string& path) {
    // Take the viewer's additions out of the file's World for the save, and put them back after.
    struct Removed {
        Ref<Node> node;
        int index;
    };
    std::vector<Removed> removed;
    Ref<Camera> active;
    Ref<Background> background;
    World* w = fileWorld_.get();
    if (w) {
        active = w->getActiveCamera();
        background = w->getBackground();
        for (int i = w->getChildCount() - 1; i >= 0; --i) {
            Ref<Node> child(w->getChild(i));
            if (std::find(fileWorldChildren_.begin(), fileWorldChildren_.end(), child) == fileWorldChildren_.end()) {
                removed.push_back({child, i});
                w->removeChild(child.get());
            }
        }
        w->setActiveCamera(fileActiveCamera_.get());
        w->setBackground(fileBackground_.get());
    }
    auto restore = [&] {
        if (!w) return;
        for (auto it = removed.rbegin(); it != removed.rend(); ++it) w->addChild(it->node.get());
        w->setActiveCamera(active.get());
        w->setBackground(background.get());
    };
    try {
        const std::vector<Object3D*> r = roots();
        Saver::save(path, std::span<Object3D* const>(r.data(), r.size()));
    } catch (...) {
        restore();
        throw;
    }
    restore();
}

}  // namespace m3gview
