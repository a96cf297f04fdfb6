// The compute-shader path of skinning and morphing (Graphics3D's m3g-vk
// extension SKINNING_COMPUTE; render-vk/ComputeDeformer, shaders/skin.comp
// and morph.comp) against the CPU path (scene/deform/MeshDeformer with the skin/
// kernels): the shaders' output read back and compared value by value on
// random meshes, and rendered images compared, on lavapipe with the
// validation layer on.
//
// Tolerance: |gpu - cpu| <= 1e-5 * max(|gpu|, |cpu|) + floor. Both paths
// round sums of products in single precision (in different orders, with or
// without fused multiply-adds), so a component that cancels to near zero
// carries an absolute error of a few ulps of its terms, not of itself. The
// floor is therefore 1e-6 (about 8 ulps) of the magnitude of the terms: for
// skinning, per vertex, sum_k w_k (|P_k| |p| + |t_k|) for positions and
// sum_k w_k |N_k| |n| / |sum_k w_k N_k n| for normals (renormalisation
// divides the error by the blended length too); for morphing, the largest
// magnitude in the stream.
#include "VkTestSupport.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <m3g/skin/InfluenceTable.h>

#include "ComputeDeformer.h"
#include "ComputeRunner.h"
#include "Context.h"
#include "ImageIO.h"
#include "MeshDeformer.h"
#include "SceneKit.h"
#include "SceneSetup.h"

using namespace m3g;
using m3g::detail::MeshDeformer;
using m3gtest::VkTest;
namespace fs = std::filesystem;

namespace {

class ComputeSkinningTest : public m3gtest::SkinningModeTest {};

constexpr double kRelative = 1e-5;
constexpr double kFloorUlps = 1e-6;

struct Agreement {
    double worstRelative = 0.0;  // largest |gpu - cpu| / max(|gpu|, |cpu|, floor / kRelative)
    std::size_t failures = 0;
    std::string first;           // the first failing element, for the message
};

/// Compares `components` of every vertex: cpu has `cpuStride` floats per
/// vertex, gpu `gpuStride` (extra gpu components must be 0). `floors`: the
/// absolute floor per vertex; empty: kFloorUlps of the stream's largest
/// magnitude.
Agreement compare(const float* cpu, int cpuStride, const float* gpu, int gpuStride, int vertices, int components,
                  const std::vector<double>& floors = {}) {
    double largest = 0.0;
    for (int v = 0; v < vertices; ++v)
        for (int c = 0; c < components; ++c) largest = std::max(largest, std::abs(double(cpu[v * cpuStride + c])));
    Agreement a;
    for (int v = 0; v < vertices; ++v)
        for (int c = 0; c < gpuStride; ++c) {
            const double floor = floors.empty() ? kFloorUlps * largest : floors[static_cast<std::size_t>(v)];
            const double g = gpu[v * gpuStride + c];
            const double x = c < components ? double(cpu[v * cpuStride + c]) : 0.0;
            const double scale = std::max({std::abs(g), std::abs(x), floor / kRelative});
            const double rel = scale > 0 ? std::abs(g - x) / scale : 0.0;
            a.worstRelative = std::max(a.worstRelative, rel);
            if (std::abs(g - x) > kRelative * std::max(std::abs(g), std::abs(x)) + floor || std::isnan(g)) {
                if (a.failures++ == 0)
                    a.first = "vertex " + std::to_string(v) + " component " + std::to_string(c) + ": gpu " +
                              std::to_string(g) + ", cpu " + std::to_string(x);
            }
        }
    return a;
}

#define EXPECT_AGREE(agreement, what)                                                                       \
    do {                                                                                                    \
        const Agreement a_ = (agreement);                                                                   \
        EXPECT_EQ(a_.failures, 0u) << (what) << ": " << a_.failures << " values off; first " << a_.first;  \
        std::printf("  %-28s worst relative difference %.3g (limit %.0e)\n", (what), a_.worstRelative, kRelative); \
    } while (0)

/// The compute path's harness (tests/bench/ComputeRunner.h) on the shared device.
struct GpuRunner : m3gbench::ComputeRunner {
    GpuRunner() : ComputeRunner(vk::Context::get()) {}
};

// ---- Random skinned meshes -------------------------------------------------

struct RandomSkin {
    Ref<Group> skeleton = new Group();
    std::vector<Ref<Group>> nodes;  // [0] = skeleton, then the bones
    Ref<SkinnedMesh> mesh;
    std::mt19937 rng;

