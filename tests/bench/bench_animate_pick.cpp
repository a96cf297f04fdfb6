// animate() and Group::pick throughput. Figures to report, never
// pass/fail tests.
//   BM_AnimateCorpus       animate() of the largest animated corpus file
//   BM_AnimateSynthetic    a World of 1,000 animated groups (translation +
//                          orientation each, two blended controllers)
//   BM_SkinnedCorpusFrame  a skinned corpus file's frame: animate(), then
//                          every SkinnedMesh deformed as the renderer does it
//                          (MeshDeformer: bone transforms, palette, kernels;
//                          a rigidly bound mesh reports its bone's transform
//                          instead, Rigid::AsTransform)
//   BM_SkinnedCorpusFrameAllVertices  the same with every vertex deformed,
//                          rigid meshes too (Rigid::Deform)
//   BM_SkinnedCorpusAnimate  the same frames' animate() alone
//   BM_PickRay/Camera100k  one pick on a 100,000-triangle mesh
//   BM_PickRayMiss100k     a ray beside it (bounding-box rejection)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <m3g/m3g.h>

#include <m3g/skin/InfluenceTable.h>
#include <m3g/skin/Skinning.h>

#include "MeshDeformer.h"

namespace {

using namespace m3g;

struct AnimatedFile {
    std::string name;
    std::uintmax_t bytes = 0;
    int tracks = 0;
    int objects = 0;
    std::vector<Ref<Object3D>> roots;
};

// The largest corpus file (by size) that loads and has animation tracks.
const AnimatedFile& largestAnimatedFile() {
    static const AnimatedFile file = [] {
        AnimatedFile best;
        const std::filesystem::path root = std::filesystem::path(M3G_CORPUS_DIR) / "models";
        if (!std::filesystem::exists(root)) return best;
        for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
            if (!e.is_regular_file() || e.file_size() <= best.bytes) continue;
            LoadResult r;
            try {
                r = Loader::loadDetailed(e.path().string());
            } catch (const Exception&) {
                continue;
            }
            int tracks = 0;
            for (const auto& o : r.objects)
                if (dynamic_cast<AnimationTrack*>(o.get())) ++tracks;
            if (tracks == 0) continue;
            try {
                for (const auto& root2 : r.roots) root2->animate(0);
            } catch (const Exception&) {
                continue;  // e.g. an invalid keyframe sequence
            }
            best.name = e.path().lexically_relative(root).string();
            best.bytes = e.file_size();
            best.tracks = tracks;
            best.objects = static_cast<int>(r.objects.size());
            best.roots = std::move(r.roots);
        }
        return best;
    }();
    return file;
}

