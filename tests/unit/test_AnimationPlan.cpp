// animate()'s cached resolution of what it reaches (scene/animation/
// AnimationPlan): after a first animate(), every change that alters what
// animate() reaches — a track added or removed, a controller set, a child
// added or removed, a component or the background or camera replaced — must
// show in the next animate(). Each test changes a scene that has been
// animated, applies the same change to a scene built afresh, and compares
// every animated value of the two over a range of times (forwards and
// backwards), as well as the validity intervals. Changes that alter no
// reference (controller parameters, keyframes) are read live.
#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <vector>

#include <m3g/m3g.h>

#include "AnimationPlan.h"

using namespace m3g;

namespace {

Ref<KeyframeSequence> sequence(int interpolation, const std::vector<std::vector<float>>& keys, int spacing = 100) {
    const int comps = static_cast<int>(keys[0].size());
    Ref<KeyframeSequence> s = make<KeyframeSequence>(static_cast<int>(keys.size()), comps, interpolation);
    for (std::size_t k = 0; k < keys.size(); ++k) s->setKeyframe(static_cast<int>(k), static_cast<int>(k) * spacing, keys[k]);
    s->setDuration(static_cast<int>(keys.size()) * spacing);
    s->setRepeatMode(KeyframeSequence::LOOP);
    return s;
}

Ref<AnimationTrack> attach(Object3D& target, KeyframeSequence* s, int property, AnimationController* c) {
    Ref<AnimationTrack> t = make<AnimationTrack>(s, property);
    t->setController(c);
    target.addAnimationTrack(t);
    return t;
}

Ref<KeyframeSequence> colors() {
    return sequence(KeyframeSequence::LINEAR, {{0.1f, 0.2f, 0.3f}, {0.9f, 0.5f, 0.1f}, {0.3f, 0.8f, 0.6f}});
}
Ref<KeyframeSequence> moves() {
    return sequence(KeyframeSequence::SPLINE, {{0, 0, 0}, {1, 2, 0}, {3, 1, -1}, {0, -1, 2}, {2, 2, 2}});
}
Ref<KeyframeSequence> turns() {
    return sequence(KeyframeSequence::SQUAD,
                    {{0, 0, 0, 1}, {0, 0.38268f, 0, 0.92388f}, {0.5f, 0.5f, 0.5f, 0.5f}, {0.6f, 0, 0, 0.8f}});
}
Ref<KeyframeSequence> angles() { return sequence(KeyframeSequence::STEP, {{40}, {55}, {70}}); }

/// A World with animated nodes, components, background and camera, and
/// animated objects not (yet) in it for the tests to attach.
struct Scene {
    Ref<World> world = make<World>();
    Ref<AnimationController> walk = make<AnimationController>();
    Ref<AnimationController> run = make<AnimationController>();
    Ref<Group> group = make<Group>();
    Ref<AnimationTrack> groupWalk, groupRun, groupTurn;
    Ref<Mesh> mesh;
    Ref<Appearance> appearance = make<Appearance>();
    Ref<Material> material = make<Material>();
    Ref<Background> background = make<Background>();
    Ref<AnimationTrack> backgroundColor;
    Ref<Camera> camera = make<Camera>();
    // Not attached at first.
    Ref<Group> spareGroup = make<Group>();
    Ref<Appearance> spareAppearance = make<Appearance>();
    Ref<Material> spareMaterial = make<Material>();
    Ref<Background> spareBackground = make<Background>();
    Ref<Camera> spareCamera = make<Camera>();
    Ref<Texture2D> texture = make<Texture2D>(make<Image2D>(Image2D::RGB, 4, 4));
    Ref<AnimationController> spareController = make<AnimationController>();

