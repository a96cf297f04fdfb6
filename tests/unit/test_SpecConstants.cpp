// Every constant of JSR-184 1.1 (the static final int fields of each class),
// through the umbrella header. These values
// are also the enum bytes of the .m3g file format: a wrong one breaks files.
#include <gtest/gtest.h>

#include <m3g/m3g.h>

using namespace m3g;

TEST(SpecConstants, AnimationTrack) {
    const int expected[] = {256, 257, 258, 259, 260, 261, 262, 263, 264, 265, 266,
                            267, 268, 269, 270, 271, 272, 273, 274, 275, 276};
    const int actual[] = {AnimationTrack::ALPHA, AnimationTrack::AMBIENT_COLOR, AnimationTrack::COLOR,
                          AnimationTrack::CROP, AnimationTrack::DENSITY, AnimationTrack::DIFFUSE_COLOR,
                          AnimationTrack::EMISSIVE_COLOR, AnimationTrack::FAR_DISTANCE,
                          AnimationTrack::FIELD_OF_VIEW, AnimationTrack::INTENSITY, AnimationTrack::MORPH_WEIGHTS,
                          AnimationTrack::NEAR_DISTANCE, AnimationTrack::ORIENTATION, AnimationTrack::PICKABILITY,
                          AnimationTrack::SCALE, AnimationTrack::SHININESS, AnimationTrack::SPECULAR_COLOR,
                          AnimationTrack::SPOT_ANGLE, AnimationTrack::SPOT_EXPONENT, AnimationTrack::TRANSLATION,
                          AnimationTrack::VISIBILITY};
    for (int i = 0; i < 21; ++i) EXPECT_EQ(actual[i], expected[i]) << "index " << i;
}

TEST(SpecConstants, OtherClasses) {
    EXPECT_EQ(Background::BORDER, 32);
    EXPECT_EQ(Background::REPEAT, 33);
    EXPECT_EQ(Camera::GENERIC, 48);
    EXPECT_EQ(Camera::PARALLEL, 49);
    EXPECT_EQ(Camera::PERSPECTIVE, 50);
    EXPECT_EQ(CompositingMode::ALPHA, 64);
    EXPECT_EQ(CompositingMode::ALPHA_ADD, 65);
    EXPECT_EQ(CompositingMode::MODULATE, 66);
    EXPECT_EQ(CompositingMode::MODULATE_X2, 67);
    EXPECT_EQ(CompositingMode::REPLACE, 68);
    EXPECT_EQ(Fog::EXPONENTIAL, 80);
    EXPECT_EQ(Fog::LINEAR, 81);
    EXPECT_EQ(Graphics3D::ANTIALIAS, 2);
    EXPECT_EQ(Graphics3D::DITHER, 4);
    EXPECT_EQ(Graphics3D::TRUE_COLOR, 8);
    EXPECT_EQ(Graphics3D::OVERWRITE, 16);
    EXPECT_EQ(Image2D::ALPHA, 96);
    EXPECT_EQ(Image2D::LUMINANCE, 97);
    EXPECT_EQ(Image2D::LUMINANCE_ALPHA, 98);
    EXPECT_EQ(Image2D::RGB, 99);
    EXPECT_EQ(Image2D::RGBA, 100);
    EXPECT_EQ(KeyframeSequence::LINEAR, 176);
    EXPECT_EQ(KeyframeSequence::SLERP, 177);
    EXPECT_EQ(KeyframeSequence::SPLINE, 178);
    EXPECT_EQ(KeyframeSequence::SQUAD, 179);
    EXPECT_EQ(KeyframeSequence::STEP, 180);
    EXPECT_EQ(KeyframeSequence::CONSTANT, 192);
    EXPECT_EQ(KeyframeSequence::LOOP, 193);
    EXPECT_EQ(Light::AMBIENT, 128);
    EXPECT_EQ(Light::DIRECTIONAL, 129);
    EXPECT_EQ(Light::OMNI, 130);
    EXPECT_EQ(Light::SPOT, 131);
    EXPECT_EQ(Material::AMBIENT, 1024);
    EXPECT_EQ(Material::DIFFUSE, 2048);
    EXPECT_EQ(Material::EMISSIVE, 4096);
    EXPECT_EQ(Material::SPECULAR, 8192);
    EXPECT_EQ(Node::NONE, 144);
    EXPECT_EQ(Node::ORIGIN, 145);
    EXPECT_EQ(Node::X_AXIS, 146);
    EXPECT_EQ(Node::Y_AXIS, 147);
    EXPECT_EQ(Node::Z_AXIS, 148);
    EXPECT_EQ(PolygonMode::CULL_BACK, 160);
    EXPECT_EQ(PolygonMode::CULL_FRONT, 161);
    EXPECT_EQ(PolygonMode::CULL_NONE, 162);
    EXPECT_EQ(PolygonMode::SHADE_FLAT, 164);
    EXPECT_EQ(PolygonMode::SHADE_SMOOTH, 165);
    EXPECT_EQ(PolygonMode::WINDING_CCW, 168);
    EXPECT_EQ(PolygonMode::WINDING_CW, 169);
    EXPECT_EQ(Texture2D::FILTER_BASE_LEVEL, 208);
    EXPECT_EQ(Texture2D::FILTER_LINEAR, 209);
    EXPECT_EQ(Texture2D::FILTER_NEAREST, 210);
    EXPECT_EQ(Texture2D::FUNC_ADD, 224);
    EXPECT_EQ(Texture2D::FUNC_BLEND, 225);
    EXPECT_EQ(Texture2D::FUNC_DECAL, 226);
    EXPECT_EQ(Texture2D::FUNC_MODULATE, 227);
    EXPECT_EQ(Texture2D::FUNC_REPLACE, 228);
    EXPECT_EQ(Texture2D::WRAP_CLAMP, 240);
    EXPECT_EQ(Texture2D::WRAP_REPEAT, 241);
}

TEST(ObjectGraph, DuplicateWorldRemapsActiveCameraInsideSubtree) {
    Ref<World> w = make<World>();
    Ref<Camera> cam = make<Camera>();
    Ref<Background> bg = make<Background>();
    w->addChild(cam);
    w->setActiveCamera(cam);
    w->setBackground(bg);
    Ref<World> copy = dynamicCast<World>(w->duplicate());
    ASSERT_TRUE(copy);
    ASSERT_EQ(copy->getChildCount(), 1);
    EXPECT_NE(copy->getActiveCamera(), cam);
    EXPECT_EQ(copy->getActiveCamera(), copy->getChild(0));
    EXPECT_EQ(copy->getBackground(), bg);  // components are shared
}

TEST(ObjectGraph, SharedAppearanceSurvivesMeshes) {
    // One Appearance used by many meshes, meshes dropped in any order.
    Ref<Appearance> app = make<Appearance>();
    Ref<VertexArray> pos = make<VertexArray>(3, 3, 2);
    Ref<VertexBuffer> vb = make<VertexBuffer>();
    vb->setPositions(pos, 1.0f, std::span<const float>());
    const int lengths[] = {3};
    Ref<IndexBuffer> ib = make<TriangleStripArray>(0, std::span<const int>(lengths));
    {
        Ref<Group> g = make<Group>();
        for (int i = 0; i < 4; ++i) g->addChild(make<Mesh>(vb, ib, app));
        EXPECT_EQ(app->getRefCount(), 5);
        Ref<Object3D> copy = g->duplicate();
        EXPECT_EQ(app->getRefCount(), 9);
    }
    EXPECT_EQ(app->getRefCount(), 1);
    EXPECT_EQ(vb->getRefCount(), 1);
}
