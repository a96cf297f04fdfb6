#include "GltfExport.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include <m3g/m3g.h>

#include "GltfAnimation.h"
#include "GltfGeometry.h"
#include "GltfMaterial.h"
#include "GltfNotes.h"
#include "GltfTransform.h"

namespace m3gcli::gltf {

namespace {

using m3g::AnimationTrack;

std::string propertyName(int property) {
    static const char* const kNames[] = {"ALPHA",         "AMBIENT_COLOR",  "COLOR",        "CROP",
                                         "DENSITY",       "DIFFUSE_COLOR",  "EMISSIVE_COLOR", "FAR_DISTANCE",
                                         "FIELD_OF_VIEW", "INTENSITY",      "MORPH_WEIGHTS", "NEAR_DISTANCE",
                                         "ORIENTATION",   "PICKABILITY",    "SCALE",        "SHININESS",
                                         "SPECULAR_COLOR", "SPOT_ANGLE",    "SPOT_EXPONENT", "TRANSLATION",
                                         "VISIBILITY"};
    const int i = property - AnimationTrack::ALPHA;
    return i >= 0 && i < 21 ? kNames[i] : std::to_string(property);
}

std::string nodeName(const m3g::Object3D& o) {
    std::string name = o.getClassName();
    if (o.getUserID() != 0) name += " " + std::to_string(o.getUserID());
    return name;
}

/// Node names made unique: the second "Group" becomes "Group #2", and so on.
/// glTF allows repeated names, but importers that key nodes by name refuse
/// them (assimp 5.2 rejects a file with forty "Group"s).
void makeNamesUnique(std::vector<Json>& nodes) {
    std::unordered_map<std::string, int> seen;
    std::unordered_set<std::string> taken;
    for (const Json& n : nodes)
        if (n.contains("name")) taken.insert(n["name"].get<std::string>());
    for (Json& n : nodes) {
        if (!n.contains("name")) continue;
        const std::string name = n["name"].get<std::string>();
        int& count = seen[name];
        if (++count == 1) continue;
        std::string unique;
        do unique = name + " #" + std::to_string(count++);
        while (taken.count(unique));  // "Group #2" may be a name of its own
        --count;
        taken.insert(unique);
        n["name"] = unique;
    }
}

Json objectExtras(const m3g::Object3D& o) { return {{"m3gClass", o.getClassName()}, {"m3gUserID", o.getUserID()}}; }

/// Column-major floats of a row-major M3G transform (glTF matrices, §3.5.2).
void appendColumnMajor(const m3g::Transform& m, std::vector<float>& out) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) out.push_back(m.at(r, c));
}

bool isTrsProperty(int p) {
    return p == AnimationTrack::TRANSLATION || p == AnimationTrack::ORIENTATION || p == AnimationTrack::SCALE;
}

bool hasTrsTrack(const m3g::Object3D& o) {
    for (int i = 0; i < o.getAnimationTrackCount(); ++i)
        if (isTrsProperty(o.getAnimationTrack(i)->getTargetProperty())) return true;
    return false;
}

/// Every object reachable from `roots` through getReferences, each once.
std::vector<m3g::Object3D*> reachable(std::span<m3g::Object3D* const> roots) {
    std::vector<m3g::Object3D*> out;
    std::unordered_set<const m3g::Object3D*> seen;
    std::vector<m3g::Object3D*> stack(roots.rbegin(), roots.rend());
    while (!stack.empty()) {
        m3g::Object3D* o = stack.back();
        stack.pop_back();
        if (!o || !seen.insert(o).second) continue;
        out.push_back(o);
        std::vector<m3g::Ref<m3g::Object3D>> refs(static_cast<std::size_t>(o->getReferences()));
        o->getReferences(refs);
        for (auto it = refs.rbegin(); it != refs.rend(); ++it) stack.push_back(it->get());
    }
    return out;
}

/// The glTF nodes made for one M3G node.
struct NodeSlots {
    int outer = -1;    ///< carries the M3G T R S (the animation target)
    int content = -1;  ///< carries M, the mesh/camera/light and the children
};

/// The glTF rotation (x, y, z, w) taking the unit axis `up` to +Y: 90
/// degrees about up x Y, or 180 about X for -Y.
Json uprightRotation(const Axis& up) {
    if (up[1] < 0.0f) return Json::array({1.0, 0.0, 0.0, 0.0});
    const double s = std::sqrt(0.5);
    // up x (0, 1, 0) = (-up.z, 0, up.x)
    return Json::array({-up[2] * s, 0.0, up[0] * s, s});
}

