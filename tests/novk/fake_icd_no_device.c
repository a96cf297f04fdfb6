/* A Vulkan driver (ICD) with one physical device that looks fit for m3g-vk
 * (Vulkan 1.3, a graphics+compute queue, dynamicRendering and
 * synchronization2, every format usable) but whose vkCreateDevice fails with
 * VK_ERROR_INITIALIZATION_FAILED: the "driver that fails device creation"
 * case of the no-Vulkan tests, as a GPU whose kernel driver is gone would
 * behave.
 *
 * The loader-driver interface (Khronos LoaderDriverInterface.md, vk_icd.h):
 * the loader negotiates the interface version through
 * vk_icdNegotiateLoaderICDInterfaceVersion, then finds every other entry
 * point through vk_icdGetInstanceProcAddr (and physical-device extensions
 * through vk_icdGetPhysicalDeviceProcAddr). Dispatchable handles (VkInstance,
 * VkPhysicalDevice) point at memory whose first pointer-sized word belongs to
 * the loader and holds ICD_LOADER_MAGIC when created.
 *
 * Every instance and physical-device function of Vulkan 1.0 to 1.3 that a
 * loader, a validation layer or m3g-vk's Context calls before vkCreateDevice
 * is implemented: loader 1.3.239's terminators call some of them (e.g.
 * vkGetPhysicalDeviceFeatures2) without checking for NULL once the driver
 * reports 1.1 or later, so a missing one is a crash, not an error. Names the
 * driver does not implement (surface, display, debug extensions) give NULL,
 * which is how a driver says "not supported" and what the loader expects. */
#include <stdlib.h>
#include <string.h>

#include <vulkan/vk_icd.h>
#include <vulkan/vulkan.h>

#define EXPORT __attribute__((visibility("default")))

/* Interface 5: the loader passes the application's API version and checks
 * our device's; 6 and 7 add nothing a Linux driver needs. */
#define FAKE_INTERFACE_VERSION 5u
#define FAKE_API_VERSION VK_MAKE_API_VERSION(0, 1, 3, 239)

struct FakePhysicalDevice {
    VK_LOADER_DATA loader; /* first word: the loader's */
};

struct FakeInstance {
    VK_LOADER_DATA loader; /* first word: the loader's */
    struct FakePhysicalDevice physical;
};

EXPORT VKAPI_ATTR VkResult VKAPI_CALL vk_icdNegotiateLoaderICDInterfaceVersion(uint32_t* pVersion);
EXPORT VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL vk_icdGetInstanceProcAddr(VkInstance instance, const char* pName);
EXPORT VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL vk_icdGetPhysicalDeviceProcAddr(VkInstance instance, const char* pName);

/* ---- instance ---- */

static VKAPI_ATTR VkResult VKAPI_CALL fakeCreateInstance(const VkInstanceCreateInfo* info,
                                                         const VkAllocationCallbacks* allocator, VkInstance* out) {
    (void)allocator;
    /* The loader passes only the extensions we listed (none). */
    if (info && info->enabledExtensionCount > 0) return VK_ERROR_EXTENSION_NOT_PRESENT;
    struct FakeInstance* inst = calloc(1, sizeof *inst);
    if (!inst) return VK_ERROR_OUT_OF_HOST_MEMORY;
    set_loader_magic_value(inst);
    set_loader_magic_value(&inst->physical);
    *out = (VkInstance)inst;
    return VK_SUCCESS;
}

static VKAPI_ATTR void VKAPI_CALL fakeDestroyInstance(VkInstance instance, const VkAllocationCallbacks* allocator) {
    (void)allocator;
    free(instance);
}

static VKAPI_ATTR VkResult VKAPI_CALL fakeEnumerateInstanceExtensionProperties(const char* layer, uint32_t* count,
                                                                               VkExtensionProperties* props) {
    (void)props;
    if (layer) return VK_ERROR_LAYER_NOT_PRESENT;
    *count = 0;
    return VK_SUCCESS;
}

