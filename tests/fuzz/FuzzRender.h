// The rules of the render fuzz target (fuzz_render.cpp), shared with the
// replay of its reproducers in the device tests (tests/vk/test_FuzzReplay.cpp):
// whatever the Loader accepts from hostile bytes is drawn on the Vulkan
// device (lavapipe in practice) the way `m3g render` draws a file, and then
// some. Test-only, header-only; needs m3g_cli_support (SceneSetup) and a
// Vulkan device.
//
// One input, in its checksum-repaired form (FuzzInput.h; the loader target
// covers the bytes as given):
//   1. lenient load; an IOException ends the input;
//   2. prepareScene (the World, auto-framing, camera fix-up), no exception;
//   3. three 32x32 frames: t = 0 with CPU deformation into a Graphics
//      surface (an RGB target, as `m3g render` draws), t = 977 ms with
//      compute deformation into an RGBA Image2D (where RGBA background
//      images are drawn), t = 977 ms again on the CPU into the Graphics (a
//      mode switch with nothing changed); then up to eight loaded
//      Mesh, Sprite3D and Group nodes in immediate mode, render(Node, null);
//   4. picks through the active camera at two points of the viewport;
//   5. everything dropped, one clear-only frame; steps 1-5 once more, after
//      which the renderer's live buffers, textures, pipelines and device
//      memory must be back where the first pass left them. (The first pass may grow the
//      renderer's pools, uniform chunks and sprite quads, to a new high
//      water mark that the renderer keeps; an identical second pass may not:
//      growth there is a leak per load.) On a CPU device (lavapipe) both
//      passes are counted (m3g::vk::setShaderInvocationCounting) and must
//      shade the same vertices and fragments: the same bytes draw the same
//      frames, whatever the first pass left in the renderer's caches.
// Allowed failures are those the API documents for a scene the Loader may
// legitimately produce: IllegalStateException from animate() (a keyframe
// sequence that cannot be sampled), render() (no active camera, indices
// past the vertex count, no positions, a background image of the wrong
// format) and pick(), ArithmeticException from render(World) (the active
// camera's transform to the World is singular) and from pick() (singular
// transforms or projections). Any other exception, a VulkanError, a
// validation message or a sanitizer report is a finding.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <typeinfo>

#include <m3g/m3g.h>
#include <m3g/vk/Vulkan.h>

#include "FuzzChecks.h"
#include "SceneSetup.h"

namespace m3gfuzz {

/// What a second pass over an input must leave as the first left it.
struct RendererBalance {
    std::uint64_t liveBuffers = 0, liveTextures = 0, deviceMemoryBytes = 0;
    /// The second pass draws with the keys of the first: it finds them all
    /// in the pipeline cache and makes none.
    std::uint64_t livePipelines = 0;

