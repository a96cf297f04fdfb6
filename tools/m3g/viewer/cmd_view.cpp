// m3g view: the desktop preview app (GLFW window, Vulkan swapchain through
// m3g::vk::WindowTarget, Dear ImGui panels). Also scriptable for tests:
// --frames N --screenshot OUT.png, or --script FILE (docs/viewer.md).
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <exception>
#include <memory>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>

#include <m3g/m3g.h>
#include <m3g/vk/ImGuiOverlay.h>
#include <m3g/vk/Vulkan.h>
#include <m3g/vk/WindowTarget.h>

#include "CliArgs.h"
#include "Commands.h"
#include "ImageIO.h"
#include "InputFile.h"
#include "ViewerInput.h"
#include "ViewerScript.h"
#include "ViewerSettings.h"
#include "ViewerState.h"
#include "ViewerUi.h"

namespace m3gcli {

namespace {

using namespace m3gview;
using Clock = std::chrono::steady_clock;

struct ViewArgs {
    std::string file;
    int width = 0, height = 0;  // 0: remembered or 1024x768
    int time = 0;
    int frames = -1;  // -1: interactive
    int camera = -2;  // -2: the file's choice
    std::string screenshot, script;
    bool noUi = false, lenient = false, vsync = true, headlight = true;
};

/// The options as given; finish() checks them.
struct ViewFlags {
    std::string file, size, time, frames, camera, screenshot, script;
    bool noUi = false, lenient = false, noVsync = false, noHeadlight = false;
};

ViewArgs finish(const ViewFlags& f) {
    ViewArgs r;
    r.file = f.file;
    if (!f.size.empty()) parseSizeOption("--size", f.size, r.width, r.height);
    if (!f.time.empty()) r.time = parseIntOption("--time", f.time, INT_MIN, "an integer (ms)");
    if (!f.frames.empty()) r.frames = parseIntOption("--frames", f.frames, 1, "a positive integer");
    if (!f.camera.empty()) r.camera = parseIntOption("--camera-index", f.camera, -1, "a Camera's index (0, 1, ...; -1: the viewer's own)");
    r.screenshot = f.screenshot;
    r.script = f.script;
    r.noUi = f.noUi;
    r.lenient = f.lenient;
    r.vsync = !f.noVsync;
    r.headlight = !f.noHeadlight;
    if (!r.screenshot.empty()) imageFormatFor(r.screenshot);  // refused before the window opens
    if (!r.script.empty()) requireInputFile(r.script);
    if (!r.screenshot.empty() && r.frames < 0 && r.script.empty()) r.frames = 1;
    // Before a window opens: a missing file is exit code 3 with its reason,
    // not an error panel (files dropped later still get one). A folder
    // opens the file browser there, except in a --frames run, which has
    // nothing to render then.
    const bool browsable = r.frames < 0 && std::filesystem::is_directory(r.file);
    if (!r.file.empty() && !browsable) requireInputFile(r.file);
    return r;
}

/// The window and everything bound to it.
class ViewerApp {
public:
    ViewerApp(const ViewArgs& args, Settings& settings) : args_(args), settings_(settings) {}
    int run();

private:
    void open(const std::string& request);
    /// What the UI, the keys and a drop asked for (open, reset, save, undo,
    /// redo), after each event poll or script command.
    void handleRequests();
    /// Window size (the layout's units) and framebuffer pixels per unit.
    void readWindowSize();
    void frame();
    void saveScreenshot(const std::string& path, bool withUi = false);

