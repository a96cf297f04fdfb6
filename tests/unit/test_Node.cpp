// Transformable, Node and Group semantics (JSR-184 1.1, Transformable, Node,
// Group and World; Node.align).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <m3g/AnimationTrack.h>
#include <m3g/Group.h>
#include <m3g/World.h>

using namespace m3g;

namespace {
void expectPoint(const Transform& t, std::array<float, 3> p, std::array<float, 3> expected, float eps = 1e-5f) {
    std::array<float, 4> v{p[0], p[1], p[2], 1};
    t.transform(v);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(v[i], expected[i], eps) << "component " << i;
}
}  // namespace

TEST(Transformable, Defaults) {
    Ref<Group> g = make<Group>();
    float t[3], s[3], o[4];
    g->getTranslation(t);
    g->getScale(s);
    g->getOrientation(o);
    EXPECT_EQ(t[0], 0); EXPECT_EQ(t[1], 0); EXPECT_EQ(t[2], 0);
    EXPECT_EQ(s[0], 1); EXPECT_EQ(s[1], 1); EXPECT_EQ(s[2], 1);
    EXPECT_EQ(o[0], 0);
    Transform m;
    m.postScale(3, 3, 3);
    g->getTransform(&m);
    EXPECT_TRUE(m == Transform());
}

TEST(Transformable, TranslateAndScaleAccumulate) {
    Ref<Group> g = make<Group>();
    g->setTranslation(1, 2, 3);
    g->translate(1, 1, 1);
    g->setScale(2, 3, 4);
    g->scale(2, 2, 0.5f);
    float t[3], s[3];
    g->getTranslation(t);
    g->getScale(s);
    EXPECT_EQ(t[0], 2); EXPECT_EQ(t[1], 3); EXPECT_EQ(t[2], 4);
    EXPECT_EQ(s[0], 4); EXPECT_EQ(s[1], 6); EXPECT_EQ(s[2], 2);
}

TEST(Transformable, OrientationRoundTrip) {
    Ref<Group> g = make<Group>();
    g->setOrientation(60, 0, 0, 2);
    float o[4];
    g->getOrientation(o);
    EXPECT_NEAR(o[0], 60, 1e-4);
    EXPECT_NEAR(o[1], 0, 1e-6);
    EXPECT_NEAR(o[2], 0, 1e-6);
    EXPECT_NEAR(o[3], 1, 1e-6);
    g->postRotate(30, 0, 0, 1);
    g->getOrientation(o);
    EXPECT_NEAR(o[0], 90, 1e-4);
    g->preRotate(-90, 0, 0, 1);
    g->getOrientation(o);
    EXPECT_NEAR(o[0], 0, 1e-3);
}

TEST(Transformable, ArgumentChecks) {
    Ref<Group> g = make<Group>();
    EXPECT_THROW(g->setOrientation(10, 0, 0, 0), IllegalArgumentException);
    EXPECT_THROW(g->postRotate(10, 0, 0, 0), IllegalArgumentException);
    EXPECT_THROW(g->preRotate(10, 0, 0, 0), IllegalArgumentException);
    EXPECT_NO_THROW(g->setOrientation(0, 0, 0, 0));
    float two[2];
    EXPECT_THROW(g->getOrientation(two), IllegalArgumentException);
    EXPECT_THROW(g->getScale(two), IllegalArgumentException);
    EXPECT_THROW(g->getTranslation(two), IllegalArgumentException);
    EXPECT_THROW(g->getTranslation(std::span<float>()), NullPointerException);
    EXPECT_THROW(g->getTransform(nullptr), NullPointerException);
    EXPECT_THROW(g->getCompositeTransform(nullptr), NullPointerException);
}

TEST(Transformable, NodeRejectsProjectiveMatrix) {
    Ref<Group> g = make<Group>();
    Transform p;
    p.at(3, 2) = -1;
    EXPECT_THROW(g->setTransform(&p), IllegalArgumentException);
    Transform ok;
    ok.postTranslate(1, 2, 3);
    g->setTransform(&ok);
    g->setTransform(nullptr);  // resets M
    Transform m;
    g->getTransform(&m);
    EXPECT_TRUE(m == Transform());
}

