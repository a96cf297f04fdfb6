#include "ViewerUi.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <set>
#include <string>

#include <imgui.h>
#include <nlohmann/json.hpp>

#include <m3g/vk/ImGuiOverlay.h>

#include "ObjectDump.h"
#include "ViewerInput.h"

namespace m3gview {

using namespace m3g;

namespace {

const char* propertyName(int property) {
    static const char* names[] = {"ALPHA",          "AMBIENT_COLOR", "COLOR",         "CROP",         "DENSITY",
                                  "DIFFUSE_COLOR",  "EMISSIVE_COLOR", "FAR_DISTANCE", "FIELD_OF_VIEW", "INTENSITY",
                                  "MORPH_WEIGHTS",  "NEAR_DISTANCE", "ORIENTATION",   "PICKABILITY",  "SCALE",
                                  "SHININESS",      "SPECULAR_COLOR", "SPOT_ANGLE",   "SPOT_EXPONENT", "TRANSLATION",
                                  "VISIBILITY"};
    const int i = property - AnimationTrack::ALPHA;
    return i >= 0 && i < static_cast<int>(std::size(names)) ? names[i] : "?";
}

// A docked panel: placed on its layout rectangle every frame (ImGui 1.89
// has no docking); the splitters resize it.
bool beginPanel(const char* name, const Rect& r) {
    ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(std::max(r.w, 1.0f), std::max(r.h, 1.0f)), ImGuiCond_Always);
    constexpr ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;
    return ImGui::Begin(name, nullptr, flags);
}

// A splitter bar on `r`: dragging it adds the mouse motion times
// `perPixel` to `value` (a column width, or a share of a column).
void splitter(const char* id, const Rect& r, bool vertical, float& value, float perPixel) {
    if (r.w <= 0.0f || r.h <= 0.0f) return;
    ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1, 1));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
    constexpr ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBackground |
                                       ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoFocusOnAppearing;
    ImGui::Begin(id, nullptr, flags);
    ImGui::InvisibleButton("##bar", ImVec2(r.w, r.h));
    const bool hot = ImGui::IsItemHovered() || ImGui::IsItemActive();
    if (hot) ImGui::SetMouseCursor(vertical ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
    if (ImGui::IsItemActive()) value += (vertical ? ImGui::GetIO().MouseDelta.x : ImGui::GetIO().MouseDelta.y) * perPixel;
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(r.x, r.y), ImVec2(r.x + r.w, r.y + r.h),
                                              ImGui::GetColorU32(hot ? ImGuiCol_SeparatorActive : ImGuiCol_Separator));
    ImGui::End();
    ImGui::PopStyleVar(3);
}

// ---- edits ----

// The edit a widget is making (values applied live while it is dragged),
// recorded on the undo stack once no widget is active any more.
struct PendingEdit {
    Ref<Object3D> target;
    const EditProperty* property = nullptr;
    std::vector<float> before;
    int worldTime = 0;
    const ViewerScene* scene = nullptr;  ///< the scene it was made in
};
PendingEdit pending;

void commitPending(ViewerState& state) {
    if (!pending.property) return;
    if (pending.scene != state.scene.get()) {  // another file was opened meanwhile: its stack is not for this
        pending = {};
        return;
    }
    Edit e;
    e.target = pending.target;
    e.property = pending.property;
    e.before = pending.before;
    e.after = pending.property->get(*pending.target);
    e.worldTime = pending.worldTime;
    if (e.after != e.before) {
        state.status = state.scene->numbering().label(*e.target) + ": " + describe(*e.property, e.after);
        state.edits.push(std::move(e));
    }
    pending = {};
}

