// test_device_select.cpp - requirement checks and device choice on synthetic devices, so the
// refusal paths are tested without owning a device that lacks features.
#include <gtest/gtest.h>

#include "vk/check.h"
#include "vk/device_select.h"

namespace {

vk::DeviceInfo capable(uint32_t index, const char* name, VkPhysicalDeviceType type) {
    vk::DeviceInfo d;
    d.index = index;
    d.name = name;
    d.type = type;
    d.apiVersion = VK_API_VERSION_1_3;
    d.bufferDeviceAddress = d.shaderInt64 = d.shaderFloat64 = d.shaderBufferInt64Atomics =
        d.geometryShader = true;
    d.multiDrawIndirect = d.drawIndirectFirstInstance = d.fragmentStoresAndAtomics =
        d.independentBlend = true;
    d.pushDescriptor = d.drawIndirectCount = d.shaderDrawParameters = true;
    d.graphicsQueueFamily = 0;
    return d;
}

std::string errorOf(const std::vector<vk::DeviceInfo>& devices, const std::string& request) {
    try {
        vk::chooseDevice(devices, request);
    } catch (const vk::Error& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(DeviceSelect, CapableDeviceMissesNothing) {
    EXPECT_TRUE(
        vk::missingRequirements(capable(0, "gpu", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU)).empty());
}

TEST(DeviceSelect, NamesEveryMissingRequirement) {
    vk::DeviceInfo d = capable(0, "old", VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU);
    d.apiVersion = VK_API_VERSION_1_1;
    d.shaderInt64 = false;
    d.shaderFloat64 = false;
    d.geometryShader = false;
    d.drawIndirectCount = false;
    d.shaderDrawParameters = false;
    d.graphicsQueueFamily = UINT32_MAX;
    auto missing = vk::missingRequirements(d);
    ASSERT_EQ(missing.size(), 7u);
    EXPECT_EQ(missing[0], "Vulkan 1.2");
    EXPECT_EQ(missing[1], "shaderInt64");
    EXPECT_EQ(missing[2], "shaderFloat64");
    EXPECT_EQ(missing[3], "geometryShader");
    EXPECT_EQ(missing[4], "drawIndirectCount");
    EXPECT_EQ(missing[5], "shaderDrawParameters");
    EXPECT_EQ(missing[6], "a graphics queue with timestamps");

    vk::DeviceInfo none;
    EXPECT_EQ(vk::missingRequirements(none).size(), 14u);
}

TEST(DeviceSelect, PrefersDiscreteThenIntegratedThenCpu) {
    std::vector<vk::DeviceInfo> devices = {
        capable(0, "llvmpipe", VK_PHYSICAL_DEVICE_TYPE_CPU),
        capable(1, "Intel", VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU),
        capable(2, "NVIDIA H100", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU)};
    EXPECT_EQ(vk::chooseDevice(devices, "").index, 2u);
    devices[2].geometryShader = false; // an unsuitable discrete GPU is skipped
    EXPECT_EQ(vk::chooseDevice(devices, "").index, 1u);
    devices.erase(devices.begin() + 1);
    EXPECT_EQ(vk::chooseDevice(devices, "").index, 0u); // the CPU device is selectable
}

TEST(DeviceSelect, ByIndexOrCaseInsensitiveName) {
    std::vector<vk::DeviceInfo> devices = {
        capable(0, "NVIDIA H100", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU),
        capable(1, "llvmpipe (LLVM 15)", VK_PHYSICAL_DEVICE_TYPE_CPU)};
    EXPECT_EQ(vk::chooseDevice(devices, "1").index, 1u);
    EXPECT_EQ(vk::chooseDevice(devices, "LLVMPIPE").index, 1u);
    EXPECT_EQ(vk::chooseDevice(devices, "h100").index, 0u);
}

TEST(DeviceSelect, RefusalsSayWhy) {
    std::vector<vk::DeviceInfo> devices = {capable(0, "llvmpipe", VK_PHYSICAL_DEVICE_TYPE_CPU)};
    EXPECT_NE(errorOf(devices, "3").find("only 1 Vulkan devices"), std::string::npos);
    EXPECT_NE(errorOf(devices, "radeon").find("no Vulkan device name contains it"),
              std::string::npos);
    EXPECT_NE(errorOf({}, "").find("no Vulkan device found"), std::string::npos);

    devices[0].shaderBufferInt64Atomics = false;
    devices[0].multiDrawIndirect = false;
    const std::string chosen = errorOf(devices, "0");
    EXPECT_NE(chosen.find("'llvmpipe' cannot run idview: missing shaderBufferInt64Atomics, "
                          "multiDrawIndirect"),
              std::string::npos)
        << chosen;
    const std::string automatic = errorOf(devices, "");
    EXPECT_NE(automatic.find("no Vulkan device can run idview: 'llvmpipe' misses "
                             "shaderBufferInt64Atomics, multiDrawIndirect"),
              std::string::npos)
        << automatic;
    EXPECT_EQ(automatic.find('\n'), std::string::npos); // one line
}

TEST(DeviceSelect, DescriptionHasIndexNameTypeDriverAndApi) {
    vk::DeviceInfo d = capable(3, "llvmpipe", VK_PHYSICAL_DEVICE_TYPE_CPU);
    d.driverName = "llvmpipe";
    d.driverInfo = "Mesa 22.3.6";
    const std::string text = vk::describeDevice(d);
    EXPECT_EQ(text.rfind("3: llvmpipe | CPU | driver llvmpipe Mesa 22.3.6", 0), 0u) << text;
    EXPECT_NE(text.find("Vulkan 1.3.0"), std::string::npos) << text;
}
