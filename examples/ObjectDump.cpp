#include "ObjectDump.h"

#include <algorithm>
#include <any>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <memory>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <variant>

#include <m3g/m3g.h>

namespace m3gcli {

using namespace m3g;

namespace {

// ---------------------------------------------------------------------------
// A minimal JSON document model and writer.

class JsonValue {
public:
    using Array = std::vector<JsonValue>;
    using Members = std::vector<std::pair<std::string, JsonValue>>;
    struct Object {
        Members members;
    };

    JsonValue() = default;
    JsonValue(std::nullptr_t) {}
    JsonValue(bool b) : v_(b) {}
    JsonValue(int i) : v_(static_cast<long long>(i)) {}
    JsonValue(long long i) : v_(i) {}
    JsonValue(float f) : v_(f) {}
    JsonValue(const char* s) : v_(std::string(s)) {}
    JsonValue(std::string s) : v_(std::move(s)) {}
    JsonValue(Array a) : v_(std::move(a)) {}
    JsonValue(Object o) : v_(std::move(o)) {}

    static JsonValue array() { return JsonValue(Array{}); }
    static JsonValue object() { return JsonValue(Object{}); }

    /// Appends to an array.
    JsonValue& add(JsonValue v) {
        std::get<Array>(v_).push_back(std::move(v));
        return *this;
    }
    /// Appends a member to an object (keys are written in insertion order).
    JsonValue& set(std::string key, JsonValue v) {
        std::get<Object>(v_).members.emplace_back(std::move(key), std::move(v));
        return *this;
    }

    void write(std::string& out, int indent) const {
        std::visit([&](const auto& x) { writeValue(out, x, indent); }, v_);
    }

private:
    bool isScalar() const { return !std::holds_alternative<Array>(v_) && !std::holds_alternative<Object>(v_); }

    static void writeValue(std::string& out, std::monostate, int) { out += "null"; }
    static void writeValue(std::string& out, bool b, int) { out += b ? "true" : "false"; }
    static void writeValue(std::string& out, long long i, int) { out += std::to_string(i); }
    static void writeValue(std::string& out, float f, int) {
        if (!std::isfinite(f)) {
            out += "null";
            return;
        }
        char buf[64];
        // Shortest representation that reads back as the same float.
        auto res = std::to_chars(buf, buf + sizeof buf, f);
        out.append(buf, res.ptr);
    }
    static void writeValue(std::string& out, const std::string& s, int) { writeString(out, s); }
    static void writeValue(std::string& out, const Array& a, int indent) {
        if (a.empty()) {
            out += "[]";
            return;
        }
        const bool inlined = std::all_of(a.begin(), a.end(), [](const JsonValue& e) { return e.isScalar(); });
        if (inlined) {
            out += '[';
            for (std::size_t i = 0; i < a.size(); ++i) {
                if (i) out += ", ";
                a[i].write(out, indent);
            }
            out += ']';
            return;
        }
        out += "[\n";
        for (std::size_t i = 0; i < a.size(); ++i) {
            out.append(static_cast<std::size_t>(indent + 2), ' ');
            a[i].write(out, indent + 2);
            out += i + 1 < a.size() ? ",\n" : "\n";
        }
        out.append(static_cast<std::size_t>(indent), ' ');
        out += ']';
    }
    static void writeValue(std::string& out, const Object& o, int indent) {
        if (o.members.empty()) {
            out += "{}";
            return;
        }
        out += "{\n";
        for (std::size_t i = 0; i < o.members.size(); ++i) {
            out.append(static_cast<std::size_t>(indent + 2), ' ');
            writeString(out, o.members[i].first);
            out += ": ";
            o.members[i].second.write(out, indent + 2);
            out += i + 1 < o.members.size() ? ",\n" : "\n";
        }
        out.append(static_cast<std::size_t>(indent), ' ');
        out += '}';
    }
    static void writeString(std::string& out, std::string_view s) {
        out += '"';
        for (char c : s) {
            const auto u = static_cast<unsigned char>(c);
            switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\r': out += "\\r"; break;
            case '\t': out += "\\t"; break;
            case '\b': out += "\\b"; break;
            case '\f': out += "\\f"; break;
            default:
                if (u < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", u);
                    out += buf;
                } else {
                    out += c;
                }
            }
        }
        out += '"';
    }