void editor(ViewerState& state, Object3D& o, const EditProperty& p) {
    std::vector<float> v = p.get(o);
    const std::vector<float> before = v;
    bool changed = false;
    const char* label = p.label;
    const std::string name = p.name;
    switch (p.kind) {
        case EditKind::Color3: changed = ImGui::ColorEdit3(label, v.data()); break;
        case EditKind::Color4: changed = ImGui::ColorEdit4(label, v.data()); break;
        case EditKind::Float:
            if (name == "shininess") changed = ImGui::DragFloat(label, v.data(), 0.5f, 0.0f, 128.0f);
            else if (name == "weight") changed = ImGui::DragFloat(label, v.data(), 0.01f, 0.0f, 100.0f);
            else changed = ImGui::DragFloat(label, v.data(), 0.01f);
            break;
        case EditKind::Float3: changed = ImGui::DragFloat3(label, v.data(), 0.01f); break;
        case EditKind::AngleAxis: changed = ImGui::DragFloat4(label, v.data(), 0.5f); break;
        case EditKind::Int2: {
            int iv[2] = {static_cast<int>(v[0]), static_cast<int>(v[1])};
            changed = ImGui::DragInt2(label, iv, 10.0f);
            v = {static_cast<float>(iv[0]), static_cast<float>(iv[1])};
            break;
        }
        case EditKind::Bool: {
            bool on = v[0] != 0.0f;
            if (ImGui::Checkbox(label, &on)) {
                // A click is a whole edit.
                commitPending(state);
                Edit e;
                e.target = Ref<Object3D>(&o);
                e.property = &p;
                e.after = {on ? 1.0f : 0.0f};
                e.worldTime = static_cast<int>(state.timeMs);
                state.edits.perform(std::move(e));
                state.status = state.scene->numbering().label(o) + ": " + describe(p, {on ? 1.0f : 0.0f});
            }
            return;
        }
    }
    if (p.kind == EditKind::AngleAxis && ImGui::IsItemHovered()) ImGui::SetTooltip("angle (degrees), axis x y z");
    if (p.kind == EditKind::Int2 && ImGui::IsItemHovered()) ImGui::SetTooltip("start, end (world time, ms)");
    if (!changed) return;
    if (pending.property != &p || pending.target.get() != &o) {
        commitPending(state);
        pending = {Ref<Object3D>(&o), &p, before, static_cast<int>(state.timeMs), state.scene.get()};
    }
    try {
        p.set(o, v, pending.worldTime);
    } catch (const std::exception& e) {
        state.status = std::string(p.name) + ": " + e.what();
    }
}

// "Class #id userID=N" with the ids of `m3g info` (one numbering in the
// tool, the tree, the object list and the properties); ImGui's unique part
// after "##".
std::string label(const ViewerState& state, const Object3D& o) {
    std::string s = state.scene->numbering().label(o);
    if (o.getUserID() != 0) s += " userID=" + std::to_string(o.getUserID());
    return s + "##" + std::to_string(o.getObjectId());
}

void sceneTree(ViewerState& state, Node& node) {
    ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_SpanAvailWidth;
    auto* group = dynamic_cast<Group*>(&node);
    auto* skinned = dynamic_cast<SkinnedMesh*>(&node);
    const bool leaf = !(group && group->getChildCount() > 0) && !(skinned && skinned->getSkeleton());
    if (leaf) flags |= ImGuiTreeNodeFlags_Leaf;
    if (state.selected == &node) flags |= ImGuiTreeNodeFlags_Selected;
    bool visible = node.isRenderingEnabled();
    ImGui::PushID(static_cast<int>(node.getObjectId()));
    if (ImGui::Checkbox("##visible", &visible)) {
        commitPending(state);
        Edit e;
        e.target = Ref<Object3D>(&node);
        e.property = findEditProperty(node, "rendering");
        e.after = {visible ? 1.0f : 0.0f};
        state.edits.perform(std::move(e));
    }
    ImGui::SameLine();
    const bool open = ImGui::TreeNodeEx(label(state, node).c_str(), flags);
    if (ImGui::IsItemClicked() && !ImGui::IsItemToggledOpen()) state.selected = &node;
    if (open) {
        if (group)
            for (int i = 0; i < group->getChildCount(); ++i) sceneTree(state, *group->getChild(i));
        if (skinned && skinned->getSkeleton()) sceneTree(state, *skinned->getSkeleton());
        ImGui::TreePop();
    }
    ImGui::PopID();
}

// The dump's members by the class that declares them (ObjectDump writes
// them in this order: Object3D, Transformable, Node, Group, then the class).
const char* declaringClass(const std::string& key, const char* cls) {
    static const std::set<std::string> object3d{"id", "class", "userID", "userObject", "userParameters",
                                                "animationTracks", "references"};
    static const std::set<std::string> transformable{"translation", "orientation", "scale", "transform",
                                                     "compositeTransform"};
    static const std::set<std::string> node{"parent", "renderingEnabled", "pickingEnabled", "alphaFactor", "scope",
                                            "alignment"};
    static const std::set<std::string> group{"childCount", "children"};
    static const std::set<std::string> mesh{"vertexBuffer", "submeshCount", "submeshes"};
    if (object3d.count(key)) return "Object3D";
    if (transformable.count(key)) return "Transformable";
    if (node.count(key)) return "Node";
    if (group.count(key)) return "Group";
    if (mesh.count(key)) return "Mesh";
    return cls;
}

