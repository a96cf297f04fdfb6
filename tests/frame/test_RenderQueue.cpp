// scene/frame/RenderQueue, the collect step (JSR-184 1.1, Graphics3D.render
// and Node): rendering enable, scope against the camera, the alpha factor
// product along the path, light collection and selection (the first
// maxLights lights whose scope meets the mesh's, as Nokia's
// m3gSelectGLLights), and the drawing order (layer, then opaque before
// blended, then collection order).
#include <gtest/gtest.h>

#include <vector>

#include "FrameTestKit.h"
#include "RenderQueue.h"

using namespace m3g;
using m3g::detail::RenderItem;
using m3g::detail::RenderQueue;
using frametest::appearance;
using frametest::quadMesh;

namespace {

/// A queue reset for an identity camera of `scope` with `maxLights`.
RenderQueue queueFor(int cameraScope = -1, int maxLights = 8) {
    Ref<Camera> cam(new Camera());
    cam->setScope(cameraScope);
    RenderQueue q;
    q.reset(*cam, maxLights);
    return q;
}

/// The collected items' nodes, in the queue's order.
std::vector<const Node*> nodes(const RenderQueue& q) {
    std::vector<const Node*> out;
    for (const RenderItem& i : q.items) out.push_back(i.node);
    return out;
}

std::vector<int> lightsOf(const RenderItem& item) {
    return std::vector<int>(item.lights.begin(), item.lights.begin() + item.lightCount);
}

}  // namespace

// ---- Order ----

TEST(RenderQueue, LayersAscending) {
    Ref<Group> root(new Group());
    Ref<Mesh> m1 = quadMesh(appearance(1).get()), m0 = quadMesh(appearance(0).get()),
              m5 = quadMesh(appearance(-5).get()), m63 = quadMesh(appearance(63).get()),
              mm63 = quadMesh(appearance(-63).get());
    for (Mesh* m : {m1.get(), m0.get(), m5.get(), m63.get(), mm63.get()}) root->addChild(m);
    RenderQueue q = queueFor();
    q.collectNode(*root, Transform());
    // Collection order before sorting.
    EXPECT_EQ(nodes(q), (std::vector<const Node*>{m1.get(), m0.get(), m5.get(), m63.get(), mm63.get()}));
    q.sort();
    EXPECT_EQ(nodes(q), (std::vector<const Node*>{mm63.get(), m5.get(), m0.get(), m1.get(), m63.get()}));
}

TEST(RenderQueue, OpaqueBeforeBlendedWithinALayerOnly) {
    // Same layer: the blended mesh, collected first, is drawn after the
    // opaque one. A blended mesh of a lower layer still comes before an
    // opaque one of a higher layer.
    Ref<Group> root(new Group());
    Ref<Mesh> blended = quadMesh(appearance(0, CompositingMode::ALPHA).get());
    Ref<Mesh> opaque = quadMesh(appearance(0, CompositingMode::REPLACE).get());
    Ref<Mesh> blendedBelow = quadMesh(appearance(-1, CompositingMode::ALPHA).get());
    Ref<Mesh> opaqueAbove = quadMesh(appearance(1).get());
    for (Mesh* m : {opaqueAbove.get(), blended.get(), opaque.get(), blendedBelow.get()}) root->addChild(m);
    RenderQueue q = queueFor();
    q.collectNode(*root, Transform());
    q.sort();
    EXPECT_EQ(nodes(q),
              (std::vector<const Node*>{blendedBelow.get(), opaque.get(), blended.get(), opaqueAbove.get()}));
}

TEST(RenderQueue, EveryModeButReplaceCountsAsBlended) {
    Ref<Group> root(new Group());
    std::vector<Ref<Mesh>> blended;
    for (int mode : {CompositingMode::ALPHA_ADD, CompositingMode::MODULATE, CompositingMode::MODULATE_X2}) {
        blended.push_back(quadMesh(appearance(0, mode).get()));
        root->addChild(blended.back().get());
    }
    // An Appearance without a CompositingMode is opaque (REPLACE).
    Ref<Mesh> plain = quadMesh(Ref<Appearance>(new Appearance()).get());
    root->addChild(plain.get());
    RenderQueue q = queueFor();
    q.collectNode(*root, Transform());
    q.sort();
    EXPECT_EQ(nodes(q), (std::vector<const Node*>{plain.get(), blended[0].get(), blended[1].get(), blended[2].get()}));
}

