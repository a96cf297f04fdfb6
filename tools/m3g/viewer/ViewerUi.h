// The viewer's Dear ImGui panels: menu, scene tree, properties, animation,
// textures, statistics, debug views and picking results. Draws into the
// current ImGui frame; changes go to the state or straight to the scene.
#pragma once

#include "ViewerState.h"

namespace m3g::vk {
class ImGuiOverlay;
}

namespace m3gview {

void drawUi(ViewerState& state, m3g::vk::ImGuiOverlay& overlay, int width, int height);

/// Bones, bounding boxes and normals of the scene as lines over the view
/// (ImGui's background draw list; no depth test), as the state asks.
void drawDebugLines(ViewerState& state, int width, int height);

}  // namespace m3gview
