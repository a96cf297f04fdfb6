// The viewer's state shared by its window loop, its UI panels and its
// script runner.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <m3g/m3g.h>
#include <m3g/vk/Vulkan.h>

#include "FileBrowser.h"
#include "TextureInspector.h"
#include "ViewerEdit.h"
#include "ViewerLayout.h"
#include "ViewerScene.h"

namespace m3gview {

struct PickResult {
    float x = 0, y = 0;  ///< where, in pixels
    m3g::Ref<m3g::Node> node;
    float distance = 0;
    int submesh = 0;
    float normal[3] = {0, 0, 0};
    float s = 0, t = 0;
};

struct ViewerState {
    std::unique_ptr<ViewerScene> scene;
    std::string error;                  ///< last load or render error, shown in the window
    std::vector<std::string> warnings;  ///< lenient-load warnings and scene notes
    bool lenient = false;

    // Animation (world time in ms).
    bool playing = true;
    float speed = 1.0f;
    double timeMs = 0.0;
    std::vector<float> controllerWeights;  ///< saved weights of disabled controllers

    // Layout (ViewerLayout.h): sizes the splitters set, and the rectangles
    // of this frame for a window width x height (window units, those of
    // GLFW's cursor and of ImGui) under a menu bar menuHeight high
    // (updateLayout in ViewerInput.h). The swapchain has pixelScaleX x
    // pixelScaleY framebuffer pixels per unit (2 on a scaled HiDPI screen).
    LayoutSizes layoutSizes;
    Layout layout;
    int width = 0, height = 0;
    float pixelScaleX = 1.0f, pixelScaleY = 1.0f;
    /// The 3D view in framebuffer pixels (viewport, screenshots, aspect).
    PixelRect viewPixels() const noexcept { return pixels(layout.view, pixelScaleX, pixelScaleY); }
    float menuHeight = 19.0f;  ///< ImGui's default frame height until the first frame says

    // Edits of the scene (undo/redo) and where Ctrl+S saves.
    EditStack edits;
    std::string savePath;
    /// The last action's outcome (screenshot name, save, undo), shown in the menu bar.
    std::string status;

    // View.
    bool showUi = true;
    m3g::vk::DebugView debug;
    bool showNormals = false, showBounds = false, showBones = false;
    m3g::Object3D* selected = nullptr;
    std::optional<PickResult> pick;

    // Statistics of the last frame; the shader invocations only while
    // countShaders is on (m3g::vk::setShaderInvocationCounting).
    double frameMs = 0.0, renderMs = 0.0;
    std::uint64_t drawsPerFrame = 0;
    bool countShaders = false;
    std::uint64_t vertexInvocations = 0, fragmentInvocations = 0;

    // A JAR whose .m3g entries are listed for choosing.
    std::string jarPath;
    std::vector<std::string> jarEntries;

    // The file browser (File > Browse, Ctrl+O) and the recently opened
    // files (Settings::recent, most recent first).
    FileBrowser browser;
    bool showBrowser = false;
    std::vector<std::string> recent;

    // The texture inspector (Textures tab): images()[inspector.index()].
    TextureInspector inspector;

    // Requests from the UI, handled by the loop.
    std::string openRequest;      ///< a file (or "jar!entry") to open; a folder opens the browser there
    std::string screenshotPath;   ///< save the next frame's 3D view here
    bool resetViewRequest = false;
    bool saveRequest = false, undoRequest = false, redoRequest = false;  ///< menu items
    bool quit = false;
};

}  // namespace m3gview