    std::variant<std::monostate, bool, long long, float, std::string, Array, Object> v_;
};

// ---------------------------------------------------------------------------
// Traversal.

/// Direct links followed by the dump: getReferences(), then SkinnedMesh
/// bones, then Node alignment references (Z, Y). Nulls omitted.
std::vector<Object3D*> links(const Object3D* o) {
    std::vector<Ref<Object3D>> refs(static_cast<std::size_t>(o->getReferences()));
    if (!refs.empty()) o->getReferences(refs);
    std::vector<Object3D*> out;
    out.reserve(refs.size() + 2);
    for (const auto& r : refs)
        if (r) out.push_back(r.get());
    if (const auto* sm = dynamic_cast<const SkinnedMesh*>(o))
        for (int i = 0; i < sm->boneCount(); ++i)
            if (Node* b = sm->bone(i)) out.push_back(b);
    if (const auto* n = dynamic_cast<const Node*>(o)) {
        for (int axis : {Node::Z_AXIS, Node::Y_AXIS})
            if (Ref<Node> a = n->getAlignmentReference(axis)) out.push_back(a.get());
    }
    return out;
}

using IdMap = std::unordered_map<const Object3D*, int>;

IdMap makeIds(const std::vector<Object3D*>& objects) {
    IdMap ids;
    for (std::size_t i = 0; i < objects.size(); ++i) ids.emplace(objects[i], static_cast<int>(i));
    return ids;
}

// ---------------------------------------------------------------------------
// Value helpers.

JsonValue idOf(const IdMap& ids, const Object3D* o) {
    if (!o) return nullptr;
    auto it = ids.find(o);
    return it == ids.end() ? JsonValue() : JsonValue(it->second);
}

std::string hex32(std::uint32_t v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%08X", static_cast<unsigned>(v));
    return buf;
}
JsonValue color(int argb) { return hex32(static_cast<std::uint32_t>(argb)); }

std::string enumName(int value, std::initializer_list<std::pair<int, const char*>> names) {
    for (const auto& [v, n] : names)
        if (v == value) return n;
    return std::to_string(value);  // not a known constant: its decimal value
}

JsonValue floats(std::span<const float> v) {
    JsonValue a = JsonValue::array();
    for (float f : v) a.add(f);
    return a;
}
JsonValue ints(std::span<const int> v) {
    JsonValue a = JsonValue::array();
    for (int i : v) a.add(i);
    return a;
}
JsonValue matrix(const Transform& t) {
    float m[16];
    t.get(m);
    return floats(m);
}

std::string alignmentTargetName(int t) {
    return enumName(t, {{Node::NONE, "NONE"},
                        {Node::ORIGIN, "ORIGIN"},
                        {Node::X_AXIS, "X_AXIS"},
                        {Node::Y_AXIS, "Y_AXIS"},
                        {Node::Z_AXIS, "Z_AXIS"}});
}
std::string projectionName(int t) {
    return enumName(t, {{Camera::GENERIC, "GENERIC"}, {Camera::PARALLEL, "PARALLEL"}, {Camera::PERSPECTIVE, "PERSPECTIVE"}});
}
std::string lightModeName(int m) {
    return enumName(m, {{Light::AMBIENT, "AMBIENT"}, {Light::DIRECTIONAL, "DIRECTIONAL"}, {Light::OMNI, "OMNI"}, {Light::SPOT, "SPOT"}});
}
std::string imageFormatName(int f) {
    return enumName(f, {{Image2D::ALPHA, "ALPHA"},
                        {Image2D::LUMINANCE, "LUMINANCE"},
                        {Image2D::LUMINANCE_ALPHA, "LUMINANCE_ALPHA"},
                        {Image2D::RGB, "RGB"},
                        {Image2D::RGBA, "RGBA"}});
}
std::string propertyName(int p) {
    return enumName(p, {{AnimationTrack::ALPHA, "ALPHA"},
                        {AnimationTrack::AMBIENT_COLOR, "AMBIENT_COLOR"},
                        {AnimationTrack::COLOR, "COLOR"},
                        {AnimationTrack::CROP, "CROP"},
                        {AnimationTrack::DENSITY, "DENSITY"},
                        {AnimationTrack::DIFFUSE_COLOR, "DIFFUSE_COLOR"},
                        {AnimationTrack::EMISSIVE_COLOR, "EMISSIVE_COLOR"},
                        {AnimationTrack::FAR_DISTANCE, "FAR_DISTANCE"},
                        {AnimationTrack::FIELD_OF_VIEW, "FIELD_OF_VIEW"},
                        {AnimationTrack::INTENSITY, "INTENSITY"},
                        {AnimationTrack::MORPH_WEIGHTS, "MORPH_WEIGHTS"},
                        {AnimationTrack::NEAR_DISTANCE, "NEAR_DISTANCE"},
                        {AnimationTrack::ORIENTATION, "ORIENTATION"},
                        {AnimationTrack::PICKABILITY, "PICKABILITY"},
                        {AnimationTrack::SCALE, "SCALE"},
                        {AnimationTrack::SHININESS, "SHININESS"},
                        {AnimationTrack::SPECULAR_COLOR, "SPECULAR_COLOR"},
                        {AnimationTrack::SPOT_ANGLE, "SPOT_ANGLE"},
                        {AnimationTrack::SPOT_EXPONENT, "SPOT_EXPONENT"},
                        {AnimationTrack::TRANSLATION, "TRANSLATION"},
                        {AnimationTrack::VISIBILITY, "VISIBILITY"}});
}

/// FNV-1a, 32 bits.
std::uint32_t checksum(std::span<const std::uint8_t> bytes) {
    std::uint32_t h = 2166136261u;
    for (std::uint8_t b : bytes) {
        h ^= b;
        h *= 16777619u;
    }
    return h;
}

const UserParameters* userParameters(const Object3D* o) {
    const std::any& u = o->getUserObject();
    if (const auto* p = std::any_cast<std::shared_ptr<const UserParameters>>(&u)) return p->get();
    if (const auto* q = std::any_cast<std::shared_ptr<UserParameters>>(&u)) return q->get();
    return nullptr;
}

std::string hexBytes(std::span<const std::uint8_t> bytes) {
    static constexpr char digits[] = "0123456789abcdef";
    std::string s;
    s.reserve(bytes.size() * 2);
    for (std::uint8_t b : bytes) {
        s += digits[b >> 4];
        s += digits[b & 15];
    }
    return s;
}

// ---------------------------------------------------------------------------
// Per-class properties. Each block adds the getters of one class; an object
// gets the blocks of all its classes, base first.

struct Dumper {
    const IdMap& ids;
    const DumpOptions& opt;

