// The game's World, built in code the way a J2ME game builds (or loads) it
// in startApp(): a skinned robot whose bones are driven by two
// AnimationControllers (a looping sway and a one-shot jump), three crates to
// collect, the sample scene's ground, a camera and lights.
#pragma once

#include <array>

#include <m3g/m3g.h>

namespace m3ggame {

/// User IDs, as a J2ME game tags the nodes it looks up with find() or pick().
constexpr int kRobotID = 100;
constexpr int kFirstCrateID = 11;  // crates are 11, 12, 13

struct RobotWorld {
    m3g::Ref<m3g::World> world;
    m3g::Ref<m3g::Camera> camera;
    m3g::Ref<m3g::SkinnedMesh> robot;
    m3g::Ref<m3g::AnimationController> sway;  ///< always active, loops every second
    m3g::Ref<m3g::AnimationController> jump;  ///< activated for 600 ms per jump
    std::array<m3g::Ref<m3g::Mesh>, 3> crates;
    std::array<m3g::Ref<m3g::Material>, 3> crateMaterials;
};

/// Builds the World for a viewport of the given aspect ratio (width/height).
RobotWorld buildRobotWorld(float aspect);

}  // namespace m3ggame
