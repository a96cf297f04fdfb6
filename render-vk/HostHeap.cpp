#include "HostHeap.h"

#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace m3g::vk {

bool keepHostHeap() {
    if (const char* v = std::getenv("M3G_VK_KEEP_HEAP"); v && std::strcmp(v, "0") == 0) return false;
#if defined(__GLIBC__)
    // Setting either threshold ends glibc's dynamic raising of the mmap
    // threshold, so both are set: blocks below 32 MiB (glibc's maximum)
    // come from the heap, and a heap keeps up to 64 MiB free at its top.
    const bool mmap = mallopt(M_MMAP_THRESHOLD, 32 << 20) == 1;
    const bool trim = mallopt(M_TRIM_THRESHOLD, 64 << 20) == 1;
    return mmap && trim;
#else
    return false;
#endif
}

}  // namespace m3g::vk
