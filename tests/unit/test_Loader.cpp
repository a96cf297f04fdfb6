// Loader over hand-made files: every object type and encoding, loaded values
// checked field by field against what was written (JSR-184 1.1 file format,
// section "Per-Class Data", and §8; JSR-184 1.1, Loader).
#include <gtest/gtest.h>

#include <any>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>

#include <png.h>

#include <m3g/AnimationController.h>
#include <m3g/AnimationTrack.h>
#include <m3g/Appearance.h>
#include <m3g/Background.h>
#include <m3g/Camera.h>
#include <m3g/CompositingMode.h>
#include <m3g/Exception.h>
#include <m3g/Fog.h>
#include <m3g/Group.h>
#include <m3g/Image2D.h>
#include <m3g/KeyframeSequence.h>
#include <m3g/Light.h>
#include <m3g/Loader.h>
#include <m3g/Material.h>
#include <m3g/Mesh.h>
#include <m3g/MorphingMesh.h>
#include <m3g/PolygonMode.h>
#include <m3g/SkinnedMesh.h>
#include <m3g/Sprite3D.h>
#include <m3g/Texture2D.h>
#include <m3g/Transform.h>
#include <m3g/TriangleStripArray.h>
#include <m3g/VertexArray.h>
#include <m3g/VertexBuffer.h>
#include <m3g/World.h>

#include "JpegTestBytes.h"
#include "LoaderTestObjects.h"

using namespace m3g;
using namespace m3gtest;

namespace {

template <class T>
Ref<T> at(const LoadResult& r, std::size_t i) {
    EXPECT_LT(i, r.objects.size());
    if (i >= r.objects.size()) return nullptr;
    Ref<T> p = dynamicCast<T>(r.objects[i]);
    EXPECT_TRUE(p) << "object " << i << " is a " << r.objects[i]->getClassName();
    return p;
}

/// Loading must fail with an IOException whose message contains every part.
void expectLoadError(const std::vector<Bytes>& objects, const std::vector<std::string>& parts, bool lenient = false) {
    try {
        loadObjects(objects, lenient);
        ADD_FAILURE() << "load succeeded";
    } catch (const IOException& e) {
        const std::string m = e.what();
        for (const auto& p : parts) EXPECT_NE(m.find(p), std::string::npos) << "'" << p << "' not in: " << m;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not an IOException: " << e.what();
    }
}

}  // namespace

// ---- header, roots, objects -------------------------------------------------

TEST(Loader, HeaderFieldsAndRoots) {
    // 2: Group (root), 3: Group (child of 5), 4: Material (root), 5: Group(3) (root)
    O mat;
    mat.obj3d(44).rgb(1, 2, 3).rgba(4, 5, 6, 7).rgb(8, 9, 10).rgb(11, 12, 13).f32(5).boolean(true);
    const auto r = loadObjects({group({}, 11), group({}, 22), mat.as(13), group({3}, 33)});
    EXPECT_EQ(r.versionMajor, 1);
    EXPECT_EQ(r.versionMinor, 0);
    EXPECT_FALSE(r.hasExternalReferences);
    EXPECT_EQ(r.approximateContentSize, 1234u);
    EXPECT_EQ(r.authoringField, "m3g-vk test");
    EXPECT_GT(r.totalFileSize, 12u);
    ASSERT_EQ(r.objects.size(), 4u);
    ASSERT_EQ(r.roots.size(), 3u);
    EXPECT_EQ(r.roots[0]->getUserID(), 11);
    EXPECT_EQ(r.roots[1]->getUserID(), 44);
    EXPECT_EQ(r.roots[2]->getUserID(), 33);
    EXPECT_TRUE(r.warnings.empty());
    const Bytes file = sceneFile({group({}, 11), group({}, 22), mat.as(13), group({3}, 33)});
    const auto roots = Loader::load(std::span<const std::uint8_t>(file), 0);
    ASSERT_EQ(roots.size(), 3u);
    EXPECT_EQ(roots[2]->getUserID(), 33);
}

TEST(Loader, CompressedSectionsLoad) {
    const auto r = loadObjects({group({}, 5), group({2}, 6)}, false, 1);
    ASSERT_EQ(r.roots.size(), 1u);
    EXPECT_EQ(r.roots[0]->getUserID(), 6);
}

TEST(Loader, JavaEntryPointArgumentChecks) {
    const Bytes file = sceneFile({group({})});
    EXPECT_THROW(Loader::load(std::span<const std::uint8_t>(), 0), NullPointerException);
    EXPECT_THROW(Loader::load(std::span<const std::uint8_t>(file), -1), IndexOutOfBoundsException);
    EXPECT_THROW(Loader::load(std::span<const std::uint8_t>(file), int(file.size())), IndexOutOfBoundsException);
    EXPECT_THROW(Loader::load(std::string()), NullPointerException);
    // An embedded file at an offset, with trailing bytes after TotalFileSize.
    Bytes container = {1, 2, 3};
    container.insert(container.end(), file.begin(), file.end());
    container.push_back(0xEE);
    EXPECT_EQ(Loader::load(std::span<const std::uint8_t>(container), 3).size(), 1u);
}

TEST(Loader, NonM3GInputsAreNamed) {
    // The start of a JPEG file goes to the JPEG decoder, which finds it cut short.
    const Bytes jpeg = {0xFF, 0xD8, 0xFF, 0xE0, 0, 16, 'J', 'F', 'I', 'F', 0};
    try {
        Loader::load(std::span<const std::uint8_t>(jpeg), 0);
        ADD_FAILURE();
    } catch (const IOException& e) {
        EXPECT_NE(std::string(e.what()).find("JPEG image: invalid JPEG: "), std::string::npos) << e.what();
    }
    const Bytes mascot = {'M', 'B', 5, 0, 1, 2, 1, 1, 10, 0};
    try {
        Loader::load(std::span<const std::uint8_t>(mascot), 0);
        ADD_FAILURE();
    } catch (const IOException& e) {
        EXPECT_NE(std::string(e.what()).find("Mascot Capsule"), std::string::npos) << e.what();
    }
    EXPECT_THROW(Loader::load("/nonexistent/dir/file.m3g"), IOException);
}

// ---- inherited blocks ------------------------------------------------------

TEST(Loader, Object3DBlockUserParameters) {
    O g;
    g.obj3d(0x12345678, {}, {{7, {1, 2, 3}}, {0xFFFFFFFFu, {}}, {9, {42}}}).noTransform().nodeDefaults().refs({});
    const auto r = loadObjects({g.as(9)});
    auto grp = at<Group>(r, 0);
    EXPECT_EQ(grp->getUserID(), 0x12345678);
    const auto* params = std::any_cast<std::shared_ptr<const UserParameters>>(&grp->getUserObject());
    ASSERT_NE(params, nullptr);
    ASSERT_EQ((*params)->size(), 3u);
    EXPECT_EQ((*params)->at(7), (std::vector<std::uint8_t>{1, 2, 3}));
    EXPECT_TRUE((*params)->at(-1).empty());
    EXPECT_EQ((*params)->at(9), (std::vector<std::uint8_t>{42}));
    // No parameters: no user object.
    EXPECT_FALSE(at<Group>(loadObjects({group({})}), 0)->getUserObject().has_value());
}

TEST(Loader, DuplicateUserParameterIdIsAnError) {
    O g;
    g.obj3d(0, {}, {{7, {1}}, {7, {2}}}).noTransform().nodeDefaults().refs({});
    expectLoadError({g.as(9)}, {"section 1", "object 2", "Group", "duplicate user parameter ID 7", "byte offset"});
}

