// javax.microedition.m3g.Graphics3D: the rendering context singleton
// (JSR-184 1.1, Graphics3D). State, properties and binding rules are
// implemented in scene/; clear() and render() are implemented by render-vk,
// which records them into a Vulkan command buffer submitted at releaseTarget.
//
// Threading (docs/threading.md): a Graphics3D is used by one thread at a
// time. getInstance() is the process-wide one of JSR-184; a program that
// renders on several threads gives each thread its own from create(). The
// Vulkan device behind them is shared and safe to use from all of them at
// once. The objects a Graphics3D renders (and the bound target) must not be
// used by another thread while it renders them, read-only use included.
#pragma once

#include <m3g/Export.h>

#include <map>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include <m3g/Camera.h>
#include <m3g/Graphics.h>
#include <m3g/Image2D.h>
#include <m3g/Light.h>
#include <m3g/Limits.h>
#include <m3g/Transform.h>

namespace m3g {

class Appearance;
class Background;
class IndexBuffer;
class Node;
class VertexBuffer;
class World;

namespace detail {
struct FrameState;
}  // namespace detail
namespace frame {
class FrameBackend;
struct Target;
}  // namespace frame

class M3G_API Graphics3D {
public:
    static constexpr int ANTIALIAS = 2;
    static constexpr int DITHER = 4;
    static constexpr int TRUE_COLOR = 8;
    static constexpr int OVERWRITE = 16;  // M3G 1.1

    /// A property value: Boolean, Integer or String as in the Java Hashtable.
    using Property = std::variant<bool, int, std::string>;

    /// The process-wide instance.
    static Graphics3D* getInstance();
    /// A new, independent Graphics3D (m3g-vk extension, not in JSR-184): its
    /// own target, camera, lights and renderer, for rendering on another
    /// thread. Destroy it before the program exits; destruction finishes the
    /// work of a bound target (as releaseTarget) and frees its GPU resources.
    static std::unique_ptr<Graphics3D> create();
    /// The implementation properties (the keys of JSR-184 1.1,
    /// Graphics3D.getProperties, plus Nokia's "m3gRelease").
    static std::map<std::string, Property> getProperties();

    /// bindTarget(target, true, 0).
    void bindTarget(Graphics* target) { bindTarget(target, true, 0); }
    void bindTarget(Image2D* target) { bindTarget(target, true, 0); }
    /// Binds a Graphics surface. ISE if a target is bound; NPE if null; IAE if
    /// `hints` has bits other than ANTIALIAS|DITHER|TRUE_COLOR|OVERWRITE or the
    /// surface is larger than maxViewportWidth x maxViewportHeight. Resets the
    /// viewport to the clip rectangle (translated coordinates).
    void bindTarget(Graphics* target, bool depthBuffer, int hints);
    /// Binds a mutable RGB or RGBA Image2D. As above, plus IAE if the image is
    /// immutable or of another format. Resets the viewport to the whole image.
    void bindTarget(Image2D* target, bool depthBuffer, int hints);
    /// Finishes the rendering recorded since bindTarget, writes the pixels
    /// into the bound Image2D or Graphics, and unbinds; no-op if unbound.
    void releaseTarget();

    /// Clears the viewport (within the Graphics clip) as JSR-184 1.1,
    /// Graphics3D.clear and Background specify: colour
    /// and/or depth, then the background image. Null: colour 0x00000000 and
    /// depth far. ISE if no target; IAE if the background image's format is
    /// not the target's (RGB for Graphics and RGB Image2D, RGBA for RGBA).
    void clear(Background* background);
    /// Renders a World with its active camera, its lights and its background
    /// (JSR-184 1.1, Graphics3D.render(World)), then makes that camera and
    /// those lights Graphics3D's current ones. Does not animate or align.
    /// NPE if null; ISE if no target, no active camera, the camera is not in
    /// this World, or the background image's format is not the target's;
    /// ArithmeticException if the active camera's transform to the World is
    /// singular (as setCamera's, e.g. a zero scale on the camera's path).
    void render(World* world);
    /// Renders a Mesh, Sprite3D or Group (IAE otherwise, NPE if null) with
    /// the current camera and lights; `transform` (null = identity) is the
    /// node-to-world transform, replacing the node's own. ISE if no target
    /// or no current camera.
    void render(Node* node, const Transform* transform);
    /// Immediate mode: one submesh with the current camera and lights, drawn
    /// if `scope` & camera scope != 0. NPE if vertices, triangles or
    /// appearance is null; ISE if no target or camera, or the vertex data is
    /// invalid (no positions, indices out of range).
    void render(VertexBuffer* vertices, IndexBuffer* triangles, Appearance* appearance, const Transform* transform) {
        render(vertices, triangles, appearance, transform, -1);
    }
    void render(VertexBuffer* vertices, IndexBuffer* triangles, Appearance* appearance, const Transform* transform,
                int scope);
    /// The bound Graphics or Image2D, or null.
    Ref<RefCounted> getTarget() const noexcept { return target_; }
    /// The hints given to bindTarget (0 when unbound).
    int getHints() const noexcept { return hints_; }
    bool isDepthBufferEnabled() const noexcept { return depthBuffer_; }