// Setting the value a Transformable already holds (bit for bit, the
// orientation after its normalisation) changes nothing and leaves the
// revision alone, so that animate() holding a bone still does not make its
// skinned meshes compose it again; any other value, -0 for +0 included,
// counts as a change.
TEST(Transformable, SettingTheHeldValueKeepsTheRevision) {
    Ref<Group> g = make<Group>();
    g->setTranslation(1, 2, 3);
    g->setScale(2, 2, 0.5f);
    g->setOrientationQuat(0, 0, 3, 4);  // normalised to (0, 0, 0.6, 0.8)
    const auto r = g->getRevision();
    g->setTranslation(1, 2, 3);
    g->setScale(2, 2, 0.5f);
    g->setOrientationQuat(0, 0, 3, 4);
    EXPECT_EQ(g->getRevision(), r);
    g->setTranslation(1, 2, 3.5f);
    EXPECT_GT(g->getRevision(), r);
    const auto r2 = g->getRevision();
    g->setTranslation(0, 0, 0);
    g->setTranslation(-0.0f, 0, 0);
    EXPECT_EQ(g->getRevision(), r2 + 2);
    g->setScale(2, 2, 0.25f);
    EXPECT_EQ(g->getRevision(), r2 + 3);
    g->setOrientationQuat(0, 0, 0, 1);
    EXPECT_EQ(g->getRevision(), r2 + 4);
}

TEST(Transformable, CompositeIsTRSM) {
    // C = T(10,0,0) * Rz(90) * S(2,1,1) * M(translate 0,1,0):
    // p = (1,0,0): M -> (1,1,0); S -> (2,1,0); Rz90 -> (-1,2,0); T -> (9,2,0).
    Ref<Group> g = make<Group>();
    g->setTranslation(10, 0, 0);
    g->setOrientation(90, 0, 0, 1);
    g->setScale(2, 1, 1);
    Transform m;
    m.postTranslate(0, 1, 0);
    g->setTransform(&m);
    Transform c;
    g->getCompositeTransform(&c);
    expectPoint(c, {1, 0, 0}, {9, 2, 0});
}

// The composite T R S M (JSR-184 1.1, Transformable) against the same
// product built with the public Transform API, for random parts; and an
// affine M on a Node, where the product's bottom row is M's.
TEST(Transformable, CompositeIsTranslationRotationScaleThenM) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-2.0f, 2.0f);
    for (int i = 0; i < 50; ++i) {
        Ref<Group> g = make<Group>();
        const float t[3] = {u(rng), u(rng), u(rng)}, s[3] = {u(rng), u(rng), u(rng)};
        const float angle = 90.0f * u(rng), axis[3] = {u(rng), u(rng), u(rng) + 3.0f};
        g->setTranslation(t[0], t[1], t[2]);
        g->setScale(s[0], s[1], s[2]);
        g->setOrientation(angle, axis[0], axis[1], axis[2]);
        Transform m;
        if (i % 2) {
            m.postRotate(40.0f * u(rng), 1, u(rng), 0);
            m.postTranslate(u(rng), u(rng), u(rng));
            m.postScale(1, 0.5f, 2);
            g->setTransform(&m);
        }
        Transform expected;
        expected.postTranslate(t[0], t[1], t[2]);
        expected.postRotate(angle, axis[0], axis[1], axis[2]);
        expected.postScale(s[0], s[1], s[2]);
        expected.postMultiply(&m);
        Transform c;
        g->getCompositeTransform(&c);
        for (int r = 0; r < 4; ++r)
            for (int k = 0; k < 4; ++k)
                EXPECT_NEAR(c.at(r, k), expected.at(r, k), 2e-6f * std::max(1.0f, std::abs(expected.at(r, k))))
                    << "case " << i << " element " << r << "," << k;
    }
}