TEST(RenderQueue, StableCollectionOrderWithinLayerAndKind) {
    // Depth first, children in order: a, (b, (c)), d; all opaque in layer 0,
    // with a blended one in between that must not disturb them.
    Ref<Group> root(new Group()), g1(new Group()), g2(new Group());
    Ref<Appearance> app = appearance(0);
    Ref<Mesh> a = quadMesh(app.get()), b = quadMesh(app.get()), c = quadMesh(app.get()), d = quadMesh(app.get());
    Ref<Mesh> x = quadMesh(appearance(0, CompositingMode::ALPHA).get());
    root->addChild(a.get());
    root->addChild(g1.get());
    g1->addChild(b.get());
    g1->addChild(x.get());
    g1->addChild(g2.get());
    g2->addChild(c.get());
    root->addChild(d.get());
    RenderQueue q = queueFor();
    q.collectNode(*root, Transform());
    q.sort();
    EXPECT_EQ(nodes(q), (std::vector<const Node*>{a.get(), b.get(), c.get(), d.get(), x.get()}));
}

TEST(RenderQueue, SubmeshesInOrderAndThoseWithoutAppearanceSkipped) {
    // Three submeshes: 0 without appearance (not rendered, JSR-184 1.1 Mesh),
    // 1 in layer 2, 2 in layer 1.
    frametest::Quad q0 = frametest::quad();
    const Ref<IndexBuffer> ibs[] = {q0.ib, q0.ib, q0.ib};
    const Ref<Appearance> apps[] = {nullptr, appearance(2), appearance(1)};
    Ref<Mesh> m(new Mesh(q0.vb.get(), ibs, apps));
    RenderQueue q = queueFor();
    q.collectNode(*m, Transform());
    ASSERT_EQ(q.items.size(), 2u);
    EXPECT_EQ(q.items[0].submesh, 1);
    EXPECT_EQ(q.items[1].submesh, 2);
    EXPECT_EQ(q.items[0].appearance, apps[1].get());
    q.sort();
    EXPECT_EQ(q.items[0].submesh, 2);
    EXPECT_EQ(q.items[1].submesh, 1);
}

// ---- Scope, rendering enable, alpha factor ----

TEST(RenderQueue, NodeScopeMustMeetTheCameraScope) {
    Ref<Group> root(new Group());
    Ref<Appearance> app = appearance();
    Ref<Mesh> s1 = quadMesh(app.get()), s2 = quadMesh(app.get()), s6 = quadMesh(app.get()), s0 = quadMesh(app.get());
    s1->setScope(1);
    s2->setScope(2);
    s6->setScope(6);
    s0->setScope(0);
    for (Mesh* m : {s1.get(), s2.get(), s6.get(), s0.get()}) root->addChild(m);
    RenderQueue q = queueFor(5);  // 0b101: meets 1 and 6 (0b110), not 2 or 0
    q.collectNode(*root, Transform());
    EXPECT_EQ(nodes(q), (std::vector<const Node*>{s1.get(), s6.get()}));
    // The default scope -1 meets every camera scope but 0.
    RenderQueue all = queueFor(-1);
    all.collectNode(*root, Transform());
    EXPECT_EQ(all.items.size(), 3u);
}

