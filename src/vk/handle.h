// handle.h - Vulkan objects that free themselves: Handle<T> owns one object of a device and
// destroys it when it goes, and make() creates one (fault point, checked result, debug name).
// Move-only, so ownership is always visible in a type; an object that GPU work in flight may
// still use is handed to that frame slot rather than destroyed (render/frame_slots.h).
#pragma once

#include <string>
#include <utility>
#include <vulkan/vulkan.h>

#include "vk/check.h"

namespace vk {

// The vkDestroy* of each handle type idview owns; VkDeviceMemory lives in vk::Allocation.
inline void destroy(VkDevice d, VkBuffer h) {
    vkDestroyBuffer(d, h, nullptr);
}
inline void destroy(VkDevice d, VkImage h) {
    vkDestroyImage(d, h, nullptr);
}
inline void destroy(VkDevice d, VkImageView h) {
    vkDestroyImageView(d, h, nullptr);
}
inline void destroy(VkDevice d, VkPipeline h) {
    vkDestroyPipeline(d, h, nullptr);
}
inline void destroy(VkDevice d, VkPipelineLayout h) {
    vkDestroyPipelineLayout(d, h, nullptr);
}
inline void destroy(VkDevice d, VkPipelineCache h) {
    vkDestroyPipelineCache(d, h, nullptr);
}
inline void destroy(VkDevice d, VkShaderModule h) {
    vkDestroyShaderModule(d, h, nullptr);
}
inline void destroy(VkDevice d, VkDescriptorSetLayout h) {
    vkDestroyDescriptorSetLayout(d, h, nullptr);
}
inline void destroy(VkDevice d, VkRenderPass h) {
    vkDestroyRenderPass(d, h, nullptr);
}
inline void destroy(VkDevice d, VkFramebuffer h) {
    vkDestroyFramebuffer(d, h, nullptr);
}
inline void destroy(VkDevice d, VkFence h) {
    vkDestroyFence(d, h, nullptr);
}
inline void destroy(VkDevice d, VkSemaphore h) {
    vkDestroySemaphore(d, h, nullptr);
}
inline void destroy(VkDevice d, VkCommandPool h) {
    vkDestroyCommandPool(d, h, nullptr);
}
inline void destroy(VkDevice d, VkQueryPool h) {
    vkDestroyQueryPool(d, h, nullptr);
}
inline void destroy(VkDevice d, VkDescriptorPool h) {
    vkDestroyDescriptorPool(d, h, nullptr);
}
inline void destroy(VkDevice d, VkSwapchainKHR h) {
    vkDestroySwapchainKHR(d, h, nullptr);
}
inline void destroy(VkDevice d, VkSampler h) {
    vkDestroySampler(d, h, nullptr);
}

template <typename T>
class Handle {
  public:
    Handle() = default;
    Handle(VkDevice device, T handle) : device_(device), handle_(handle) {}
    Handle(Handle&& other) noexcept
        : device_(other.device_), handle_(std::exchange(other.handle_, VK_NULL_HANDLE)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            device_ = other.device_;
            handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    ~Handle() { reset(); }

    T get() const { return handle_; }
    explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }
    void reset() {
        if (handle_) destroy(device_, handle_);
        handle_ = VK_NULL_HANDLE;
    }

  private:
    VkDevice device_ = VK_NULL_HANDLE;
    T handle_ = VK_NULL_HANDLE;
};

// The VkObjectType of a handle type, for debug names.
template <typename T>
constexpr VkObjectType objectType();
#define IDV_OBJECT_TYPE(T, E)                                                                      \
    template <>                                                                                    \
    constexpr VkObjectType objectType<T>() {                                                       \
        return E;                                                                                  \
    }
IDV_OBJECT_TYPE(VkBuffer, VK_OBJECT_TYPE_BUFFER)
IDV_OBJECT_TYPE(VkImage, VK_OBJECT_TYPE_IMAGE)
IDV_OBJECT_TYPE(VkImageView, VK_OBJECT_TYPE_IMAGE_VIEW)
IDV_OBJECT_TYPE(VkPipelineLayout, VK_OBJECT_TYPE_PIPELINE_LAYOUT)
IDV_OBJECT_TYPE(VkPipelineCache, VK_OBJECT_TYPE_PIPELINE_CACHE)
IDV_OBJECT_TYPE(VkShaderModule, VK_OBJECT_TYPE_SHADER_MODULE)
IDV_OBJECT_TYPE(VkRenderPass, VK_OBJECT_TYPE_RENDER_PASS)
IDV_OBJECT_TYPE(VkFramebuffer, VK_OBJECT_TYPE_FRAMEBUFFER)
IDV_OBJECT_TYPE(VkSampler, VK_OBJECT_TYPE_SAMPLER)
IDV_OBJECT_TYPE(VkFence, VK_OBJECT_TYPE_FENCE)
IDV_OBJECT_TYPE(VkSemaphore, VK_OBJECT_TYPE_SEMAPHORE)
IDV_OBJECT_TYPE(VkCommandPool, VK_OBJECT_TYPE_COMMAND_POOL)
IDV_OBJECT_TYPE(VkQueryPool, VK_OBJECT_TYPE_QUERY_POOL)
IDV_OBJECT_TYPE(VkDescriptorPool, VK_OBJECT_TYPE_DESCRIPTOR_POOL)
IDV_OBJECT_TYPE(VkDescriptorSetLayout, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT)
IDV_OBJECT_TYPE(VkPipeline, VK_OBJECT_TYPE_PIPELINE)
IDV_OBJECT_TYPE(VkSwapchainKHR, VK_OBJECT_TYPE_SWAPCHAIN_KHR)
#undef IDV_OBJECT_TYPE

class Device;
// Defined in context.cpp, where Device is complete.
VkDevice rawDevice(const Device& device);
void nameObject(const Device& device, VkObjectType type, uint64_t handle, const std::string& name);

// Creates an object with vkCreate*(device, &info, nullptr, &handle), the signature almost
// every Vulkan object shares, and gives it the debug name `name`, which is also what an error
// message calls it.
template <typename T, typename Info>
Handle<T> make(const Device& device,
               VkResult(VKAPI_PTR* create)(VkDevice, const Info*, const VkAllocationCallbacks*, T*),
               const Info& info, const std::string& name) {
    faultPoint(name.c_str());
    T handle = VK_NULL_HANDLE;
    const VkResult result = create(rawDevice(device), &info, nullptr, &handle);
    if (result != VK_SUCCESS) check(result, ("creating '" + name + "'").c_str());
    Handle<T> owned(rawDevice(device), handle);
    nameObject(device, objectType<T>(), reinterpret_cast<uint64_t>(handle), name);
    return owned;
}

} // namespace vk
