// Object graph equivalence for round-trip tests (load -> save -> load, and
// duplicate()): walks two graphs in parallel through getReferences (plus the
// named slots of every class, node alignment references and SkinnedMesh
// bones) and compares every getter of every class. Test-only.
#pragma once

#include <algorithm>
#include <any>
#include <cmath>
#include <deque>
#include <memory>
#include <span>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include <m3g/m3g.h>

namespace m3gtest {

struct GraphCompareOptions {
    /// Float tolerance: |a - b| <= epsilon * max(1, |a|, |b|).
    float epsilon = 1e-5f;
    /// Tolerance for Node alpha factor and CompositingMode alpha threshold,
    /// which the file stores as bytes (use 1.0f / 255 to compare an
    /// API-built graph with its saved-and-loaded copy).
    float alphaEpsilon = 1e-6f;
    /// Compare the pixels of mutable images (the file does not store them).
    bool compareMutablePixels = true;
};

namespace roundtrip_detail {

using m3g::Object3D;
using m3g::Ref;

template <class T>
std::string toText(const T& v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

class GraphComparer {
public:
    explicit GraphComparer(const GraphCompareOptions& options) : opt_(options) {}

    /// Empty if equivalent, else "<path>: <difference>".
    std::string run(std::span<const Object3D* const> a, std::span<const Object3D* const> b) {
        if (a.size() != b.size()) return "roots: count " + toText(a.size()) + " != " + toText(b.size());
        for (std::size_t i = 0; i < a.size(); ++i)
            if (!edge("roots[" + toText(i) + "]", a[i], b[i])) return error_;
        while (!queue_.empty()) {
            auto [x, y, path] = queue_.front();
            queue_.pop_front();
            if (!compareObject(path, *x, *y)) return error_;
        }
        return {};
    }

private:
    struct Item {
        const Object3D* a;
        const Object3D* b;
        std::string path;
    };

    bool fail(const std::string& path, const std::string& what) {
        error_ = path + ": " + what;
        return false;
    }

    template <class T>
    bool eq(const std::string& path, const char* what, const T& x, const T& y) {
        if (x == y) return true;
        return fail(path, std::string(what) + " " + toText(x) + " != " + toText(y));
    }

    bool near(float x, float y, float eps) const {
        if (x == y) return true;
        const float scale = std::max({1.0f, std::fabs(x), std::fabs(y)});
        return std::fabs(x - y) <= eps * scale;
    }

    bool feq(const std::string& path, const char* what, float x, float y, float eps = -1.0f) {
        if (near(x, y, eps < 0 ? opt_.epsilon : eps)) return true;
        return fail(path, std::string(what) + " " + toText(x) + " != " + toText(y));
    }

    bool feqs(const std::string& path, const char* what, std::span<const float> x, std::span<const float> y) {
        if (x.size() != y.size()) return fail(path, std::string(what) + ": length differs");
        for (std::size_t i = 0; i < x.size(); ++i)
            if (!feq(path, (std::string(what) + "[" + toText(i) + "]").c_str(), x[i], y[i])) return false;
        return true;
    }

    bool transforms(const std::string& path, const char* what, const m3g::Transform& x, const m3g::Transform& y) {
        return feqs(path, what, x.rows(), y.rows());
    }

    /// A reference slot: null-ness must agree, and the pairing of objects
    /// must be one-to-one across the whole graph (sharing is preserved).
    bool edge(const std::string& path, const Object3D* x, const Object3D* y) {
        if (!x || !y) {
            if (x == y) return true;
            return fail(path, std::string("reference is ") + (x ? x->getClassName() : "null") + " vs " +
                                  (y ? y->getClassName() : "null"));
        }
        auto ix = ab_.find(x);
        auto iy = ba_.find(y);
        if (ix != ab_.end() || iy != ba_.end()) {
            if (ix == ab_.end() || iy == ba_.end() || ix->second != y || iy->second != x)
                return fail(path, std::string("sharing differs (") + x->getClassName() + " vs " + y->getClassName() +
                                      " paired differently elsewhere)");
            return true;
        }
        if (std::string(x->getClassName()) != y->getClassName())
            return fail(path, std::string("class ") + x->getClassName() + " != " + y->getClassName());
        ab_[x] = y;
        ba_[y] = x;
        queue_.push_back({x, y, path + " " + x->getClassName()});
        return true;
    }

    bool compareObject(const std::string& path, const Object3D& a, const Object3D& b);
    bool compareObject3D(const std::string& path, const Object3D& a, const Object3D& b);
    bool compareTransformable(const std::string& path, const m3g::Transformable& a, const m3g::Transformable& b);
    bool compareNode(const std::string& path, const m3g::Node& a, const m3g::Node& b);
    bool compareMesh(const std::string& path, const m3g::Mesh& a, const m3g::Mesh& b);
    bool compareClass(const std::string& path, const Object3D& a, const Object3D& b);

    GraphCompareOptions opt_;
    std::unordered_map<const Object3D*, const Object3D*> ab_, ba_;
    std::deque<Item> queue_;
    std::string error_;
};

inline bool GraphComparer::compareObject(const std::string& path, const Object3D& a, const Object3D& b) {
    if (!compareObject3D(path, a, b) || !compareClass(path, a, b)) return false;
    // Then the generic references (catches anything a class-specific slot misses).
    const int na = a.getReferences();
    const int nb = b.getReferences();
    if (!eq(path, "getReferences count", na, nb)) return false;
    std::vector<Ref<Object3D>> ra(static_cast<std::size_t>(na)), rb(static_cast<std::size_t>(nb));
    a.getReferences(ra);
    b.getReferences(rb);
    for (int i = 0; i < na; ++i)
        if (!edge(path + " > refs[" + toText(i) + "]", ra[i].get(), rb[i].get())) return false;
    return true;
}

inline bool GraphComparer::compareObject3D(const std::string& path, const Object3D& a, const Object3D& b) {
    if (!eq(path, "getUserID", a.getUserID(), b.getUserID())) return false;
    if (!eq(path, "getAnimationTrackCount", a.getAnimationTrackCount(), b.getAnimationTrackCount())) return false;
    for (int i = 0; i < a.getAnimationTrackCount(); ++i)
        if (!edge(path + " > animationTrack[" + toText(i) + "]", a.getAnimationTrack(i).get(),
                  b.getAnimationTrack(i).get()))
            return false;
    static const m3g::UserParameters kNone;
    const auto* pa = a.getUserParameters();
    const auto* pb = b.getUserParameters();
    if (*(pa ? pa : &kNone) != *(pb ? pb : &kNone)) return fail(path, "user parameters differ");
    return true;
}

inline bool GraphComparer::compareTransformable(const std::string& path, const m3g::Transformable& a,
                                                const m3g::Transformable& b) {
    float ta[3], tb[3], sa[3], sb[3];
    a.getTranslation(ta);
    b.getTranslation(tb);
    a.getScale(sa);
    b.getScale(sb);
    if (!feqs(path, "getTranslation", ta, tb) || !feqs(path, "getScale", sa, sb)) return false;
    // Orientation as a quaternion; q and -q are the same rotation.
    const auto& qa = a.orientationQuat();
    const auto& qb = b.orientationQuat();
    bool same = true, opposite = true;
    for (int i = 0; i < 4; ++i) {
        same = same && near(qa[i], qb[i], opt_.epsilon * 10);
        opposite = opposite && near(qa[i], -qb[i], opt_.epsilon * 10);
    }
    if (!same && !opposite)
        return fail(path, "orientation (" + toText(qa[0]) + "," + toText(qa[1]) + "," + toText(qa[2]) + "," +
                              toText(qa[3]) + ") != (" + toText(qb[0]) + "," + toText(qb[1]) + "," +
                              toText(qb[2]) + "," + toText(qb[3]) + ")");
    m3g::Transform ma, mb;
    a.getTransform(&ma);
    b.getTransform(&mb);
    return transforms(path, "getTransform", ma, mb);
}

inline bool GraphComparer::compareNode(const std::string& path, const m3g::Node& a, const m3g::Node& b) {
    using m3g::Node;
    if (!compareTransformable(path, a, b)) return false;
    if (!eq(path, "isRenderingEnabled", a.isRenderingEnabled(), b.isRenderingEnabled()) ||
        !eq(path, "isPickingEnabled", a.isPickingEnabled(), b.isPickingEnabled()) ||
        !feq(path, "getAlphaFactor", a.getAlphaFactor(), b.getAlphaFactor(), opt_.alphaEpsilon) ||
        !eq(path, "getScope", a.getScope(), b.getScope()))
        return false;
    for (int axis : {Node::Z_AXIS, Node::Y_AXIS}) {
        const std::string which = axis == Node::Z_AXIS ? "Z" : "Y";
        if (!eq(path, ("getAlignmentTarget(" + which + ")").c_str(), a.getAlignmentTarget(axis),
                b.getAlignmentTarget(axis)) ||
            !edge(path + " > alignmentReference(" + which + ")", a.getAlignmentReference(axis).get(),
                  b.getAlignmentReference(axis).get()))
            return false;
    }
    return true;
}

inline bool GraphComparer::compareMesh(const std::string& path, const m3g::Mesh& a, const m3g::Mesh& b) {
    if (!compareNode(path, a, b)) return false;
    if (!edge(path + " > vertexBuffer", a.getVertexBuffer().get(), b.getVertexBuffer().get())) return false;
    if (!eq(path, "getSubmeshCount", a.getSubmeshCount(), b.getSubmeshCount())) return false;
    for (int i = 0; i < a.getSubmeshCount(); ++i) {
        const std::string k = "[" + toText(i) + "]";
        if (!edge(path + " > indexBuffer" + k, a.getIndexBuffer(i).get(), b.getIndexBuffer(i).get()) ||
            !edge(path + " > appearance" + k, a.getAppearance(i).get(), b.getAppearance(i).get()))
            return false;
    }
    return true;
}

inline bool GraphComparer::compareClass(const std::string& path, const Object3D& oa, const Object3D& ob) {
    using namespace m3g;
    const std::string cls = oa.getClassName();
    // Classes are equal here (edge() checked getClassName).
    if (auto* a = dynamic_cast<const World*>(&oa)) {
        auto* b = static_cast<const World*>(&ob);
        if (!compareNode(path, *a, *b) || !eq(path, "getChildCount", a->getChildCount(), b->getChildCount()))
            return false;
        for (int i = 0; i < a->getChildCount(); ++i)
            if (!edge(path + " > child[" + toText(i) + "]", a->getChild(i).get(), b->getChild(i).get())) return false;
        return edge(path + " > activeCamera", a->getActiveCamera().get(), b->getActiveCamera().get()) &&
               edge(path + " > background", a->getBackground().get(), b->getBackground().get());
    }
    if (auto* a = dynamic_cast<const Group*>(&oa)) {
        auto* b = static_cast<const Group*>(&ob);
        if (!compareNode(path, *a, *b) || !eq(path, "getChildCount", a->getChildCount(), b->getChildCount()))
            return false;
        for (int i = 0; i < a->getChildCount(); ++i)
            if (!edge(path + " > child[" + toText(i) + "]", a->getChild(i).get(), b->getChild(i).get())) return false;
        return true;
    }
    if (auto* a = dynamic_cast<const SkinnedMesh*>(&oa)) {
        auto* b = static_cast<const SkinnedMesh*>(&ob);
        if (!compareMesh(path, *a, *b) ||
            !edge(path + " > skeleton", a->getSkeleton().get(), b->getSkeleton().get()))
            return false;
        const auto ta = a->addedTransforms();
        const auto tb = b->addedTransforms();
        if (!eq(path, "addTransform count", ta.size(), tb.size())) return false;
        for (std::size_t i = 0; i < ta.size(); ++i) {
            const std::string k = "addTransform[" + toText(i) + "]";
            if (!edge(path + " > " + k + ".bone", a->bone(ta[i].bone), b->bone(tb[i].bone)) ||
                !eq(path, (k + ".weight").c_str(), ta[i].weight, tb[i].weight) ||
                !eq(path, (k + ".firstVertex").c_str(), ta[i].firstVertex, tb[i].firstVertex) ||
                !eq(path, (k + ".vertexCount").c_str(), ta[i].vertexCount, tb[i].vertexCount))
                return false;
        }
        if (!eq(path, "boneCount", a->boneCount(), b->boneCount())) return false;
        for (int i = 0; i < a->boneCount(); ++i) {
            const std::string k = "bone[" + toText(i) + "]";
            if (!transforms(path, (k + " at-rest transform").c_str(), a->atRestTransform(i), b->atRestTransform(i)))
                return false;
            const int ca = a->getBoneVertices(a->bone(i));
            const int cb = b->getBoneVertices(b->bone(i));
            if (!eq(path, (k + " getBoneVertices count").c_str(), ca, cb)) return false;
            std::vector<int> ia(static_cast<std::size_t>(ca)), ib(static_cast<std::size_t>(cb));
            std::vector<float> wa(ia.size()), wb(ib.size());
            a->getBoneVertices(a->bone(i), ia, wa);
            b->getBoneVertices(b->bone(i), ib, wb);
            if (ia != ib) return fail(path, k + " getBoneVertices indices differ");
            if (!feqs(path, (k + " getBoneVertices weights").c_str(), wa, wb)) return false;
        }
        return true;
    }
    if (auto* a = dynamic_cast<const MorphingMesh*>(&oa)) {
        auto* b = static_cast<const MorphingMesh*>(&ob);
        if (!compareMesh(path, *a, *b) ||
            !eq(path, "getMorphTargetCount", a->getMorphTargetCount(), b->getMorphTargetCount()))
            return false;
        for (int i = 0; i < a->getMorphTargetCount(); ++i)
            if (!edge(path + " > morphTarget[" + toText(i) + "]", a->getMorphTarget(i).get(),
                      b->getMorphTarget(i).get()))
                return false;
        std::vector<float> wa(static_cast<std::size_t>(a->getMorphTargetCount())), wb(wa.size());
        a->getWeights(wa);
        b->getWeights(wb);
        return feqs(path, "getWeights", wa, wb);
    }
    if (auto* a = dynamic_cast<const Mesh*>(&oa)) return compareMesh(path, *a, static_cast<const Mesh&>(ob));
    if (auto* a = dynamic_cast<const Camera*>(&oa)) {
        auto* b = static_cast<const Camera*>(&ob);
        if (!compareNode(path, *a, *b)) return false;
        float pa[4] = {0, 0, 0, 0}, pb[4] = {0, 0, 0, 0};
        const int typeA = a->getProjection(std::span<float>(pa));
        const int typeB = b->getProjection(std::span<float>(pb));
        if (!eq(path, "getProjection type", typeA, typeB)) return false;
        if (typeA != Camera::GENERIC) return feqs(path, "getProjection params", pa, pb);
        Transform ma, mb;
        a->getProjection(&ma);
        b->getProjection(&mb);
        return transforms(path, "getProjection matrix", ma, mb);
    }
    if (auto* a = dynamic_cast<const Light*>(&oa)) {
        auto* b = static_cast<const Light*>(&ob);
        return compareNode(path, *a, *b) && eq(path, "getMode", a->getMode(), b->getMode()) &&
               eq(path, "getColor", a->getColor(), b->getColor()) &&
               feq(path, "getIntensity", a->getIntensity(), b->getIntensity()) &&
               feq(path, "getSpotAngle", a->getSpotAngle(), b->getSpotAngle()) &&
               feq(path, "getSpotExponent", a->getSpotExponent(), b->getSpotExponent()) &&
               feq(path, "getConstantAttenuation", a->getConstantAttenuation(), b->getConstantAttenuation()) &&
               feq(path, "getLinearAttenuation", a->getLinearAttenuation(), b->getLinearAttenuation()) &&
               feq(path, "getQuadraticAttenuation", a->getQuadraticAttenuation(), b->getQuadraticAttenuation());
    }
    if (auto* a = dynamic_cast<const Sprite3D*>(&oa)) {
        auto* b = static_cast<const Sprite3D*>(&ob);
        return compareNode(path, *a, *b) && eq(path, "isScaled", a->isScaled(), b->isScaled()) &&
               edge(path + " > image", a->getImage().get(), b->getImage().get()) &&
               edge(path + " > appearance", a->getAppearance().get(), b->getAppearance().get()) &&
               eq(path, "getCropX", a->getCropX(), b->getCropX()) && eq(path, "getCropY", a->getCropY(), b->getCropY()) &&
               eq(path, "getCropWidth", a->getCropWidth(), b->getCropWidth()) &&
               eq(path, "getCropHeight", a->getCropHeight(), b->getCropHeight());
    }
    if (auto* a = dynamic_cast<const Texture2D*>(&oa)) {
        auto* b = static_cast<const Texture2D*>(&ob);
        return compareTransformable(path, *a, *b) &&
               edge(path + " > image", a->getImage().get(), b->getImage().get()) &&
               eq(path, "getBlendColor", a->getBlendColor(), b->getBlendColor()) &&
               eq(path, "getBlending", a->getBlending(), b->getBlending()) &&
               eq(path, "getWrappingS", a->getWrappingS(), b->getWrappingS()) &&
               eq(path, "getWrappingT", a->getWrappingT(), b->getWrappingT()) &&
               eq(path, "getLevelFilter", a->getLevelFilter(), b->getLevelFilter()) &&
               eq(path, "getImageFilter", a->getImageFilter(), b->getImageFilter());
    }
    if (auto* a = dynamic_cast<const Appearance*>(&oa)) {
        auto* b = static_cast<const Appearance*>(&ob);
        if (!eq(path, "getLayer", a->getLayer(), b->getLayer()) ||
            !edge(path + " > compositingMode", a->getCompositingMode().get(), b->getCompositingMode().get()) ||
            !edge(path + " > fog", a->getFog().get(), b->getFog().get()) ||
            !edge(path + " > polygonMode", a->getPolygonMode().get(), b->getPolygonMode().get()) ||
            !edge(path + " > material", a->getMaterial().get(), b->getMaterial().get()))
            return false;
        for (int i = 0; i < getLimits().numTextureUnits; ++i)
            if (!edge(path + " > texture[" + toText(i) + "]", a->getTexture(i).get(), b->getTexture(i).get()))
                return false;
        return true;
    }
    if (auto* a = dynamic_cast<const CompositingMode*>(&oa)) {
        auto* b = static_cast<const CompositingMode*>(&ob);
        return eq(path, "getBlending", a->getBlending(), b->getBlending()) &&
               feq(path, "getAlphaThreshold", a->getAlphaThreshold(), b->getAlphaThreshold(), opt_.alphaEpsilon) &&
               eq(path, "isDepthTestEnabled", a->isDepthTestEnabled(), b->isDepthTestEnabled()) &&
               eq(path, "isDepthWriteEnabled", a->isDepthWriteEnabled(), b->isDepthWriteEnabled()) &&
               eq(path, "isColorWriteEnabled", a->isColorWriteEnabled(), b->isColorWriteEnabled()) &&
               eq(path, "isAlphaWriteEnabled", a->isAlphaWriteEnabled(), b->isAlphaWriteEnabled()) &&
               feq(path, "getDepthOffsetFactor", a->getDepthOffsetFactor(), b->getDepthOffsetFactor()) &&
               feq(path, "getDepthOffsetUnits", a->getDepthOffsetUnits(), b->getDepthOffsetUnits());
    }
    if (auto* a = dynamic_cast<const PolygonMode*>(&oa)) {
        auto* b = static_cast<const PolygonMode*>(&ob);
        return eq(path, "getCulling", a->getCulling(), b->getCulling()) &&
               eq(path, "getShading", a->getShading(), b->getShading()) &&
               eq(path, "getWinding", a->getWinding(), b->getWinding()) &&
               eq(path, "isTwoSidedLightingEnabled", a->isTwoSidedLightingEnabled(), b->isTwoSidedLightingEnabled()) &&
               eq(path, "isLocalCameraLightingEnabled", a->isLocalCameraLightingEnabled(),
                  b->isLocalCameraLightingEnabled()) &&
               eq(path, "isPerspectiveCorrectionEnabled", a->isPerspectiveCorrectionEnabled(),
                  b->isPerspectiveCorrectionEnabled());
    }
    if (auto* a = dynamic_cast<const Material*>(&oa)) {
        auto* b = static_cast<const Material*>(&ob);
        return eq(path, "getColor(AMBIENT)", a->getColor(Material::AMBIENT), b->getColor(Material::AMBIENT)) &&
               eq(path, "getColor(DIFFUSE)", a->getColor(Material::DIFFUSE), b->getColor(Material::DIFFUSE)) &&
               eq(path, "getColor(EMISSIVE)", a->getColor(Material::EMISSIVE), b->getColor(Material::EMISSIVE)) &&
               eq(path, "getColor(SPECULAR)", a->getColor(Material::SPECULAR), b->getColor(Material::SPECULAR)) &&
               feq(path, "getShininess", a->getShininess(), b->getShininess()) &&
               eq(path, "isVertexColorTrackingEnabled", a->isVertexColorTrackingEnabled(),
                  b->isVertexColorTrackingEnabled());
    }
    if (auto* a = dynamic_cast<const Fog*>(&oa)) {
        auto* b = static_cast<const Fog*>(&ob);
        return eq(path, "getMode", a->getMode(), b->getMode()) && eq(path, "getColor", a->getColor(), b->getColor()) &&
               feq(path, "getDensity", a->getDensity(), b->getDensity()) &&
               feq(path, "getNearDistance", a->getNearDistance(), b->getNearDistance()) &&
               feq(path, "getFarDistance", a->getFarDistance(), b->getFarDistance());
    }
    if (auto* a = dynamic_cast<const Background*>(&oa)) {
        auto* b = static_cast<const Background*>(&ob);
        return eq(path, "getColor", a->getColor(), b->getColor()) &&
               edge(path + " > image", a->getImage().get(), b->getImage().get()) &&
               eq(path, "getImageModeX", a->getImageModeX(), b->getImageModeX()) &&
               eq(path, "getImageModeY", a->getImageModeY(), b->getImageModeY()) &&
               eq(path, "getCropX", a->getCropX(), b->getCropX()) && eq(path, "getCropY", a->getCropY(), b->getCropY()) &&
               eq(path, "getCropWidth", a->getCropWidth(), b->getCropWidth()) &&
               eq(path, "getCropHeight", a->getCropHeight(), b->getCropHeight()) &&
               eq(path, "isColorClearEnabled", a->isColorClearEnabled(), b->isColorClearEnabled()) &&
               eq(path, "isDepthClearEnabled", a->isDepthClearEnabled(), b->isDepthClearEnabled());
    }
    if (auto* a = dynamic_cast<const Image2D*>(&oa)) {
        auto* b = static_cast<const Image2D*>(&ob);
        if (!eq(path, "getFormat", a->getFormat(), b->getFormat()) ||
            !eq(path, "getWidth", a->getWidth(), b->getWidth()) ||
            !eq(path, "getHeight", a->getHeight(), b->getHeight()) ||
            !eq(path, "isMutable", a->isMutable(), b->isMutable()) ||
            !eq(path, "isPalettized", a->isPalettized(), b->isPalettized()))
            return false;
        if (a->isMutable() && !opt_.compareMutablePixels) return true;
        auto same = [](std::span<const std::uint8_t> x, std::span<const std::uint8_t> y) {
            return std::equal(x.begin(), x.end(), y.begin(), y.end());
        };
        if (a->isPalettized() &&
            (!same(a->palette(), b->palette()) || !same(a->paletteIndices(), b->paletteIndices())))
            return fail(path, "palette or palette indices differ");
        if (!same(a->pixels(), b->pixels())) return fail(path, "pixels differ");
        return true;
    }
    if (auto* a = dynamic_cast<const TriangleStripArray*>(&oa)) {
        auto* b = static_cast<const TriangleStripArray*>(&ob);
        if (!eq(path, "getIndexCount", a->getIndexCount(), b->getIndexCount())) return false;
        std::vector<int> ia(static_cast<std::size_t>(a->getIndexCount())), ib(ia.size());
        a->getIndices(ia);
        b->getIndices(ib);
        if (ia != ib) return fail(path, "getIndices differ");
        auto sa = a->stripLengths(), sb = b->stripLengths();
        if (!std::equal(sa.begin(), sa.end(), sb.begin(), sb.end())) return fail(path, "strip lengths differ");
        auto xa = a->stripIndices(), xb = b->stripIndices();
        if (!std::equal(xa.begin(), xa.end(), xb.begin(), xb.end())) return fail(path, "strip indices differ");
        return true;
    }
    if (auto* a = dynamic_cast<const VertexArray*>(&oa)) {
        auto* b = static_cast<const VertexArray*>(&ob);
        if (!eq(path, "getVertexCount", a->getVertexCount(), b->getVertexCount()) ||
            !eq(path, "getComponentCount", a->getComponentCount(), b->getComponentCount()) ||
            !eq(path, "getComponentType", a->getComponentType(), b->getComponentType()))
            return false;
        for (int v = 0; v < a->getVertexCount(); ++v)
            for (int c = 0; c < a->getComponentCount(); ++c)
                if (a->value(v, c) != b->value(v, c))
                    return fail(path, "value[" + toText(v) + "][" + toText(c) + "] " + toText(a->value(v, c)) +
                                          " != " + toText(b->value(v, c)));
        return true;
    }
    if (auto* a = dynamic_cast<const VertexBuffer*>(&oa)) {
        auto* b = static_cast<const VertexBuffer*>(&ob);
        if (!eq(path, "getVertexCount", a->getVertexCount(), b->getVertexCount()) ||
            !eq(path, "getDefaultColor", a->getDefaultColor(), b->getDefaultColor()))
            return false;
        float sa[4] = {0, 0, 0, 0}, sb[4] = {0, 0, 0, 0};
        auto pa = a->getPositions(sa);
        auto pb = b->getPositions(sb);
        if (!edge(path + " > positions", pa.get(), pb.get()) || (pa && !feqs(path, "positions scale/bias", sa, sb)))
            return false;
        if (!edge(path + " > normals", a->getNormals().get(), b->getNormals().get()) ||
            !edge(path + " > colors", a->getColors().get(), b->getColors().get()))
            return false;
        for (int i = 0; i < getLimits().numTextureUnits; ++i) {
            float ta[4] = {0, 0, 0, 0}, tb[4] = {0, 0, 0, 0};
            auto xa = a->getTexCoords(i, ta);
            auto xb = b->getTexCoords(i, tb);
            const std::string k = "texCoords[" + toText(i) + "]";
            if (!edge(path + " > " + k, xa.get(), xb.get()) || (xa && !feqs(path, (k + " scale/bias").c_str(), ta, tb)))
                return false;
        }
        return true;
    }
    if (auto* a = dynamic_cast<const KeyframeSequence*>(&oa)) {
        auto* b = static_cast<const KeyframeSequence*>(&ob);
        if (!eq(path, "getKeyframeCount", a->getKeyframeCount(), b->getKeyframeCount()) ||
            !eq(path, "getComponentCount", a->getComponentCount(), b->getComponentCount()) ||
            !eq(path, "getInterpolationType", a->getInterpolationType(), b->getInterpolationType()) ||
            !eq(path, "getDuration", a->getDuration(), b->getDuration()) ||
            !eq(path, "getRepeatMode", a->getRepeatMode(), b->getRepeatMode()) ||
            !eq(path, "getValidRangeFirst", a->getValidRangeFirst(), b->getValidRangeFirst()) ||
            !eq(path, "getValidRangeLast", a->getValidRangeLast(), b->getValidRangeLast()))
            return false;
        std::vector<float> va(static_cast<std::size_t>(a->getComponentCount())), vb(va.size());
        for (int k = 0; k < a->getKeyframeCount(); ++k) {
            const std::string key = "getKeyframe(" + toText(k) + ")";
            if (!eq(path, (key + " time").c_str(), a->getKeyframe(k, va), b->getKeyframe(k, vb)) ||
                !feqs(path, (key + " value").c_str(), va, vb))
                return false;
        }
        return true;
    }
    if (auto* a = dynamic_cast<const AnimationTrack*>(&oa)) {
        auto* b = static_cast<const AnimationTrack*>(&ob);
        return eq(path, "getTargetProperty", a->getTargetProperty(), b->getTargetProperty()) &&
               edge(path + " > keyframeSequence", a->getKeyframeSequence().get(), b->getKeyframeSequence().get()) &&
               edge(path + " > controller", a->getController().get(), b->getController().get());
    }
    if (auto* a = dynamic_cast<const AnimationController*>(&oa)) {
        auto* b = static_cast<const AnimationController*>(&ob);
        return eq(path, "getActiveIntervalStart", a->getActiveIntervalStart(), b->getActiveIntervalStart()) &&
               eq(path, "getActiveIntervalEnd", a->getActiveIntervalEnd(), b->getActiveIntervalEnd()) &&
               feq(path, "getSpeed", a->getSpeed(), b->getSpeed()) &&
               feq(path, "getWeight", a->getWeight(), b->getWeight()) &&
               eq(path, "getRefWorldTime", a->getRefWorldTime(), b->getRefWorldTime()) &&
               feq(path, "getPosition(refWorldTime)", a->getPosition(a->getRefWorldTime()),
                   b->getPosition(b->getRefWorldTime()));
    }
    return fail(path, "unknown class " + cls);
}

}  // namespace roundtrip_detail

/// Empty if the graphs reachable from `a` and `b` (root lists compared
/// pairwise) are equivalent, else the first difference as
/// "roots[0] World > child[2] Mesh > vertexBuffer VertexBuffer: getDefaultColor 1 != 2".
inline std::string compareGraphs(std::span<const m3g::Object3D* const> a, std::span<const m3g::Object3D* const> b,
                                 const GraphCompareOptions& options = {}) {
    return roundtrip_detail::GraphComparer(options).run(a, b);
}

inline std::string compareGraphs(const m3g::Object3D* a, const m3g::Object3D* b,
                                 const GraphCompareOptions& options = {}) {
    const m3g::Object3D* ra[] = {a};
    const m3g::Object3D* rb[] = {b};
    return compareGraphs(ra, rb, options);
}

inline std::string compareGraphs(std::span<const m3g::Ref<m3g::Object3D>> a, std::span<const m3g::Ref<m3g::Object3D>> b,
                                 const GraphCompareOptions& options = {}) {
    std::vector<const m3g::Object3D*> ra, rb;
    for (const auto& r : a) ra.push_back(r.get());
    for (const auto& r : b) rb.push_back(r.get());
    return compareGraphs(ra, rb, options);
}

}  // namespace m3gtest