TEST(RenderQueue, RenderingDisabledSkipsTheSubtree) {
    Ref<Group> root(new Group()), off(new Group()), on(new Group());
    Ref<Appearance> app = appearance();
    Ref<Mesh> under = quadMesh(app.get()), deeper = quadMesh(app.get()), self = quadMesh(app.get()),
              visible = quadMesh(app.get());
    root->addChild(off.get());
    off->addChild(under.get());
    Ref<Group> inner(new Group());
    off->addChild(inner.get());
    inner->addChild(deeper.get());
    root->addChild(on.get());
    on->addChild(self.get());
    on->addChild(visible.get());
    off->setRenderingEnable(false);
    self->setRenderingEnable(false);
    RenderQueue q = queueFor();
    q.collectNode(*root, Transform());
    EXPECT_EQ(nodes(q), (std::vector<const Node*>{visible.get()}));
    // The root itself disabled: nothing.
    root->setRenderingEnable(false);
    RenderQueue none = queueFor();
    none.collectNode(*root, Transform());
    EXPECT_TRUE(none.items.empty());
}

TEST(RenderQueue, AlphaFactorIsTheProductAlongThePath) {
    // root 0.5 -> group 0.5 -> mesh 0.8: 0.2; root -> mesh 1: 0.5 (the root's
    // own factor counts); the caller's factor multiplies in too.
    Ref<Group> root(new Group()), group(new Group());
    root->setAlphaFactor(0.5f);
    group->setAlphaFactor(0.5f);
    Ref<Appearance> app = appearance();
    Ref<Mesh> deep = quadMesh(app.get()), shallow = quadMesh(app.get());
    deep->setAlphaFactor(0.8f);
    root->addChild(group.get());
    group->addChild(deep.get());
    root->addChild(shallow.get());
    RenderQueue q = queueFor();
    q.collectNode(*root, Transform());
    ASSERT_EQ(q.items.size(), 2u);
    EXPECT_FLOAT_EQ(q.items[0].alphaFactor, 0.2f);
    EXPECT_FLOAT_EQ(q.items[1].alphaFactor, 0.5f);
    RenderQueue scaled = queueFor();
    scaled.collectNode(*root, Transform(), 0.5f);
    EXPECT_FLOAT_EQ(scaled.items[0].alphaFactor, 0.1f);
    // A zero factor anywhere on the path gives zero (still collected: JSR-184 blends, it does not skip).
    group->setAlphaFactor(0.0f);
    RenderQueue zero = queueFor();
    zero.collectNode(*root, Transform());
    ASSERT_EQ(zero.items.size(), 2u);
    EXPECT_EQ(zero.items[0].alphaFactor, 0.0f);
}

TEST(RenderQueue, ModelViewAccumulatesChildTransforms) {
    // collectNode's transform already includes the node's own; children's
    // transforms multiply in on the right.
    Ref<Group> root(new Group()), group(new Group());
    group->setTranslation(1, 0, 0);
    group->setScale(2, 2, 2);
    Ref<Mesh> m = quadMesh(appearance().get());
    m->setTranslation(0, 3, 0);
    root->addChild(group.get());
    group->addChild(m.get());
    RenderQueue q = queueFor();
    q.collectNode(*root, frametest::translation(0, 0, -10));
    ASSERT_EQ(q.items.size(), 1u);
    // (0, 0, -10) + (1, 0, 0) + 2 * (0, 3, 0) = (1, 6, -10); scale 2.
    const Transform& mv = q.items[0].modelView;
    EXPECT_FLOAT_EQ(mv.at(0, 3), 1.0f);
    EXPECT_FLOAT_EQ(mv.at(1, 3), 6.0f);
    EXPECT_FLOAT_EQ(mv.at(2, 3), -10.0f);
    EXPECT_FLOAT_EQ(mv.at(0, 0), 2.0f);
}

TEST(RenderQueue, SkeletonOfASkinnedMeshIsPartOfItsSubtree) {
    // A Mesh attached to a bone renders with the SkinnedMesh (its children are the skeleton).
    frametest::Quad q0 = frametest::quad();
    Ref<Group> skeleton(new Group()), bone(new Group());
    skeleton->addChild(bone.get());
    Ref<Mesh> attached = quadMesh(appearance().get());
    bone->addChild(attached.get());
    bone->setTranslation(0, 0, -1);
    Ref<SkinnedMesh> skinned(new SkinnedMesh(q0.vb.get(), q0.ib.get(), appearance().get(), skeleton.get()));
    RenderQueue q = queueFor();
    q.collectNode(*skinned, Transform());
    EXPECT_EQ(nodes(q), (std::vector<const Node*>{skinned.get(), attached.get()}));
    EXPECT_FLOAT_EQ(q.items[1].modelView.at(2, 3), -1.0f);
}

