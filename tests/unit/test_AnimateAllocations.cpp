// animate() must not allocate once warmed up: the global
// allocation functions are replaced here by counting ones (for the whole
// test program; they only count) and repeated animate() calls on a scene with
// every kind of animated object are checked to allocate nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include <m3g/m3g.h>

namespace {
std::atomic<long long> gAllocations{0};
}  // namespace

// noinline: GCC would otherwise see malloc/free paired with new/delete after
// inlining and warn (-Wmismatched-new-delete).
[[gnu::noinline]] void* operator new(std::size_t size) {
    gAllocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size ? size : 1)) return p;
    throw std::bad_alloc();
}
[[gnu::noinline]] void* operator new[](std::size_t size) {
    gAllocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size ? size : 1)) return p;
    throw std::bad_alloc();
}
// The nothrow forms too: the library's own would pair with these deletes
// (std::get_temporary_buffer allocates with new(nothrow); ASan flags a mismatch).
[[gnu::noinline]] void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    gAllocations.fetch_add(1, std::memory_order_relaxed);
    return std::malloc(size ? size : 1);
}
[[gnu::noinline]] void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    gAllocations.fetch_add(1, std::memory_order_relaxed);
    return std::malloc(size ? size : 1);
}
[[gnu::noinline]] void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

using namespace m3g;

namespace {

Ref<KeyframeSequence> seq(int components, int interpolation = KeyframeSequence::LINEAR,
                          int repeat = KeyframeSequence::LOOP) {
    Ref<KeyframeSequence> s = new KeyframeSequence(3, components, interpolation);
    std::vector<float> v(static_cast<std::size_t>(components));
    for (int k = 0; k < 3; ++k) {
        for (int c = 0; c < components; ++c) v[static_cast<std::size_t>(c)] = 0.1f * static_cast<float>(k + c + 1);
        s->setKeyframe(k, k * 100, v);
    }
    s->setDuration(300);
    s->setRepeatMode(repeat);
    return s;
}

void animateProperty(Object3D& o, int property, int components, AnimationController* c,
                     int interpolation = KeyframeSequence::LINEAR) {
    Ref<AnimationTrack> t = new AnimationTrack(seq(components, interpolation), property);
    t->setController(c);
    o.addAnimationTrack(t);
}

/// A World with nodes, a mesh whose appearance has material, fog and a
/// texture, a morphing mesh, a sprite, a light, a camera and a background,
/// each animated on several properties by two blended controllers.
Ref<World> animatedWorld() {
    Ref<World> world = new World();
    Ref<AnimationController> a = new AnimationController();
    Ref<AnimationController> b = new AnimationController();
    b->setWeight(0.5f);
    b->setSpeed(2.0f, 0);

    Ref<Camera> cam = new Camera();
    cam->setPerspective(60, 1, 1, 100);
    world->addChild(cam);
    world->setActiveCamera(cam);
    animateProperty(*cam, AnimationTrack::FIELD_OF_VIEW, 1, a);
    animateProperty(*cam, AnimationTrack::ORIENTATION, 4, a, KeyframeSequence::SLERP);
    animateProperty(*cam, AnimationTrack::ORIENTATION, 4, b, KeyframeSequence::SQUAD);

    Ref<Background> bg = new Background();
    world->setBackground(bg);
    animateProperty(*bg, AnimationTrack::COLOR, 3, a);
    animateProperty(*bg, AnimationTrack::CROP, 4, b);

    Ref<Light> light = new Light();
    world->addChild(light);
    animateProperty(*light, AnimationTrack::INTENSITY, 1, a, KeyframeSequence::SPLINE);
    animateProperty(*light, AnimationTrack::COLOR, 3, b, KeyframeSequence::STEP);

    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<VertexArray> pos = new VertexArray(3, 3, 2);
    vb->setPositions(pos, 1.0f, {});
    animateProperty(*vb, AnimationTrack::ALPHA, 1, a);
    const int lengths[] = {3};
    Ref<IndexBuffer> ib = new TriangleStripArray(0, lengths);
    Ref<Appearance> app = new Appearance();
    Ref<Material> mat = new Material();
    animateProperty(*mat, AnimationTrack::DIFFUSE_COLOR, 3, a);
    animateProperty(*mat, AnimationTrack::SHININESS, 1, b);
    app->setMaterial(mat);
    Ref<Fog> fog = new Fog();
    animateProperty(*fog, AnimationTrack::DENSITY, 1, a);
    app->setFog(fog);
    Ref<Texture2D> tex = new Texture2D(new Image2D(Image2D::RGB, 4, 4));
    animateProperty(*tex, AnimationTrack::TRANSLATION, 3, a);
    app->setTexture(0, tex);

    for (int i = 0; i < 20; ++i) {
        Ref<Group> g = new Group();
        animateProperty(*g, AnimationTrack::TRANSLATION, 3, a);
        animateProperty(*g, AnimationTrack::TRANSLATION, 3, b);
        animateProperty(*g, AnimationTrack::SCALE, 3, b);
        animateProperty(*g, AnimationTrack::ALPHA, 1, a);
        Ref<Mesh> m = new Mesh(vb, ib, app);  // shared components: visited once
        animateProperty(*m, AnimationTrack::VISIBILITY, 1, a);
        g->addChild(m);
        world->addChild(g);
    }
    std::vector<Ref<VertexBuffer>> targets{new VertexBuffer()};
    targets[0]->setPositions(new VertexArray(3, 3, 2), 1.0f, {});
    Ref<MorphingMesh> morph = new MorphingMesh(vb, targets, ib, app);
    animateProperty(*morph, AnimationTrack::MORPH_WEIGHTS, 1, a);
    world->addChild(morph);
    Ref<Sprite3D> sprite = new Sprite3D(true, new Image2D(Image2D::RGBA, 8, 8), app);
    animateProperty(*sprite, AnimationTrack::CROP, 2, a);
    animateProperty(*sprite, AnimationTrack::PICKABILITY, 1, b);
    world->addChild(sprite);
    return world;
}

}  // namespace