static VKAPI_ATTR VkResult VKAPI_CALL fakeEnumerateInstanceVersion(uint32_t* version) {
    *version = FAKE_API_VERSION;
    return VK_SUCCESS;
}

static VKAPI_ATTR VkResult VKAPI_CALL fakeEnumeratePhysicalDevices(VkInstance instance, uint32_t* count,
                                                                   VkPhysicalDevice* devices) {
    struct FakeInstance* inst = (struct FakeInstance*)instance;
    if (!devices) {
        *count = 1;
        return VK_SUCCESS;
    }
    if (*count < 1) return VK_INCOMPLETE;
    devices[0] = (VkPhysicalDevice)&inst->physical;
    *count = 1;
    return VK_SUCCESS;
}

static VKAPI_ATTR VkResult VKAPI_CALL fakeEnumeratePhysicalDeviceGroups(VkInstance instance, uint32_t* count,
                                                                        VkPhysicalDeviceGroupProperties* groups) {
    struct FakeInstance* inst = (struct FakeInstance*)instance;
    if (!groups) {
        *count = 1;
        return VK_SUCCESS;
    }
    if (*count < 1) return VK_INCOMPLETE;
    groups[0].physicalDeviceCount = 1;
    memset(groups[0].physicalDevices, 0, sizeof groups[0].physicalDevices);
    groups[0].physicalDevices[0] = (VkPhysicalDevice)&inst->physical;
    groups[0].subsetAllocation = VK_FALSE;
    *count = 1;
    return VK_SUCCESS;
}

/* ---- physical device: what a fit 1.3 device reports ---- */