void properties(ViewerState& state) {
    if (!beginPanel("Properties", state.layout.properties)) {
        ImGui::End();
        return;
    }
    if (!state.selected) {
        ImGui::TextDisabled("Select an object in the scene tree, the object list or by clicking the view.");
        ImGui::End();
        return;
    }
    // Dumped again only when the selection, its revision or the animation
    // time changed (a World's dump walks the whole scene).
    struct Cached {
        std::uint64_t id = 0;
        std::uint32_t revision = 0;
        double time = -1.0;
        nlohmann::ordered_json object;
    };
    static Cached cache;
    Object3D* root = state.selected;
    if (cache.id != root->getObjectId() || cache.revision != root->getRevision() || cache.time != state.timeMs) {
        m3gcli::DumpOptions options;
        options.numberingRoots = state.scene->roots();  // ids as `m3g info` gives them
        options.maxVertices = 8;
        options.maxIndices = 24;
        options.maxKeyframes = 8;
        const auto doc =
            nlohmann::ordered_json::parse(m3gcli::dumpJson(std::span<Object3D* const>(&root, 1), options));
        cache = {root->getObjectId(), root->getRevision(), state.timeMs, doc["objects"][0]};
    }
    // Editable properties first (undo: Ctrl+Z, redo: Ctrl+Y).
    if (const auto editable = editPropertiesOf(*root); !editable.empty()) {
        ImGui::TextUnformatted(state.scene->numbering().label(*root).c_str());
        if (ImGui::CollapsingHeader("Edit", ImGuiTreeNodeFlags_DefaultOpen)) {
            ImGui::PushItemWidth(-ImGui::GetContentRegionAvail().x * 0.45f);
            for (const EditProperty* p : editable) editor(state, *root, *p);
            ImGui::PopItemWidth();
        }
    }
    const nlohmann::ordered_json& o = cache.object;
    const char* cls = root->getClassName();
    std::string current;
    bool open = false;
    for (auto it = o.begin(); it != o.end(); ++it) {
        const std::string group = declaringClass(it.key(), cls);
        if (group != current) {
            current = group;
            open = ImGui::CollapsingHeader(group.c_str(), ImGuiTreeNodeFlags_DefaultOpen);
        }
        if (!open) continue;
        std::string value = it.value().dump();
        if (value.size() > 160) value = value.substr(0, 157) + "...";
        ImGui::TextWrapped("%s: %s", it.key().c_str(), value.c_str());
    }
    ImGui::End();
}

void animation(ViewerState& state) {
    ViewerScene& scene = *state.scene;
    if (!beginPanel("Animation", state.layout.animation)) {
        ImGui::End();
        return;
    }
    if (ImGui::Button(state.playing ? "Pause" : "Play")) state.playing = !state.playing;
    ImGui::SameLine();
    if (ImGui::Button("<")) state.timeMs = std::max(0.0, state.timeMs - 1000.0 / 30.0);
    ImGui::SameLine();
    if (ImGui::Button(">")) state.timeMs += 1000.0 / 30.0;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(120);
    ImGui::SliderFloat("speed", &state.speed, 0.0f, 4.0f, "%.2fx");
    float t = static_cast<float>(state.timeMs);
    const float length = static_cast<float>(std::max(scene.animationLength(), 1000));
    if (ImGui::SliderFloat("time (ms)", &t, 0.0f, std::max(length, t))) state.timeMs = t;
    const auto& controllers = scene.controllers();
    state.controllerWeights.resize(controllers.size(), -1.0f);
    for (std::size_t i = 0; i < controllers.size(); ++i) {
        AnimationController& c = *controllers[i];
        ImGui::PushID(static_cast<int>(i));
        bool on = c.getWeight() != 0.0f || state.controllerWeights[i] < 0.0f;
        if (ImGui::Checkbox("", &on)) {
            if (on) {
                c.setWeight(state.controllerWeights[i] < 0.0f ? 1.0f : state.controllerWeights[i]);
                state.controllerWeights[i] = -1.0f;
            } else {
                state.controllerWeights[i] = c.getWeight();
                c.setWeight(0.0f);
            }
        }
        ImGui::SameLine();
        ImGui::Text("AnimationController %zu: speed %.2f, weight %.2f, active [%d, %d)", i, c.getSpeed(),
                    c.getWeight(), c.getActiveIntervalStart(), c.getActiveIntervalEnd());
        ImGui::PopID();
    }
    if (controllers.empty()) ImGui::TextDisabled("No AnimationController in the file.");
    // Tracks: disabling one detaches it from its controller (setController(null)).
    const auto& tracks = scene.tracks();
    if (!tracks.empty() && ImGui::TreeNode("tracks", "AnimationTracks (%zu)", tracks.size())) {
        for (std::size_t i = 0; i < tracks.size(); ++i) {
            AnimationTrack& track = *tracks[i].track;
            ImGui::PushID(static_cast<int>(1000 + i));
            bool on = track.getController() != nullptr;
            if (ImGui::Checkbox("", &on)) track.setController(on ? tracks[i].controller.get() : nullptr);
            ImGui::SameLine();
            const auto c = std::find(controllers.begin(), controllers.end(), tracks[i].controller);
            Ref<KeyframeSequence> k = track.getKeyframeSequence();
            ImGui::Text("track %zu: %s, %d keyframes over %d ms, controller %s", i, propertyName(track.getTargetProperty()),
                        k ? k->getKeyframeCount() : 0, k ? k->getDuration() : 0,
                        c == controllers.end() ? "none" : std::to_string(c - controllers.begin()).c_str());
            ImGui::PopID();
        }
        ImGui::TreePop();
    }
    ImGui::End();
}

