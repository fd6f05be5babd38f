// device_select.cpp - reading device capabilities and choosing a device.
#include "vk/device_select.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "vk/check.h"

namespace vk {

bool hasDeviceExtension(VkPhysicalDevice device, const char* name) {
    const auto extensions = enumerate<VkExtensionProperties>(
        "vkEnumerateDeviceExtensionProperties", [&](uint32_t* n, VkExtensionProperties* v) {
            return vkEnumerateDeviceExtensionProperties(device, nullptr, n, v);
        });
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const auto& e) { return std::string(e.extensionName) == name; });
}

DeviceInfo queryDevice(VkPhysicalDevice device, uint32_t index) {
    DeviceInfo info;
    info.index = index;
    info.handle = device;

    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(device, &props);
    info.name = props.deviceName;
    info.type = props.deviceType;
    info.apiVersion = props.apiVersion;
    info.driverVersion = props.driverVersion;
    info.vendorId = props.vendorID;
    info.timestampPeriodNs = props.limits.timestampPeriod;
    info.maxDrawIndirectCount = props.limits.maxDrawIndirectCount;

    info.pushDescriptor = hasDeviceExtension(device, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME);
    info.geometryShaderPassthrough =
        hasDeviceExtension(device, VK_NV_GEOMETRY_SHADER_PASSTHROUGH_EXTENSION_NAME);
    info.pipelineCreationFeedback =
        hasDeviceExtension(device, VK_EXT_PIPELINE_CREATION_FEEDBACK_EXTENSION_NAME);

    const bool vulkan12 = props.apiVersion >= VK_API_VERSION_1_2;
    if (vulkan12) {
        auto driver = vk::init<VkPhysicalDeviceDriverProperties>(
            VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES);
        auto props2 =
            vk::init<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2);
        props2.pNext = &driver;
        vkGetPhysicalDeviceProperties2(device, &props2);
        info.driverName = driver.driverName;
        info.driverInfo = driver.driverInfo;

        auto f11 = vk::init<VkPhysicalDeviceVulkan11Features>(
            VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES);
        auto f12 = vk::init<VkPhysicalDeviceVulkan12Features>(
            VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES);
        f12.pNext = &f11;
        auto f2 = vk::init<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
        f2.pNext = &f12;
        vkGetPhysicalDeviceFeatures2(device, &f2);
        info.bufferDeviceAddress = f12.bufferDeviceAddress;
        info.shaderBufferInt64Atomics = f12.shaderBufferInt64Atomics;
        info.drawIndirectCount = f12.drawIndirectCount;
        info.shaderDrawParameters = f11.shaderDrawParameters;

        if (hasDeviceExtension(device, VK_EXT_MESH_SHADER_EXTENSION_NAME)) {
            auto mesh = vk::init<VkPhysicalDeviceMeshShaderFeaturesEXT>(
                VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MESH_SHADER_FEATURES_EXT);
            auto meshFeatures =
                vk::init<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
            meshFeatures.pNext = &mesh;
            vkGetPhysicalDeviceFeatures2(device, &meshFeatures);
            // Culling their meshlets needs task shaders.
            info.meshShader = mesh.meshShader && mesh.taskShader;
        }
    }
    VkPhysicalDeviceFeatures features;
    vkGetPhysicalDeviceFeatures(device, &features);
    info.shaderInt64 = features.shaderInt64;
    info.shaderFloat64 = features.shaderFloat64;
    info.geometryShader = features.geometryShader;
    info.multiDrawIndirect = features.multiDrawIndirect;
    info.drawIndirectFirstInstance = features.drawIndirectFirstInstance;
    info.fragmentStoresAndAtomics = features.fragmentStoresAndAtomics;
    info.independentBlend = features.independentBlend;

    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (uint32_t i = 0; i < count; ++i) {
        if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) &&
            families[i].timestampValidBits > 0) {
            info.graphicsQueueFamily = i;
            break;
        }
    }
    return info;
}

