// tools/m3g/Gltf*: the glTF export's conversions checked against hand-computed
// values (strip unrolling and winding, scale/bias, quaternions, matrices,
// keyframe time mapping, SPLINE tangents, SLERP arcs, materials, skins,
// images, the GLB container).
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <cstring>
#include <numbers>
#include <vector>

#include <png.h>

#include <m3g/m3g.h>

#include "GltfAnimation.h"
#include "GltfDocument.h"
#include "GltfExport.h"
#include "GltfGeometry.h"
#include "GltfTransform.h"

using namespace m3g;
using namespace m3gcli::gltf;

namespace {

constexpr float kEps = 1e-5f;

Ref<VertexBuffer> quadBuffer() {
    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<VertexArray> pos = new VertexArray(4, 3, 2);
    const std::int16_t p[] = {0, 0, 0, 2, 0, 0, 0, 2, 0, 2, 2, 0};
    pos->set(0, 4, p);
    const float bias[] = {0.0f, 0.0f, 0.0f};
    vb->setPositions(pos, 1.0f, bias);
    return vb;
}

/// A sequence with the given keys (time, one component each).
Ref<KeyframeSequence> scalarSequence(int interpolation, std::initializer_list<std::pair<int, float>> keys,
                                     int duration, int repeat = KeyframeSequence::CONSTANT) {
    Ref<KeyframeSequence> s = new KeyframeSequence(static_cast<int>(keys.size()), 1, interpolation);
    int i = 0;
    for (const auto& [t, v] : keys) {
        const float value[] = {v};
        s->setKeyframe(i++, t, value);
    }
    s->setDuration(duration);
    s->setRepeatMode(repeat);
    return s;
}

/// The JSON chunk of a GLB file.
Json glbJson(const std::vector<std::uint8_t>& glb) {
    std::uint32_t length = 0;
    std::memcpy(&length, glb.data() + 12, 4);
    return Json::parse(std::string(glb.begin() + 20, glb.begin() + 20 + length));
}

}  // namespace

TEST(GltfGeometry, StripOfFourVerticesIsTwoTrianglesWithAlternatingWinding) {
    const int lengths[] = {4};
    Ref<TriangleStripArray> strip = new TriangleStripArray(0, lengths);
    // Strip 0 1 2 3: (0 1 2) and the odd triangle (1 2 3) with its last two
    // indices swapped so that both wind the same way: (1 3 2).
    EXPECT_EQ(triangleList(*strip, false), (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2}));
    // Flipped (WINDING_CW / CULL_FRONT): second and third index swapped.
    EXPECT_EQ(triangleList(*strip, true), (std::vector<std::uint32_t>{0, 2, 1, 1, 2, 3}));
}

TEST(GltfGeometry, PositionsAndTexCoordsGetScaleAndBias) {
    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<VertexArray> pos = new VertexArray(2, 3, 2);
    const std::int16_t p[] = {1, 2, 3, -4, 0, 10};
    pos->set(0, 2, p);
    const float bias[] = {1.0f, 2.0f, 3.0f};
    vb->setPositions(pos, 0.5f, bias);
    // 0.5 * (1, 2, 3) + (1, 2, 3) and 0.5 * (-4, 0, 10) + (1, 2, 3).
    EXPECT_EQ(positions(*vb), (std::vector<float>{1.5f, 3.0f, 4.5f, -1.0f, 2.0f, 8.0f}));

    Ref<VertexArray> tex = new VertexArray(2, 2, 1);
    const std::int8_t t[] = {10, 20, -10, 0};
    tex->set(0, 2, t);
    const float tbias[] = {0.5f, 0.25f, 0.0f};
    vb->setTexCoords(0, tex, 0.1f, tbias);
    Transform identity;
    const auto uv = texCoords(*vb, 0, identity);
    ASSERT_EQ(uv.size(), 4u);
    EXPECT_NEAR(uv[0], 1.5f, kEps);   // 0.1 * 10 + 0.5
    EXPECT_NEAR(uv[1], 2.25f, kEps);  // 0.1 * 20 + 0.25
    EXPECT_NEAR(uv[2], -0.5f, kEps);
    EXPECT_NEAR(uv[3], 0.25f, kEps);
    // A texture transform is applied after scale and bias: s' = 2 s + 1.
    Transform m;
    m.postTranslate(1.0f, 0.0f, 0.0f);
    m.postScale(2.0f, 1.0f, 1.0f);
    const auto uv2 = texCoords(*vb, 0, m);
    EXPECT_NEAR(uv2[0], 4.0f, kEps);
    EXPECT_NEAR(uv2[1], 2.25f, kEps);
}

