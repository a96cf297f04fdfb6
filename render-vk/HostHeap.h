// The host heap as a CPU Vulkan device uses it. Mesa's lavapipe (llvmpipe's
// draw module) mallocs each draw's vertex storage on its queue thread and
// frees it after the draw: megabytes per frame for a 16k-vertex mesh. glibc's
// default policy gives such memory back to the kernel at every free
// (madvise of the thread heap's top, or munmap), so the next frame faults
// every page in again, zero-filled by the kernel: a third of midpath
// robot.m3g's frame at 320x240 (A/B: 8.7 -> 5.8 ms median).
#pragma once

namespace m3g::vk {

/// Keeps freed heap memory in the process (glibc: an mmap threshold of
/// 32 MiB and a trim threshold of 64 MiB, set with mallopt) so that a CPU
/// device's per-draw allocations reuse it. Process-wide; called once when
/// the shared Context chooses a CPU device. M3G_VK_KEEP_HEAP=0 skips it.
/// Returns whether the policy was set (false elsewhere than glibc).
bool keepHostHeap();

}  // namespace m3g::vk