TEST(Node, Defaults) {
    Ref<Group> g = make<Group>();
    EXPECT_TRUE(g->isRenderingEnabled());
    EXPECT_TRUE(g->isPickingEnabled());
    EXPECT_EQ(g->getAlphaFactor(), 1.0f);
    EXPECT_EQ(g->getScope(), -1);
    EXPECT_EQ(g->getParent(), nullptr);
    EXPECT_EQ(g->getAlignmentTarget(Node::Z_AXIS), Node::NONE);
    EXPECT_EQ(g->getAlignmentTarget(Node::Y_AXIS), Node::NONE);
    EXPECT_EQ(g->getAlignmentReference(Node::Z_AXIS), nullptr);
}

TEST(Node, SettersAndChecks) {
    Ref<Group> g = make<Group>();
    g->setAlphaFactor(0.25f);
    EXPECT_EQ(g->getAlphaFactor(), 0.25f);
    EXPECT_THROW(g->setAlphaFactor(-0.01f), IllegalArgumentException);
    EXPECT_THROW(g->setAlphaFactor(1.01f), IllegalArgumentException);
    EXPECT_THROW(g->setAlphaFactor(NAN), IllegalArgumentException);
    g->setRenderingEnable(false);
    g->setPickingEnable(false);
    g->setScope(0x10);
    EXPECT_FALSE(g->isRenderingEnabled());
    EXPECT_FALSE(g->isPickingEnabled());
    EXPECT_EQ(g->getScope(), 0x10);
    EXPECT_THROW(g->getAlignmentTarget(Node::X_AXIS), IllegalArgumentException);
    EXPECT_THROW(g->getAlignmentReference(Node::ORIGIN), IllegalArgumentException);
}

TEST(Node, SetAlignmentChecks) {
    Ref<Group> root = make<Group>();
    Ref<Group> a = make<Group>(), b = make<Group>();
    root->addChild(a);
    root->addChild(b);
    EXPECT_THROW(a->setAlignment(b, 999, nullptr, Node::NONE), IllegalArgumentException);
    EXPECT_THROW(a->setAlignment(b, Node::ORIGIN, nullptr, 143), IllegalArgumentException);
    EXPECT_THROW(a->setAlignment(a, Node::ORIGIN, nullptr, Node::NONE), IllegalArgumentException);
    EXPECT_THROW(a->setAlignment(b, Node::Z_AXIS, b, Node::Z_AXIS), IllegalArgumentException);
    EXPECT_THROW(a->setAlignment(nullptr, Node::ORIGIN, nullptr, Node::ORIGIN), IllegalArgumentException);
    a->setAlignment(b, Node::ORIGIN, b, Node::Y_AXIS);
    EXPECT_EQ(a->getAlignmentReference(Node::Z_AXIS), b);
    EXPECT_EQ(a->getAlignmentTarget(Node::Y_AXIS), Node::Y_AXIS);
    // A reference with target NONE is discarded.
    a->setAlignment(b, Node::NONE, b, Node::Y_AXIS);
    EXPECT_EQ(a->getAlignmentReference(Node::Z_AXIS), nullptr);
    EXPECT_EQ(a->getAlignmentReference(Node::Y_AXIS), b);
}

TEST(Node, AlignZToOrigin) {
    // Node at (0,0,0) with its Z axis aimed at a target at (0,10,0): +Z must
    // map to +Y in parent space.
    Ref<Group> root = make<Group>();
    Ref<Group> n = make<Group>(), target = make<Group>();
    root->addChild(n);
    root->addChild(target);
    target->setTranslation(0, 10, 0);
    n->setAlignment(target, Node::ORIGIN, nullptr, Node::NONE);
    n->align(nullptr);
    Transform c;
    n->getCompositeTransform(&c);
    std::array<float, 4> z{0, 0, 1, 0};
    c.transform(z);
    EXPECT_NEAR(z[0], 0, 1e-5);
    EXPECT_NEAR(z[1], 1, 1e-5);
    EXPECT_NEAR(z[2], 0, 1e-5);
}