void BM_AnimateCorpus(benchmark::State& state) {
    const AnimatedFile& f = largestAnimatedFile();
    if (f.roots.empty()) {
        state.SkipWithError("no animated corpus file under " M3G_CORPUS_DIR "/models");
        return;
    }
    int t = 0;
    for (auto _ : state) {
        for (const auto& r : f.roots) benchmark::DoNotOptimize(r->animate(t));
        t += 16;
    }
    state.SetLabel(f.name);
    state.counters["tracks"] = f.tracks;
    state.counters["objects"] = f.objects;
    state.counters["tracks/s"] = benchmark::Counter(double(f.tracks), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_AnimateCorpus)->Unit(benchmark::kMicrosecond);

// Every skinned corpus file (every file under models/ with a SkinnedMesh),
// by path under models/, and the short name its benchmark argument has.
// boy.m3g names a texture the corpus does not hold: loaded leniently.
struct SkinnedFile {
    const char* path;
    const char* name;
    bool lenient;
};
const SkinnedFile kSkinnedFiles[] = {
    {"bryan10328__java-m3g/res/mahosyojo-with-sexy-walking.m3g", "mahosyojo", false},
    {"BaalNetbek__M3G-Viewer/com.wizzer.m3g.toolkit/test/robot.m3g", "robot", false},
    {"vadosnaprimer__desktop-m3g/sample/sample-12-loader/test.m3g", "test", false},
    {"jacques-gasselin__m3x/tools/test/data/otokka_jump2.m3g", "otokka_jump2", false},
    {"vadosnaprimer__desktop-m3g/src/parser/test/boy.m3g", "boy", true},
};

// A loaded skinned corpus file, its SkinnedMeshes, and the animation period:
// world time cycles through the longest sequence, so that every frame moves
// the bones (past the end of a CONSTANT sequence nothing would change and
// the deformers would skip their work).
struct SkinnedScene {
    LoadResult loaded;
    std::vector<SkinnedMesh*> meshes;
    int bones = 0, vertices = 0, tracks = 0, period = 1;
};

bool loadSkinned(benchmark::State& state, const SkinnedFile& file, SkinnedScene& f) {
    const std::string name = file.path;
    const std::filesystem::path path = std::filesystem::path(M3G_CORPUS_DIR) / "models" / name;
    if (!std::filesystem::exists(path)) {
        state.SkipWithError(("corpus file not found: " + path.string()).c_str());
        return false;
    }
    LoaderOptions options;
    options.lenient = file.lenient;
    f.loaded = Loader::loadDetailed(path.string(), options);
    // How the kernels see the vertices (InfluencePartition, as MeshDeformer
    // builds it: every vertex with influences in the compact space, sorted
    // by influence set): in its runs, in its bone runs (shared bones, own
    // weights), and loose (the list kernel, vertex by vertex).
    std::size_t compactRunVertices = 0, boneRunVertices = 0, looseVertices = 0;
    for (const auto& o : f.loaded.objects) {
        if (auto* s = dynamic_cast<SkinnedMesh*>(o.get())) {
            f.meshes.push_back(s);
            f.bones += s->boneCount();
            f.vertices += s->getVertexBuffer()->getVertexCount();
            const skin::InfluenceTable& table = s->influenceTable();
            skin::InfluencePartition p;
            p.buildForKernels(table, static_cast<std::size_t>(s->getVertexBuffer()->getVertexCount()));
            for (int c = 1; c <= p.maxInfluences(); ++c) {
                for (const auto& run : p.compactRuns(c)) compactRunVertices += run.vertexCount;
                for (const auto& run : p.compactBoneRuns(c)) boneRunVertices += run.vertexCount;
                looseVertices += p.compactLoose(c).size();
            }
        }
        if (auto* k = dynamic_cast<KeyframeSequence*>(o.get())) f.period = std::max(f.period, k->getDuration());
        if (dynamic_cast<AnimationTrack*>(o.get())) ++f.tracks;
    }
    state.SetLabel(name.substr(name.find_last_of('/') + 1));
    state.counters["meshes"] = static_cast<double>(f.meshes.size());
    state.counters["bones"] = f.bones;
    state.counters["vertices"] = f.vertices;
    state.counters["tracks"] = f.tracks;
    state.counters["period_ms"] = f.period;
    state.counters["compact_runs"] = static_cast<double>(compactRunVertices);
    state.counters["bone_runs"] = static_cast<double>(boneRunVertices);
    state.counters["loose"] = static_cast<double>(looseVertices);
    return true;
}

void skinnedCorpusFrames(benchmark::State& state, const SkinnedFile& file, detail::MeshDeformer::Rigid rigid) {
    SkinnedScene f;
    if (!loadSkinned(state, file, f)) return;
    std::vector<detail::MeshDeformer> deformers(f.meshes.size());
    int t = 0;
    for (auto _ : state) {
        for (const auto& root : f.loaded.roots) benchmark::DoNotOptimize(root->animate(t));
        for (std::size_t i = 0; i < f.meshes.size(); ++i)
            benchmark::DoNotOptimize(deformers[i].update(*f.meshes[i], detail::MeshDeformer::Output::Vertices, rigid));
        t = (t + 33) % f.period;
    }
    std::size_t rigidMeshes = 0;
    for (const auto& d : deformers) rigidMeshes += d.vertices().rigid;
    state.counters["rigid_meshes"] = static_cast<double>(rigidMeshes);
}

void BM_SkinnedCorpusFrame(benchmark::State& state, const SkinnedFile& file) {
    skinnedCorpusFrames(state, file, detail::MeshDeformer::Rigid::AsTransform);
}

void BM_SkinnedCorpusFrameAllVertices(benchmark::State& state, const SkinnedFile& file) {
    skinnedCorpusFrames(state, file, detail::MeshDeformer::Rigid::Deform);
}

// The animation share of BM_SkinnedCorpusFrame: the same files and times,
// animate() alone.
void BM_SkinnedCorpusAnimate(benchmark::State& state, const SkinnedFile& file) {
    SkinnedScene f;
    if (!loadSkinned(state, file, f)) return;
    int t = 0;
    for (auto _ : state) {
        for (const auto& root : f.loaded.roots) benchmark::DoNotOptimize(root->animate(t));
        t = (t + 33) % f.period;
    }
}

// One benchmark per file, named after it: BM_SkinnedCorpusFrame/test,
// BM_SkinnedCorpusFrameAllVertices/test, BM_SkinnedCorpusAnimate/test.
const int kSkinnedCorpusRegistered = [] {
    for (const SkinnedFile& f : kSkinnedFiles) {
        benchmark::RegisterBenchmark((std::string("BM_SkinnedCorpusFrame/") + f.name).c_str(),
                                     [&f](benchmark::State& state) { BM_SkinnedCorpusFrame(state, f); })
            ->Unit(benchmark::kMicrosecond);
        benchmark::RegisterBenchmark((std::string("BM_SkinnedCorpusFrameAllVertices/") + f.name).c_str(),
                                     [&f](benchmark::State& state) { BM_SkinnedCorpusFrameAllVertices(state, f); })
            ->Unit(benchmark::kMicrosecond);
        benchmark::RegisterBenchmark((std::string("BM_SkinnedCorpusAnimate/") + f.name).c_str(),
                                     [&f](benchmark::State& state) { BM_SkinnedCorpusAnimate(state, f); })
            ->Unit(benchmark::kMicrosecond);
    }
    return 0;
}();

Ref<KeyframeSequence> sequence(int components, int interpolation, const std::vector<std::vector<float>>& keys) {
    Ref<KeyframeSequence> s = new KeyframeSequence(static_cast<int>(keys.size()), components, interpolation);
    for (std::size_t k = 0; k < keys.size(); ++k) s->setKeyframe(static_cast<int>(k), static_cast<int>(k) * 250, keys[k]);
    s->setDuration(static_cast<int>(keys.size()) * 250);
    s->setRepeatMode(KeyframeSequence::LOOP);
    return s;
}

Ref<World> syntheticWorld(int nodes) {
    Ref<World> world = new World();
    Ref<AnimationController> walk = new AnimationController();
    Ref<AnimationController> run = new AnimationController();
    run->setSpeed(1.5f, 0);
    run->setWeight(0.25f);
    walk->setWeight(0.75f);
    Ref<KeyframeSequence> move =
        sequence(3, KeyframeSequence::SPLINE, {{0, 0, 0}, {1, 2, 0}, {3, 1, -1}, {0, -1, 2}});
    Ref<KeyframeSequence> turn = sequence(4, KeyframeSequence::SLERP,
                                          {{0, 0, 0, 1}, {0, 0.38268f, 0, 0.92388f}, {0, 0.70711f, 0, 0.70711f}});
    for (int i = 0; i < nodes; ++i) {
        Ref<Group> g = new Group();
        for (AnimationController* c : {walk.get(), run.get()}) {
            Ref<AnimationTrack> tm = new AnimationTrack(move, AnimationTrack::TRANSLATION);
            tm->setController(c);
            g->addAnimationTrack(tm);
        }
        Ref<AnimationTrack> tr = new AnimationTrack(turn, AnimationTrack::ORIENTATION);
        tr->setController(walk);
        g->addAnimationTrack(tr);
        world->addChild(g);
    }
    return world;
}

void BM_AnimateSynthetic(benchmark::State& state) {
    const int nodes = static_cast<int>(state.range(0));
    Ref<World> world = syntheticWorld(nodes);
    int t = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(world->animate(t));
        t += 16;
    }
    state.counters["nodes/s"] = benchmark::Counter(double(nodes), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_AnimateSynthetic)->Arg(1000)->Unit(benchmark::kMicrosecond);

// A 250 x 200 quad grid (100,000 triangles) in the z = 0 plane, 1 unit per
// quad, centred on the origin, with normals and texture coordinates; a
// camera at z = 300 looking at it.
struct PickScene {
    Ref<World> world = new World();
    Ref<Camera> camera = new Camera();
    Ref<Mesh> mesh;
    int triangles = 0;
    PickScene() {
        constexpr int qx = 250, qy = 200;
        const int vx = qx + 1, vy = qy + 1;
        std::vector<std::int16_t> pos, nrm, tex;
        for (int y = 0; y < vy; ++y)
            for (int x = 0; x < vx; ++x) {
                pos.insert(pos.end(), {std::int16_t(x - qx / 2), std::int16_t(y - qy / 2), 0});
                nrm.insert(nrm.end(), {0, 0, 32767});
                tex.insert(tex.end(), {std::int16_t(x), std::int16_t(y)});
            }
        auto array = [](const std::vector<std::int16_t>& v, int comps) {
            Ref<VertexArray> a = new VertexArray(static_cast<int>(v.size()) / comps, comps, 2);
            a->set(0, a->getVertexCount(), v);
            return a;
        };
        Ref<VertexBuffer> vb = new VertexBuffer();
        vb->setPositions(array(pos, 3), 1.0f, {});
        vb->setNormals(array(nrm, 3));
        vb->setTexCoords(0, array(tex, 2), 1.0f / 250.0f, {});
        std::vector<int> strips, lengths;  // one strip per row of quads
        for (int y = 0; y < qy; ++y) {
            for (int x = 0; x < vx; ++x) {
                strips.push_back(y * vx + x);
                strips.push_back((y + 1) * vx + x);
            }
            lengths.push_back(2 * vx);
        }
        Ref<IndexBuffer> ib = new TriangleStripArray(strips, lengths);
        triangles = ib->getIndexCount() / 3;
        Ref<Appearance> app = new Appearance();
        Ref<PolygonMode> pm = new PolygonMode();
        pm->setCulling(PolygonMode::CULL_NONE);
        app->setPolygonMode(pm);
        mesh = new Mesh(vb, ib, app);
        world->addChild(mesh);
        camera->setPerspective(60, 1, 1, 1000);
        camera->setTranslation(0, 0, 300);
        world->addChild(camera);
        world->setActiveCamera(camera);
    }
};

void BM_PickRay100k(benchmark::State& state) {
    PickScene s;
    RayIntersection ri;
    bool hit = false;
    for (auto _ : state) {
        hit = s.world->pick(-1, 10.25f, -20.5f, 50, 0, 0, -1, &ri);
        benchmark::DoNotOptimize(hit);
    }
    if (!hit) state.SkipWithError("the ray missed the grid");
    state.counters["triangles"] = s.triangles;
    state.counters["triangles/s"] =
        benchmark::Counter(double(s.triangles), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PickRay100k)->Unit(benchmark::kMillisecond);

void BM_PickRayMiss100k(benchmark::State& state) {
    // Passes beside the grid: the bounding box rejects the mesh.
    PickScene s;
    RayIntersection ri;
    bool hit = true;
    for (auto _ : state) {
        hit = s.world->pick(-1, 500, 0, 50, 0, 0, -1, &ri);
        benchmark::DoNotOptimize(hit);
    }
    if (hit) state.SkipWithError("the ray hit the grid");
}
BENCHMARK(BM_PickRayMiss100k)->Unit(benchmark::kMillisecond);

void BM_PickCamera100k(benchmark::State& state) {
    PickScene s;
    RayIntersection ri;
    bool hit = false;
    for (auto _ : state) {
        hit = s.world->pick(-1, 0.4f, 0.55f, s.camera, &ri);
        benchmark::DoNotOptimize(hit);
    }
    if (!hit) state.SkipWithError("the camera ray missed the grid");
    state.counters["triangles/s"] =
        benchmark::Counter(double(s.triangles), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PickCamera100k)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