TEST(GltfGeometry, NormalsUseTheGlMappingAndAreUnitLength) {
    Ref<VertexArray> n = new VertexArray(2, 3, 1);
    const std::int8_t v[] = {127, 0, 0, 0, 0, 0};
    n->set(0, 2, v);
    int degenerate = -1;
    const auto out = normals(*n, degenerate);
    // (2*127+1)/255 = 1 and (2*0+1)/255 on y and z, normalised.
    const double len = std::sqrt(1.0 + 2.0 / (255.0 * 255.0));
    EXPECT_NEAR(out[0], 1.0 / len, 1e-6);
    EXPECT_NEAR(out[1], (1.0 / 255.0) / len, 1e-6);
    // (1,1,1)/255 is not zero: it normalises to the diagonal.
    EXPECT_NEAR(out[3], 1.0 / std::sqrt(3.0), 1e-6);
    EXPECT_EQ(degenerate, 0);
}

TEST(GltfTransform, QuaternionOfAKnownRotation) {
    // 90 degrees about z: rows (0 -1 0) (1 0 0) (0 0 1) -> (0, 0, sin 45, cos 45).
    const auto q = quaternionFromRotation({0, -1, 0, 1, 0, 0, 0, 0, 1});
    EXPECT_NEAR(q[0], 0.0f, kEps);
    EXPECT_NEAR(q[1], 0.0f, kEps);
    EXPECT_NEAR(q[2], std::sqrt(0.5f), kEps);
    EXPECT_NEAR(q[3], std::sqrt(0.5f), kEps);
    // 180 degrees about x (trace -1 branch): (1, 0, 0, 0).
    const auto h = quaternionFromRotation({1, 0, 0, 0, -1, 0, 0, 0, -1});
    EXPECT_NEAR(std::abs(h[0]), 1.0f, kEps);
    EXPECT_NEAR(h[3], 0.0f, kEps);
}

TEST(GltfTransform, RotationTimesScaleIsOneMatrixShearIsAnExactChain) {
    Transform rs;
    rs.postTranslate(1, 2, 3);
    rs.postRotate(30, 0, 1, 0);
    rs.postScale(2, 3, 4);
    const MatrixNodes a = matrixNodes(rs);
    ASSERT_TRUE(a.asMatrix);
    EXPECT_FALSE(a.projectiveDropped);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(a.columnMajor[c * 4 + r], rs.at(r, c), kEps);

    // Shear x += 0.5 y with a translation: T R(U) S(Σ) R(Vᵀ) must give it back.
    Transform shear;
    const float rows[16] = {1, 0.5f, 0, 4, 0, 1, 0, 5, 0, 0, 1, 6, 0, 0, 0, 1};
    shear.set(rows);
    const MatrixNodes b = matrixNodes(shear);
    ASSERT_FALSE(b.asMatrix);
    ASSERT_EQ(b.chain.size(), 3u);
    Transform product;
    for (const Trs& n : b.chain) {
        product.postTranslate(n.t[0], n.t[1], n.t[2]);
        product.postRotateQuat(n.r[0], n.r[1], n.r[2], n.r[3]);
        product.postScale(n.s[0], n.s[1], n.s[2]);
    }
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(product.at(r, c), shear.at(r, c), 1e-4f) << r << "," << c;
}

