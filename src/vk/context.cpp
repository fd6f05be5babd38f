// context.cpp - instance, debug messenger and logical device creation.
#include "vk/context.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "vk/check.h"

namespace vk {

static bool hasLayer(const char* name) {
    const auto layers = enumerate<VkLayerProperties>(
        "vkEnumerateInstanceLayerProperties",
        [](uint32_t* n, VkLayerProperties* v) { return vkEnumerateInstanceLayerProperties(n, v); });
    return std::any_of(layers.begin(), layers.end(),
                       [&](const auto& layer) { return std::strcmp(layer.layerName, name) == 0; });
}

static bool hasInstanceExtension(const char* name) {
    const auto extensions = enumerate<VkExtensionProperties>(
        "vkEnumerateInstanceExtensionProperties", [](uint32_t* n, VkExtensionProperties* v) {
            return vkEnumerateInstanceExtensionProperties(nullptr, n, v);
        });
    return std::any_of(extensions.begin(), extensions.end(), [&](const auto& extension) {
        return std::strcmp(extension.extensionName, name) == 0;
    });
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
    faultPoint("vkCreateInstance");
    VkResult created = vkCreateInstance(&info, nullptr, &owned_.instance);
    if (created == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw Error("no Vulkan device found: the loader found no driver (Debian: "
                    "mesa-vulkan-drivers for the CPU device, or your GPU vendor's driver)");
    check(created, "vkCreateInstance");
    instance_ = owned_.instance;

    if (debugUtils) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        check(create(instance_, &messenger, nullptr, &owned_.messenger),
              "vkCreateDebugUtilsMessengerEXT");
        debug_.load(instance_);
    }
}

Instance::~Instance() = default;

Instance::Owned::~Owned() {
    if (messenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(instance, messenger, nullptr);
    }
    if (instance) vkDestroyInstance(instance, nullptr);
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
    const auto handles = enumerate<VkPhysicalDevice>(
        "vkEnumeratePhysicalDevices", [&](uint32_t* n, VkPhysicalDevice* v) {
            return vkEnumeratePhysicalDevices(instance_, n, v);
        });
    std::vector<DeviceInfo> infos;
    for (uint32_t i = 0; i < handles.size(); ++i) infos.push_back(queryDevice(handles[i], i));
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

    // What missingRequirements checked, then what the device offers beyond it.
    FeatureChain features(info.meshShader);
    std::vector<const char*> extensions = extraExtensions;
    requireAll(features, extensions);
    if (info.geometryShaderPassthrough)
        extensions.push_back(VK_NV_GEOMETRY_SHADER_PASSTHROUGH_EXTENSION_NAME);
    if (info.pipelineCreationFeedback)
        extensions.push_back(VK_EXT_PIPELINE_CREATION_FEEDBACK_EXTENSION_NAME);
    // Mesh shaders, and task shaders for culling their meshlets (shaders/scene.task).
    if (info.meshShader) {
        features.mesh.meshShader = VK_TRUE;
        features.mesh.taskShader = VK_TRUE;
        extensions.push_back(VK_EXT_MESH_SHADER_EXTENSION_NAME);
    }
    auto create = vk::init<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
    create.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    create.ppEnabledExtensionNames = extensions.data();
    create.pNext = &features.core;
    create.queueCreateInfoCount = 1;
    create.pQueueCreateInfos = &queue;
    faultPoint("vkCreateDevice");
    check(vkCreateDevice(info.handle, &create, nullptr, &owned_.device), "vkCreateDevice");
    device_ = owned_.device;
    vkGetDeviceQueue(device_, info.graphicsQueueFamily, 0, &queue_);
    vkGetPhysicalDeviceMemoryProperties(info.handle, &memory_);
    if (info.meshShader) loadMeshCommands();
    pushDescriptorSet_ = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
        vkGetDeviceProcAddr(device_, "vkCmdPushDescriptorSetKHR"));
    if (!pushDescriptorSet_)
        throw Error("the driver offers VK_KHR_push_descriptor but not vkCmdPushDescriptorSetKHR");