TEST(Loader, TransformableAndNodeBlocks) {
    O g;
    g.obj3d(1).boolean(true).vec3(1, 2, 3).vec3(2, 2, 2).f32(90).vec3(0, 0, 1);
    g.boolean(true);
    const float m[16] = {1, 0, 0, 5, 0, 1, 0, 6, 0, 0, 1, 7, 0, 0, 0, 1};
    for (float x : m) g.f32(x);
    g.boolean(false).boolean(true).u8(51).u32(0x0F).boolean(false).refs({});
    const auto r = loadObjects({g.as(9)});
    auto grp = at<Group>(r, 0);
    float t[3], s[3], o[4];
    grp->getTranslation(t);
    grp->getScale(s);
    grp->getOrientation(o);
    EXPECT_FLOAT_EQ(t[0], 1);
    EXPECT_FLOAT_EQ(t[2], 3);
    EXPECT_FLOAT_EQ(s[1], 2);
    EXPECT_NEAR(o[0], 90, 1e-3);
    EXPECT_NEAR(o[3], 1, 1e-5);
    Transform tr;
    grp->getTransform(&tr);
    EXPECT_FLOAT_EQ(tr.at(0, 3), 5);
    EXPECT_FLOAT_EQ(tr.at(2, 3), 7);
    EXPECT_FALSE(grp->isRenderingEnabled());
    EXPECT_TRUE(grp->isPickingEnabled());
    EXPECT_NEAR(grp->getAlphaFactor(), 51 / 255.0f, 1e-6);
    EXPECT_EQ(grp->getScope(), 0x0F);
}

TEST(Loader, NodeAlignment) {
    O n;
    n.obj3d().noTransform().boolean(true).boolean(true).u8(255).u32(1).boolean(true);
    n.u8(Node::ORIGIN).u8(Node::Z_AXIS).ref(2).ref(0).refs({});
    const auto r = loadObjects({group({}, 1), n.as(9), group({2, 3})});
    auto ref = at<Group>(r, 0);
    auto g = at<Group>(r, 1);
    EXPECT_EQ(g->getAlignmentTarget(Node::Z_AXIS), Node::ORIGIN);
    EXPECT_EQ(g->getAlignmentTarget(Node::Y_AXIS), Node::Z_AXIS);
    EXPECT_EQ(g->getAlignmentReference(Node::Z_AXIS), ref);
    EXPECT_FALSE(g->getAlignmentReference(Node::Y_AXIS));
    ASSERT_EQ(r.roots.size(), 1u);  // the alignment reference counts as a reference
}

TEST(Loader, NodeWithNonAffineTransformIsRejected) {
    O g;
    g.obj3d().boolean(false).boolean(true);
    for (int i = 0; i < 16; ++i) g.f32(i == 15 ? 2.0f : (i % 5 == 0 ? 1.0f : 0.0f));
    g.nodeDefaults().refs({});
    expectLoadError({g.as(9)}, {"object 2 (Group, type 9)", "IllegalArgumentException", "byte offset"});
}

// ---- animation -----------------------------------------------------------

TEST(Loader, AnimationControllerLoadOrder) {
    O c;
    c.obj3d(3).f32(2.0f).f32(0.5f).i32(100).i32(900).f32(250.0f).i32(1000);
    const auto r = loadObjects({c.as(1)});
    auto ac = at<AnimationController>(r, 0);
    EXPECT_FLOAT_EQ(ac->getSpeed(), 2.0f);
    EXPECT_FLOAT_EQ(ac->getWeight(), 0.5f);
    EXPECT_EQ(ac->getActiveIntervalStart(), 100);
    EXPECT_EQ(ac->getActiveIntervalEnd(), 900);
    EXPECT_EQ(ac->getRefWorldTime(), 1000);
    EXPECT_FLOAT_EQ(ac->getPosition(1000), 250.0f);
    EXPECT_FLOAT_EQ(ac->getPosition(1100), 450.0f);
}

TEST(Loader, KeyframeSequenceEncodings) {
    // 2: float, 3: 8-bit, 4: 16-bit.
    O f;
    f.obj3d().u8(KeyframeSequence::LINEAR).u8(KeyframeSequence::LOOP).u8(0).u32(1000).u32(0).u32(1).u32(3).u32(2);
    f.i32(0).vec3(1, 2, 3).i32(500).vec3(-4, 5.5f, 6);
    O q8;
    q8.obj3d().u8(KeyframeSequence::STEP).u8(KeyframeSequence::CONSTANT).u8(1).u32(200).u32(1).u32(1).u32(2).u32(2);
    q8.f32(-1).f32(2).f32(10).f32(100);  // bias, scale
    q8.i32(10).u8(0).u8(255).i32(20).u8(51).u8(102);
    O q16;
    q16.obj3d().u8(KeyframeSequence::SPLINE).u8(KeyframeSequence::CONSTANT).u8(2).u32(300).u32(0).u32(0).u32(1).u32(1);
    q16.f32(1).f32(65535);
    q16.i32(7).u16(1234);
    const auto r = loadObjects({f.as(19), q8.as(19), q16.as(19)});
    auto a = at<KeyframeSequence>(r, 0);
    EXPECT_EQ(a->getInterpolationType(), KeyframeSequence::LINEAR);
    EXPECT_EQ(a->getRepeatMode(), KeyframeSequence::LOOP);
    EXPECT_EQ(a->getDuration(), 1000);
    EXPECT_EQ(a->getValidRangeFirst(), 0);
    EXPECT_EQ(a->getValidRangeLast(), 1);
    EXPECT_EQ(a->getComponentCount(), 3);
    EXPECT_EQ(a->getKeyframeCount(), 2);
    float v[3];
    EXPECT_EQ(a->getKeyframe(1, v), 500);
    EXPECT_FLOAT_EQ(v[0], -4);
    EXPECT_FLOAT_EQ(v[1], 5.5f);
    auto b = at<KeyframeSequence>(r, 1);
    EXPECT_EQ(b->getInterpolationType(), KeyframeSequence::STEP);
    EXPECT_EQ(b->getRepeatMode(), KeyframeSequence::CONSTANT);
    EXPECT_EQ(b->getDuration(), 200);
    EXPECT_EQ(b->getValidRangeFirst(), 1);
    EXPECT_EQ(b->getKeyframe(0, v), 10);
    EXPECT_FLOAT_EQ(v[0], -1);
    EXPECT_FLOAT_EQ(v[1], 102);
    EXPECT_EQ(b->getKeyframe(1, v), 20);
    EXPECT_FLOAT_EQ(v[0], -1 + 10 * 51 / 255.0f);
    EXPECT_FLOAT_EQ(v[1], 2 + 100 * 102 / 255.0f);
    auto c = at<KeyframeSequence>(r, 2);
    EXPECT_EQ(c->getKeyframe(0, v), 7);
    EXPECT_FLOAT_EQ(v[0], 1 + 1234);
}

TEST(Loader, KeyframeSequenceRejectedValues) {
    O bad;  // SLERP needs 4 components
    bad.obj3d().u8(KeyframeSequence::SLERP).u8(KeyframeSequence::CONSTANT).u8(0).u32(10).u32(0).u32(0).u32(3).u32(1);
    bad.i32(0).vec3(0, 0, 0);
    expectLoadError({bad.as(19)}, {"KeyframeSequence, type 19", "IllegalArgumentException"});
    O enc;
    enc.obj3d().u8(KeyframeSequence::LINEAR).u8(KeyframeSequence::CONSTANT).u8(3).u32(10).u32(0).u32(0).u32(1).u32(1);
    enc.i32(0).f32(0);
    expectLoadError({enc.as(19)}, {"invalid keyframe encoding 3"});
    O huge;  // counts far larger than the data: no allocation, clean error
    huge.obj3d().u8(KeyframeSequence::LINEAR).u8(KeyframeSequence::CONSTANT).u8(0).u32(10).u32(0).u32(0);
    huge.u32(0x40000000).u32(0x40000000);
    expectLoadError({huge.as(19)}, {"keyframes", "truncated"});
}

TEST(Loader, AnimationTrackAttachedToTarget) {
    O seq;
    seq.obj3d().u8(KeyframeSequence::LINEAR).u8(KeyframeSequence::CONSTANT).u8(0).u32(100).u32(0).u32(0).u32(3).u32(1);
    seq.i32(0).vec3(1, 2, 3);
    O ctrl;
    ctrl.obj3d().f32(1).f32(1).i32(0).i32(0).f32(0).i32(0);
    O track;
    track.obj3d(9).ref(2).ref(3).u32(AnimationTrack::TRANSLATION);
    O g;
    g.obj3d(1, {4}).noTransform().nodeDefaults().refs({});
    const auto r = loadObjects({seq.as(19), ctrl.as(1), track.as(2), g.as(9)});
    auto t = at<AnimationTrack>(r, 2);
    EXPECT_EQ(t->getUserID(), 9);
    EXPECT_EQ(t->getTargetProperty(), AnimationTrack::TRANSLATION);
    EXPECT_EQ(t->getKeyframeSequence(), at<KeyframeSequence>(r, 0));
    EXPECT_EQ(t->getController(), at<AnimationController>(r, 1));
    auto grp = at<Group>(r, 3);
    ASSERT_EQ(grp->getAnimationTrackCount(), 1);
    EXPECT_EQ(grp->getAnimationTrack(0), t);
    ASSERT_EQ(r.roots.size(), 1u);
    EXPECT_EQ(r.roots[0], grp);
    grp->animate(0);
    float tr[3];
    grp->getTranslation(tr);
    EXPECT_FLOAT_EQ(tr[1], 2);

    // A track on a property the class cannot animate (Group has no COLOR).
    O bad;
    bad.obj3d(9).ref(2).ref(3).u32(AnimationTrack::COLOR);
    expectLoadError({seq.as(19), ctrl.as(1), bad.as(2), g.as(9)},
                    {"object 5 (Group, type 9)", "IllegalArgumentException"});
}

