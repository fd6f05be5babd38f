// context.h - the Vulkan instance (with debug utils and optional validation) and the logical
// device idview renders with. Owners: the instance outlives the device.
#pragma once

#include <atomic>
#include <string>
#include <vector>
#include <vulkan/vulkan.h>

#include "vk/debug.h"
#include "vk/device_select.h"

namespace vk {

struct InstanceOptions {
    bool validation = false;
    std::vector<const char*> extensions; // e.g. surface extensions; empty when headless
    // With validation: also the layer's synchronization validation (hazards between
    // commands, across frames and queue submissions), through VK_EXT_validation_features.
    bool syncValidation = false;
};

class Instance {
  public:
    explicit Instance(const InstanceOptions& options);
    ~Instance();
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    VkInstance handle() const { return instance_; }
    const DebugUtils& debug() const { return debug_; }
    std::vector<DeviceInfo> devices() const;

    // Validation-layer warnings and errors seen so far; the tests require zero.
    uint32_t validationMessages() const { return validationMessages_.load(); }

  private:
    static VkBool32 VKAPI_PTR onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                        VkDebugUtilsMessageTypeFlagsEXT types,
                                        const VkDebugUtilsMessengerCallbackDataEXT* data,
                                        void* user);

    bool verbose_;
    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    DebugUtils debug_;
    std::atomic<uint32_t> validationMessages_{0};
};

class Device {
  public:
    // Creates the logical device on `info` (already chosen and checked) with every feature
    // idview needs enabled. `extraExtensions` are enabled too (the window adds
    // VK_KHR_swapchain; headless rendering needs none).
    Device(const Instance& instance, const DeviceInfo& info,
           const std::vector<const char*>& extraExtensions = {});
    ~Device();
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;

    VkDevice handle() const { return device_; }
    VkPhysicalDevice physical() const { return info_.handle; }
    const DeviceInfo& info() const { return info_; }
    const DebugUtils& debug() const { return debug_; }
    VkQueue queue() const { return queue_; }
    uint32_t queueFamily() const { return info_.graphicsQueueFamily; }
    const VkPhysicalDeviceMemoryProperties& memory() const { return memory_; }

    // Index of a memory type in `typeBits` with all of `flags`; throws if there is none.
    uint32_t memoryType(uint32_t typeBits, VkMemoryPropertyFlags flags) const;

    // Device memory idview holds right now (vk/resources.cpp keeps these up to date), for
    // the leak checks and the viewer's panel.
    struct LiveMemory {
        int64_t allocations = 0;
        int64_t bytes = 0;
    };
    LiveMemory liveMemory() const { return {liveAllocations_.load(), liveBytes_.load()}; }
    void countAllocation(int64_t bytes, int sign) {
        liveAllocations_ += sign;
        liveBytes_ += sign * bytes;
    }

    // Records `record` into a one-time command buffer, submits it and waits. For uploads at
    // scene load, never on the per-frame path.
    template <typename Fn>
    void submitNow(Fn&& record) {
        VkCommandBuffer cmd = beginOneTime();
        record(cmd);
        endOneTime(cmd);
    }

    template <typename Handle>
    void name(VkObjectType type, Handle handle, const std::string& text) const {
        debug_.name(device_, type, handle, text.c_str());
    }

  private:
    VkCommandBuffer beginOneTime();
    void endOneTime(VkCommandBuffer cmd);

    DeviceInfo info_;
    DebugUtils debug_;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    VkCommandPool uploadPool_ = VK_NULL_HANDLE;
    VkPhysicalDeviceMemoryProperties memory_{};
    std::atomic<int64_t> liveAllocations_{0}, liveBytes_{0};
};

} // namespace vk
