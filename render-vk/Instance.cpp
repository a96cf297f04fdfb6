// The Vulkan loader, the instance and the validation layer's messages, and
// the requests an application makes before the device exists (validation,
// window extensions).
#include "Instance.h"

#include <dlfcn.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace m3g::vk {


std::atomic<std::uint64_t> gValidationMessages{0};
std::mutex gMessageMutex;
std::string gLastMessage;
int gValidationRequest = -1;

const char* const kInstallHint =
    "install a Vulkan loader and driver (Debian: apt-get install libvulkan1 mesa-vulkan-drivers) "
    "or select another device with M3G_VK_DEVICE";

namespace {

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

}  // namespace

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
    // The window system extensions, when the loader has them (the viewer's
    // swapchain). Listed only when some are wanted: each listing makes the
    // loader read every driver manifest again and open the drivers (about
    // 9 ms a call with lavapipe), and headless work wants none.
    const std::vector<const char*> wantedWindow = windowExtensions();
    std::vector<VkExtensionProperties> available;
    if (!wantedWindow.empty()) {
        std::uint32_t n = 0;
        vkEnumerateInstanceExtensionProperties(nullptr, &n, nullptr);
        available.resize(n);
        vkEnumerateInstanceExtensionProperties(nullptr, &n, available.data());
        available.resize(n);
    }
    for (const char* wanted : wantedWindow) {
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


VkDebugUtilsMessengerEXT createMessenger(VkInstance instance) {
    VkDebugUtilsMessengerCreateInfoEXT mi{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    mi.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    mi.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    mi.pfnUserCallback = onMessage;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    check(vkCreateDebugUtilsMessengerEXT(instance, &mi, nullptr, &messenger), "vkCreateDebugUtilsMessengerEXT");
    return messenger;
}

}  // namespace m3g::vk
