// Graphics3D state, properties and target binding rules (JSR-184 1.1,
// Graphics3D, including the getters and properties new in 1.1).
#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>
#include <memory>
#include <string>

#include <m3g/Graphics3D.h>

using namespace m3g;

namespace {
// Graphics3D is a process-wide singleton: leave it unbound and clean.
struct Graphics3DTest : ::testing::Test {
    Graphics3D* g3d = Graphics3D::getInstance();
    void SetUp() override { reset(); }
    void TearDown() override { reset(); }
    void reset() {
        g3d->releaseTarget();
        g3d->resetLights();
        g3d->setCamera(nullptr, nullptr);
        g3d->setDepthRange(0, 1);
    }
};
}  // namespace

TEST_F(Graphics3DTest, SingletonAndProperties) {
    EXPECT_EQ(Graphics3D::getInstance(), g3d);
    auto p = Graphics3D::getProperties();
    EXPECT_EQ(std::get<int>(p.at("maxLights")), 8);
    EXPECT_EQ(std::get<int>(p.at("numTextureUnits")), 2);
    EXPECT_EQ(std::get<int>(p.at("maxTransformsPerVertex")), 4);
    EXPECT_EQ(std::get<int>(p.at("maxTextureDimension")), 1024);
    EXPECT_GE(std::get<int>(p.at("maxViewportWidth")), 256);
    EXPECT_GE(std::get<int>(p.at("maxViewportHeight")), 256);
    EXPECT_GE(std::get<int>(p.at("maxViewportDimension")), 256);
    EXPECT_GE(std::get<int>(p.at("maxSpriteCropDimension")), 256);
    for (const char* key : {"supportAntialiasing", "supportTrueColor", "supportDithering", "supportMipmapping",
                            "supportPerspectiveCorrection", "supportLocalCameraLighting"})
        EXPECT_TRUE(std::holds_alternative<bool>(p.at(key))) << key;
    EXPECT_TRUE(std::holds_alternative<std::string>(p.at("m3gRelease")));
}

TEST_F(Graphics3DTest, HintConstants) {
    EXPECT_EQ(Graphics3D::ANTIALIAS, 2);
    EXPECT_EQ(Graphics3D::DITHER, 4);
    EXPECT_EQ(Graphics3D::TRUE_COLOR, 8);
    EXPECT_EQ(Graphics3D::OVERWRITE, 16);
}

TEST_F(Graphics3DTest, BindImageTargetResetsViewport) {
    Ref<Image2D> img = make<Image2D>(Image2D::RGBA, 64, 32);
    g3d->setViewport(5, 5, 10, 10);
    g3d->bindTarget(img, false, Graphics3D::ANTIALIAS | Graphics3D::OVERWRITE);
    EXPECT_EQ(g3d->getTarget().get(), static_cast<RefCounted*>(img.get()));
    EXPECT_EQ(g3d->getViewportX(), 0);
    EXPECT_EQ(g3d->getViewportY(), 0);
    EXPECT_EQ(g3d->getViewportWidth(), 64);
    EXPECT_EQ(g3d->getViewportHeight(), 32);
    EXPECT_FALSE(g3d->isDepthBufferEnabled());
    EXPECT_EQ(g3d->getHints(), Graphics3D::ANTIALIAS | Graphics3D::OVERWRITE);
    // A second bind without release is an error.
    EXPECT_THROW(g3d->bindTarget(img), IllegalStateException);
    g3d->releaseTarget();
    EXPECT_EQ(g3d->getTarget(), nullptr);
    g3d->releaseTarget();  // no-op when unbound
}

TEST_F(Graphics3DTest, BindGraphicsUsesClipInTranslatedCoordinates) {
    Ref<Graphics> g = make<Graphics>(200, 100);
    g->translate(20, 10);
    g->setClip(5, 5, 50, 40);
    g3d->bindTarget(g);
    EXPECT_TRUE(g3d->isDepthBufferEnabled());
    EXPECT_EQ(g3d->getHints(), 0);
    EXPECT_EQ(g3d->getViewportX(), 5);
    EXPECT_EQ(g3d->getViewportY(), 5);
    EXPECT_EQ(g3d->getViewportWidth(), 50);
    EXPECT_EQ(g3d->getViewportHeight(), 40);
}