static VKAPI_ATTR void VKAPI_CALL fakeGetPhysicalDeviceProperties(VkPhysicalDevice pd, VkPhysicalDeviceProperties* p) {
    (void)pd;
    memset(p, 0, sizeof *p);
    p->apiVersion = FAKE_API_VERSION;
    p->driverVersion = 1;
    p->vendorID = 0xFFFF; /* no real vendor: no vendor-specific path in a layer */
    p->deviceID = 0xdead;
    p->deviceType = VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU;
    strcpy(p->deviceName, "m3g-vk fake GPU that fails vkCreateDevice");
    VkPhysicalDeviceLimits* l = &p->limits;
    l->maxImageDimension1D = l->maxImageDimension2D = 16384;
    l->maxImageDimension3D = 2048;
    l->maxImageDimensionCube = 16384;
    l->maxImageArrayLayers = 2048;
    l->maxTexelBufferElements = 1u << 27;
    l->maxUniformBufferRange = 65536;
    l->maxStorageBufferRange = 1u << 30;
    l->maxPushConstantsSize = 256;
    l->maxMemoryAllocationCount = 4096;
    l->maxSamplerAllocationCount = 4000;
    l->bufferImageGranularity = 1;
    l->maxBoundDescriptorSets = 8;
    l->maxPerStageDescriptorSamplers = l->maxPerStageDescriptorUniformBuffers = 64;
    l->maxPerStageDescriptorStorageBuffers = l->maxPerStageDescriptorSampledImages = 64;
    l->maxPerStageDescriptorStorageImages = l->maxPerStageDescriptorInputAttachments = 64;
    l->maxPerStageResources = 512;
    l->maxDescriptorSetSamplers = l->maxDescriptorSetUniformBuffers = 256;
    l->maxDescriptorSetUniformBuffersDynamic = l->maxDescriptorSetStorageBuffersDynamic = 16;
    l->maxDescriptorSetStorageBuffers = l->maxDescriptorSetSampledImages = 256;
    l->maxDescriptorSetStorageImages = l->maxDescriptorSetInputAttachments = 256;
    l->maxVertexInputAttributes = l->maxVertexInputBindings = 32;
    l->maxVertexInputAttributeOffset = 2047;
    l->maxVertexInputBindingStride = 2048;
    l->maxVertexOutputComponents = l->maxFragmentInputComponents = 128;
    l->maxFragmentOutputAttachments = 8;
    l->maxFragmentCombinedOutputResources = 16;
    l->maxComputeSharedMemorySize = 32768;
    for (int i = 0; i < 3; ++i) l->maxComputeWorkGroupCount[i] = 65535;
    l->maxComputeWorkGroupInvocations = 1024;
    l->maxComputeWorkGroupSize[0] = l->maxComputeWorkGroupSize[1] = 1024;
    l->maxComputeWorkGroupSize[2] = 64;
    l->subPixelPrecisionBits = l->subTexelPrecisionBits = l->mipmapPrecisionBits = 8;
    l->maxDrawIndexedIndexValue = UINT32_MAX;
    l->maxDrawIndirectCount = 1;
    l->maxSamplerLodBias = 16.0f;
    l->maxSamplerAnisotropy = 16.0f;
    l->maxViewports = 1;
    l->maxViewportDimensions[0] = l->maxViewportDimensions[1] = 16384;
    l->viewportBoundsRange[0] = -32768.0f;
    l->viewportBoundsRange[1] = 32767.0f;
    l->minMemoryMapAlignment = 64;
    l->minTexelBufferOffsetAlignment = l->minUniformBufferOffsetAlignment = l->minStorageBufferOffsetAlignment = 16;
    l->maxTexelOffset = l->maxTexelGatherOffset = 7;
    l->minTexelOffset = l->minTexelGatherOffset = -8;
    l->maxFramebufferWidth = l->maxFramebufferHeight = 16384;
    l->maxFramebufferLayers = 1024;
    l->framebufferColorSampleCounts = l->framebufferDepthSampleCounts = VK_SAMPLE_COUNT_1_BIT | VK_SAMPLE_COUNT_4_BIT;
    l->framebufferStencilSampleCounts = l->framebufferNoAttachmentsSampleCounts = l->framebufferColorSampleCounts;
    l->maxColorAttachments = 8;
    l->sampledImageColorSampleCounts = l->sampledImageDepthSampleCounts = l->framebufferColorSampleCounts;
    l->sampledImageIntegerSampleCounts = l->sampledImageStencilSampleCounts = l->framebufferColorSampleCounts;
    l->storageImageSampleCounts = VK_SAMPLE_COUNT_1_BIT;
    l->maxSampleMaskWords = 1;
    l->timestampComputeAndGraphics = VK_TRUE;
    l->timestampPeriod = 1.0f;
    l->maxClipDistances = l->maxCullDistances = l->maxCombinedClipAndCullDistances = 8;
    l->discreteQueuePriorities = 2;
    l->pointSizeRange[0] = l->lineWidthRange[0] = 1.0f;
    l->pointSizeRange[1] = l->lineWidthRange[1] = 1.0f;
    l->standardSampleLocations = VK_TRUE;
    l->optimalBufferCopyOffsetAlignment = l->optimalBufferCopyRowPitchAlignment = 1;
    l->nonCoherentAtomSize = 64;
}

static VKAPI_ATTR void VKAPI_CALL fakeGetPhysicalDeviceProperties2(VkPhysicalDevice pd, VkPhysicalDeviceProperties2* p) {
    fakeGetPhysicalDeviceProperties(pd, &p->properties);
    /* The extension structures the caller chained stay as it initialised
     * them (zero): no optional property is claimed. */
}

static VKAPI_ATTR void VKAPI_CALL fakeGetPhysicalDeviceFeatures(VkPhysicalDevice pd, VkPhysicalDeviceFeatures* f) {
    (void)pd;
    memset(f, 0, sizeof *f);
    f->fillModeNonSolid = VK_TRUE;
}