TEST(Node, AlignZThenYKeepsZExact) {
    // Z to the reference's origin at (10,0,0) (so +Z -> +X), Y towards the
    // reference's Y axis (0,1,0): +Y must stay +Y, +X must become -Z.
    Ref<Group> root = make<Group>();
    Ref<Group> n = make<Group>(), ref = make<Group>();
    root->addChild(n);
    root->addChild(ref);
    ref->setTranslation(10, 0, 0);
    n->setAlignment(ref, Node::ORIGIN, ref, Node::Y_AXIS);
    n->align(nullptr);
    Transform c;
    n->getCompositeTransform(&c);
    std::array<float, 12> axes{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0};
    c.transform(axes);
    EXPECT_NEAR(axes[0], 1, 1e-5);   // Z -> +X
    EXPECT_NEAR(axes[5], 1, 1e-5);   // Y -> +Y
    EXPECT_NEAR(axes[10], -1, 1e-5); // X -> -Z
}

TEST(Node, AlignNullReferenceResolvesToArgument) {
    Ref<Group> root = make<Group>();
    Ref<Group> n = make<Group>(), cam = make<Group>();
    root->addChild(n);
    root->addChild(cam);
    cam->setTranslation(0, 0, -5);
    n->setAlignment(nullptr, Node::ORIGIN, nullptr, Node::NONE);
    EXPECT_THROW(n->align(nullptr), IllegalStateException);
    n->align(cam);
    Transform c;
    n->getCompositeTransform(&c);
    std::array<float, 4> z{0, 0, 1, 0};
    c.transform(z);
    EXPECT_NEAR(z[2], -1, 1e-5);
}

TEST(Node, AlignExceptions) {
    Ref<Group> root = make<Group>(), other = make<Group>();
    Ref<Group> n = make<Group>(), child = make<Group>();
    root->addChild(n);
    n->addChild(child);
    EXPECT_THROW(n->align(other), IllegalArgumentException);  // other scene graph
    n->setAlignment(child, Node::ORIGIN, nullptr, Node::NONE);
    EXPECT_THROW(n->align(nullptr), IllegalStateException);   // reference is a descendant
    n->setAlignment(other, Node::ORIGIN, nullptr, Node::NONE);
    EXPECT_THROW(n->align(nullptr), IllegalStateException);   // reference in another graph
}

TEST(Node, GetTransformToHandComputed) {
    // root -> a (translate 1,0,0) -> b (scale 2); root -> c (translate 0,5,0).
    // b->c maps p to T(0,-5,0) T(1,0,0) S(2) p.
    Ref<Group> root = make<Group>(), a = make<Group>(), b = make<Group>(), c = make<Group>();
    root->addChild(a);
    a->addChild(b);
    root->addChild(c);
    a->setTranslation(1, 0, 0);
    b->setScale(2, 2, 2);
    c->setTranslation(0, 5, 0);
    Transform t;
    ASSERT_TRUE(b->getTransformTo(c, &t));
    expectPoint(t, {1, 1, 1}, {3, -3, 2});
    ASSERT_TRUE(c->getTransformTo(b, &t));
    expectPoint(t, {3, -3, 2}, {1, 1, 1});
    // To an ancestor (no inverse taken): T(1,0,0) S(2).
    ASSERT_TRUE(b->getTransformTo(root, &t));
    expectPoint(t, {1, 1, 1}, {3, 2, 2});
    ASSERT_TRUE(b->getTransformTo(a, &t));
    expectPoint(t, {1, 1, 1}, {2, 2, 2});
    ASSERT_TRUE(b->getTransformTo(b, &t));
    EXPECT_TRUE(t == Transform());
}

TEST(Node, GetTransformToOtherGraphAndErrors) {
    Ref<Group> a = make<Group>(), b = make<Group>();
    Transform t;
    t.postScale(7, 7, 7);
    const Transform before = t;
    EXPECT_FALSE(a->getTransformTo(b, &t));
    EXPECT_TRUE(t == before);
    EXPECT_THROW(a->getTransformTo(nullptr, &t), NullPointerException);
    EXPECT_THROW(a->getTransformTo(b, nullptr), NullPointerException);
    Ref<Group> root = make<Group>();
    root->addChild(a);
    root->addChild(b);
    b->setScale(0, 1, 1);
    EXPECT_THROW(a->getTransformTo(b, &t), ArithmeticException);
}