// ---- Sprites ----

TEST(RenderQueue, SpritesAreCollectedAndSortedWithMeshes) {
    Ref<Group> root(new Group());
    Ref<Image2D> img = frametest::image(Image2D::RGB, 4, 4);
    Ref<Sprite3D> sprite(new Sprite3D(false, img.get(), appearance(-1).get()));
    sprite->setAlphaFactor(0.25f);
    Ref<Sprite3D> noAppearance(new Sprite3D(false, img.get(), nullptr));
    Ref<Sprite3D> outOfScope(new Sprite3D(false, img.get(), appearance().get()));
    outOfScope->setScope(2);
    Ref<Mesh> mesh = quadMesh(appearance(0).get());
    for (Node* n : std::initializer_list<Node*>{mesh.get(), noAppearance.get(), outOfScope.get(), sprite.get()})
        root->addChild(n);
    RenderQueue q = queueFor(1);
    q.collectNode(*root, Transform());
    q.sort();
    ASSERT_EQ(nodes(q), (std::vector<const Node*>{sprite.get(), mesh.get()}));
    EXPECT_EQ(q.items[0].kind, RenderItem::Kind::Sprite);
    EXPECT_EQ(q.items[0].appearance, sprite->getAppearance().get());
    EXPECT_FLOAT_EQ(q.items[0].alphaFactor, 0.25f);
    EXPECT_EQ(q.items[0].vertices, nullptr);
    EXPECT_EQ(q.items[1].kind, RenderItem::Kind::Submesh);
}

// ---- Lights ----

TEST(RenderQueue, LightsCollectedOnlyFromEnabledPathsWithTheirWorldTransform) {
    Ref<World> world = frametest::worldWithCamera();
    Ref<Light> top = frametest::light(Light::OMNI), nested = frametest::light(Light::OMNI),
               hiddenByGroup = frametest::light(Light::OMNI), hiddenItself = frametest::light(Light::OMNI);
    Ref<Group> g(new Group()), off(new Group());
    g->setTranslation(1, 0, 0);
    nested->setTranslation(0, 2, 0);
    off->setRenderingEnable(false);
    hiddenItself->setRenderingEnable(false);
    world->addChild(top.get());
    world->addChild(g.get());
    g->addChild(nested.get());
    world->addChild(off.get());
    off->addChild(hiddenByGroup.get());
    world->addChild(hiddenItself.get());
    std::vector<Graphics3D::LightEntry> found;
    m3g::detail::collectLights(*world, Transform(), found);
    ASSERT_EQ(found.size(), 2u);
    EXPECT_EQ(found[0].light.get(), top.get());
    EXPECT_EQ(found[1].light.get(), nested.get());
    EXPECT_FLOAT_EQ(found[1].toWorld.at(0, 3), 1.0f);
    EXPECT_FLOAT_EQ(found[1].toWorld.at(1, 3), 2.0f);
}

TEST(RenderQueue, TheFirstMaxLightsLightsInCollectionOrder) {
    RenderQueue q = queueFor(-1, 3);
    std::vector<Ref<Light>> lights;
    for (int i = 0; i < 5; ++i) {
        lights.push_back(frametest::light(Light::AMBIENT, 0x010101 * (i + 1)));
        q.addLight(*lights.back(), Transform());
    }
    Ref<Mesh> m = quadMesh(appearance().get());
    q.collectNode(*m, Transform());
    ASSERT_EQ(q.items.size(), 1u);
    EXPECT_EQ(lightsOf(q.items[0]), (std::vector<int>{0, 1, 2}));
}