    JsonValue ref(const Object3D* o) const { return idOf(ids, o); }

    void object3D(const Object3D* o, JsonValue& j) const {
        j.set("id", idOf(ids, o));
        j.set("class", o->getClassName());
        j.set("userID", o->getUserID());
        const UserParameters* params = userParameters(o);
        const std::any& u = o->getUserObject();
        j.set("userObject", params ? JsonValue("UserParameters") : u.has_value() ? JsonValue("other") : JsonValue());
        if (params) {
            JsonValue p = JsonValue::object();
            for (const auto& [key, bytes] : *params) p.set(std::to_string(key), hexBytes(bytes));
            j.set("userParameters", std::move(p));
        } else {
            j.set("userParameters", nullptr);
        }
        JsonValue tracks = JsonValue::array();
        for (int i = 0; i < o->getAnimationTrackCount(); ++i) tracks.add(ref(o->getAnimationTrack(i).get()));
        j.set("animationTracks", std::move(tracks));
        std::vector<Ref<Object3D>> refs(static_cast<std::size_t>(o->getReferences()));
        if (!refs.empty()) o->getReferences(refs);
        JsonValue r = JsonValue::array();
        for (const auto& x : refs) r.add(ref(x.get()));
        j.set("references", std::move(r));
    }

    void transformable(const Transformable* t, JsonValue& j) const {
        float v[4];
        t->getTranslation(v);
        j.set("translation", floats(std::span<const float>(v, 3)));
        t->getOrientation(v);
        j.set("orientation", floats(std::span<const float>(v, 4)));  // angle, axis x, y, z
        t->getScale(v);
        j.set("scale", floats(std::span<const float>(v, 3)));
        Transform m;
        t->getTransform(&m);
        j.set("transform", matrix(m));
        t->getCompositeTransform(&m);
        j.set("compositeTransform", matrix(m));
    }

    void node(const Node* n, JsonValue& j) const {
        j.set("parent", ref(n->getParent().get()));
        j.set("renderingEnabled", n->isRenderingEnabled());
        j.set("pickingEnabled", n->isPickingEnabled());
        j.set("alphaFactor", n->getAlphaFactor());
        j.set("scope", n->getScope());
        JsonValue a = JsonValue::object();
        a.set("zTarget", alignmentTargetName(n->getAlignmentTarget(Node::Z_AXIS)));
        a.set("zReference", ref(n->getAlignmentReference(Node::Z_AXIS).get()));
        a.set("yTarget", alignmentTargetName(n->getAlignmentTarget(Node::Y_AXIS)));
        a.set("yReference", ref(n->getAlignmentReference(Node::Y_AXIS).get()));
        j.set("alignment", std::move(a));
    }

    void group(const Group* g, JsonValue& j) const {
        JsonValue c = JsonValue::array();
        for (int i = 0; i < g->getChildCount(); ++i) c.add(ref(g->getChild(i).get()));
        j.set("childCount", g->getChildCount());
        j.set("children", std::move(c));
    }

    void world(const World* w, JsonValue& j) const {
        j.set("activeCamera", ref(w->getActiveCamera().get()));
        j.set("background", ref(w->getBackground().get()));
    }

    void camera(const Camera* c, JsonValue& j) const {
        float p[4];
        const int type = c->getProjection(std::span<float>(p));
        j.set("projection", projectionName(type));
        j.set("projectionParams", type == Camera::GENERIC ? JsonValue() : floats(p));
        Transform m;
        try {
            c->getProjection(&m);
            j.set("projectionMatrix", matrix(m));
        } catch (const ArithmeticException&) {
            j.set("projectionMatrix", nullptr);  // near == far
        }
    }

