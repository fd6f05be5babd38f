// context.h - the Vulkan instance (with debug utils and optional validation) and the logical
// device idview renders with. Owners: the instance outlives the device.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <utility>
#include <vector>
#include <vulkan/vulkan.h>

#include "vk/debug.h"
#include "vk/device_select.h"
#include "vk/handle.h"

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

    // The instance and the messenger, destroyed in that order's reverse.
    struct Owned {
        VkInstance instance = VK_NULL_HANDLE;
        VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
        Owned() = default;
        Owned(const Owned&) = delete;
        Owned& operator=(const Owned&) = delete;
        ~Owned();
    };

    bool verbose_;
    Owned owned_;
    VkInstance instance_ = VK_NULL_HANDLE;
    DebugUtils debug_;
    std::atomic<uint32_t> validationMessages_{0};
};

// A primary command buffer of a pool, freed when it goes (or with its pool).
class CommandBuffer {
  public:
    CommandBuffer() = default;
    CommandBuffer(VkDevice device, VkCommandPool pool, VkCommandBuffer cmd)
        : device_(device), pool_(pool), cmd_(cmd) {}
    CommandBuffer(CommandBuffer&& other) noexcept
        : device_(other.device_), pool_(other.pool_),
          cmd_(std::exchange(other.cmd_, VK_NULL_HANDLE)) {}
    CommandBuffer& operator=(CommandBuffer&& other) noexcept {
        std::swap(device_, other.device_);
        std::swap(pool_, other.pool_);
        std::swap(cmd_, other.cmd_);
        return *this;
    }
    ~CommandBuffer() {
        if (cmd_) vkFreeCommandBuffers(device_, pool_, 1, &cmd_);
    }
    VkCommandBuffer get() const { return cmd_; }

  private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
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

    // Records `record` into a one-time command buffer, submits it and waits for it. Only
    // where nothing can go on before the result is there (the panel's font at start-up).
    template <typename Fn>
    void submitNow(Fn&& record) {
        CommandBuffer cmd = beginOneTime();
        record(cmd.get());
        submitAndWait(std::move(cmd));
    }

    // Uploads (vk/upload.h): a one-time command buffer to record into, then submitted
    // without waiting; `keep` (the staging memory) lives until the GPU has run it, which
    // collectFinishedUploads() notices without waiting. The queue orders the upload before
    // every later submission, and its final barrier makes the writes visible to them.
    CommandBuffer beginOneTime();
    void submitUpload(CommandBuffer cmd, std::shared_ptr<void> keep);
    void collectFinishedUploads();
    size_t uploadsInFlight() const { return uploads_.size(); }

    template <typename Handle>
    void name(VkObjectType type, Handle handle, const std::string& text) const {
        debug_.name(device_, type, handle, text.c_str());
    }

    // VK_EXT_mesh_shader's draw commands; null unless info().meshShader.
    struct MeshCommands {
        PFN_vkCmdDrawMeshTasksEXT draw = nullptr;
        PFN_vkCmdDrawMeshTasksIndirectEXT drawIndirect = nullptr;
        PFN_vkCmdDrawMeshTasksIndirectCountEXT drawIndirectCount = nullptr; // culled lists
    };
    const MeshCommands& meshCommands() const { return meshCommands_; }
    PFN_vkCmdPushDescriptorSetKHR pushDescriptorSet() const { return pushDescriptorSet_; }

  private:
    void submitAndWait(CommandBuffer cmd);
    void loadMeshCommands();

    struct Upload {
        Handle<VkFence> done;
        CommandBuffer cmd;
        std::shared_ptr<void> keep;
    };
    // The VkDevice itself, destroyed after every member below.
    struct Owned {
        VkDevice device = VK_NULL_HANDLE;
        Owned() = default;
        Owned(const Owned&) = delete;
        Owned& operator=(const Owned&) = delete;
        ~Owned();
    };

    DeviceInfo info_;
    DebugUtils debug_;
    Owned owned_;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    VkPhysicalDeviceMemoryProperties memory_{};
    MeshCommands meshCommands_;
    PFN_vkCmdPushDescriptorSetKHR pushDescriptorSet_ = nullptr;
    std::atomic<int64_t> liveAllocations_{0}, liveBytes_{0};
    Handle<VkCommandPool> uploadPool_;
    std::vector<Upload> uploads_; // submitted, not yet seen finished
};

} // namespace vk
