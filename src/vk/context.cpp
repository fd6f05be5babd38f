// context.cpp - instance, debug messenger and logical device creation.
#include "vk/context.h"

#include <cstdio>
#include <cstring>

#include "vk/check.h"

namespace vk {

static bool hasLayer(const char* name) {
    uint32_t count = 0;
    check(vkEnumerateInstanceLayerProperties(&count, nullptr),
          "vkEnumerateInstanceLayerProperties");
    std::vector<VkLayerProperties> layers(count);
    check(vkEnumerateInstanceLayerProperties(&count, layers.data()),
          "vkEnumerateInstanceLayerProperties");
    for (const auto& layer : layers)
        if (std::strcmp(layer.layerName, name) == 0) return true;
    return false;
}

static bool hasInstanceExtension(const char* name) {
    uint32_t count = 0;
    check(vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr),
          "vkEnumerateInstanceExtensionProperties");
    std::vector<VkExtensionProperties> extensions(count);
    check(vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data()),
          "vkEnumerateInstanceExtensionProperties");
    for (const auto& extension : extensions)
        if (std::strcmp(extension.extensionName, name) == 0) return true;
    return false;
}

Instance::Instance(const InstanceOptions& options) : verbose_(options.validation) {
    uint32_t loaderVersion = 0;
    check(vkEnumerateInstanceVersion(&loaderVersion), "vkEnumerateInstanceVersion");
    if (loaderVersion < VK_API_VERSION_1_2)
        throw Error("the Vulkan loader supports only Vulkan " + versionString(loaderVersion) +
                    "; idview needs 1.2 or newer");

    const char* validationLayer = "VK_LAYER_KHRONOS_validation";
    std::vector<const char*> layers;
    if (options.validation) {
        if (!hasLayer(validationLayer))
            throw Error("--validation: the Khronos validation layer is not installed (Debian "
                        "package vulkan-validationlayers)");
        layers.push_back(validationLayer);
    }
    std::vector<const char*> extensions = options.extensions;
    const bool debugUtils = hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (debugUtils)
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    else if (options.validation)
        throw Error("--validation needs VK_EXT_debug_utils, which this Vulkan loader lacks");

    auto app = vk::init<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
    app.pApplicationName = "idview";
    app.applicationVersion = VK_MAKE_API_VERSION(0, 0, 1, 0);
    app.pEngineName = "idview";
    app.apiVersion = VK_API_VERSION_1_2;

    // The messenger is chained into creation too, so messages from vkCreateInstance count.
    auto messenger = vk::init<VkDebugUtilsMessengerCreateInfoEXT>(
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
    messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger.pfnUserCallback = &Instance::onMessage;
    messenger.pUserData = this;

    const VkValidationFeatureEnableEXT syncEnable =
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    auto features = vk::init<VkValidationFeaturesEXT>(VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT);
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = &syncEnable;
    if (options.validation && options.syncValidation) {
        extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME); // from the layer
        features.pNext = &messenger;
    }

    auto info = vk::init<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
    info.pNext = debugUtils ? &messenger : nullptr;
    if (options.validation && options.syncValidation) info.pNext = &features;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = static_cast<uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkResult created = vkCreateInstance(&info, nullptr, &instance_);
    if (created == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw Error("no Vulkan device found: the loader found no driver (Debian: "
                    "mesa-vulkan-drivers for the CPU device, or your GPU vendor's driver)");
    check(created, "vkCreateInstance");

    if (debugUtils) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        VkResult result = create(instance_, &messenger, nullptr, &messenger_);
        if (result != VK_SUCCESS) {
            vkDestroyInstance(instance_, nullptr);
            check(result, "vkCreateDebugUtilsMessengerEXT");
        }
        debug_.load(instance_);
    }
}

Instance::~Instance() {
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(instance_, messenger_, nullptr);
    }
    vkDestroyInstance(instance_, nullptr);
}