struct MeshJob {
    m3g::Mesh* mesh;
    int node;  ///< content node
    float alphaFactor;
};

class Exporter {
public:
    explicit Exporter(const ExportOptions& options) : options_(options) {}
    ExportResult run(std::span<m3g::Object3D* const> roots);

private:
    int newNode(Json node) {
        nodes_.push_back(std::move(node));
        return static_cast<int>(nodes_.size()) - 1;
    }
    void addChild(int parent, int child) { nodes_[static_cast<std::size_t>(parent)]["children"].push_back(child); }
    int visit(m3g::Node& node, bool hidden, float alpha);
    const ExportOptions options_;
    void setTrs(Json& node, const Trs& trs);
    void attachCamera(m3g::Camera& camera, int node);
    void attachLight(m3g::Light& light, int node);
    void exportMesh(const MeshJob& job);
    int skin(m3g::SkinnedMesh& mesh, int meshNode, bool& restJoint);
    void exportAnimations(std::span<m3g::Object3D* const> all);

    int positionAccessor(const m3g::VertexBuffer& vb);
    int normalAccessor(const m3g::VertexBuffer& vb);

    ExportResult result_;
    Document& doc_ = result_.document;
    Notes notes_;
    MaterialWriter materials_{doc_, notes_};
    std::vector<Json> nodes_;
    std::unordered_map<const m3g::Node*, NodeSlots> slots_;
    std::vector<MeshJob> meshes_;
    std::unordered_map<const m3g::Mesh*, int> meshNodes_;  // mesh -> content node with a glTF mesh
    std::unordered_map<const m3g::Mesh*, int> morphTargets_;
    std::map<std::string, int> accessors_;  // cache key -> accessor
};

void Exporter::setTrs(Json& node, const Trs& trs) {
    if (trs.t != std::array<float, 3>{0, 0, 0}) node["translation"] = trs.t;
    if (trs.r != std::array<float, 4>{0, 0, 0, 1}) node["rotation"] = trs.r;
    if (trs.s != std::array<float, 3>{1, 1, 1}) node["scale"] = trs.s;
}

int Exporter::visit(m3g::Node& node, bool hidden, float alpha) {
    if (slots_.count(&node)) return slots_[&node].outer;  // a tree, but stay safe
    alpha *= node.getAlphaFactor();
    hidden = hidden || !node.isRenderingEnabled();

    Trs trs;
    node.getTranslation(trs.t);
    trs.r = normalizedQuaternion(node.orientationQuat());
    node.getScale(trs.s);
    m3g::Transform m;
    node.getTransform(&m);

    Json outer = {{"name", nodeName(node)}, {"extras", objectExtras(node)}};
    NodeSlots slots;
    if (isIdentity(m)) {
        setTrs(outer, trs);
        slots.outer = slots.content = newNode(std::move(outer));
    } else {
        const MatrixNodes split = matrixNodes(m);
        if (split.projectiveDropped)
            notes_.add("a node matrix with a projective bottom row: its affine part is exported");
        const bool plainTrs = trs.t == std::array<float, 3>{0, 0, 0} && trs.r == std::array<float, 4>{0, 0, 0, 1} &&
                              trs.s == std::array<float, 3>{1, 1, 1};
        if (split.asMatrix && plainTrs && !hasTrsTrack(node)) {
            outer["matrix"] = split.columnMajor;
            slots.outer = slots.content = newNode(std::move(outer));
        } else {
            // T R S on the outer node (what animation targets), M below it.
            setTrs(outer, trs);
            slots.outer = slots.content = newNode(std::move(outer));
            if (split.asMatrix) {
                const int child = newNode({{"name", nodeName(node) + " matrix"}, {"matrix", split.columnMajor}});
                addChild(slots.content, child);
                slots.content = child;
            } else {
                notes_.add("a node matrix with shear: exported as a chain of three TRS nodes (exact)");
                for (std::size_t i = 0; i < split.chain.size(); ++i) {
                    Json part = {{"name", nodeName(node) + " matrix " + std::to_string(i)}};
                    setTrs(part, split.chain[i]);
                    const int child = newNode(std::move(part));
                    addChild(slots.content, child);
                    slots.content = child;
                }
            }
        }
    }
    slots_[&node] = slots;
    if (node.getAlignmentTarget(m3g::Node::Z_AXIS) != m3g::Node::NONE ||
        node.getAlignmentTarget(m3g::Node::Y_AXIS) != m3g::Node::NONE)
        notes_.add("node alignment (setAlignment) is computed at render time in M3G: not exported");

    if (auto* mesh = dynamic_cast<m3g::Mesh*>(&node)) {
        if (hidden)
            notes_.add("a Mesh with rendering disabled (itself or an ancestor): exported without geometry");
        else
            meshes_.push_back({mesh, slots.content, alpha});
    } else if (auto* camera = dynamic_cast<m3g::Camera*>(&node)) {
        attachCamera(*camera, slots.content);
    } else if (auto* light = dynamic_cast<m3g::Light*>(&node)) {
        attachLight(*light, slots.content);
    } else if (dynamic_cast<m3g::Sprite3D*>(&node)) {
        notes_.add("Sprite3D has no glTF equivalent: exported as an empty node");
    }

    std::vector<m3g::Node*> children;
    node.collectChildren(children);
    for (m3g::Node* child : children)
        if (child) addChild(slots.content, visit(*child, hidden, alpha));
    return slots.outer;
}

