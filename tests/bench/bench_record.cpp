// CPU cost of recording draws (the "recording per draw" figure in
// docs/rendering.md, "Measuring"). Figures to report, never pass/fail tests.
//   BM_RecordWorld/N      render(World) of N meshes (one shared cube, four
//                         Appearances, a light, a camera), the calling
//                         thread's CPU time per call and per draw
//   BM_RecordImmediate/N  N immediate-mode render(VertexBuffer, ...) calls
// The target is 64x48 so lavapipe's rasterisation (in other threads, after
// releaseTarget) stays small; only the recording thread's CPU time counts.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <span>
#include <ctime>
#include <vector>

#include <m3g/m3g.h>
#include <m3g/vk/Vulkan.h>

namespace {

using namespace m3g;

double threadSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

struct Cube {
    Ref<VertexBuffer> vertices;
    Ref<IndexBuffer> indices;
};

Cube makeCube() {
    static const std::int8_t p[] = {-1, -1, 1,  1, -1, 1,  -1, 1, 1,  1, 1, 1,
                                    -1, -1, -1, 1, -1, -1, -1, 1, -1, 1, 1, -1};
    Ref<VertexArray> positions(new VertexArray(8, 3, 1));
    positions->set(0, 8, std::span<const std::int8_t>(p));
    std::vector<std::int8_t> n(std::begin(p), std::end(p));
    Ref<VertexArray> normals(new VertexArray(8, 3, 1));
    normals->set(0, 8, std::span<const std::int8_t>(n));
    Cube c;
    c.vertices = Ref<VertexBuffer>(new VertexBuffer());
    const float bias[3] = {0, 0, 0};
    c.vertices->setPositions(positions.get(), 1.0f, std::span<const float>(bias));
    c.vertices->setNormals(normals.get());
    const int strip[] = {0, 1, 2, 3, 7, 1, 5, 4, 7, 6, 2, 4, 0, 1};
    const int lengths[] = {14};
    c.indices = Ref<IndexBuffer>(new TriangleStripArray(std::span<const int>(strip), std::span<const int>(lengths)));
    return c;
}

Ref<Appearance> makeAppearance(int i) {
    Ref<Appearance> a(new Appearance());
    Ref<Material> m(new Material());
    m->setColor(Material::DIFFUSE, static_cast<int>(0xFF000000u | (0x40u << (8 * (i % 3)))));
    a->setMaterial(m.get());
    if (i % 4 == 3) {
        Ref<CompositingMode> c(new CompositingMode());
        c->setBlending(CompositingMode::ALPHA);
        a->setCompositingMode(c.get());
    }
    return a;
}

struct Scene {
    Ref<World> world;
    Cube cube;
    std::vector<Ref<Appearance>> appearances;
    std::vector<Transform> transforms;
};

Scene makeScene(int meshes) {
    Scene s;
    s.world = Ref<World>(new World());
    s.cube = makeCube();
    for (int i = 0; i < 4; ++i) s.appearances.push_back(makeAppearance(i));
    const int side = 1 + static_cast<int>(std::sqrt(static_cast<double>(meshes)));
    for (int i = 0; i < meshes; ++i) {
        Ref<Mesh> mesh(new Mesh(s.cube.vertices.get(), s.cube.indices.get(), s.appearances[i % 4].get()));
        const float x = static_cast<float>(i % side) * 3.0f, y = static_cast<float>(i / side) * 3.0f;
        mesh->setTranslation(x, y, 0.0f);
        s.world->addChild(mesh.get());
        Transform t;
        t.postTranslate(x, y, 0.0f);
        s.transforms.push_back(t);
    }
    Ref<Camera> camera(new Camera());
    camera->setPerspective(60.0f, 4.0f / 3.0f, 1.0f, 1000.0f);
    camera->setTranslation(static_cast<float>(side) * 1.5f, static_cast<float>(side) * 1.5f,
                           static_cast<float>(side) * 3.0f);
    s.world->addChild(camera.get());
    s.world->setActiveCamera(camera.get());
    Ref<Light> light(new Light());
    light->setMode(Light::DIRECTIONAL);
    s.world->addChild(light.get());
    return s;
}

template <class Record>
void runFrames(benchmark::State& state, Graphics3D* g, Graphics* target, Record&& record) {
    double recorded = 0.0;
    const std::uint64_t drawsBefore = vk::renderStats().draws;
    for (auto _ : state) {
        g->bindTarget(target, true, 0);
        g->clear(nullptr);  // opens the frame outside the measured part
        const double t0 = threadSeconds();
        record();
        const double dt = threadSeconds() - t0;
        g->releaseTarget();
        state.SetIterationTime(dt);
        recorded += dt;
    }
    // Draws the renderer recorded (culled meshes would not count).
    const double frames = static_cast<double>(state.iterations());
    const double draws = static_cast<double>(vk::renderStats().draws - drawsBefore) / frames;
    state.counters["draws"] = draws;
    state.counters["us_per_draw"] = draws > 0 ? recorded / frames / draws * 1e6 : 0.0;
}

void BM_RecordWorld(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    Scene s = makeScene(n);
    Graphics3D* g = Graphics3D::getInstance();
    Ref<Graphics> target(new Graphics(64, 48));
    runFrames(state, g, target.get(), [&] { g->render(s.world.get()); });
}
BENCHMARK(BM_RecordWorld)->Arg(1)->Arg(100)->Arg(1000)->UseManualTime()->Unit(benchmark::kMicrosecond);

void BM_RecordImmediate(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    Scene s = makeScene(n);
    Graphics3D* g = Graphics3D::getInstance();
    Ref<Graphics> target(new Graphics(64, 48));
    Ref<Camera> camera(new Camera());
    camera->setPerspective(60.0f, 4.0f / 3.0f, 1.0f, 1000.0f);
    Transform eye;
    eye.postTranslate(0.0f, 0.0f, 200.0f);
    runFrames(state, g, target.get(), [&] {
        g->setCamera(camera.get(), &eye);
        for (int i = 0; i < n; ++i)
            g->render(s.cube.vertices.get(), s.cube.indices.get(), s.appearances[static_cast<std::size_t>(i % 4)].get(),
                      &s.transforms[static_cast<std::size_t>(i)]);
    });
}
BENCHMARK(BM_RecordImmediate)->Arg(1)->Arg(100)->Arg(1000)->UseManualTime()->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