VkBool32 VKAPI_PTR Instance::onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                       VkDebugUtilsMessageTypeFlagsEXT types,
                                       const VkDebugUtilsMessengerCallbackDataEXT* data,
                                       void* user) {
    auto* self = static_cast<Instance*>(user);
    const bool error = severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    const bool validation = types & (VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT);
    if (validation) self->validationMessages_.fetch_add(1);
    // Loader chatter (a broken ICD file, ...) only matters when debugging, i.e. --validation.
    if (!validation && !self->verbose_) return VK_FALSE;
    std::fprintf(stderr, "idview: vulkan %s %s: %s\n", validation ? "validation" : "loader",
                 error ? "error" : "warning", data->pMessage ? data->pMessage : "");
    return VK_FALSE;
}

std::vector<DeviceInfo> Instance::devices() const {
    uint32_t count = 0;
    check(vkEnumeratePhysicalDevices(instance_, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> handles(count);
    check(vkEnumeratePhysicalDevices(instance_, &count, handles.data()),
          "vkEnumeratePhysicalDevices");
    std::vector<DeviceInfo> infos;
    for (uint32_t i = 0; i < count; ++i) infos.push_back(queryDevice(handles[i], i));
    return infos;
}

Device::Device(const Instance& instance, const DeviceInfo& info,
               const std::vector<const char*>& extraExtensions)
    : info_(info), debug_(instance.debug()) {
    float priority = 1.0f;
    auto queue = vk::init<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
    queue.queueFamilyIndex = info.graphicsQueueFamily;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;

    auto f12 = vk::init<VkPhysicalDeviceVulkan12Features>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES);
    f12.bufferDeviceAddress = VK_TRUE;
    f12.shaderBufferInt64Atomics = VK_TRUE;
    auto features =
        vk::init<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
    features.pNext = &f12;
    features.features.shaderInt64 = VK_TRUE;
    features.features.geometryShader = VK_TRUE;
    features.features.multiDrawIndirect = VK_TRUE;
    features.features.drawIndirectFirstInstance = VK_TRUE;
    features.features.fragmentStoresAndAtomics = VK_TRUE;
    features.features.independentBlend = VK_TRUE;

    std::vector<const char*> extensions = extraExtensions;
    if (info.geometryShaderPassthrough)
        extensions.push_back(VK_NV_GEOMETRY_SHADER_PASSTHROUGH_EXTENSION_NAME);
    auto create = vk::init<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
    create.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    create.ppEnabledExtensionNames = extensions.data();
    create.pNext = &features;
    create.queueCreateInfoCount = 1;
    create.pQueueCreateInfos = &queue;
    check(vkCreateDevice(info.handle, &create, nullptr, &device_), "vkCreateDevice");
    vkGetDeviceQueue(device_, info.graphicsQueueFamily, 0, &queue_);
    vkGetPhysicalDeviceMemoryProperties(info.handle, &memory_);

    auto pool = vk::init<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    pool.queueFamilyIndex = info.graphicsQueueFamily;
    VkResult result = vkCreateCommandPool(device_, &pool, nullptr, &uploadPool_);
    if (result != VK_SUCCESS) {
        vkDestroyDevice(device_, nullptr);
        check(result, "vkCreateCommandPool");
    }
    name(VK_OBJECT_TYPE_COMMAND_POOL, uploadPool_, "upload pool");
    name(VK_OBJECT_TYPE_QUEUE, queue_, "graphics queue");
}

Device::~Device() {
    // Nothing may be in flight when the device goes; a failure here cannot be acted on.
    vkDeviceWaitIdle(device_);
    vkDestroyCommandPool(device_, uploadPool_, nullptr);
    vkDestroyDevice(device_, nullptr);
}

uint32_t Device::memoryType(uint32_t typeBits, VkMemoryPropertyFlags flags) const {
    for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & flags) == flags)
            return i;
    throw Error("no Vulkan memory type with the needed properties on " + info_.name);
}

VkCommandBuffer Device::beginOneTime() {
    auto alloc =
        vk::init<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    alloc.commandPool = uploadPool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd;
    check(vkAllocateCommandBuffers(device_, &alloc, &cmd), "vkAllocateCommandBuffers");
    auto begin = vk::init<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
    return cmd;
}

void Device::endOneTime(VkCommandBuffer cmd) {
    check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
    auto submit = vk::init<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    check(vkQueueSubmit(queue_, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit (upload)");
    check(vkQueueWaitIdle(queue_), "vkQueueWaitIdle (upload)");
    vkFreeCommandBuffers(device_, uploadPool_, 1, &cmd);
}

} // namespace vk
