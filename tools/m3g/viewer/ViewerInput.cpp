#include "ViewerInput.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "ImageIO.h"
#include "InputFile.h"
#include "JarArchive.h"

namespace m3gview {

using namespace m3g;

struct InputCallbacks {
    static Input* of(GLFWwindow* w) { return static_cast<Input*>(glfwGetWindowUserPointer(w)); }

    static void mouseButton(GLFWwindow* w, int button, int action, int) {
        Input& in = *of(w);
        if (action == GLFW_PRESS) {
            if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse) return;
            double x = 0, y = 0;
            glfwGetCursorPos(w, &x, &y);
            // Only a press in the 3D view drags or picks (the panels have their own area).
            if (!in.state_.layout.view.contains(static_cast<float>(x), static_cast<float>(y))) return;
            in.button_ = button;
            in.pressX_ = x;
            in.pressY_ = y;
            in.lastX_ = in.pressX_;
            in.lastY_ = in.pressY_;
            in.moved_ = false;
        } else if (action == GLFW_RELEASE && in.button_ == button) {
            in.button_ = -1;
            if (!in.moved_ && button == GLFW_MOUSE_BUTTON_LEFT)
                in.click(static_cast<float>(in.pressX_), static_cast<float>(in.pressY_));
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
        in.drag(in.button_ != GLFW_MOUSE_BUTTON_LEFT, static_cast<float>(dx), static_cast<float>(dy));
    }
    static void scroll(GLFWwindow* w, double, double dy) {
        if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse) return;
        double x = 0, y = 0;
        glfwGetCursorPos(w, &x, &y);
        if (!of(w)->state_.layout.view.contains(static_cast<float>(x), static_cast<float>(y))) return;
        of(w)->scroll(static_cast<float>(dy));
    }
    static void key(GLFWwindow* w, int key, int, int action, int mods) {
        if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
        if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureKeyboard) return;
        std::string name;
        if (mods & GLFW_MOD_CONTROL) {
            // Undo/redo/save (Ctrl+Y, or Ctrl+Shift+Z, redoes); repeats only for undo/redo.
            if (key == GLFW_KEY_Z) name = (mods & GLFW_MOD_SHIFT) ? "ctrl+shift+z" : "ctrl+z";
            else if (key == GLFW_KEY_Y) name = "ctrl+y";
            else if (key == GLFW_KEY_S && action == GLFW_PRESS) name = "ctrl+s";
            else if (key == GLFW_KEY_O && action == GLFW_PRESS) name = "ctrl+o";
            if (!name.empty()) of(w)->key(name);
            return;
        }
        if (action != GLFW_PRESS) return;
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
        of(w)->key(name);
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

void updateLayout(ViewerState& state) {
    const Rect before = state.layout.view;
    state.layout = computeLayout(state.width, state.height, state.menuHeight, state.showUi, state.layoutSizes);
    const Rect& v = state.layout.view;
    if (state.scene && (v.w != before.w || v.h != before.h)) {
        const PixelRect p = state.viewPixels();
        state.scene->applyOrbit(p.w, p.h);
    }
}

void Input::drag(bool pan, float dx, float dy) {
    if (!state_.scene) return;
    ViewerScene& scene = *state_.scene;
    const PixelRect view = state_.viewPixels();
    if (scene.cameraIndex() >= 0) scene.useCamera(-1);  // moving the view takes the orbit camera
    // dx, dy are window units: the pan is relative to the view's height in the same units.
    if (pan) scene.orbit().pan(dx, dy, pixels(state_.layout.view).h);
    else scene.orbit().orbit(dx, dy);
    scene.applyOrbit(view.w, view.h);
}

void Input::scroll(float steps) {
    if (!state_.scene) return;
    const PixelRect view = state_.viewPixels();
    if (state_.scene->cameraIndex() >= 0) state_.scene->useCamera(-1);
    state_.scene->orbit().zoom(steps);
    state_.scene->applyOrbit(view.w, view.h);
}

void Input::click(float x, float y) {
    const Rect& view = state_.layout.view;
    if (!state_.scene || view.w <= 0 || view.h <= 0) return;
    World& world = state_.scene->world();
    Ref<Camera> camera = world.getActiveCamera();
    if (!camera) return;
    PickResult p;
    p.x = x;
    p.y = y;
    float vx = 0, vy = 0;
    toView(view, x, y, vx, vy);
    RayIntersection ri;
    if (view.contains(x, y) && world.pick(-1, vx / view.w, vy / view.h, camera.get(), &ri)) {
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

bool Input::undo() {
    const Edit* e = state_.edits.lastApplied();
    if (!e) {
        state_.status = "nothing to undo";
        return false;
    }
    const std::string what = describe(*e->property, e->before);
    try {
        state_.edits.undo();
    } catch (const std::exception& ex) {
        state_.status = std::string("undo failed: ") + ex.what();
        return false;
    }
    state_.status = "undo: " + what;
    return true;
}

bool Input::redo() {
    if (!state_.edits.canRedo()) {
        state_.status = "nothing to redo";
        return false;
    }
    try {
        state_.edits.redo();
    } catch (const std::exception& ex) {
        state_.status = std::string("redo failed: ") + ex.what();
        return false;
    }
    const Edit* e = state_.edits.lastApplied();
    state_.status = "redo: " + describe(*e->property, e->after);
    return true;
}

bool Input::save(const std::string& path) {
    const std::string to = path.empty() ? state_.savePath : path;
    if (!state_.scene || to.empty()) {
        state_.status = "save: no scene or no path";
        return false;
    }
    try {
        state_.scene->save(to);
    } catch (const std::exception& e) {
        state_.status = "save " + to + " failed: " + e.what();
        std::fprintf(stderr, "m3g: view: %s\n", state_.status.c_str());
        return false;
    }
    state_.status = "saved " + to;
    std::fprintf(stderr, "m3g: view: saved %s\n", to.c_str());
    return true;
}

bool Input::key(const std::string& name) {
    if (name == "space") state_.playing = !state_.playing;
    else if (name == "r") state_.resetViewRequest = true;
    else if (name == "w") state_.debug.wireframe = !state_.debug.wireframe;
    else if (name == "l") state_.debug.unlit = !state_.debug.unlit;
    else if (name == "h") {
        if (state_.scene) state_.scene->setHeadlight(!state_.scene->headlight());
    } else if (name == "s") {
        try {
            state_.screenshotPath = nextScreenshotName();
        } catch (const std::exception& e) {
            state_.status = e.what();
        }
    } else if (name == "f1") {
        state_.showUi = !state_.showUi;
        updateLayout(state_);
    } else if (name == "left") state_.timeMs = std::max(0.0, state_.timeMs - 1000.0 / 30.0);
    else if (name == "right") state_.timeMs += 1000.0 / 30.0;
    else if (name == "ctrl+z") undo();
    else if (name == "ctrl+y" || name == "ctrl+shift+z") redo();
    else if (name == "ctrl+s") save("");
    else if (name == "ctrl+o") {
        try {
            if (state_.showBrowser) state_.showBrowser = false;
            else showBrowser(state_, state_.browser.isOpen() ? state_.browser.folder().string() : "");
        } catch (const std::exception& e) {
            state_.status = e.what();
        }
    }
    else if (name.size() == 1 && name[0] >= '0' && name[0] <= '9') {
        if (state_.scene) state_.scene->useCamera(name[0] - '1');  // 0: orbit, 1: the first camera
    } else return false;
    return true;
}

namespace {

/// Script output: appended to `file`, or stdout when it is empty.
void report(const std::string& text, const std::string& file) {
    if (file.empty()) {
        std::fputs(text.c_str(), stdout);
        std::fflush(stdout);
        return;
    }
    std::ofstream out(file, std::ios::app);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + file);
}

std::string rectText(const char* name, const Rect& r) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s %g %g %g %g", name, static_cast<double>(r.x), static_cast<double>(r.y),
                  static_cast<double>(r.w), static_cast<double>(r.h));
    return buf;
}

}  // namespace

