// What the viewer shows: a loaded file turned into a World (the corpus
// rules of SceneSetup), the viewer's own orbit camera and headlight, the
// file's cameras, animation state and statistics. No window, no ImGui.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <memory>
#include <string>
#include <vector>

#include <m3g/m3g.h>

#include "ObjectDump.h"
#include "OrbitCamera.h"
#include "SceneSetup.h"

namespace m3gview {

struct SceneStats {
    int meshes = 0, submeshes = 0, triangles = 0, vertices = 0, skinned = 0, morphing = 0, sprites = 0;
};

class ViewerScene {
public:
    /// Loads `path` (.m3g or .png; lenient when asked) for a view of
    /// width x height. Throws what the Loader throws.
    ViewerScene(const std::string& path, int width, int height, bool lenient);
    /// The same from a load already made (a JAR entry); `name` for messages.
    ViewerScene(std::string name, m3g::LoadResult loaded, int width, int height);

    const std::string& name() const noexcept { return name_; }
    m3g::World& world() const noexcept { return *prepared_.world; }
    const m3g::LoadResult& loaded() const noexcept { return loaded_; }
    /// The file's objects numbered as `m3g info` numbers them ("#id").
    const m3gcli::ObjectNumbering& numbering() const noexcept { return *numbering_; }
    /// The file's root objects (the numbering's roots).
    std::vector<m3g::Object3D*> roots() const;
    const m3gcli::PreparedScene& prepared() const noexcept { return prepared_; }
    const SceneStats& stats() const noexcept { return stats_; }
    const std::vector<m3g::Ref<m3g::Camera>>& cameras() const noexcept { return cameras_; }
    const std::vector<m3g::Ref<m3g::AnimationController>>& controllers() const noexcept { return controllers_; }
    const std::vector<m3g::Ref<m3g::Image2D>>& images() const noexcept { return images_; }
    /// Every AnimationTrack in file order, with the controller it had when
    /// loaded (what enabling it again restores).
    struct Track {
        m3g::Ref<m3g::AnimationTrack> track;
        m3g::Ref<m3g::AnimationController> controller;
    };
    const std::vector<Track>& tracks() const noexcept { return tracks_; }
    /// Longest keyframe sequence duration in ms (0: nothing animates).
    int animationLength() const noexcept { return animationLength_; }

    /// Which camera renders: -1 the orbit camera, else cameras()[i] (a file
    /// camera outside the World is added to it, as m3gcli::useCamera does).
    /// False, with the reason in cameraError(), when that camera cannot
    /// render this World (out of range, or in another scene graph); the
    /// orbit camera renders then.
    bool useCamera(int index);
    int cameraIndex() const noexcept { return cameraIndex_; }
    const std::string& cameraError() const noexcept { return cameraError_; }
    /// Puts the orbit camera back on the auto-framed view of the scene.
    void resetView(int width, int height);
    OrbitCamera& orbit() noexcept { return orbit_; }
    /// Copies the orbit state into the orbit camera node (after input).
    void applyOrbit(int width, int height);

    /// A light at the camera, on by default when no light of the file
    /// contributes (the note explains it).
    bool hasOwnLight() const noexcept { return hasOwnLight_; }
    void setHeadlight(bool on);
    bool headlight() const noexcept { return headlight_->isRenderingEnabled(); }
    /// Keeps the headlight at the rendering camera; call before rendering.
    void followCamera();

    /// Animates the World to `timeMs`.
    void animate(int timeMs);

    /// The file's object with `m3g info` id `id`, or null.
    m3g::Object3D* object(int id) const;
    /// Writes the file's objects (its roots and all they reach) as .m3g
    /// with m3g::Saver, as they are now (edits included). What the viewer
    /// added is left out: its orbit camera and headlight, and what the
    /// scene set-up added to a World of the file (auto-framing camera,
    /// lights, background, a camera moved into it); the World's active
    /// camera and background are the file's while saving. Throws what the
    /// Saver throws.
    void save(const std::string& path);

private:
    void setup(int width, int height);

    std::string name_;
    m3g::LoadResult loaded_;
    std::unique_ptr<m3gcli::ObjectNumbering> numbering_;
    m3gcli::PreparedScene prepared_;
    SceneStats stats_;
    std::vector<m3g::Ref<m3g::Camera>> cameras_;
    std::vector<m3g::Ref<m3g::AnimationController>> controllers_;
    std::vector<m3g::Ref<m3g::Image2D>> images_;
    std::vector<Track> tracks_;
    int animationLength_ = 0;
    m3g::Ref<m3g::Camera> orbitCamera_;
    m3g::Ref<m3g::Light> headlight_;
    bool hasOwnLight_ = false;
    int cameraIndex_ = -1;
    bool autoCamera_ = false;  // cameras_[0] is the auto-framing camera, not the file's
    std::string cameraError_;
    OrbitCamera orbit_;
    // The file's first World as loaded (before the set-up added to it).
    m3g::Ref<m3g::World> fileWorld_;
    std::vector<m3g::Ref<m3g::Node>> fileWorldChildren_;
    m3g::Ref<m3g::Camera> fileActiveCamera_;
    m3g::Ref<m3g::Background> fileBackground_;
};

}  // namespace m3gview
