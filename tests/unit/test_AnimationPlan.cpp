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