TEST(GltfAnimation, KeyframeTimesFollowTheControllerInSeconds) {
    auto seq = scalarSequence(KeyframeSequence::LINEAR, {{0, 0.0f}, {1000, 10.0f}}, 1000);
    // Speed 2: sequence time 1000 is reached at world time 500 ms = 0.5 s.
    TimeMapping fast;
    fast.speed = 2.0;
    EXPECT_DOUBLE_EQ(channelEnd(*seq, fast), 500.0);
    SamplerKeys k = convertSequence(*seq, fast, 500.0, false);
    EXPECT_EQ(k.interpolation, "LINEAR");
    EXPECT_EQ(k.times, (std::vector<float>{0.0f, 0.5f}));
    EXPECT_EQ(k.values, (std::vector<float>{0.0f, 10.0f}));

    // Reference point (world 100 ms, sequence 0), speed 0.5: key 0 at world
    // 100 ms, key 1 at 100 + 1000 / 0.5 = 2100 ms; world 0 is before the
    // first key (value held at 0).
    TimeMapping slow;
    slow.refWorldTime = 100.0;
    slow.speed = 0.5;
    EXPECT_DOUBLE_EQ(channelEnd(*seq, slow), 2100.0);
    k = convertSequence(*seq, slow, 2100.0, false);
    EXPECT_EQ(k.times, (std::vector<float>{0.0f, 0.1f, 2.1f}));
    EXPECT_EQ(k.values, (std::vector<float>{0.0f, 0.0f, 10.0f}));
}

TEST(GltfAnimation, LoopingSequenceIsRepeatedOverTheClip) {
    // Period 1000 ms; a 2500 ms clip needs keys at 0, 500, 1000, ..., 2500.
    auto seq = scalarSequence(KeyframeSequence::LINEAR, {{0, 0.0f}, {500, 1.0f}}, 1000, KeyframeSequence::LOOP);
    TimeMapping m;
    EXPECT_DOUBLE_EQ(channelEnd(*seq, m), 1000.0);
    const SamplerKeys k = convertSequence(*seq, m, 2500.0, false);
    EXPECT_EQ(k.times, (std::vector<float>{0.0f, 0.5f, 1.0f, 1.5f, 2.0f, 2.5f}));
    EXPECT_EQ(k.values, (std::vector<float>{0.0f, 1.0f, 0.0f, 1.0f, 0.0f, 1.0f}));
}

TEST(GltfAnimation, SplineTangentsBecomeValuePerSecond) {
    // Keys (0 ms, 0) (1000 ms, 10) (3000 ms, 40), CONSTANT. M3G tangents at
    // key 1 (JSR-184 1.1, KeyframeSequence: SPLINE): central difference (40 - 0) / 2 = 20 scaled
    // by F- = 2 * 1000 / 3000 (in) and F+ = 2 * 2000 / 3000 (out): 13.33 over
    // the 1 s segment and 26.67 over the 2 s segment, both 40/3 per second.
    // The end keys of a CONSTANT sequence have zero tangents.
    auto seq = scalarSequence(KeyframeSequence::SPLINE, {{0, 0.0f}, {1000, 10.0f}, {3000, 40.0f}}, 3000);
    const SamplerKeys k = convertSequence(*seq, TimeMapping{}, 3000.0, false);
    EXPECT_EQ(k.interpolation, "CUBICSPLINE");
    EXPECT_EQ(k.times, (std::vector<float>{0.0f, 1.0f, 3.0f}));
    ASSERT_EQ(k.values.size(), 9u);  // (in, value, out) per key
    EXPECT_NEAR(k.values[1], 0.0f, kEps);
    EXPECT_NEAR(k.values[2], 0.0f, kEps);       // out-tangent of key 0
    EXPECT_NEAR(k.values[3], 40.0f / 3, 1e-4);  // in-tangent of key 1
    EXPECT_NEAR(k.values[4], 10.0f, kEps);
    EXPECT_NEAR(k.values[5], 40.0f / 3, 1e-4);  // out-tangent of key 1
    EXPECT_NEAR(k.values[6], 0.0f, kEps);       // in-tangent of key 2
    EXPECT_NEAR(k.values[7], 40.0f, kEps);

    // The glTF curve (Appendix C) equals M3G's in the middle of segment 1:
    // p(0.5) = (p0 + p1) / 2 + td * (b0 - a1) / 8 with td = 2 s.
    const double gltf = 0.5 * (10.0 + 40.0) + 2.0 * (k.values[5] - k.values[6]) / 8.0;
    // M3G's own value there, through a TRANSLATION track (x = the curve).
    Ref<Group> g = new Group();
    Ref<AnimationController> c = new AnimationController();
    Ref<KeyframeSequence> seq3 = new KeyframeSequence(3, 3, KeyframeSequence::SPLINE);
    const float v0[] = {0, 0, 0}, v1[] = {10, 0, 0}, v2[] = {40, 0, 0};
    seq3->setKeyframe(0, 0, v0);
    seq3->setKeyframe(1, 1000, v1);
    seq3->setKeyframe(2, 3000, v2);
    seq3->setDuration(3000);
    Ref<AnimationTrack> t3 = new AnimationTrack(seq3, AnimationTrack::TRANSLATION);
    t3->setController(c);
    g->addAnimationTrack(t3);
    g->animate(2000);
    float xyz[3];
    g->getTranslation(xyz);
    EXPECT_NEAR(gltf, xyz[0], 1e-3);
    EXPECT_NEAR(gltf, 25.0 + 10.0 / 3.0, 1e-3);  // (10 + 40) / 2 + 26.67 / 8
}

