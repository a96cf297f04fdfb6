#include "Context.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <sstream>
#include <string_view>
#include <vector>

#include "HostHeap.h"

namespace m3g::vk {

namespace {

std::atomic<std::uint64_t> gValidationMessages{0};
std::mutex gMessageMutex;
std::string gLastMessage;
int gValidationRequest = -1;  // -1: from the environment
std::mutex gContextMutex;
std::shared_ptr<Context> gContext;
std::atomic<bool> gExists{false};

const char* kInstallHint =
    "install a Vulkan loader and driver (Debian: apt-get install libvulkan1 mesa-vulkan-drivers) "
    "or select another device with M3G_VK_DEVICE";

VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                         VkDebugUtilsMessageTypeFlagsEXT type,
                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
    const bool counted = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ||
                         ((severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) &&
                          (type & VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT));
    if (counted) {
        ++gValidationMessages;
        std::lock_guard lock(gMessageMutex);
        gLastMessage = data && data->pMessage ? data->pMessage : "(no text)";
        std::fprintf(stderr, "m3g-vk validation: %s\n", gLastMessage.c_str());
    }
    return VK_FALSE;
}

std::vector<std::string> gWindowExtensions;  // requested by a windowed application

std::vector<const char*> windowExtensions() {
    std::vector<const char*> out;
    for (const auto& e : gWindowExtensions) out.push_back(e.c_str());
    return out;
}

bool envValidation() {
    if (gValidationRequest >= 0) return gValidationRequest == 1;
    if (const char* v = std::getenv("M3G_VK_VALIDATION")) return std::strcmp(v, "0") != 0 && *v != '\0';
#ifdef NDEBUG
    return false;
#else
    return true;
#endif
}

const char* typeName(VkPhysicalDeviceType t) {
    switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
    default: return "other";
    }
}

int typeRank(VkPhysicalDeviceType t) {
    switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
    default: return 4;
    }
}

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

/// ", with VK_DRIVER_FILES=..." for the loader variables that choose drivers, or "".
std::string driverOverrides() {
    std::string out;
    for (const char* name : {"VK_DRIVER_FILES", "VK_ICD_FILENAMES", "VK_ADD_DRIVER_FILES"})
        if (const char* v = std::getenv(name); v && *v) out += std::string(out.empty() ? ", with " : " ") + name + "=" + v;
    return out;
}

/// Opens the Vulkan loader and hands its vkGetInstanceProcAddr to volk; ""
/// or what went wrong. Done here rather than by volkInitialize, which (in
/// Debian 12's volk) calls through a null vkGetInstanceProcAddr when the
/// library it opened does not export one.
std::string openLoader() {
    void* module = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!module) module = dlopen("libvulkan.so", RTLD_NOW | RTLD_LOCAL);
    if (!module) {
        const char* why = dlerror();
        return std::string("the Vulkan loader (libvulkan.so.1) is not installed") + (why ? std::string(" (") + why + ")" : "");
    }
    auto gipa = reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(module, "vkGetInstanceProcAddr"));
    if (!gipa) return "the libvulkan.so.1 found does not export vkGetInstanceProcAddr: it is not a Vulkan loader";
    volkInitializeCustom(gipa);
    if (!vkCreateInstance || !vkEnumerateInstanceExtensionProperties)
        return "the Vulkan loader (libvulkan.so.1) does not provide vkCreateInstance";
    return {};
}

void loadLoader() {
    static const std::string error = openLoader();
    if (!error.empty()) throw VulkanError("m3g-vk: " + error + "; " + kInstallHint);
}