    void randomPose(Group& g) {
        std::uniform_real_distribution<float> u(-1.0f, 1.0f), s(0.4f, 2.2f);
        g.setTranslation(2 * u(rng), 2 * u(rng), 2 * u(rng));
        g.setOrientation(180 * u(rng), u(rng), u(rng), u(rng) + 0.01f);
        g.setScale(s(rng), s(rng), s(rng));  // non-uniform: normals need the inverse transpose
    }
    void newPose() {
        for (std::size_t i = 1; i < nodes.size(); ++i) randomPose(*nodes[i]);
    }

    /// `n` vertices in runs of 1..8 sharing 0..6 bones (more than 4: the
    /// top-4 selection), the last 16 vertices with none (beyond the table).
    RandomSkin(std::uint32_t seed, int n, int bones, bool shortNormals) : rng(seed) {
        std::uniform_int_distribution<int> coord(-3000, 3000), s16(-32768, 32767), s8(-128, 127);
        std::vector<std::int16_t> pos, nrm16;
        std::vector<std::int8_t> nrm8;
        for (int i = 0; i < n * 3; ++i) {
            pos.push_back(static_cast<std::int16_t>(coord(rng)));
            nrm16.push_back(static_cast<std::int16_t>(s16(rng)));
            nrm8.push_back(static_cast<std::int8_t>(s8(rng)));
        }
        Ref<VertexBuffer> vb = new VertexBuffer();
        Ref<VertexArray> p = new VertexArray(n, 3, 2);
        p->set(0, n, pos);
        const float bias[3] = {0.25f, -0.5f, 1.0f};
        vb->setPositions(p, 0.003f, bias);
        Ref<VertexArray> a = new VertexArray(n, 3, shortNormals ? 2 : 1);
        if (shortNormals) a->set(0, n, nrm16);
        else a->set(0, n, nrm8);
        vb->setNormals(a);

        nodes.push_back(skeleton);
        for (int i = 0; i < bones; ++i) {
            Ref<Group> g = new Group();
            std::uniform_int_distribution<std::size_t> parent(0, nodes.size() - 1);
            nodes[parent(rng)]->addChild(g);
            randomPose(*g);
            nodes.push_back(g);
        }
        const int lengths[] = {n};
        mesh = new SkinnedMesh(vb, new TriangleStripArray(0, lengths), nullptr, skeleton);
        std::uniform_int_distribution<int> run(1, 8), influences(0, 6), weight(1, 100);
        std::vector<int> pool(static_cast<std::size_t>(bones));
        for (int i = 0; i < bones; ++i) pool[static_cast<std::size_t>(i)] = i + 1;
        for (int first = 0; first < n - 16;) {
            const int count = std::min(run(rng), n - 16 - first);
            std::shuffle(pool.begin(), pool.end(), rng);
            const int k = influences(rng);
            for (int b = 0; b < k; ++b)
                mesh->addTransform(nodes[static_cast<std::size_t>(pool[static_cast<std::size_t>(b)])], weight(rng),
                                   first, count);
            first += count;
        }
        newPose();
    }