TEST(Node, AnimatedPropertiesUseSetterSemantics) {
    Ref<Group> g = make<Group>();
    EXPECT_TRUE(g->isAnimatable(AnimationTrack::ALPHA));
    EXPECT_TRUE(g->isAnimatable(AnimationTrack::ORIENTATION));
    EXPECT_FALSE(g->isAnimatable(AnimationTrack::FIELD_OF_VIEW));
    const float big[] = {1.5f};
    g->updateProperty(AnimationTrack::ALPHA, big);
    EXPECT_EQ(g->getAlphaFactor(), 1.0f);
    const float low[] = {0.49f};
    g->updateProperty(AnimationTrack::VISIBILITY, low);
    EXPECT_FALSE(g->isRenderingEnabled());
    const float half[] = {0.5f};
    g->updateProperty(AnimationTrack::PICKABILITY, half);
    EXPECT_TRUE(g->isPickingEnabled());
    const float uniform[] = {3.0f};
    g->updateProperty(AnimationTrack::SCALE, uniform);
    float s[3];
    g->getScale(s);
    EXPECT_EQ(s[0], 3); EXPECT_EQ(s[1], 3); EXPECT_EQ(s[2], 3);
    const float q[] = {0, 0, 2, 0};  // unnormalised 180 degrees about Z
    g->updateProperty(AnimationTrack::ORIENTATION, q);
    float o[4];
    g->getOrientation(o);
    EXPECT_NEAR(o[0], 180, 1e-3);
    EXPECT_NEAR(o[3], 1, 1e-5);
}

TEST(Group, AddRemoveChildren) {
    Ref<Group> g = make<Group>();
    Ref<Group> a = make<Group>(), b = make<Group>();
    g->addChild(a);
    g->addChild(b);
    g->addChild(a);  // re-adding is a no-op
    ASSERT_EQ(g->getChildCount(), 2);
    EXPECT_EQ(g->getChild(0), a);
    EXPECT_EQ(g->getChild(1), b);
    EXPECT_EQ(a->getParent(), g);
    EXPECT_THROW(g->getChild(2), IndexOutOfBoundsException);
    EXPECT_THROW(g->getChild(-1), IndexOutOfBoundsException);
    g->removeChild(a);
    EXPECT_EQ(g->getChildCount(), 1);
    EXPECT_EQ(a->getParent(), nullptr);
    g->removeChild(a);        // not a child: ignored
    g->removeChild(nullptr);  // ignored
    EXPECT_EQ(g->getChildCount(), 1);
}

TEST(Group, AddChildChecks) {
    Ref<Group> g = make<Group>(), other = make<Group>(), child = make<Group>();
    EXPECT_THROW(g->addChild(nullptr), NullPointerException);
    EXPECT_THROW(g->addChild(g), IllegalArgumentException);
    EXPECT_THROW(g->addChild(make<World>()), IllegalArgumentException);
    other->addChild(child);
    EXPECT_THROW(g->addChild(child), IllegalArgumentException);  // different parent
    g->addChild(other);
    Ref<Group> grandchild = make<Group>();
    child->addChild(grandchild);
    EXPECT_THROW(grandchild->addChild(g), IllegalArgumentException);  // ancestor: cycle
}

TEST(Group, ChildOutlivesGroup) {
    Ref<Group> child = make<Group>();
    {
        Ref<Group> g = make<Group>();
        g->addChild(child);
        EXPECT_EQ(child->getRefCount(), 2);
    }
    EXPECT_EQ(child->getParent(), nullptr);
    EXPECT_EQ(child->getRefCount(), 1);
}

TEST(Group, ReparentingMovesChild) {
    Ref<Group> g1 = make<Group>(), g2 = make<Group>(), c = make<Group>();
    g1->addChild(c);
    g1->removeChild(c);
    g2->addChild(c);
    EXPECT_EQ(c->getParent(), g2);
    EXPECT_EQ(g1->getChildCount(), 0);
    EXPECT_EQ(c->getRefCount(), 2);
}

