/* A Vulkan driver (ICD) that loads, reports one Vulkan 1.3 device with the
 * features m3g-vk needs, and then fails vkCreateDevice with
 * VK_ERROR_INITIALIZATION_FAILED: the case of a broken or unsupported GPU
 * driver. Only what the loader and m3g-vk's device selection call exists;
 * every other function is reported absent. Test support, never installed. */
#include <stdlib.h>
#include <string.h>

#include <vulkan/vk_icd.h>
#include <vulkan/vulkan.h>

#define EXPORT __attribute__((visibility("default")))

/* Dispatchable handles start with the loader's dispatch slot (vk_icd.h). */
struct FakeInstance {
    VK_LOADER_DATA loader;
};
static struct {
    VK_LOADER_DATA loader;
} physical = {{ICD_LOADER_MAGIC}};

static VKAPI_ATTR VkResult VKAPI_CALL enumerateInstanceExtensionProperties(const char* layer, uint32_t* count,
                                                                           VkExtensionProperties* props) {
    (void)layer;
    (void)props;
    *count = 0;
    return VK_SUCCESS;
}

static VKAPI_ATTR VkResult VKAPI_CALL enumerateInstanceVersion(uint32_t* version) {
    *version = VK_API_VERSION_1_3;
    return VK_SUCCESS;
}

static VKAPI_ATTR VkResult VKAPI_CALL createInstance(const VkInstanceCreateInfo* info, const VkAllocationCallbacks* a,
                                                     VkInstance* out) {
    (void)info;
    (void)a;
    struct FakeInstance* instance = calloc(1, sizeof *instance);
    if (!instance) return VK_ERROR_OUT_OF_HOST_MEMORY;
    set_loader_magic_value(instance);
    *out = (VkInstance)instance;
    return VK_SUCCESS;
}

static VKAPI_ATTR void VKAPI_CALL destroyInstance(VkInstance instance, const VkAllocationCallbacks* a) {
    (void)a;
    free(instance);
}

static VKAPI_ATTR VkResult VKAPI_CALL enumeratePhysicalDevices(VkInstance instance, uint32_t* count,
                                                               VkPhysicalDevice* devices) {
    (void)instance;
    if (!devices) {
        *count = 1;
        return VK_SUCCESS;
    }
    if (*count < 1) return VK_INCOMPLETE;
    *count = 1;
    devices[0] = (VkPhysicalDevice)&physical;
    return VK_SUCCESS;
}

static VKAPI_ATTR void VKAPI_CALL getPhysicalDeviceProperties(VkPhysicalDevice pd, VkPhysicalDeviceProperties* p) {
    (void)pd;
    memset(p, 0, sizeof *p);
    p->apiVersion = VK_API_VERSION_1_3;
    p->deviceType = VK_PHYSICAL_DEVICE_TYPE_CPU;
    strcpy(p->deviceName, "m3g-vk failing test driver");
    p->limits.minUniformBufferOffsetAlignment = 256;
    p->limits.framebufferColorSampleCounts = VK_SAMPLE_COUNT_1_BIT;
    p->limits.framebufferDepthSampleCounts = VK_SAMPLE_COUNT_1_BIT;
    p->limits.maxImageDimension2D = 4096;
}

static VKAPI_ATTR void VKAPI_CALL getPhysicalDeviceProperties2(VkPhysicalDevice pd, VkPhysicalDeviceProperties2* p) {
    getPhysicalDeviceProperties(pd, &p->properties);
}

static VKAPI_ATTR void VKAPI_CALL getPhysicalDeviceFeatures(VkPhysicalDevice pd, VkPhysicalDeviceFeatures* f) {
    (void)pd;
    memset(f, 0, sizeof *f);
}

static VKAPI_ATTR void VKAPI_CALL getPhysicalDeviceFeatures2(VkPhysicalDevice pd, VkPhysicalDeviceFeatures2* f) {
    getPhysicalDeviceFeatures(pd, &f->features);
    for (VkBaseOutStructure* s = (VkBaseOutStructure*)f->pNext; s; s = s->pNext)
        if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES) {
            VkPhysicalDeviceVulkan13Features* f13 = (VkPhysicalDeviceVulkan13Features*)s;
            f13->dynamicRendering = VK_TRUE;
            f13->synchronization2 = VK_TRUE;
        }
}

static VKAPI_ATTR void VKAPI_CALL getQueueFamilyProperties(VkPhysicalDevice pd, uint32_t* count,
                                                           VkQueueFamilyProperties* props) {
    (void)pd;
    if (!props) {
        *count = 1;
        return;
    }
    if (*count < 1) return;
    *count = 1;
    memset(props, 0, sizeof *props);
    props->queueFlags = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT | VK_QUEUE_TRANSFER_BIT;
    props->queueCount = 1;
}