    /// Vertices per number of filled influence slots (0..4).
    std::array<int, 5> influenceHistogram() const {
        std::array<int, 5> h{};
        const auto& table = mesh->influenceTable();
        for (int v = 0; v < mesh->getVertexBuffer()->getVertexCount(); ++v) ++h[static_cast<std::size_t>(table.count(v))];
        return h;
    }
};

void skinOnGpu(GpuRunner& gpu, const MeshDeformer& d) {
    const detail::SkinInputs in = d.skinInputs();
    const auto n = static_cast<std::uint32_t>(in.vertexCount);
    gpu.ensureOutput(std::size_t(n) * 6);
    vk::ComputeDeformer::Streams streams;
    streams.positions = 0;
    streams.normals = n * 3;
    gpu.run([&](VkCommandBuffer cmd) { gpu.deformer.recordSkin(cmd, gpu.state, in, d.inputStamp(), gpu.out, streams); });
}

/// Per-vertex floors (see the top of the file) from the kernel inputs.
void skinFloors(const detail::SkinInputs& in, std::vector<double>& positions, std::vector<double>& normals) {
    const auto n = static_cast<std::size_t>(in.vertexCount);
    const auto stride = static_cast<std::size_t>(in.influenceStride);
    const std::size_t tableVertices = stride ? in.bones.size() / stride : 0;
    positions.assign(n, 0.0);
    normals.assign(n, 0.0);
    for (std::size_t v = 0; v < n; ++v) {
        double p[3];
        const double nn[3] = {in.normals[v * 3], in.normals[v * 3 + 1], in.normals[v * 3 + 2]};
        // Influenced: the palette (scale and bias folded in) times the raw
        // position; no bone: the scaled position (set below).
        for (int c = 0; c < 3; ++c) p[c] = in.positions[v * 3 + c];
        // Per output row: the sum of |terms| over influences and columns.
        double posRows[3] = {}, nrmRows[3] = {}, blended[3] = {};
        int used = 0;
        for (std::size_t k = 0; v < tableVertices && k < stride && in.bones[v * stride + k] >= 0; ++k) {
            const auto b = static_cast<std::size_t>(in.bones[v * stride + k]);
            if (b >= in.palette.size()) continue;
            const double w = in.weights[v * stride + k];
            const skin::PaletteEntry& e = in.palette[b];
            ++used;
            for (int r = 0; r < 3; ++r) {
                posRows[r] += w * std::abs(e.position[r * 4 + 3]);
                for (int c = 0; c < 3; ++c) {
                    posRows[r] += w * std::abs(e.position[r * 4 + c] * p[c]);
                    nrmRows[r] += w * std::abs(e.normal[r * 4 + c] * nn[c]);
                    blended[r] += w * e.normal[r * 4 + c] * nn[c];
                }
            }
        }
        if (used == 0) {  // mesh space: the scaled position and the renormalised normal
            for (int c = 0; c < 3; ++c) p[c] = double(in.positionScale) * p[c] + in.positionBias[c];
            positions[v] = kFloorUlps * std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
            normals[v] = kFloorUlps;
            continue;
        }
        const double len = std::sqrt(blended[0] * blended[0] + blended[1] * blended[1] + blended[2] * blended[2]);
        positions[v] = kFloorUlps * std::max({posRows[0], posRows[1], posRows[2]});
        normals[v] = kFloorUlps * std::max({nrmRows[0], nrmRows[1], nrmRows[2]}) / std::max(len, 1e-30);
    }
}

void expectSkinAgrees(const GpuRunner& gpu, const MeshDeformer& cpu, const detail::SkinInputs& in) {
    const auto& v = cpu.vertices();
    const int n = v.vertexCount;
    std::vector<double> positionFloors, normalFloors;
    skinFloors(in, positionFloors, normalFloors);
    // The CPU's outputs come in its own order (DeformedVertices::order), the
    // kernel's in the mesh's.
    const std::vector<float> positions = v.inMeshOrder(v.positions, 3), normals = v.inMeshOrder(v.normals, 3);
    EXPECT_AGREE(compare(positions.data(), 3, gpu.floats(), 3, n, 3, positionFloors), "positions");
    EXPECT_AGREE(compare(normals.data(), 3, gpu.floats() + n * 3, 3, n, 3, normalFloors), "normals");
}

}  // namespace