TEST(World, ActiveCameraAndBackgroundDefaults) {
    Ref<World> w = make<World>();
    EXPECT_EQ(w->getActiveCamera(), nullptr);
    EXPECT_EQ(w->getBackground(), nullptr);
    EXPECT_THROW(w->setActiveCamera(nullptr), NullPointerException);
    w->setBackground(nullptr);
    EXPECT_EQ(w->getBackground(), nullptr);
}

// ---- Alignment, every case of JSR-184 1.1, Node.align (hand-computed axes) ----

namespace {

/// Direction of the node's local axis `v` in its parent's space (composite
/// transform applied to (v, 0)).
std::array<float, 3> axisInParent(const Node& n, std::array<float, 3> v) {
    Transform c;
    n.getCompositeTransform(&c);
    std::array<float, 4> d{v[0], v[1], v[2], 0};
    c.transform(d);
    return {d[0], d[1], d[2]};
}

/// Direction of the node's local axis `v` in the coordinates of `to`.
std::array<float, 3> axisIn(const Node& n, const Node& to, std::array<float, 3> v) {
    Transform t;
    EXPECT_TRUE(n.getTransformTo(&to, &t));
    std::array<float, 4> d{v[0], v[1], v[2], 0};
    t.transform(d);
    return {d[0], d[1], d[2]};
}

void expectVec(std::array<float, 3> v, std::array<float, 3> expected, const char* what) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(v[i], expected[i], 1e-5f) << what << " component " << i;
}

constexpr std::array<float, 3> kX{1, 0, 0}, kY{0, 1, 0}, kZ{0, 0, 1};

}  // namespace

TEST(NodeAlign, ZToEachAxisOfARotatedReference) {
    // The reference is turned 90 degrees about Y: its axes in parent space
    // are X -> (0,0,-1), Y -> (0,1,0), Z -> (1,0,0). The node's translation
    // plays no part for axis targets.
    struct Case {
        int target;
        std::array<float, 3> z;
    };
    for (const Case& c : {Case{Node::X_AXIS, {0, 0, -1}}, Case{Node::Y_AXIS, {0, 1, 0}}, Case{Node::Z_AXIS, {1, 0, 0}}}) {
        Ref<Group> root = make<Group>();
        Ref<Group> n = make<Group>(), ref = make<Group>();
        root->addChild(n);
        root->addChild(ref);
        ref->setOrientation(90, 0, 1, 0);
        ref->setTranslation(7, -3, 2);
        n->setTranslation(3, 4, 5);
        n->setAlignment(ref, c.target, nullptr, Node::NONE);
        n->align(nullptr);
        expectVec(axisInParent(*n, kZ), c.z, "Z");
    }
    // Z onto the reference's Z (1,0,0) by the shortest rotation, 90 degrees
    // about +Y: Y stays, X goes to -Z.
    Ref<Group> root = make<Group>();
    Ref<Group> n = make<Group>(), ref = make<Group>();
    root->addChild(n);
    root->addChild(ref);
    ref->setOrientation(90, 0, 1, 0);
    n->setAlignment(ref, Node::Z_AXIS, nullptr, Node::NONE);
    n->align(nullptr);
    expectVec(axisInParent(*n, kY), {0, 1, 0}, "Y");
    expectVec(axisInParent(*n, kX), {0, 0, -1}, "X");
}

TEST(NodeAlign, YOnlyIsTheShortestRotationOfY) {
    Ref<Group> root = make<Group>();
    Ref<Group> n = make<Group>(), ref = make<Group>();
    root->addChild(n);
    root->addChild(ref);
    // Y towards the reference origin at (0,0,10): 90 degrees about +X, so
    // Y -> +Z, Z -> -Y, X stays.
    ref->setTranslation(0, 0, 10);
    n->setAlignment(nullptr, Node::NONE, ref, Node::ORIGIN);
    n->align(nullptr);
    expectVec(axisInParent(*n, kY), {0, 0, 1}, "Y");
    expectVec(axisInParent(*n, kZ), {0, -1, 0}, "Z");
    expectVec(axisInParent(*n, kX), {1, 0, 0}, "X");
    // Y onto the reference's Y axis, the reference turned 90 degrees about Z
    // (its Y is (-1,0,0)): 90 degrees about +Z, so X -> +Y and Z stays.
    ref->setTranslation(0, 0, 0);
    ref->setOrientation(90, 0, 0, 1);
    n->setAlignment(nullptr, Node::NONE, ref, Node::Y_AXIS);
    n->align(nullptr);
    expectVec(axisInParent(*n, kY), {-1, 0, 0}, "Y");
    expectVec(axisInParent(*n, kX), {0, 1, 0}, "X");
    expectVec(axisInParent(*n, kZ), {0, 0, 1}, "Z");
}