static VKAPI_ATTR void VKAPI_CALL fakeGetPhysicalDeviceFeatures2(VkPhysicalDevice pd, VkPhysicalDeviceFeatures2* f) {
    fakeGetPhysicalDeviceFeatures(pd, &f->features);
    /* The 1.3 features m3g-vk requires; other chained structures stay zero. */
    for (VkBaseOutStructure* s = (VkBaseOutStructure*)f->pNext; s; s = s->pNext)
        if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES) {
            VkPhysicalDeviceVulkan13Features* f13 = (VkPhysicalDeviceVulkan13Features*)s;
            f13->dynamicRendering = VK_TRUE;
            f13->synchronization2 = VK_TRUE;
        }
}

static VKAPI_ATTR void VKAPI_CALL fakeGetPhysicalDeviceQueueFamilyProperties(VkPhysicalDevice pd, uint32_t* count,
                                                                            VkQueueFamilyProperties* props) {
    (void)pd;
    if (!props) {
        *count = 1;
        return;
    }
    if (*count < 1) return;
    memset(props, 0, sizeof *props);
    props[0].queueFlags = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT | VK_QUEUE_TRANSFER_BIT;
    props[0].queueCount = 1;
    props[0].timestampValidBits = 64;
    props[0].minImageTransferGranularity = (VkExtent3D){1, 1, 1};
    *count = 1;
}

static VKAPI_ATTR void VKAPI_CALL fakeGetPhysicalDeviceQueueFamilyProperties2(VkPhysicalDevice pd, uint32_t* count,
                                                                             VkQueueFamilyProperties2* props) {
    if (!props) {
        fakeGetPhysicalDeviceQueueFamilyProperties(pd, count, NULL);
        return;
    }
    if (*count < 1) return;
    fakeGetPhysicalDeviceQueueFamilyProperties(pd, count, &props[0].queueFamilyProperties);
}

static VKAPI_ATTR void VKAPI_CALL fakeGetPhysicalDeviceMemoryProperties(VkPhysicalDevice pd,
                                                                       VkPhysicalDeviceMemoryProperties* m) {
    (void)pd;
    memset(m, 0, sizeof *m);
    m->memoryTypeCount = 1;
    m->memoryTypes[0].propertyFlags =
        VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT | VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    m->memoryTypes[0].heapIndex = 0;
    m->memoryHeapCount = 1;
    m->memoryHeaps[0].size = 1ull << 30;
    m->memoryHeaps[0].flags = VK_MEMORY_HEAP_DEVICE_LOCAL_BIT;
}

static VKAPI_ATTR void VKAPI_CALL fakeGetPhysicalDeviceMemoryProperties2(VkPhysicalDevice pd,
                                                                        VkPhysicalDeviceMemoryProperties2* m) {
    fakeGetPhysicalDeviceMemoryProperties(pd, &m->memoryProperties);
}

/* Every format can do everything: m3g-vk's colour, depth and texture
 * formats all pass, so nothing but vkCreateDevice fails. */
static VKAPI_ATTR void VKAPI_CALL fakeGetPhysicalDeviceFormatProperties(VkPhysicalDevice pd, VkFormat format,
                                                                       VkFormatProperties* p) {
    (void)pd;
    memset(p, 0, sizeof *p);
    if (format == VK_FORMAT_UNDEFINED) return;
    const VkFormatFeatureFlags all =
        VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT |
        VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT |
        VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT |
        VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
    const int depth = format == VK_FORMAT_D16_UNORM || format == VK_FORMAT_D32_SFLOAT ||
                      format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_D32_SFLOAT_S8_UINT;
    p->optimalTilingFeatures =
        depth ? (VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                 VK_FORMAT_FEATURE_TRANSFER_SRC_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT)
              : all;
    p->linearTilingFeatures = depth ? 0 : all;
    p->bufferFeatures = depth ? 0
                              : (VK_FORMAT_FEATURE_VERTEX_BUFFER_BIT | VK_FORMAT_FEATURE_UNIFORM_TEXEL_BUFFER_BIT |
                                 VK_FORMAT_FEATURE_STORAGE_TEXEL_BUFFER_BIT);
}

static VKAPI_ATTR void VKAPI_CALL fakeGetPhysicalDeviceFormatProperties2(VkPhysicalDevice pd, VkFormat format,
                                                                        VkFormatProperties2* p) {
    fakeGetPhysicalDeviceFormatProperties(pd, format, &p->formatProperties);
}