    void light(const Light* l, JsonValue& j) const {
        j.set("mode", lightModeName(l->getMode()));
        j.set("color", color(l->getColor()));
        j.set("intensity", l->getIntensity());
        j.set("spotAngle", l->getSpotAngle());
        j.set("spotExponent", l->getSpotExponent());
        const float att[] = {l->getConstantAttenuation(), l->getLinearAttenuation(), l->getQuadraticAttenuation()};
        j.set("attenuation", floats(att));
    }

    void mesh(const Mesh* m, JsonValue& j) const {
        j.set("vertexBuffer", ref(m->getVertexBuffer().get()));
        j.set("submeshCount", m->getSubmeshCount());
        JsonValue subs = JsonValue::array();
        for (int i = 0; i < m->getSubmeshCount(); ++i) {
            JsonValue s = JsonValue::object();
            s.set("indexBuffer", ref(m->getIndexBuffer(i).get()));
            s.set("appearance", ref(m->getAppearance(i).get()));
            subs.add(std::move(s));
        }
        j.set("submeshes", std::move(subs));
    }

    void morphingMesh(const MorphingMesh* m, JsonValue& j) const {
        JsonValue t = JsonValue::array();
        for (int i = 0; i < m->getMorphTargetCount(); ++i) t.add(ref(m->getMorphTarget(i).get()));
        j.set("morphTargets", std::move(t));
        std::vector<float> w(static_cast<std::size_t>(m->getMorphTargetCount()));
        if (!w.empty()) m->getWeights(w);
        j.set("weights", floats(w));
    }

    void skinnedMesh(const SkinnedMesh* m, JsonValue& j) const {
        j.set("skeleton", ref(m->getSkeleton().get()));
        JsonValue bones = JsonValue::array();
        for (int i = 0; i < m->boneCount(); ++i) {
            Node* b = m->bone(i);
            JsonValue e = JsonValue::object();
            e.set("bone", ref(b));
            if (b) {
                e.set("vertexCount", m->getBoneVertices(b));
                Transform t;
                m->getBoneTransform(b, &t);
                e.set("atRestTransform", matrix(t));
            }
            bones.add(std::move(e));
        }
        j.set("bones", std::move(bones));
    }

    void sprite(const Sprite3D* s, JsonValue& j) const {
        j.set("scaled", s->isScaled());
        j.set("image", ref(s->getImage().get()));
        j.set("appearance", ref(s->getAppearance().get()));
        const int crop[] = {s->getCropX(), s->getCropY(), s->getCropWidth(), s->getCropHeight()};
        j.set("crop", ints(crop));
    }

    void appearance(const Appearance* a, JsonValue& j) const {
        j.set("layer", a->getLayer());
        j.set("compositingMode", ref(a->getCompositingMode().get()));
        j.set("fog", ref(a->getFog().get()));
        j.set("polygonMode", ref(a->getPolygonMode().get()));
        j.set("material", ref(a->getMaterial().get()));
        JsonValue t = JsonValue::array();
        for (int i = 0; i < getLimits().numTextureUnits; ++i) t.add(ref(a->getTexture(i).get()));
        j.set("textures", std::move(t));
    }

    void compositingMode(const CompositingMode* c, JsonValue& j) const {
        j.set("blending", enumName(c->getBlending(), {{CompositingMode::ALPHA, "ALPHA"},
                                                      {CompositingMode::ALPHA_ADD, "ALPHA_ADD"},
                                                      {CompositingMode::MODULATE, "MODULATE"},
                                                      {CompositingMode::MODULATE_X2, "MODULATE_X2"},
                                                      {CompositingMode::REPLACE, "REPLACE"}}));
        j.set("alphaThreshold", c->getAlphaThreshold());
        j.set("depthTestEnabled", c->isDepthTestEnabled());
        j.set("depthWriteEnabled", c->isDepthWriteEnabled());
        j.set("colorWriteEnabled", c->isColorWriteEnabled());
        j.set("alphaWriteEnabled", c->isAlphaWriteEnabled());
        j.set("depthOffsetFactor", c->getDepthOffsetFactor());
        j.set("depthOffsetUnits", c->getDepthOffsetUnits());
    }

    void polygonMode(const PolygonMode* p, JsonValue& j) const {
        j.set("culling", enumName(p->getCulling(), {{PolygonMode::CULL_BACK, "CULL_BACK"},
                                                    {PolygonMode::CULL_FRONT, "CULL_FRONT"},
                                                    {PolygonMode::CULL_NONE, "CULL_NONE"}}));
        j.set("shading", enumName(p->getShading(), {{PolygonMode::SHADE_FLAT, "SHADE_FLAT"},
                                                    {PolygonMode::SHADE_SMOOTH, "SHADE_SMOOTH"}}));
        j.set("winding", enumName(p->getWinding(), {{PolygonMode::WINDING_CCW, "WINDING_CCW"},
                                                    {PolygonMode::WINDING_CW, "WINDING_CW"}}));
        j.set("twoSidedLightingEnabled", p->isTwoSidedLightingEnabled());
        j.set("localCameraLightingEnabled", p->isLocalCameraLightingEnabled());
        j.set("perspectiveCorrectionEnabled", p->isPerspectiveCorrectionEnabled());
    }