// ---- appearance components -------------------------------------------------

TEST(Loader, AppearanceAndComponents) {
    O cm;
    cm.obj3d().boolean(false).boolean(true).boolean(false).boolean(true).u8(CompositingMode::MODULATE_X2).u8(128);
    cm.f32(1.5f).f32(-2.0f);
    O fogE;
    fogE.obj3d().rgb(0x10, 0x20, 0x30).u8(Fog::EXPONENTIAL).f32(0.25f);
    O fogL;
    fogL.obj3d().rgb(1, 2, 3).u8(Fog::LINEAR).f32(5).f32(50);
    O pm;
    pm.obj3d().u8(PolygonMode::CULL_NONE).u8(PolygonMode::SHADE_FLAT).u8(PolygonMode::WINDING_CW);
    pm.boolean(true).boolean(true).boolean(false);
    O mat;
    mat.obj3d().rgb(1, 2, 3).rgba(4, 5, 6, 7).rgb(8, 9, 10).rgb(11, 12, 13).f32(64).boolean(true);
    O tex;
    tex.obj3d().boolean(true).vec3(0.5f, 0, 0).vec3(2, 2, 1).f32(0).vec3(0, 0, 1).boolean(false);
    tex.ref(7).rgb(0xAA, 0xBB, 0xCC).u8(Texture2D::FUNC_ADD).u8(Texture2D::WRAP_CLAMP).u8(Texture2D::WRAP_REPEAT);
    tex.u8(Texture2D::FILTER_NEAREST).u8(Texture2D::FILTER_LINEAR);
    O app;
    app.obj3d().u8(0xFB).ref(2).ref(4).ref(5).ref(6).refs({0, 8});
    // 2 cm, 3 fogE, 4 fogL, 5 pm, 6 mat, 7 image, 8 tex, 9 app
    const auto r = loadObjects({cm.as(6), fogE.as(7), fogL.as(7), pm.as(8), mat.as(13), rgbImage(4, 2), tex.as(17),
                                app.as(3)});
    auto c = at<CompositingMode>(r, 0);
    EXPECT_FALSE(c->isDepthTestEnabled());
    EXPECT_TRUE(c->isDepthWriteEnabled());
    EXPECT_FALSE(c->isColorWriteEnabled());
    EXPECT_TRUE(c->isAlphaWriteEnabled());
    EXPECT_EQ(c->getBlending(), CompositingMode::MODULATE_X2);
    EXPECT_NEAR(c->getAlphaThreshold(), 128 / 255.0f, 1e-6);
    EXPECT_FLOAT_EQ(c->getDepthOffsetFactor(), 1.5f);
    EXPECT_FLOAT_EQ(c->getDepthOffsetUnits(), -2.0f);
    auto fe = at<Fog>(r, 1);
    EXPECT_EQ(fe->getMode(), Fog::EXPONENTIAL);
    EXPECT_EQ(fe->getColor(), 0x102030);
    EXPECT_FLOAT_EQ(fe->getDensity(), 0.25f);
    auto fl = at<Fog>(r, 2);
    EXPECT_EQ(fl->getMode(), Fog::LINEAR);
    EXPECT_FLOAT_EQ(fl->getNearDistance(), 5);
    EXPECT_FLOAT_EQ(fl->getFarDistance(), 50);
    auto p = at<PolygonMode>(r, 3);
    EXPECT_EQ(p->getCulling(), PolygonMode::CULL_NONE);
    EXPECT_EQ(p->getShading(), PolygonMode::SHADE_FLAT);
    EXPECT_EQ(p->getWinding(), PolygonMode::WINDING_CW);
    EXPECT_TRUE(p->isTwoSidedLightingEnabled());
    EXPECT_TRUE(p->isLocalCameraLightingEnabled());
    EXPECT_FALSE(p->isPerspectiveCorrectionEnabled());
    auto m = at<Material>(r, 4);
    EXPECT_EQ(m->getColor(Material::AMBIENT), 0x010203);
    EXPECT_EQ(m->getColor(Material::DIFFUSE), 0x07040506);
    EXPECT_EQ(m->getColor(Material::EMISSIVE), 0x08090A);
    EXPECT_EQ(m->getColor(Material::SPECULAR), 0x0B0C0D);
    EXPECT_FLOAT_EQ(m->getShininess(), 64);
    EXPECT_TRUE(m->isVertexColorTrackingEnabled());
    auto t = at<Texture2D>(r, 6);
    EXPECT_EQ(t->getImage(), at<Image2D>(r, 5));
    EXPECT_EQ(t->getBlendColor(), 0xAABBCC);
    EXPECT_EQ(t->getBlending(), Texture2D::FUNC_ADD);
    EXPECT_EQ(t->getWrappingS(), Texture2D::WRAP_CLAMP);
    EXPECT_EQ(t->getWrappingT(), Texture2D::WRAP_REPEAT);
    EXPECT_EQ(t->getLevelFilter(), Texture2D::FILTER_NEAREST);
    EXPECT_EQ(t->getImageFilter(), Texture2D::FILTER_LINEAR);
    float tt[3];
    t->getTranslation(tt);
    EXPECT_FLOAT_EQ(tt[0], 0.5f);
    auto a = at<Appearance>(r, 7);
    EXPECT_EQ(a->getLayer(), -5);  // signed byte
    EXPECT_EQ(a->getCompositingMode(), c);
    EXPECT_EQ(a->getFog(), fl);
    EXPECT_EQ(a->getPolygonMode(), p);
    EXPECT_EQ(a->getMaterial(), m);
    EXPECT_FALSE(a->getTexture(0));
    EXPECT_EQ(a->getTexture(1), t);
    // Roots: fogE (unreferenced) and the appearance.
    ASSERT_EQ(r.roots.size(), 2u);
    EXPECT_EQ(r.roots[0], fe);
    EXPECT_EQ(r.roots[1], a);
}

TEST(Loader, ComponentSetterRejections) {
    O cm;
    cm.obj3d().boolean(true).boolean(true).boolean(true).boolean(true).u8(99).u8(0).f32(0).f32(0);
    expectLoadError({cm.as(6)}, {"section 1", "object 2", "CompositingMode, type 6", "byte offset",
                                 "IllegalArgumentException", "CompositingMode::setBlending"});
    O fog;
    fog.obj3d().rgb(0, 0, 0).u8(82).f32(1);
    expectLoadError({fog.as(7)}, {"Fog, type 7", "invalid fog mode 82"});
    O pm;
    pm.obj3d().u8(163).u8(PolygonMode::SHADE_FLAT).u8(PolygonMode::WINDING_CW).boolean(true).boolean(true).boolean(true);
    expectLoadError({pm.as(8)}, {"PolygonMode, type 8", "IllegalArgumentException"});
    O app;  // layer 64 is out of range
    app.obj3d().u8(64).ref(0).ref(0).ref(0).ref(0).u32(0);
    expectLoadError({app.as(3)}, {"Appearance, type 3", "IllegalArgumentException"});
    O boolBad;
    boolBad.obj3d().u8(2).boolean(true).boolean(true).boolean(true).u8(64).u8(0).f32(0).f32(0);
    expectLoadError({boolBad.as(6)}, {"CompositingMode, type 6", "byte offset"});
    O mat;  // negative shininess
    mat.obj3d().rgb(1, 2, 3).rgba(4, 5, 6, 7).rgb(8, 9, 10).rgb(11, 12, 13).f32(-1).boolean(true);
    expectLoadError({mat.as(13)}, {"Material, type 13", "IllegalArgumentException"});
}