TEST_F(Graphics3DTest, BindTargetChecks) {
    EXPECT_THROW(g3d->bindTarget(static_cast<Image2D*>(nullptr)), NullPointerException);
    EXPECT_THROW(g3d->bindTarget(static_cast<Graphics*>(nullptr)), NullPointerException);
    const std::uint8_t px[4] = {1, 2, 3, 4};
    Ref<Image2D> immutable = make<Image2D>(Image2D::RGBA, 1, 1, std::span<const std::uint8_t>(px));
    EXPECT_THROW(g3d->bindTarget(immutable), IllegalArgumentException);
    Ref<Image2D> lum = make<Image2D>(Image2D::LUMINANCE, 4, 4);
    EXPECT_THROW(g3d->bindTarget(lum), IllegalArgumentException);
    Ref<Image2D> rgb = make<Image2D>(Image2D::RGB, 4, 4);
    EXPECT_THROW(g3d->bindTarget(rgb, true, 1), IllegalArgumentException);   // unknown hint bit
    EXPECT_THROW(g3d->bindTarget(rgb, true, 32), IllegalArgumentException);
    const int tooWide = getLimits().maxViewportWidth + 1;
    Ref<Graphics> huge = make<Graphics>(tooWide, 8);
    EXPECT_THROW(g3d->bindTarget(huge), IllegalArgumentException);
    EXPECT_EQ(g3d->getTarget(), nullptr);  // failed binds leave nothing bound
    g3d->bindTarget(rgb, true, 0);
    EXPECT_EQ(g3d->getViewportWidth(), 4);
}

TEST_F(Graphics3DTest, ViewportAndDepthRange) {
    g3d->setViewport(-10, -20, 30, 40);
    EXPECT_EQ(g3d->getViewportX(), -10);
    EXPECT_EQ(g3d->getViewportY(), -20);
    EXPECT_EQ(g3d->getViewportWidth(), 30);
    EXPECT_EQ(g3d->getViewportHeight(), 40);
    EXPECT_THROW(g3d->setViewport(0, 0, 0, 10), IllegalArgumentException);
    EXPECT_THROW(g3d->setViewport(0, 0, 10, -1), IllegalArgumentException);
    EXPECT_THROW(g3d->setViewport(0, 0, getLimits().maxViewportWidth + 1, 10), IllegalArgumentException);
    EXPECT_EQ(g3d->getDepthRangeNear(), 0.0f);
    EXPECT_EQ(g3d->getDepthRangeFar(), 1.0f);
    g3d->setDepthRange(0.75f, 0.25f);  // near > far is allowed
    EXPECT_EQ(g3d->getDepthRangeNear(), 0.75f);
    EXPECT_EQ(g3d->getDepthRangeFar(), 0.25f);
    EXPECT_THROW(g3d->setDepthRange(-0.1f, 1), IllegalArgumentException);
    EXPECT_THROW(g3d->setDepthRange(0, 1.1f), IllegalArgumentException);
}

TEST_F(Graphics3DTest, CameraAndInverse) {
    Ref<Camera> cam = make<Camera>();
    Transform t;
    t.postTranslate(0, 0, 10);
    g3d->setCamera(cam, &t);
    Transform out;
    EXPECT_EQ(g3d->getCamera(&out), cam);
    EXPECT_TRUE(out == t);
    EXPECT_FLOAT_EQ(g3d->worldToCamera().at(2, 3), -10.0f);
    Transform singular;
    singular.postScale(0, 1, 1);
    EXPECT_THROW(g3d->setCamera(cam, &singular), ArithmeticException);
    EXPECT_EQ(g3d->getCamera(nullptr), cam);  // unchanged after the failure
    g3d->setCamera(nullptr, nullptr);
    EXPECT_EQ(g3d->getCamera(nullptr), nullptr);
}