    void material(const Material* m, JsonValue& j) const {
        j.set("ambientColor", color(m->getColor(Material::AMBIENT)));
        j.set("diffuseColor", color(m->getColor(Material::DIFFUSE)));
        j.set("emissiveColor", color(m->getColor(Material::EMISSIVE)));
        j.set("specularColor", color(m->getColor(Material::SPECULAR)));
        j.set("shininess", m->getShininess());
        j.set("vertexColorTrackingEnabled", m->isVertexColorTrackingEnabled());
    }

    void fog(const Fog* f, JsonValue& j) const {
        j.set("mode", enumName(f->getMode(), {{Fog::EXPONENTIAL, "EXPONENTIAL"}, {Fog::LINEAR, "LINEAR"}}));
        j.set("color", color(f->getColor()));
        j.set("density", f->getDensity());
        j.set("nearDistance", f->getNearDistance());
        j.set("farDistance", f->getFarDistance());
    }

    void background(const Background* b, JsonValue& j) const {
        j.set("color", color(b->getColor()));
        j.set("image", ref(b->getImage().get()));
        const std::initializer_list<std::pair<int, const char*>> modes = {{Background::BORDER, "BORDER"},
                                                                         {Background::REPEAT, "REPEAT"}};
        j.set("imageModeX", enumName(b->getImageModeX(), modes));
        j.set("imageModeY", enumName(b->getImageModeY(), modes));
        const int crop[] = {b->getCropX(), b->getCropY(), b->getCropWidth(), b->getCropHeight()};
        j.set("crop", ints(crop));
        j.set("colorClearEnabled", b->isColorClearEnabled());
        j.set("depthClearEnabled", b->isDepthClearEnabled());
    }

    void image(const Image2D* im, JsonValue& j) const {
        j.set("format", imageFormatName(im->getFormat()));
        j.set("width", im->getWidth());
        j.set("height", im->getHeight());
        j.set("mutable", im->isMutable());
        j.set("palettized", im->isPalettized());
        j.set("pixelBytes", static_cast<long long>(im->pixels().size()));
        j.set("pixelChecksum", hex32(checksum(im->pixels())));  // FNV-1a of the resolved pixels
    }

    void texture(const Texture2D* t, JsonValue& j) const {
        const std::initializer_list<std::pair<int, const char*>> filters = {
            {Texture2D::FILTER_BASE_LEVEL, "FILTER_BASE_LEVEL"},
            {Texture2D::FILTER_LINEAR, "FILTER_LINEAR"},
            {Texture2D::FILTER_NEAREST, "FILTER_NEAREST"}};
        const std::initializer_list<std::pair<int, const char*>> wraps = {{Texture2D::WRAP_CLAMP, "WRAP_CLAMP"},
                                                                         {Texture2D::WRAP_REPEAT, "WRAP_REPEAT"}};
        j.set("image", ref(t->getImage().get()));
        j.set("levelFilter", enumName(t->getLevelFilter(), filters));
        j.set("imageFilter", enumName(t->getImageFilter(), filters));
        j.set("wrappingS", enumName(t->getWrappingS(), wraps));
        j.set("wrappingT", enumName(t->getWrappingT(), wraps));
        j.set("blending", enumName(t->getBlending(), {{Texture2D::FUNC_ADD, "FUNC_ADD"},
                                                      {Texture2D::FUNC_BLEND, "FUNC_BLEND"},
                                                      {Texture2D::FUNC_DECAL, "FUNC_DECAL"},
                                                      {Texture2D::FUNC_MODULATE, "FUNC_MODULATE"},
                                                      {Texture2D::FUNC_REPLACE, "FUNC_REPLACE"}}));
        j.set("blendColor", color(t->getBlendColor()));
    }

    void vertexArray(const VertexArray* va, JsonValue& j) const {
        const int n = va->getVertexCount();
        const int c = va->getComponentCount();
        const int shown = std::clamp(opt.maxVertices, 0, n);
        j.set("vertexCount", n);
        j.set("componentCount", c);
        j.set("componentType", va->getComponentType());  // bytes per component
        std::vector<int> values(static_cast<std::size_t>(shown) * static_cast<std::size_t>(c));
        if (shown > 0) {
            if (va->getComponentType() == 1) {
                std::vector<std::int8_t> raw(values.size());
                va->get(0, shown, std::span<std::int8_t>(raw));
                std::copy(raw.begin(), raw.end(), values.begin());
            } else {
                std::vector<std::int16_t> raw(values.size());
                va->get(0, shown, std::span<std::int16_t>(raw));
                std::copy(raw.begin(), raw.end(), values.begin());
            }
        }
        JsonValue rows = JsonValue::array();
        for (int v = 0; v < shown; ++v)
            rows.add(ints(std::span<const int>(values).subspan(static_cast<std::size_t>(v) * c, static_cast<std::size_t>(c))));
        j.set("values", std::move(rows));
        j.set("truncated", shown < n);
    }

