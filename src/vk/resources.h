// resources.h - buffers and images that own their device memory and free it (and its count in
// Device::liveMemory) when they go. Move-only; one allocation per resource, which is plenty
// for the few large buffers a scene needs.
#pragma once

#include <string>
#include <utility>
#include <vulkan/vulkan.h>

#include "vk/context.h"
#include "vk/handle.h"

namespace vk {

// One VkDeviceMemory, counted in Device::liveMemory() while it lives.
class Allocation {
  public:
    Allocation() = default;
    Allocation(Device& device, const VkMemoryRequirements& requirements,
               VkMemoryPropertyFlags flags, bool deviceAddress, const std::string& name);
    Allocation(Allocation&& other) noexcept { swap(other); }
    Allocation& operator=(Allocation&& other) noexcept {
        Allocation old(std::move(*this)); // freed at the end of this call
        swap(other);
        return *this;
    }
    Allocation(const Allocation&) = delete;
    Allocation& operator=(const Allocation&) = delete;
    ~Allocation();

    VkDeviceMemory get() const { return memory_; }
    VkDeviceSize bytes() const { return bytes_; }

  private:
    void swap(Allocation& other) noexcept;

    Device* device_ = nullptr;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize bytes_ = 0;
};

class Buffer {
  public:
    // Device-local unless `memoryFlags` says otherwise; host-visible memory stays mapped.
    // Buffers with SHADER_DEVICE_ADDRESS usage get their address.
    Buffer(Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
           VkMemoryPropertyFlags memoryFlags, const std::string& name);
    Buffer() = default;
    Buffer(Buffer&&) noexcept = default;
    Buffer& operator=(Buffer&&) noexcept = default;

    VkBuffer handle() const { return buffer_.get(); }
    VkDeviceSize size() const { return size_; }
    VkDeviceAddress address() const { return address_; }
    void* mapped() const { return mapped_; }
    VkDeviceSize allocated() const { return memory_.bytes(); }

  private:
    // Declared first, freed last: the buffer goes before its memory.
    Allocation memory_;
    Handle<VkBuffer> buffer_;
    VkDeviceSize size_ = 0;
    VkDeviceAddress address_ = 0;
    void* mapped_ = nullptr;
};

// A host-visible, coherent buffer (readbacks, staging).
Buffer hostBuffer(Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                  const std::string& name);

class Image {
  public:
    Image(Device& device, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
          VkImageAspectFlags aspect, const std::string& name,
          VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT);
    Image() = default;
    Image(Image&&) noexcept = default;
    Image& operator=(Image&&) noexcept = default;

    VkImage handle() const { return image_.get(); }
    VkImageView view() const { return view_.get(); }
    VkFormat format() const { return format_; }
    VkExtent2D extent() const { return extent_; }

  private:
    Allocation memory_;
    Handle<VkImage> image_;
    Handle<VkImageView> view_;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{};
};

} // namespace vk