void Exporter::attachCamera(m3g::Camera& camera, int node) {
    float p[4];
    m3g::Transform proj;
    int type = m3g::Camera::GENERIC;
    try {
        type = camera.getProjection(std::span<float>(p, 4));
        camera.getProjection(&proj);
    } catch (const m3g::Exception&) {
        notes_.add("a Camera with near == far: not exported");
        return;
    }
    Json cam = {{"name", nodeName(camera)}};
    double yfov = 0, aspect = 0, znear = 0, zfar = 0, xmag = 0, ymag = 0;
    bool perspective = true;
    if (type == m3g::Camera::PERSPECTIVE) {
        yfov = p[0] * std::numbers::pi / 180.0;
        aspect = p[1];
        znear = p[2];
        zfar = p[3];
    } else if (type == m3g::Camera::PARALLEL) {
        perspective = false;
        ymag = p[0] / 2.0;
        xmag = ymag * p[1];
        znear = p[2];
        zfar = p[3];
    } else {
        // GENERIC: read the OpenGL-style matrix back (symmetric frusta only).
        const auto& r = proj.rows();
        bool decoded = true;
        if (r[12] == 0 && r[13] == 0 && r[14] == -1 && r[15] == 0 && r[0] != 0 && r[5] != 0) {
            yfov = 2.0 * std::atan(1.0 / r[5]);
            aspect = r[5] / r[0];
            znear = r[11] / (r[10] - 1.0);
            zfar = r[11] / (r[10] + 1.0);
        } else if (r[12] == 0 && r[13] == 0 && r[14] == 0 && r[15] == 1 && r[0] != 0 && r[5] != 0 && r[10] != 0) {
            perspective = false;
            xmag = 1.0 / r[0];
            ymag = 1.0 / r[5];
            znear = (r[11] + 1.0) / r[10];
            zfar = (r[11] - 1.0) / r[10];
        } else {
            decoded = false;
            yfov = std::numbers::pi / 3.0;
            aspect = 1.0;
            znear = 0.1;
            zfar = 1000.0;
            notes_.add("a GENERIC camera matrix that is neither a perspective nor an orthographic projection: "
                       "exported as a 60 degree perspective camera");
        }
        if (decoded)
            notes_.add("a GENERIC camera: its matrix read back as a symmetric perspective or orthographic camera");
        if (r[2] != 0 || r[6] != 0 || r[3] != 0 || r[7] != 0)
            notes_.add("an off-centre GENERIC camera: glTF cameras are symmetric, the offset is dropped");
    }
    // glTF limits (§3.10): 0 < znear < zfar (perspective), 0 <= znear < zfar (orthographic).
    if (!(yfov > 0 && yfov < std::numbers::pi) && perspective) yfov = std::numbers::pi / 3.0;
    if (!std::isfinite(znear) || !std::isfinite(zfar) || (perspective ? znear <= 0 : znear < 0) || zfar <= znear) {
        notes_.add("a Camera with near/far outside glTF's range: clamped");
        if (!std::isfinite(znear) || (perspective ? znear <= 0 : znear < 0)) znear = perspective ? 0.01 : 0.0;
        if (!std::isfinite(zfar) || zfar <= znear) zfar = znear + 1000.0;
    }
    if (perspective) {
        Json pj = {{"yfov", yfov}, {"znear", znear}, {"zfar", zfar}};
        if (aspect > 0 && std::isfinite(aspect)) pj["aspectRatio"] = aspect;
        cam["type"] = "perspective";
        cam["perspective"] = std::move(pj);
    } else {
        if (!(std::abs(xmag) > 0) || !std::isfinite(xmag)) xmag = 1;
        if (!(std::abs(ymag) > 0) || !std::isfinite(ymag)) ymag = 1;
        cam["type"] = "orthographic";
        cam["orthographic"] = {{"xmag", xmag}, {"ymag", ymag}, {"znear", znear}, {"zfar", zfar}};
    }
    nodes_[static_cast<std::size_t>(node)]["camera"] = doc_.add("cameras", std::move(cam));
}