VkInstance createInstance(bool wantValidation, bool& validation) {
    loadLoader();
    std::uint32_t version = VK_API_VERSION_1_0;
    if (vkEnumerateInstanceVersion) vkEnumerateInstanceVersion(&version);
    if (version < VK_API_VERSION_1_3)
        throw VulkanError("m3g-vk: the Vulkan loader supports only version " + std::to_string(VK_API_VERSION_MAJOR(version)) +
                          "." + std::to_string(VK_API_VERSION_MINOR(version)) + "; m3g-vk needs Vulkan 1.3");
    std::vector<const char*> layers, extensions;
    validation = false;
    if (wantValidation) {
        std::uint32_t n = 0;
        vkEnumerateInstanceLayerProperties(&n, nullptr);
        std::vector<VkLayerProperties> props(n);
        vkEnumerateInstanceLayerProperties(&n, props.data());
        for (const auto& p : props)
            if (std::strcmp(p.layerName, "VK_LAYER_KHRONOS_validation") == 0) validation = true;
        if (validation) {
            layers.push_back("VK_LAYER_KHRONOS_validation");
            extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        } else {
            std::fprintf(stderr, "m3g-vk: validation requested but VK_LAYER_KHRONOS_validation is not installed "
                                 "(Debian: vulkan-validationlayers)\n");
        }
    }
    // The window system extensions, when the loader has them (the viewer's swapchain).
    std::uint32_t n = 0;
    vkEnumerateInstanceExtensionProperties(nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> available(n);
    vkEnumerateInstanceExtensionProperties(nullptr, &n, available.data());
    for (const char* wanted : windowExtensions()) {
        bool found = false;
        for (const auto& e : available) found = found || std::strcmp(e.extensionName, wanted) == 0;
        if (!found) throw VulkanError(std::string("m3g-vk: the Vulkan loader lacks the window extension ") + wanted);
        extensions.push_back(wanted);
    }

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "m3g-vk";
    app.pEngineName = "m3g-vk";
    app.apiVersion = VK_API_VERSION_1_3;
    VkInstanceCreateInfo ci{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ci.pApplicationInfo = &app;
    ci.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
    ci.ppEnabledLayerNames = layers.data();
    ci.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    ci.ppEnabledExtensionNames = extensions.data();
    VkInstance instance = VK_NULL_HANDLE;
    VkResult r = vkCreateInstance(&ci, nullptr, &instance);
    if (r == VK_ERROR_INCOMPATIBLE_DRIVER)
        // The loader's answer when it found no driver it could load.
        throw VulkanError(std::string("m3g-vk: no usable Vulkan driver (ICD) was found (vkCreateInstance: "
                                      "VK_ERROR_INCOMPATIBLE_DRIVER)") + driverOverrides() + "; " + kInstallHint);
    if (r != VK_SUCCESS)
        throw VulkanError(std::string("m3g-vk: vkCreateInstance failed (") + resultName(r) + ")" + driverOverrides() +
                          "; " + kInstallHint);
    volkLoadInstance(instance);
    return instance;
}

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
    std::uint32_t n = 0;
    vkEnumeratePhysicalDevices(instance, &n, nullptr);
    std::vector<VkPhysicalDevice> out(n);
    if (n) vkEnumeratePhysicalDevices(instance, &n, out.data());
    return out;
}

DeviceInfo describe(VkPhysicalDevice pd) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(pd, &p);
    return {p.deviceName, typeName(p.deviceType), p.apiVersion, p.vendorID, p.deviceID};
}

}  // namespace

const char* resultName(VkResult r) {
    switch (r) {
    case VK_SUCCESS: return "VK_SUCCESS";
    case VK_NOT_READY: return "VK_NOT_READY";
    case VK_TIMEOUT: return "VK_TIMEOUT";
    case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER";
    case VK_ERROR_FORMAT_NOT_SUPPORTED: return "VK_ERROR_FORMAT_NOT_SUPPORTED";
    case VK_ERROR_OUT_OF_DATE_KHR: return "VK_ERROR_OUT_OF_DATE_KHR";
    case VK_SUBOPTIMAL_KHR: return "VK_SUBOPTIMAL_KHR";
    case VK_ERROR_SURFACE_LOST_KHR: return "VK_ERROR_SURFACE_LOST_KHR";
    default: return "VkResult error";
    }
}

void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, std::uint32_t level,
                  std::uint32_t count, VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 srcStage,
                  VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask = srcStage;
    b.srcAccessMask = srcAccess;
    b.dstStageMask = dstStage;
    b.dstAccessMask = dstAccess;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {aspect, level, count, 0, 1};
    VkDependencyInfo d{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    d.imageMemoryBarrierCount = 1;
    d.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &d);
}