void textures(ViewerState& state, vk::ImGuiOverlay& overlay) {
    const auto& images = state.scene->images();
    if (images.empty()) ImGui::TextDisabled("No Image2D in the file.");
    for (std::size_t i = 0; i < images.size(); ++i) {
        const Image2D& image = *images[i];
        ImGui::PushID(static_cast<int>(i));
        ImGui::Text("%zu: Image2D %dx%d %s%s%s", i, image.getWidth(), image.getHeight(), imageFormatName(image.getFormat()),
                    image.isMutable() ? " (mutable)" : "", image.isPalettized() ? " (paletted)" : "");
        ImGui::SameLine();
        // The inspector: zoom and texel values (a click on the image too).
        const bool inspect = ImGui::SmallButton("Inspect");
        const float scale = std::min(1.0f, 256.0f / static_cast<float>(std::max(image.getWidth(), image.getHeight())));
        ImGui::Image(overlay.texture(image), ImVec2(image.getWidth() * scale, image.getHeight() * scale));
        if (inspect || ImGui::IsItemClicked()) {
            state.selected = images[i].get();
            state.inspector.open(static_cast<int>(i));
        }
        ImGui::Separator();
        ImGui::PopID();
    }
}

// The left column's lower panel: the objects in file order, and the textures.
void objectsAndTextures(ViewerState& state, vk::ImGuiOverlay& overlay) {
    if (!beginPanel("Objects", state.layout.objects)) {
        ImGui::End();
        return;
    }
    if (ImGui::BeginTabBar("objects-tabs")) {
        if (ImGui::BeginTabItem("Objects")) {
            ImGui::BeginChild("objects-list");
            for (const auto& o : state.scene->loaded().objects) {
                const std::string text = label(state, *o);
                if (ImGui::Selectable(text.c_str(), state.selected == o.get())) state.selected = o.get();
            }
            ImGui::EndChild();
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Textures")) {
            ImGui::BeginChild("textures-list");
            textures(state, overlay);
            ImGui::EndChild();
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    ImGui::End();
}

void statsAndDebug(ViewerState& state) {
    ViewerScene& scene = *state.scene;
    if (!beginPanel("View", state.layout.stats)) {
        ImGui::End();
        return;
    }
    const SceneStats& s = scene.stats();
    ImGui::Text("%s", scene.name().c_str());
    ImGui::Text("meshes %d (skinned %d, morphing %d), sprites %d", s.meshes, s.skinned, s.morphing, s.sprites);
    ImGui::Text("submeshes %d, triangles %d, vertices %d", s.submeshes, s.triangles, s.vertices);
    ImGui::Text("draws %llu, frame %.2f ms (render %.2f ms)", static_cast<unsigned long long>(state.drawsPerFrame),
                state.frameMs, state.renderMs);
    // What the device shaded in the last frame (overdraw, vertex reuse): a
    // pipeline-statistics query per frame while ticked.
    ImGui::Checkbox("count shader invocations", &state.countShaders);
    if (state.countShaders) {
        if (vk::shaderInvocationCountingSupported())
            ImGui::Text("shaded: %llu vertices, %llu fragments", static_cast<unsigned long long>(state.vertexInvocations),
                        static_cast<unsigned long long>(state.fragmentInvocations));
        else
            ImGui::TextDisabled("the device cannot count them (no pipelineStatisticsQuery)");
    }
    ImGui::Text("skinning: %s; device: %s",
                Graphics3D::getInstance()->getSkinningMode() == Graphics3D::SKINNING_COMPUTE ? "compute shader" : "CPU",
                vk::currentDevice().name.c_str());
    int compute = Graphics3D::getInstance()->getSkinningMode() == Graphics3D::SKINNING_COMPUTE ? 1 : 0;
    if (ImGui::Combo("skinning", &compute, "CPU\0compute shader\0"))
        Graphics3D::getInstance()->setSkinningMode(compute ? Graphics3D::SKINNING_COMPUTE : Graphics3D::SKINNING_CPU);
    ImGui::Separator();
    // Camera choice: the orbit camera or any Camera of the file.
    std::string current = scene.cameraIndex() < 0 ? "orbit (viewer)" : "camera " + std::to_string(scene.cameraIndex());
    if (ImGui::BeginCombo("camera", current.c_str())) {
        if (ImGui::Selectable("orbit (viewer)", scene.cameraIndex() < 0)) scene.useCamera(-1);
        for (int i = 0; i < static_cast<int>(scene.cameras().size()); ++i)
            if (ImGui::Selectable(("camera " + std::to_string(i) + " " + label(state, *scene.cameras()[i])).c_str(),
                                  scene.cameraIndex() == i))
                scene.useCamera(i);
        ImGui::EndCombo();
    }
    if (!scene.cameraError().empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", scene.cameraError().c_str());
    if (ImGui::Button("Reset view (R)")) state.resetViewRequest = true;
    ImGui::SameLine();
    if (ImGui::Button("Screenshot (S)")) {
        try {
            state.screenshotPath = nextScreenshotName();
        } catch (const std::exception& e) {
            state.status = e.what();
        }
    }
    ImGui::Checkbox("wireframe (W)", &state.debug.wireframe);
    ImGui::SameLine();
    ImGui::Checkbox("unlit (L)", &state.debug.unlit);
    ImGui::Checkbox("normals", &state.showNormals);
    ImGui::SameLine();
    ImGui::Checkbox("bounds", &state.showBounds);
    ImGui::SameLine();
    ImGui::Checkbox("bones", &state.showBones);
    bool headlight = scene.headlight();
    if (ImGui::Checkbox("headlight", &headlight)) scene.setHeadlight(headlight);
    if (!scene.hasOwnLight())
        ImGui::TextWrapped("No light of the file contributes: the headlight lights the scene.");
    if (state.pick) {
        const PickResult& p = *state.pick;
        ImGui::Separator();
        if (p.node) {
            ImGui::Text("pick at (%.0f, %.0f): %s, distance %.4f, submesh %d", p.x, p.y, p.node->getClassName(),
                        p.distance, p.submesh);
            ImGui::Text("normal (%.3f, %.3f, %.3f), texcoord 0 (%.3f, %.3f)", p.normal[0], p.normal[1], p.normal[2],
                        p.s, p.t);
        } else {
            ImGui::Text("pick at (%.0f, %.0f): nothing", p.x, p.y);
        }
    }
    if (!state.warnings.empty()) {
        ImGui::Separator();
        if (ImGui::CollapsingHeader(("Messages (" + std::to_string(state.warnings.size()) + ")###messages").c_str()))
            for (const auto& w : state.warnings) ImGui::TextWrapped("%s", w.c_str());
    }
    ImGui::End();
}

void menu(ViewerState& state) {
    static char path[1024] = "";
    static char saveAs[1024] = "";
    static std::string shownSavePath;
    if (shownSavePath != state.savePath) {  // a new file: its default save path
        shownSavePath = state.savePath;
        std::snprintf(saveAs, sizeof saveAs, "%s", state.savePath.c_str());
    }
    if (!ImGui::BeginMainMenuBar()) return;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Browse...", "Ctrl+O")) {
            try {
                showBrowser(state, state.browser.isOpen() ? state.browser.folder().string() : "");
            } catch (const std::exception& e) {
                state.status = e.what();
            }
        }
        if (ImGui::BeginMenu("Recent", !state.recent.empty())) {
            for (const auto& r : state.recent)
                if (ImGui::MenuItem(r.c_str())) state.openRequest = r;
            ImGui::EndMenu();
        }
        ImGui::InputText("path", path, sizeof path);
        if (ImGui::MenuItem("Open")) state.openRequest = path;
        ImGui::Separator();
        if (ImGui::InputText("save as", saveAs, sizeof saveAs)) state.savePath = shownSavePath = saveAs;
        if (ImGui::MenuItem("Save", "Ctrl+S", false, state.scene != nullptr)) state.saveRequest = true;
        ImGui::Separator();
        if (ImGui::MenuItem("Quit", "Esc")) state.quit = true;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        if (ImGui::MenuItem("Undo", "Ctrl+Z", false, state.edits.canUndo())) state.undoRequest = true;
        if (ImGui::MenuItem("Redo", "Ctrl+Y", false, state.edits.canRedo())) state.redoRequest = true;
        ImGui::EndMenu();
    }
    if (!state.status.empty()) {
        ImGui::Separator();
        ImGui::TextUnformatted(state.status.c_str());
    }
    ImGui::EndMainMenuBar();
}

// Load errors and a JAR's entries, over the top of the 3D view (they need
// an answer). Returns where the browser and the inspector begin: below it.
float messages(ViewerState& state) {
    const Rect& v = state.layout.view;
    if (state.error.empty() && state.jarEntries.empty() && (state.scene || state.warnings.empty())) return v.y + 8.0f;
    const float maxWidth = std::max(v.w - 16.0f, 64.0f);
    ImGui::SetNextWindowPos(ImVec2(v.x + 8.0f, v.y + 8.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(maxWidth, std::max(v.h * 0.5f, 64.0f)));
    ImGui::Begin("Messages", nullptr,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
    // Wrapped at the view's width (an auto-sized window has no width of its own to wrap at).
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + maxWidth - 2.0f * ImGui::GetStyle().WindowPadding.x);
    if (!state.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.4f, 0.4f, 1));
        ImGui::TextUnformatted(state.error.c_str());
        ImGui::PopStyleColor();
    }
    if (!state.scene)
        for (const auto& w : state.warnings) ImGui::TextUnformatted(w.c_str());
    ImGui::PopTextWrapPos();
    if (!state.jarEntries.empty()) {
        ImGui::Text("%s: pick a model", state.jarPath.c_str());
        for (const auto& e : state.jarEntries)
            if (ImGui::Selectable(e.c_str())) state.openRequest = state.jarPath + "!" + e;
    }
    const float bottom = ImGui::GetWindowPos().y + ImGui::GetWindowHeight() + 4.0f;
    ImGui::End();
    return bottom;
}

