// The soak run behind `m3g bench soak` and the device test VkTest.Soak*: load
// a file, animate and render it frame after frame, drop it and load it again
// every `reload` frames, with immediate-mode draws of objects made afresh
// every frame, and watch resident and GPU memory. A leak shows as growth
// from one reload cycle to the next; GPU mirrors are counted exactly.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace m3gcli {

struct SoakOptions {
    std::string file;
    int frames = 3000;
    int reload = 300;        ///< drop and load the file again every `reload` frames
    int width = 160, height = 120;
    int reportEvery = 0;     ///< a progress sample every N frames (0 = only at cycle ends)
    int warmupCycles = 2;    ///< cycles left out of the verdict
};

/// Memory figures after a frame (after releaseTarget).
struct SoakSample {
    int frame = 0;                   ///< frames done
    int cycle = 0;                   ///< reload cycle the frame belongs to (0 = first load)
    std::uint64_t residentBytes = 0; ///< /proc/self/statm resident set
    std::uint64_t deviceBytes = 0;   ///< m3g::vk::renderStats().deviceMemoryBytes
    std::uint64_t liveBuffers = 0, liveTextures = 0;
};

struct SoakResult {
    std::vector<SoakSample> cycleEnds;  ///< after the last frame of every complete cycle
    std::uint64_t draws = 0;            ///< draws recorded during the run
    std::uint64_t validationMessages = 0;  ///< during the run
    /// GPU: buffers, textures and device bytes equal at every cycle end
    /// after the warm-up. Resident: growth over those cycle ends within
    /// `residentToleranceBytes`.
    bool gpuFlat = false, residentFlat = false;
    std::int64_t residentGrowthBytes = 0;
    std::uint64_t residentToleranceBytes = 0;
    int judgedCycles = 0;  ///< cycle ends the verdict compared
    std::string verdict;   ///< one line
};

/// Resident set size of this process (0 where /proc is not available).
std::uint64_t residentBytes();

/// Runs the soak; `onSample` (may be empty) sees every progress sample and
/// every cycle end. Throws what the Loader or Graphics3D throw.
SoakResult runSoak(const SoakOptions& options, const std::function<void(const SoakSample&)>& onSample);

}  // namespace m3gcli