    const ViewArgs& args_;
    Settings& settings_;
    GLFWwindow* window_ = nullptr;
    m3g::Ref<m3g::vk::WindowTarget> target_;
    std::shared_ptr<m3g::vk::ImGuiOverlay> overlay_;
    ViewerState state_;
    Input input_{state_};
    Clock::time_point last_ = Clock::now();
    int fbWidth_ = 0, fbHeight_ = 0;
};

void ViewerApp::open(const std::string& request) {
    std::error_code ec;
    if (std::filesystem::is_directory(request, ec)) {  // a folder (dropped, typed, given): browse it
        try {
            showBrowser(state_, request);
        } catch (const std::exception& e) {
            state_.error = e.what();
        }
        return;
    }
    state_.error.clear();
    state_.warnings.clear();
    state_.selected = nullptr;
    state_.pick.reset();
    state_.controllerWeights.clear();
    state_.edits.clear();  // the edits belong to the scene they were made on
    try {
        updateLayout(state_);
        const PixelRect view = state_.viewPixels();
        auto scene = openScene(request, view.w, view.h, state_);
        state_.showBrowser = false;
        settings_.remember(request);
        state_.recent = settings_.recent;
        if (!scene) return;  // a JAR: its entries are listed
        state_.scene = std::move(scene);
        state_.inspector.close();
        for (const auto& w : state_.scene->loaded().warnings) state_.warnings.push_back("warning: " + w);
        for (const auto& n : state_.scene->prepared().notes) state_.warnings.push_back(n);
        if (!args_.headlight) state_.scene->setHeadlight(false);
        if (args_.camera >= -1 && !state_.scene->useCamera(args_.camera))
            state_.warnings.push_back("--camera-index: " + state_.scene->cameraError());
        settings_.lastFile = request;
        // Ctrl+S writes next to the file, never over it unless asked (File > Save as).
        const std::filesystem::path file(request.substr(0, request.find(".jar!")));
        state_.savePath = (file.parent_path() / (file.stem().string() + "-edited.m3g")).string();
        glfwSetWindowTitle(window_, ("m3g view: " + request).c_str());
    } catch (const std::exception& e) {
        state_.error = request + ": " + e.what();
        std::fprintf(stderr, "m3g: %s\n", state_.error.c_str());
    }
}

void ViewerApp::saveScreenshot(const std::string& request, bool withUi) {
    // The 3D view's rectangle, or the whole window with the UI; no path:
    // the next free m3g-screenshot-NNNN.png here (never overwriting).
    const std::string path = request.empty() ? nextScreenshotName() : request;
    target_->requestReadback(withUi);
    frame();
    if (!target_->readbackReady()) throw std::runtime_error("view: the screenshot frame was not rendered");
    m3gcli::RgbaImage image = fromGraphics(*target_);
    if (!withUi) {
        const PixelRect v = state_.viewPixels();
        const int x0 = std::clamp(v.x, 0, image.width), y0 = std::clamp(v.y, 0, image.height);
        const int w = std::clamp(v.w, 0, image.width - x0), h = std::clamp(v.h, 0, image.height - y0);
        if (w != image.width || h != image.height) {
            m3gcli::RgbaImage crop;
            crop.width = w;
            crop.height = h;
            crop.pixels.resize(static_cast<std::size_t>(w) * h * 4);
            for (int y = 0; y < h; ++y)
                std::copy_n(image.pixels.begin() + ((static_cast<std::ptrdiff_t>(y0 + y) * image.width + x0) * 4), w * 4,
                            crop.pixels.begin() + static_cast<std::ptrdiff_t>(y) * w * 4);
            image = std::move(crop);
        }
    }
    writeImage(path, image, false);
    state_.status = "screenshot: " + path;
    std::fprintf(stderr, "m3g: wrote %s (%dx%d)\n", path.c_str(), image.width, image.height);
}

void ViewerApp::readWindowSize() {
    int w = 0, h = 0;
    glfwGetWindowSize(window_, &w, &h);
    state_.width = w > 0 ? w : fbWidth_;
    state_.height = h > 0 ? h : fbHeight_;
    // GLFW's cursor and ImGui are in window units, the swapchain in pixels:
    // on a HiDPI screen whose window system scales windows there are two
    // pixels a unit (glfwGetWindowContentScale tells the UI's size, not this).
    state_.pixelScaleX = state_.width > 0 ? static_cast<float>(fbWidth_) / static_cast<float>(state_.width) : 1.0f;
    state_.pixelScaleY = state_.height > 0 ? static_cast<float>(fbHeight_) / static_cast<float>(state_.height) : 1.0f;
}

void ViewerApp::handleRequests() {
    // A drop is an open: the same identifier check, a folder opens the browser.
    if (auto dropped = input_.takeDrop()) state_.openRequest = *dropped;
    if (!state_.openRequest.empty()) {
        const std::string request = std::move(state_.openRequest);
        state_.openRequest.clear();
        open(request);
    }
    if (state_.resetViewRequest && state_.scene) {
        const PixelRect view = state_.viewPixels();
        state_.scene->resetView(view.w, view.h);
        state_.scene->useCamera(-1);
    }
    state_.resetViewRequest = false;
    if (state_.saveRequest) input_.save("");
    if (state_.undoRequest) input_.undo();
    if (state_.redoRequest) input_.redo();
    state_.saveRequest = state_.undoRequest = state_.redoRequest = false;
}

void ViewerApp::frame() {
    const auto now = Clock::now();
    const double dt = std::chrono::duration<double, std::milli>(now - last_).count();
    last_ = now;
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    if (w <= 0 || h <= 0) return;  // minimised
    if (w != fbWidth_ || h != fbHeight_) {
        fbWidth_ = w;
        fbHeight_ = h;
        target_->resize(w, h);
    }
    readWindowSize();
    updateLayout(state_);  // (the orbit camera follows the view's size)
    // Interactive sessions follow the clock; tests (frames/script) do not.
    if (state_.playing && args_.frames < 0 && args_.script.empty()) state_.timeMs += dt * state_.speed;

    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (state_.menuHeight != ImGui::GetFrameHeight()) {
        state_.menuHeight = ImGui::GetFrameHeight();
        updateLayout(state_);
    }
    if (state_.showUi) drawUi(state_, *overlay_);
    drawDebugLines(state_);
    ImGui::Render();
    const PixelRect view = state_.viewPixels();

    m3g::vk::setDebugView(state_.debug);
    m3g::vk::setShaderInvocationCounting(state_.countShaders);
    m3g::Graphics3D* g3d = m3g::Graphics3D::getInstance();
    const m3g::vk::RenderStats before = m3g::vk::renderStats();
    const auto t0 = Clock::now();
    g3d->bindTarget(target_.get(), true, 0);
    try {
        // The M3G frame goes into the 3D view's rectangle only; with panels
        // the whole target is cleared first (the gaps between the panels).
        if (state_.layout.panels) g3d->clear(nullptr);
        g3d->setViewport(view.x, view.y, view.w, view.h);
        if (state_.scene) {
            state_.scene->animate(static_cast<int>(state_.timeMs));
            state_.scene->followCamera();
            g3d->render(&state_.scene->world());
        } else {
            g3d->clear(nullptr);
        }
    } catch (const std::exception& e) {
        state_.error = std::string("render: ") + e.what();
        try {
            g3d->clear(nullptr);
        } catch (...) {
        }
    }
    g3d->releaseTarget();
    state_.renderMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    state_.frameMs = dt;
    const m3g::vk::RenderStats after = m3g::vk::renderStats();
    state_.drawsPerFrame = after.draws - before.draws;
    state_.vertexInvocations = after.vertexShaderInvocations - before.vertexShaderInvocations;
    state_.fragmentInvocations = after.fragmentShaderInvocations - before.fragmentShaderInvocations;
}

int ViewerApp::run() {
    glfwSetErrorCallback([](int code, const char* text) { std::fprintf(stderr, "m3g: GLFW error %d: %s\n", code, text); });
    if (!glfwInit()) throw RenderError("cannot open a window (no display? set DISPLAY, or run under xvfb-run)");
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw RenderError("GLFW finds no Vulkan loader (Debian: libvulkan1 mesa-vulkan-drivers)");
    }
    std::uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    std::vector<std::string> extensions(names, names + count);
    if (!m3g::vk::requestWindowExtensions(extensions))
        std::fprintf(stderr, "m3g: view: the Vulkan device already exists without window extensions\n");