TEST_F(ComputeSkinningTest, SkinningAgreesWithCpuOnRandomMeshes) {
    struct Case {
        std::uint32_t seed;
        int vertices, bones;
        bool shortNormals;
    };
    // The last case has many bones (a large palette).
    for (const Case c : {Case{1, 3000, 20, true}, Case{2, 5000, 41, false}, Case{3, 2000, 60, true},
                         Case{4, 2000, 150, false}}) {
        SCOPED_TRACE("seed " + std::to_string(c.seed) + ", " + std::to_string(c.bones) + " bones");
        std::printf("random skin: %d vertices, %d bones\n", c.vertices, c.bones);
        RandomSkin rig(c.seed, c.vertices, c.bones, c.shortNormals);
        const auto histogram = rig.influenceHistogram();
        for (int k = 0; k <= 4; ++k) EXPECT_GT(histogram[static_cast<std::size_t>(k)], 0) << k << " influences";
        ASSERT_LT(rig.mesh->influenceTable().vertexCount(), c.vertices);  // vertices beyond the table

        MeshDeformer cpu, gpuInputs;
        ASSERT_TRUE(cpu.update(*rig.mesh));
        ASSERT_TRUE(gpuInputs.update(*rig.mesh, MeshDeformer::Output::InputsOnly));
        EXPECT_TRUE(gpuInputs.vertices().positions.empty());  // no CPU kernel ran
        GpuRunner gpu;
        skinOnGpu(gpu, gpuInputs);
        expectSkinAgrees(gpu, cpu, gpuInputs.skinInputs());

        // A new pose: only the palette changes; the static inputs stay on the GPU.
        EXPECT_FALSE(gpuInputs.update(*rig.mesh, MeshDeformer::Output::InputsOnly));
        rig.newPose();
        const auto stamp = gpuInputs.inputStamp();
        const VkBuffer inputs = gpu.state.inputs.buffer;
        ASSERT_TRUE(cpu.update(*rig.mesh));
        ASSERT_TRUE(gpuInputs.update(*rig.mesh, MeshDeformer::Output::InputsOnly));
        EXPECT_EQ(gpuInputs.inputStamp(), stamp);
        skinOnGpu(gpu, gpuInputs);
        EXPECT_EQ(gpu.state.inputs.buffer, inputs);
        expectSkinAgrees(gpu, cpu, gpuInputs.skinInputs());
    }
}

TEST_F(ComputeSkinningTest, SkinningWithoutNormalsAndWithEmptyPalette) {
    // No normals: only positions are written. A mesh with no bone at all:
    // every vertex stays in mesh space (s * p + bias).
    const int n = 300;  // several 64-wide groups, the last one partial
    std::vector<std::int16_t> pos;
    for (int i = 0; i < n * 3; ++i) pos.push_back(static_cast<std::int16_t>(i * 37 - 2000));
    Ref<VertexBuffer> vb = new VertexBuffer();
    Ref<VertexArray> p = new VertexArray(n, 3, 2);
    p->set(0, n, pos);
    const float bias[3] = {1.0f, 2.0f, 3.0f};
    vb->setPositions(p, 0.5f, bias);
    const int lengths[] = {n};
    Ref<Group> skeleton = new Group();
    Ref<SkinnedMesh> mesh = new SkinnedMesh(vb, new TriangleStripArray(0, lengths), nullptr, skeleton);
    MeshDeformer d;
    ASSERT_TRUE(d.update(*mesh, MeshDeformer::Output::InputsOnly));
    EXPECT_TRUE(d.skinInputs().normals.empty());
    GpuRunner gpu;
    gpu.ensureOutput(std::size_t(n) * 3);
    vk::ComputeDeformer::Streams streams;
    streams.positions = 0;
    gpu.run([&](VkCommandBuffer cmd) { gpu.deformer.recordSkin(cmd, gpu.state, d.skinInputs(), d.inputStamp(), gpu.out, streams); });
    for (int v = 0; v < n; ++v)
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(gpu.floats()[v * 3 + c], 0.5f * static_cast<float>(pos[static_cast<std::size_t>(v * 3 + c)]) + bias[c])
                << "vertex " << v;
}

