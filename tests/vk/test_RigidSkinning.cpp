// A rigidly bound SkinnedMesh (every vertex on one bone, weight 1) is drawn
// from its undeformed vertices through its bone's transform
// (MeshDeformer::Rigid::AsTransform, VertexLayout::rigid; docs/skinning.md
// "Rigid binding"). The reference is the same geometry skinned vertex by
// vertex: the mesh bound to two bones that always share one pose, half the
// vertices on each, which the CPU kernels deform. Lit by a directional and
// an omni light, with the bone scaled non-uniformly, so that a normal
// matrix made from the wrong rows, or a position transform in the wrong
// order, shows in the image. On lavapipe with the validation layer on.
#include "VkTestSupport.h"

#include <cstdio>
#include <vector>

#include "ImageIO.h"
#include "SceneKit.h"

using namespace m3g;
using m3gtest::VkTest;

namespace {

constexpr std::uint32_t kBackground = 0xFF202020u;

class RigidSkinningTest : public m3gtest::SkinningModeTest {
protected:
    /// Three poses of the rigid grid drawn with skinning `mode`, each against
    /// the two-bone reference skinned on the CPU.
    void expectLikeTheReference(int mode, bool normals);
};

/// A lit 16x16 grid with a position scale and bias, bound to `boneCount`
/// (1 or 2) bones under one joint; the two bones of the reference always
/// take the same pose.
struct RigidScene {
    static constexpr int kCols = 16, kRows = 16, kVertices = kCols * kRows;
    Ref<World> world = new World();
    Ref<Group> skeleton = new Group();
    Ref<Group> joint = new Group();
    std::vector<Ref<Group>> bones;
    Ref<SkinnedMesh> mesh;
    Ref<Camera> camera = new Camera();

    /// `normals`: whether the VertexBuffer has a normal array (without one
    /// the default normal is lit, and no bone turns it).
    explicit RigidScene(int boneCount, bool normals = true) {
        std::vector<std::int16_t> pos;
        std::vector<std::int8_t> nrm;
        for (int r = 0; r < kRows; ++r)
            for (int c = 0; c < kCols; ++c) {
                // A shallow bowl, so that the normals vary over the grid.
                const int z = ((c - 8) * (c - 8) + (r - 8) * (r - 8)) * 2;
                pos.insert(pos.end(), {static_cast<std::int16_t>(c * 20), static_cast<std::int16_t>(r * 20),
                                       static_cast<std::int16_t>(z)});
                nrm.insert(nrm.end(), {static_cast<std::int8_t>((8 - c) * 6), static_cast<std::int8_t>((8 - r) * 6), 100});
            }
        Ref<VertexBuffer> vb = new VertexBuffer();
        Ref<VertexArray> p = new VertexArray(kVertices, 3, 2), n = new VertexArray(kVertices, 3, 1);
        p->set(0, kVertices, pos);
        n->set(0, kVertices, nrm);
        const float bias[] = {-1.5f, -1.5f, 0.2f};
        vb->setPositions(p, 0.01f, bias);
        if (normals) vb->setNormals(n);
        vb->setDefaultColor(0xFFFFFFFF);
        Ref<Appearance> app = new Appearance();
        Ref<Material> material = new Material();
        material->setColor(Material::DIFFUSE, 0xFFD08040);
        material->setColor(Material::SPECULAR, 0xFF606060);
        material->setShininess(20);
        app->setMaterial(material);
        Ref<PolygonMode> pm = new PolygonMode();
        pm->setCulling(PolygonMode::CULL_NONE);
        pm->setTwoSidedLightingEnable(true);
        app->setPolygonMode(pm);
        mesh = new SkinnedMesh(vb, m3gtest::gridStrips(kRows, kCols), app, skeleton);
        skeleton->addChild(joint);
        joint->setTranslation(0.2f, -0.1f, 0);
        for (int b = 0; b < boneCount; ++b) {
            bones.push_back(new Group());
            joint->addChild(bones.back());
        }
        // At rest the bones are already turned and moved: addTransform
        // captures that pose.
        pose(20, 0.1f, 1.0f);
        const int share = kVertices / boneCount;
        for (int b = 0; b < boneCount; ++b)
            mesh->addTransform(bones[static_cast<std::size_t>(b)], 1, b * share, b + 1 == boneCount ? kVertices - b * share : share);
        world->addChild(mesh);

        world->addChild(camera);
        world->setActiveCamera(camera);
        camera->setPerspective(50, 1, 0.5f, 20);
        camera->setTranslation(0, 0, 5);
        Ref<Light> sun = new Light();
        sun->setMode(Light::DIRECTIONAL);
        sun->setOrientation(-35, 1, 1, 0);
        world->addChild(sun);
        Ref<Light> lamp = new Light();
        lamp->setMode(Light::OMNI);
        lamp->setColor(0x80A0FF);
        lamp->setTranslation(-1, 1, 2);
        world->addChild(lamp);
    }