void Exporter::attachLight(m3g::Light& light, int node) {
    if (light.getMode() == m3g::Light::AMBIENT) {
        notes_.add("AMBIENT Light has no glTF equivalent (KHR_lights_punctual has none): not exported");
        return;
    }
    const auto c = static_cast<std::uint32_t>(light.getColor());
    Json l = {{"name", nodeName(light)},
              {"color", {((c >> 16) & 0xFF) / 255.0, ((c >> 8) & 0xFF) / 255.0, (c & 0xFF) / 255.0}}};
    float intensity = light.getIntensity();
    if (!(intensity >= 0.0f)) {
        notes_.add("a Light with negative intensity: exported with intensity 0");
        intensity = 0.0f;
    }
    l["intensity"] = intensity;
    switch (light.getMode()) {
    case m3g::Light::DIRECTIONAL: l["type"] = "directional"; break;
    case m3g::Light::OMNI: l["type"] = "point"; break;
    default: {
        l["type"] = "spot";
        // Outer cone = the M3G cut-off; the exponent's falloff approximated by
        // an inner cone where cos^e reaches one half.
        const double outer = std::max(light.getSpotAngle() * std::numbers::pi / 180.0, 1e-4);
        double inner = 0.0;
        if (light.getSpotExponent() > 0.0f)
            inner = std::min(std::acos(std::pow(0.5, 1.0 / light.getSpotExponent())), outer * 0.999);
        else
            inner = outer * 0.999;
        l["spot"] = {{"innerConeAngle", inner}, {"outerConeAngle", outer}};
    }
    }
    if (light.getMode() != m3g::Light::DIRECTIONAL &&
        (light.getConstantAttenuation() != 0.0f || light.getLinearAttenuation() != 0.0f ||
         light.getQuadraticAttenuation() != 1.0f))
        notes_.add("Light attenuation other than (0, 0, 1): glTF point and spot lights fall off with the inverse square");
    doc_.useExtension("KHR_lights_punctual");
    Json& ext = doc_.json()["extensions"]["KHR_lights_punctual"]["lights"];
    if (!ext.is_array()) ext = Json::array();
    ext.push_back(std::move(l));
    nodes_[static_cast<std::size_t>(node)]["extensions"]["KHR_lights_punctual"] = {
        {"light", static_cast<int>(ext.size()) - 1}};
}

int Exporter::positionAccessor(const m3g::VertexBuffer& vb) {
    const std::string key = "P" + std::to_string(vb.getObjectId());
    if (auto it = accessors_.find(key); it != accessors_.end()) return it->second;
    const auto p = positions(vb);
    for (float v : p)
        if (!std::isfinite(v)) throw std::runtime_error("VertexBuffer positions are not finite after scale and bias");
    return accessors_[key] = doc_.addFloatAccessor(p, "VEC3", ViewTarget::ArrayBuffer, true);
}

int Exporter::normalAccessor(const m3g::VertexBuffer& vb) {
    const std::string key = "N" + std::to_string(vb.getObjectId());
    if (auto it = accessors_.find(key); it != accessors_.end()) return it->second;
    int degenerate = 0;
    const auto n = normals(*vb.normals(), degenerate);
    if (degenerate) notes_.add("zero-length normals replaced by (0, 0, 1) (glTF normals are unit vectors)");
    return accessors_[key] = doc_.addFloatAccessor(n, "VEC3", ViewTarget::ArrayBuffer, false);
}

