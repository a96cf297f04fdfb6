// RayIntersection defaults and argument checks (JSR-184 1.1, RayIntersection) and the
// Graphics target stand-in.
#include <gtest/gtest.h>

#include <m3g/Graphics.h>
#include <m3g/Group.h>
#include <m3g/RayIntersection.h>

using namespace m3g;

TEST(RayIntersection, Defaults) {
    RayIntersection ri;
    EXPECT_EQ(ri.getIntersected(), nullptr);
    EXPECT_EQ(ri.getDistance(), 0.0f);
    EXPECT_EQ(ri.getSubmeshIndex(), 0);
    EXPECT_EQ(ri.getTextureS(0), 0.0f);
    EXPECT_EQ(ri.getTextureT(1), 0.0f);
    EXPECT_EQ(ri.getNormalX(), 0.0f);
    EXPECT_EQ(ri.getNormalY(), 0.0f);
    EXPECT_EQ(ri.getNormalZ(), 1.0f);
    float ray[6];
    ri.getRay(ray);
    EXPECT_EQ(ray[0], 0.0f);
    EXPECT_EQ(ray[5], 1.0f);
}

TEST(RayIntersection, ArgumentChecks) {
    RayIntersection ri;
    EXPECT_THROW(ri.getTextureS(-1), IndexOutOfBoundsException);
    EXPECT_THROW(ri.getTextureT(getLimits().numTextureUnits), IndexOutOfBoundsException);
    float five[5];
    EXPECT_THROW(ri.getRay(five), IllegalArgumentException);
    EXPECT_THROW(ri.getRay(std::span<float>()), NullPointerException);
}

TEST(RayIntersection, EngineSettersRoundTrip) {
    RayIntersection ri;
    Ref<Group> g = make<Group>();
    ri.setIntersected(g, 2.5f, 1);
    ri.setTextureCoords(1, 0.25f, 0.75f);
    ri.setNormal(0, 1, 0);
    ri.setRay(1, 2, 3, 4, 5, 6);
    EXPECT_EQ(ri.getIntersected(), g);
    EXPECT_EQ(ri.getDistance(), 2.5f);
    EXPECT_EQ(ri.getSubmeshIndex(), 1);
    EXPECT_EQ(ri.getTextureS(1), 0.25f);
    EXPECT_EQ(ri.getTextureT(1), 0.75f);
    EXPECT_EQ(ri.getNormalY(), 1.0f);
    float ray[6];
    ri.getRay(ray);
    EXPECT_EQ(ray[3], 4.0f);
}

TEST(Graphics, SurfaceClipAndTranslation) {
    EXPECT_THROW(Graphics(0, 10), IllegalArgumentException);
    Ref<Graphics> g = make<Graphics>(100, 50);
    EXPECT_EQ(g->getClipWidth(), 100);
    EXPECT_EQ(g->getClipHeight(), 50);
    EXPECT_EQ(g->getPixel(99, 49), 0xFF000000u);
    EXPECT_THROW(g->getPixel(100, 0), IndexOutOfBoundsException);
    g->translate(10, 5);
    g->setClip(0, 0, 200, 20);  // clipped to the surface: x in [10, 100)
    EXPECT_EQ(g->getClipX(), 0);
    EXPECT_EQ(g->getClipY(), 0);
    EXPECT_EQ(g->getClipWidth(), 90);
    EXPECT_EQ(g->getClipHeight(), 20);
    g->setClip(-20, -20, 5, 5);  // entirely outside
    EXPECT_EQ(g->getClipWidth(), 0);
}