    void vertexBuffer(const VertexBuffer* vb, JsonValue& j) const {
        j.set("vertexCount", vb->getVertexCount());
        float sb[4] = {0, 0, 0, 0};
        if (Ref<VertexArray> p = vb->getPositions(std::span<float>(sb))) {
            JsonValue e = JsonValue::object();
            e.set("array", ref(p.get()));
            e.set("scale", sb[0]);
            e.set("bias", floats(std::span<const float>(sb + 1, 3)));
            j.set("positions", std::move(e));
        } else {
            j.set("positions", nullptr);
        }
        j.set("normals", ref(vb->getNormals().get()));
        j.set("colors", ref(vb->getColors().get()));
        JsonValue tcs = JsonValue::array();
        for (int i = 0; i < getLimits().numTextureUnits; ++i) {
            Ref<VertexArray> t = vb->getTexCoords(i);
            if (!t) {
                tcs.add(nullptr);
                continue;
            }
            const int nc = t->getComponentCount();
            std::vector<float> v(static_cast<std::size_t>(nc) + 1);
            vb->getTexCoords(i, v);
            JsonValue e = JsonValue::object();
            e.set("array", ref(t.get()));
            e.set("scale", v[0]);
            e.set("bias", floats(std::span<const float>(v).subspan(1)));
            tcs.add(std::move(e));
        }
        j.set("texCoords", std::move(tcs));
        j.set("defaultColor", color(vb->getDefaultColor()));
    }

    void indexBuffer(const IndexBuffer* ib, JsonValue& j) const {
        const int n = ib->getIndexCount();
        const int shown = std::clamp(opt.maxIndices, 0, n);
        std::vector<int> all(static_cast<std::size_t>(n));
        if (n > 0) ib->getIndices(all);
        j.set("indexCount", n);
        j.set("indices", ints(std::span<const int>(all).first(static_cast<std::size_t>(shown))));
        j.set("truncated", shown < n);
    }

    void strips(const TriangleStripArray* t, JsonValue& j) const {
        const auto lengths = t->stripLengths();
        const std::size_t shown = std::min(lengths.size(), static_cast<std::size_t>(std::max(opt.maxIndices, 0)));
        j.set("stripCount", static_cast<long long>(lengths.size()));
        j.set("stripLengths", ints(lengths.first(shown)));
        j.set("stripLengthsTruncated", shown < lengths.size());
    }

    void keyframes(const KeyframeSequence* k, JsonValue& j) const {
        j.set("keyframeCount", k->getKeyframeCount());
        j.set("componentCount", k->getComponentCount());
        j.set("interpolation", enumName(k->getInterpolationType(), {{KeyframeSequence::LINEAR, "LINEAR"},
                                                                    {KeyframeSequence::SLERP, "SLERP"},
                                                                    {KeyframeSequence::SPLINE, "SPLINE"},
                                                                    {KeyframeSequence::SQUAD, "SQUAD"},
                                                                    {KeyframeSequence::STEP, "STEP"}}));
        j.set("duration", k->getDuration());
        j.set("repeatMode", enumName(k->getRepeatMode(), {{KeyframeSequence::CONSTANT, "CONSTANT"},
                                                          {KeyframeSequence::LOOP, "LOOP"}}));
        const int vr[] = {k->getValidRangeFirst(), k->getValidRangeLast()};
        j.set("validRange", ints(vr));
        const int n = k->getKeyframeCount();
        const int shown = std::clamp(opt.maxKeyframes, 0, n);
        JsonValue times = JsonValue::array();
        JsonValue values = JsonValue::array();
        std::vector<float> v(static_cast<std::size_t>(k->getComponentCount()));
        for (int i = 0; i < shown; ++i) {
            times.add(k->getKeyframe(i, v));
            values.add(floats(v));
        }
        j.set("keyframeTimes", std::move(times));
        j.set("keyframeValues", std::move(values));
        j.set("truncated", shown < n);
    }

    void track(const AnimationTrack* t, JsonValue& j) const {
        j.set("targetProperty", propertyName(t->getTargetProperty()));
        j.set("keyframeSequence", ref(t->getKeyframeSequence().get()));
        j.set("controller", ref(t->getController().get()));
    }

    void controller(const AnimationController* c, JsonValue& j) const {
        const int interval[] = {c->getActiveIntervalStart(), c->getActiveIntervalEnd()};
        j.set("activeInterval", ints(interval));
        j.set("speed", c->getSpeed());
        j.set("weight", c->getWeight());
        j.set("refWorldTime", c->getRefWorldTime());
        j.set("refSequenceTime", c->getPosition(c->getRefWorldTime()));
        if (opt.worldTime) {
            j.set("worldTime", *opt.worldTime);
            j.set("position", c->getPosition(*opt.worldTime));
            j.set("active", c->isActive(*opt.worldTime));
        }
    }

