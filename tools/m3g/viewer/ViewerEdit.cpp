#include "ViewerEdit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace m3gview {

using namespace m3g;

namespace {

template <class T>
bool is(const Object3D& o) {
    return dynamic_cast<const T*>(&o) != nullptr;
}
template <class T>
const T& as(const Object3D& o) {
    return dynamic_cast<const T&>(o);
}
template <class T>
T& as(Object3D& o) {
    return dynamic_cast<T&>(o);
}

int channel(float v) { return static_cast<int>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

std::vector<float> unpack(int argb, bool alpha) {
    const auto u = static_cast<unsigned>(argb);
    std::vector<float> v{static_cast<float>((u >> 16) & 0xFF) / 255.0f, static_cast<float>((u >> 8) & 0xFF) / 255.0f,
                         static_cast<float>(u & 0xFF) / 255.0f};
    if (alpha) v.push_back(static_cast<float>(u >> 24) / 255.0f);
    return v;
}

int pack(const std::vector<float>& v, int previousArgb) {
    const int a = v.size() > 3 ? channel(v[3]) : static_cast<int>(static_cast<unsigned>(previousArgb) >> 24);
    return static_cast<int>((static_cast<unsigned>(a) << 24) | (static_cast<unsigned>(channel(v[0])) << 16) |
                            (static_cast<unsigned>(channel(v[1])) << 8) | static_cast<unsigned>(channel(v[2])));
}

template <int Target, bool Alpha>
EditProperty materialColor(const char* name, const char* label) {
    return {name, label, Alpha ? EditKind::Color4 : EditKind::Color3, Alpha ? 4u : 3u, is<Material>,
            [](const Object3D& o) { return unpack(as<Material>(o).getColor(Target), Alpha); },
            [](Object3D& o, const std::vector<float>& v, int) {
                Material& m = as<Material>(o);
                m.setColor(Target, pack(v, m.getColor(Target)));
            }};
}

std::vector<EditProperty> makeProperties() {
    std::vector<EditProperty> p;
    p.push_back({"translation", "translation", EditKind::Float3, 3, is<Transformable>,
                 [](const Object3D& o) {
                     std::vector<float> v(3);
                     as<Transformable>(o).getTranslation(v);
                     return v;
                 },
                 [](Object3D& o, const std::vector<float>& v, int) { as<Transformable>(o).setTranslation(v[0], v[1], v[2]); }});
    p.push_back({"orientation", "orientation", EditKind::AngleAxis, 4, is<Transformable>,
                 [](const Object3D& o) {
                     std::vector<float> v(4);
                     as<Transformable>(o).getOrientation(v);
                     return v;
                 },
                 [](Object3D& o, const std::vector<float>& v, int) {
                     // A zero axis (the identity as getOrientation reports it) with angle 0 is fine.
                     const bool noAxis = v[1] == 0.0f && v[2] == 0.0f && v[3] == 0.0f;
                     if (noAxis && v[0] == 0.0f) as<Transformable>(o).setOrientation(0.0f, 1.0f, 0.0f, 0.0f);
                     else as<Transformable>(o).setOrientation(v[0], v[1], v[2], v[3]);
                 }});
    p.push_back({"scale", "scale", EditKind::Float3, 3, is<Transformable>,
                 [](const Object3D& o) {
                     std::vector<float> v(3);
                     as<Transformable>(o).getScale(v);
                     return v;
                 },
                 [](Object3D& o, const std::vector<float>& v, int) { as<Transformable>(o).setScale(v[0], v[1], v[2]); }});
    p.push_back({"rendering", "rendering enabled", EditKind::Bool, 1, is<Node>,
                 [](const Object3D& o) { return std::vector<float>{as<Node>(o).isRenderingEnabled() ? 1.0f : 0.0f}; },
                 [](Object3D& o, const std::vector<float>& v, int) { as<Node>(o).setRenderingEnable(v[0] != 0.0f); }});
    p.push_back({"picking", "picking enabled", EditKind::Bool, 1, is<Node>,
                 [](const Object3D& o) { return std::vector<float>{as<Node>(o).isPickingEnabled() ? 1.0f : 0.0f}; },
                 [](Object3D& o, const std::vector<float>& v, int) { as<Node>(o).setPickingEnable(v[0] != 0.0f); }});
    p.push_back(materialColor<Material::AMBIENT, false>("ambient", "ambient"));
    p.push_back(materialColor<Material::DIFFUSE, true>("diffuse", "diffuse (RGBA)"));
    p.push_back(materialColor<Material::EMISSIVE, false>("emissive", "emissive"));
    p.push_back(materialColor<Material::SPECULAR, false>("specular", "specular"));
    p.push_back({"shininess", "shininess", EditKind::Float, 1, is<Material>,
                 [](const Object3D& o) { return std::vector<float>{as<Material>(o).getShininess()}; },
                 [](Object3D& o, const std::vector<float>& v, int) { as<Material>(o).setShininess(v[0]); }});
    p.push_back({"speed", "speed", EditKind::Float, 1, is<AnimationController>,
                 [](const Object3D& o) { return std::vector<float>{as<AnimationController>(o).getSpeed()}; },
                 [](Object3D& o, const std::vector<float>& v, int worldTime) {
                     as<AnimationController>(o).setSpeed(v[0], worldTime);
                 }});
    p.push_back({"weight", "weight", EditKind::Float, 1, is<AnimationController>,
                 [](const Object3D& o) { return std::vector<float>{as<AnimationController>(o).getWeight()}; },
                 [](Object3D& o, const std::vector<float>& v, int) { as<AnimationController>(o).setWeight(v[0]); }});
    p.push_back({"interval", "active interval", EditKind::Int2, 2, is<AnimationController>,
                 [](const Object3D& o) {
                     const auto& c = as<AnimationController>(o);
                     return std::vector<float>{static_cast<float>(c.getActiveIntervalStart()),
                                               static_cast<float>(c.getActiveIntervalEnd())};
                 },
                 [](Object3D& o, const std::vector<float>& v, int) {
                     as<AnimationController>(o).setActiveInterval(static_cast<int>(std::lround(v[0])),
                                                                  static_cast<int>(std::lround(v[1])));
                 }});
    return p;
}

}  // namespace

const std::vector<EditProperty>& editProperties() {
    static const std::vector<EditProperty> properties = makeProperties();
    return properties;
}

std::vector<const EditProperty*> editPropertiesOf(const Object3D& object) {
    std::vector<const EditProperty*> out;
    for (const auto& p : editProperties())
        if (p.applies(object)) out.push_back(&p);
    return out;
}

const EditProperty* findEditProperty(const Object3D& object, const std::string& name) {
    for (const auto& p : editProperties())
        if (name == p.name && p.applies(object)) return &p;
    return nullptr;
}

void EditStack::push(Edit edit) {
    edits_.resize(done_);
    edits_.push_back(std::move(edit));
    done_ = edits_.size();
}

void EditStack::perform(Edit edit) {
    if (!edit.target || !edit.property) throw std::invalid_argument("edit: no object or property");
    if (edit.after.size() != edit.property->count)
        throw std::invalid_argument(std::string("edit: ") + edit.property->name + " takes " +
                                    std::to_string(edit.property->count) + " value(s)");
    if (edit.before.empty()) edit.before = edit.property->get(*edit.target);
    edit.property->set(*edit.target, edit.after, edit.worldTime);
    push(std::move(edit));
}

bool EditStack::undo() {
    if (!canUndo()) return false;
    const Edit& e = edits_[done_ - 1];
    e.property->set(*e.target, e.before, e.worldTime);
    --done_;
    return true;
}

bool EditStack::redo() {
    if (!canRedo()) return false;
    const Edit& e = edits_[done_];
    e.property->set(*e.target, e.after, e.worldTime);
    ++done_;
    return true;
}

std::string describe(const EditProperty& property, const std::vector<float>& values) {
    std::string s = std::string(property.name) + " =";
    for (float v : values) {
        char buf[32];
        std::snprintf(buf, sizeof buf, " %g", static_cast<double>(v));
        s += buf;
    }
    return s;
}

std::string nextScreenshotName(const std::string& folder) {
    for (int n = 1; n < 100000; ++n) {
        char name[48];
        std::snprintf(name, sizeof name, "m3g-screenshot-%04d.png", n);
        const std::string path = folder.empty() ? std::string(name) : folder + "/" + name;
        std::error_code ec;
        if (!std::filesystem::exists(path, ec) && !ec) return path;
    }
    throw std::runtime_error("no free screenshot name (m3g-screenshot-0001 ... 99999 all exist)");
}

}  // namespace m3gview