// Places a window over the 3D view from `top` down, 8 pixels in (the
// browser, the inspector).
void overView(const ViewerState& state, float top) {
    const Rect& v = state.layout.view;
    ImGui::SetNextWindowPos(ImVec2(v.x + 8.0f, top), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(std::max(v.w - 16.0f, 64.0f), std::max(v.y + v.h - 8.0f - top, 64.0f)), ImGuiCond_Always);
}

constexpr ImGuiWindowFlags kOverViewFlags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;

std::string sizeText(std::uint64_t bytes) {
    char buf[32];
    if (bytes < 10 * 1024) std::snprintf(buf, sizeof buf, "%llu B", static_cast<unsigned long long>(bytes));
    else if (bytes < 10 * 1024 * 1024) std::snprintf(buf, sizeof buf, "%llu KiB", static_cast<unsigned long long>(bytes >> 10));
    else std::snprintf(buf, sizeof buf, "%llu MiB", static_cast<unsigned long long>(bytes >> 20));
    return buf;
}

// The file browser: recent files, then the folder's sub-folders, M3G files
// (by their identifier bytes) and .jar files; a click enters or opens.
void browserWindow(ViewerState& state, float top) {
    if (!state.showBrowser || !state.browser.isOpen()) return;
    FileBrowser& browser = state.browser;
    overView(state, top);
    bool open = true;
    if (ImGui::Begin("Open a file (Ctrl+O)", &open, kOverViewFlags)) {
        try {
            if (ImGui::Button("Up")) browser.up();
            ImGui::SameLine();
            if (ImGui::Button("Refresh")) browser.refresh();
        } catch (const std::exception& e) {
            state.status = e.what();
        }
        ImGui::SameLine();
        ImGui::TextUnformatted(browser.folder().string().c_str());
        if (!state.recent.empty() && ImGui::CollapsingHeader("Recent files", ImGuiTreeNodeFlags_DefaultOpen)) {
            for (std::size_t i = 0; i < state.recent.size(); ++i) {
                ImGui::PushID(static_cast<int>(i));
                if (ImGui::Selectable(state.recent[i].c_str())) state.openRequest = state.recent[i];
                ImGui::PopID();
            }
        }
        ImGui::Separator();
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("M3G files by their identifier bytes, whatever their names; %d other file(s) not shown",
                           browser.otherFiles());
        ImGui::PopStyleColor();
        ImGui::BeginChild("##entries");
        const auto& entries = browser.entries();
        for (std::size_t i = 0; i < entries.size(); ++i) {
            const BrowserEntry& e = entries[i];
            const char* tag = e.kind == BrowserEntry::Kind::M3G   ? "[m3g]"
                              : e.kind == BrowserEntry::Kind::Jar ? "[jar]"
                                                                  : "[dir]";
            std::string text = std::string(tag) + " " + e.name;
            if (e.kind == BrowserEntry::Kind::M3G || e.kind == BrowserEntry::Kind::Jar) text += "  (" + sizeText(e.size) + ")";
            ImGui::PushID(static_cast<int>(i));
            const bool clicked = ImGui::Selectable(text.c_str());
            ImGui::PopID();
            if (!clicked) continue;
            try {
                const std::string file = browser.activate(i);
                if (!file.empty()) state.openRequest = file;
            } catch (const std::exception& ex) {
                state.status = ex.what();
            }
            break;  // the listing may have changed
        }
        ImGui::EndChild();
    }
    ImGui::End();
    if (!open) state.showBrowser = false;
}