int Exporter::skin(m3g::SkinnedMesh& mesh, int meshNode, bool& restJoint) {
    const int vertexCount = mesh.vertexBuffer()->getVertexCount();
    const SkinAttributes attrs = skinAttributes(mesh, vertexCount, mesh.boneCount());
    restJoint = attrs.usesRestJoint;
    Json joints = Json::array();
    std::vector<float> ibm;
    for (int b = 0; b < mesh.boneCount(); ++b) {
        const auto it = slots_.find(mesh.bone(b));
        if (it == slots_.end()) throw std::runtime_error("SkinnedMesh bone outside the exported node tree");
        joints.push_back(it->second.content);
        appendColumnMajor(mesh.atRestTransform(b), ibm);
    }
    if (attrs.usesRestJoint) {
        // Vertices without bones stay in mesh space: a joint at the mesh node.
        const int rest = newNode({{"name", nodeName(mesh) + " unskinned vertices"}});
        addChild(meshNode, rest);
        joints.push_back(rest);
        appendColumnMajor(m3g::Transform(), ibm);
    }
    Json skinJson = {{"name", nodeName(mesh)}, {"joints", joints}};
    skinJson["inverseBindMatrices"] = doc_.addFloatAccessor(ibm, "MAT4", ViewTarget::None, false);
    const int skinIndex = doc_.add("skins", std::move(skinJson));

    // JOINTS_n / WEIGHTS_n: bytes when the joint indices fit.
    const std::size_t stride = static_cast<std::size_t>(attrs.sets) * 4;
    const bool bytes = joints.size() <= 256;
    for (int set = 0; set < attrs.sets; ++set) {
        std::vector<std::uint16_t> j;
        std::vector<float> w;
        for (int v = 0; v < vertexCount; ++v)
            for (int k = 0; k < 4; ++k) {
                const std::size_t i = static_cast<std::size_t>(v) * stride + static_cast<std::size_t>(set) * 4 + k;
                j.push_back(attrs.joints[i]);
                w.push_back(attrs.weights[i]);
            }
        const std::string suffix = std::to_string(set);
        if (bytes) {
            const std::vector<std::uint8_t> j8(j.begin(), j.end());
            accessors_["J" + suffix + "/" + std::to_string(mesh.getObjectId())] = doc_.addByteAccessor(j8, "VEC4", false);
        } else {
            accessors_["J" + suffix + "/" + std::to_string(mesh.getObjectId())] = doc_.addShortAccessor(j, "VEC4", false);
        }
        accessors_["W" + suffix + "/" + std::to_string(mesh.getObjectId())] =
            doc_.addFloatAccessor(w, "VEC4", ViewTarget::ArrayBuffer, false);
    }
    accessors_["sets/" + std::to_string(mesh.getObjectId())] = attrs.sets;
    return skinIndex;
}

