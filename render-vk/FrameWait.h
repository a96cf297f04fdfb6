// Waiting for a frame's fence. By default the calling thread sleeps in
// vkWaitForFences at once; M3G_VK_FENCE_SPIN_US asks it to poll the fence
// for up to that many microseconds first. On a GPU the polling thread takes
// nothing from the device, and a frame that finishes within the budget is
// seen without the driver's wake-up (the H200 VM's submit-to-wake round
// trip was ~0.9 ms, docs/gpu.md); on a CPU device such as lavapipe it takes
// a core from the rasteriser threads (docs/rendering.md, "Measuring").
#pragma once

#include <cstdint>
#include <optional>

#include <volk.h>

namespace m3g::vk {

/// The largest M3G_VK_FENCE_SPIN_US accepted (0.1 s).
inline constexpr std::uint32_t kMaxFenceSpinMicros = 100000;

/// `text` as a spin budget: a decimal integer in [0, kMaxFenceSpinMicros];
/// nullopt for anything else (empty, signs, other characters, too large).
std::optional<std::uint32_t> parseFenceSpinMicros(const char* text) noexcept;

/// M3G_VK_FENCE_SPIN_US, read once per process: 0 when unset; a value
/// parseFenceSpinMicros rejects is reported once on stderr and taken as 0.
std::uint32_t fenceSpinMicros();

/// Waits until `fence` is signalled: polls it for up to `spinMicros`
/// microseconds, then sleeps in vkWaitForFences for up to `timeoutNanos`
/// more (a frame waits without a limit). Returns what the last Vulkan call
/// returned: VK_SUCCESS, VK_TIMEOUT, or an error such as
/// VK_ERROR_DEVICE_LOST.
VkResult waitForFence(VkDevice device, VkFence fence, std::uint32_t spinMicros, std::uint64_t timeoutNanos = UINT64_MAX);

}  // namespace m3g::vk