static VKAPI_ATTR void VKAPI_CALL getFormatProperties(VkPhysicalDevice pd, VkFormat format, VkFormatProperties* p) {
    (void)pd;
    memset(p, 0, sizeof *p);
    if (format == VK_FORMAT_D32_SFLOAT) p->optimalTilingFeatures = VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT;
}

static VKAPI_ATTR void VKAPI_CALL getMemoryProperties(VkPhysicalDevice pd, VkPhysicalDeviceMemoryProperties* p) {
    (void)pd;
    memset(p, 0, sizeof *p);
    p->memoryTypeCount = 1;
    p->memoryTypes[0].propertyFlags = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT | VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                      VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    p->memoryHeapCount = 1;
    p->memoryHeaps[0].size = 256u << 20;
    p->memoryHeaps[0].flags = VK_MEMORY_HEAP_DEVICE_LOCAL_BIT;
}

static VKAPI_ATTR VkResult VKAPI_CALL enumerateDeviceExtensionProperties(VkPhysicalDevice pd, const char* layer,
                                                                         uint32_t* count, VkExtensionProperties* props) {
    (void)pd;
    (void)layer;
    (void)props;
    *count = 0;
    return VK_SUCCESS;
}

/* The point of this driver. */
static VKAPI_ATTR VkResult VKAPI_CALL createDevice(VkPhysicalDevice pd, const VkDeviceCreateInfo* info,
                                                   const VkAllocationCallbacks* a, VkDevice* out) {
    (void)pd;
    (void)info;
    (void)a;
    (void)out;
    return VK_ERROR_INITIALIZATION_FAILED;
}

static VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL getDeviceProcAddr(VkDevice device, const char* name) {
    (void)device;
    (void)name;
    return NULL;
}

static const struct {
    const char* name;
    PFN_vkVoidFunction fn;
} kFunctions[] = {
    {"vkEnumerateInstanceExtensionProperties", (PFN_vkVoidFunction)enumerateInstanceExtensionProperties},
    {"vkEnumerateInstanceVersion", (PFN_vkVoidFunction)enumerateInstanceVersion},
    {"vkCreateInstance", (PFN_vkVoidFunction)createInstance},
    {"vkDestroyInstance", (PFN_vkVoidFunction)destroyInstance},
    {"vkEnumeratePhysicalDevices", (PFN_vkVoidFunction)enumeratePhysicalDevices},
    {"vkGetPhysicalDeviceProperties", (PFN_vkVoidFunction)getPhysicalDeviceProperties},
    {"vkGetPhysicalDeviceProperties2", (PFN_vkVoidFunction)getPhysicalDeviceProperties2},
    {"vkGetPhysicalDeviceFeatures", (PFN_vkVoidFunction)getPhysicalDeviceFeatures},
    {"vkGetPhysicalDeviceFeatures2", (PFN_vkVoidFunction)getPhysicalDeviceFeatures2},
    {"vkGetPhysicalDeviceQueueFamilyProperties", (PFN_vkVoidFunction)getQueueFamilyProperties},
    {"vkGetPhysicalDeviceFormatProperties", (PFN_vkVoidFunction)getFormatProperties},
    {"vkGetPhysicalDeviceMemoryProperties", (PFN_vkVoidFunction)getMemoryProperties},
    {"vkEnumerateDeviceExtensionProperties", (PFN_vkVoidFunction)enumerateDeviceExtensionProperties},
    {"vkCreateDevice", (PFN_vkVoidFunction)createDevice},
    {"vkGetDeviceProcAddr", (PFN_vkVoidFunction)getDeviceProcAddr},
};

EXPORT VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL vk_icdGetInstanceProcAddr(VkInstance instance, const char* name);
EXPORT VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL vk_icdGetInstanceProcAddr(VkInstance instance, const char* name) {
    (void)instance;
    if (strcmp(name, "vk_icdGetInstanceProcAddr") == 0) return (PFN_vkVoidFunction)vk_icdGetInstanceProcAddr;
    for (size_t i = 0; i < sizeof kFunctions / sizeof kFunctions[0]; ++i)
        if (strcmp(name, kFunctions[i].name) == 0) return kFunctions[i].fn;
    return NULL;
}

EXPORT VKAPI_ATTR VkResult VKAPI_CALL vk_icdNegotiateLoaderICDInterfaceVersion(uint32_t* version);
EXPORT VKAPI_ATTR VkResult VKAPI_CALL vk_icdNegotiateLoaderICDInterfaceVersion(uint32_t* version) {
    if (*version > 5) *version = 5;
    return VK_SUCCESS;
}