// The texture inspector: one Image2D magnified nearest-neighbour, its
// format, and the texel under the cursor as the image stores it.
void inspectorWindow(ViewerState& state, vk::ImGuiOverlay& overlay, float top) {
    TextureInspector& in = state.inspector;
    in.wasDrawn = false;
    if (!in.isOpen() || !state.scene) return;
    const auto& images = state.scene->images();
    if (in.index() >= static_cast<int>(images.size())) {
        in.close();
        return;
    }
    const Image2D& image = *images[static_cast<std::size_t>(in.index())];
    const int w = image.getWidth(), h = image.getHeight();
    overView(state, top);
    bool open = true;
    if (ImGui::Begin("Texture inspector", &open, kOverViewFlags)) {
        std::string palette = "not paletted";
        if (image.isPalettized())
            palette = "paletted (" + std::to_string(image.palette().size() / static_cast<std::size_t>(image.bytesPerPixel())) +
                      " entries)";
        ImGui::Text("%s: %d x %d %s, %s, %s", state.scene->numbering().label(image).c_str(), w, h,
                    imageFormatName(image.getFormat()), image.isMutable() ? "mutable" : "immutable", palette.c_str());
        // The zoom buttons act on the area of the last frame (the child below).
        const Rect area = in.lastArea;
        const float lineH = ImGui::GetTextLineHeightWithSpacing();
        struct Zoom {
            const char* label;
            int zoom;
        };
        for (const Zoom z : {Zoom{"Fit", TextureInspector::kFit}, {"1:1", 1}, {"2x", 2}, {"4x", 4}, {"8x", 8}, {"16x", 16}}) {
            if (ImGui::RadioButton(z.label, in.zoom() == z.zoom)) in.setZoom(z.zoom);
            ImGui::SameLine();
        }
        if (ImGui::Button("-")) in.zoomOut(w, h, area);
        ImGui::SameLine();
        if (ImGui::Button("+")) in.zoomIn(w, h, area);
        ImGui::SameLine();
        ImGui::Text("%.2f pixels a texel", static_cast<double>(in.scale(w, h, area)));
        std::optional<Texel> hovered;
        ImGui::BeginChild("##texels", ImVec2(0, -lineH), true, ImGuiWindowFlags_HorizontalScrollbar);
        const ImVec2 origin = ImGui::GetCursorScreenPos(), room = ImGui::GetContentRegionAvail();
        in.lastArea = Rect{origin.x, origin.y, std::max(1.0f, room.x), std::max(1.0f, room.y)};
        const Rect place = in.placement(w, h, in.lastArea);
        ImGui::SetCursorScreenPos(ImVec2(place.x, place.y));
        ImGui::Image(overlay.texture(image, true), ImVec2(place.w, place.h));
        const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
        in.drawn = Rect{lo.x, lo.y, hi.x - lo.x, hi.y - lo.y};
        in.wasDrawn = true;
        if (ImGui::IsItemHovered()) {
            const ImVec2 m = ImGui::GetIO().MousePos;
            if (const auto at = TextureInspector::texelUnder(m.x, m.y, in.drawn, w, h)) hovered = texelAt(image, at->first, at->second);
        }
        ImGui::EndChild();
        if (hovered) ImGui::Text("texel %s", hovered->describe().c_str());
        else ImGui::TextDisabled("texel: move the cursor over the image");
    }
    ImGui::End();
    if (!open) in.close();
}

}  // namespace