    /// Every bone: turned `angle` degrees about (1, 1, 0.5), moved by
    /// `dx` along x, scaled (`sx`, 0.7, 1.2).
    void pose(float angle, float dx, float sx) {
        for (auto& b : bones) {
            b->setOrientation(angle, 1, 1, 0.5f);
            b->setTranslation(dx, 0.05f, -0.2f);
            b->setScale(sx, 0.7f, 1.2f);
        }
    }

    /// Renders the World into `image` with skinning `mode`.
    void render(int mode, Image2D* image) {
        Graphics3D* g = Graphics3D::getInstance();
        g->setSkinningMode(mode);
        g->bindTarget(image);
        g->render(world.get());
        g->releaseTarget();
    }
};

double shareOff(const m3gcli::RgbaImage& a, const m3gcli::RgbaImage& b, int threshold, const char* what) {
    const m3gcli::Comparison c = m3gcli::compareImages(a, b, threshold);
    std::printf("  %-44s pixels off by more than %d: %.4f%%, PSNR %.1f dB\n", what, threshold, c.share * 100, c.psnr);
    return c.share;
}

void RigidSkinningTest::expectLikeTheReference(int mode, bool normals) {
    RigidScene rigid(1, normals), reference(2, normals);
    int posed = 0;
    for (float angle : {-30.0f, 45.0f, 110.0f}) {
        rigid.pose(angle, angle / 200.0f, 1.0f + angle / 100.0f);
        reference.pose(angle, angle / 200.0f, 1.0f + angle / 100.0f);
        const Ref<Image2D> expected = target(96, 96, kBackground), actual = target(96, 96, kBackground);
        reference.render(Graphics3D::SKINNING_CPU, expected.get());
        const auto before = vk::renderStats();
        rigid.render(mode, actual.get());
        const auto after = vk::renderStats();
        // The grid's vertices are copied to the device once, with the first
        // pose; later poses change the draw's transform only.
        if (posed++ > 0) {
            EXPECT_EQ(after.bufferUploads, before.bufferUploads) << "at " << angle << " degrees";
        }
        EXPECT_EQ(after.computeDispatches, before.computeDispatches) << "at " << angle << " degrees";
        char what[64];
        std::snprintf(what, sizeof what, "rigid grid at %.0f degrees%s", angle, normals ? "" : ", no normals");
        // The same triangles, placed by (model-view x bone) p instead of
        // model-view (bone p): rounding apart, the same pixels.
        EXPECT_LE(shareOff(toRgba(*actual), toRgba(*expected), 2, what), 0.002) << what;
        EXPECT_GT(shareOff(toRgba(*actual), toRgba(*target(96, 96, kBackground)), 8, "against the empty target"), 0.15)
            << "the grid should cover the target";
    }
}

}  // namespace

TEST_F(RigidSkinningTest, DrawsLikeTheSkinnedVerticesWithoutUploadsOrDispatches) {
    for (int mode : {Graphics3D::SKINNING_CPU, Graphics3D::SKINNING_COMPUTE}) {
        for (bool normals : {true, false}) {
            SCOPED_TRACE(mode == Graphics3D::SKINNING_CPU ? "CPU skinning" : "compute skinning");
            SCOPED_TRACE(normals ? "with normals" : "without normals");
            expectLikeTheReference(mode, normals);
        }
    }
}

TEST_F(RigidSkinningTest, TheReferenceDoesUploadPerPose) {
    // The other side of the first test's upload count: the two-bone
    // reference is skinned per pose, so a new pose copies its vertices.
    RigidScene reference(2);
    const Ref<Image2D> image = target(96, 96, kBackground);
    reference.render(Graphics3D::SKINNING_CPU, image.get());
    reference.pose(60, 0.2f, 1.3f);
    const auto before = vk::renderStats().bufferUploads;
    reference.render(Graphics3D::SKINNING_CPU, image.get());
    EXPECT_GT(vk::renderStats().bufferUploads, before);
}
