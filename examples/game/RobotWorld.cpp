#include "RobotWorld.h"

#include <cmath>
#include <vector>

#include "SampleScene.h"

namespace m3ggame {

using namespace m3g;

namespace {

constexpr int kRings = 4;                                    // at y = 0, 0.6, 1.2, 1.8
constexpr int kCorners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};  // x, z around the Y axis

/// The robot's body: a square column of four rings of four vertices (shorts
/// in centimetres), radial normals, a colour per ring; four side strips and
/// a lid. Rings 1 and 2 sit at the joints and are shared by two bones.
Ref<VertexBuffer> robotVertices() {
    const std::int8_t ringColors[kRings][3] = {{30, 50, 110}, {40, 70, 120}, {-26, 120, 30}, {-36, -36, -46}};
    const int halfWidth[kRings] = {25, 30, 35, 28};
    std::vector<std::int16_t> pos;
    std::vector<std::int8_t> nrm, col;
    for (int r = 0; r < kRings; ++r)
        for (const auto& c : kCorners) {
            pos.insert(pos.end(), {static_cast<std::int16_t>(c[0] * halfWidth[r]), static_cast<std::int16_t>(r * 60),
                                   static_cast<std::int16_t>(c[1] * halfWidth[r])});
            nrm.insert(nrm.end(), {static_cast<std::int8_t>(c[0] * 90), 0, static_cast<std::int8_t>(c[1] * 90)});
            col.insert(col.end(), ringColors[r], ringColors[r] + 3);  // bytes are signed: -26 is 230
        }
    const int n = kRings * 4;
    Ref<VertexArray> positions(new VertexArray(n, 3, 2));
    positions->set(0, n, std::span<const std::int16_t>(pos));
    Ref<VertexArray> normals(new VertexArray(n, 3, 1));
    normals->set(0, n, std::span<const std::int8_t>(nrm));
    Ref<VertexArray> colors(new VertexArray(n, 3, 1));
    colors->set(0, n, std::span<const std::int8_t>(col));
    Ref<VertexBuffer> vb(new VertexBuffer());
    const float bias[3] = {0, 0, 0};
    vb->setPositions(positions.get(), 0.01f, bias);
    vb->setNormals(normals.get());
    vb->setColors(colors.get());
    return vb;
}

Ref<IndexBuffer> robotStrips() {
    std::vector<int> indices, lengths;
    for (int side = 0; side < 4; ++side) {
        for (int r = 0; r < kRings; ++r) {
            indices.push_back(r * 4 + side);
            indices.push_back(r * 4 + (side + 1) % 4);
        }
        lengths.push_back(2 * kRings);
    }
    const int top = (kRings - 1) * 4;
    indices.insert(indices.end(), {top + 0, top + 1, top + 3, top + 2});
    lengths.push_back(4);
    return Ref<IndexBuffer>(new TriangleStripArray(indices, lengths));
}

/// A quaternion keyframe sequence rocking about Z: +a, -a, +a over a second.
Ref<KeyframeSequence> rock(float degrees) {
    Ref<KeyframeSequence> seq(new KeyframeSequence(3, 4, KeyframeSequence::SLERP));
    for (int k = 0; k < 3; ++k) {
        const float half = (k == 1 ? -degrees : degrees) * 3.14159265f / 360.0f;
        const float q[4] = {0.0f, 0.0f, std::sin(half), std::cos(half)};
        seq->setKeyframe(k, k * 500, q);
    }
    seq->setDuration(1000);
    seq->setRepeatMode(KeyframeSequence::LOOP);
    return seq;
}

void animate(Object3D& target, KeyframeSequence* seq, int property, AnimationController* controller) {
    Ref<AnimationTrack> track(new AnimationTrack(seq, property));
    track->setController(controller);
    target.addAnimationTrack(track.get());
}

}  // namespace

