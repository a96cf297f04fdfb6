#include "Soak.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <m3g/m3g.h>
#include <m3g/vk/Vulkan.h>

#include "SceneSetup.h"

namespace m3gcli {

namespace {

using namespace m3g;

constexpr int kFrameMs = 40;  // animation time step (25 fps)

/// A quad of two triangles, made of new objects: what a game's immediate-mode
/// HUD or effect draw looks like when it builds its geometry per frame.
struct Immediate {
    Ref<VertexBuffer> vertices;
    Ref<IndexBuffer> triangles;
    Ref<Appearance> appearance;
};

Immediate makeImmediate(int frame, float centerX, float centerY, float centerZ, float size) {
    Immediate d;
    Ref<VertexArray> pos(new VertexArray(4, 3, 2));
    const std::int16_t p[] = {-1, -1, 0, 1, -1, 0, -1, 1, 0, 1, 1, 0};
    pos->set(0, 4, std::span<const std::int16_t>(p));
    Ref<VertexArray> col(new VertexArray(4, 4, 1));
    const auto c = static_cast<std::int8_t>(frame & 0x7F);
    const std::int8_t cv[] = {c, 0, 0, -1, 0, c, 0, -1, 0, 0, c, -1, c, c, c, -1};
    col->set(0, 4, std::span<const std::int8_t>(cv));
    d.vertices = new VertexBuffer();
    const float bias[3] = {centerX, centerY, centerZ};
    d.vertices->setPositions(pos.get(), size, bias);
    d.vertices->setColors(col.get());
    const int lengths[] = {4};
    d.triangles = new TriangleStripArray(0, lengths);
    d.appearance = new Appearance();
    Ref<CompositingMode> cm(new CompositingMode());
    cm->setBlending(CompositingMode::ALPHA_ADD);
    d.appearance->setCompositingMode(cm.get());
    // A texture every few frames: exercises image uploads and their deferred frees.
    if (frame % 4 == 0) {
        std::uint8_t texels[2 * 2 * 3];
        for (int i = 0; i < 12; ++i) texels[i] = static_cast<std::uint8_t>(frame * 7 + i * 19);
        Ref<Texture2D> t(new Texture2D(new Image2D(Image2D::RGB, 2, 2, std::span<const std::uint8_t>(texels))));
        d.appearance->setTexture(0, t.get());
        Ref<VertexArray> tc(new VertexArray(4, 2, 1));
        const std::int8_t tv[] = {0, 0, 1, 0, 0, 1, 1, 1};
        tc->set(0, 4, std::span<const std::int8_t>(tv));
        const float zero[3] = {0, 0, 0};
        d.vertices->setTexCoords(0, tc.get(), 1.0f, zero);
    }
    return d;
}

SoakSample sample(int frame, int cycle) {
    const vk::RenderStats s = vk::renderStats();
    SoakSample out;
    out.frame = frame;
    out.cycle = cycle;
    out.residentBytes = residentBytes();
    out.deviceBytes = s.deviceMemoryBytes;
    out.liveBuffers = s.liveBuffers;
    out.liveTextures = s.liveTextures;
    return out;
}

}  // namespace

std::uint64_t residentBytes() {
    std::ifstream statm("/proc/self/statm");
    std::uint64_t size = 0, resident = 0;
    if (!(statm >> size >> resident)) return 0;
    return resident * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
}

SoakResult runSoak(const SoakOptions& o, const std::function<void(const SoakSample&)>& onSample) {
    SoakResult result;
    const std::uint64_t messagesBefore = vk::validationMessageCount();
    const std::uint64_t drawsBefore = vk::renderStats().draws;
    Graphics3D* g = Graphics3D::getInstance();
    // A Graphics surface, as `m3g render` (background images are RGB).
    Ref<Graphics> target(new Graphics(o.width, o.height));
    Ref<World> world;
    std::array<float, 3> center{};
    float radius = 1.0f;
    const int reload = std::max(1, o.reload);
    for (int frame = 0; frame < o.frames; ++frame) {
        const int cycle = frame / reload, phase = frame % reload;
        if (phase == 0) {
            // Drop everything of the previous load first: its GPU mirrors go
            // at the end of this frame, once the GPU is done with them.
            world = nullptr;
            g->setCamera(nullptr, nullptr);
            g->resetLights();
            const LoadResult loaded = Loader::loadDetailed(o.file);
            PreparedScene scene = prepareScene(loaded, o.width, o.height);
            world = scene.world;
            sceneBounds(*world, center, radius);
        }
        world->animate(phase * kFrameMs);
        // By phase, not frame: every cycle does the same work, so cycle ends compare exactly.
        Immediate a = makeImmediate(phase, center[0], center[1], center[2], radius * 0.1f);
        g->bindTarget(target.get(), true, 0);
        try {
            g->render(world.get());
            // Immediate mode with the World's camera and lights, left by render(World).
            Transform spin;
            spin.postRotate(static_cast<float>(phase % 360), 0, 0, 1);
            g->render(a.vertices.get(), a.triangles.get(), a.appearance.get(), &spin);
            g->render(a.vertices.get(), a.triangles.get(), a.appearance.get(), nullptr, 0);  // scope 0: not drawn
        } catch (...) {
            g->releaseTarget();
            throw;
        }
        g->releaseTarget();
        if (phase == reload - 1) {
            result.cycleEnds.push_back(sample(frame + 1, cycle));
            if (onSample) onSample(result.cycleEnds.back());
        } else if (o.reportEvery > 0 && (frame + 1) % o.reportEvery == 0 && onSample) {
            onSample(sample(frame + 1, cycle));
        }
    }
    world = nullptr;
    g->setCamera(nullptr, nullptr);
    g->resetLights();
    result.draws = vk::renderStats().draws - drawsBefore;
    result.validationMessages = vk::validationMessageCount() - messagesBefore;

    // The verdict over the cycle ends after the warm-up (at least the last two).
    const auto& ends = result.cycleEnds;
    const std::size_t first =
        ends.size() > 2 ? std::min<std::size_t>(static_cast<std::size_t>(std::max(0, o.warmupCycles)), ends.size() - 2) : 0;
    std::ostringstream v;
    if (ends.size() < 2) {
        v << "not judged: fewer than two complete reload cycles (need frames >= 2 x reload)";
        result.verdict = v.str();
        return result;
    }
    result.judgedCycles = static_cast<int>(ends.size() - first);
    result.gpuFlat = true;
    std::uint64_t minResident = ends[first].residentBytes, maxResident = ends[first].residentBytes;
    for (std::size_t i = first; i < ends.size(); ++i) {
        result.gpuFlat = result.gpuFlat && ends[i].liveBuffers == ends[first].liveBuffers &&
                         ends[i].liveTextures == ends[first].liveTextures &&
                         ends[i].deviceBytes == ends[first].deviceBytes;
        minResident = std::min(minResident, ends[i].residentBytes);
        maxResident = std::max(maxResident, ends[i].residentBytes);
    }
    result.residentGrowthBytes =
        static_cast<std::int64_t>(ends.back().residentBytes) - static_cast<std::int64_t>(ends[first].residentBytes);
    // Allocator noise: 4 MiB or 5 % of the first judged value, whichever is larger.
    result.residentToleranceBytes = std::max<std::uint64_t>(4u << 20, ends[first].residentBytes / 20);
    result.residentFlat = result.residentGrowthBytes <= static_cast<std::int64_t>(result.residentToleranceBytes);
    v << "GPU " << (result.gpuFlat ? "flat" : "NOT flat") << " (" << ends[first].liveBuffers << " buffers, "
      << ends[first].liveTextures << " textures, " << ends[first].deviceBytes << " bytes at cycle " << ends[first].cycle
      << "; " << ends.back().liveBuffers << ", " << ends.back().liveTextures << ", " << ends.back().deviceBytes
      << " at cycle " << ends.back().cycle << "); resident " << (result.residentFlat ? "flat" : "GROWING") << " ("
      << (result.residentGrowthBytes >= 0 ? "+" : "") << static_cast<double>(result.residentGrowthBytes) / 1048576.0
      << " MiB from cycle " << ends[first].cycle << " to " << ends.back().cycle << ", range "
      << static_cast<double>(maxResident - minResident) / 1048576.0 << " MiB, tolerance "
      << static_cast<double>(result.residentToleranceBytes) / 1048576.0 << " MiB)";
    result.verdict = v.str();
    return result;
}

}  // namespace m3gcli