    JsonValue dump(const Object3D* o) const {
        JsonValue j = JsonValue::object();
        object3D(o, j);
        if (auto* x = dynamic_cast<const Transformable*>(o)) transformable(x, j);
        if (auto* x = dynamic_cast<const Node*>(o)) node(x, j);
        if (auto* x = dynamic_cast<const Group*>(o)) group(x, j);
        if (auto* x = dynamic_cast<const World*>(o)) world(x, j);
        if (auto* x = dynamic_cast<const Camera*>(o)) camera(x, j);
        if (auto* x = dynamic_cast<const Light*>(o)) light(x, j);
        if (auto* x = dynamic_cast<const Mesh*>(o)) mesh(x, j);
        if (auto* x = dynamic_cast<const MorphingMesh*>(o)) morphingMesh(x, j);
        if (auto* x = dynamic_cast<const SkinnedMesh*>(o)) skinnedMesh(x, j);
        if (auto* x = dynamic_cast<const Sprite3D*>(o)) sprite(x, j);
        if (auto* x = dynamic_cast<const Appearance*>(o)) appearance(x, j);
        if (auto* x = dynamic_cast<const CompositingMode*>(o)) compositingMode(x, j);
        if (auto* x = dynamic_cast<const PolygonMode*>(o)) polygonMode(x, j);
        if (auto* x = dynamic_cast<const Material*>(o)) material(x, j);
        if (auto* x = dynamic_cast<const Fog*>(o)) fog(x, j);
        if (auto* x = dynamic_cast<const Background*>(o)) background(x, j);
        if (auto* x = dynamic_cast<const Image2D*>(o)) image(x, j);
        if (auto* x = dynamic_cast<const Texture2D*>(o)) texture(x, j);
        if (auto* x = dynamic_cast<const VertexArray*>(o)) vertexArray(x, j);
        if (auto* x = dynamic_cast<const VertexBuffer*>(o)) vertexBuffer(x, j);
        if (auto* x = dynamic_cast<const IndexBuffer*>(o)) indexBuffer(x, j);
        if (auto* x = dynamic_cast<const TriangleStripArray*>(o)) strips(x, j);
        if (auto* x = dynamic_cast<const KeyframeSequence*>(o)) keyframes(x, j);
        if (auto* x = dynamic_cast<const AnimationTrack*>(o)) track(x, j);
        if (auto* x = dynamic_cast<const AnimationController*>(o)) controller(x, j);
        return j;
    }
};

// ---------------------------------------------------------------------------
// Tree summaries.

std::string num(float f) {
    if (!std::isfinite(f)) return std::isnan(f) ? "nan" : (f < 0 ? "-inf" : "inf");
    char buf[64];
    auto res = std::to_chars(buf, buf + sizeof buf, f);
    return std::string(buf, res.ptr);
}

std::string summary(const Object3D* o, const IdMap& ids) {
    std::string s;
    auto add = [&](const std::string& part) {
        s += ' ';
        s += part;
    };
    auto refText = [&](const Object3D* x) {
        if (!x) return std::string("none");
        auto it = ids.find(x);
        return it == ids.end() ? std::string("?") : "#" + std::to_string(it->second);
    };
    if (auto* w = dynamic_cast<const World*>(o)) {
        add("camera=" + refText(w->getActiveCamera().get()));
        add("background=" + refText(w->getBackground().get()));
    }
    if (auto* g = dynamic_cast<const Group*>(o)) add("children=" + std::to_string(g->getChildCount()));
    if (auto* c = dynamic_cast<const Camera*>(o)) {
        float p[4];
        const int type = c->getProjection(std::span<float>(p));
        add(projectionName(type));
        if (type == Camera::PERSPECTIVE)
            add("fovy=" + num(p[0]) + " aspect=" + num(p[1]) + " near=" + num(p[2]) + " far=" + num(p[3]));
        else if (type == Camera::PARALLEL)
            add("height=" + num(p[0]) + " aspect=" + num(p[1]) + " near=" + num(p[2]) + " far=" + num(p[3]));
    }
    if (auto* l = dynamic_cast<const Light*>(o)) {
        add(lightModeName(l->getMode()));
        add("color=" + hex32(static_cast<std::uint32_t>(l->getColor())));
        add("intensity=" + num(l->getIntensity()));
    }
    if (auto* m = dynamic_cast<const Mesh*>(o)) {
        add("submeshes=" + std::to_string(m->getSubmeshCount()));
        add("vertices=" + std::to_string(m->getVertexBuffer() ? m->getVertexBuffer()->getVertexCount() : 0));
        int indices = 0;
        for (int i = 0; i < m->getSubmeshCount(); ++i) indices += m->getIndexBuffer(i)->getIndexCount();
        add("triangles=" + std::to_string(indices / 3));
    }
    if (auto* m = dynamic_cast<const MorphingMesh*>(o)) add("targets=" + std::to_string(m->getMorphTargetCount()));
    if (auto* m = dynamic_cast<const SkinnedMesh*>(o)) add("bones=" + std::to_string(m->boneCount()));
    if (auto* sp = dynamic_cast<const Sprite3D*>(o)) {
        add(sp->isScaled() ? "scaled" : "unscaled");
        add("crop=" + std::to_string(sp->getCropX()) + "," + std::to_string(sp->getCropY()) + "," +
            std::to_string(sp->getCropWidth()) + "x" + std::to_string(sp->getCropHeight()));
    }
    if (auto* im = dynamic_cast<const Image2D*>(o)) {
        add(imageFormatName(im->getFormat()));
        add(std::to_string(im->getWidth()) + "x" + std::to_string(im->getHeight()));
        if (im->isMutable()) add("mutable");
    }
    if (auto* n = dynamic_cast<const Node*>(o)) {
        if (!n->isRenderingEnabled()) add("rendering=off");
        if (!n->isPickingEnabled()) add("picking=off");
        if (n->getAlphaFactor() != 1.0f) add("alpha=" + num(n->getAlphaFactor()));
        if (n->getScope() != -1) add("scope=" + std::to_string(n->getScope()));
        if (n->getAlignmentTarget(Node::Z_AXIS) != Node::NONE || n->getAlignmentTarget(Node::Y_AXIS) != Node::NONE)
            add("aligned");
        if (n->boneUseCount() > 0) add("bone");
    }
    if (o->getAnimationTrackCount() > 0) add("tracks=" + std::to_string(o->getAnimationTrackCount()));
    return s;
}

}  // namespace