    /// IAE unless 0 < width <= maxViewportWidth and 0 < height <= maxViewportHeight.
    void setViewport(int x, int y, int width, int height);
    int getViewportX() const noexcept { return viewport_[0]; }
    int getViewportY() const noexcept { return viewport_[1]; }
    int getViewportWidth() const noexcept { return viewport_[2]; }
    int getViewportHeight() const noexcept { return viewport_[3]; }

    /// Both in [0, 1], else IAE (near > far is allowed).
    void setDepthRange(float near, float far);
    float getDepthRangeNear() const noexcept { return depthNear_; }
    float getDepthRangeFar() const noexcept { return depthFar_; }

    /// Camera for render(Node) and immediate mode; `transform` is
    /// camera-to-world (null = identity). ArithmeticException if singular.
    void setCamera(Camera* camera, const Transform* transform);
    /// The current camera; fills `transform` (if non-null) with its transform.
    Ref<Camera> getCamera(Transform* transform) const;

    /// Appends a light with its light-to-world transform (null = identity);
    /// returns its index. NPE if `light` is null.
    int addLight(Light* light, const Transform* transform);
    /// Replaces light `index` (null leaves an empty slot). IOOBE if out of range.
    void setLight(int index, Light* light, const Transform* transform);
    void resetLights() noexcept;
    int getLightCount() const noexcept { return static_cast<int>(lights_.size()); }
    /// IOOBE if out of range; fills `transform` if non-null.
    Ref<Light> getLight(int index, Transform* transform) const;

    // ---- m3g-vk extension (not part of JSR-184) ----
    /// Where the vertices of SkinnedMesh and MorphingMesh are deformed for
    /// drawing: on the CPU (skin/ kernels, the default) or by compute shaders
    /// on the Vulkan device (shaders/skin.comp, morph.comp), which write the
    /// vertex buffer the draw reads. Either way deformation runs only when a
    /// bone, weight or target changed, and picking (Group::pick) always uses
    /// the CPU-deformed vertices.
    static constexpr int SKINNING_CPU = 0;
    static constexpr int SKINNING_COMPUTE = 1;
    /// m3g-vk extension: selects SKINNING_CPU or SKINNING_COMPUTE for the
    /// following render calls (IAE otherwise). The initial mode comes from
    /// the environment variable M3G_SKINNING (`cpu` or `compute`), else CPU.
    void setSkinningMode(int mode);
    /// m3g-vk extension: the current skinning mode.
    int getSkinningMode() const noexcept { return skinningMode_; }

    // ---- Engine interface ----
    /// Frees the renderer and its GPU resources (after finishing the work of
    /// a bound target); the next clear or render creates a new one.
    void releaseRenderer() noexcept;
    /// Replaces the back end (after finishing the work of a bound target),
    /// e.g. with scene's recording NullBackend in tests; null: the next clear
    /// or render makes the installed back end (frame/FrameBackend.h).
    void useBackend(std::unique_ptr<frame::FrameBackend> backend);
    struct LightEntry {
        Ref<Light> light;
        Transform toWorld;
    };
    const std::vector<LightEntry>& lights() const noexcept { return lights_; }
    /// Camera-to-world and its inverse (the view matrix).
    const Transform& cameraToWorld() const noexcept { return cameraToWorld_; }
    const Transform& worldToCamera() const noexcept { return worldToCamera_; }
    /// The bound Image2D or Graphics (at most one is non-null).
    Image2D* targetImage() const noexcept { return targetImage_; }
    Graphics* targetGraphics() const noexcept { return targetGraphics_; }
    /// Target size in pixels (0 when unbound).
    int targetWidth() const noexcept { return targetWidth_; }
    int targetHeight() const noexcept { return targetHeight_; }

    Graphics3D(const Graphics3D&) = delete;
    Graphics3D& operator=(const Graphics3D&) = delete;
    ~Graphics3D();

private:
    Graphics3D();
    /// The frame state with its back end (made on the first clear or render
    /// by the installed factory: render-vk's renderer when it is linked).
    detail::FrameState& frame();
    /// The bound target as the back end sees it.
    frame::Target frameTarget() const;
    /// Hands a clear to the back end.
    void drawClear(const Background* background);
    /// Turns the queue collected last into the draw list (deforming meshes,
    /// throwing for vertex data a draw cannot use), then hands it over.
    void prepareQueue();
    void drawPrepared();
    void requireTarget(const char* where) const;
    void bindCommon(RefCounted* target, int width, int height, bool depthBuffer, int hints, const char* where);

    Ref<RefCounted> target_;
    Image2D* targetImage_ = nullptr;
    Graphics* targetGraphics_ = nullptr;
    int targetWidth_ = 0, targetHeight_ = 0;
    bool depthBuffer_ = false;
    int hints_ = 0;
    int viewport_[4] = {0, 0, 0, 0};
    float depthNear_ = 0.0f, depthFar_ = 1.0f;
    Ref<Camera> camera_;
    Transform cameraToWorld_, worldToCamera_;
    std::vector<LightEntry> lights_;
    int skinningMode_ = SKINNING_CPU;
    std::unique_ptr<detail::FrameState> frame_;
};

}  // namespace m3g