void copyBufferToImage(VkCommandBuffer cmd, VkBuffer buffer, VkImage image, std::uint32_t width, std::uint32_t height) {
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {width, height, 1};
    vkCmdCopyBufferToImage(cmd, buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
}

void check(VkResult result, const char* what) {
    if (result != VK_SUCCESS)
        throw VulkanError(std::string("m3g-vk: ") + what + " failed (" + resultName(result) + ", " +
                          std::to_string(static_cast<int>(result)) + ")");
}

VkShaderModule createShaderModule(VkDevice device, const std::uint32_t* code, std::size_t bytes) {
    VkShaderModuleCreateInfo ci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    ci.codeSize = bytes;
    ci.pCode = code;
    VkShaderModule module;
    check(vkCreateShaderModule(device, &ci, nullptr, &module), "vkCreateShaderModule");
    return module;
}

VkDescriptorPool createDescriptorPool(VkDevice device, VkDescriptorType type, std::uint32_t sets,
                                      std::uint32_t perSet, const char* what, VkDescriptorPoolCreateFlags flags) {
    VkDescriptorPoolSize size{type, sets * perSet};
    VkDescriptorPoolCreateInfo pi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pi.flags = flags;
    pi.maxSets = sets;
    pi.poolSizeCount = 1;
    pi.pPoolSizes = &size;
    VkDescriptorPool pool;
    check(vkCreateDescriptorPool(device, &pi, nullptr, &pool), (std::string("vkCreateDescriptorPool (") + what + ")").c_str());
    return pool;
}

bool Context::exists() noexcept { return gExists.load(); }

Context& Context::get() { return *shared(); }

std::shared_ptr<Context> Context::shared() {
    std::lock_guard lock(gContextMutex);
    if (!gContext) {
        gContext.reset(new Context());
        gExists = true;
        // Destroy the device before the driver's and layers' static
        // destructors (registered before this handler, so they run after it).
        static const bool registered = [] {
            std::atexit([] {
                std::shared_ptr<Context> last;
                {
                    std::lock_guard inner(gContextMutex);
                    last.swap(gContext);
                    gExists = false;
                }
            });
            return true;
        }();
        (void)registered;
    }
    return gContext;
}

Context::Context() {
    instance_ = createInstance(envValidation(), validation_);
    try {
        if (validation_) {
            VkDebugUtilsMessengerCreateInfoEXT mi{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
            mi.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
            mi.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                             VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
            mi.pfnUserCallback = onMessage;
            check(vkCreateDebugUtilsMessengerEXT(instance_, &mi, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
        }

        // Device choice: M3G_VK_DEVICE (index or name substring), else by type rank.
        auto devices = physicalDevices(instance_);
        std::vector<VkPhysicalDevice> usable;
        for (auto pd : devices) {
            VkPhysicalDeviceProperties p;
            vkGetPhysicalDeviceProperties(pd, &p);
            if (p.apiVersion >= VK_API_VERSION_1_3) usable.push_back(pd);
        }
        if (devices.empty())
            throw VulkanError("m3g-vk: the Vulkan loader reports no device" + driverOverrides() + "; " + kInstallHint);
        if (usable.empty())
            throw VulkanError(std::string("m3g-vk: no Vulkan 1.3 device found (") + std::to_string(devices.size()) +
                              " device(s) of older versions); " + kInstallHint);
        VkPhysicalDevice chosen = VK_NULL_HANDLE;
        if (const char* want = std::getenv("M3G_VK_DEVICE"); want && *want) {
            char* end = nullptr;
            long index = std::strtol(want, &end, 10);
            if (end && *end == '\0') {
                if (index < 0 || index >= static_cast<long>(devices.size()))
                    throw VulkanError("m3g-vk: M3G_VK_DEVICE=" + std::string(want) + " is out of range [0, " +
                                      std::to_string(devices.size()) + ")");
                chosen = devices[index];
            } else {
                for (auto pd : devices)
                    if (lower(describe(pd).name).find(lower(want)) != std::string::npos) {
                        chosen = pd;
                        break;
                    }
                if (!chosen) throw VulkanError("m3g-vk: no device name contains M3G_VK_DEVICE=\"" + std::string(want) + "\"");
            }
        } else {
            chosen = *std::min_element(usable.begin(), usable.end(), [](VkPhysicalDevice a, VkPhysicalDevice b) {
                VkPhysicalDeviceProperties pa, pb;
                vkGetPhysicalDeviceProperties(a, &pa);
                vkGetPhysicalDeviceProperties(b, &pb);
                return typeRank(pa.deviceType) < typeRank(pb.deviceType);
            });
        }
        physical_ = chosen;
        vkGetPhysicalDeviceProperties(physical_, &properties_);
        vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
        info_ = describe(physical_);
        // lavapipe's per-draw vertex storage comes from the host heap (HostHeap.h).
        if (properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) keepHostHeap();
        if (properties_.apiVersion < VK_API_VERSION_1_3)
            throw VulkanError("m3g-vk: device \"" + info_.name + "\" supports only Vulkan " +
                              std::to_string(VK_API_VERSION_MAJOR(properties_.apiVersion)) + "." +
                              std::to_string(VK_API_VERSION_MINOR(properties_.apiVersion)) + "; m3g-vk needs 1.3");

        std::uint32_t nq = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(physical_, &nq, nullptr);
        std::vector<VkQueueFamilyProperties> families(nq);
        vkGetPhysicalDeviceQueueFamilyProperties(physical_, &nq, families.data());
        bool found = false;
        for (std::uint32_t i = 0; i < nq && !found; ++i)
            if ((families[i].queueFlags & (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) ==
                (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) {
                queueFamily_ = i;
                found = true;
            }
        if (!found) throw VulkanError("m3g-vk: device \"" + info_.name + "\" has no graphics+compute queue");

        // Depth: 16-bit UNORM, as the reference renders (Nokia's engine asks
        // EGL for at least 8 depth bits and EGL picks the smallest: Mesa's
        // 16), so surfaces closer than 1/65535 of the depth range tie under
        // LEQUAL the same way. D16_UNORM is mandatory for depth attachments;
        // M3G_VK_DEPTH_BITS=32 prefers D32_SFLOAT (guide §8) for precision.
        const char* depthBits = std::getenv("M3G_VK_DEPTH_BITS");
        const bool wide = depthBits != nullptr && std::string_view(depthBits) == "32";
        depthFormat_ = VK_FORMAT_UNDEFINED;
        const VkFormat narrowFirst[2] = {VK_FORMAT_D16_UNORM, VK_FORMAT_D32_SFLOAT};
        const VkFormat wideFirst[2] = {VK_FORMAT_D32_SFLOAT, VK_FORMAT_D16_UNORM};
        for (VkFormat f : wide ? wideFirst : narrowFirst) {
            VkFormatProperties fp;
            vkGetPhysicalDeviceFormatProperties(physical_, f, &fp);
            if (fp.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT) {
                depthFormat_ = f;
                break;
            }
        }
        if (depthFormat_ == VK_FORMAT_UNDEFINED) throw VulkanError("m3g-vk: no usable depth format");
        const VkSampleCountFlags counts =
            properties_.limits.framebufferColorSampleCounts & properties_.limits.framebufferDepthSampleCounts;
        maxSamples_ = (counts & VK_SAMPLE_COUNT_4_BIT) ? VK_SAMPLE_COUNT_4_BIT
                      : (counts & VK_SAMPLE_COUNT_2_BIT) ? VK_SAMPLE_COUNT_2_BIT
                                                         : VK_SAMPLE_COUNT_1_BIT;

        VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
        VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        f2.pNext = &f13;
        vkGetPhysicalDeviceFeatures2(physical_, &f2);
        if (!f13.dynamicRendering || !f13.synchronization2)
            throw VulkanError("m3g-vk: device \"" + info_.name + "\" lacks dynamicRendering or synchronization2");
        VkPhysicalDeviceVulkan13Features enable13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
        enable13.dynamicRendering = VK_TRUE;
        enable13.synchronization2 = VK_TRUE;
        VkPhysicalDeviceFeatures2 enable{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        enable.pNext = &enable13;
        enable.features.samplerAnisotropy = VK_FALSE;
        // Wireframe debug view only (DebugView::wireframe).
        enable.features.fillModeNonSolid = f2.features.fillModeNonSolid;
        wireframe_ = f2.features.fillModeNonSolid == VK_TRUE;

        std::vector<const char*> extensions;
        std::uint32_t ne = 0;
        vkEnumerateDeviceExtensionProperties(physical_, nullptr, &ne, nullptr);
        std::vector<VkExtensionProperties> available(ne);
        vkEnumerateDeviceExtensionProperties(physical_, nullptr, &ne, available.data());
        // Swapchains only for windowed applications (requestWindowExtensions).
        if (!gWindowExtensions.empty())
            for (const auto& e : available)
                if (std::strcmp(e.extensionName, VK_KHR_SWAPCHAIN_EXTENSION_NAME) == 0) {
                    extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
                    swapchain_ = true;
                }

        const float priority = 1.0f;
        VkDeviceQueueCreateInfo qi{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        qi.queueFamilyIndex = queueFamily_;
        qi.queueCount = 1;
        qi.pQueuePriorities = &priority;
        VkDeviceCreateInfo di{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
        di.pNext = &enable;
        di.queueCreateInfoCount = 1;
        di.pQueueCreateInfos = &qi;
        di.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
        di.ppEnabledExtensionNames = extensions.data();
        VkResult r = vkCreateDevice(physical_, &di, nullptr, &device_);
        if (r != VK_SUCCESS) {
            // The driver loaded and showed the device, then refused it: a
            // broken driver or a GPU that is gone. Name the device as
            // M3G_VK_DEVICE selects it, and the other ways out.
            const auto index = std::find(devices.begin(), devices.end(), physical_) - devices.begin();
            throw VulkanError("m3g-vk: the Vulkan driver could not create a device on device " + std::to_string(index) +
                              " \"" + info_.name + "\" (vkCreateDevice: " + resultName(r) + ", " +
                              std::to_string(static_cast<int>(r)) + ")" + driverOverrides() +
                              "; the driver or the GPU is not working (check with vulkaninfo): " + kInstallHint +
                              ", or another driver with VK_DRIVER_FILES");
        }
        volkLoadDevice(device_);
        vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
        pool_ = createCommandPool();
    } catch (...) {
        if (device_) vkDestroyDevice(device_, nullptr);
        if (messenger_) vkDestroyDebugUtilsMessengerEXT(instance_, messenger_, nullptr);
        vkDestroyInstance(instance_, nullptr);
        throw;
    }
}

Context::~Context() {
    if (device_) {
        vkDeviceWaitIdle(device_);
        vkDestroyCommandPool(device_, pool_, nullptr);
        vkDestroyDevice(device_, nullptr);
    }
    if (messenger_) vkDestroyDebugUtilsMessengerEXT(instance_, messenger_, nullptr);
    if (instance_) vkDestroyInstance(instance_, nullptr);
}

std::uint32_t Context::memoryType(std::uint32_t bits, VkMemoryPropertyFlags want, VkMemoryPropertyFlags fallback) const {
    for (VkMemoryPropertyFlags flags : {want, fallback})
        for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
            if ((bits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & flags) == flags) return i;
    throw VulkanError("m3g-vk: no suitable memory type");
}

Buffer Context::createHostBuffer(VkDeviceSize size, VkBufferUsageFlags usage) {
    Buffer b;
    b.size = size;
    VkBufferCreateInfo bi{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bi.size = size;
    bi.usage = usage;
    bi.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    check(vkCreateBuffer(device_, &bi, nullptr, &b.buffer), "vkCreateBuffer");
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device_, b.buffer, &req);
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    // Device-local and host-visible when the device has it (lavapipe, ReBAR), else plain host memory.
    ai.memoryTypeIndex = memoryType(req.memoryTypeBits,
                                    VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT | VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                        VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                                    VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    VkResult r = vkAllocateMemory(device_, &ai, nullptr, &b.memory);
    if (r != VK_SUCCESS) {
        vkDestroyBuffer(device_, b.buffer, nullptr);
        check(r, "vkAllocateMemory (buffer)");
    }
    vkBindBufferMemory(device_, b.buffer, b.memory, 0);
    check(vkMapMemory(device_, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
    ++liveBuffers;
    memoryBytes += static_cast<std::int64_t>(req.size);
    b.size = size;
    return b;
}

void Context::destroy(Buffer& b) noexcept {
    if (!b.buffer) return;
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device_, b.buffer, &req);
    memoryBytes -= static_cast<std::int64_t>(req.size);
    --liveBuffers;
    vkDestroyBuffer(device_, b.buffer, nullptr);
    vkFreeMemory(device_, b.memory, nullptr);
    b = Buffer{};
}

Image Context::createImage(std::uint32_t width, std::uint32_t height, VkFormat format, VkImageUsageFlags usage,
                           std::uint32_t mipLevels, VkSampleCountFlagBits samples) {
    return makeImage(width, height, format, usage, mipLevels, samples, false);
}

Image Context::createHostImage(std::uint32_t width, std::uint32_t height, VkFormat format, VkImageUsageFlags usage) {
    return makeImage(width, height, format, usage, 1, VK_SAMPLE_COUNT_1_BIT, true);
}

bool Context::hostImageUsable(VkFormat format, VkFormatFeatureFlags features) const {
    if (properties_.deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU) return false;
    VkFormatProperties fp;
    vkGetPhysicalDeviceFormatProperties(physical_, format, &fp);
    return (fp.linearTilingFeatures & features) == features;
}

Image Context::makeImage(std::uint32_t width, std::uint32_t height, VkFormat format, VkImageUsageFlags usage,
                         std::uint32_t mipLevels, VkSampleCountFlagBits samples, bool host) {
    Image img;
    img.format = format;
    img.width = width;
    img.height = height;
    img.mipLevels = mipLevels;
    VkImageCreateInfo ii{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ii.imageType = VK_IMAGE_TYPE_2D;
    ii.format = format;
    ii.extent = {width, height, 1};
    ii.mipLevels = mipLevels;
    ii.arrayLayers = 1;
    ii.samples = samples;
    ii.tiling = host ? VK_IMAGE_TILING_LINEAR : VK_IMAGE_TILING_OPTIMAL;
    ii.usage = usage;
    ii.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    check(vkCreateImage(device_, &ii, nullptr, &img.image), "vkCreateImage");
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device_, img.image, &req);
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    const VkMemoryPropertyFlags hostFlags = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    VkResult r = VK_ERROR_OUT_OF_DEVICE_MEMORY;
    try {
        ai.memoryTypeIndex = host ? memoryType(req.memoryTypeBits, hostFlags, hostFlags)
                                  : memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0);
        r = vkAllocateMemory(device_, &ai, nullptr, &img.memory);
    } catch (...) {
        vkDestroyImage(device_, img.image, nullptr);
        throw;
    }
    if (r != VK_SUCCESS) {
        vkDestroyImage(device_, img.image, nullptr);
        check(r, "vkAllocateMemory (image)");
    }
    vkBindImageMemory(device_, img.image, img.memory, 0);
    if (host) {
        const VkImageSubresource sub{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0};
        VkSubresourceLayout layout;
        vkGetImageSubresourceLayout(device_, img.image, &sub, &layout);
        img.rowPitch = layout.rowPitch;
        void* base = nullptr;
        check(vkMapMemory(device_, img.memory, 0, VK_WHOLE_SIZE, 0, &base), "vkMapMemory (image)");
        img.mapped = static_cast<char*>(base) + layout.offset;
    }
    const bool depth = format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D16_UNORM;
    VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vi.image = img.image;
    vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vi.format = format;
    vi.subresourceRange = {static_cast<VkImageAspectFlags>(depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT),
                           0, mipLevels, 0, 1};
    check(vkCreateImageView(device_, &vi, nullptr, &img.view), "vkCreateImageView");
    img.bytes = req.size;
    memoryBytes += static_cast<std::int64_t>(req.size);
    ++liveTextures;
    return img;
}

void Context::destroy(Image& img) noexcept {
    if (!img.image) return;
    memoryBytes -= static_cast<std::int64_t>(img.bytes);
    --liveTextures;
    vkDestroyImageView(device_, img.view, nullptr);
    vkDestroyImage(device_, img.image, nullptr);
    vkFreeMemory(device_, img.memory, nullptr);
    img = Image{};
}

void Context::submitNow(const std::function<void(VkCommandBuffer)>& record) {
    VkCommandBuffer cmd;
    {
        // Recording into a buffer of the shared pool is host access to the
        // pool: hold its lock until the buffer is ended.
        std::lock_guard lock(poolMutex_);
        VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        ai.commandPool = pool_;
        ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        ai.commandBufferCount = 1;
        check(vkAllocateCommandBuffers(device_, &ai, &cmd), "vkAllocateCommandBuffers");
        VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        vkBeginCommandBuffer(cmd, &bi);
        try {
            record(cmd);
        } catch (...) {
            vkEndCommandBuffer(cmd);
            vkFreeCommandBuffers(device_, pool_, 1, &cmd);
            throw;
        }
        vkEndCommandBuffer(cmd);
    }
    auto freeCommandBuffer = [&] {
        std::lock_guard lock(poolMutex_);
        vkFreeCommandBuffers(device_, pool_, 1, &cmd);
    };
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    VkResult r = vkCreateFence(device_, &fi, nullptr, &fence);
    if (r != VK_SUCCESS) {
        freeCommandBuffer();
        check(r, "vkCreateFence");
    }
    try {
        submit(cmd, fence);
    } catch (...) {
        vkDestroyFence(device_, fence, nullptr);
        freeCommandBuffer();
        throw;
    }
    r = vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX);
    vkDestroyFence(device_, fence, nullptr);
    freeCommandBuffer();
    check(r, "vkWaitForFences (upload)");
}

void Context::submit(std::span<const VkCommandBuffer> cmds, VkFence fence, VkSemaphore wait,
                     VkPipelineStageFlags waitStage, VkSemaphore signal) {
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = static_cast<std::uint32_t>(cmds.size());
    si.pCommandBuffers = cmds.data();
    si.waitSemaphoreCount = wait ? 1 : 0;
    si.pWaitSemaphores = &wait;
    si.pWaitDstStageMask = &waitStage;
    si.signalSemaphoreCount = signal ? 1 : 0;
    si.pSignalSemaphores = &signal;
    std::lock_guard lock(queueMutex_);
    check(vkQueueSubmit(queue_, 1, &si, fence), "vkQueueSubmit");
}

VkResult Context::present(const VkPresentInfoKHR& info) {
    std::lock_guard lock(queueMutex_);
    return vkQueuePresentKHR(queue_, &info);
}

void Context::waitIdle() {
    std::lock_guard lock(queueMutex_);
    vkDeviceWaitIdle(device_);
}

VkCommandPool Context::createCommandPool() {
    VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pi.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pi.queueFamilyIndex = queueFamily_;
    VkCommandPool pool = VK_NULL_HANDLE;
    check(vkCreateCommandPool(device_, &pi, nullptr, &pool), "vkCreateCommandPool");
    return pool;
}

// ---- public functions (Vulkan.h) ----

std::vector<DeviceInfo> listDevices() {
    if (Context::exists()) {
        std::vector<DeviceInfo> out;
        for (auto pd : physicalDevices(Context::get().instance())) out.push_back(describe(pd));
        return out;
    }
    bool validation = false;
    VkInstance instance = createInstance(false, validation);
    std::vector<DeviceInfo> out;
    for (auto pd : physicalDevices(instance)) out.push_back(describe(pd));
    vkDestroyInstance(instance, nullptr);
    return out;
}

DeviceInfo currentDevice() { return Context::get().info(); }

bool requestValidation(bool enable) {
    std::lock_guard lock(gContextMutex);
    if (gContext) return false;
    gValidationRequest = enable ? 1 : 0;
    return true;
}

bool requestWindowExtensions(const std::vector<std::string>& instanceExtensions) {
    std::lock_guard lock(gContextMutex);
    if (gContext) return false;
    gWindowExtensions = instanceExtensions;
    return true;
}

bool validationEnabled() { return Context::exists() && Context::get().validation(); }
std::uint64_t validationMessageCount() { return gValidationMessages.load(); }

namespace {
std::atomic<bool> gWireframe{false}, gUnlit{false};
}

void setDebugView(const DebugView& view) noexcept {
    gWireframe = view.wireframe;
    gUnlit = view.unlit;
}

DebugView debugView() noexcept { return DebugView{gWireframe.load(), gUnlit.load()}; }

namespace {
std::atomic<bool>& clampLitFlag() noexcept {
    static std::atomic<bool> flag{[] {
        const char* v = std::getenv("M3G_CLAMP_LIGHTING");
        return v != nullptr && std::string_view(v) == "1";
    }()};
    return flag;
}
}  // namespace

void setLitColorClamping(bool clamp) noexcept { clampLitFlag() = clamp; }
bool litColorClamping() noexcept { return clampLitFlag().load(); }
std::string lastValidationMessage() {
    std::lock_guard lock(gMessageMutex);
    return gLastMessage;
}

RenderStats renderStats() {
    RenderStats s;
    if (!Context::exists()) return s;
    Context& c = Context::get();
    s.pipelinesCreated = c.pipelinesCreated;
    s.pipelinesEvicted = c.pipelinesEvicted;
    s.livePipelines = static_cast<std::uint64_t>(std::max<std::int64_t>(0, c.livePipelines));
    s.draws = c.draws;
    s.bufferUploads = c.bufferUploads;
    s.textureUploads = c.textureUploads;
    s.frames = c.frames;
    s.computeDispatches = c.computeDispatches;
    s.liveBuffers = static_cast<std::uint64_t>(std::max<std::int64_t>(0, c.liveBuffers));
    s.liveTextures = static_cast<std::uint64_t>(std::max<std::int64_t>(0, c.liveTextures));
    s.deviceMemoryBytes = static_cast<std::uint64_t>(std::max<std::int64_t>(0, c.memoryBytes));
    return s;
}

}  // namespace m3g::vk