    static RendererBalance now() {
        const m3g::vk::RenderStats s = m3g::vk::renderStats();
        return {s.liveBuffers, s.liveTextures, s.deviceMemoryBytes, s.livePipelines};
    }
};

namespace detail {

inline constexpr int kTargetSize = 32;

/// Runs `step`; the exceptions named in FuzzRender.h's header pass (the
/// input then goes on to the next step), anything else is a Failure naming
/// the step. Returns false when an allowed exception was thrown.
template <class Step>
bool allowDocumented(const char* stage, bool arithmeticAllowed, Step step) {
    try {
        step();
        return true;
    } catch (const Failure&) {
        throw;
    } catch (const m3g::vk::VulkanError& e) {
        throw Failure{std::string(stage) + ": VulkanError: " + e.what()};
    } catch (const m3g::IllegalStateException&) {
        return false;
    } catch (const m3g::ArithmeticException& e) {
        if (arithmeticAllowed) return false;
        throw Failure{std::string(stage) + ": unexpected ArithmeticException: " + e.what()};
    } catch (const std::exception& e) {
        throw Failure{std::string(stage) + ": unexpected " + typeid(e).name() + ": " + e.what()};
    } catch (...) {
        throw Failure{std::string(stage) + ": unexpected non-std exception"};
    }
}

inline void expectNoValidation(std::uint64_t before, const std::string& stage) {
    if (m3g::vk::validationMessageCount() != before)
        throw Failure{stage + ": validation message: " + m3g::vk::lastValidationMessage()};
}

/// A clear-only frame: finishes the GPU's use of dropped objects, whose
/// mirrors the renderer frees at the end of a frame.
inline void settleFrame(m3g::Graphics& surface) {
    m3g::Graphics3D* g = m3g::Graphics3D::getInstance();
    g->bindTarget(&surface, true, 0);
    g->clear(nullptr);
    g->releaseTarget();
}

/// The frames and picks of steps 3 and 4 for a prepared World.
inline void drawAndPick(m3gcli::PreparedScene& scene, const m3g::LoadResult& loaded, m3g::Graphics& surface) {
    using namespace m3g;
    Graphics3D* g = Graphics3D::getInstance();
    const std::uint64_t messages = vk::validationMessageCount();
    static Ref<Image2D> rgbaTarget(new Image2D(Image2D::RGBA, kTargetSize, kTargetSize));
    struct Frame {
        int time, mode;
        bool rgba;
        const char* name;
    };
    const Frame frames[] = {{0, Graphics3D::SKINNING_CPU, false, "frame t=0 (CPU deformation, Graphics)"},
                            {977, Graphics3D::SKINNING_COMPUTE, true, "frame t=977 (compute deformation, RGBA Image2D)"},
                            {977, Graphics3D::SKINNING_CPU, false, "frame t=977 (back to CPU deformation, Graphics)"}};
    for (const Frame& f : frames) {
        allowDocumented("animate", false, [&] { scene.world->animate(f.time); });
        g->setSkinningMode(f.mode);
        if (f.rgba) g->bindTarget(rgbaTarget.get(), true, 0);
        else g->bindTarget(&surface, true, 0);
        allowDocumented(f.name, true, [&] { g->render(scene.world.get()); });
        g->releaseTarget();
        expectNoValidation(messages, f.name);
    }
    g->setSkinningMode(Graphics3D::SKINNING_CPU);

    // Immediate mode, with the World's camera and lights (current since its
    // render; a failed render leaves none, and then these throw ISE).
    int immediate = 0;
    for (const Ref<Object3D>& o : loaded.objects) {
        Node* node = dynamic_cast<Node*>(o.get());
        if (!node || dynamic_cast<World*>(node) || (!dynamic_cast<Mesh*>(node) && !dynamic_cast<Sprite3D*>(node) &&
                                                    !dynamic_cast<Group*>(node)))
            continue;
        if (++immediate > 8) break;
        g->bindTarget(&surface, true, 0);
        allowDocumented("render(Node)", false, [&] { g->render(node, nullptr); });
        g->releaseTarget();
        expectNoValidation(messages, std::string("render(") + node->getClassName() + ")");
    }

    if (Camera* camera = scene.world->getActiveCamera().get()) {
        for (const float at : {0.5f, 0.25f}) {
            RayIntersection hit;
            allowDocumented("pick", true, [&] { scene.world->pick(-1, at, 1.0f - at, camera, &hit); });
        }
    }
}

/// Steps 1-4 and the drop of step 5, one pass; false if the load failed.
inline bool renderPass(std::span<const std::uint8_t> bytes, m3g::Graphics& surface) {
    using namespace m3g;
    {
        LoaderOptions lenient;
        lenient.lenient = true;
        LoadResult loaded;
        try {
            loaded = Loader::loadDetailed(bytes, 0, lenient);
        } catch (const IOException&) {
            return false;
        }
        M3G_FUZZ_OTHER_EXCEPTIONS_FAIL("load")
        m3gcli::PreparedScene scene;
        try {
            scene = m3gcli::prepareScene(loaded, detail::kTargetSize, detail::kTargetSize);
        }
        M3G_FUZZ_OTHER_EXCEPTIONS_FAIL("prepareScene")
        drawAndPick(scene, loaded, surface);
        // Graphics3D keeps the last World's camera and lights (JSR-184 1.1,
        // Graphics3D.render(World)).
        Graphics3D* g = Graphics3D::getInstance();
        g->setCamera(nullptr, nullptr);
        g->resetLights();
    }
    const std::uint64_t messages = vk::validationMessageCount();
    settleFrame(surface);
    expectNoValidation(messages, "settle frame");
    return true;
}

}  // namespace detail

/// The vertex and fragment shader invocations of what `pass` renders, where
/// the device counts them the same way every time (a CPU device; a GPU's
/// vertex reuse is its own): {0, 0} elsewhere.
struct Shading {
    std::uint64_t vertices = 0, fragments = 0;
};
template <class Pass>
Shading countShading(bool counted, Pass pass) {
    struct Off {
        ~Off() { m3g::vk::setShaderInvocationCounting(false); }
    } off;
    m3g::vk::setShaderInvocationCounting(counted);
    const m3g::vk::RenderStats s0 = m3g::vk::renderStats();
    pass();
    const m3g::vk::RenderStats s1 = m3g::vk::renderStats();
    return {s1.vertexShaderInvocations - s0.vertexShaderInvocations,
            s1.fragmentShaderInvocations - s0.fragmentShaderInvocations};
}

/// Steps 1-5 of the header on bytes as they are (no checksum repair).
inline void checkRenderOnce(std::span<const std::uint8_t> bytes) {
    using namespace m3g;
    if (bytes.empty()) return;
    static Ref<Graphics> surface(new Graphics(detail::kTargetSize, detail::kTargetSize));
    // Each pass ends with a settle frame, so the balance is read with the
    // pass's objects gone and the GPU done with them.
    // currentDevice() makes the device if this is the first input.
    const bool counted = vk::currentDevice().type == "cpu" && vk::shaderInvocationCountingSupported();
    bool loaded = false;
    const Shading first = countShading(counted, [&] { loaded = detail::renderPass(bytes, *surface); });
    if (!loaded) return;
    const RendererBalance before = RendererBalance::now();
    const Shading second = countShading(counted, [&] { detail::renderPass(bytes, *surface); });
    const RendererBalance after = RendererBalance::now();
    expect(second.vertices == first.vertices && second.fragments == first.fragments,
           "a second pass over the input shaded " + std::to_string(second.vertices) + " vertices and " +
               std::to_string(second.fragments) + " fragments, the first " + std::to_string(first.vertices) +
               " and " + std::to_string(first.fragments));
    expect(after.liveBuffers == before.liveBuffers,
           "GPU buffers left by a second pass over the input: " + std::to_string(before.liveBuffers) + " -> " +
               std::to_string(after.liveBuffers));
    expect(after.liveTextures == before.liveTextures,
           "GPU textures left by a second pass over the input: " + std::to_string(before.liveTextures) +
               " -> " + std::to_string(after.liveTextures));
    expect(after.deviceMemoryBytes == before.deviceMemoryBytes,
           "device memory kept by a second pass over the input: " +
               std::to_string(before.deviceMemoryBytes) + " -> " + std::to_string(after.deviceMemoryBytes) +
               " bytes");
    expect(after.livePipelines == before.livePipelines,
           "pipelines made by a second pass over the input: " + std::to_string(before.livePipelines) + " -> " +
               std::to_string(after.livePipelines));
}

/// The render target: the checksum-repaired form only (the bytes as given
/// rarely get past the first section's Adler-32; fuzz_loader covers them).
inline void checkRender(std::span<const std::uint8_t> data) {
    const Bytes repaired = repairChecksums(data);
    checkRenderOnce(std::span<const std::uint8_t>(repaired));
}

}  // namespace m3gfuzz