TEST(Loader, BackgroundFlagsInSpecOrder) {
    O bg;
    bg.obj3d().rgba(0x11, 0x22, 0x33, 0x44).ref(2).u8(Background::REPEAT).u8(Background::BORDER);
    bg.i32(-1).i32(2).i32(30).i32(40);
    bg.boolean(true).boolean(false);  // depthClearEnabled, colorClearEnabled
    const auto r = loadObjects({rgbImage(8, 8), bg.as(4)});
    auto b = at<Background>(r, 1);
    EXPECT_EQ(b->getColor(), 0x44112233);
    EXPECT_EQ(b->getImage(), at<Image2D>(r, 0));
    EXPECT_EQ(b->getImageModeX(), Background::REPEAT);
    EXPECT_EQ(b->getImageModeY(), Background::BORDER);
    EXPECT_EQ(b->getCropX(), -1);
    EXPECT_EQ(b->getCropY(), 2);
    EXPECT_EQ(b->getCropWidth(), 30);
    EXPECT_EQ(b->getCropHeight(), 40);
    EXPECT_TRUE(b->isDepthClearEnabled());
    EXPECT_FALSE(b->isColorClearEnabled());
}

// ---- images ------------------------------------------------------------------

TEST(Loader, Image2DAllFormatsDirectPalettedMutable) {
    std::vector<Bytes> objs;
    const int formats[] = {Image2D::ALPHA, Image2D::LUMINANCE, Image2D::LUMINANCE_ALPHA, Image2D::RGB, Image2D::RGBA};
    for (int f : formats) {  // direct 2 x 1
        const int bpp = Image2D::bytesPerPixel(f);
        O o;
        o.obj3d().u8(std::uint8_t(f)).boolean(false).u32(2).u32(1).u32(0).u32(std::uint32_t(2 * bpp));
        for (int i = 0; i < 2 * bpp; ++i) o.u8(std::uint8_t(10 + i));
        objs.push_back(o.as(10));
    }
    for (int f : formats) {  // paletted 2 x 2, 3-entry palette
        const int bpp = Image2D::bytesPerPixel(f);
        O o;
        o.obj3d().u8(std::uint8_t(f)).boolean(false).u32(2).u32(2).u32(std::uint32_t(3 * bpp));
        for (int i = 0; i < 3 * bpp; ++i) o.u8(std::uint8_t(100 + i));
        o.u32(4).u8(0).u8(1).u8(2).u8(1);
        objs.push_back(o.as(10));
    }
    O mut;
    mut.obj3d().u8(Image2D::RGBA).boolean(true).u32(16).u32(8);
    objs.push_back(mut.as(10));
    const auto r = loadObjects(objs);
    for (int i = 0; i < 5; ++i) {
        auto img = at<Image2D>(r, std::size_t(i));
        const int bpp = Image2D::bytesPerPixel(formats[i]);
        EXPECT_EQ(img->getFormat(), formats[i]);
        EXPECT_FALSE(img->isMutable());
        EXPECT_EQ(img->getWidth(), 2);
        EXPECT_EQ(img->getHeight(), 1);
        ASSERT_EQ(img->pixels().size(), std::size_t(2 * bpp));
        for (int k = 0; k < 2 * bpp; ++k) EXPECT_EQ(img->pixels()[std::size_t(k)], 10 + k);
    }
    for (int i = 0; i < 5; ++i) {
        auto img = at<Image2D>(r, std::size_t(5 + i));
        const int bpp = Image2D::bytesPerPixel(formats[i]);
        EXPECT_EQ(img->getFormat(), formats[i]);
        EXPECT_TRUE(img->isPalettized());
        ASSERT_EQ(img->paletteIndices().size(), 4u);
        EXPECT_EQ(img->paletteIndices()[2], 2);
        ASSERT_GE(img->palette().size(), std::size_t(3 * bpp));
        EXPECT_EQ(img->palette()[std::size_t(bpp)], 100 + bpp);  // entry 1, first byte
    }
    auto m = at<Image2D>(r, 10);
    EXPECT_TRUE(m->isMutable());
    EXPECT_EQ(m->getWidth(), 16);
    EXPECT_EQ(m->getHeight(), 8);
    EXPECT_EQ(m->getFormat(), Image2D::RGBA);
}

TEST(Loader, Image2DSizeErrors) {
    O short_;
    short_.obj3d().u8(Image2D::RGB).boolean(false).u32(2).u32(2).u32(0).u32(11);
    for (int i = 0; i < 11; ++i) short_.u8(0);
    expectLoadError({short_.as(10)}, {"Image2D, type 10", "needs 12 pixel bytes"});
    O fmt;
    fmt.obj3d().u8(101).boolean(true).u32(1).u32(1);
    expectLoadError({fmt.as(10)}, {"invalid image format 101"});
    O huge;
    huge.obj3d().u8(Image2D::RGBA).boolean(true).u32(100000).u32(100000);
    expectLoadError({huge.as(10)}, {"mutable image", "larger than the loader accepts"});
    O pal;  // palette not a multiple of bpp
    pal.obj3d().u8(Image2D::RGB).boolean(false).u32(1).u32(1).u32(4).u32(0).u32(1).u32(1).u8(0);
    expectLoadError({pal.as(10)}, {"palette of 4 bytes"});
}

// ---- geometry ------------------------------------------------------------------

TEST(Loader, VertexArrayPlainAndDeltaEncodings) {
    O d8;  // deltas 100, +100 (wraps to -56), -100
    d8.obj3d().u8(1).u8(2).u8(1).u16(3).u8(100).u8(1).u8(100).u8(1).u8(std::uint8_t(-100)).u8(std::uint8_t(-3));
    O d16;
    d16.obj3d().u8(2).u8(3).u8(1).u16(2).u16(30000).u16(1).u16(std::uint16_t(-5));
    d16.u16(10000).u16(std::uint16_t(-2)).u16(5);  // 30000+10000 wraps to -25536
    const auto r = loadObjects({d8.as(20), d16.as(20), vertexArray16(4, {1, -2, 3, -32768})});
    auto a = at<VertexArray>(r, 0);
    EXPECT_EQ(a->getComponentType(), 1);
    EXPECT_EQ(a->getComponentCount(), 2);
    EXPECT_EQ(a->getVertexCount(), 3);
    std::int8_t v8[6];
    a->get(0, 3, v8);
    EXPECT_EQ(v8[0], 100);
    EXPECT_EQ(v8[1], 1);
    EXPECT_EQ(v8[2], -56);
    EXPECT_EQ(v8[3], 2);
    EXPECT_EQ(v8[4], 100);  // -56 - 100 wraps to 100
    EXPECT_EQ(v8[5], -1);
    auto b = at<VertexArray>(r, 1);
    std::int16_t v16[6];
    b->get(0, 2, v16);
    EXPECT_EQ(v16[0], 30000);
    EXPECT_EQ(v16[1], 1);
    EXPECT_EQ(v16[2], -5);
    EXPECT_EQ(v16[3], -25536);
    EXPECT_EQ(v16[4], -1);
    EXPECT_EQ(v16[5], 0);
    auto c = at<VertexArray>(r, 2);
    std::int16_t p[4];
    c->get(0, 1, p);
    EXPECT_EQ(p[3], -32768);

    O bad;
    bad.obj3d().u8(3).u8(2).u8(0).u16(1).u8(0).u8(0);
    expectLoadError({bad.as(20)}, {"VertexArray, type 20", "invalid componentSize 3"});
    O enc;
    enc.obj3d().u8(1).u8(2).u8(2).u16(1).u8(0).u8(0);
    expectLoadError({enc.as(20)}, {"invalid vertex array encoding 2"});
    O cc;  // 5 components: rejected by the constructor
    cc.obj3d().u8(1).u8(5).u8(0).u16(1).u8(0).u8(0).u8(0).u8(0).u8(0);
    expectLoadError({cc.as(20)}, {"VertexArray, type 20", "IllegalArgumentException"});
}

