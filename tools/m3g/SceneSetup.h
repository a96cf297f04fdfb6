// Turning a loaded file into a renderable World by the project's scene
// set-up rules (docs/scene-setup.md): the first World, or a
// new one holding the root nodes; auto-framing when there is no active
// camera; the camera fix-up when the active camera is outside the World.
// Shared by `m3g render`, the viewer and the agreement test.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <m3g/m3g.h>

namespace m3gcli {

struct PreparedScene {
    m3g::Ref<m3g::World> world;
    bool createdWorld = false;     ///< no World in the file: one made of the root nodes
    bool autoFramed = false;       ///< camera (and maybe lights, background) added
    bool cameraFixup = false;      ///< the active camera was added to the World
    bool lightsAdded = false;
    bool backgroundAdded = false;
    std::array<float, 3> center{}; ///< auto-framing bounds (valid when autoFramed)
    float radius = 0.0f;
    std::vector<std::string> notes;  ///< what was done, for stderr
};

/// Builds the World for `loaded` at a target of width x height pixels.
PreparedScene prepareScene(const m3g::LoadResult& loaded, int width, int height);

/// The longest KeyframeSequence duration of a load in milliseconds (0 when
/// it has none): the length of its animation, as the viewer's timeline and
/// `m3g bench render --animate` cycle through it.
int longestSequence(const m3g::LoadResult& loaded);

/// The Cameras of a load, in file order (what `--camera-index` counts).
std::vector<m3g::Camera*> camerasInFileOrder(const m3g::LoadResult& loaded);

/// Makes the `index`-th Camera of the file (camerasInFileOrder) the World's
/// active camera, adding it to the World when it has no parent (as the
/// camera fix-up does). Throws std::out_of_range naming the number of
/// Cameras, std::invalid_argument when the Camera sits in another tree.
void useCamera(PreparedScene& scene, const m3g::LoadResult& loaded, int index);

/// The auto-framing bounds (docs/scene-setup.md; stored transforms, rest poses):
/// centre and radius; no vertex gives (0,0,0) and 1.
void sceneBounds(m3g::World& world, std::array<float, 3>& center, float& radius);

/// True if some Light in `world` can contribute (enabled path, colour and
/// intensity non-zero).
bool hasContributingLight(const m3g::World& world);

}  // namespace m3gcli