    Scene() {
        run->setSpeed(2.0f, 0);
        run->setWeight(0.5f);
        spareController->setPosition(130.0f, 10);
        spareController->setSpeed(-0.5f, 10);

        groupWalk = attach(*group, moves(), AnimationTrack::TRANSLATION, walk);
        groupRun = attach(*group, moves(), AnimationTrack::TRANSLATION, run);
        groupTurn = attach(*group, turns(), AnimationTrack::ORIENTATION, walk);
        world->addChild(group);

        attach(*material, colors(), AnimationTrack::DIFFUSE_COLOR, walk);
        appearance->setMaterial(material);
        Ref<VertexBuffer> vb = make<VertexBuffer>();
        vb->setPositions(make<VertexArray>(3, 3, 2), 1.0f, {});
        const int lengths[] = {3};
        mesh = make<Mesh>(vb, make<TriangleStripArray>(0, lengths), appearance);
        group->addChild(mesh);

        backgroundColor = attach(*background, colors(), AnimationTrack::COLOR, run);
        world->setBackground(background);

        camera->setPerspective(60, 1, 1, 100);
        attach(*camera, angles(), AnimationTrack::FIELD_OF_VIEW, walk);
        world->addChild(camera);
        world->setActiveCamera(camera);

        attach(*spareGroup, moves(), AnimationTrack::TRANSLATION, run);
        attach(*spareMaterial, colors(), AnimationTrack::EMISSIVE_COLOR, walk);
        spareAppearance->setMaterial(spareMaterial);
        attach(*spareBackground, colors(), AnimationTrack::COLOR, walk);
        spareCamera->setPerspective(50, 1, 1, 100);
        attach(*spareCamera, angles(), AnimationTrack::FIELD_OF_VIEW, run);
        attach(*texture, moves(), AnimationTrack::TRANSLATION, walk);
    }

    /// Every value the scene animates, attached or not.
    std::vector<float> values() const {
        std::vector<float> v;
        auto transform = [&](const Transformable& t) {
            std::array<float, 4> a{};
            t.getTranslation(std::span(a.data(), 3));
            v.insert(v.end(), a.begin(), a.begin() + 3);
            t.getOrientation(a);
            v.insert(v.end(), a.begin(), a.end());
            t.getScale(std::span(a.data(), 3));
            v.insert(v.end(), a.begin(), a.begin() + 3);
        };
        transform(*group);
        transform(*spareGroup);
        transform(*texture);
        for (const Material* m : {material.get(), spareMaterial.get()})
            for (int target : {Material::DIFFUSE, Material::EMISSIVE, Material::SPECULAR})
                v.push_back(float(m->getColor(target)));
        v.push_back(float(background->getColor()));
        v.push_back(float(spareBackground->getColor()));
        for (const Camera* c : {camera.get(), spareCamera.get()}) {
            std::array<float, 4> p{};
            c->getProjection(p);
            v.push_back(p[0]);
        }
        return v;
    }
};

const std::vector<int> kTimes = [] {
    std::vector<int> t;
    for (int i = 0; i < 700; i += 23) t.push_back(i);
    for (int i = 650; i > -120; i -= 71) t.push_back(i);  // backwards, past 0
    return t;
}();

/// Animates a scene, applies `change`, and compares it over kTimes with a
/// fresh scene that had the change made before it was ever animated.
void expectSameAsFresh(const std::function<void(Scene&)>& change) {
    Scene used;
    for (int t = 0; t < 400; t += 17) used.world->animate(t);
    change(used);
    Scene fresh;
    change(fresh);
    for (int t : kTimes) {
        const int validityUsed = used.world->animate(t);
        const int validityFresh = fresh.world->animate(t);
        ASSERT_EQ(validityUsed, validityFresh) << "time " << t;
        ASSERT_EQ(used.values(), fresh.values()) << "time " << t;
    }
}

}  // namespace

TEST(AnimationPlan, AddedTracksAreApplied) {
    expectSameAsFresh([](Scene& s) {
        attach(*s.group, moves(), AnimationTrack::SCALE, s.run);
        attach(*s.material, colors(), AnimationTrack::SPECULAR_COLOR, s.walk);  // reached through components
    });
}