    auto pool = vk::init<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    pool.queueFamilyIndex = info.graphicsQueueFamily;
    uploadPool_ = make(*this, vkCreateCommandPool, pool, "upload pool");
    name(VK_OBJECT_TYPE_QUEUE, queue_, "graphics queue");
}

void Device::loadMeshCommands() {
    meshCommands_.draw = reinterpret_cast<PFN_vkCmdDrawMeshTasksEXT>(
        vkGetDeviceProcAddr(device_, "vkCmdDrawMeshTasksEXT"));
    meshCommands_.drawIndirect = reinterpret_cast<PFN_vkCmdDrawMeshTasksIndirectEXT>(
        vkGetDeviceProcAddr(device_, "vkCmdDrawMeshTasksIndirectEXT"));
    meshCommands_.drawIndirectCount = reinterpret_cast<PFN_vkCmdDrawMeshTasksIndirectCountEXT>(
        vkGetDeviceProcAddr(device_, "vkCmdDrawMeshTasksIndirectCountEXT"));
    if (!meshCommands_.draw || !meshCommands_.drawIndirect || !meshCommands_.drawIndirectCount)
        throw Error("the driver offers VK_EXT_mesh_shader but not its draw commands");
}

Device::~Device() {
    // Teardown: nothing may be in flight when the device goes (members go after this, the
    // uploads' staging memory first). A failure here cannot be acted on.
    vkDeviceWaitIdle(device_);
}

Device::Owned::~Owned() {
    if (device) vkDestroyDevice(device, nullptr);
}

VkDevice rawDevice(const Device& device) {
    return device.handle();
}

void nameObject(const Device& device, VkObjectType type, uint64_t handle, const std::string& name) {
    device.debug().name(device.handle(), type, handle, name.c_str());
}

uint32_t Device::memoryType(uint32_t typeBits, VkMemoryPropertyFlags flags) const {
    for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & flags) == flags)
            return i;
    throw Error("no Vulkan memory type with the needed properties on " + info_.name);
}

CommandBuffer Device::beginOneTime() {
    auto alloc =
        vk::init<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    alloc.commandPool = uploadPool_.get();
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer handle;
    check(vkAllocateCommandBuffers(device_, &alloc, &handle), "vkAllocateCommandBuffers");
    CommandBuffer cmd(device_, uploadPool_.get(), handle);
    auto begin = vk::init<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(handle, &begin), "vkBeginCommandBuffer");
    return cmd;
}

void Device::submitUpload(CommandBuffer cmd, std::shared_ptr<void> keep) {
    collectFinishedUploads();
    check(vkEndCommandBuffer(cmd.get()), "vkEndCommandBuffer (upload)");
    Upload upload{make(*this, vkCreateFence,
                       vk::init<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO),
                       "upload done"),
                  std::move(cmd), std::move(keep)};
    faultPoint("vkQueueSubmit (upload)");
    const VkCommandBuffer handle = upload.cmd.get();
    auto submit = vk::init<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &handle;
    check(vkQueueSubmit(queue_, 1, &submit, upload.done.get()), "vkQueueSubmit (upload)");
    uploads_.push_back(std::move(upload));
}

void Device::collectFinishedUploads() {
    std::erase_if(uploads_, [&](const Upload& upload) {
        const VkResult status = vkGetFenceStatus(device_, upload.done.get());
        if (status == VK_NOT_READY) return false;
        check(status, "vkGetFenceStatus (upload)");
        return true; // fence, command buffer and staging memory go with the entry
    });
}

void Device::submitAndWait(CommandBuffer cmd) {
    submitUpload(std::move(cmd), nullptr);
    const VkFence fence = uploads_.back().done.get();
    check(vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX), "waiting for an upload");
    collectFinishedUploads();
}

} // namespace vk