int Input::apply(const ScriptCommand& c, const std::function<void()>& frame,
                 const std::function<void(const std::string&, bool)>& screenshot) {
    auto number = [&](std::size_t i) { return std::stof(c.args.at(i)); };
    auto fail = [&](const std::string& why) {
        std::fprintf(stderr, "m3g: view: script line %d (%s): %s\n", c.line, c.name.c_str(), why.c_str());
        return 1;
    };
    // "ID PROPERTY ..." of edit/expect/select: the object by `m3g info` id.
    auto objectArg = [&](Object3D*& object, std::string& why) {
        if (!state_.scene) return why = "no scene", false;
        object = state_.scene->object(std::stoi(c.args[0]));
        if (!object) return why = "no object #" + c.args[0], false;
        return true;
    };
    try {
        if (c.name == "frames") {
            for (int i = 0, n = std::stoi(c.args[0]); i < n; ++i) frame();
        } else if (c.name == "time") state_.timeMs = number(0);
        else if (c.name == "play") state_.playing = true;
        else if (c.name == "pause") state_.playing = false;
        else if (c.name == "drag") {
            if (c.args[0] != "left" && c.args[0] != "right") return fail("button must be left or right");
            if (!state_.layout.view.contains(number(1), number(2))) return fail("the drag starts outside the 3D view");
            drag(c.args[0] == "right", number(3) - number(1), number(4) - number(2));
        } else if (c.name == "scroll") scroll(number(0));
        else if (c.name == "click") click(number(0), number(1));
        else if (c.name == "key") {
            if (!key(c.args[0])) return fail("unknown key " + c.args[0]);
            if (state_.resetViewRequest && state_.scene) {
                const PixelRect view = state_.viewPixels();
                state_.scene->resetView(view.w, view.h);
                state_.scene->useCamera(-1);
                state_.resetViewRequest = false;
            }
            if (!state_.screenshotPath.empty()) {
                const std::string path = state_.screenshotPath;
                state_.screenshotPath.clear();
                screenshot(path, false);
            }
        } else if (c.name == "camera") {
            if (state_.scene && !state_.scene->useCamera(std::stoi(c.args[0])))
                return fail(state_.scene->cameraError());
        } else if (c.name == "screenshot") screenshot(c.args.empty() ? "" : c.args[0], false);
        else if (c.name == "screenshot-ui") screenshot(c.args[0], true);
        else if (c.name == "expect-pick") {
            if (!state_.pick) return fail("no click before it");
            const std::string got = state_.pick->node ? state_.pick->node->getClassName() : "none";
            if (got != c.args[0]) return fail("picked " + got + ", expected " + c.args[0]);
            std::fprintf(stderr, "m3g: view: pick at (%.0f, %.0f): %s (distance %.4f)\n", state_.pick->x,
                         state_.pick->y, got.c_str(), state_.pick ? state_.pick->distance : 0.0f);
        } else if (c.name == "select") {
            Object3D* o = nullptr;
            std::string why;
            if (!objectArg(o, why)) return fail(why);
            state_.selected = o;
        } else if (c.name == "edit" || c.name == "expect") {
            Object3D* o = nullptr;
            std::string why;
            if (!objectArg(o, why)) return fail(why);
            const EditProperty* p = findEditProperty(*o, c.args[1]);
            if (!p) return fail(state_.scene->numbering().label(*o) + " has no editable property " + c.args[1]);
            std::vector<float> values;
            for (std::size_t i = 2; i < c.args.size(); ++i) values.push_back(number(i));
            if (values.size() != p->count)
                return fail(std::string(p->name) + " takes " + std::to_string(p->count) + " value(s)");
            if (c.name == "edit") {
                Edit e;
                e.target = Ref<Object3D>(o);
                e.property = p;
                e.after = values;
                e.worldTime = static_cast<int>(state_.timeMs);
                try {
                    state_.edits.perform(std::move(e));
                } catch (const std::exception& ex) {
                    return fail(ex.what());
                }
                state_.status = state_.scene->numbering().label(*o) + ": " + describe(*p, values);
            } else {
                const std::vector<float> got = p->get(*o);
                for (std::size_t i = 0; i < got.size(); ++i)
                    if (std::abs(got[i] - values[i]) > 1e-3f) return fail("got " + describe(*p, got));
                std::fprintf(stderr, "m3g: view: %s %s\n", state_.scene->numbering().label(*o).c_str(),
                             describe(*p, got).c_str());
            }
        } else if (c.name == "undo") {
            if (!undo()) return fail(state_.status);
        } else if (c.name == "redo") {
            if (!redo()) return fail(state_.status);
        } else if (c.name == "save") {
            if (!save(c.args[0])) return fail(state_.status);
        } else if (c.name == "panels") {
            if (c.args[0] != "on" && c.args[0] != "off") return fail("panels takes on or off");
            state_.showUi = c.args[0] == "on";
            updateLayout(state_);
        } else if (c.name == "splitter") {
            LayoutSizes& s = state_.layoutSizes;
            const float v = number(1);
            if (c.args[0] == "left") s.left = v;
            else if (c.args[0] == "right") s.right = v;
            else if (c.args[0] == "left-split") s.leftSplit = v;
            else if (c.args[0] == "right-split1") s.rightSplit1 = v;
            else if (c.args[0] == "right-split2") s.rightSplit2 = v;
            else return fail("unknown splitter " + c.args[0]);
            s = clampSizes(s, state_.width, state_.height);
            updateLayout(state_);
        } else if (c.name == "layout") {
            const Layout& l = state_.layout;
            std::fprintf(stderr, "m3g: view: layout %s\n", rectText("view", l.view).c_str());
            if (l.panels)
                for (const auto& [name, r] : {std::pair{"scene", l.scene}, {"objects", l.objects}, {"properties", l.properties},
                                              {"animation", l.animation}, {"stats", l.stats}})
                    std::fprintf(stderr, "m3g: view: layout %s\n", rectText(name, r).c_str());
            if (state_.inspector.wasDrawn)  // where the inspected image was drawn in the last frame
                std::fprintf(stderr, "m3g: view: layout %s\n", rectText("inspector-image", state_.inspector.drawn).c_str());
        } else if (c.name == "expect-pixel") {
            const m3gcli::RgbaImage image = m3gcli::readPng(c.args[0]);
            const int x = std::stoi(c.args[1]), y = std::stoi(c.args[2]);
            if (x < 0 || y < 0 || x >= image.width || y >= image.height) return fail("outside the image");
            const unsigned want = static_cast<unsigned>(std::stoul(c.args[3], nullptr, 16));
            const std::uint8_t* px = &image.pixels[(static_cast<std::size_t>(y) * image.width + x) * 4];
            char got[8];
            std::snprintf(got, sizeof got, "%02X%02X%02X", px[0], px[1], px[2]);
            for (int k = 0; k < 3; ++k)
                if (std::abs(static_cast<int>(px[k]) - static_cast<int>((want >> (16 - 8 * k)) & 0xFF)) > 8)
                    return fail(c.args[0] + " (" + c.args[1] + ", " + c.args[2] + ") is " + got + ", not " + c.args[3]);
            std::fprintf(stderr, "m3g: view: %s (%d, %d) = %s\n", c.args[0].c_str(), x, y, got);
        } else if (c.name == "browse") {
            showBrowser(state_, c.args.empty() ? "" : c.args[0]);
        } else if (c.name == "browse-list") {
            if (!state_.browser.isOpen()) return fail("the file browser is not open (browse DIR)");
            std::string text = "# " + state_.browser.folder().string() + "\n";
            const auto& entries = state_.browser.entries();
            for (std::size_t i = 0; i < entries.size(); ++i)
                text += std::to_string(i) + " " + kindName(entries[i].kind) + " " + entries[i].name + "\n";
            text += "# other files: " + std::to_string(state_.browser.otherFiles()) + "\n";
            report(text, c.args.empty() ? "" : c.args[0]);
        } else if (c.name == "browse-open") {
            if (!state_.browser.isOpen()) return fail("the file browser is not open (browse DIR)");
            const int n = std::stoi(c.args[0]);
            if (n < 0 || n >= static_cast<int>(state_.browser.entries().size()))
                return fail("no entry " + c.args[0] + " (the browser lists " +
                            std::to_string(state_.browser.entries().size()) + ")");
            const std::string file = state_.browser.activate(static_cast<std::size_t>(n));
            if (!file.empty()) state_.openRequest = file;  // opened by the loop, as a click does
        } else if (c.name == "browse-up") {
            if (!state_.browser.isOpen()) return fail("the file browser is not open (browse DIR)");
            state_.browser.up();
        } else if (c.name == "browse-close") {
            state_.showBrowser = false;
        } else if (c.name == "recent") {
            std::string text;
            for (const auto& r : state_.recent) text += r + "\n";
            report(text, c.args.empty() ? "" : c.args[0]);
        } else if (c.name == "drop") {
            drop(c.args[0]);
        } else if (c.name == "expect-error") {
            std::string want;
            for (const auto& a : c.args) want += (want.empty() ? "" : " ") + a;
            if (want == "none") {
                if (!state_.error.empty()) return fail("error shown: " + state_.error);
            } else if (state_.error.find(want) == std::string::npos) {
                return fail("the error shown is '" + state_.error + "', without '" + want + "'");
            }
            std::fprintf(stderr, "m3g: view: error shown: %s\n", state_.error.empty() ? "none" : state_.error.c_str());
        } else if (c.name == "expect-scene") {
            const std::string name = state_.scene ? state_.scene->name() : "";
            if (!name.ends_with(c.args[0])) return fail("the scene is '" + name + "'");
        } else if (c.name == "inspect") {
            if (!state_.scene) return fail("no scene");
            const int n = std::stoi(c.args[0]);
            const int count = static_cast<int>(state_.scene->images().size());
            if (n < 0 || n >= count)
                return fail("no image " + c.args[0] + " (the file has " + std::to_string(count) + ")");
            int zoom = TextureInspector::kFit;
            if (c.args.size() > 1 && c.args[1] != "fit") zoom = std::stoi(c.args[1]);
            state_.inspector.open(n, zoom);
        } else if (c.name == "inspect-close") {
            state_.inspector.close();
        } else if (c.name == "texel" || c.name == "hover") {
            if (!state_.scene || !state_.inspector.isOpen()) return fail("no texture inspected (inspect N)");
            const m3g::Image2D& image = *state_.scene->images().at(static_cast<std::size_t>(state_.inspector.index()));
            std::optional<Texel> texel;
            std::string prefix;
            if (c.name == "texel") {
                texel = texelAt(image, std::stoi(c.args[0]), std::stoi(c.args[1]));
                if (!texel) return fail("(" + c.args[0] + ", " + c.args[1] + ") is outside the " +
                                        std::to_string(image.getWidth()) + "x" + std::to_string(image.getHeight()) + " image");
                prefix = "texel ";
            } else {
                if (!state_.inspector.wasDrawn) return fail("the inspector was not drawn yet (frames 1)");
                if (const auto at = TextureInspector::texelUnder(number(0), number(1), state_.inspector.drawn,
                                                                 image.getWidth(), image.getHeight()))
                    texel = texelAt(image, at->first, at->second);
                prefix = "hover " + c.args[0] + " " + c.args[1] + ": ";
            }
            report(prefix + (texel ? texel->describe() : "none") + "\n", c.args.size() > 2 ? c.args[2] : "");
        } else if (c.name == "expect-view") {
            const Rect want{number(0), number(1), number(2), number(3)};
            if (!(state_.layout.view == want))
                return fail("the view is " + rectText("", state_.layout.view).substr(1));
        }
    } catch (const std::invalid_argument&) {
        return fail("arguments must be numbers");
    } catch (const std::out_of_range&) {
        return fail("argument out of range");
    } catch (const std::exception& e) {
        return fail(e.what());
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
    // The identifier decides, not the name (games name models .res, .mod, ...);
    // anything else is said to be what its bytes are, before the Loader runs.
    m3gcli::requireInputFile(request);
    const m3gcli::FileContent content = m3gcli::sniffFile(request);
    if (!content.image && !m3gcli::listedAsM3g(content, request))
        throw std::runtime_error("not M3G data (it does not begin with the JSR-184 file identifier), nor a PNG, JPEG or "
                                 ".jar: " + content.what);
    return std::make_unique<ViewerScene>(request, width, height, state.lenient);
}

void showBrowser(ViewerState& state, const std::string& folder) {
    std::string at = folder;
    if (at.empty() && state.scene) {
        const std::string& name = state.scene->name();
        at = std::filesystem::path(name.substr(0, name.find(".jar!") == std::string::npos ? name.size() : name.find(".jar!") + 4))
                 .parent_path()
                 .string();
    }
    if (at.empty()) at = ".";
    state.browser.open(at);
    state.showBrowser = true;
}

}  // namespace m3gview
