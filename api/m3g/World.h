// javax.microedition.m3g.World (JSR-184 1.1, World).
#pragma once

#include <m3g/Export.h>

#include <m3g/Background.h>
#include <m3g/Camera.h>
#include <m3g/Group.h>

namespace m3g {

/// The root of a scene: a Group with an active camera and a background. A
/// World can never be a child of another node.
class M3G_API World : public Group {
public:
    World();
    ~World() override;

    /// NPE if null.
    void setActiveCamera(Camera* camera);
    Ref<Camera> getActiveCamera() const noexcept;
    /// Null clears to black and far depth.
    void setBackground(Background* background) noexcept;
    Ref<Background> getBackground() const noexcept;

    const char* getClassName() const noexcept override { return "World"; }

protected:
    World(const World& other);
    /// Order: children, active camera, background.
    void collectReferences(std::vector<Object3D*>& out) const override;
    Object3D* duplicateImpl(DuplicateMap& map) const override;
    void remapReferences(const DuplicateMap& map) override;

private:
    Ref<Camera> activeCamera_;
    Ref<Background> background_;
};

}  // namespace m3g
