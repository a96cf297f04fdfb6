#include "ViewerInput.h"

#include <cmath>
#include <cstdio>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "JarArchive.h"

namespace m3gview {

using namespace m3g;

struct InputCallbacks {
    static Input* of(GLFWwindow* w) { return static_cast<Input*>(glfwGetWindowUserPointer(w)); }
    static void size(GLFWwindow* w, int& width, int& height) { glfwGetFramebufferSize(w, &width, &height); }

    static void mouseButton(GLFWwindow* w, int button, int action, int) {
        Input& in = *of(w);
        if (action == GLFW_PRESS) {
            if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse) return;
            in.button_ = button;
            glfwGetCursorPos(w, &in.pressX_, &in.pressY_);
            in.lastX_ = in.pressX_;
            in.lastY_ = in.pressY_;
            in.moved_ = false;
        } else if (action == GLFW_RELEASE && in.button_ == button) {
            in.button_ = -1;
            if (!in.moved_ && button == GLFW_MOUSE_BUTTON_LEFT) {
                int width = 0, height = 0;
                size(w, width, height);
                in.click(static_cast<float>(in.pressX_), static_cast<float>(in.pressY_), width, height);
            }
        }
    }
    static void cursor(GLFWwindow* w, double x, double y) {
        Input& in = *of(w);
        if (in.button_ < 0) return;
        const double dx = x - in.lastX_, dy = y - in.lastY_;
        in.lastX_ = x;
        in.lastY_ = y;
        if (std::abs(x - in.pressX_) + std::abs(y - in.pressY_) > 3.0) in.moved_ = true;
        if (!in.moved_) return;
        int width = 0, height = 0;
        size(w, width, height);
        in.drag(in.button_ != GLFW_MOUSE_BUTTON_LEFT, static_cast<float>(dx), static_cast<float>(dy), width, height);
    }
    static void scroll(GLFWwindow* w, double, double dy) {
        if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse) return;
        int width = 0, height = 0;
        size(w, width, height);
        of(w)->scroll(static_cast<float>(dy), width, height);
    }
    static void key(GLFWwindow* w, int key, int, int action, int) {
        if (action != GLFW_PRESS) return;
        if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureKeyboard) return;
        std::string name;
        switch (key) {
            case GLFW_KEY_SPACE: name = "space"; break;
            case GLFW_KEY_R: name = "r"; break;
            case GLFW_KEY_W: name = "w"; break;
            case GLFW_KEY_L: name = "l"; break;
            case GLFW_KEY_H: name = "h"; break;
            case GLFW_KEY_S: name = "s"; break;
            case GLFW_KEY_F1: name = "f1"; break;
            case GLFW_KEY_LEFT: name = "left"; break;
            case GLFW_KEY_RIGHT: name = "right"; break;
            case GLFW_KEY_ESCAPE: of(w)->state_.quit = true; return;
            default:
                if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) name = std::string(1, static_cast<char>('0' + key - GLFW_KEY_0));
        }
        if (name.empty()) return;
        int width = 0, height = 0;
        size(w, width, height);
        of(w)->key(name, width, height);
    }
    static void drop(GLFWwindow* w, int count, const char** paths) {
        if (count > 0) of(w)->dropped_ = paths[0];
    }
};

void Input::install(GLFWwindow* window) {
    glfwSetWindowUserPointer(window, this);
    glfwSetMouseButtonCallback(window, InputCallbacks::mouseButton);
    glfwSetCursorPosCallback(window, InputCallbacks::cursor);
    glfwSetScrollCallback(window, InputCallbacks::scroll);
    glfwSetKeyCallback(window, InputCallbacks::key);
    glfwSetDropCallback(window, InputCallbacks::drop);
}

std::optional<std::string> Input::takeDrop() {
    auto d = std::move(dropped_);
    dropped_.reset();
    return d;
}

void Input::drag(bool pan, float dx, float dy, int width, int height) {
    if (!state_.scene) return;
    ViewerScene& scene = *state_.scene;
    if (scene.cameraIndex() >= 0) scene.useCamera(-1);  // moving the view takes the orbit camera
    if (pan) scene.orbit().pan(dx, dy, height);
    else scene.orbit().orbit(dx, dy);
    scene.applyOrbit(width, height);
}

void Input::scroll(float steps, int width, int height) {
    if (!state_.scene) return;
    if (state_.scene->cameraIndex() >= 0) state_.scene->useCamera(-1);
    state_.scene->orbit().zoom(steps);
    state_.scene->applyOrbit(width, height);
}

void Input::click(float x, float y, int width, int height) {
    if (!state_.scene || width <= 0 || height <= 0) return;
    World& world = state_.scene->world();
    Ref<Camera> camera = world.getActiveCamera();
    if (!camera) return;
    PickResult p;
    p.x = x;
    p.y = y;
    RayIntersection ri;
    if (world.pick(-1, x / static_cast<float>(width), y / static_cast<float>(height), camera.get(), &ri)) {
        p.node = ri.getIntersected();
        p.distance = ri.getDistance();
        p.submesh = ri.getSubmeshIndex();
        p.normal[0] = ri.getNormalX();
        p.normal[1] = ri.getNormalY();
        p.normal[2] = ri.getNormalZ();
        p.s = ri.getTextureS(0);
        p.t = ri.getTextureT(0);
        state_.selected = p.node.get();
    }
    state_.pick = p;
}