void Exporter::exportMesh(const MeshJob& job) {
    m3g::Mesh& mesh = *job.mesh;
    const m3g::VertexBuffer* vb = mesh.vertexBuffer();
    if (!vb || !vb->positions() || vb->getVertexCount() == 0) {
        notes_.add("a Mesh without vertex positions: exported without geometry");
        return;
    }
    const int vertexCount = vb->getVertexCount();
    auto* skinned = dynamic_cast<m3g::SkinnedMesh*>(&mesh);
    auto* morphing = dynamic_cast<m3g::MorphingMesh*>(&mesh);
    int skinIndex = -1;
    bool restJoint = false;
    if (skinned && skinned->boneCount() > 0) skinIndex = skin(*skinned, job.node, restJoint);

    // Morph targets: position and normal displacements (§3.7.2.2).
    Json targets = Json::array();
    if (morphing) {
        for (int t = 0; t < morphing->getMorphTargetCount(); ++t) {
            const m3g::VertexBuffer& target = *morphing->morphTarget(t);
            Json tj = Json::object();
            tj["POSITION"] =
                doc_.addFloatAccessor(positionDeltas(*vb, target), "VEC3", ViewTarget::ArrayBuffer, true);
            if (vb->normals() && target.normals())
                tj["NORMAL"] = doc_.addFloatAccessor(normalDeltas(*vb->normals(), *target.normals()), "VEC3",
                                                     ViewTarget::ArrayBuffer, false);
            if (target.colors() || target.texCoords(0))
                notes_.add("morphed colours and texture coordinates: only positions and normals are morphed in glTF");
            targets.push_back(std::move(tj));
        }
    }

    Json primitives = Json::array();
    for (int i = 0; i < mesh.getSubmeshCount(); ++i) {
        const m3g::IndexBuffer* ib = mesh.indexBuffer(i);
        const m3g::Appearance* ap = mesh.appearance(i);
        if (!ap) {
            notes_.add("a submesh without Appearance (not rendered by M3G): skipped");
            continue;
        }
        if (!ib || ib->getIndexCount() == 0) continue;
        if (ib->maxIndex() >= vertexCount) {
            notes_.add("a submesh with indices past the end of its VertexBuffer: skipped");
            continue;
        }
        const PrimitiveLook look = materials_.look(*ap, *vb, job.alphaFactor);
        Json attributes = Json::object();
        attributes["POSITION"] = positionAccessor(*vb);
        if (vb->normals()) attributes["NORMAL"] = normalAccessor(*vb);
        if (look.vertexColors) {
            const std::string key = "C" + std::to_string(vb->getObjectId());
            if (!accessors_.count(key)) accessors_[key] = doc_.addByteAccessor(colors(*vb->colors()), "VEC4", true);
            attributes["COLOR_0"] = accessors_[key];
        }
        if (look.textureUnit >= 0) {
            m3g::Transform tm;
            look.texture->getCompositeTransform(&tm);
            std::string key = "T" + std::to_string(vb->getObjectId()) + "/" + std::to_string(look.textureUnit);
            for (float v : tm.rows()) key += "/" + std::to_string(v);
            if (!accessors_.count(key))
                accessors_[key] = doc_.addFloatAccessor(texCoords(*vb, look.textureUnit, tm), "VEC2",
                                                        ViewTarget::ArrayBuffer, false);
            attributes["TEXCOORD_0"] = accessors_[key];
        }
        if (skinIndex >= 0) {
            const std::string id = std::to_string(mesh.getObjectId());
            for (int set = 0; set < accessors_["sets/" + id]; ++set) {
                attributes["JOINTS_" + std::to_string(set)] = accessors_["J" + std::to_string(set) + "/" + id];
                attributes["WEIGHTS_" + std::to_string(set)] = accessors_["W" + std::to_string(set) + "/" + id];
            }
        }
        const std::string ikey = "I" + std::to_string(ib->getObjectId()) + (look.flipWinding ? "f" : "");
        if (!accessors_.count(ikey)) accessors_[ikey] = doc_.addIndexAccessor(triangleList(*ib, look.flipWinding));
        Json prim = {{"attributes", std::move(attributes)}, {"indices", accessors_[ikey]}, {"material", look.material}};
        if (!targets.empty()) prim["targets"] = targets;
        primitives.push_back(std::move(prim));
    }
    if (primitives.empty()) return;
    Json meshJson = {{"name", nodeName(mesh)}, {"primitives", std::move(primitives)}};
    if (!targets.empty()) {
        const auto w = morphing->weights();
        meshJson["weights"] = std::vector<float>(w.begin(), w.end());
        morphTargets_[&mesh] = static_cast<int>(targets.size());
    }
    int meshNode = job.node;
    if (skinIndex >= 0 && nodes_[static_cast<std::size_t>(job.node)].contains("matrix")) {
        // A skinned mesh's own transform plays no part in glTF (the joints
        // place its vertices), and importers refuse a node that has both a
        // skin and a matrix (f3d: "Invalid node.matrix value with node.skin
        // defined"): the mesh goes on a child without a transform.
        meshNode = newNode({{"name", nodeName(mesh) + " skinned"}});
        addChild(job.node, meshNode);
    }
    Json& node = nodes_[static_cast<std::size_t>(meshNode)];
    node["mesh"] = doc_.add("meshes", std::move(meshJson));
    if (skinIndex >= 0) node["skin"] = skinIndex;
    meshNodes_[&mesh] = meshNode;
}