TEST(RenderQueue, LightScopeMustMeetTheMeshScope) {
    // Light scopes 2, 1, 2, 6, 2; a mesh of scope 2 with maxLights 3 takes
    // lights 0, 2 and 3 (6 & 2 != 0), not 1 and not the fifth (over the limit).
    // The camera's scope plays no part in the choice.
    RenderQueue q = queueFor(-1, 3);
    std::vector<Ref<Light>> lights;
    for (int scope : {2, 1, 2, 6, 2}) {
        lights.push_back(frametest::light(Light::AMBIENT, 0xFFFFFF, 1.0f, scope));
        q.addLight(*lights.back(), Transform());
    }
    Ref<Mesh> m = quadMesh(appearance().get());
    m->setScope(2);
    q.collectNode(*m, Transform());
    ASSERT_EQ(q.items.size(), 1u);
    EXPECT_EQ(lightsOf(q.items[0]), (std::vector<int>{0, 2, 3}));
    // A mesh of scope 1 meets only light 1.
    Ref<Mesh> m1 = quadMesh(appearance().get());
    m1->setScope(1);
    q.collectNode(*m1, Transform());
    EXPECT_EQ(lightsOf(q.items[1]), (std::vector<int>{1}));
}

TEST(RenderQueue, ImmediateModeSelectsLightsByTheGivenScope) {
    RenderQueue q = queueFor();
    Ref<Light> a = frametest::light(Light::AMBIENT, 0xFFFFFF, 1.0f, 4);
    Ref<Light> b = frametest::light(Light::AMBIENT, 0xFFFFFF, 1.0f, 8);
    q.addLight(*a, Transform());
    q.addLight(*b, Transform());
    frametest::Quad quad = frametest::quad();
    Ref<Appearance> app = appearance(3);
    q.addSubmesh(quad.vb.get(), quad.ib.get(), app.get(), frametest::translation(0, 0, -2), 8);
    ASSERT_EQ(q.items.size(), 1u);
    const RenderItem& item = q.items[0];
    EXPECT_EQ(lightsOf(item), (std::vector<int>{1}));
    EXPECT_EQ(item.node, nullptr);
    EXPECT_EQ(item.vertices, quad.vb.get());
    EXPECT_EQ(item.indices, quad.ib.get());
    EXPECT_FLOAT_EQ(item.alphaFactor, 1.0f);
    EXPECT_FLOAT_EQ(item.modelView.at(2, 3), -2.0f);
}

TEST(RenderQueue, MaxLightsIsClampedToTheEightShaderSlots) {
    Ref<Camera> cam(new Camera());
    RenderQueue q;
    q.reset(*cam, 20);
    EXPECT_EQ(q.maxLights, 8);
    q.reset(*cam, -3);
    EXPECT_EQ(q.maxLights, 0);
    // With nine lights in scope and a limit of 8 (getLimits().maxLights'
    // default), the first eight are used.
    q.reset(*cam, getLimits().maxLights);
    std::vector<Ref<Light>> lights;
    for (int i = 0; i < 9; ++i) {
        lights.push_back(frametest::light(Light::AMBIENT));
        q.addLight(*lights.back(), Transform());
    }
    Ref<Mesh> m = quadMesh(appearance().get());
    q.collectNode(*m, Transform());
    EXPECT_EQ(lightsOf(q.items[0]), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
}

TEST(RenderQueue, ResetTakesTheCameraProjectionAndScope) {
    Ref<Camera> cam(new Camera());
    cam->setParallel(4.0f, 2.0f, 1.0f, 3.0f);
    cam->setScope(6);
    RenderQueue q;
    q.items.resize(3);
    q.reset(*cam, 8);
    EXPECT_TRUE(q.items.empty());
    EXPECT_TRUE(q.lights.empty());
    EXPECT_EQ(q.cameraScope, 6);
    // Parallel: x scale 2 / (height * aspect) = 0.25, y scale 2 / height = 0.5,
    // z scale -2 / (far - near) = -1, z offset -(far + near) / (far - near) = -2.
    EXPECT_FLOAT_EQ(q.projection.at(0, 0), 0.25f);
    EXPECT_FLOAT_EQ(q.projection.at(1, 1), 0.5f);
    EXPECT_FLOAT_EQ(q.projection.at(2, 2), -1.0f);
    EXPECT_FLOAT_EQ(q.projection.at(2, 3), -2.0f);
}