TEST(AnimationPlan, RemovedTracksAreNotApplied) {
    expectSameAsFresh([](Scene& s) {
        s.group->removeAnimationTrack(s.groupWalk);  // the run track still animates the translation
        s.background->removeAnimationTrack(s.backgroundColor);
        s.background->setColor(0x123456);  // must stay
    });
}

TEST(AnimationPlan, RemovedChildIsNotAnimated) {
    expectSameAsFresh([](Scene& s) {
        s.world->removeChild(s.group);
        s.group->setTranslation(7, 8, 9);  // must stay, and so must the material's colour below it
        s.group->setOrientation(30, 0, 0, 1);
        s.material->setColor(Material::DIFFUSE, 0x11223344);
    });
}

TEST(AnimationPlan, AddedChildrenAreAnimated) {
    expectSameAsFresh([](Scene& s) { s.world->addChild(s.spareGroup); });
    expectSameAsFresh([](Scene& s) {
        Ref<Group> inner = make<Group>();
        s.group->addChild(inner);  // below a node that was reached
        inner->addChild(s.spareGroup);
    });
}

TEST(AnimationPlan, ChangedControllersAreUsed) {
    expectSameAsFresh([](Scene& s) {
        s.groupWalk->setController(s.run);
        s.groupTurn->setController(s.spareController);
        s.backgroundColor->setController(nullptr);  // inactive: the colour stays
        s.background->setColor(0x654321);
    });
}

TEST(AnimationPlan, ReplacedComponentsAreAnimated) {
    expectSameAsFresh([](Scene& s) {
        s.mesh->setAppearance(0, s.spareAppearance);
        s.material->setColor(Material::DIFFUSE, 0x10203040);  // no longer reached
    });
    expectSameAsFresh([](Scene& s) {
        s.appearance->setMaterial(s.spareMaterial);
        s.appearance->setTexture(0, s.texture);
        s.material->setColor(Material::DIFFUSE, 0x10203040);
    });
    expectSameAsFresh([](Scene& s) {
        s.world->setBackground(s.spareBackground);
        s.background->setColor(0x0F0F0F);
        s.world->setActiveCamera(s.spareCamera);  // reached only as the active camera
    });
}

TEST(AnimationPlan, ControllerAndSequenceChangesAreReadLive) {
    expectSameAsFresh([](Scene& s) {
        s.walk->setWeight(0.25f);
        s.run->setActiveInterval(0, 300);  // active at the first time compared
        s.walk->setSpeed(3.0f, 50);
        s.run->setPosition(20.0f, 0);
    });
    expectSameAsFresh([](Scene& s) {
        // The sequence the group's walk track samples: fewer valid keys than
        // the segment the last sample used, a new key value and duration.
        Ref<KeyframeSequence> seq = s.groupWalk->getKeyframeSequence();
        seq->setValidRange(0, 1);
        const float key[] = {5, 5, 5};
        seq->setKeyframe(1, 150, key);
        seq->setDuration(320);
        Ref<KeyframeSequence> turn = s.groupTurn->getKeyframeSequence();
        turn->setRepeatMode(KeyframeSequence::CONSTANT);
    });
}

TEST(AnimationPlan, ChangesBetweenAnimateCallsAccumulate) {
    // Remove a child, animate, add it back, animate: each step as fresh.
    Scene used;
    used.world->animate(10);
    used.world->removeChild(used.group);
    used.group->setTranslation(1, 1, 1);
    used.world->animate(20);
    EXPECT_FLOAT_EQ(used.values()[0], 1.0f);
    used.world->addChild(used.group);
    Scene fresh;
    for (int t : kTimes) {
        used.world->animate(t);
        fresh.world->animate(t);
        ASSERT_EQ(used.values(), fresh.values()) << "time " << t;
    }
}