RobotWorld buildRobotWorld(float aspect) {
    RobotWorld w;
    w.world = new World();
    Ref<Background> bg(new Background());
    bg->setColor(static_cast<int>(0xFF20304Au));
    w.world->setBackground(bg.get());

    w.camera = new Camera();
    w.camera->setPerspective(50.0f, aspect, 0.5f, 50.0f);
    w.camera->setTranslation(0.0f, 1.5f, 5.0f);
    w.camera->setOrientation(-15.0f, 1.0f, 0.0f, 0.0f);
    w.world->addChild(w.camera.get());
    w.world->setActiveCamera(w.camera.get());

    Ref<Light> sun(new Light());
    sun->setMode(Light::DIRECTIONAL);
    sun->setOrientation(-50.0f, 1.0f, 0.4f, 0.0f);
    w.world->addChild(sun.get());
    Ref<Light> ambient(new Light());
    ambient->setMode(Light::AMBIENT);
    ambient->setIntensity(0.4f);
    w.world->addChild(ambient.get());

    w.world->addChild(m3gcli::makeGround().get());

    // The skeleton: hips -> spine -> chest, each bone 0.6 above its parent.
    Ref<Group> hips(new Group()), spine(new Group()), chest(new Group());
    spine->setTranslation(0.0f, 0.6f, 0.0f);
    chest->setTranslation(0.0f, 0.6f, 0.0f);
    hips->addChild(spine.get());
    spine->addChild(chest.get());
    Ref<Appearance> look(new Appearance());
    Ref<Material> material(new Material());
    material->setVertexColorTrackingEnable(true);
    look->setMaterial(material.get());
    Ref<PolygonMode> noCull(new PolygonMode());
    noCull->setCulling(PolygonMode::CULL_NONE);
    look->setPolygonMode(noCull.get());
    w.robot = new SkinnedMesh(robotVertices().get(), robotStrips().get(), look.get(), hips.get());
    // Rest pose = the bones' transforms now (JSR-184 1.1,
    // SkinnedMesh.addTransform); joint rings are
    // shared half and half between the two bones they join.
    w.robot->addTransform(hips.get(), 1, 0, 8);
    w.robot->addTransform(spine.get(), 1, 4, 8);
    w.robot->addTransform(chest.get(), 1, 8, 8);
    w.robot->setTranslation(0.0f, -1.2f, 1.0f);
    w.robot->setUserID(kRobotID);
    w.world->addChild(w.robot.get());

    w.sway = new AnimationController();
    animate(*spine, rock(12.0f).get(), AnimationTrack::ORIENTATION, w.sway.get());
    animate(*chest, rock(-18.0f).get(), AnimationTrack::ORIENTATION, w.sway.get());

    // The jump: up 0.8 and back in 600 ms, applied while the controller is
    // active (inactive until the first jump: world times are >= 0).
    Ref<KeyframeSequence> hop(new KeyframeSequence(3, 3, KeyframeSequence::LINEAR));
    const float ground[3] = {0, 0, 0}, air[3] = {0, 0.8f, 0};
    hop->setKeyframe(0, 0, ground);
    hop->setKeyframe(1, 300, air);
    hop->setKeyframe(2, 600, ground);
    hop->setDuration(600);
    w.jump = new AnimationController();
    w.jump->setActiveInterval(-2, -1);
    animate(*hips, hop.get(), AnimationTrack::TRANSLATION, w.jump.get());

    // Crates: two on the ground left and right, one floating behind the robot.
    const float cratePos[3][3] = {{-2.0f, -0.9f, 0.0f}, {2.0f, -0.9f, 0.0f}, {0.0f, 1.0f, -1.5f}};
    for (int i = 0; i < 3; ++i) {
        Ref<Appearance> crateLook(new Appearance());
        w.crateMaterials[i] = new Material();
        w.crateMaterials[i]->setColor(Material::DIFFUSE, static_cast<int>(0xFFB07840u));
        crateLook->setMaterial(w.crateMaterials[i].get());
        w.crates[i] = m3gcli::makeCube(crateLook.get());
        w.crates[i]->setTranslation(cratePos[i][0], cratePos[i][1], cratePos[i][2]);
        w.crates[i]->setScale(0.3f, 0.3f, 0.3f);
        w.crates[i]->setOrientation(20.0f * static_cast<float>(i + 1), 0.0f, 1.0f, 0.0f);
        w.crates[i]->setUserID(kFirstCrateID + i);
        w.world->addChild(w.crates[i].get());
    }
    return w;
}

}  // namespace m3ggame