void drawUi(ViewerState& state, vk::ImGuiOverlay& overlay) {
    menu(state);
    if (state.scene) {
        const Layout& l = state.layout;
        beginPanel("Scene", l.scene);
        sceneTree(state, state.scene->world());
        ImGui::End();
        objectsAndTextures(state, overlay);
        properties(state);
        animation(state);
        statsAndDebug(state);
        // Splitters: the columns' widths beside the view, the rows within them.
        LayoutSizes& s = state.layoutSizes;
        const float colH = std::max(1.0f, l.scene.h + l.objects.h + Layout::kGap);
        splitter("##split-left", l.leftSplitter, true, s.left, 1.0f);
        splitter("##split-right", l.rightSplitter, true, s.right, -1.0f);
        splitter("##split-left-rows", l.leftRowSplitter, false, s.leftSplit, 1.0f / colH);
        splitter("##split-right-rows1", l.rightRowSplitter1, false, s.rightSplit1, 1.0f / colH);
        splitter("##split-right-rows2", l.rightRowSplitter2, false, s.rightSplit2, 1.0f / colH);
        s = clampSizes(s, state.width, state.height);
    }
    const float top = messages(state);
    inspectorWindow(state, overlay, top);
    browserWindow(state, top);
    // A widget's edit is one undo step once the widget is let go.
    if (pending.property && !ImGui::IsAnyItemActive()) commitPending(state);
}

// ---- debug lines ----