TEST(Loader, VertexBufferFields) {
    O vb;
    vb.obj3d().rgba(0x10, 0x20, 0x30, 0x40).ref(2).vec3(1, 2, 3).f32(0.5f).ref(3).ref(4).u32(2);
    vb.ref(5).vec3(0.25f, 0.5f, 0).f32(2).ref(0).vec3(0, 0, 0).f32(1);
    const auto r = loadObjects({vertexArray16(3, {0, 0, 0, 1, 1, 1}), vertexArray8(3, {0, 0, 127, 0, 127, 0}),
                                vertexArray8(4, {1, 2, 3, 4, 5, 6, 7, 8}), vertexArray16(2, {0, 0, 1, 1}), vb.as(21)});
    auto v = at<VertexBuffer>(r, 4);
    EXPECT_EQ(v->getDefaultColor(), 0x40102030);
    float sb[4];
    EXPECT_EQ(v->getPositions(sb), at<VertexArray>(r, 0));
    EXPECT_FLOAT_EQ(sb[0], 0.5f);
    EXPECT_FLOAT_EQ(sb[1], 1);
    EXPECT_FLOAT_EQ(sb[3], 3);
    EXPECT_EQ(v->getNormals(), at<VertexArray>(r, 1));
    EXPECT_EQ(v->getColors(), at<VertexArray>(r, 2));
    EXPECT_EQ(v->getTexCoords(0, sb), at<VertexArray>(r, 3));
    EXPECT_FLOAT_EQ(sb[0], 2);
    EXPECT_FLOAT_EQ(sb[1], 0.25f);
    EXPECT_FALSE(v->getTexCoords(1));
    EXPECT_EQ(v->getVertexCount(), 2);
    // Positions with 2 components: rejected by setPositions.
    O bad;
    bad.obj3d().rgba(0, 0, 0, 0).ref(2).vec3(0, 0, 0).f32(1).ref(0).ref(0).u32(0);
    expectLoadError({vertexArray16(2, {0, 0}), bad.as(21)}, {"VertexBuffer, type 21", "IllegalArgumentException"});
}

TEST(Loader, TriangleStripArrayEncodings) {
    O e0, e1, e2, e128, e129, e130;
    e0.obj3d().u8(0).u32(70000 - 69990).refs({3});
    e1.obj3d().u8(1).u8(200).refs({4});
    e2.obj3d().u8(2).u16(60000).refs({3, 3});
    e128.obj3d().u8(128).refs({9, 8, 65535}).refs({3});
    e129.obj3d().u8(129).u32(4).u8(1).u8(2).u8(255).u8(4).refs({4});
    e130.obj3d().u8(130).u32(3).u16(500).u16(40000).u16(7).refs({3});
    const auto r = loadObjects({e0.as(11), e1.as(11), e2.as(11), e128.as(11), e129.as(11), e130.as(11)});
    auto idx = [&](std::size_t i) {
        auto t = at<TriangleStripArray>(r, i);
        return std::vector<int>(t->stripIndices().begin(), t->stripIndices().end());
    };
    auto len = [&](std::size_t i) {
        auto t = at<TriangleStripArray>(r, i);
        return std::vector<int>(t->stripLengths().begin(), t->stripLengths().end());
    };
    EXPECT_EQ(idx(0), (std::vector<int>{10, 11, 12}));
    EXPECT_EQ(idx(1), (std::vector<int>{200, 201, 202, 203}));
    EXPECT_EQ(idx(2), (std::vector<int>{60000, 60001, 60002, 60003, 60004, 60005}));
    EXPECT_EQ(len(2), (std::vector<int>{3, 3}));
    EXPECT_EQ(idx(3), (std::vector<int>{9, 8, 65535}));
    EXPECT_EQ(idx(4), (std::vector<int>{1, 2, 255, 4}));
    EXPECT_EQ(idx(5), (std::vector<int>{500, 40000, 7}));
    EXPECT_EQ(at<TriangleStripArray>(r, 0)->getIndexCount(), 3);

    O enc;
    enc.obj3d().u8(3).u32(0).refs({3});
    expectLoadError({enc.as(11)}, {"TriangleStripArray, type 11", "invalid TriangleStripArray encoding 3"});
    O shortStrip;
    shortStrip.obj3d().u8(0).u32(0).refs({2});
    expectLoadError({shortStrip.as(11)}, {"TriangleStripArray, type 11", "IllegalArgumentException"});
    O range;
    range.obj3d().u8(2).u16(65534).refs({3});
    expectLoadError({range.as(11)}, {"TriangleStripArray, type 11", "IndexOutOfBoundsException"});
}

TEST(Loader, MeshMorphingMeshSkinnedMesh) {
    // 2 positions, 3 vb, 4 tsa, 5 app, 6 mesh, 7 target positions, 8 target vb, 9 morph, 10 bone, 11 skeleton(10),
    // 12 skinned
    O mesh;
    mesh.plainNode(1).ref(3).u32(2).ref(4).ref(5).ref(4).ref(0);
    O morph;
    morph.plainNode(2).ref(3).u32(1).ref(4).ref(5).u32(1).ref(8).f32(0.75f);
    O skin;
    skin.plainNode(3).ref(3).u32(1).ref(4).ref(0).ref(11).u32(1).ref(10).u32(1).u32(2).i32(5);
    const auto r = loadObjects({vertexArray16(3, {0, 0, 0, 1, 0, 0, 0, 1, 0}), vertexBufferWithPositions(2),
                                stripArray(0, {3}), emptyAppearance(), mesh.as(14),
                                vertexArray16(3, {1, 1, 1, 2, 2, 2, 3, 3, 3}), vertexBufferWithPositions(7), morph.as(15),
                                group({}, 10), group({10}, 11), skin.as(16)});
    auto m = at<Mesh>(r, 4);
    EXPECT_EQ(m->getUserID(), 1);
    EXPECT_EQ(m->getVertexBuffer(), at<VertexBuffer>(r, 1));
    ASSERT_EQ(m->getSubmeshCount(), 2);
    EXPECT_EQ(m->getIndexBuffer(0), at<IndexBuffer>(r, 2));
    EXPECT_EQ(m->getAppearance(0), at<Appearance>(r, 3));
    EXPECT_EQ(m->getIndexBuffer(1), at<IndexBuffer>(r, 2));
    EXPECT_FALSE(m->getAppearance(1));
    auto mm = at<MorphingMesh>(r, 7);
    ASSERT_EQ(mm->getMorphTargetCount(), 1);
    EXPECT_EQ(mm->getMorphTarget(0), at<VertexBuffer>(r, 6));
    float w[1];
    mm->getWeights(w);
    EXPECT_FLOAT_EQ(w[0], 0.75f);
    auto sm = at<SkinnedMesh>(r, 10);
    EXPECT_EQ(sm->getSkeleton(), at<Group>(r, 9));
    auto bone = at<Group>(r, 8);
    int vi[4];
    float vw[4];
    ASSERT_EQ(sm->getBoneVertices(bone.get(), vi, vw), 2);
    EXPECT_EQ(vi[0], 1);
    EXPECT_EQ(vi[1], 2);
    EXPECT_FLOAT_EQ(vw[0], 1.0f);
    // Roots: mesh, morph, skinned mesh (the skeleton is referenced).
    ASSERT_EQ(r.roots.size(), 3u);
    EXPECT_EQ(r.roots[0], m);
    EXPECT_EQ(r.roots[1], mm);
    EXPECT_EQ(r.roots[2], sm);

    // A bone outside the skeleton is rejected by addTransform.
    O badSkin;
    badSkin.plainNode(3).ref(3).u32(1).ref(4).ref(0).ref(11).u32(1).ref(12).u32(0).u32(1).i32(1);
    expectLoadError({vertexArray16(3, {0, 0, 0, 1, 0, 0, 0, 1, 0}), vertexBufferWithPositions(2), stripArray(0, {3}),
                     emptyAppearance(), mesh.as(14), vertexArray16(3, {1, 1, 1, 2, 2, 2, 3, 3, 3}),
                     vertexBufferWithPositions(7), morph.as(15), group({}, 10), group({10}, 11), group({}),
                     badSkin.as(16)},
                    {"object 13 (SkinnedMesh, type 16)", "IllegalArgumentException"});
    // A Mesh without index buffers.
    O noSub;
    noSub.plainNode().ref(3).u32(0);
    expectLoadError({vertexArray16(3, {0, 0, 0}), vertexBufferWithPositions(2), noSub.as(14)},
                    {"object 4 (Mesh, type 14)", "IllegalArgumentException"});
}

// ---- nodes ---------------------------------------------------------------------