TEST(GltfAnimation, SlerpOverHalfATurnIsSplitSoGltfTakesTheSameArc) {
    // Identity to 270 degrees about z: the quaternions' dot product is
    // negative, so glTF's short-arc slerp would turn -90 degrees; M3G (Nokia)
    // turns +270. A key in the middle (135 degrees) makes both agree.
    Ref<KeyframeSequence> s = new KeyframeSequence(2, 4, KeyframeSequence::SLERP);
    const float q0[] = {0, 0, 0, 1};
    const float half = static_cast<float>(135.0 * std::numbers::pi / 180.0);
    const float q1[] = {0, 0, std::sin(half), std::cos(half)};
    s->setKeyframe(0, 0, q0);
    s->setKeyframe(1, 1000, q1);
    s->setDuration(1000);
    const SamplerKeys k = convertSequence(*s, TimeMapping{}, 1000.0, true);
    EXPECT_EQ(k.interpolation, "LINEAR");
    ASSERT_EQ(k.times, (std::vector<float>{0.0f, 0.5f, 1.0f}));
    const float quarter = static_cast<float>(67.5 * std::numbers::pi / 180.0);
    EXPECT_NEAR(k.values[6], std::sin(quarter), 1e-5);
    EXPECT_NEAR(k.values[7], std::cos(quarter), 1e-5);
    for (int i = 0; i + 1 < 3; ++i) {
        double dot = 0;
        for (int c = 0; c < 4; ++c) dot += double(k.values[i * 4 + c]) * k.values[(i + 1) * 4 + c];
        EXPECT_GE(dot, 0.0);
    }
}

TEST(GltfAnimation, StepAndSquad) {
    auto step = scalarSequence(KeyframeSequence::STEP, {{0, 1.0f}, {400, 2.0f}}, 1000);
    const SamplerKeys k = convertSequence(*step, TimeMapping{}, 400.0, false);
    EXPECT_EQ(k.interpolation, "STEP");
    EXPECT_EQ(k.times, (std::vector<float>{0.0f, 0.4f}));
    EXPECT_EQ(k.values, (std::vector<float>{1.0f, 2.0f}));

    Ref<KeyframeSequence> squad = new KeyframeSequence(2, 4, KeyframeSequence::SQUAD);
    const float q0[] = {0, 0, 0, 1}, q1[] = {0, std::sqrt(0.5f), 0, std::sqrt(0.5f)};
    squad->setKeyframe(0, 0, q0);
    squad->setKeyframe(1, 800, q1);
    squad->setDuration(800);
    const SamplerKeys r = convertSequence(*squad, TimeMapping{}, 800.0, true);
    EXPECT_EQ(r.interpolation, "LINEAR");
    EXPECT_EQ(r.times.size(), static_cast<std::size_t>(kResamplesPerSegment + 1));
    EXPECT_NEAR(r.times[1], 0.1f, kEps);
    for (std::size_t i = 0; i < r.times.size(); ++i) {
        const float* q = &r.values[i * 4];
        EXPECT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0f, 1e-5);
    }
}