    const int width = args_.width ? args_.width : settings_.width;
    const int height = args_.height ? args_.height : settings_.height;
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    // Test runs: the window must be exactly the requested size.
    glfwWindowHint(GLFW_RESIZABLE, args_.frames < 0 && args_.script.empty() ? GLFW_TRUE : GLFW_FALSE);
    window_ = glfwCreateWindow(width, height, "m3g view", nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw RenderError("glfwCreateWindow failed");
    }
    glfwGetFramebufferSize(window_, &fbWidth_, &fbHeight_);
    GLFWwindow* window = window_;
    target_ = m3g::Ref<m3g::vk::WindowTarget>(new m3g::vk::WindowTarget(
        [window](void* instance) {
            VkSurfaceKHR surface = VK_NULL_HANDLE;
            const VkResult r = glfwCreateWindowSurface(static_cast<VkInstance>(instance), window, nullptr, &surface);
            if (r != VK_SUCCESS) throw m3g::vk::VulkanError("glfwCreateWindowSurface failed (" + std::to_string(r) + ")");
            return reinterpret_cast<std::uint64_t>(surface);
        },
        std::max(1, fbWidth_), std::max(1, fbHeight_), args_.vsync));

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // panel layout is not persisted
    ImGui::StyleColorsDark();
    input_.install(window_);  // first, so that ImGui's backend forwards events to it
    ImGui_ImplGlfw_InitForVulkan(window_, true);
    overlay_ = std::make_shared<m3g::vk::ImGuiOverlay>();
    target_->setOverlay(overlay_);
    state_.showUi = !args_.noUi;
    state_.layoutSizes = settings_.layout;
    state_.recent = settings_.recent;
    readWindowSize();
    updateLayout(state_);
    state_.lenient = args_.lenient;
    state_.timeMs = args_.time;

