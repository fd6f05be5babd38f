// device_select.cpp - reading device capabilities and choosing a device.
#include "vk/device_select.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "vk/check.h"

namespace vk {

namespace {

// A requirement as a refusal names it, its flag in DeviceInfo, and where a device offers it:
// a feature of the chain, or, without one, the extension of that name.
struct Requirement {
    const char* name;
    bool DeviceInfo::*flag;
    VkBool32* (*feature)(FeatureChain&);
};

// Every requirement but the API version and the queue, in the order a refusal lists them:
// what queryDevice reads, missingRequirements checks and requireAll enables.
const Requirement requirements[] = {
    {"bufferDeviceAddress", &DeviceInfo::bufferDeviceAddress,
     [](FeatureChain& c) { return &c.v12.bufferDeviceAddress; }},
    {"shaderInt64", &DeviceInfo::shaderInt64,
     [](FeatureChain& c) { return &c.core.features.shaderInt64; }},
    {"shaderFloat64", &DeviceInfo::shaderFloat64,
     [](FeatureChain& c) { return &c.core.features.shaderFloat64; }},
    {"shaderBufferInt64Atomics", &DeviceInfo::shaderBufferInt64Atomics,
     [](FeatureChain& c) { return &c.v12.shaderBufferInt64Atomics; }},
    {"geometryShader", &DeviceInfo::geometryShader,
     [](FeatureChain& c) { return &c.core.features.geometryShader; }},
    {"multiDrawIndirect", &DeviceInfo::multiDrawIndirect,
     [](FeatureChain& c) { return &c.core.features.multiDrawIndirect; }},
    {"drawIndirectFirstInstance", &DeviceInfo::drawIndirectFirstInstance,
     [](FeatureChain& c) { return &c.core.features.drawIndirectFirstInstance; }},
    {"fragmentStoresAndAtomics", &DeviceInfo::fragmentStoresAndAtomics,
     [](FeatureChain& c) { return &c.core.features.fragmentStoresAndAtomics; }},
    {"independentBlend", &DeviceInfo::independentBlend,
     [](FeatureChain& c) { return &c.core.features.independentBlend; }},
    {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME, &DeviceInfo::pushDescriptor, nullptr},
    {"drawIndirectCount", &DeviceInfo::drawIndirectCount,
     [](FeatureChain& c) { return &c.v12.drawIndirectCount; }},
    {"shaderDrawParameters", &DeviceInfo::shaderDrawParameters,
     [](FeatureChain& c) { return &c.v11.shaderDrawParameters; }},
};

// Name, type, versions and limits, the driver's name (Vulkan 1.2), and the optional
// extensions.
void readProperties(VkPhysicalDevice device, DeviceInfo& info) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(device, &props);
    info.name = props.deviceName;
    info.type = props.deviceType;
    info.apiVersion = props.apiVersion;
    info.driverVersion = props.driverVersion;
    info.vendorId = props.vendorID;
    info.timestampPeriodNs = props.limits.timestampPeriod;
    info.maxDrawIndirectCount = props.limits.maxDrawIndirectCount;
    if (props.apiVersion >= VK_API_VERSION_1_2) {
        auto driver = vk::init<VkPhysicalDeviceDriverProperties>(
            VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES);
        auto props2 =
            vk::init<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2);
        props2.pNext = &driver;
        vkGetPhysicalDeviceProperties2(device, &props2);
        info.driverName = driver.driverName;
        info.driverInfo = driver.driverInfo;
    }
    info.geometryShaderPassthrough =
        hasDeviceExtension(device, VK_NV_GEOMETRY_SHADER_PASSTHROUGH_EXTENSION_NAME);
    info.pipelineCreationFeedback =
        hasDeviceExtension(device, VK_EXT_PIPELINE_CREATION_FEEDBACK_EXTENSION_NAME);
}

// The requirements, and mesh shaders. Before Vulkan 1.2 only the core features are read
// (the device is refused for its version anyway), the rest left off.
void readFeatures(VkPhysicalDevice device, DeviceInfo& info) {
    const bool vulkan12 = info.apiVersion >= VK_API_VERSION_1_2;
    FeatureChain chain(vulkan12 && hasDeviceExtension(device, VK_EXT_MESH_SHADER_EXTENSION_NAME));
    if (vulkan12)
        vkGetPhysicalDeviceFeatures2(device, &chain.core);
    else
        vkGetPhysicalDeviceFeatures(device, &chain.core.features);
    for (const Requirement& r : requirements)
        info.*r.flag =
            r.feature ? *r.feature(chain) != VK_FALSE : hasDeviceExtension(device, r.name);
    // Culling their meshlets needs task shaders.
    info.meshShader = chain.mesh.meshShader && chain.mesh.taskShader;
}

// A queue family with graphics and timestamps, UINT32_MAX if none has both.
uint32_t graphicsQueueFamily(VkPhysicalDevice device) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (uint32_t i = 0; i < count; ++i)
        if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && families[i].timestampValidBits > 0)
            return i;
    return UINT32_MAX;
}

} // namespace

bool hasDeviceExtension(VkPhysicalDevice device, const char* name) {
    const auto extensions = enumerate<VkExtensionProperties>(
        "vkEnumerateDeviceExtensionProperties", [&](uint32_t* n, VkExtensionProperties* v) {
            return vkEnumerateDeviceExtensionProperties(device, nullptr, n, v);
        });
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const auto& e) { return std::string(e.extensionName) == name; });
}

FeatureChain::FeatureChain(bool withMesh)
    : core(init<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2)),
      v12(init<VkPhysicalDeviceVulkan12Features>(
          VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES)),
      v11(init<VkPhysicalDeviceVulkan11Features>(
          VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES)),
      mesh(init<VkPhysicalDeviceMeshShaderFeaturesEXT>(
          VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MESH_SHADER_FEATURES_EXT)) {
    core.pNext = &v12;
    v12.pNext = &v11;
    if (withMesh) v11.pNext = &mesh;
}

void requireAll(FeatureChain& chain, std::vector<const char*>& extensions) {
    for (const Requirement& r : requirements)
        if (r.feature)
            *r.feature(chain) = VK_TRUE;
        else
            extensions.push_back(r.name);
}

DeviceInfo queryDevice(VkPhysicalDevice device, uint32_t index) {
    DeviceInfo info;
    info.index = index;
    info.handle = device;
    readProperties(device, info);
    readFeatures(device, info);
    info.graphicsQueueFamily = graphicsQueueFamily(device);
    return info;
}

std::vector<std::string> missingRequirements(const DeviceInfo& info) {
    std::vector<std::string> missing;
    if (info.apiVersion < VK_API_VERSION_1_2) missing.push_back("Vulkan 1.2");
    for (const Requirement& r : requirements)
        if (!(info.*r.flag)) missing.push_back(r.name);
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
