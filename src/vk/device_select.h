// device_select.h - what idview needs from a Vulkan device, and which device it takes.
// The checks are plain functions over DeviceInfo so they are unit-tested without a GPU.
#pragma once

#include <cstdint>
#include <string>
#include <vector>
#include <vulkan/vulkan.h>

namespace vk {

// What idview reads off a physical device to decide whether, and how well, it can run there.
struct DeviceInfo {
    uint32_t index = 0;
    VkPhysicalDevice handle = VK_NULL_HANDLE;
    std::string name;
    VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
    uint32_t apiVersion = 0;
    std::string driverName; // from VkPhysicalDeviceDriverProperties; empty before Vulkan 1.2
    std::string driverInfo;
    uint32_t driverVersion = 0;
    uint32_t vendorId = 0;

    // Requirements, one flag each so the refusal can name every missing one.
    bool bufferDeviceAddress = false;
    bool shaderInt64 = false;
    bool shaderFloat64 = false; // animate.comp places objects relative to the eye in double
    bool shaderBufferInt64Atomics = false;
    bool geometryShader = false;
    bool multiDrawIndirect = false;
    bool drawIndirectFirstInstance = false;
    bool fragmentStoresAndAtomics = false;
    bool independentBlend = false;  // no-id pipelines mask the ID attachment
    bool pushDescriptor = false;    // VK_KHR_push_descriptor: the passes over the ID image
    bool drawIndirectCount = false; // culled draw lists draw by a count the GPU wrote
    // gl_DrawID: culled lists of cluster runs, and the mesh techniques' mdi modes
    bool shaderDrawParameters = false;
    // A queue family with graphics and timestamps; UINT32_MAX if there is none.
    uint32_t graphicsQueueFamily = UINT32_MAX;
    float timestampPeriodNs = 0.0f;

    // Optional, used when present.
    bool geometryShaderPassthrough = false; // VK_NV_geometry_shader_passthrough
    // VK_EXT_pipeline_creation_feedback: whether a pipeline came from the pipeline cache
    bool pipelineCreationFeedback = false;
    // VK_EXT_mesh_shader with its meshShader and taskShader features (mesh-*)
    bool meshShader = false;
    uint32_t maxDrawIndirectCount = 1;
};

bool hasDeviceExtension(VkPhysicalDevice device, const char* name);

// The feature structs idview reads from a device and enables on it, chained as Vulkan takes
// them: core, then Vulkan 1.2's, 1.1's and, where the device has them, mesh shaders'. Not
// copyable: each points at the next.
struct FeatureChain {
    VkPhysicalDeviceFeatures2 core;
    VkPhysicalDeviceVulkan12Features v12;
    VkPhysicalDeviceVulkan11Features v11;
    VkPhysicalDeviceMeshShaderFeaturesEXT mesh;

    explicit FeatureChain(bool withMesh);
    FeatureChain(const FeatureChain&) = delete;
    FeatureChain& operator=(const FeatureChain&) = delete;
};

// For vkCreateDevice: every required feature (those missingRequirements names) set in
// `chain`, every required extension added to `extensions`.
void requireAll(FeatureChain& chain, std::vector<const char*>& extensions);

// Reads everything above from the driver.
DeviceInfo queryDevice(VkPhysicalDevice device, uint32_t index);

// Names of every requirement the device misses ("Vulkan 1.2", "shaderInt64", ...).
std::vector<std::string> missingRequirements(const DeviceInfo& info);

// "discrete GPU", "CPU", ...
const char* deviceTypeName(VkPhysicalDeviceType type);
std::string versionString(uint32_t apiVersion);
std::string driverVersionString(const DeviceInfo& info);

// One line for --list-devices: index, name, type, driver and API version.
std::string describeDevice(const DeviceInfo& info);

// Picks the device to use. An empty request takes the best suitable device (discrete GPU,
// then integrated, virtual, CPU). A request of digits is an index; anything else is a
// case-insensitive substring of the name. Throws vk::Error with one line naming the reason
// (no device, no match, or each missing requirement).
const DeviceInfo& chooseDevice(const std::vector<DeviceInfo>& devices, const std::string& request);

} // namespace vk