    int rc = kExitOk;
    std::exception_ptr failure;  // rethrown after the window is gone: its exit code
    try {
        if (!args_.file.empty()) open(args_.file);
        else if (!settings_.lastFile.empty() && args_.frames < 0 && args_.script.empty()) open(settings_.lastFile);
        if (!args_.script.empty()) {
            Script script = Script::load(args_.script);
            rc = script.run([&](const ScriptCommand& c) {
                const int status =
                    input_.apply(c, [&] { frame(); }, [&](const std::string& p, bool ui) { saveScreenshot(p, ui); });
                handleRequests();
                return status;
            });
        } else if (args_.frames > 0) {
            for (int i = 0; i + 1 < args_.frames; ++i) frame();
            if (!args_.screenshot.empty()) saveScreenshot(args_.screenshot);
            else frame();
        } else {
            while (!glfwWindowShouldClose(window_) && !state_.quit) {
                glfwPollEvents();
                handleRequests();
                if (!state_.screenshotPath.empty()) {
                    saveScreenshot(state_.screenshotPath);
                    state_.screenshotPath.clear();
                    continue;
                }
                frame();
            }
            int w = 0, h = 0;
            glfwGetWindowSize(window_, &w, &h);
            settings_.width = w;
            settings_.height = h;
            settings_.layout = state_.layoutSizes;
        }
        // Unattended runs fail when the file did not open (3) or a frame did not render (5).
        if (!state_.error.empty() && (args_.frames > 0 || !args_.script.empty()) && rc == kExitOk)
            rc = state_.error.rfind("render: ", 0) == 0 ? kExitRender : kExitInput;
    } catch (...) {
        failure = std::current_exception();
    }
    m3g::Graphics3D::getInstance()->releaseTarget();
    target_->setOverlay(nullptr);
    overlay_.reset();
    target_ = nullptr;  // the swapchain and surface go before the window
    m3g::Graphics3D::getInstance()->releaseRenderer();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window_);
    glfwTerminate();
    if (m3g::vk::validationEnabled()) {
        std::fprintf(stderr, "m3g: view: validation messages: %llu\n",
                     static_cast<unsigned long long>(m3g::vk::validationMessageCount()));
        if (m3g::vk::validationMessageCount() != 0 && rc == 0) rc = kExitRender;
    }
    if (failure) std::rethrow_exception(failure);
    return rc;
}

int runView(const ViewArgs& args) {
    if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY"))
        throw RenderError("no display (DISPLAY/WAYLAND_DISPLAY unset); use `m3g render` headless, or xvfb-run m3g view ...");
    Settings settings = Settings::load();
    ViewerApp app(args, settings);
    const int rc = app.run();
    if (args.frames < 0 && args.script.empty()) settings.save();
    return rc;
}

}  // namespace

void addViewCommand(CLI::App& parent, CommandTable& table) {
    CLI::App* app = addCommandApp(parent, "view",
                                  "the desktop viewer for .m3g, PNG, JPEG or a game .jar (needs a display; docs/viewer.md)");
    auto f = std::make_shared<ViewFlags>();
    app->add_option("file", f->file, "the file to open (default: the last one); a folder: browse it")->type_name("FILE");
    app->add_option("--size", f->size, "window size (default: the last one, or 1024x768)")->type_name("WxH");
    app->add_option("--time", f->time, "world time to start at, ms (default 0)")->type_name("MS");
    app->add_option("--camera-index", f->camera, "look through the file's I-th Camera (0-based; -1: the viewer's orbit camera)")
        ->type_name("I");
    app->add_flag("--no-ui", f->noUi, "hide the panels");
    app->add_flag("--lenient", f->lenient, "accept the exporter faults seen in real files (LoaderOptions.lenient)");
    app->add_option("--frames", f->frames, "draw N frames and exit (unattended; with --screenshot, the last is saved)")
        ->type_name("N");
    app->add_option("--screenshot", f->screenshot, "save the 3D view after the frames (.png or .jpg; implies --frames 1)")
        ->type_name("OUT.png");
    app->add_option("--script", f->script, "run the commands of FILE, unattended (docs/viewer.md)")->type_name("FILE");
    app->add_flag("--no-vsync", f->noVsync, "present without waiting for vertical sync");
    app->add_flag("--no-headlight", f->noHeadlight, "no light at the orbit camera");
    table[app] = [f] { return runView(finish(*f)); };
}

}  // namespace m3gcli