TEST(AnimationPlan, SubtreeAndWorldPlansBothFollowChanges) {
    // Two plans reach the group: the World's and the group's own.
    Scene used, fresh;
    used.world->animate(0);
    used.group->animate(0);
    for (Scene* s : {&used, &fresh}) {
        s->mesh->setAppearance(0, s->spareAppearance);
        s->material->setColor(Material::DIFFUSE, 0x10203040);  // no longer reached
    }
    for (int t : kTimes) {
        used.world->animate(t);
        fresh.world->animate(t);
        ASSERT_EQ(used.values(), fresh.values()) << "time " << t;
        used.group->animate(t + 5);
        fresh.group->animate(t + 5);
        ASSERT_EQ(used.values(), fresh.values()) << "time " << t + 5;
    }
}

TEST(AnimationPlan, DuplicateAnimatesItsOwnGraph) {
    Scene s;
    s.group->setUserID(42);
    s.world->animate(100);
    Ref<World> copy = dynamicCast<World>(s.world->duplicate());
    Ref<Group> copiedGroup = dynamicCast<Group>(copy->find(42));
    ASSERT_TRUE(copiedGroup);
    ASSERT_NE(copiedGroup.get(), s.group.get());
    for (int t : kTimes) {
        copy->animate(t);
        s.world->animate(t + 1);  // the original at another time
        std::array<float, 3> a{}, b{};
        copiedGroup->getTranslation(a);
        s.world->animate(t);
        s.group->getTranslation(b);
        ASSERT_EQ(a, b) << "time " << t;
    }
}

// The cache itself: built once, stale only after a change of what it reached.
TEST(AnimationPlan, StaleOnlyAfterAChangeToAnObjectItReached) {
    Scene s;
    detail::AnimationPlan plan;
    plan.build(*s.world);
    EXPECT_TRUE(plan.current());

    // Objects no plan reached: building another graph, attaching spare objects
    // to each other, adding tracks to them.
    Ref<Group> other = make<Group>();
    other->addChild(make<Group>());
    s.spareAppearance->setTexture(0, s.texture);
    attach(*s.spareGroup, colors(), AnimationTrack::SCALE, s.walk);
    // Reached objects, values only: no reference changes.
    s.group->setTranslation(1, 2, 3);
    s.material->setShininess(3);
    s.walk->setWeight(2);
    s.world->setBackground(s.background);  // the same background again
    s.appearance->setMaterial(s.material);
    EXPECT_TRUE(plan.current());

    s.appearance->setTexture(0, s.texture);  // a reached object's reference
    EXPECT_FALSE(plan.current());
    plan.build(*s.world);
    EXPECT_TRUE(plan.current());
    // The texture is reached now. Its image is not followed (Image2D has no
    // animatable property and no references); a track on it is.
    s.texture->setImage(make<Image2D>(Image2D::RGB, 8, 8));
    EXPECT_TRUE(plan.current());
    attach(*s.texture, colors(), AnimationTrack::COLOR, s.run);
    EXPECT_FALSE(plan.current());
    plan.build(*s.world);
    s.groupTurn->setController(s.walk);  // the same controller
    EXPECT_TRUE(plan.current());
    s.groupTurn->setController(s.run);
    EXPECT_FALSE(plan.current());
}