TEST(GltfExport, SceneNodesMaterialsAndGlbContainer) {
    Ref<World> world = new World();
    Ref<Group> group = new Group();
    group->setOrientation(90, 0, 0, 1);
    group->setTranslation(1, 2, 3);
    world->addChild(group);

    const int lengths[] = {4};
    Ref<TriangleStripArray> strip = new TriangleStripArray(0, lengths);
    Ref<Appearance> ap = new Appearance();
    Ref<Material> mat = new Material();
    mat->setColor(Material::DIFFUSE, static_cast<int>(0x80FF0000u));
    ap->setMaterial(mat);
    Ref<CompositingMode> cm = new CompositingMode();
    cm->setBlending(CompositingMode::ALPHA);
    ap->setCompositingMode(cm);
    Ref<PolygonMode> pm = new PolygonMode();
    pm->setCulling(PolygonMode::CULL_NONE);
    ap->setPolygonMode(pm);
    Ref<Mesh> lit = new Mesh(quadBuffer(), strip, ap);
    group->addChild(lit);

    Ref<Appearance> unlitAp = new Appearance();
    Ref<CompositingMode> masked = new CompositingMode();
    masked->setAlphaThreshold(0.5f);
    unlitAp->setCompositingMode(masked);
    Ref<Mesh> unlit = new Mesh(quadBuffer(), strip, unlitAp);
    world->addChild(unlit);

    Object3D* roots[] = {world.get()};
    const ExportResult result = exportScene(roots);
    const auto glb = result.document.toGlb();
    // GLB header: magic "glTF", version 2, total length; chunks 4-aligned.
    ASSERT_GE(glb.size(), 28u);
    EXPECT_EQ(std::memcmp(glb.data(), "glTF", 4), 0);
    std::uint32_t version = 0, length = 0, jsonLength = 0;
    std::memcpy(&version, glb.data() + 4, 4);
    std::memcpy(&length, glb.data() + 8, 4);
    std::memcpy(&jsonLength, glb.data() + 12, 4);
    EXPECT_EQ(version, 2u);
    EXPECT_EQ(length, glb.size());
    EXPECT_EQ(jsonLength % 4, 0u);

    const Json j = glbJson(glb);
    ASSERT_EQ(j["scenes"].size(), 1u);
    ASSERT_EQ(j["scenes"][0]["nodes"].size(), 2u);  // the World's children
    const Json& g = j["nodes"][j["scenes"][0]["nodes"][0].get<int>()];
    EXPECT_EQ(g["translation"], Json({1.0, 2.0, 3.0}));
    EXPECT_NEAR(g["rotation"][2].get<double>(), std::sqrt(0.5), 1e-6);
    EXPECT_NEAR(g["rotation"][3].get<double>(), std::sqrt(0.5), 1e-6);
    ASSERT_EQ(g["children"].size(), 1u);

    const Json& litNode = j["nodes"][g["children"][0].get<int>()];
    const Json& prim = j["meshes"][litNode["mesh"].get<int>()]["primitives"][0];
    const Json& litMat = j["materials"][prim["material"].get<int>()];
    EXPECT_EQ(litMat["alphaMode"], "BLEND");
    EXPECT_EQ(litMat["doubleSided"], true);
    EXPECT_NEAR(litMat["pbrMetallicRoughness"]["baseColorFactor"][0].get<double>(), 1.0, 1e-9);
    EXPECT_NEAR(litMat["pbrMetallicRoughness"]["baseColorFactor"][3].get<double>(), 128.0 / 255.0, 1e-9);
    EXPECT_FALSE(litMat.contains("extensions"));
    EXPECT_EQ(j["accessors"][prim["indices"].get<int>()]["count"], 6);
    const Json& pos = j["accessors"][prim["attributes"]["POSITION"].get<int>()];
    EXPECT_EQ(pos["max"], Json({2.0, 2.0, 0.0}));

    const Json& unlitNode = j["nodes"][j["scenes"][0]["nodes"][1].get<int>()];
    const Json& unlitMat = j["materials"][j["meshes"][unlitNode["mesh"].get<int>()]["primitives"][0]["material"].get<int>()];
    EXPECT_TRUE(unlitMat["extensions"].contains("KHR_materials_unlit"));
    EXPECT_EQ(unlitMat["alphaMode"], "MASK");
    EXPECT_NEAR(unlitMat["alphaCutoff"].get<double>(), 0.5, 1e-9);
    // Lighting off, no colour array: the default colour (white) is the base colour.
    EXPECT_EQ(unlitMat["pbrMetallicRoughness"]["baseColorFactor"], Json({1.0, 1.0, 1.0, 1.0}));
}

