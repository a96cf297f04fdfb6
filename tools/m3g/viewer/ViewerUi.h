// The viewer's Dear ImGui panels: menu, scene tree, properties, animation,
// textures, statistics, debug views and picking results, and the editing
// of properties (ViewerEdit.h, undoable). Draws into the current ImGui
// frame; changes go to the state or straight to the scene.
#pragma once

#include "ViewerState.h"

namespace m3g::vk {
class ImGuiOverlay;
}

namespace m3gview {

/// The menu bar and the panels docked where state.layout puts them (its
/// splitters change state.layoutSizes, used from the next frame on).
void drawUi(ViewerState& state, m3g::vk::ImGuiOverlay& overlay);

/// Bones, bounding boxes and normals of the scene as lines over the 3D
/// view (ImGui's background draw list clipped to state.layout.view; no
/// depth test), as the state asks.
void drawDebugLines(ViewerState& state);

}  // namespace m3gview