static VKAPI_ATTR VkResult VKAPI_CALL fakeGetPhysicalDeviceImageFormatProperties(
    VkPhysicalDevice pd, VkFormat format, VkImageType type, VkImageTiling tiling, VkImageUsageFlags usage,
    VkImageCreateFlags flags, VkImageFormatProperties* p) {
    (void)pd, (void)format, (void)tiling, (void)usage, (void)flags;
    memset(p, 0, sizeof *p);
    p->maxExtent = (VkExtent3D){16384, type == VK_IMAGE_TYPE_1D ? 1u : 16384u, type == VK_IMAGE_TYPE_3D ? 2048u : 1u};
    p->maxMipLevels = 15;
    p->maxArrayLayers = 2048;
    p->sampleCounts = VK_SAMPLE_COUNT_1_BIT | VK_SAMPLE_COUNT_4_BIT;
    p->maxResourceSize = 1ull << 31;
    return VK_SUCCESS;
}

static VKAPI_ATTR VkResult VKAPI_CALL fakeGetPhysicalDeviceImageFormatProperties2(
    VkPhysicalDevice pd, const VkPhysicalDeviceImageFormatInfo2* info, VkImageFormatProperties2* p) {
    return fakeGetPhysicalDeviceImageFormatProperties(pd, info->format, info->type, info->tiling, info->usage,
                                                      info->flags, &p->imageFormatProperties);
}

static VKAPI_ATTR void VKAPI_CALL fakeGetPhysicalDeviceSparseImageFormatProperties(
    VkPhysicalDevice pd, VkFormat format, VkImageType type, VkSampleCountFlagBits samples, VkImageUsageFlags usage,
    VkImageTiling tiling, uint32_t* count, VkSparseImageFormatProperties* props) {
    (void)pd, (void)format, (void)type, (void)samples, (void)usage, (void)tiling, (void)props;
    *count = 0; /* no sparse support */
}

static VKAPI_ATTR void VKAPI_CALL fakeGetPhysicalDeviceSparseImageFormatProperties2(
    VkPhysicalDevice pd, const VkPhysicalDeviceSparseImageFormatInfo2* info, uint32_t* count,
    VkSparseImageFormatProperties2* props) {
    (void)pd, (void)info, (void)props;
    *count = 0;
}

static VKAPI_ATTR void VKAPI_CALL fakeGetPhysicalDeviceExternalBufferProperties(
    VkPhysicalDevice pd, const VkPhysicalDeviceExternalBufferInfo* info, VkExternalBufferProperties* p) {
    (void)pd, (void)info;
    memset(&p->externalMemoryProperties, 0, sizeof p->externalMemoryProperties); /* no external memory */
}

static VKAPI_ATTR void VKAPI_CALL fakeGetPhysicalDeviceExternalFenceProperties(
    VkPhysicalDevice pd, const VkPhysicalDeviceExternalFenceInfo* info, VkExternalFenceProperties* p) {
    (void)pd, (void)info;
    p->exportFromImportedHandleTypes = p->compatibleHandleTypes = 0;
    p->externalFenceFeatures = 0;
}

static VKAPI_ATTR void VKAPI_CALL fakeGetPhysicalDeviceExternalSemaphoreProperties(
    VkPhysicalDevice pd, const VkPhysicalDeviceExternalSemaphoreInfo* info, VkExternalSemaphoreProperties* p) {
    (void)pd, (void)info;
    p->exportFromImportedHandleTypes = p->compatibleHandleTypes = 0;
    p->externalSemaphoreFeatures = 0;
}

static VKAPI_ATTR VkResult VKAPI_CALL fakeGetPhysicalDeviceToolProperties(VkPhysicalDevice pd, uint32_t* count,
                                                                          VkPhysicalDeviceToolProperties* props) {
    (void)pd, (void)props;
    *count = 0;
    return VK_SUCCESS;
}