TEST(AnimateAllocations, SteadyStateAnimateDoesNotAllocate) {
    Ref<World> world = animatedWorld();
    world->animate(0);  // warm-up: validation, scratch storage
    world->animate(1);
    const long long before = gAllocations.load();
    for (int t = 2; t < 2000; t += 7) world->animate(t);
    EXPECT_EQ(gAllocations.load() - before, 0);
}

TEST(AnimateAllocations, TheCounterSeesAllocations) {
    // The replacement is in force: direct calls (which the compiler may not
    // elide, unlike new-expressions) are counted.
    static void* volatile sink = nullptr;
    const long long before = gAllocations.load();
    sink = ::operator new(24);
    ::operator delete(sink);
    sink = ::operator new[](24);
    ::operator delete[](sink);
    EXPECT_EQ(gAllocations.load() - before, 2);
}

TEST(AnimateAllocations, SubtreeAndOtherGraphsStayAllocationFree) {
    // After warming up on the larger graph, animating a smaller one (or a
    // subtree) reuses the storage.
    Ref<World> big = animatedWorld();
    Ref<World> small = animatedWorld();
    big->animate(0);
    small->animate(0);
    Ref<Node> child = small->getChild(3);
    child->animate(0);
    const long long before = gAllocations.load();
    for (int t = 1; t < 500; t += 13) {
        big->animate(t);
        small->animate(t);
        child->animate(t);
    }
    EXPECT_EQ(gAllocations.load() - before, 0);
}

TEST(AnimateAllocations, SkinnedCorpusFramesDoNotAllocate) {
    // The skinned corpus files of BM_SkinnedCorpusFrame, animated over their
    // whole longest sequence in the benchmark's steps after two warm-up
    // frames (the first builds the animation plan).
    const char* const files[] = {
        "bryan10328__java-m3g/res/mahosyojo-with-sexy-walking.m3g",
        "BaalNetbek__M3G-Viewer/com.wizzer.m3g.toolkit/test/robot.m3g",
        "vadosnaprimer__desktop-m3g/sample/sample-12-loader/test.m3g",
        "jacques-gasselin__m3x/tools/test/data/otokka_jump2.m3g",
    };
    int tested = 0;
    for (const char* name : files) {
        const std::string path = std::string(M3G_CORPUS_DIR) + "/models/" + name;
        LoadResult r;
        try {
            r = Loader::loadDetailed(path);
        } catch (const IOException&) {
            continue;  // corpus not present
        }
        int period = 1;
        for (const auto& o : r.objects)
            if (auto* k = dynamic_cast<KeyframeSequence*>(o.get())) period = std::max(period, k->getDuration());
        for (const auto& root : r.roots) {
            root->animate(0);
            root->animate(33);
        }
        const long long before = gAllocations.load();
        for (int t = 66; t < period + 66; t += 33)
            for (const auto& root : r.roots) root->animate(t % period);
        EXPECT_EQ(gAllocations.load() - before, 0) << name;
        ++tested;
    }
    if (tested == 0) GTEST_SKIP() << "no skinned corpus file under " << M3G_CORPUS_DIR;
}