void Exporter::exportAnimations(std::span<m3g::Object3D* const> all) {
    struct Channel {
        AnimationTrack* track;
        int node;
        std::string path;
        TimeMapping mapping;
        float weight;
        int outputs;  // components per output element
        double activeStart = 0.0, activeEnd = 0.0;  // equal: always active
    };
    std::map<std::pair<int, std::string>, Channel> channels;  // one per (node, path)
    for (m3g::Object3D* o : all) {
        for (int i = 0; i < o->getAnimationTrackCount(); ++i) {
            AnimationTrack* track = o->getAnimationTrack(i).get();
            const int property = track->getTargetProperty();
            const m3g::AnimationController* controller = track->getController().get();
            if (!controller) {
                notes_.add("an AnimationTrack without AnimationController (inactive in M3G): not exported");
                continue;
            }
            if (controller->getWeight() <= 0.0f) {
                notes_.add("an AnimationTrack whose controller has weight 0 (no effect in M3G): not exported");
                continue;
            }
            int node = -1;
            std::string path;
            int outputs = 0;
            if (isTrsProperty(property) && dynamic_cast<m3g::Node*>(o) && slots_.count(static_cast<m3g::Node*>(o))) {
                node = slots_[static_cast<m3g::Node*>(o)].outer;
                path = property == AnimationTrack::TRANSLATION ? "translation"
                       : property == AnimationTrack::ORIENTATION ? "rotation"
                                                                  : "scale";
                outputs = property == AnimationTrack::ORIENTATION ? 4 : 3;
            } else if (property == AnimationTrack::MORPH_WEIGHTS && dynamic_cast<m3g::Mesh*>(o) &&
                       morphTargets_.count(static_cast<m3g::Mesh*>(o))) {
                node = meshNodes_[static_cast<m3g::Mesh*>(o)];
                path = "weights";
                outputs = morphTargets_[static_cast<m3g::Mesh*>(o)];
            } else {
                notes_.add(std::string("AnimationTrack on ") + o->getClassName() + "." + propertyName(property) +
                           ": no glTF equivalent, not exported");
                continue;
            }
            Channel ch{track, node, path, {}, controller->getWeight(), outputs, 0.0, 0.0};
            ch.mapping.refWorldTime = controller->getRefWorldTime();
            ch.mapping.refSequenceTime = controller->getPosition(controller->getRefWorldTime());
            ch.mapping.speed = controller->getSpeed();
            if (controller->getActiveIntervalStart() != controller->getActiveIntervalEnd()) {
                ch.activeStart = controller->getActiveIntervalStart();
                ch.activeEnd = controller->getActiveIntervalEnd();
            }
            const auto key = std::make_pair(node, path);
            const auto it = channels.find(key);
            if (it != channels.end()) {
                notes_.add("several AnimationTracks on one property (M3G blends them by weight): the heaviest is exported");
                if (it->second.weight >= ch.weight) continue;
            }
            channels[key] = ch;
        }
    }
    if (channels.empty()) return;

    double clipEnd = 0.0;
    for (const auto& [key, ch] : channels)
        clipEnd = std::max(clipEnd, channelEnd(*ch.track->getKeyframeSequence(), ch.mapping));

    Json samplers = Json::array();
    Json channelList = Json::array();
    for (const auto& [key, ch] : channels) {
        // An active interval covering the whole clip changes nothing.
        if (ch.activeStart != ch.activeEnd && (ch.activeStart > 0.0 || ch.activeEnd < clipEnd))
            notes_.add("AnimationController active intervals are not exported (tracks play throughout the clip)");
        SamplerKeys keys;
        try {
            keys = convertSequence(*ch.track->getKeyframeSequence(), ch.mapping, clipEnd, ch.path == "rotation");
        } catch (const std::invalid_argument& e) {
            notes_.add(std::string("an AnimationTrack was not exported: ") + e.what());
            continue;
        }
        if (keys.capped) notes_.add("a looping channel was cut at " + std::to_string(kMaxChannelKeys) + " keys");
        reshapeComponents(keys, ch.outputs);
        const char* type = ch.path == "weights" ? "SCALAR" : ch.outputs == 4 ? "VEC4" : "VEC3";
        const int input = doc_.addFloatAccessor(keys.times, "SCALAR", ViewTarget::None, true);
        const int output = doc_.addFloatAccessor(keys.values, type, ViewTarget::None, false);
        channelList.push_back({{"sampler", samplers.size()}, {"target", {{"node", ch.node}, {"path", ch.path}}}});
        samplers.push_back({{"input", input}, {"output", output}, {"interpolation", keys.interpolation}});
    }
    if (channelList.empty()) return;
    doc_.add("animations", {{"name", "M3G animation"}, {"channels", channelList}, {"samplers", samplers}});
}