TEST(Loader, CameraLightSprite) {
    O persp;
    persp.plainNode().u8(Camera::PERSPECTIVE).f32(60).f32(1.5f).f32(0.1f).f32(100);
    O par;
    par.plainNode().u8(Camera::PARALLEL).f32(10).f32(2).f32(-1).f32(1);
    O gen;
    gen.plainNode().u8(Camera::GENERIC);
    for (int i = 0; i < 16; ++i) gen.f32(float(i + 1));
    O light;
    light.plainNode().f32(1).f32(0.5f).f32(0.25f).rgb(0xFF, 0x80, 0x00).u8(Light::SPOT).f32(2).f32(30).f32(8);
    O sprite;
    sprite.plainNode().ref(6).ref(7).boolean(true).i32(1).i32(2).i32(-3).i32(4);
    const auto r = loadObjects({persp.as(5), par.as(5), gen.as(5), light.as(12), rgbImage(4, 4), emptyAppearance(),
                                sprite.as(18)});
    float p[4];
    EXPECT_EQ(at<Camera>(r, 0)->getProjection(std::span<float>(p)), Camera::PERSPECTIVE);
    EXPECT_FLOAT_EQ(p[0], 60);
    EXPECT_FLOAT_EQ(p[1], 1.5f);
    EXPECT_FLOAT_EQ(p[2], 0.1f);
    EXPECT_FLOAT_EQ(p[3], 100);
    EXPECT_EQ(at<Camera>(r, 1)->getProjection(std::span<float>(p)), Camera::PARALLEL);
    EXPECT_FLOAT_EQ(p[0], 10);
    EXPECT_FLOAT_EQ(p[2], -1);
    Transform t;
    EXPECT_EQ(at<Camera>(r, 2)->getProjection(&t), Camera::GENERIC);
    EXPECT_FLOAT_EQ(t.at(0, 1), 2);
    EXPECT_FLOAT_EQ(t.at(3, 3), 16);
    auto l = at<Light>(r, 3);
    EXPECT_FLOAT_EQ(l->getConstantAttenuation(), 1);
    EXPECT_FLOAT_EQ(l->getLinearAttenuation(), 0.5f);
    EXPECT_FLOAT_EQ(l->getQuadraticAttenuation(), 0.25f);
    EXPECT_EQ(l->getColor(), 0xFF8000);
    EXPECT_EQ(l->getMode(), Light::SPOT);
    EXPECT_FLOAT_EQ(l->getIntensity(), 2);
    EXPECT_FLOAT_EQ(l->getSpotAngle(), 30);
    EXPECT_FLOAT_EQ(l->getSpotExponent(), 8);
    auto s = at<Sprite3D>(r, 6);
    EXPECT_TRUE(s->isScaled());
    EXPECT_EQ(s->getImage(), at<Image2D>(r, 4));
    EXPECT_EQ(s->getAppearance(), at<Appearance>(r, 5));
    EXPECT_EQ(s->getCropX(), 1);
    EXPECT_EQ(s->getCropY(), 2);
    EXPECT_EQ(s->getCropWidth(), -3);
    EXPECT_EQ(s->getCropHeight(), 4);

    O badProj;
    badProj.plainNode().u8(51).f32(60).f32(1).f32(1).f32(2);
    expectLoadError({badProj.as(5)}, {"Camera, type 5", "invalid projectionType 51"});
    O badLight;
    badLight.plainNode().f32(1).f32(0).f32(0).rgb(1, 1, 1).u8(127).f32(1).f32(45).f32(0);
    expectLoadError({badLight.as(12)}, {"Light, type 12", "IllegalArgumentException"});
    O badSpot;
    badSpot.plainNode().f32(1).f32(0).f32(0).rgb(1, 1, 1).u8(Light::SPOT).f32(1).f32(91).f32(0);
    expectLoadError({badSpot.as(12)}, {"Light, type 12", "IllegalArgumentException"});
}

TEST(Loader, WorldGroupHierarchy) {
    O cam;
    cam.plainNode(2).u8(Camera::PERSPECTIVE).f32(60).f32(1).f32(1).f32(10);
    O bg;
    bg.obj3d().rgba(0, 0, 0, 255).ref(0).u8(Background::BORDER).u8(Background::BORDER).i32(0).i32(0).i32(0).i32(0);
    bg.boolean(true).boolean(true);
    O world;
    world.plainNode(9).refs({2, 4}).ref(2).ref(3);
    const auto r = loadObjects({cam.as(5), bg.as(4), group({}, 4), world.as(22)});
    auto w = at<World>(r, 3);
    ASSERT_EQ(w->getChildCount(), 2);
    EXPECT_EQ(w->getChild(0), at<Camera>(r, 0));
    EXPECT_EQ(w->getChild(1), at<Group>(r, 2));
    EXPECT_EQ(w->getActiveCamera(), at<Camera>(r, 0));
    EXPECT_EQ(w->getBackground(), at<Background>(r, 1));
    EXPECT_EQ(at<Group>(r, 2)->getParent(), w);
    ASSERT_EQ(r.roots.size(), 1u);
    EXPECT_EQ(r.roots[0], w);

    // A child with two parents.
    expectLoadError({group({}), group({2}), group({2})}, {"object 4 (Group, type 9)", "IllegalArgumentException"});
    // A null child.
    expectLoadError({group({0})}, {"object 2 (Group, type 9)", "NullPointerException"});
}

// ---- references ----------------------------------------------------------------

TEST(Loader, ReferenceRules) {
    expectLoadError({group({3}), group({})}, {"object 2 (Group, type 9)", "forward reference to ObjectIndex 3"});
    expectLoadError({group({2})}, {"object 2 (Group, type 9)", "refers to the object itself"});
    expectLoadError({group({1})}, {"ObjectIndex 1 refers to the header"});
    expectLoadError({group({99})}, {"forward reference to ObjectIndex 99"});
    // Type checks: a Material where a Node is expected; a Group where a VertexBuffer is expected.
    O mat;
    mat.obj3d().rgb(1, 2, 3).rgba(4, 5, 6, 7).rgb(8, 9, 10).rgb(11, 12, 13).f32(5).boolean(true);
    expectLoadError({mat.as(13), group({2})}, {"object 3 (Group, type 9)", "ObjectIndex 2 is a Material, expected Node",
                                               "byte offset"});
    O mesh;
    mesh.plainNode().ref(2).u32(1).ref(0).ref(0);
    expectLoadError({group({}), mesh.as(14)}, {"Mesh, type 14", "is a Group, expected VertexBuffer"});
    // Node slots accept every Node subclass; IndexBuffer slots accept TriangleStripArray.
    O cam;
    cam.plainNode().u8(Camera::PERSPECTIVE).f32(60).f32(1).f32(1).f32(10);
    O m2;
    m2.plainNode().ref(3).u32(1).ref(4).ref(0);
    const auto r = loadObjects({vertexArray16(3, {0, 0, 0}), vertexBufferWithPositions(2), stripArray(0, {3}),
                                m2.as(14), cam.as(5), group({5, 6})});
    EXPECT_EQ(at<Group>(r, 5)->getChildCount(), 2);
    // Trailing bytes in an object.
    O extra;
    extra.plainNode().refs({}).u8(0);
    expectLoadError({extra.as(9)}, {"object 2 (Group, type 9)", "byte offset"});
    // Truncated object data.
    O trunc;
    trunc.obj3d().noTransform();
    expectLoadError({trunc.as(9)}, {"object 2 (Group, type 9)", "truncated"});
}

// ---- external references and PNG ------------------------------------------------