TEST_F(ComputeSkinningTest, MorphAgreesWithCpu) {
    // 4 targets with every attribute: positions (shorts, scale and bias),
    // normals (bytes), RGBA colours (pushed past [0, 1] by the weights:
    // clamped), texture coordinates with 2 and 3 components; one weight 0,
    // one negative, one above 1.
    const int n = 900;
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> s16(-4000, 4000), s8(-128, 127);
    auto buffer = [&]() {
        std::vector<std::int16_t> pos, tex0;
        std::vector<std::int8_t> nrm, col, tex1;
        for (int i = 0; i < n * 3; ++i) {
            pos.push_back(static_cast<std::int16_t>(s16(rng)));
            nrm.push_back(static_cast<std::int8_t>(s8(rng)));
            tex1.push_back(static_cast<std::int8_t>(s8(rng)));
        }
        for (int i = 0; i < n * 4; ++i) col.push_back(static_cast<std::int8_t>(s8(rng)));
        for (int i = 0; i < n * 2; ++i) tex0.push_back(static_cast<std::int16_t>(s16(rng)));
        Ref<VertexBuffer> vb = new VertexBuffer();
        Ref<VertexArray> p = new VertexArray(n, 3, 2), nn = new VertexArray(n, 3, 1), c = new VertexArray(n, 4, 1),
                         t0 = new VertexArray(n, 2, 2), t1 = new VertexArray(n, 3, 1);
        p->set(0, n, pos);
        nn->set(0, n, nrm);
        c->set(0, n, col);
        t0->set(0, n, tex0);
        t1->set(0, n, tex1);
        const float bias[3] = {0.5f, -1.0f, 2.0f};
        vb->setPositions(p, 0.01f, bias);
        vb->setNormals(nn);
        vb->setColors(c);
        vb->setTexCoords(0, t0, 0.001f, bias);
        vb->setTexCoords(1, t1, 1.0f, {});
        return vb;
    };
    Ref<VertexBuffer> base = buffer();
    std::vector<Ref<VertexBuffer>> targets{buffer(), buffer(), buffer(), buffer()};
    const int lengths[] = {n};
    Ref<MorphingMesh> mesh = new MorphingMesh(base, targets, new TriangleStripArray(0, lengths), nullptr);

    GpuRunner gpu;
    gpu.ensureOutput(std::size_t(n) * 16);
    vk::ComputeDeformer::Streams streams;
    streams.positions = 0;
    streams.normals = n * 3;
    streams.colors = n * 6;
    streams.texCoords = {std::uint32_t(n) * 10, std::uint32_t(n) * 13};
    MeshDeformer cpu, inputs;
    for (const std::array<float, 4>& w :
         {std::array<float, 4>{0.7f, -0.4f, 0.0f, 1.3f}, std::array<float, 4>{0.25f, 0.25f, 0.25f, 0.25f}}) {
        mesh->setWeights(w);
        ASSERT_TRUE(cpu.update(*mesh));
        ASSERT_TRUE(inputs.update(*mesh, MeshDeformer::Output::InputsOnly));
        std::array<detail::MorphAttributeInputs, MeshDeformer::kMorphAttributes> attributes{};
        for (int a = 0; a < MeshDeformer::kMorphAttributes; ++a)
            attributes[static_cast<std::size_t>(a)] = inputs.morphAttribute(a);
        gpu.run([&](VkCommandBuffer cmd) {
            gpu.deformer.recordMorph(cmd, gpu.state, attributes, inputs.morphWeights(), n, inputs.inputStamp(),
                                     gpu.out, streams);
        });
        const auto& v = cpu.vertices();
        const float* out = gpu.floats();
        EXPECT_AGREE(compare(v.positions.data(), 3, out, 3, n, 3), "morphed positions");
        EXPECT_AGREE(compare(v.normals.data(), 3, out + n * 3, 3, n, 3), "morphed normals");
        EXPECT_AGREE(compare(v.colors.data(), 4, out + n * 6, 4, n, 4), "morphed colours");
        EXPECT_AGREE(compare(v.texCoords[0].data(), 2, out + n * 10, 3, n, 2), "morphed texcoords 0 (2D)");
        EXPECT_AGREE(compare(v.texCoords[1].data(), 3, out + n * 13, 3, n, 3), "morphed texcoords 1 (3D)");
        if (w[0] == 0.7f) {  // the first weights push colours past both ends: clamped
            EXPECT_NE(std::find(out + n * 6, out + n * 10, 0.0f), out + n * 10);
            EXPECT_NE(std::find(out + n * 6, out + n * 10, 1.0f), out + n * 10);
        }
    }
}

// ---- Through Graphics3D ---------------------------------------------------