TEST(GltfExport, NodeNamesAreUnique) {
    // Three Groups without user ids and one with id 7: every node name ends
    // up different, the first of each name kept as it was.
    Ref<World> world = new World();
    for (int i = 0; i < 3; ++i) world->addChild(new Group());
    Ref<Group> seven = new Group();
    seven->setUserID(7);
    world->addChild(seven);
    Object3D* roots[] = {world.get()};
    const Json j = glbJson(exportScene(roots).document.toGlb());
    std::vector<std::string> names;
    for (const Json& n : j["nodes"]) names.push_back(n["name"].get<std::string>());
    EXPECT_EQ(std::count(names.begin(), names.end(), "Group"), 1);
    EXPECT_EQ(std::count(names.begin(), names.end(), "Group #2"), 1);
    EXPECT_EQ(std::count(names.begin(), names.end(), "Group #3"), 1);
    EXPECT_EQ(std::count(names.begin(), names.end(), "Group 7"), 1);
    std::sort(names.begin(), names.end());
    EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end()) << "a repeated name";
}

TEST(GltfExport, SkinJointsWeightsAndInverseBindMatrices) {
    Ref<Group> skeleton = new Group();
    Ref<Group> bone = new Group();
    bone->setTranslation(1, 0, 0);
    skeleton->addChild(bone);
    Ref<VertexBuffer> vb = quadBuffer();
    const int lengths[] = {4};
    Ref<TriangleStripArray> strip = new TriangleStripArray(0, lengths);
    Ref<Appearance> ap = new Appearance();
    Ref<SkinnedMesh> mesh = new SkinnedMesh(vb, strip, ap, skeleton);
    mesh->addTransform(bone, 1, 0, 3);  // vertex 3 has no bone

    const SkinAttributes s = skinAttributes(*mesh, 4, 1);
    EXPECT_EQ(s.sets, 1);
    EXPECT_TRUE(s.usesRestJoint);
    EXPECT_EQ(s.joints[0], 0);
    EXPECT_FLOAT_EQ(s.weights[0], 1.0f);
    EXPECT_EQ(s.joints[12], 1);  // vertex 3 -> the rest joint
    EXPECT_FLOAT_EQ(s.weights[12], 1.0f);
    EXPECT_FLOAT_EQ(s.weights[13], 0.0f);

    Ref<World> world = new World();
    world->addChild(mesh);
    Object3D* roots[] = {world.get()};
    const Json j = glbJson(exportScene(roots).document.toGlb());
    ASSERT_EQ(j["skins"].size(), 1u);
    EXPECT_EQ(j["skins"][0]["joints"].size(), 2u);  // the bone and the rest joint
    // The inverse bind matrix of the bone is its at-rest matrix: translate(-1, 0, 0).
    Transform atRest;
    mesh->getBoneTransform(bone, &atRest);
    EXPECT_FLOAT_EQ(atRest.at(0, 3), -1.0f);
}