namespace {

struct Projector {
    Transform worldToClip;
    float x, y, w, h;  ///< the view's rectangle in the window
    /// Pixel position of a world point, or false when behind the camera.
    bool operator()(const float* p, ImVec2& out) const {
        float v[4] = {p[0], p[1], p[2], 1.0f};
        worldToClip.transform(v);
        if (v[3] <= 1e-6f) return false;
        out = ImVec2(x + (v[0] / v[3] * 0.5f + 0.5f) * w, y + (0.5f - v[1] / v[3] * 0.5f) * h);
        return true;
    }
};

void line(ImDrawList* dl, const Projector& proj, const float* a, const float* b, ImU32 color) {
    ImVec2 pa, pb;
    if (proj(a, pa) && proj(b, pb)) dl->AddLine(pa, pb, color);
}

void toWorld(const Transform& t, const float* in, float* out) {
    float v[4] = {in[0], in[1], in[2], 1.0f};
    t.transform(v);
    for (int k = 0; k < 3; ++k) out[k] = v[3] != 0.0f ? v[k] / v[3] : v[k];
}

void meshLines(ViewerState& state, World& world, Node& node, const Projector& proj, ImDrawList* dl, int& budget) {
    if (auto* mesh = dynamic_cast<Mesh*>(&node); mesh && node.isRenderingEnabled()) {
        Transform t;
        VertexBuffer* vb = mesh->vertexBuffer();
        float sb[4] = {1, 0, 0, 0};
        Ref<VertexArray> pos = vb ? vb->getPositions(sb) : nullptr;
        if (pos && mesh->getTransformTo(&world, &t)) {
            const int n = pos->getVertexCount();
            float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
            Ref<VertexArray> normals = vb->getNormals();
            for (int v = 0; v < n; ++v) {
                float p[3];
                for (int k = 0; k < 3; ++k) {
                    p[k] = sb[0] * static_cast<float>(pos->value(v, k)) + sb[k + 1];
                    lo[k] = std::min(lo[k], p[k]);
                    hi[k] = std::max(hi[k], p[k]);
                }
                if (state.showNormals && normals && budget-- > 0) {
                    // Rest-pose normals (a skinned mesh's deformed ones are not shown).
                    const float scale = normals->getComponentType() == 1 ? 1.0f / 127.0f : 1.0f / 32767.0f;
                    const float len = 0.05f * state.scene->orbit().radius;
                    float q[3], a[3], b[3];
                    for (int k = 0; k < 3; ++k) q[k] = p[k] + len * scale * static_cast<float>(normals->value(v, k));
                    toWorld(t, p, a);
                    toWorld(t, q, b);
                    line(dl, proj, a, b, IM_COL32(80, 160, 255, 255));
                }
            }
            if (state.showBounds && n > 0) {
                float c[8][3];
                for (int i = 0; i < 8; ++i) {
                    const float local[3] = {(i & 1) ? hi[0] : lo[0], (i & 2) ? hi[1] : lo[1], (i & 4) ? hi[2] : lo[2]};
                    toWorld(t, local, c[i]);
                }
                for (int i = 0; i < 8; ++i)
                    for (int bit : {1, 2, 4})
                        if (!(i & bit)) line(dl, proj, c[i], c[i | bit], IM_COL32(255, 220, 0, 255));
            }
        }
        if (auto* skinned = dynamic_cast<SkinnedMesh*>(mesh); skinned && state.showBones && skinned->getSkeleton()) {
            // Each bone node to its parent, within the skeleton.
            std::vector<Node*> stack{skinned->getSkeleton().get()};
            while (!stack.empty()) {
                Node* b = stack.back();
                stack.pop_back();
                auto* g = dynamic_cast<Group*>(b);
                if (!g) continue;
                Transform tg;
                if (!g->getTransformTo(&world, &tg)) continue;
                const float origin[3] = {0, 0, 0};
                float a[3];
                toWorld(tg, origin, a);
                for (int i = 0; i < g->getChildCount(); ++i) {
                    Node* child = g->getChild(i);
                    Transform tc;
                    if (child->getTransformTo(&world, &tc)) {
                        float c[3];
                        toWorld(tc, origin, c);
                        line(dl, proj, a, c, IM_COL32(255, 80, 200, 255));
                    }
                    stack.push_back(child);
                }
            }
        }
    }
    if (auto* group = dynamic_cast<Group*>(&node))
        for (int i = 0; i < group->getChildCount(); ++i) meshLines(state, world, *group->getChild(i), proj, dl, budget);
}

}  // namespace

void drawDebugLines(ViewerState& state) {
    if (!state.scene || !(state.showNormals || state.showBounds || state.showBones)) return;
    World& world = state.scene->world();
    Ref<Camera> camera = world.getActiveCamera();
    Transform cameraToWorld;
    if (!camera || !camera->getTransformTo(&world, &cameraToWorld)) return;
    Projector proj;
    camera->getProjection(&proj.worldToClip);
    Transform view = cameraToWorld;
    view.invert();
    proj.worldToClip.postMultiply(&view);
    const Rect& v = state.layout.view;
    proj.x = v.x;
    proj.y = v.y;
    proj.w = v.w;
    proj.h = v.h;
    int budget = 20000;  // normals drawn at most
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    dl->PushClipRect(ImVec2(v.x, v.y), ImVec2(v.x + v.w, v.y + v.h));
    meshLines(state, world, world, proj, dl, budget);
    dl->PopClipRect();
}

}  // namespace m3gview