TEST_F(Graphics3DTest, Lights) {
    Ref<Light> a = make<Light>(), b = make<Light>();
    EXPECT_THROW(g3d->addLight(nullptr, nullptr), NullPointerException);
    Transform t;
    t.postTranslate(1, 2, 3);
    EXPECT_EQ(g3d->addLight(a, &t), 0);
    EXPECT_EQ(g3d->addLight(b, nullptr), 1);
    EXPECT_EQ(g3d->getLightCount(), 2);
    Transform out;
    EXPECT_EQ(g3d->getLight(0, &out), a);
    EXPECT_TRUE(out == t);
    g3d->setLight(1, nullptr, nullptr);
    EXPECT_EQ(g3d->getLight(1, nullptr), nullptr);
    EXPECT_EQ(g3d->getLightCount(), 2);
    EXPECT_THROW(g3d->setLight(2, a, nullptr), IndexOutOfBoundsException);
    EXPECT_THROW(g3d->getLight(-1, nullptr), IndexOutOfBoundsException);
    g3d->resetLights();
    EXPECT_EQ(g3d->getLightCount(), 0);
}

TEST_F(Graphics3DTest, DepthRangeRejectsNaN) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(g3d->setDepthRange(nan, 1), IllegalArgumentException);
    EXPECT_THROW(g3d->setDepthRange(0, nan), IllegalArgumentException);
    EXPECT_EQ(g3d->getDepthRangeNear(), 0.0f);
    EXPECT_EQ(g3d->getDepthRangeFar(), 1.0f);
}

// Graphics3D::create (docs/threading.md): independent instances, one per
// rendering thread, none of them the process-wide one.
TEST_F(Graphics3DTest, CreatedInstancesAreIndependent) {
    std::unique_ptr<Graphics3D> a = Graphics3D::create(), b = Graphics3D::create();
    ASSERT_NE(a.get(), g3d);
    ASSERT_NE(a.get(), b.get());
    Ref<Image2D> ia = make<Image2D>(Image2D::RGBA, 16, 8), ib = make<Image2D>(Image2D::RGB, 4, 4);
    a->bindTarget(ia);
    b->bindTarget(ib);  // no "already bound": each has its own target
    EXPECT_EQ(g3d->getTarget(), nullptr);
    EXPECT_EQ(a->getViewportWidth(), 16);
    EXPECT_EQ(b->getViewportWidth(), 4);
    Ref<Camera> cam = make<Camera>();
    a->setCamera(cam, nullptr);
    EXPECT_EQ(b->getCamera(nullptr), nullptr);
    Ref<Light> light = make<Light>();
    b->addLight(light, nullptr);
    EXPECT_EQ(a->getLightCount(), 0);
    // Destroying a bound instance unbinds its target (it drops its reference).
    const int before = ia->getRefCount();
    a.reset();
    EXPECT_EQ(ia->getRefCount(), before - 1);
    b->releaseTarget();
}

TEST_F(Graphics3DTest, SkinningModeExtension) {
    // m3g-vk extension: CPU unless M3G_SKINNING said otherwise at start-up.
    const char* env = std::getenv("M3G_SKINNING");
    const bool compute = env && std::string(env) == "compute";
    const int initial = g3d->getSkinningMode();
    EXPECT_EQ(initial, compute ? Graphics3D::SKINNING_COMPUTE : Graphics3D::SKINNING_CPU);
    g3d->setSkinningMode(Graphics3D::SKINNING_COMPUTE);
    EXPECT_EQ(g3d->getSkinningMode(), Graphics3D::SKINNING_COMPUTE);
    g3d->setSkinningMode(Graphics3D::SKINNING_CPU);
    EXPECT_EQ(g3d->getSkinningMode(), Graphics3D::SKINNING_CPU);
    try {
        g3d->setSkinningMode(2);
        FAIL() << "mode 2 accepted";
    } catch (const IllegalArgumentException& e) {
        EXPECT_NE(std::string(e.what()).find("Graphics3D::setSkinningMode: mode 2"), std::string::npos) << e.what();
    }
    EXPECT_THROW(g3d->setSkinningMode(-1), IllegalArgumentException);
    EXPECT_EQ(g3d->getSkinningMode(), Graphics3D::SKINNING_CPU);  // unchanged by the rejected calls
    g3d->setSkinningMode(initial);
}