// What a plan keeps per track between animate() calls: the sequence's
// sampling view (validated, with its SQUAD controls, arcs and SPLINE
// tangents), refreshed when the sequence's revision changes. Every setter of
// the sequence must show in the next animate(), for every interpolation.
TEST(AnimationPlan, SequenceChangesShowForEveryInterpolation) {
    const std::vector<std::vector<float>> quats = {
        {0, 0, 0, 1}, {0, 0.38268f, 0, 0.92388f}, {0.5f, 0.5f, 0.5f, 0.5f}, {0.6f, 0, 0, 0.8f}};
    const std::vector<std::vector<float>> points = {{0, 0, 0}, {1, 2, 0}, {3, 1, -1}, {0, -1, 2}};
    for (int interpolation : {KeyframeSequence::LINEAR, KeyframeSequence::SLERP, KeyframeSequence::SPLINE,
                              KeyframeSequence::SQUAD, KeyframeSequence::STEP}) {
        const bool quaternion = interpolation == KeyframeSequence::SLERP || interpolation == KeyframeSequence::SQUAD;
        const int property = quaternion ? AnimationTrack::ORIENTATION : AnimationTrack::TRANSLATION;
        const std::vector<float> changedKey = quaternion ? std::vector<float>{0, 0, 0.6f, 0.8f} : std::vector<float>{4, 4, 4};
        // Each change after the used group has been animated, then both
        // groups compared, the used one against one never animated.
        const std::vector<std::function<void(KeyframeSequence&)>> changes = {
            [&](KeyframeSequence& s) { s.setKeyframe(1, 100, changedKey); },
            [&](KeyframeSequence& s) { s.setKeyframe(2, 150, changedKey); },  // a new time, too
            [](KeyframeSequence& s) { s.setValidRange(1, 3); },
            [](KeyframeSequence& s) { s.setDuration(520); },
            [](KeyframeSequence& s) { s.setRepeatMode(KeyframeSequence::CONSTANT); },
        };
        for (std::size_t c = 0; c < changes.size(); ++c) {
            Ref<Group> used = make<Group>(), fresh = make<Group>();
            Ref<AnimationController> controller = make<AnimationController>();
            Ref<KeyframeSequence> usedSeq = sequence(interpolation, quaternion ? quats : points);
            Ref<KeyframeSequence> freshSeq = sequence(interpolation, quaternion ? quats : points);
            attach(*used, usedSeq, property, controller);
            attach(*fresh, freshSeq, property, controller);
            std::vector<std::array<float, 4>> before;
            for (int t = 0; t < 700; t += 37) {
                used->animate(t);
                std::array<float, 4> v{};
                quaternion ? used->getOrientation(v) : used->getTranslation(std::span(v.data(), 3));
                before.push_back(v);
            }
            changes[c](*usedSeq);
            changes[c](*freshSeq);
            bool differs = false;
            std::size_t i = 0;
            for (int t = 0; t < 700; t += 37, ++i) {
                ASSERT_EQ(used->animate(t), fresh->animate(t)) << "interpolation " << interpolation << ", change " << c;
                std::array<float, 4> u{}, f{};
                if (quaternion) {
                    used->getOrientation(u);
                    fresh->getOrientation(f);
                } else {
                    used->getTranslation(std::span(u.data(), 3));
                    fresh->getTranslation(std::span(f.data(), 3));
                }
                ASSERT_EQ(u, f) << "interpolation " << interpolation << ", change " << c << ", time " << t;
                differs = differs || u != before[i];
            }
            EXPECT_TRUE(differs) << "interpolation " << interpolation << ", change " << c << " changed nothing";
        }
    }
}

// A sequence that becomes unsampleable after animate() has kept its view
// throws at the next animate(), and at every one until it is fixed.
TEST(AnimationPlan, SequenceMadeInvalidAfterAnimateThrows) {
    Ref<Group> g = make<Group>();
    Ref<KeyframeSequence> s = moves();
    attach(*g, s, AnimationTrack::TRANSLATION, make<AnimationController>());
    g->animate(10);
    const float key[] = {1, 1, 1};
    s->setKeyframe(1, 450, key);  // after key 2 (time 200): times decrease
    EXPECT_THROW(g->animate(20), IllegalStateException);
    EXPECT_THROW(g->animate(30), IllegalStateException);
    s->setKeyframe(1, 150, key);
    EXPECT_NO_THROW(g->animate(150));
    float t[3];
    g->getTranslation(t);
    EXPECT_EQ(t[0], 1.0f);  // key 1's value, at its time
}