namespace {

/// An opaque dark grey RGBA target.
Ref<Image2D> makeTarget(int w, int h) {
    std::vector<std::uint8_t> px(static_cast<std::size_t>(w) * h * 4);
    for (std::size_t i = 0; i < px.size(); i += 4) {
        px[i] = px[i + 1] = px[i + 2] = 0x20;
        px[i + 3] = 0xFF;
    }
    Ref<Image2D> image = new Image2D(Image2D::RGBA, w, h);
    image->set(0, 0, w, h, px);
    return image;
}

m3gcli::RgbaImage rgbaOf(const Image2D& image) {
    m3gcli::RgbaImage out;
    out.width = image.getWidth();
    out.height = image.getHeight();
    image.getPixelsRGBA8(out.pixels);
    return out;
}

/// A lit, vertex-coloured grid skinned by three bones in a chain, and a
/// morphing quad strip beside it.
struct SkinScene {
    Ref<Group> root = new Group();
    Ref<Group> skeleton = new Group();
    std::vector<Ref<Group>> bones;
    Ref<SkinnedMesh> skinned;
    Ref<MorphingMesh> morphing;
    Ref<Camera> camera = new Camera();
    Ref<Light> light = new Light();

    SkinScene() {
        const int cols = 12, rows = 24, n = cols * rows;
        std::vector<std::int16_t> pos, tex;
        std::vector<std::int8_t> nrm, col;
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < cols; ++c) {
                pos.insert(pos.end(), {static_cast<std::int16_t>(c * 100 - 550), static_cast<std::int16_t>(r * 100 - 1150), 0});
                nrm.insert(nrm.end(), {static_cast<std::int8_t>(c * 5 - 30), 0, 127});
                col.insert(col.end(), {static_cast<std::int8_t>(r * 10), static_cast<std::int8_t>(c * 20), -1});
            }
        Ref<VertexBuffer> vb = new VertexBuffer();
        Ref<VertexArray> p = new VertexArray(n, 3, 2), nn = new VertexArray(n, 3, 1), cc = new VertexArray(n, 3, 1);
        p->set(0, n, pos);
        nn->set(0, n, nrm);
        cc->set(0, n, col);
        vb->setPositions(p, 0.001f, {});
        vb->setNormals(nn);
        vb->setColors(cc);
        Ref<Appearance> app = new Appearance();
        Ref<Material> material = new Material();
        material->setVertexColorTrackingEnable(true);
        app->setMaterial(material);
        Ref<PolygonMode> pm = new PolygonMode();
        pm->setCulling(PolygonMode::CULL_NONE);
        pm->setTwoSidedLightingEnable(true);
        app->setPolygonMode(pm);
        skinned = new SkinnedMesh(vb, m3gtest::gridStrips(rows, cols), app, skeleton);
        Group* parent = skeleton.get();
        for (int b = 0; b < 3; ++b) {
            Ref<Group> bone = new Group();
            bone->setTranslation(0, b == 0 ? -1.15f : 0.8f, 0);
            parent->addChild(bone);
            parent = bone.get();
            bones.push_back(bone);
        }
        // Rows 0..7 to bone 0, 8..15 to bone 1, 16..23 to bone 2, with a
        // blend to the neighbour across each boundary row band.
        for (int b = 0; b < 3; ++b) skinned->addTransform(bones[static_cast<std::size_t>(b)], 2, b * 8 * cols, 8 * cols);
        for (int b = 0; b < 2; ++b) skinned->addTransform(bones[static_cast<std::size_t>(b + 1)], 1, (b * 8 + 6) * cols, 4 * cols);
        skinned->setTranslation(-0.6f, 0, 0);
        root->addChild(skinned);

        // Morphing: a strip of 8 quads whose targets bend and recolour it.
        auto strip = [&](int bend, std::int8_t red) {
            std::vector<std::int16_t> q;
            std::vector<std::int8_t> qc;
            for (int i = 0; i < 18; ++i) {
                q.insert(q.end(), {static_cast<std::int16_t>((i % 2) * 400 - 200),
                                   static_cast<std::int16_t>((i / 2) * 250 - 1000 + ((i / 2) % 2) * bend), 0});
                qc.insert(qc.end(), {red, static_cast<std::int8_t>(i * 12), 64, -1});
            }
            Ref<VertexBuffer> v = new VertexBuffer();
            Ref<VertexArray> a = new VertexArray(18, 3, 2), c = new VertexArray(18, 4, 1);
            a->set(0, 18, q);
            c->set(0, 18, qc);
            v->setPositions(a, 0.001f, {});
            v->setColors(c);
            return v;
        };
        std::vector<Ref<VertexBuffer>> targets{strip(150, 127), strip(-300, 0)};
        const int quadLengths[] = {18};
        Ref<Appearance> flat = new Appearance();
        flat->setPolygonMode(pm);
        morphing = new MorphingMesh(strip(0, -1), targets, new TriangleStripArray(0, quadLengths), flat);
        morphing->setTranslation(0.8f, 0, 0);
        root->addChild(morphing);