ExportResult Exporter::run(std::span<m3g::Object3D* const> roots) {
    const std::vector<m3g::Object3D*> all = reachable(roots);

    // Scenes: one per World (its children, plus an active camera outside
    // it), then the root nodes outside any World.
    struct Scene {
        std::string name;
        std::vector<m3g::Node*> nodes;
        Axis up = kUpY;
    };
    std::vector<Scene> scenes;
    for (m3g::Object3D* o : all) {
        auto* world = dynamic_cast<m3g::World*>(o);
        if (!world) continue;
        std::vector<m3g::Node*> nodes;
        world->collectChildren(nodes);
        m3g::Camera* active = world->getActiveCamera().get();
        if (active && active->root() != world) {
            notes_.add("the World's active camera is outside the World: added as a root node of its scene");
            if (!active->getParent()) nodes.push_back(active);
        }
        if (world->getAnimationTrackCount() > 0 || !isIdentity(world->compositeTransform()))
            notes_.add("the World's own transform and animation are not applied (as in M3G rendering)");
        scenes.push_back({nodeName(*world), std::move(nodes), options_.up ? *options_.up : sceneUp(*world)});
    }
    std::vector<m3g::Node*> loose;
    for (m3g::Object3D* o : all) {
        auto* node = dynamic_cast<m3g::Node*>(o);
        if (!node || node->getParent() || dynamic_cast<m3g::World*>(node)) continue;
        bool placed = false;
        for (const auto& s : scenes) placed = placed || std::find(s.nodes.begin(), s.nodes.end(), node) != s.nodes.end();
        if (!placed) loose.push_back(node);
    }
    if (!loose.empty())
        scenes.push_back({scenes.empty() ? "scene" : "nodes outside the World", std::move(loose), options_.up.value_or(kUpY)});

    for (const Scene& scene : scenes) {
        Json sceneNodes = Json::array();
        for (m3g::Node* n : scene.nodes) sceneNodes.push_back(visit(*n, false, 1.0f));
        if (scene.up != kUpY) {
            // glTF is +Y up: one root node turns the scene's up onto +Y.
            const int upright = newNode({{"name", "M3G " + axisName(scene.up) + " up to glTF +Y"},
                                         {"rotation", uprightRotation(scene.up)},
                                         {"children", sceneNodes}});
            sceneNodes = Json::array({upright});
            notes_.add("the scene's up axis is " + axisName(scene.up) +
                       " (its active camera's up): a root node turns it to glTF's +Y");
        }
        doc_.add("scenes", {{"name", scene.name}, {"nodes", sceneNodes}});
    }
    for (const MeshJob& job : meshes_) exportMesh(job);
    exportAnimations(all);

    for (m3g::Object3D* o : all) {
        if (dynamic_cast<m3g::Background*>(o)) notes_.add("Background has no glTF equivalent (dropped)");
    }
    if (nodes_.empty()) {
        // Nothing to place in a scene (a texture library, a lone array): keep
        // the images at least.
        notes_.add("the file has no nodes: the glTF has no scene");
        for (m3g::Object3D* o : all)
            if (auto* image = dynamic_cast<m3g::Image2D*>(o)) materials_.image(*image);
    }
    if (!scenes.empty()) doc_.json()["scene"] = 0;
    makeNamesUnique(nodes_);
    if (!nodes_.empty()) doc_.json()["nodes"] = nodes_;
    // Keep the top-level order readable: move extensions to the end.
    if (doc_.json().contains("extensions")) {
        Json ext = doc_.json()["extensions"];
        doc_.json().erase("extensions");
        doc_.json()["extensions"] = std::move(ext);
    }
    result_.warnings = notes_.lines();
    return std::move(result_);
}

}  // namespace

ExportResult exportScene(std::span<m3g::Object3D* const> roots, const ExportOptions& options) {
    Exporter exporter(options);
    return exporter.run(roots);
}

void writeExport(const ExportResult& result, const std::string& path, bool separateBin) {
    auto endsWith = [&](const char* ext) {
        const std::string e = ext;
        if (path.size() < e.size()) return false;
        std::string tail = path.substr(path.size() - e.size());
        std::transform(tail.begin(), tail.end(), tail.begin(), [](unsigned char c) { return std::tolower(c); });
        return tail == e;
    };
    auto writeBytes = [](const std::string& file, const char* data, std::size_t size) {
        std::ofstream out(file, std::ios::binary);
        if (!out) throw std::runtime_error("cannot open " + file + " for writing");
        out.write(data, static_cast<std::streamsize>(size));
        if (!out) throw std::runtime_error("cannot write " + file);
    };
    if (endsWith(".glb")) {
        if (separateBin) throw std::runtime_error("--separate-bin applies to .gltf output only, not " + path);
        const auto bytes = result.document.toGlb();
        writeBytes(path, reinterpret_cast<const char*>(bytes.data()), bytes.size());
    } else if (endsWith(".gltf")) {
        std::string binUri;
        if (separateBin && !result.document.binary().empty()) {
            const std::string binPath = path.substr(0, path.size() - 5) + ".bin";
            const auto slash = binPath.find_last_of('/');
            binUri = slash == std::string::npos ? binPath : binPath.substr(slash + 1);
            const auto& bin = result.document.binary();
            writeBytes(binPath, reinterpret_cast<const char*>(bin.data()), bin.size());
        }
        const std::string text = result.document.toGltf(binUri);
        writeBytes(path, text.data(), text.size());
    } else {
        throw std::runtime_error("output " + path + " must end in .glb or .gltf");
    }
}

}  // namespace m3gcli::gltf