std::vector<std::string> missingRequirements(const DeviceInfo& info) {
    std::vector<std::string> missing;
    if (info.apiVersion < VK_API_VERSION_1_2) missing.push_back("Vulkan 1.2");
    if (!info.bufferDeviceAddress) missing.push_back("bufferDeviceAddress");
    if (!info.shaderInt64) missing.push_back("shaderInt64");
    if (!info.shaderFloat64) missing.push_back("shaderFloat64");
    if (!info.shaderBufferInt64Atomics) missing.push_back("shaderBufferInt64Atomics");
    if (!info.geometryShader) missing.push_back("geometryShader");
    if (!info.multiDrawIndirect) missing.push_back("multiDrawIndirect");
    if (!info.drawIndirectFirstInstance) missing.push_back("drawIndirectFirstInstance");
    if (!info.fragmentStoresAndAtomics) missing.push_back("fragmentStoresAndAtomics");
    if (!info.independentBlend) missing.push_back("independentBlend");
    if (!info.pushDescriptor) missing.push_back("VK_KHR_push_descriptor");
    if (!info.drawIndirectCount) missing.push_back("drawIndirectCount");
    if (!info.shaderDrawParameters) missing.push_back("shaderDrawParameters");
    if (info.graphicsQueueFamily == UINT32_MAX)
        missing.push_back("a graphics queue with timestamps");
    return missing;
}

const char* deviceTypeName(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return "CPU";
    default:
        return "other";
    }
}

std::string versionString(uint32_t v) {
    return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) +
           "." + std::to_string(VK_API_VERSION_PATCH(v));
}

std::string driverVersionString(const DeviceInfo& info) {
    uint32_t v = info.driverVersion;
    char text[64];
    if (info.vendorId == 0x10DE) { // NVIDIA packs 10.8.8.6 bits
        std::snprintf(text, sizeof text, "%u.%u.%u", v >> 22, (v >> 14) & 0xFF, (v >> 6) & 0xFF);
    } else {
        std::snprintf(text, sizeof text, "%u.%u.%u", VK_API_VERSION_MAJOR(v),
                      VK_API_VERSION_MINOR(v), VK_API_VERSION_PATCH(v));
    }
    return text;
}

std::string describeDevice(const DeviceInfo& info) {
    std::string driver = info.driverName.empty() ? "unknown driver" : info.driverName;
    if (!info.driverInfo.empty()) driver += " " + info.driverInfo;
    return std::to_string(info.index) + ": " + info.name + " | " + deviceTypeName(info.type) +
           " | driver " + driver + " (" + driverVersionString(info) + ") | Vulkan " +
           versionString(info.apiVersion);
}

static int typeRank(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return 3;
    default:
        return 4;
    }
}

static std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

static std::string joined(const std::vector<std::string>& items) {
    std::string text;
    for (const auto& item : items) text += (text.empty() ? "" : ", ") + item;
    return text;
}

static const DeviceInfo& requireSuitable(const DeviceInfo& info) {
    auto missing = missingRequirements(info);
    if (!missing.empty())
        throw Error("device " + std::to_string(info.index) + " '" + info.name +
                    "' cannot run idview: missing " + joined(missing));
    return info;
}

const DeviceInfo& chooseDevice(const std::vector<DeviceInfo>& devices, const std::string& request) {
    if (devices.empty())
        throw Error("no Vulkan device found (is a Vulkan driver installed? Debian: "
                    "mesa-vulkan-drivers for the CPU device, or your GPU vendor's driver)");
    if (!request.empty()) {
        const bool isIndex = std::all_of(request.begin(), request.end(),
                                         [](unsigned char c) { return std::isdigit(c); });
        if (isIndex) {
            unsigned long index = std::stoul(request);
            if (index >= devices.size())
                throw Error("--device " + request + ": there are only " +
                            std::to_string(devices.size()) +
                            " Vulkan devices (see --list-devices)");
            return requireSuitable(devices[index]);
        }
        for (const auto& info : devices)
            if (lower(info.name).find(lower(request)) != std::string::npos)
                return requireSuitable(info);
        throw Error("--device " + request +
                    ": no Vulkan device name contains it (see --list-devices)");
    }
    const DeviceInfo* best = nullptr;
    std::vector<std::string> refusals;
    for (const auto& info : devices) {
        auto missing = missingRequirements(info);
        if (!missing.empty()) {
            refusals.push_back("'" + info.name + "' misses " + joined(missing));
            continue;
        }
        if (!best || typeRank(info.type) < typeRank(best->type)) best = &info;
    }
    if (!best) {
        std::string text;
        for (const auto& r : refusals) text += (text.empty() ? "" : "; ") + r;
        throw Error("no Vulkan device can run idview: " + text);
    }
    return *best;
}

} // namespace vk