TEST(NodeAlign, ZAndYTwistsAboutTheAlignedZ) {
    Ref<Group> root = make<Group>();
    Ref<Group> n = make<Group>(), zRef = make<Group>(), yRef = make<Group>();
    root->addChild(n);
    root->addChild(zRef);
    root->addChild(yRef);
    zRef->setTranslation(10, 0, 0);  // Z -> +X
    // Y towards yRef's Z axis (0,0,1), perpendicular to the new Z: exact,
    // and X = Y x Z = (0,1,0).
    n->setAlignment(zRef, Node::ORIGIN, yRef, Node::Z_AXIS);
    n->align(nullptr);
    expectVec(axisInParent(*n, kZ), {1, 0, 0}, "Z");
    expectVec(axisInParent(*n, kY), {0, 0, 1}, "Y");
    expectVec(axisInParent(*n, kX), {0, 1, 0}, "X");
    // Y towards (1,1,0)/sqrt 2 (yRef turned -45 degrees about Z): only its
    // part across Z, (0,1,0), can be matched; Z stays exact.
    yRef->setOrientation(-45, 0, 0, 1);
    n->setAlignment(zRef, Node::ORIGIN, yRef, Node::Y_AXIS);
    n->align(nullptr);
    expectVec(axisInParent(*n, kZ), {1, 0, 0}, "Z");
    expectVec(axisInParent(*n, kY), {0, 1, 0}, "Y");
    // Y target parallel to the new Z (yRef's X axis = (1,0,0) when
    // unrotated): no twist, the Z-only result (90 degrees about +Y).
    yRef->setOrientation(0, 0, 0, 1);
    n->setOrientation(33, 1, 1, 0);
    n->setAlignment(zRef, Node::ORIGIN, yRef, Node::X_AXIS);
    n->align(nullptr);
    expectVec(axisInParent(*n, kZ), {1, 0, 0}, "Z");
    expectVec(axisInParent(*n, kY), {0, 1, 0}, "Y");
    expectVec(axisInParent(*n, kX), {0, 0, -1}, "X");
}

TEST(NodeAlign, ReplacesOrientationKeepsTranslationAndScale) {
    Ref<Group> root = make<Group>();
    Ref<Group> n = make<Group>(), ref = make<Group>();
    root->addChild(n);
    root->addChild(ref);
    n->setTranslation(1, 2, 3);
    n->setScale(2, 2, 2);
    n->setOrientation(30, 1, 0, 0);
    n->postRotate(50, 0, 0, 1);
    ref->setTranslation(1, 12, 3);  // 10 above the node: Z -> +Y, -90 about X
    n->setAlignment(ref, Node::ORIGIN, nullptr, Node::NONE);
    n->align(nullptr);
    float t[3], s[3];
    n->getTranslation(t);
    n->getScale(s);
    EXPECT_EQ(t[0], 1.0f);
    EXPECT_EQ(t[1], 2.0f);
    EXPECT_EQ(t[2], 3.0f);
    EXPECT_EQ(s[0], 2.0f);
    EXPECT_EQ(s[2], 2.0f);
    // Unit axes scaled by 2; the earlier rotation is gone.
    expectVec(axisInParent(*n, kZ), {0, 2, 0}, "Z");
    expectVec(axisInParent(*n, kX), {2, 0, 0}, "X");
    float aa[4];
    n->getOrientation(aa);
    EXPECT_NEAR(aa[0], 90, 1e-3);
    EXPECT_NEAR(aa[1], -1, 1e-5);
}