static VKAPI_ATTR VkResult VKAPI_CALL fakeEnumerateDeviceExtensionProperties(VkPhysicalDevice pd, const char* layer,
                                                                             uint32_t* count,
                                                                             VkExtensionProperties* props) {
    (void)pd, (void)props;
    if (layer) return VK_ERROR_LAYER_NOT_PRESENT;
    *count = 0; /* everything m3g-vk needs is core 1.3 */
    return VK_SUCCESS;
}

static VKAPI_ATTR VkResult VKAPI_CALL fakeEnumerateDeviceLayerProperties(VkPhysicalDevice pd, uint32_t* count,
                                                                         VkLayerProperties* props) {
    (void)pd, (void)props;
    *count = 0;
    return VK_SUCCESS;
}

/* ---- the point of this driver ---- */

static VKAPI_ATTR VkResult VKAPI_CALL fakeCreateDevice(VkPhysicalDevice pd, const VkDeviceCreateInfo* info,
                                                       const VkAllocationCallbacks* allocator, VkDevice* device) {
    (void)pd, (void)info, (void)allocator;
    *device = VK_NULL_HANDLE;
    return VK_ERROR_INITIALIZATION_FAILED;
}

/* No device is ever made, so there is no device-level function to give. */
static VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL fakeGetDeviceProcAddr(VkDevice device, const char* name) {
    (void)device, (void)name;
    return NULL;
}

/* ---- lookup ---- */

struct Entry {
    const char* name;
    PFN_vkVoidFunction fn;
};

#define ENTRY(name, fn) {name, (PFN_vkVoidFunction)fn}

/* Callable without an instance (vkGetInstanceProcAddr(NULL, ...)). */
static const struct Entry kGlobal[] = {
    ENTRY("vkCreateInstance", fakeCreateInstance),
    ENTRY("vkEnumerateInstanceExtensionProperties", fakeEnumerateInstanceExtensionProperties),
    ENTRY("vkEnumerateInstanceVersion", fakeEnumerateInstanceVersion),
    ENTRY("vk_icdNegotiateLoaderICDInterfaceVersion", vk_icdNegotiateLoaderICDInterfaceVersion),
    ENTRY("vk_icdGetPhysicalDeviceProcAddr", vk_icdGetPhysicalDeviceProcAddr),
};

