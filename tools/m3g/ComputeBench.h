// The compute-shader path of `m3g bench skin|morph`: runs shaders/skin.comp
// and morph.comp (render-vk's ComputeDeformer, the code the renderer uses
// for Graphics3D::SKINNING_COMPUTE) on the benchmark workloads' plain
// arrays. One frame = what the renderer pays per deformed mesh: the palette
// on the CPU (skinning), the per-frame data copied to the device, the
// dispatch recorded, submitted and waited for; the dispatch alone is also
// timed on the device (timestamps). Vulkan stays behind this interface.
#pragma once

#include <memory>
#include <string>

#include "SkinWorkload.h"

namespace m3gcli {

class ComputeBench {
public:
    /// Null when no Vulkan device can be used; `why` then says why.
    static std::unique_ptr<ComputeBench> create(std::string& why);
    ~ComputeBench();

    /// The device the shaders run on (e.g. "llvmpipe (LLVM 15.0.6, 256 bits)").
    std::string deviceName() const;

    /// Starts a new workload: its static inputs are uploaded by the next frame.
    void reset();
    /// One frame of skinning (positions + normals) or morphing (positions +
    /// renormalised normals) of `w` on the device.
    void skinFrame(m3gbench::SkinWorkload& w);
    void morphFrame(m3gbench::MorphWorkload& w);
    /// Device time of the last frame's dispatches (GPU timestamps around
    /// them), in seconds; negative when the device has no timestamps.
    double lastDispatchSeconds() const;
    /// Largest |gpu - cpu| / max(1, |cpu|) between the last frame's output and
    /// the workload's outPositions / outNormals (run a CPU frame first).
    double skinDifference(const m3gbench::SkinWorkload& w) const;
    double morphDifference(const m3gbench::MorphWorkload& w) const;

    ComputeBench(const ComputeBench&) = delete;
    ComputeBench& operator=(const ComputeBench&) = delete;

private:
    struct State;
    explicit ComputeBench(std::unique_ptr<State> state);
    std::unique_ptr<State> s_;
};

}  // namespace m3gcli
