// Group::pick with an explicit ray (JSR-184 1.1, Group.pick). Every expectation is
// worked out by hand from the geometry in the comments.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <m3g/Image2D.h>
#include <m3g/MorphingMesh.h>
#include <m3g/SkinnedMesh.h>
#include <m3g/Sprite3D.h>
#include <m3g/Texture2D.h>
#include <m3g/World.h>

#include "PickTestScenes.h"

using namespace m3g;
using namespace picktest;

namespace {

// Straight down the -z axis from above the triangle of triangleAt(): (2, 3)
// lies inside it with barycentric weights v0 0.5, v1 0.2, v2 0.3.
constexpr float kX = 2, kY = 3;

bool pickDown(Group& g, float z0, RayIntersection* ri = nullptr, int scope = -1, float dz = -1.0f) {
    return g.pick(scope, kX, kY, z0, 0, 0, dz, ri);
}

std::vector<float> ray(const RayIntersection& ri) {
    std::vector<float> r(6);
    ri.getRay(r);
    return r;
}

template <class E, class F>
void expectThrowMentioning(F&& f, const std::string& text) {
    try {
        f();
        ADD_FAILURE() << "no exception";
    } catch (const E& e) {
        EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
}

}  // namespace

TEST(PickRay, HitFillsTheRayIntersection) {
    Ref<Group> g = new Group();
    Ref<Mesh> m = triangleAt(0);
    g->addChild(m);
    RayIntersection ri;
    // o = (2, 3, 5), d = (0, 0, -2): z = 5 - 2t = 0 at t = 2.5.
    ASSERT_TRUE(g->pick(-1, 2, 3, 5, 0, 0, -2, &ri));
    EXPECT_EQ(ri.getIntersected().get(), m.get());
    EXPECT_FLOAT_EQ(ri.getDistance(), 2.5f);
    EXPECT_EQ(ri.getSubmeshIndex(), 0);
    EXPECT_EQ(ray(ri), (std::vector<float>{2, 3, 5, 0, 0, -2}));
    // No normals: (0, 0, 1); no texture coordinates: 0.
    EXPECT_EQ(ri.getNormalX(), 0.0f);
    EXPECT_EQ(ri.getNormalY(), 0.0f);
    EXPECT_EQ(ri.getNormalZ(), 1.0f);
    EXPECT_EQ(ri.getTextureS(0), 0.0f);
    EXPECT_EQ(ri.getTextureT(1), 0.0f);
    // A null RayIntersection is allowed.
    EXPECT_TRUE(g->pick(-1, 2, 3, 5, 0, 0, -2, nullptr));
}

TEST(PickRay, MissesLeaveTheRayIntersectionUntouched) {
    Ref<Group> g = new Group();
    g->addChild(triangleAt(0));
    RayIntersection ri;
    // (8, 8): x + y = 16 > 10, outside the hypotenuse.
    EXPECT_FALSE(g->pick(-1, 8, 8, 5, 0, 0, -1, &ri));
    // Pointing away (t = -5) and starting behind the plane (t = -1).
    EXPECT_FALSE(pickDown(*g, 5, &ri, -1, +1.0f));
    EXPECT_FALSE(pickDown(*g, -1, &ri));
    // Parallel to the plane, in it.
    EXPECT_FALSE(g->pick(-1, -5, 1, 0, 1, 0, 0, &ri));
    EXPECT_EQ(ri.getIntersected().get(), nullptr);
    EXPECT_EQ(ri.getDistance(), 0.0f);
    EXPECT_EQ(ray(ri), (std::vector<float>{0, 0, 0, 0, 0, 1}));
    // An empty group.
    Ref<Group> empty = new Group();
    EXPECT_FALSE(empty->pick(-1, 0, 0, 0, 0, 0, -1, &ri));
}

TEST(PickRay, EdgesAndVerticesCount) {
    Ref<Group> g = new Group();
    g->addChild(triangleAt(0));
    EXPECT_TRUE(g->pick(-1, 5, 5, 1, 0, 0, -1, nullptr));   // on the hypotenuse
    EXPECT_TRUE(g->pick(-1, 0, 4, 1, 0, 0, -1, nullptr));   // on the x = 0 edge
    EXPECT_TRUE(g->pick(-1, 10, 0, 1, 0, 0, -1, nullptr));  // vertex v1
    EXPECT_FALSE(g->pick(-1, -0.01f, 4, 1, 0, 0, -1, nullptr));
}

TEST(PickRay, ClosestPositiveDistanceWins) {
    Ref<Group> g = new Group();
    Ref<Mesh> far = triangleAt(-6);
    Ref<Mesh> near = triangleAt(-2);
    Ref<Mesh> behind = triangleAt(4);
    g->addChild(far);
    g->addChild(near);
    g->addChild(behind);
    RayIntersection ri;
    // From z = 3 downwards: behind (z = 4) has t = -1, near t = 5, far t = 9.
    ASSERT_TRUE(pickDown(*g, 3, &ri));
    EXPECT_EQ(ri.getIntersected().get(), near.get());
    EXPECT_FLOAT_EQ(ri.getDistance(), 5.0f);
    // Distance is in units of |d|: d = (0, 0, -4) halves... quarters it.
    ASSERT_TRUE(pickDown(*g, 3, &ri, -1, -4.0f));
    EXPECT_FLOAT_EQ(ri.getDistance(), 1.25f);
    // From below upwards (CCW seen from +z means these are back faces from
    // below, so use CULL_NONE meshes): the first above z = -10 is far.
    Ref<Group> g2 = new Group();
    Ref<Mesh> a = triangleAt(-6, culled(PolygonMode::CULL_NONE));
    Ref<Mesh> b = triangleAt(-2, culled(PolygonMode::CULL_NONE));
    g2->addChild(b);
    g2->addChild(a);
    ASSERT_TRUE(pickDown(*g2, -10, &ri, -1, +1.0f));
    EXPECT_EQ(ri.getIntersected().get(), a.get());
    EXPECT_FLOAT_EQ(ri.getDistance(), 4.0f);
}

TEST(PickRay, ClosestTriangleAndSubmeshWithinOneMesh) {
    // Vertices 0-2 at z = -5, 3-5 at z = -1; submesh 0 holds the far
    // triangle, submesh 1 the near one; a third triangle list puts both into
    // one submesh.
    Ref<VertexBuffer> vb = positionsVB({0, 0, -5, 10, 0, -5, 0, 10, -5, 0, 0, -1, 10, 0, -1, 0, 10, -1});
    std::vector<Ref<IndexBuffer>> ibs{triangles({0, 1, 2}), triangles({3, 4, 5})};
    std::vector<Ref<Appearance>> apps{new Appearance(), new Appearance()};
    Ref<Mesh> m = new Mesh(vb, ibs, apps);
    Ref<Group> g = new Group();
    g->addChild(m);
    RayIntersection ri;
    ASSERT_TRUE(pickDown(*g, 3, &ri));
    EXPECT_EQ(ri.getSubmeshIndex(), 1);
    EXPECT_FLOAT_EQ(ri.getDistance(), 4.0f);

    Ref<Mesh> one = new Mesh(vb, triangles({0, 1, 2, 3, 4, 5}), new Appearance());
    Ref<Group> g2 = new Group();
    g2->addChild(one);
    ASSERT_TRUE(pickDown(*g2, 3, &ri));
    EXPECT_EQ(ri.getSubmeshIndex(), 0);
    EXPECT_FLOAT_EQ(ri.getDistance(), 4.0f);
}

TEST(PickRay, NullAppearanceSubmeshesAreSkipped) {
    Ref<VertexBuffer> vb = positionsVB({0, 0, -5, 10, 0, -5, 0, 10, -5, 0, 0, -1, 10, 0, -1, 0, 10, -1});
    std::vector<Ref<IndexBuffer>> ibs{triangles({0, 1, 2}), triangles({3, 4, 5})};
    std::vector<Ref<Appearance>> apps{new Appearance(), nullptr};  // the near submesh has none
    Ref<Mesh> m = new Mesh(vb, ibs, apps);
    Ref<Group> g = new Group();
    g->addChild(m);
    RayIntersection ri;
    ASSERT_TRUE(pickDown(*g, 3, &ri));
    EXPECT_EQ(ri.getSubmeshIndex(), 0);
    EXPECT_FLOAT_EQ(ri.getDistance(), 8.0f);
    m->setAppearance(0, nullptr);
    EXPECT_FALSE(pickDown(*g, 3, &ri));
}

TEST(PickRay, ScopeMaskSelectsCandidates) {
    Ref<Group> g = new Group();
    Ref<Mesh> near = triangleAt(-1);
    Ref<Mesh> far = triangleAt(-5);
    near->setScope(2);
    far->setScope(4 | 1);
    g->addChild(near);
    g->addChild(far);
    RayIntersection ri;
    ASSERT_TRUE(pickDown(*g, 3, &ri, -1));
    EXPECT_EQ(ri.getIntersected().get(), near.get());
    ASSERT_TRUE(pickDown(*g, 3, &ri, 2 | 8));
    EXPECT_EQ(ri.getIntersected().get(), near.get());
    ASSERT_TRUE(pickDown(*g, 3, &ri, 1));  // near is out of scope: far
    EXPECT_EQ(ri.getIntersected().get(), far.get());
    EXPECT_FALSE(pickDown(*g, 3, &ri, 8));
    EXPECT_FALSE(pickDown(*g, 3, &ri, 0));
    // A group's own scope does not matter, only the candidates'.
    g->setScope(0);
    EXPECT_TRUE(pickDown(*g, 3, &ri, 2));
}

TEST(PickRay, PickingDisabledOnThePathHidesTheSubtree) {
    Ref<Group> root = new Group();
    Ref<Group> mid = new Group();
    Ref<Mesh> near = triangleAt(-1);
    Ref<Mesh> far = triangleAt(-5);
    root->addChild(mid);
    mid->addChild(near);
    root->addChild(far);
    RayIntersection ri;
    ASSERT_TRUE(pickDown(*root, 3, &ri));
    EXPECT_EQ(ri.getIntersected().get(), near.get());
    mid->setPickingEnable(false);  // ancestor disabled
    ASSERT_TRUE(pickDown(*root, 3, &ri));
    EXPECT_EQ(ri.getIntersected().get(), far.get());
    mid->setPickingEnable(true);
    near->setPickingEnable(false);  // the mesh itself
    ASSERT_TRUE(pickDown(*root, 3, &ri));
    EXPECT_EQ(ri.getIntersected().get(), far.get());
    // Picking from `mid` directly: near is still disabled.
    EXPECT_FALSE(pickDown(*mid, 3, &ri));
    near->setPickingEnable(true);
    EXPECT_TRUE(pickDown(*mid, 3, &ri));
    // The picked group itself is on the path.
    root->setPickingEnable(false);
    EXPECT_FALSE(pickDown(*root, 3, &ri));
    // Ancestors above the picked group are not.
    EXPECT_TRUE(pickDown(*mid, 3, &ri));
    // Rendering enable does not matter.
    root->setPickingEnable(true);
    near->setRenderingEnable(false);
    ASSERT_TRUE(pickDown(*root, 3, &ri));
    EXPECT_EQ(ri.getIntersected().get(), near.get());
}

TEST(PickRay, CullingAndWinding) {
    // The triangle is CCW seen from +z (from above) and CW seen from below.
    struct Case {
        int culling, winding;
        bool fromAbove, fromBelow;
    };
    const Case cases[] = {
        {PolygonMode::CULL_BACK, PolygonMode::WINDING_CCW, true, false},
        {PolygonMode::CULL_FRONT, PolygonMode::WINDING_CCW, false, true},
        {PolygonMode::CULL_NONE, PolygonMode::WINDING_CCW, true, true},
        {PolygonMode::CULL_BACK, PolygonMode::WINDING_CW, false, true},
        {PolygonMode::CULL_FRONT, PolygonMode::WINDING_CW, true, false},
        {PolygonMode::CULL_NONE, PolygonMode::WINDING_CW, true, true},
    };
    for (const Case& c : cases) {
        Ref<Group> g = new Group();
        g->addChild(triangleAt(0, culled(c.culling, c.winding)));
        EXPECT_EQ(pickDown(*g, 5), c.fromAbove) << c.culling << "/" << c.winding;
        EXPECT_EQ(pickDown(*g, -5, nullptr, -1, +1.0f), c.fromBelow) << c.culling << "/" << c.winding;
    }
    // No PolygonMode: CULL_BACK with CCW.
    Ref<Group> g = new Group();
    g->addChild(triangleAt(0));
    EXPECT_TRUE(pickDown(*g, 5));
    EXPECT_FALSE(pickDown(*g, -5, nullptr, -1, +1.0f));
}

TEST(PickRay, StripTrianglesKeepTheWindingOfTheFirst) {
    // Strip (0,0) (10,0) (0,10) (10,10): triangles (0,1,2) and (1,3,2), both
    // CCW from +z, so back-face culling lets both be hit from above only.
    const int lengths[] = {4};
    Ref<Mesh> m = new Mesh(positionsVB({0, 0, 0, 10, 0, 0, 0, 10, 0, 10, 10, 0}), new TriangleStripArray(0, lengths),
                           new Appearance());
    Ref<Group> g = new Group();
    g->addChild(m);
    EXPECT_TRUE(g->pick(-1, 2, 3, 5, 0, 0, -1, nullptr));
    EXPECT_TRUE(g->pick(-1, 8, 8, 5, 0, 0, -1, nullptr));
    EXPECT_FALSE(g->pick(-1, 2, 3, -5, 0, 0, 1, nullptr));
    EXPECT_FALSE(g->pick(-1, 8, 8, -5, 0, 0, 1, nullptr));
}

TEST(PickRay, DegenerateTrianglesAreIgnored) {
    // Triangle 0: repeated index; triangle 1: three collinear points on the
    // x axis, which the ray (in their line's vertical plane) crosses at
    // (5, 0, 0); triangle 2: the real one at z = -4.
    Ref<VertexBuffer> vb =
        positionsVB({0, 0, 0, 5, 0, 0, 10, 0, 0, 0, -10, -4, 20, -10, -4, 0, 10, -4});
    Ref<Mesh> m = new Mesh(vb, triangles({0, 0, 2, 0, 1, 2, 3, 4, 5}), culled(PolygonMode::CULL_NONE));
    Ref<Group> g = new Group();
    g->addChild(m);
    RayIntersection ri;
    ASSERT_TRUE(g->pick(-1, 5, 0, 2, 0, 0, -1, &ri));
    EXPECT_FLOAT_EQ(ri.getDistance(), 6.0f);
    Ref<Mesh> onlyDegenerate = new Mesh(vb, triangles({0, 0, 2, 0, 1, 2}), culled(PolygonMode::CULL_NONE));
    Ref<Group> g2 = new Group();
    g2->addChild(onlyDegenerate);
    EXPECT_FALSE(g2->pick(-1, 5, 0, 2, 0, 0, -1, &ri));
    EXPECT_FALSE(g2->pick(-1, 0, 0, 2, 0, 0, -1, &ri));  // through the shared vertex
}

TEST(PickRay, RayStartingInsideTheMeshBounds) {
    // Floor at z = -5 and ceiling at z = 5 in one mesh (both sides pickable);
    // the ray starts between them, inside the mesh's bounding box.
    Ref<VertexBuffer> vb = positionsVB({0, 0, -5, 10, 0, -5, 0, 10, -5, 0, 0, 5, 10, 0, 5, 0, 10, 5});
    Ref<Group> g = new Group();
    g->addChild(new Mesh(vb, triangles({0, 1, 2, 3, 4, 5}), culled(PolygonMode::CULL_NONE)));
    RayIntersection ri;
    ASSERT_TRUE(pickDown(*g, 1, &ri));
    EXPECT_FLOAT_EQ(ri.getDistance(), 6.0f);
    ASSERT_TRUE(pickDown(*g, 1, &ri, -1, +0.5f));
    EXPECT_FLOAT_EQ(ri.getDistance(), 8.0f);
    // Sideways from inside: leaves the box without a hit.
    EXPECT_FALSE(g->pick(-1, 2, 3, 1, 1, 0, 0, &ri));
}

TEST(PickRay, TransformsAlongThePath) {
    // root -> mid (translate (0,0,-3), scale 2) -> mesh (triangle at local z = 1).
    // In root space the triangle is (0,0,-1) (20,0,-1) (0,20,-1).
    Ref<Group> root = new Group();
    Ref<Group> mid = new Group();
    mid->setTranslation(0, 0, -3);
    mid->setScale(2, 2, 2);
    Ref<Mesh> m = triangleAt(1);
    root->addChild(mid);
    mid->addChild(m);
    RayIntersection ri;
    ASSERT_TRUE(root->pick(-1, 15, 4, 5, 0, 0, -1, &ri));  // x + y = 19 < 20
    EXPECT_FLOAT_EQ(ri.getDistance(), 6.0f);
    EXPECT_FALSE(root->pick(-1, 15, 6, 5, 0, 0, -1, &ri));
    // Picking from mid: the ray is in mid's space (triangle at z = 1).
    ASSERT_TRUE(mid->pick(-1, 2, 3, 5, 0, 0, -2, &ri));
    EXPECT_FLOAT_EQ(ri.getDistance(), 2.0f);
    // Position scale and bias: scale 0.5, bias (1, 1, -2) gives the triangle
    // (1,1,-2) (6,1,-2) (1,6,-2).
    Ref<Mesh> sb = new Mesh(positionsVB({0, 0, 0, 10, 0, 0, 0, 10, 0}, 0.5f, {1, 1, -2}), triangles({0, 1, 2}),
                            new Appearance());
    Ref<Group> g = new Group();
    g->addChild(sb);
    ASSERT_TRUE(g->pick(-1, 1.5f, 1.5f, 0, 0, 0, -1, &ri));
    EXPECT_FLOAT_EQ(ri.getDistance(), 2.0f);
    EXPECT_FALSE(g->pick(-1, 0.5f, 1.5f, 0, 0, 0, -1, &ri));
}

TEST(PickRay, TextureCoordinatesWithScaleBiasAndTextureTransform) {
    // Texcoords (raw) v0 (0,0), v1 (10,0), v2 (0,10); at (2, 3) the weights
    // are 0.5, 0.2, 0.3, so the raw interpolation is (2, 3).
    Ref<VertexBuffer> vb = positionsVB({0, 0, 0, 10, 0, 0, 0, 10, 0});
    Ref<VertexArray> tc = shortArray({0, 0, 10, 0, 0, 10}, 2);
    const float bias0[] = {0.5f, 0.25f};
    vb->setTexCoords(0, tc, 0.1f, bias0);  // (0.2 + 0.5, 0.3 + 0.25) = (0.7, 0.55)
    vb->setTexCoords(1, tc, 1.0f, {});     // (2, 3)
    Ref<Image2D> img = new Image2D(Image2D::RGB, 4, 4);
    Ref<Texture2D> t0 = new Texture2D(img);
    t0->setTranslation(1, 2, 0);
    t0->setScale(2, 2, 1);  // T S: (2 * 0.7 + 1, 2 * 0.55 + 2) = (2.4, 3.1)
    Ref<Texture2D> t1 = new Texture2D(img);
    Transform q;  // projective: q = 2 -> (1, 1.5)
    q.at(3, 3) = 2.0f;
    t1->setTransform(&q);
    Ref<Appearance> app = new Appearance();
    app->setTexture(0, t0);
    app->setTexture(1, t1);
    Ref<Mesh> m = new Mesh(vb, triangles({0, 1, 2}), app);
    Ref<Group> g = new Group();
    g->addChild(m);
    RayIntersection ri;
    ASSERT_TRUE(pickDown(*g, 1, &ri));
    EXPECT_NEAR(ri.getTextureS(0), 2.4f, 1e-5f);
    EXPECT_NEAR(ri.getTextureT(0), 3.1f, 1e-5f);
    EXPECT_NEAR(ri.getTextureS(1), 1.0f, 1e-5f);
    EXPECT_NEAR(ri.getTextureT(1), 1.5f, 1e-5f);
    // Without a texture on the unit: scale and bias only.
    app->setTexture(0, nullptr);
    ASSERT_TRUE(pickDown(*g, 1, &ri));
    EXPECT_NEAR(ri.getTextureS(0), 0.7f, 1e-5f);
    EXPECT_NEAR(ri.getTextureT(0), 0.55f, 1e-5f);
    // A unit without texture coordinates reports 0 even with a texture.
    vb->setTexCoords(1, nullptr, 1.0f, {});
    ASSERT_TRUE(pickDown(*g, 1, &ri));
    EXPECT_EQ(ri.getTextureS(1), 0.0f);
    EXPECT_EQ(ri.getTextureT(1), 0.0f);
}

TEST(PickRay, ThirdTextureCoordinateGoesThroughTheMatrix) {
    // (s, t, r) per vertex: v0 (0,0,4), v1 (10,0,4), v2 (0,10,4); the matrix
    // adds r to s: s' = s + r = 2 + 4.
    Ref<VertexBuffer> vb = positionsVB({0, 0, 0, 10, 0, 0, 0, 10, 0});
    vb->setTexCoords(0, shortArray({0, 0, 4, 10, 0, 4, 0, 10, 4}, 3), 1.0f, {});
    Ref<Texture2D> tex = new Texture2D(new Image2D(Image2D::RGB, 4, 4));
    Transform m;
    m.at(0, 2) = 1.0f;
    tex->setTransform(&m);
    Ref<Appearance> app = new Appearance();
    app->setTexture(0, tex);
    Ref<Group> g = new Group();
    g->addChild(new Mesh(vb, triangles({0, 1, 2}), app));
    RayIntersection ri;
    ASSERT_TRUE(pickDown(*g, 1, &ri));
    EXPECT_NEAR(ri.getTextureS(0), 6.0f, 1e-5f);
    EXPECT_NEAR(ri.getTextureT(0), 3.0f, 1e-5f);
}

TEST(PickRay, NormalIsInterpolatedNormalisedAndLocal) {
    // Short normals v0 +z, v1 +x, v2 +y (32767 ~ 1): at weights 0.5, 0.2, 0.3
    // the interpolation is (0.2, 0.3, 0.5), normalised by sqrt(0.38).
    Ref<VertexBuffer> vb = positionsVB({0, 0, 0, 10, 0, 0, 0, 10, 0});
    vb->setNormals(shortArray({0, 0, 32767, 32767, 0, 0, 0, 32767, 0}, 3));
    Ref<Mesh> m = new Mesh(vb, triangles({0, 1, 2}), culled(PolygonMode::CULL_NONE));
    Ref<Group> g = new Group();
    g->addChild(m);
    RayIntersection ri;
    ASSERT_TRUE(pickDown(*g, 1, &ri));
    const float len = std::sqrt(0.38f);
    EXPECT_NEAR(ri.getNormalX(), 0.2f / len, 1e-4f);
    EXPECT_NEAR(ri.getNormalY(), 0.3f / len, 1e-4f);
    EXPECT_NEAR(ri.getNormalZ(), 0.5f / len, 1e-4f);
    // Rotating the mesh 180 degrees about Y (x -> -x, z -> -z): pick the same
    // local point (2, 3) at world (-2, 3); the normal stays in local space.
    m->setOrientation(180, 0, 1, 0);
    ASSERT_TRUE(g->pick(-1, -2, 3, 1, 0, 0, -1, &ri));
    EXPECT_NEAR(ri.getNormalX(), 0.2f / len, 1e-4f);
    EXPECT_NEAR(ri.getNormalY(), 0.3f / len, 1e-4f);
    EXPECT_NEAR(ri.getNormalZ(), 0.5f / len, 1e-4f);
}

TEST(PickRay, SkinnedMeshIsPickedAtItsDeformedPosition) {
    // The triangle at z = 0 is bound (at rest) to one bone; moving the bone
    // by (20, 0, -4) moves the skinned triangle to (20,0,-4) (30,0,-4) (20,10,-4).
    Ref<Group> skeleton = new Group();
    Ref<Group> bone = new Group();
    skeleton->addChild(bone);
    Ref<VertexBuffer> vb = positionsVB({0, 0, 0, 10, 0, 0, 0, 10, 0});
    vb->setNormals(shortArray({0, 0, 32767, 0, 0, 32767, 0, 0, 32767}, 3));
    Ref<SkinnedMesh> m = new SkinnedMesh(vb, triangles({0, 1, 2}), new Appearance(), skeleton);
    m->addTransform(bone, 1, 0, 3);
    Ref<Group> g = new Group();
    g->addChild(m);
    RayIntersection ri;
    ASSERT_TRUE(pickDown(*g, 5, &ri));  // at rest: t = 5
    EXPECT_FLOAT_EQ(ri.getDistance(), 5.0f);
    bone->setTranslation(20, 0, -4);
    EXPECT_FALSE(pickDown(*g, 5, &ri));  // the rest position is empty now
    ASSERT_TRUE(g->pick(-1, 22, 3, 5, 0, 0, -1, &ri));
    EXPECT_EQ(ri.getIntersected().get(), m.get());
    EXPECT_FLOAT_EQ(ri.getDistance(), 9.0f);
    EXPECT_NEAR(ri.getNormalZ(), 1.0f, 1e-5f);
    // Rotating the bone 180 degrees about X turns the triangle over (CW from
    // above): back-face culled from above, hit from below.
    bone->setTranslation(0, 0, 0);
    bone->setOrientation(180, 1, 0, 0);  // (x, y) -> (x, -y)
    EXPECT_FALSE(g->pick(-1, 2, -3, 5, 0, 0, -1, &ri));
    ASSERT_TRUE(g->pick(-1, 2, -3, -5, 0, 0, 1, &ri));
    EXPECT_FLOAT_EQ(ri.getDistance(), 5.0f);
    EXPECT_NEAR(ri.getNormalZ(), -1.0f, 1e-5f);  // the skinned normal
}

TEST(PickRay, SkinnedMeshIsPickedThroughItsDeformedVertexOrder) {
    // Vertex 0 on bone b, vertices 1 and 2 on bone a (added first): the
    // deformed vertices come grouped by influence set (1, 2, then 0;
    // DeformedVertices::order), and the pick reads mesh vertex i where it
    // is. Both bones move by (20, 0, -4): the hit at local (2, 3) has
    // t = 9 and the texture coordinates interpolated there, s = 2, t = 3.
    Ref<Group> skeleton = new Group();
    Ref<Group> a = new Group(), b = new Group();
    skeleton->addChild(a);
    skeleton->addChild(b);
    Ref<VertexBuffer> vb = positionsVB({0, 0, 0, 10, 0, 0, 0, 10, 0});
    vb->setTexCoords(0, shortArray({0, 0, 10, 0, 0, 10}, 2), 1.0f, {});
    Ref<SkinnedMesh> m = new SkinnedMesh(vb, triangles({0, 1, 2}), new Appearance(), skeleton);
    m->addTransform(a, 1, 1, 2);
    m->addTransform(b, 1, 0, 1);
    a->setTranslation(20, 0, -4);
    b->setTranslation(20, 0, -4);
    Ref<Group> g = new Group();
    g->addChild(m);
    RayIntersection ri;
    ASSERT_TRUE(g->pick(-1, 22, 3, 5, 0, 0, -1, &ri));
    EXPECT_FLOAT_EQ(ri.getDistance(), 9.0f);
    EXPECT_NEAR(ri.getTextureS(0), 2.0f, 1e-5f);
    EXPECT_NEAR(ri.getTextureT(0), 3.0f, 1e-5f);
}

TEST(PickRay, MorphingMeshIsPickedAtItsMorphedPosition) {
    // Base at z = 0, target at z = -8 with texcoords shifted by 10 in s;
    // weight 0.5 puts the triangle at z = -4 and adds 5 to s.
    Ref<VertexBuffer> base = positionsVB({0, 0, 0, 10, 0, 0, 0, 10, 0});
    base->setTexCoords(0, shortArray({0, 0, 10, 0, 0, 10}, 2), 1.0f, {});
    Ref<VertexBuffer> target = positionsVB({0, 0, -8, 10, 0, -8, 0, 10, -8});
    target->setTexCoords(0, shortArray({10, 0, 20, 0, 10, 10}, 2), 1.0f, {});
    std::vector<Ref<VertexBuffer>> targets{target};
    Ref<MorphingMesh> m = new MorphingMesh(base, targets, triangles({0, 1, 2}), new Appearance());
    Ref<Group> g = new Group();
    g->addChild(m);
    RayIntersection ri;
    ASSERT_TRUE(pickDown(*g, 5, &ri));
    EXPECT_FLOAT_EQ(ri.getDistance(), 5.0f);
    EXPECT_NEAR(ri.getTextureS(0), 2.0f, 1e-5f);
    const float w[] = {0.5f};
    m->setWeights(w);
    ASSERT_TRUE(pickDown(*g, 5, &ri));
    EXPECT_EQ(ri.getIntersected().get(), m.get());
    EXPECT_FLOAT_EQ(ri.getDistance(), 9.0f);
    EXPECT_NEAR(ri.getTextureS(0), 7.0f, 1e-5f);
    EXPECT_NEAR(ri.getTextureT(0), 3.0f, 1e-5f);
}

TEST(PickRay, SpritesAreNeverHitByTheRayVariant) {
    Ref<Group> g = new Group();
    Ref<Sprite3D> s = new Sprite3D(true, new Image2D(Image2D::RGB, 4, 4), new Appearance());
    s->setTranslation(0, 0, -1);
    s->setScale(100, 100, 100);
    g->addChild(s);
    EXPECT_FALSE(g->pick(-1, 0, 0, 5, 0, 0, -1, nullptr));
    Ref<Mesh> m = triangleAt(-3);
    g->addChild(m);
    RayIntersection ri;
    ASSERT_TRUE(pickDown(*g, 5, &ri));
    EXPECT_EQ(ri.getIntersected().get(), m.get());
}

TEST(PickRay, Exceptions) {
    Ref<Group> g = new Group();
    g->addChild(triangleAt(0));
    expectThrowMentioning<IllegalArgumentException>([&] { g->pick(-1, 0, 0, 0, 0, 0, 0, nullptr); },
                                                    "Group::pick");
    // A candidate without positions.
    Ref<VertexBuffer> noPositions = new VertexBuffer();
    noPositions->setNormals(shortArray({0, 0, 1, 0, 0, 1, 0, 0, 1}, 3));
    Ref<Group> g2 = new Group();
    g2->addChild(new Mesh(noPositions, triangles({0, 1, 2}), new Appearance()));
    expectThrowMentioning<IllegalStateException>([&] { pickDown(*g2, 1); }, "Group::pick");
    // ... but not when it is out of scope.
    g2->getChild(0)->setScope(2);
    EXPECT_FALSE(pickDown(*g2, 1, nullptr, 1));
    // An index past the vertex count.
    Ref<Group> g3 = new Group();
    g3->addChild(new Mesh(positionsVB({0, 0, 0, 10, 0, 0, 0, 10, 0}), triangles({0, 1, 3}), new Appearance()));
    expectThrowMentioning<IllegalStateException>([&] { pickDown(*g3, 1); }, "out of range [0, 3)");
    // A singular transform to the group.
    Ref<Group> g4 = new Group();
    Ref<Mesh> flat = triangleAt(0);
    flat->setScale(1, 1, 0);
    g4->addChild(flat);
    expectThrowMentioning<ArithmeticException>([&] { pickDown(*g4, 1); }, "Group::pick");
}