namespace {

Bytes pngBytes(int w, int h, int channels) {
    png_image img{};
    img.version = PNG_IMAGE_VERSION;
    img.width = static_cast<png_uint_32>(w);
    img.height = static_cast<png_uint_32>(h);
    img.format = channels == 4 ? PNG_FORMAT_RGBA : channels == 3 ? PNG_FORMAT_RGB : PNG_FORMAT_GRAY;
    std::vector<std::uint8_t> px(static_cast<std::size_t>(w * h * channels));
    for (std::size_t i = 0; i < px.size(); ++i) px[i] = static_cast<std::uint8_t>(i * 7);
    png_alloc_size_t size = 0;
    png_image_write_to_memory(&img, nullptr, &size, 0, px.data(), 0, nullptr);
    Bytes out(size);
    png_image_write_to_memory(&img, out.data(), &size, 0, px.data(), 0, nullptr);
    out.resize(size);
    return out;
}

Bytes fileWithExternal(const std::vector<std::string>& uris, const std::vector<Bytes>& scene) {
    FileSpec f;
    f.hasExt = 1;
    std::vector<Bytes> ext;
    for (const auto& u : uris) {
        O o;
        o.str(u);
        ext.push_back(o.as(255));
    }
    f.sections.push_back({0, ext});
    f.sections.push_back({0, scene});
    return f.build();
}

void writeBytes(const std::filesystem::path& p, const Bytes& b) {
    std::ofstream out(p, std::ios::binary);
    out.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
}

struct TempDir {
    std::filesystem::path path;
    TempDir() {
        path = std::filesystem::temp_directory_path() /
               ("m3g_loader_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path / "sub");
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
};

}  // namespace

TEST(Loader, PngLoadsAsImmutableImage2D) {
    const Bytes png = pngBytes(3, 2, 4);
    const auto roots = Loader::load(std::span<const std::uint8_t>(png), 0);
    ASSERT_EQ(roots.size(), 1u);
    auto img = dynamicCast<Image2D>(roots[0]);
    ASSERT_TRUE(img);
    EXPECT_FALSE(img->isMutable());
    EXPECT_EQ(img->getFormat(), Image2D::RGBA);
    EXPECT_EQ(img->getWidth(), 3);
    EXPECT_EQ(img->getHeight(), 2);
    EXPECT_EQ(img->pixels()[5], 35);
}

TEST(Loader, ExternalReferencesRelativeNestedAndPng) {
    TempDir dir;
    // sub/inner.m3g: Material root; sub/tex.png; main.m3g: refs, Texture2D(tex), Group
    O mat;
    mat.obj3d(77).rgb(1, 2, 3).rgba(4, 5, 6, 7).rgb(8, 9, 10).rgb(11, 12, 13).f32(5).boolean(true);
    writeBytes(dir.path / "sub" / "inner.m3g", sceneFile({mat.as(13)}));
    writeBytes(dir.path / "sub" / "tex.png", pngBytes(4, 4, 3));
    O tex;
    tex.obj3d().noTransform().ref(3).rgb(0, 0, 0).u8(Texture2D::FUNC_MODULATE).u8(Texture2D::WRAP_REPEAT);
    tex.u8(Texture2D::WRAP_REPEAT).u8(Texture2D::FILTER_BASE_LEVEL).u8(Texture2D::FILTER_NEAREST);
    O app;
    app.obj3d().u8(0).ref(0).ref(0).ref(0).ref(2).refs({4});
    writeBytes(dir.path / "main.m3g", fileWithExternal({"sub/inner.m3g", "sub/tex.png"}, {tex.as(17), app.as(3)}));
    const auto r = Loader::loadDetailed((dir.path / "main.m3g").string());
    EXPECT_TRUE(r.hasExternalReferences);
    ASSERT_EQ(r.objects.size(), 4u);
    auto m = at<Material>(r, 0);
    EXPECT_EQ(m->getUserID(), 77);
    auto img = at<Image2D>(r, 1);
    EXPECT_EQ(img->getFormat(), Image2D::RGB);
    EXPECT_FALSE(img->isMutable());
    auto a = at<Appearance>(r, 3);
    EXPECT_EQ(a->getMaterial(), m);
    EXPECT_EQ(a->getTexture(0)->getImage(), img);
    ASSERT_EQ(r.roots.size(), 1u);
    EXPECT_EQ(r.roots[0], a);
    // Each reference listed in file order, with the file it resolved to.
    ASSERT_EQ(r.externalReferences.size(), 2u);
    EXPECT_EQ(r.externalReferences[0].uri, "sub/inner.m3g");
    EXPECT_EQ(std::filesystem::path(r.externalReferences[0].path), (dir.path / "sub" / "inner.m3g").lexically_normal());
    EXPECT_EQ(r.externalReferences[1].uri, "sub/tex.png");
    EXPECT_TRUE(r.externalReferences[0].loaded && r.externalReferences[1].loaded);
    EXPECT_NE(r.externalReferences[0].referencedBy.find("main.m3g"), std::string::npos);

    // A file: URI works as the name.
    EXPECT_EQ(Loader::load("file://" + (dir.path / "main.m3g").string()).size(), 1u);

    // From a byte array: relative references are refused, absolute ones work.
    const Bytes rel = fileWithExternal({"sub/inner.m3g"}, {});
    try {
        Loader::load(std::span<const std::uint8_t>(rel), 0);
        ADD_FAILURE();
    } catch (const IOException& e) {
        EXPECT_NE(std::string(e.what()).find("only absolute references"), std::string::npos) << e.what();
    }
    const Bytes abs = fileWithExternal({(dir.path / "sub" / "inner.m3g").string()}, {});
    const auto absRoots = Loader::load(std::span<const std::uint8_t>(abs), 0);
    ASSERT_EQ(absRoots.size(), 1u);
    EXPECT_EQ(absRoots[0]->getUserID(), 77);
}

TEST(Loader, ExternalReferenceMissingStrictAndLenient) {
    TempDir dir;
    O tex;
    tex.obj3d().noTransform().ref(2).rgb(0, 0, 0).u8(Texture2D::FUNC_MODULATE).u8(Texture2D::WRAP_REPEAT);
    tex.u8(Texture2D::WRAP_REPEAT).u8(Texture2D::FILTER_BASE_LEVEL).u8(Texture2D::FILTER_NEAREST);
    O app;
    app.obj3d().u8(0).ref(0).ref(0).ref(0).ref(0).refs({3});
    writeBytes(dir.path / "main.m3g", fileWithExternal({"gone.png"}, {tex.as(17), app.as(3), group({}, 5)}));
    const std::string name = (dir.path / "main.m3g").string();
    try {
        Loader::load(name);
        ADD_FAILURE();
    } catch (const IOException& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("gone.png"), std::string::npos) << m;
        EXPECT_NE(m.find("not found"), std::string::npos) << m;
        EXPECT_NE(m.find("section 1, object 2 (External Reference, type 255)"), std::string::npos) << m;
    }
    LoaderOptions lenient;
    lenient.lenient = true;
    const auto r = Loader::loadDetailed(name, lenient);
    // The image and the Texture2D that needs it are skipped; the Appearance keeps an empty unit.
    ASSERT_EQ(r.objects.size(), 2u);
    auto a = at<Appearance>(r, 0);
    EXPECT_FALSE(a->getTexture(0));
    ASSERT_EQ(r.warnings.size(), 2u);
    EXPECT_NE(r.warnings[0].find("gone.png"), std::string::npos);
    EXPECT_NE(r.warnings[1].find("Texture2D"), std::string::npos);
    ASSERT_EQ(r.roots.size(), 2u);
    ASSERT_EQ(r.externalReferences.size(), 1u);
    EXPECT_EQ(r.externalReferences[0].uri, "gone.png");
    EXPECT_FALSE(r.externalReferences[0].loaded);
}

TEST(Loader, ExternalReferenceLoopIsDetected) {
    TempDir dir;
    writeBytes(dir.path / "a.m3g", fileWithExternal({"sub/b.m3g"}, {}));
    writeBytes(dir.path / "sub" / "b.m3g", fileWithExternal({"../a.m3g"}, {}));
    try {
        Loader::load((dir.path / "a.m3g").string());
        ADD_FAILURE();
    } catch (const IOException& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("loop"), std::string::npos) << m;
        EXPECT_NE(m.find("b.m3g -> "), std::string::npos) << m;
    }
    writeBytes(dir.path / "self.m3g", fileWithExternal({"self.m3g"}, {}));
    EXPECT_THROW(Loader::load((dir.path / "self.m3g").string()), IOException);
}

// ---- JPEG images -------------------------------------------------------------

