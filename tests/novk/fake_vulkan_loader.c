/* A stand-in for libvulkan.so.1 that is not a Vulkan loader (it exports no
 * vkGetInstanceProcAddr): put first on LD_LIBRARY_PATH, it makes the system's
 * loader invisible to dlopen, as on a machine without libvulkan1. */
int m3g_fake_vulkan_loader_marker(void) { return 0; }