TEST(NodeAlign, TargetsAreTakenInTheParentSpace) {
    // parent turned 90 degrees about Z; the reference at world (10,0,0) is at
    // (0,-10,0) in the parent's space, so the node's Z must be (0,-1,0) there
    // and (1,0,0) in the world.
    Ref<Group> root = make<Group>();
    Ref<Group> parent = make<Group>(), n = make<Group>(), ref = make<Group>();
    root->addChild(parent);
    parent->addChild(n);
    root->addChild(ref);
    parent->setOrientation(90, 0, 0, 1);
    ref->setTranslation(10, 0, 0);
    n->setAlignment(ref, Node::ORIGIN, nullptr, Node::NONE);
    root->align(nullptr);
    expectVec(axisInParent(*n, kZ), {0, -1, 0}, "Z (parent)");
    expectVec(axisIn(*n, *root, kZ), {1, 0, 0}, "Z (world)");
}

TEST(NodeAlign, DescendantsAreAlignedAfterTheirAncestors) {
    // p at the origin aims Z at r1 (10,0,0): 90 degrees about +Y. c, at
    // (0,0,5) in p (world (5,0,0)), aims Z at r2 (5,10,0). Computed after p's
    // new orientation, r2 is at (0,10,5) in p's space, (0,10,0) from c: c's Z
    // is +Y in p and in the world, pointing from c at r2.
    Ref<Group> root = make<Group>();
    Ref<Group> p = make<Group>(), c = make<Group>(), r1 = make<Group>(), r2 = make<Group>();
    root->addChild(p);
    p->addChild(c);
    root->addChild(r1);
    root->addChild(r2);
    c->setTranslation(0, 0, 5);
    r1->setTranslation(10, 0, 0);
    r2->setTranslation(5, 10, 0);
    p->setAlignment(r1, Node::ORIGIN, nullptr, Node::NONE);
    c->setAlignment(r2, Node::ORIGIN, nullptr, Node::NONE);
    root->align(nullptr);
    expectVec(axisIn(*p, *root, kZ), {1, 0, 0}, "p Z");
    expectVec(axisIn(*c, *root, kZ), {0, 1, 0}, "c Z");
    expectVec(axisInParent(*c, kZ), {0, 1, 0}, "c Z in p");
}

TEST(NodeAlign, OnlyTheSubtreeOfTheAlignedNode) {
    Ref<Group> root = make<Group>();
    Ref<Group> a = make<Group>(), b = make<Group>(), ref = make<Group>();
    root->addChild(a);
    root->addChild(b);
    root->addChild(ref);
    ref->setTranslation(0, 10, 0);
    a->setAlignment(ref, Node::ORIGIN, nullptr, Node::NONE);
    b->setAlignment(ref, Node::ORIGIN, nullptr, Node::NONE);
    a->align(nullptr);
    expectVec(axisInParent(*a, kZ), {0, 1, 0}, "a Z");
    expectVec(axisInParent(*b, kZ), {0, 0, 1}, "b Z (untouched)");
    // align() on the parent reaches both.
    root->align(nullptr);
    expectVec(axisInParent(*b, kZ), {0, 1, 0}, "b Z");
}

TEST(NodeAlign, NullReferencesResolveToTheArgumentOnBothAxes) {
    Ref<Group> root = make<Group>();
    Ref<Group> n = make<Group>(), cam = make<Group>();
    root->addChild(n);
    root->addChild(cam);
    cam->setTranslation(0, 0, 10);
    cam->setOrientation(90, 0, 0, 1);  // cam's Y axis is (-1,0,0)
    n->setAlignment(nullptr, Node::ORIGIN, nullptr, Node::Y_AXIS);
    n->align(cam);
    expectVec(axisInParent(*n, kZ), {0, 0, 1}, "Z");
    expectVec(axisInParent(*n, kY), {-1, 0, 0}, "Y");
    // Y only, null reference and null argument: ISE.
    n->setAlignment(nullptr, Node::NONE, nullptr, Node::ORIGIN);
    EXPECT_THROW(n->align(nullptr), IllegalStateException);
    n->align(cam);  // Y towards (0,0,10)
    expectVec(axisInParent(*n, kY), {0, 0, 1}, "Y");
}