bool Input::key(const std::string& name, int width, int height) {
    if (name == "space") state_.playing = !state_.playing;
    else if (name == "r") state_.resetViewRequest = true;
    else if (name == "w") state_.debug.wireframe = !state_.debug.wireframe;
    else if (name == "l") state_.debug.unlit = !state_.debug.unlit;
    else if (name == "h") {
        if (state_.scene) state_.scene->setHeadlight(!state_.scene->headlight());
    } else if (name == "s") state_.screenshotPath = "m3g-screenshot.png";
    else if (name == "f1") state_.showUi = !state_.showUi;
    else if (name == "left") state_.timeMs = std::max(0.0, state_.timeMs - 1000.0 / 30.0);
    else if (name == "right") state_.timeMs += 1000.0 / 30.0;
    else if (name.size() == 1 && name[0] >= '0' && name[0] <= '9') {
        if (state_.scene) state_.scene->useCamera(name[0] - '1');  // 0: orbit, 1: the first camera
    } else return false;
    (void)width;
    (void)height;
    return true;
}

int Input::apply(const ScriptCommand& c, const std::function<void()>& frame,
                 const std::function<void(const std::string&, bool)>& screenshot, int width, int height) {
    auto number = [&](std::size_t i) { return std::stof(c.args.at(i)); };
    auto fail = [&](const std::string& why) {
        std::fprintf(stderr, "m3g: view: script line %d (%s): %s\n", c.line, c.name.c_str(), why.c_str());
        return 1;
    };
    try {
        if (c.name == "frames") {
            for (int i = 0, n = std::stoi(c.args[0]); i < n; ++i) frame();
        } else if (c.name == "time") state_.timeMs = number(0);
        else if (c.name == "play") state_.playing = true;
        else if (c.name == "pause") state_.playing = false;
        else if (c.name == "drag") {
            if (c.args[0] != "left" && c.args[0] != "right") return fail("button must be left or right");
            drag(c.args[0] == "right", number(3) - number(1), number(4) - number(2), width, height);
        } else if (c.name == "scroll") scroll(number(0), width, height);
        else if (c.name == "click") click(number(0), number(1), width, height);
        else if (c.name == "key") {
            if (!key(c.args[0], width, height)) return fail("unknown key " + c.args[0]);
            if (state_.resetViewRequest && state_.scene) {
                state_.scene->resetView(width, height);
                state_.scene->useCamera(-1);
                state_.resetViewRequest = false;
            }
        } else if (c.name == "camera") {
            if (state_.scene && !state_.scene->useCamera(std::stoi(c.args[0])))
                return fail(state_.scene->cameraError());
        } else if (c.name == "screenshot") screenshot(c.args[0], false);
        else if (c.name == "screenshot-ui") screenshot(c.args[0], true);
        else if (c.name == "expect-pick") {
            if (!state_.pick) return fail("no click before it");
            const std::string got = state_.pick->node ? state_.pick->node->getClassName() : "none";
            if (got != c.args[0]) return fail("picked " + got + ", expected " + c.args[0]);
            std::fprintf(stderr, "m3g: view: pick at (%.0f, %.0f): %s (distance %.4f)\n", state_.pick->x,
                         state_.pick->y, got.c_str(), state_.pick ? state_.pick->distance : 0.0f);
        }
    } catch (const std::invalid_argument&) {
        return fail("arguments must be numbers");
    } catch (const std::out_of_range&) {
        return fail("argument out of range");
    }
    return 0;
}

std::unique_ptr<ViewerScene> openScene(const std::string& request, int width, int height, ViewerState& state) {
    auto endsWith = [](const std::string& s, const char* suffix) {
        const std::string x(suffix);
        if (s.size() < x.size()) return false;
        for (std::size_t i = 0; i < x.size(); ++i)
            if (std::tolower(static_cast<unsigned char>(s[s.size() - x.size() + i])) != x[i]) return false;
        return true;
    };
    LoaderOptions options;
    options.lenient = state.lenient;
    // "game.jar!path/in/archive.m3g": one entry of a game archive.
    if (const auto bang = request.find(".jar!"); bang != std::string::npos) {
        const std::string jarPath = request.substr(0, bang + 4), entry = request.substr(bang + 5);
        m3gcli::JarArchive jar(jarPath);
        return std::make_unique<ViewerScene>(request, jar.load(entry, options), width, height);
    }
    state.jarEntries.clear();  // another file: its list goes
    if (endsWith(request, ".jar")) {
        m3gcli::JarArchive jar(request);
        const std::vector<std::string> entries = jar.m3gEntries();
        if (entries.empty()) throw std::runtime_error("the archive holds no .m3g file");
        if (entries.size() == 1) return std::make_unique<ViewerScene>(request + "!" + entries[0], jar.load(entries[0], options), width, height);
        state.jarPath = request;
        state.jarEntries = entries;  // the Messages panel lists them
        return nullptr;
    }
    return std::make_unique<ViewerScene>(request, width, height, state.lenient);
}

}  // namespace m3gview
