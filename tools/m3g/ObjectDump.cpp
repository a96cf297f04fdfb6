#include "ObjectDump.h"

#include <algorithm>
#include <any>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <memory>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include <m3g/m3g.h>
#include <m3g/skin/InfluenceTable.h>
#include <m3g/skin/Skinning.h>
#include <nlohmann/json.hpp>

namespace m3gcli {

using namespace m3g;

namespace {

// ---------------------------------------------------------------------------
// The document: nlohmann's JSON with insertion-ordered objects (members are
// written in the order they are set) and single-precision numbers, so that
// every float is written in the shortest form that reads back as the same
// float. Non-finite floats are written as null by the serializer.

using Json = nlohmann::basic_json<nlohmann::ordered_map, std::vector, std::string, bool, std::int64_t,
                                  std::uint64_t, float>;

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

Json idOf(const IdMap& ids, const Object3D* o) {
    if (!o) return nullptr;
    auto it = ids.find(o);
    return it == ids.end() ? Json() : Json(it->second);
}

std::string hex32(std::uint32_t v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%08X", static_cast<unsigned>(v));
    return buf;
}
Json color(int argb) { return hex32(static_cast<std::uint32_t>(argb)); }

std::string enumName(int value, std::initializer_list<std::pair<int, const char*>> names) {
    for (const auto& [v, n] : names)
        if (v == value) return n;
    return std::to_string(value);  // not a known constant: its decimal value
}

Json floats(std::span<const float> v) {
    Json a = Json::array();
    for (float f : v) a.push_back(f);
    return a;
}
Json ints(std::span<const int> v) {
    Json a = Json::array();
    for (int i : v) a.push_back(i);
    return a;
}
Json matrix(const Transform& t) {
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

    Json ref(const Object3D* o) const { return idOf(ids, o); }

    void object3D(const Object3D* o, Json& j) const {
        j["id"] = idOf(ids, o);
        j["class"] = o->getClassName();
        j["userID"] = o->getUserID();
        const UserParameters* params = o->getUserParameters();
        const std::any& u = o->getUserObject();
        j["userObject"] = params ? Json("UserParameters") : u.has_value() ? Json("other") : Json();
        if (params) {
            Json p = Json::object();
            for (const auto& [key, bytes] : *params) p[std::to_string(key)] = hexBytes(bytes);
            j["userParameters"] = std::move(p);
        } else {
            j["userParameters"] = nullptr;
        }
        Json tracks = Json::array();
        for (int i = 0; i < o->getAnimationTrackCount(); ++i) tracks.push_back(ref(o->getAnimationTrack(i).get()));
        j["animationTracks"] = std::move(tracks);
        std::vector<Ref<Object3D>> refs(static_cast<std::size_t>(o->getReferences()));
        if (!refs.empty()) o->getReferences(refs);
        Json r = Json::array();
        for (const auto& x : refs) r.push_back(ref(x.get()));
        j["references"] = std::move(r);
    }

    void transformable(const Transformable* t, Json& j) const {
        float v[4];
        t->getTranslation(v);
        j["translation"] = floats(std::span<const float>(v, 3));
        t->getOrientation(v);
        j["orientation"] = floats(std::span<const float>(v, 4));  // angle, axis x, y, z
        t->getScale(v);
        j["scale"] = floats(std::span<const float>(v, 3));
        Transform m;
        t->getTransform(&m);
        j["transform"] = matrix(m);
        t->getCompositeTransform(&m);
        j["compositeTransform"] = matrix(m);
    }

    void node(const Node* n, Json& j) const {
        j["parent"] = ref(n->getParent().get());
        j["renderingEnabled"] = n->isRenderingEnabled();
        j["pickingEnabled"] = n->isPickingEnabled();
        j["alphaFactor"] = n->getAlphaFactor();
        j["scope"] = n->getScope();
        Json a = Json::object();
        a["zTarget"] = alignmentTargetName(n->getAlignmentTarget(Node::Z_AXIS));
        a["zReference"] = ref(n->getAlignmentReference(Node::Z_AXIS).get());
        a["yTarget"] = alignmentTargetName(n->getAlignmentTarget(Node::Y_AXIS));
        a["yReference"] = ref(n->getAlignmentReference(Node::Y_AXIS).get());
        j["alignment"] = std::move(a);
    }

    void group(const Group* g, Json& j) const {
        Json c = Json::array();
        for (int i = 0; i < g->getChildCount(); ++i) c.push_back(ref(g->getChild(i).get()));
        j["childCount"] = g->getChildCount();
        j["children"] = std::move(c);
    }

    void world(const World* w, Json& j) const {
        j["activeCamera"] = ref(w->getActiveCamera().get());
        j["background"] = ref(w->getBackground().get());
    }

    void camera(const Camera* c, Json& j) const {
        float p[4];
        const int type = c->getProjection(std::span<float>(p));
        j["projection"] = projectionName(type);
        j["projectionParams"] = type == Camera::GENERIC ? Json() : floats(p);
        Transform m;
        try {
            c->getProjection(&m);
            j["projectionMatrix"] = matrix(m);
        } catch (const ArithmeticException&) {
            j["projectionMatrix"] = nullptr;  // near == far
        }
    }

    void light(const Light* l, Json& j) const {
        j["mode"] = lightModeName(l->getMode());
        j["color"] = color(l->getColor());
        j["intensity"] = l->getIntensity();
        j["spotAngle"] = l->getSpotAngle();
        j["spotExponent"] = l->getSpotExponent();
        const float att[] = {l->getConstantAttenuation(), l->getLinearAttenuation(), l->getQuadraticAttenuation()};
        j["attenuation"] = floats(att);
    }

    void mesh(const Mesh* m, Json& j) const {
        j["vertexBuffer"] = ref(m->getVertexBuffer().get());
        j["submeshCount"] = m->getSubmeshCount();
        Json subs = Json::array();
        for (int i = 0; i < m->getSubmeshCount(); ++i) {
            Json s = Json::object();
            s["indexBuffer"] = ref(m->getIndexBuffer(i).get());
            s["appearance"] = ref(m->getAppearance(i).get());
            subs.push_back(std::move(s));
        }
        j["submeshes"] = std::move(subs);
    }

    void morphingMesh(const MorphingMesh* m, Json& j) const {
        Json t = Json::array();
        for (int i = 0; i < m->getMorphTargetCount(); ++i) t.push_back(ref(m->getMorphTarget(i).get()));
        j["morphTargets"] = std::move(t);
        std::vector<float> w(static_cast<std::size_t>(m->getMorphTargetCount()));
        if (!w.empty()) m->getWeights(w);
        j["weights"] = floats(w);
    }

    void skinnedMesh(const SkinnedMesh* m, Json& j) const {
        j["skeleton"] = ref(m->getSkeleton().get());
        Json bones = Json::array();
        for (int i = 0; i < m->boneCount(); ++i) {
            Node* b = m->bone(i);
            Json e = Json::object();
            e["bone"] = ref(b);
            if (b) {
                e["vertexCount"] = m->getBoneVertices(b);
                Transform t;
                m->getBoneTransform(b, &t);
                e["atRestTransform"] = matrix(t);
            }
            bones.push_back(std::move(e));
        }
        j["bones"] = std::move(bones);
        j["influenceLayout"] = influenceLayout(m);
    }

    /// How the CPU skinning kernels see the mesh's vertices (docs/skinning.md):
    /// how many have 0..N influences; how many of those with at least one
    /// lie in shared-influence runs of the mesh's own order (the exporter's
    /// layout); and how MeshDeformer skins them, all in the compact space
    /// (sorted by influence set): in runs sharing every slot (one blend per
    /// run), in bone runs sharing their bones, or one by one.
    static Json influenceLayout(const SkinnedMesh* m) {
        const skin::InfluenceTable& table = m->influenceTable();
        const VertexBuffer* vb = m->getVertexBuffer().get();
        const auto vertices = static_cast<std::size_t>(vb ? vb->getVertexCount() : 0);
        skin::InfluencePartition meshOrder, partition;
        meshOrder.build(table.bones(), table.weights(), table.maxInfluences(), vertices);
        partition.buildForKernels(table, vertices);  // as MeshDeformer, on this CPU
        std::vector<int> byCount;
        int runs = 0, runVertices = 0, loose = 0, longest = 0;
        int compactRuns = 0, compactRunVertices = 0, compactLoose = 0, boneRuns = 0, boneRunVertices = 0;
        for (int c = 0; c <= partition.maxInfluences(); ++c) {
            byCount.push_back(static_cast<int>(partition.group(c).size()));
            if (c == 0) continue;
            loose += static_cast<int>(meshOrder.loose(c).size());
            for (const skin::InfluenceRun& r : meshOrder.runs(c)) {
                ++runs;
                runVertices += static_cast<int>(r.vertexCount);
                longest = std::max(longest, static_cast<int>(r.vertexCount));
            }
            for (const skin::InfluenceRun& r : partition.compactRuns(c)) {
                ++compactRuns;
                compactRunVertices += static_cast<int>(r.vertexCount);
            }
            for (const skin::InfluenceRun& r : partition.compactBoneRuns(c)) {
                ++boneRuns;
                boneRunVertices += static_cast<int>(r.vertexCount);
            }
            compactLoose += static_cast<int>(partition.compactLoose(c).size());
        }
        Json j = Json::object();
        j["verticesByInfluenceCount"] = ints(byCount);
        j["runs"] = runs;
        j["runVertices"] = runVertices;
        j["longestRun"] = longest;
        // Vertices in no run of the mesh's order. The kernels take every
        // vertex with influences in the compact space: as runs sharing
        // every slot, as bone runs sharing their bones (each vertex with
        // its own weights), or one by one (compactLooseVertices).
        j["looseVertices"] = loose;
        j["compactRuns"] = compactRuns;
        j["compactRunVertices"] = compactRunVertices;
        j["compactBoneRuns"] = boneRuns;
        j["compactBoneRunVertices"] = boneRunVertices;
        j["compactLooseVertices"] = compactLoose;
        // Every vertex on one bone: the renderer draws the mesh through that
        // bone's transform and skins nothing per frame (docs/skinning.md,
        // "Rigid binding").
        j["rigidBinding"] = table.rigidBone(vertices) >= 0;
        // The compact split depends on the kernels this CPU runs (short
        // runs join their bone set's bone run where there is a bone-run
        // kernel, InfluencePartition::runBlock): say which.
        j["kernels"] = skin::isaName(skin::resolveIsa(skin::Isa::Auto));
        j["runBlock"] = static_cast<int>(skin::InfluencePartition::runBlock(skin::Isa::Auto));
        return j;
    }

    void sprite(const Sprite3D* s, Json& j) const {
        j["scaled"] = s->isScaled();
        j["image"] = ref(s->getImage().get());
        j["appearance"] = ref(s->getAppearance().get());
        const int crop[] = {s->getCropX(), s->getCropY(), s->getCropWidth(), s->getCropHeight()};
        j["crop"] = ints(crop);
    }

    void appearance(const Appearance* a, Json& j) const {
        j["layer"] = a->getLayer();
        j["compositingMode"] = ref(a->getCompositingMode().get());
        j["fog"] = ref(a->getFog().get());
        j["polygonMode"] = ref(a->getPolygonMode().get());
        j["material"] = ref(a->getMaterial().get());
        Json t = Json::array();
        for (int i = 0; i < getLimits().numTextureUnits; ++i) t.push_back(ref(a->getTexture(i).get()));
        j["textures"] = std::move(t);
    }

    void compositingMode(const CompositingMode* c, Json& j) const {
        j["blending"] = enumName(c->getBlending(), {{CompositingMode::ALPHA, "ALPHA"},
                                                    {CompositingMode::ALPHA_ADD, "ALPHA_ADD"},
                                                    {CompositingMode::MODULATE, "MODULATE"},
                                                    {CompositingMode::MODULATE_X2, "MODULATE_X2"},
                                                    {CompositingMode::REPLACE, "REPLACE"}});
        j["alphaThreshold"] = c->getAlphaThreshold();
        j["depthTestEnabled"] = c->isDepthTestEnabled();
        j["depthWriteEnabled"] = c->isDepthWriteEnabled();
        j["colorWriteEnabled"] = c->isColorWriteEnabled();
        j["alphaWriteEnabled"] = c->isAlphaWriteEnabled();
        j["depthOffsetFactor"] = c->getDepthOffsetFactor();
        j["depthOffsetUnits"] = c->getDepthOffsetUnits();
    }

    void polygonMode(const PolygonMode* p, Json& j) const {
        j["culling"] = enumName(p->getCulling(), {{PolygonMode::CULL_BACK, "CULL_BACK"},
                                                  {PolygonMode::CULL_FRONT, "CULL_FRONT"},
                                                  {PolygonMode::CULL_NONE, "CULL_NONE"}});
        j["shading"] = enumName(p->getShading(), {{PolygonMode::SHADE_FLAT, "SHADE_FLAT"},
                                                  {PolygonMode::SHADE_SMOOTH, "SHADE_SMOOTH"}});
        j["winding"] = enumName(p->getWinding(), {{PolygonMode::WINDING_CCW, "WINDING_CCW"},
                                                  {PolygonMode::WINDING_CW, "WINDING_CW"}});
        j["twoSidedLightingEnabled"] = p->isTwoSidedLightingEnabled();
        j["localCameraLightingEnabled"] = p->isLocalCameraLightingEnabled();
        j["perspectiveCorrectionEnabled"] = p->isPerspectiveCorrectionEnabled();
    }

    void material(const Material* m, Json& j) const {
        j["ambientColor"] = color(m->getColor(Material::AMBIENT));
        j["diffuseColor"] = color(m->getColor(Material::DIFFUSE));
        j["emissiveColor"] = color(m->getColor(Material::EMISSIVE));
        j["specularColor"] = color(m->getColor(Material::SPECULAR));
        j["shininess"] = m->getShininess();
        j["vertexColorTrackingEnabled"] = m->isVertexColorTrackingEnabled();
    }

    void fog(const Fog* f, Json& j) const {
        j["mode"] = enumName(f->getMode(), {{Fog::EXPONENTIAL, "EXPONENTIAL"}, {Fog::LINEAR, "LINEAR"}});
        j["color"] = color(f->getColor());
        j["density"] = f->getDensity();
        j["nearDistance"] = f->getNearDistance();
        j["farDistance"] = f->getFarDistance();
    }

    void background(const Background* b, Json& j) const {
        j["color"] = color(b->getColor());
        j["image"] = ref(b->getImage().get());
        const std::initializer_list<std::pair<int, const char*>> modes = {{Background::BORDER, "BORDER"},
                                                                         {Background::REPEAT, "REPEAT"}};
        j["imageModeX"] = enumName(b->getImageModeX(), modes);
        j["imageModeY"] = enumName(b->getImageModeY(), modes);
        const int crop[] = {b->getCropX(), b->getCropY(), b->getCropWidth(), b->getCropHeight()};
        j["crop"] = ints(crop);
        j["colorClearEnabled"] = b->isColorClearEnabled();
        j["depthClearEnabled"] = b->isDepthClearEnabled();
    }

    void image(const Image2D* im, Json& j) const {
        j["format"] = imageFormatName(im->getFormat());
        j["width"] = im->getWidth();
        j["height"] = im->getHeight();
        j["mutable"] = im->isMutable();
        j["palettized"] = im->isPalettized();
        j["pixelBytes"] = static_cast<long long>(im->pixels().size());
        j["pixelChecksum"] = hex32(checksum(im->pixels()));  // FNV-1a of the resolved pixels
    }

    void texture(const Texture2D* t, Json& j) const {
        const std::initializer_list<std::pair<int, const char*>> filters = {
            {Texture2D::FILTER_BASE_LEVEL, "FILTER_BASE_LEVEL"},
            {Texture2D::FILTER_LINEAR, "FILTER_LINEAR"},
            {Texture2D::FILTER_NEAREST, "FILTER_NEAREST"}};
        const std::initializer_list<std::pair<int, const char*>> wraps = {{Texture2D::WRAP_CLAMP, "WRAP_CLAMP"},
                                                                         {Texture2D::WRAP_REPEAT, "WRAP_REPEAT"}};
        j["image"] = ref(t->getImage().get());
        j["levelFilter"] = enumName(t->getLevelFilter(), filters);
        j["imageFilter"] = enumName(t->getImageFilter(), filters);
        j["wrappingS"] = enumName(t->getWrappingS(), wraps);
        j["wrappingT"] = enumName(t->getWrappingT(), wraps);
        j["blending"] = enumName(t->getBlending(), {{Texture2D::FUNC_ADD, "FUNC_ADD"},
                                                    {Texture2D::FUNC_BLEND, "FUNC_BLEND"},
                                                    {Texture2D::FUNC_DECAL, "FUNC_DECAL"},
                                                    {Texture2D::FUNC_MODULATE, "FUNC_MODULATE"},
                                                    {Texture2D::FUNC_REPLACE, "FUNC_REPLACE"}});
        j["blendColor"] = color(t->getBlendColor());
    }

    void vertexArray(const VertexArray* va, Json& j) const {
        const int n = va->getVertexCount();
        const int c = va->getComponentCount();
        const int shown = std::clamp(opt.maxVertices, 0, n);
        j["vertexCount"] = n;
        j["componentCount"] = c;
        j["componentType"] = va->getComponentType();  // bytes per component
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
        Json rows = Json::array();
        for (int v = 0; v < shown; ++v)
            rows.push_back(ints(std::span<const int>(values).subspan(static_cast<std::size_t>(v) * c, static_cast<std::size_t>(c))));
        j["values"] = std::move(rows);
        j["truncated"] = shown < n;
    }

    void vertexBuffer(const VertexBuffer* vb, Json& j) const {
        j["vertexCount"] = vb->getVertexCount();
        float sb[4] = {0, 0, 0, 0};
        if (Ref<VertexArray> p = vb->getPositions(std::span<float>(sb))) {
            Json e = Json::object();
            e["array"] = ref(p.get());
            e["scale"] = sb[0];
            e["bias"] = floats(std::span<const float>(sb + 1, 3));
            j["positions"] = std::move(e);
        } else {
            j["positions"] = nullptr;
        }
        j["normals"] = ref(vb->getNormals().get());
        j["colors"] = ref(vb->getColors().get());
        Json tcs = Json::array();
        for (int i = 0; i < getLimits().numTextureUnits; ++i) {
            Ref<VertexArray> t = vb->getTexCoords(i);
            if (!t) {
                tcs.push_back(nullptr);
                continue;
            }
            const int nc = t->getComponentCount();
            std::vector<float> v(static_cast<std::size_t>(nc) + 1);
            vb->getTexCoords(i, v);
            Json e = Json::object();
            e["array"] = ref(t.get());
            e["scale"] = v[0];
            e["bias"] = floats(std::span<const float>(v).subspan(1));
            tcs.push_back(std::move(e));
        }
        j["texCoords"] = std::move(tcs);
        j["defaultColor"] = color(vb->getDefaultColor());
    }

    void indexBuffer(const IndexBuffer* ib, Json& j) const {
        const int n = ib->getIndexCount();
        const int shown = std::clamp(opt.maxIndices, 0, n);
        std::vector<int> all(static_cast<std::size_t>(n));
        if (n > 0) ib->getIndices(all);
        j["indexCount"] = n;
        j["indices"] = ints(std::span<const int>(all).first(static_cast<std::size_t>(shown)));
        j["truncated"] = shown < n;
    }

    void strips(const TriangleStripArray* t, Json& j) const {
        const auto lengths = t->stripLengths();
        const std::size_t shown = std::min(lengths.size(), static_cast<std::size_t>(std::max(opt.maxIndices, 0)));
        j["stripCount"] = static_cast<long long>(lengths.size());
        j["stripLengths"] = ints(lengths.first(shown));
        j["stripLengthsTruncated"] = shown < lengths.size();
    }

    void keyframes(const KeyframeSequence* k, Json& j) const {
        j["keyframeCount"] = k->getKeyframeCount();
        j["componentCount"] = k->getComponentCount();
        j["interpolation"] = enumName(k->getInterpolationType(), {{KeyframeSequence::LINEAR, "LINEAR"},
                                                                  {KeyframeSequence::SLERP, "SLERP"},
                                                                  {KeyframeSequence::SPLINE, "SPLINE"},
                                                                  {KeyframeSequence::SQUAD, "SQUAD"},
                                                                  {KeyframeSequence::STEP, "STEP"}});
        j["duration"] = k->getDuration();
        j["repeatMode"] = enumName(k->getRepeatMode(), {{KeyframeSequence::CONSTANT, "CONSTANT"},
                                                        {KeyframeSequence::LOOP, "LOOP"}});
        const int vr[] = {k->getValidRangeFirst(), k->getValidRangeLast()};
        j["validRange"] = ints(vr);
        const int n = k->getKeyframeCount();
        const int shown = std::clamp(opt.maxKeyframes, 0, n);
        Json times = Json::array();
        Json values = Json::array();
        std::vector<float> v(static_cast<std::size_t>(k->getComponentCount()));
        for (int i = 0; i < shown; ++i) {
            times.push_back(k->getKeyframe(i, v));
            values.push_back(floats(v));
        }
        j["keyframeTimes"] = std::move(times);
        j["keyframeValues"] = std::move(values);
        j["truncated"] = shown < n;
    }

    void track(const AnimationTrack* t, Json& j) const {
        j["targetProperty"] = propertyName(t->getTargetProperty());
        j["keyframeSequence"] = ref(t->getKeyframeSequence().get());
        j["controller"] = ref(t->getController().get());
    }

    void controller(const AnimationController* c, Json& j) const {
        const int interval[] = {c->getActiveIntervalStart(), c->getActiveIntervalEnd()};
        j["activeInterval"] = ints(interval);
        j["speed"] = c->getSpeed();
        j["weight"] = c->getWeight();
        j["refWorldTime"] = c->getRefWorldTime();
        j["refSequenceTime"] = c->getPosition(c->getRefWorldTime());
        if (opt.worldTime) {
            j["worldTime"] = *opt.worldTime;
            j["position"] = c->getPosition(*opt.worldTime);
            j["active"] = c->isActive(*opt.worldTime);
        }
    }

    Json dump(const Object3D* o) const {
        Json j = Json::object();
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
    if (auto* m = dynamic_cast<const SkinnedMesh*>(o)) {
        add("bones=" + std::to_string(m->boneCount()));
        // Every vertex on one bone: drawn through it, not skinned (docs/skinning.md).
        const VertexBuffer* vb = m->getVertexBuffer().get();
        if (vb && m->influenceTable().rigidBone(static_cast<std::size_t>(vb->getVertexCount())) >= 0) add("rigid");
    }
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

ObjectNumbering::ObjectNumbering(std::span<Object3D* const> roots) {
    const std::vector<Object3D*> objects = collectObjects(roots);
    for (std::size_t i = 0; i < objects.size(); ++i) ids_.emplace(objects[i], static_cast<int>(i));
}

int ObjectNumbering::id(const Object3D* object) const {
    const auto it = ids_.find(object);
    return it == ids_.end() ? -1 : it->second;
}

std::string ObjectNumbering::label(const Object3D& object) const {
    const int n = id(&object);
    return n < 0 ? std::string(object.getClassName()) : std::string(object.getClassName()) + " #" + std::to_string(n);
}

std::string dumpJson(std::span<Object3D* const> roots, const DumpOptions& options) {
    const std::vector<Object3D*> objects = collectObjects(roots);
    IdMap ids = makeIds(objects);
    if (!options.numberingRoots.empty()) {
        // The file's numbering; what lies outside it follows its last id.
        IdMap numbered = makeIds(collectObjects(options.numberingRoots));
        int next = static_cast<int>(numbered.size());
        for (Object3D* o : objects)
            if (!numbered.count(o)) numbered.emplace(o, next++);
        ids = std::move(numbered);
    }
    const Dumper dumper{ids, options};

    Json doc = Json::object();
    if (const m3g::LoadResult* load = options.load) {
        const bool m3gFile = load->versionMajor || load->versionMinor || load->totalFileSize;
        Json file = Json::object();
        file["format"] = m3gFile ? "m3g" : "image";
        if (m3gFile) {
            file["version"] = std::to_string(load->versionMajor) + "." + std::to_string(load->versionMinor);
            file["authoringField"] = load->authoringField;
            file["totalFileSize"] = load->totalFileSize;
            file["approximateContentSize"] = load->approximateContentSize;
            file["hasExternalReferences"] = load->hasExternalReferences;
        }
        doc["file"] = std::move(file);
        Json refs = Json::array();
        for (const m3g::ExternalReference& e : load->externalReferences)
            refs.push_back({{"referencedBy", e.referencedBy}, {"uri", e.uri}, {"path", e.path}, {"loaded", e.loaded}});
        doc["externalReferences"] = std::move(refs);
        Json warnings = Json::array();
        for (const std::string& w : load->warnings) warnings.push_back(w);
        doc["warnings"] = std::move(warnings);
    }
    doc["objectCount"] = static_cast<int>(objects.size());
    Json rootIds = Json::array();
    for (Object3D* r : roots)
        if (r) rootIds.push_back(idOf(ids, r));
    doc["roots"] = std::move(rootIds);
    Json list = Json::array();
    for (const Object3D* o : objects) list.push_back(dumper.dump(o));
    doc["objects"] = std::move(list);

    // Strings are ASCII here (class and constant names, hex); replace rather
    // than throw should a non-UTF-8 byte ever appear.
    std::string out = doc.dump(2, ' ', false, Json::error_handler_t::replace);
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