static const struct Entry kPhysicalDevice[] = {
    ENTRY("vkGetPhysicalDeviceProperties", fakeGetPhysicalDeviceProperties),
    ENTRY("vkGetPhysicalDeviceProperties2", fakeGetPhysicalDeviceProperties2),
    ENTRY("vkGetPhysicalDeviceProperties2KHR", fakeGetPhysicalDeviceProperties2),
    ENTRY("vkGetPhysicalDeviceFeatures", fakeGetPhysicalDeviceFeatures),
    ENTRY("vkGetPhysicalDeviceFeatures2", fakeGetPhysicalDeviceFeatures2),
    ENTRY("vkGetPhysicalDeviceFeatures2KHR", fakeGetPhysicalDeviceFeatures2),
    ENTRY("vkGetPhysicalDeviceQueueFamilyProperties", fakeGetPhysicalDeviceQueueFamilyProperties),
    ENTRY("vkGetPhysicalDeviceQueueFamilyProperties2", fakeGetPhysicalDeviceQueueFamilyProperties2),
    ENTRY("vkGetPhysicalDeviceQueueFamilyProperties2KHR", fakeGetPhysicalDeviceQueueFamilyProperties2),
    ENTRY("vkGetPhysicalDeviceMemoryProperties", fakeGetPhysicalDeviceMemoryProperties),
    ENTRY("vkGetPhysicalDeviceMemoryProperties2", fakeGetPhysicalDeviceMemoryProperties2),
    ENTRY("vkGetPhysicalDeviceMemoryProperties2KHR", fakeGetPhysicalDeviceMemoryProperties2),
    ENTRY("vkGetPhysicalDeviceFormatProperties", fakeGetPhysicalDeviceFormatProperties),
    ENTRY("vkGetPhysicalDeviceFormatProperties2", fakeGetPhysicalDeviceFormatProperties2),
    ENTRY("vkGetPhysicalDeviceFormatProperties2KHR", fakeGetPhysicalDeviceFormatProperties2),
    ENTRY("vkGetPhysicalDeviceImageFormatProperties", fakeGetPhysicalDeviceImageFormatProperties),
    ENTRY("vkGetPhysicalDeviceImageFormatProperties2", fakeGetPhysicalDeviceImageFormatProperties2),
    ENTRY("vkGetPhysicalDeviceImageFormatProperties2KHR", fakeGetPhysicalDeviceImageFormatProperties2),
    ENTRY("vkGetPhysicalDeviceSparseImageFormatProperties", fakeGetPhysicalDeviceSparseImageFormatProperties),
    ENTRY("vkGetPhysicalDeviceSparseImageFormatProperties2", fakeGetPhysicalDeviceSparseImageFormatProperties2),
    ENTRY("vkGetPhysicalDeviceSparseImageFormatProperties2KHR", fakeGetPhysicalDeviceSparseImageFormatProperties2),
    ENTRY("vkGetPhysicalDeviceExternalBufferProperties", fakeGetPhysicalDeviceExternalBufferProperties),
    ENTRY("vkGetPhysicalDeviceExternalFenceProperties", fakeGetPhysicalDeviceExternalFenceProperties),
    ENTRY("vkGetPhysicalDeviceExternalSemaphoreProperties", fakeGetPhysicalDeviceExternalSemaphoreProperties),
    ENTRY("vkGetPhysicalDeviceToolProperties", fakeGetPhysicalDeviceToolProperties),
    ENTRY("vkEnumerateDeviceExtensionProperties", fakeEnumerateDeviceExtensionProperties),
    ENTRY("vkEnumerateDeviceLayerProperties", fakeEnumerateDeviceLayerProperties),
    ENTRY("vkCreateDevice", fakeCreateDevice),
};

static const struct Entry kInstance[] = {
    ENTRY("vkDestroyInstance", fakeDestroyInstance),
    ENTRY("vkEnumeratePhysicalDevices", fakeEnumeratePhysicalDevices),
    ENTRY("vkEnumeratePhysicalDeviceGroups", fakeEnumeratePhysicalDeviceGroups),
    ENTRY("vkEnumeratePhysicalDeviceGroupsKHR", fakeEnumeratePhysicalDeviceGroups),
    ENTRY("vkGetDeviceProcAddr", fakeGetDeviceProcAddr),
    ENTRY("vkGetInstanceProcAddr", vk_icdGetInstanceProcAddr),
};

static PFN_vkVoidFunction find(const struct Entry* table, size_t n, const char* name) {
    for (size_t i = 0; i < n; ++i)
        if (strcmp(table[i].name, name) == 0) return table[i].fn;
    return NULL;
}

#define FIND(table, name) find(table, sizeof table / sizeof table[0], name)

EXPORT VKAPI_ATTR VkResult VKAPI_CALL vk_icdNegotiateLoaderICDInterfaceVersion(uint32_t* pVersion) {
    if (*pVersion > FAKE_INTERFACE_VERSION) *pVersion = FAKE_INTERFACE_VERSION;
    return VK_SUCCESS;
}

EXPORT VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL vk_icdGetInstanceProcAddr(VkInstance instance, const char* pName) {
    if (!pName) return NULL;
    PFN_vkVoidFunction fn = FIND(kGlobal, pName);
    if (fn || !instance) return fn;
    if ((fn = FIND(kInstance, pName))) return fn;
    return FIND(kPhysicalDevice, pName);
}

EXPORT VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL vk_icdGetPhysicalDeviceProcAddr(VkInstance instance, const char* pName) {
    (void)instance;
    if (!pName) return NULL;
    return FIND(kPhysicalDevice, pName);
}