        camera->setPerspective(60.0f, 1.0f, 0.1f, 10.0f);
        light->setMode(Light::DIRECTIONAL);
    }

    void pose(float angle) {
        for (std::size_t b = 1; b < bones.size(); ++b) bones[b]->setOrientation(angle * static_cast<float>(b), 0, 0.3f, 1);
        bones[0]->setScale(1.0f + angle / 200.0f, 1.0f, 1.3f);
        const float w[] = {angle / 60.0f, 1.0f - angle / 90.0f};
        morphing->setWeights(w);
    }

    /// A 96x96 target bound with skinning `mode`, no lights, the camera
    /// `distance` in front of the origin.
    Ref<Image2D> bind(int mode, float distance) {
        Ref<Image2D> target = makeTarget(96, 96);
        Graphics3D* g = Graphics3D::getInstance();
        g->setSkinningMode(mode);
        g->bindTarget(target.get());
        g->resetLights();
        Transform eye;
        eye.postTranslate(0, 0, distance);
        g->setCamera(camera, &eye);
        return target;
    }

    Ref<Image2D> render(int mode) {
        Ref<Image2D> target = bind(mode, 3);
        Graphics3D* g = Graphics3D::getInstance();
        Transform lightDir;
        lightDir.postRotate(-30, 1, 1, 0);
        g->addLight(light, &lightDir);
        g->render(root, nullptr);
        g->releaseTarget();
        return target;
    }
};

/// Images from the two paths: at most `maxShare` of the pixels may differ
/// by more than `threshold` in a channel.
void expectSameImage(const Image2D& cpu, const Image2D& gpu, int threshold, double maxShare, const std::string& what) {
    const m3gcli::Comparison c = m3gcli::compareImages(rgbaOf(gpu), rgbaOf(cpu), threshold);
    std::printf("  %-40s pixels off by more than %d: %.5f%%, PSNR %.1f dB\n", what.c_str(), threshold, c.share * 100,
                c.psnr);
    EXPECT_LE(c.share, maxShare) << what;
}

}  // namespace

TEST_F(ComputeSkinningTest, SkinningRendersAsCpuAndDispatchesOnlyOnChange) {
    // Two copies of the scene, so that the compute image cannot come from
    // vertex mirrors the CPU path filled.
    SkinScene cpuScene, scene;
    cpuScene.pose(25.0f);
    scene.pose(25.0f);
    const Ref<Image2D> cpu = cpuScene.render(Graphics3D::SKINNING_CPU);
    const auto before = vk::renderStats().computeDispatches;
    const Ref<Image2D> gpu = scene.render(Graphics3D::SKINNING_COMPUTE);
    // One dispatch for the skinned mesh, one per morphed attribute (positions, colours).
    EXPECT_EQ(vk::renderStats().computeDispatches - before, 3u);
    expectSameImage(*cpu, *gpu, 2, 0.0, "skinned grid and morphing strip");
    EXPECT_GT(m3gcli::compareImages(rgbaOf(*cpu), rgbaOf(*makeTarget(96, 96)), 8).share, 0.1)
        << "the scene should cover the target";

    // Nothing changed: no dispatch. A bone moves: the skinned mesh only.
    // A weight changes: the morphing mesh only.
    auto dispatches = [&] {
        const auto b = vk::renderStats().computeDispatches;
        scene.render(Graphics3D::SKINNING_COMPUTE);
        return vk::renderStats().computeDispatches - b;
    };
    EXPECT_EQ(dispatches(), 0u);
    scene.bones[2]->setOrientation(40, 0, 0, 1);
    EXPECT_EQ(dispatches(), 1u);
    const float w[] = {0.1f, 0.2f};
    scene.morphing->setWeights(w);
    EXPECT_EQ(dispatches(), 2u);
    EXPECT_EQ(dispatches(), 0u);

    // Back and forth between the paths on one scene, and a new pose: still
    // the same images.
    scene.pose(-35.0f);
    const Ref<Image2D> cpu2 = scene.render(Graphics3D::SKINNING_CPU);
    const Ref<Image2D> gpu2 = scene.render(Graphics3D::SKINNING_COMPUTE);
    expectSameImage(*cpu2, *gpu2, 2, 0.0, "second pose");
    EXPECT_GT(m3gcli::compareImages(rgbaOf(*cpu), rgbaOf(*cpu2), 8).share, 0.01) << "the poses should differ";

    // Picking keeps the CPU-deformed vertices whatever the drawing mode.
    Graphics3D::getInstance()->setSkinningMode(Graphics3D::SKINNING_COMPUTE);
    RayIntersection hit;
    Ref<Group> world = scene.root;
    // The ray meets the part of the grid that only bone 0 (scaled by 0.825
    // in x at this pose) moves.
    const bool picked = world->pick(-1, -0.6f, -0.9f, 0.5f, 0.0f, 0.0f, -1.0f, &hit);
    ASSERT_TRUE(picked);
    EXPECT_EQ(hit.getIntersected().get(), scene.skinned.get());
    EXPECT_NEAR(hit.getDistance(), 0.5f, 1e-4f);
}

