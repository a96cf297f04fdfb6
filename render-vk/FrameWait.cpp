#include "FrameWait.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace m3g::vk {

std::optional<std::uint32_t> parseFenceSpinMicros(const char* text) noexcept {
    if (!text || !*text) return std::nullopt;
    std::uint64_t value = 0;
    for (const char* c = text; *c; ++c) {
        if (*c < '0' || *c > '9') return std::nullopt;
        value = value * 10 + static_cast<std::uint64_t>(*c - '0');
        if (value > kMaxFenceSpinMicros) return std::nullopt;
    }
    return static_cast<std::uint32_t>(value);
}

std::uint32_t fenceSpinMicros() {
    static const std::uint32_t micros = [] {
        const char* v = std::getenv("M3G_VK_FENCE_SPIN_US");
        if (!v || !*v) return std::uint32_t{0};
        if (const auto parsed = parseFenceSpinMicros(v)) return *parsed;
        std::fprintf(stderr, "m3g-vk: M3G_VK_FENCE_SPIN_US=\"%s\" is not a number of microseconds in [0, %u]; not polling\n",
                     v, static_cast<unsigned>(kMaxFenceSpinMicros));
        return std::uint32_t{0};
    }();
    return micros;
}

VkResult waitForFence(VkDevice device, VkFence fence, std::uint32_t spinMicros, std::uint64_t timeoutNanos) {
    if (spinMicros > 0) {
        using Clock = std::chrono::steady_clock;
        const Clock::time_point until = Clock::now() + std::chrono::microseconds(spinMicros);
        do {
            const VkResult status = vkGetFenceStatus(device, fence);
            if (status != VK_NOT_READY) return status;
#if defined(__x86_64__) || defined(__i386__)
            _mm_pause();  // let a sibling hyper-thread run while polling
#endif
        } while (Clock::now() < until);
    }
    return vkWaitForFences(device, 1, &fence, VK_TRUE, timeoutNanos);
}

}  // namespace m3g::vk