// SPLINE through animate(), against the Hermite curve of JSR-184 1.1,
// KeyframeSequence worked by hand: tangents T_out(i) = F+(i) (p(i+1) -
// p(i-1)) / 2 and T_in(i) = F-(i) (p(i+1) - p(i-1)) / 2 with F+(i) =
// 2 d(i) / (d(i-1) + d(i)), F-(i) = 2 d(i-1) / (d(i-1) + d(i)), d(i) the
// length of the segment starting at key i. The tangents are kept per change
// of the sequence: each setter below must recompute them.
TEST(AnimationPlan, SplineTangentsFollowEveryChangeByHand) {
    // x only; keys 0, 10, 30, 20 at times 0, 10, 20, 30, looping over 40.
    Ref<KeyframeSequence> s = make<KeyframeSequence>(4, 3, KeyframeSequence::SPLINE);
    const float p[4] = {0, 10, 30, 20};
    for (int k = 0; k < 4; ++k) {
        const float v[3] = {p[k], 0, 0};
        s->setKeyframe(k, 10 * k, v);
    }
    s->setDuration(40);
    s->setRepeatMode(KeyframeSequence::LOOP);
    Ref<Group> g = make<Group>();
    attach(*g, s, AnimationTrack::TRANSLATION, make<AnimationController>());
    auto xAt = [&](int t) {
        g->animate(t);
        float v[3];
        g->getTranslation(v);
        return v[0];
    };
    // Hermite basis at u = 1/2: h00 = h01 = 1/2, h10 = 1/8, h11 = -1/8.
    // Time 5, segment 0 -> 1, uniform spacing (F = 1): T_out(0) = (10 - 20)/2
    // = -5, T_in(1) = (30 - 0)/2 = 15: 5 - 5/8 - 15/8 = 2.5.
    EXPECT_NEAR(xAt(5), 2.5f, 1e-5f);
    // Key 2 moved to 50: T_in(1) = 25: 5 - 5/8 - 25/8 = 1.25.
    const float v2[3] = {50, 0, 0};
    s->setKeyframe(2, 20, v2);
    EXPECT_NEAR(xAt(5), 1.25f, 1e-5f);
    // Duration 60: the wrap segment 3 -> 0 is 30 long, so F+(0) = 2 * 10 /
    // (30 + 10) = 1/2 and T_out(0) = -2.5; F-(1) stays 1: 5 - 2.5/8 - 25/8 =
    // 1.5625.
    s->setDuration(60);
    EXPECT_NEAR(xAt(5), 1.5625f, 1e-5f);
    // Valid range 1..3 (times 10, 20, 30; the wrap 30 -> 10 + 60 is 40 long).
    // Time 15, segment key 1 -> key 2 (10 -> 50), before it key 3 (20),
    // after it key 3 again: F+(1) = 2 * 10 / (40 + 10) = 0.4, T_out(1) = 0.4
    // (50 - 20)/2 = 6; F-(2) = 1, T_in(2) = (20 - 10)/2 = 5:
    // 30 + 6/8 - 5/8 = 30.125.
    s->setValidRange(1, 3);
    EXPECT_NEAR(xAt(15), 30.125f, 1e-5f);
    // CONSTANT: the end keys' outer tangents are 0 (F = 0 at the ends). Time
    // 15 is segment 1 -> 2 again, T_out(1) = 0 (key 1 is the first),
    // T_in(2) = 5: 30 - 5/8 = 29.375.
    s->setRepeatMode(KeyframeSequence::CONSTANT);
    EXPECT_NEAR(xAt(15), 29.375f, 1e-5f);
}