TEST(GltfExport, SkinnedMeshWithAMatrixIsPutOnAChildWithoutOne) {
    // A SkinnedMesh whose node transform is a general matrix (no T, R or S)
    // is exported as a matrix node; the mesh and skin then go on a child, as
    // no glTF node may have both a skin and a matrix.
    Ref<Group> skeleton = new Group();
    Ref<Group> bone = new Group();
    skeleton->addChild(bone);
    const int lengths[] = {4};
    Ref<SkinnedMesh> mesh = new SkinnedMesh(quadBuffer(), new TriangleStripArray(0, lengths), new Appearance(), skeleton);
    mesh->addTransform(bone, 1, 0, 4);
    Transform m;
    m.postTranslate(2, 3, 4);
    mesh->setTransform(&m);
    Ref<World> world = new World();
    world->addChild(mesh);
    Object3D* roots[] = {world.get()};
    const Json j = glbJson(exportScene(roots).document.toGlb());
    int skinned = 0;
    for (const Json& n : j["nodes"]) {
        if (!n.contains("skin")) continue;
        ++skinned;
        EXPECT_FALSE(n.contains("matrix")) << n.dump();
        EXPECT_TRUE(n.contains("mesh"));
    }
    EXPECT_EQ(skinned, 1);
    // The matrix stays on the mesh's own node, the parent of the skinned one.
    bool parentHasMatrix = false;
    for (const Json& n : j["nodes"])
        if (n.contains("matrix") && n.contains("children"))
            for (const Json& c : n["children"]) parentHasMatrix |= j["nodes"][c.get<int>()].contains("skin");
    EXPECT_TRUE(parentHasMatrix);
}

TEST(GltfExport, PalettedImageBecomesAnRgbPng) {
    const std::uint8_t indices[] = {0, 1, 1, 0};
    const std::uint8_t palette[] = {255, 0, 0, 0, 0, 255};
    Ref<Image2D> image = new Image2D(Image2D::RGB, 2, 2, indices, palette);
    Object3D* roots[] = {image.get()};
    const ExportResult result = exportScene(roots);
    const Json& j = result.document.json();
    ASSERT_EQ(j["images"].size(), 1u);
    const Json& view = j["bufferViews"][j["images"][0]["bufferView"].get<int>()];
    const auto& bin = result.document.binary();
    const std::size_t offset = view["byteOffset"], size = view["byteLength"];
    png_image img{};
    img.version = PNG_IMAGE_VERSION;
    ASSERT_TRUE(png_image_begin_read_from_memory(&img, bin.data() + offset, size));
    img.format = PNG_FORMAT_RGB;
    std::vector<std::uint8_t> px(PNG_IMAGE_SIZE(img));
    ASSERT_TRUE(png_image_finish_read(&img, nullptr, px.data(), 0, nullptr));
    EXPECT_EQ(px, (std::vector<std::uint8_t>{255, 0, 0, 0, 0, 255, 0, 0, 255, 255, 0, 0}));
}

TEST(GltfDocument, Base64AndDataUri) {
    const std::uint8_t bytes[] = {'M', 'a', 'n'};
    EXPECT_EQ(base64(bytes), "TWFu");
    EXPECT_EQ(base64(std::span<const std::uint8_t>(bytes, 2)), "TWE=");
    EXPECT_EQ(base64(std::span<const std::uint8_t>(bytes, 1)), "TQ==");
    Document d;
    const float v[] = {1, 2, 3};
    d.addFloatAccessor(v, "VEC3", ViewTarget::ArrayBuffer, true);
    const Json j = Json::parse(d.toGltf(""));
    EXPECT_EQ(j["buffers"][0]["byteLength"], 12);
    EXPECT_EQ(j["buffers"][0]["uri"].get<std::string>().rfind("data:application/octet-stream;base64,", 0), 0u);
}