std::vector<Object3D*> collectObjects(std::span<Object3D* const> roots) {
    std::vector<Object3D*> order;
    std::unordered_set<const Object3D*> seen;
    std::vector<Object3D*> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it)
        if (*it) stack.push_back(*it);
    // Iterative depth-first pre-order: the same order as a recursive walk,
    // without recursion depth limits on long node chains.
    while (!stack.empty()) {
        Object3D* o = stack.back();
        stack.pop_back();
        if (!seen.insert(o).second) continue;
        order.push_back(o);
        const std::vector<Object3D*> next = links(o);
        for (auto it = next.rbegin(); it != next.rend(); ++it)
            if (!seen.count(*it)) stack.push_back(*it);
    }
    return order;
}

std::string dumpJson(std::span<Object3D* const> roots, const DumpOptions& options) {
    const std::vector<Object3D*> objects = collectObjects(roots);
    const IdMap ids = makeIds(objects);
    const Dumper dumper{ids, options};

    JsonValue doc = JsonValue::object();
    doc.set("objectCount", static_cast<int>(objects.size()));
    JsonValue rootIds = JsonValue::array();
    for (Object3D* r : roots)
        if (r) rootIds.add(idOf(ids, r));
    doc.set("roots", std::move(rootIds));
    JsonValue list = JsonValue::array();
    for (const Object3D* o : objects) list.add(dumper.dump(o));
    doc.set("objects", std::move(list));

    std::string out;
    doc.write(out, 0);
    out += '\n';
    return out;
}

std::string dumpTree(std::span<Object3D* const> roots) {
    const std::vector<Object3D*> objects = collectObjects(roots);
    const IdMap ids = makeIds(objects);

    struct Item {
        const Object3D* object;
        int depth;
        const char* role;  // "" or "skeleton"
    };
    std::string out;
    std::unordered_set<const Object3D*> printed;
    std::vector<Item> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it)
        if (*it) stack.push_back({*it, 0, ""});
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        const Object3D* o = item.object;
        out.append(static_cast<std::size_t>(item.depth) * 2, ' ');
        if (*item.role) {
            out += '(';
            out += item.role;
            out += ") ";
        }
        out += o->getClassName();
        auto it = ids.find(o);
        out += " #" + (it == ids.end() ? std::string("?") : std::to_string(it->second));
        if (o->getUserID() != 0) out += " userID=" + std::to_string(o->getUserID());
        if (!printed.insert(o).second) {  // a node under two parents cannot happen; be safe anyway
            out += " (repeated)\n";
            continue;
        }
        out += summary(o, ids);
        out += '\n';
        if (const auto* n = dynamic_cast<const Node*>(o)) {
            std::vector<Node*> children;
            n->collectChildren(children);
            const bool skinned = dynamic_cast<const SkinnedMesh*>(o) != nullptr;
            for (auto c = children.rbegin(); c != children.rend(); ++c)
                if (*c) stack.push_back({*c, item.depth + 1, skinned ? "skeleton" : ""});
        }
    }
    return out;
}

std::map<std::string, int> countByClass(std::span<Object3D* const> roots) {
    std::map<std::string, int> counts;
    for (const Object3D* o : collectObjects(roots)) ++counts[o->getClassName()];
    return counts;
}

}  // namespace m3gcli