TEST_F(ComputeSkinningTest, SameMeshTwiceInOneFrame) {
    // Two poses of one mesh drawn in one frame: each draw reads its own pose
    // (the second deformation must not overwrite what the first draw reads).
    Ref<Image2D> images[2];
    for (int mode : {Graphics3D::SKINNING_CPU, Graphics3D::SKINNING_COMPUTE}) {
        SkinScene scene;  // one per path: no mirror shared between them
        Ref<Image2D> target = scene.bind(mode, 4);
        Graphics3D* g = Graphics3D::getInstance();
        scene.pose(10.0f);
        Transform left;
        left.postTranslate(-0.9f, 0, 0);
        g->render(scene.skinned, &left);
        scene.pose(-40.0f);
        Transform right;
        right.postTranslate(0.9f, 0, 0);
        g->render(scene.skinned, &right);
        g->releaseTarget();
        images[mode] = target;
    }
    expectSameImage(*images[0], *images[1], 2, 0.0, "two poses in one frame");
}

TEST_F(ComputeSkinningTest, SkinnedCorpusFilesRenderAsWithCpu) {
    const fs::path corpus = M3G_CORPUS_DIR;
    const char* files[] = {"BaalNetbek__M3G-Viewer/com.wizzer.m3g.toolkit/test/robot.m3g",
                           "bryan10328__java-m3g/res/mahosyojo-with-sexy-walking.m3g"};
    int rendered = 0;
    for (const char* file : files) {
        const fs::path path = corpus / "models" / file;
        if (!fs::exists(path)) continue;
        for (int time : {0, 1500, 3333}) {
            const int w = 160, h = 120;
            Ref<Image2D> images[2];
            std::uint64_t dispatches = 0;
            for (int mode : {Graphics3D::SKINNING_CPU, Graphics3D::SKINNING_COMPUTE}) {
                // Loaded once per path: no mirror shared between them.
                LoadResult loaded = Loader::loadDetailed(path.string());
                m3gcli::PreparedScene scene = m3gcli::prepareScene(loaded, w, h);
                scene.world->animate(time);
                images[mode] = target(w, h, 0xFF000000u);
                Graphics3D* g = Graphics3D::getInstance();
                g->setSkinningMode(mode);
                g->bindTarget(images[mode].get());
                const auto before = vk::renderStats().computeDispatches;
                g->render(scene.world.get());
                g->releaseTarget();
                if (mode == Graphics3D::SKINNING_COMPUTE) dispatches = vk::renderStats().computeDispatches - before;
            }
            EXPECT_GT(dispatches, 0u) << file << ": no mesh went through the compute path";
            expectSameImage(*images[0], *images[1], 2, 0.0005,
                            fs::path(file).filename().string() + " at " + std::to_string(time) + " ms");
            ++rendered;
        }
    }
    if (rendered == 0) GTEST_SKIP() << "no skinned corpus files under " << corpus << " (skipped)";
}