namespace {

// JPEG is lossy: decoded samples are compared with the encoded ones within
// the tolerance test_JpegImage.cpp derives for quality 100 (4 levels).
constexpr int kJpegTolerance = 4;

Bytes jpegBytes(int w, int h, int components, bool progressive = false) {
    JpegSpec s;
    s.width = w;
    s.height = h;
    s.components = components;
    s.pixels = jpegTestPattern(w, h, components);
    s.progressive = progressive;
    return writeJpeg(s);
}

void expectJpegPixels(const Image2D& img, int components) {
    const Bytes expected = jpegTestPattern(img.getWidth(), img.getHeight(), components);
    ASSERT_EQ(img.pixels().size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
        ASSERT_LE(std::abs(int(img.pixels()[i]) - int(expected[i])), kJpegTolerance) << "sample " << i;
}

std::string loadFailure(const std::string& name) {
    try {
        Loader::load(name);
    } catch (const IOException& e) {
        return e.what();
    }
    ADD_FAILURE() << "load of " << name << " succeeded";
    return {};
}

}  // namespace

TEST(Loader, JpegLoadsAsImmutableImage2D) {
    const Bytes jpeg = jpegBytes(5, 3, 3);
    const auto r = Loader::loadDetailed(std::span<const std::uint8_t>(jpeg), 0);
    ASSERT_EQ(r.roots.size(), 1u);
    ASSERT_EQ(r.objects.size(), 1u);
    auto img = dynamicCast<Image2D>(r.roots[0]);
    ASSERT_TRUE(img);
    EXPECT_FALSE(img->isMutable());
    EXPECT_EQ(img->getFormat(), Image2D::RGB);
    EXPECT_EQ(img->getWidth(), 5);
    EXPECT_EQ(img->getHeight(), 3);
    expectJpegPixels(*img, 3);
    EXPECT_EQ(r.versionMajor, 0);
    EXPECT_FALSE(r.hasExternalReferences);

    // At an offset inside a larger array, as a PNG or .m3g may be.
    Bytes container = {9, 9};
    const Bytes grey = jpegBytes(4, 6, 1, true);
    container.insert(container.end(), grey.begin(), grey.end());
    const auto roots = Loader::load(std::span<const std::uint8_t>(container), 2);
    ASSERT_EQ(roots.size(), 1u);
    auto lum = dynamicCast<Image2D>(roots[0]);
    ASSERT_TRUE(lum);
    EXPECT_EQ(lum->getFormat(), Image2D::LUMINANCE);
    expectJpegPixels(*lum, 1);
}

TEST(Loader, JpegFileByName) {
    TempDir dir;
    writeBytes(dir.path / "photo.jpg", jpegBytes(7, 9, 3, true));
    const auto roots = Loader::load((dir.path / "photo.jpg").string());
    ASSERT_EQ(roots.size(), 1u);
    auto img = dynamicCast<Image2D>(roots[0]);
    ASSERT_TRUE(img);
    EXPECT_EQ(img->getFormat(), Image2D::RGB);
    EXPECT_EQ(img->getWidth(), 7);
    EXPECT_EQ(img->getHeight(), 9);
    expectJpegPixels(*img, 3);
    // The contents decide, not the name: a JPEG named .png loads as JPEG.
    writeBytes(dir.path / "misnamed.png", jpegBytes(2, 2, 1));
    const auto misnamed = Loader::load((dir.path / "misnamed.png").string());
    ASSERT_EQ(misnamed.size(), 1u);
    EXPECT_EQ(dynamicCast<Image2D>(misnamed[0])->getFormat(), Image2D::LUMINANCE);
}

TEST(Loader, ExternalReferenceToJpeg) {
    TempDir dir;
    // main.m3g: refs to sub/tex.jpg (colour) and sub/grey.jpg, a Texture2D on
    // each, an Appearance with both units.
    writeBytes(dir.path / "sub" / "tex.jpg", jpegBytes(8, 4, 3));
    writeBytes(dir.path / "sub" / "grey.jpg", jpegBytes(4, 8, 1, true));
    auto texture = [](std::uint32_t image) {
        O tex;
        tex.obj3d().noTransform().ref(image).rgb(0, 0, 0).u8(Texture2D::FUNC_MODULATE).u8(Texture2D::WRAP_REPEAT);
        tex.u8(Texture2D::WRAP_REPEAT).u8(Texture2D::FILTER_BASE_LEVEL).u8(Texture2D::FILTER_NEAREST);
        return tex.as(17);
    };
    O app;
    app.obj3d().u8(0).ref(0).ref(0).ref(0).ref(0).refs({4, 5});
    writeBytes(dir.path / "main.m3g",
               fileWithExternal({"sub/tex.jpg", "sub/grey.jpg"}, {texture(2), texture(3), app.as(3)}));
    const auto r = Loader::loadDetailed((dir.path / "main.m3g").string());
    EXPECT_TRUE(r.hasExternalReferences);
    ASSERT_EQ(r.objects.size(), 5u);
    auto colour = at<Image2D>(r, 0);
    auto grey = at<Image2D>(r, 1);
    ASSERT_TRUE(colour && grey);
    EXPECT_FALSE(colour->isMutable());
    EXPECT_EQ(colour->getFormat(), Image2D::RGB);
    EXPECT_EQ(colour->getWidth(), 8);
    EXPECT_EQ(colour->getHeight(), 4);
    expectJpegPixels(*colour, 3);
    EXPECT_EQ(grey->getFormat(), Image2D::LUMINANCE);
    EXPECT_EQ(grey->getWidth(), 4);
    EXPECT_EQ(grey->getHeight(), 8);
    expectJpegPixels(*grey, 1);
    auto a = at<Appearance>(r, 4);
    EXPECT_EQ(a->getTexture(0)->getImage(), colour);
    EXPECT_EQ(a->getTexture(1)->getImage(), grey);
    ASSERT_EQ(r.roots.size(), 1u);
    EXPECT_EQ(r.roots[0], a);
}

TEST(Loader, BrokenJpegErrorsNameTheFile) {
    TempDir dir;
    const Bytes good = jpegBytes(8, 8, 3);
    // Standalone: truncated, garbage after SOI, zero size.
    const std::string cut = (dir.path / "cut.jpg").string();
    writeBytes(cut, Bytes(good.begin(), good.end() - 40));
    std::string m = loadFailure(cut);
    EXPECT_NE(m.find(cut + ": invalid JPEG: Premature end of JPEG file"), std::string::npos) << m;
    const std::string junk = (dir.path / "junk.jpg").string();
    Bytes garbage = {0xFF, 0xD8, 0xFF};
    for (int i = 0; i < 64; ++i) garbage.push_back(static_cast<std::uint8_t>(i * 37 % 251));
    writeBytes(junk, garbage);
    m = loadFailure(junk);
    EXPECT_NE(m.find(junk + ": invalid JPEG: "), std::string::npos) << m;
    const std::string empty = (dir.path / "empty.jpg").string();
    Bytes zero = good;
    setJpegSize(zero, 8, 0);
    writeBytes(empty, zero);
    m = loadFailure(empty);
    EXPECT_NE(m.find(empty + ": invalid JPEG: Empty JPEG image"), std::string::npos) << m;

    // Through an external reference: the referencing object and the file.
    O tex;
    tex.obj3d().noTransform().ref(2).rgb(0, 0, 0).u8(Texture2D::FUNC_MODULATE).u8(Texture2D::WRAP_REPEAT);
    tex.u8(Texture2D::WRAP_REPEAT).u8(Texture2D::FILTER_BASE_LEVEL).u8(Texture2D::FILTER_NEAREST);
    writeBytes(dir.path / "main.m3g", fileWithExternal({"cut.jpg"}, {tex.as(17)}));
    for (bool lenient : {false, true}) {
        LoaderOptions options;
        options.lenient = lenient;
        try {
            Loader::loadDetailed((dir.path / "main.m3g").string(), options);
            ADD_FAILURE() << "lenient " << lenient;
        } catch (const IOException& e) {
            m = e.what();
            EXPECT_NE(m.find("section 1, object 2 (External Reference, type 255)"), std::string::npos) << m;
            EXPECT_NE(m.find("external reference 'cut.jpg'"), std::string::npos) << m;
            EXPECT_NE(m.find(cut + ": invalid JPEG: Premature end of JPEG file"), std::string::npos) << m;
        }
    }
}

TEST(Loader, LenientWarningsAreReported) {
    FileSpec f;
    f.minor = 1;
    f.sections.push_back({0, {group({})}});
    const Bytes file = f.build();
    EXPECT_THROW(Loader::load(std::span<const std::uint8_t>(file), 0), IOException);
    LoaderOptions lenient;
    lenient.lenient = true;
    const auto r = Loader::loadDetailed(std::span<const std::uint8_t>(file), 0, lenient);
    EXPECT_EQ(r.versionMinor, 1);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("1.1"), std::string::npos);
}