// Tracks whose every sample is one value (all keys equal, every segment
// flat) are copied rather than sampled once the validity is known to be 0,
// and sampled as usual while it is not. Values and validities by hand: a
// constant track gives its key at every time, before its first key (a
// CONSTANT sequence) it still limits the validity to the time until that
// key, and a key changed later makes it move again.
TEST(AnimationPlan, ConstantTracksGiveTheirKeyAndKeepTheValidity) {
    for (int interpolation : {KeyframeSequence::LINEAR, KeyframeSequence::SPLINE, KeyframeSequence::STEP}) {
        Ref<AnimationController> controller = make<AnimationController>();
        Ref<Group> root = make<Group>(), moving = make<Group>(), still = make<Group>(), later = make<Group>();
        root->addChild(moving);
        root->addChild(still);
        root->addChild(later);
        // `moving` first: an interpolated sample settles the validity at 0
        // before `still` is reached (the walk's order).
        attach(*moving, moves(), AnimationTrack::TRANSLATION, controller);
        Ref<KeyframeSequence> constant = sequence(interpolation, {{2, 3, 4}, {2, 3, 4}, {2, 3, 4}});
        attach(*still, constant, AnimationTrack::TRANSLATION, controller);
        Ref<KeyframeSequence> scale = sequence(interpolation, {{0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}});
        attach(*later, scale, AnimationTrack::SCALE, controller);
        for (int t = 0; t < 400; t += 23) {
            EXPECT_EQ(root->animate(t), 0) << "interpolation " << interpolation << ", time " << t;
            float p[3], s[3];
            still->getTranslation(p);
            later->getScale(s);
            EXPECT_EQ(p[0], 2.0f);
            EXPECT_EQ(p[1], 3.0f);
            EXPECT_EQ(p[2], 4.0f);
            EXPECT_EQ(s[0], 0.5f);
            EXPECT_EQ(s[2], 0.5f);
        }
        // A changed key: the track is no longer constant. At time 150 (half
        // way from key 1 at 100 to key 2 at 200) LINEAR gives the midpoint,
        // STEP key 1, SPLINE its Hermite blend (checked against the midpoint
        // only for being different from the old value).
        const float key[] = {4, 3, 0};
        constant->setKeyframe(2, 200, key);
        root->animate(150);
        float p[3];
        still->getTranslation(p);
        if (interpolation == KeyframeSequence::LINEAR) {
            EXPECT_EQ(p[0], 3.0f);
            EXPECT_EQ(p[2], 2.0f);
        } else if (interpolation == KeyframeSequence::STEP) {
            EXPECT_EQ(p[0], 2.0f);
        } else {
            EXPECT_NE(p[0], 2.0f);
        }
        EXPECT_EQ(p[1], 3.0f);
    }
    // Only constant tracks of CONSTANT sequences, at world time 0 before
    // their first keys (times 100 and 50): the validity is the time to the
    // nearer key, 50, so the second track must still have been sampled.
    Ref<AnimationController> controller = make<AnimationController>();
    Ref<Group> root = make<Group>(), a = make<Group>(), b = make<Group>();
    root->addChild(a);
    root->addChild(b);
    auto delayed = [](int firstTime) {
        Ref<KeyframeSequence> s = make<KeyframeSequence>(2, 3, KeyframeSequence::LINEAR);
        const float v[] = {1, 1, 1};
        s->setKeyframe(0, firstTime, v);
        s->setKeyframe(1, firstTime + 100, v);
        s->setDuration(400);
        return s;
    };
    attach(*a, delayed(100), AnimationTrack::TRANSLATION, controller);
    attach(*b, delayed(50), AnimationTrack::TRANSLATION, controller);
    EXPECT_EQ(root->animate(0), 50);
    EXPECT_EQ(root->animate(30), 20);
    // Inside b's flat segment (50..150) its sample changes "continuously"
    // as far as validity goes (sampleKeyframes says 0 inside a segment);
    // after both last keys nothing changes any more.
    EXPECT_EQ(root->animate(60), 0);
    EXPECT_EQ(root->animate(250), 0x7FFFFFFF);
    float p[3];
    a->getTranslation(p);
    EXPECT_EQ(p[0], 1.0f);
}
