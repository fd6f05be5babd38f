// resources.h - buffers and images as plain structs with explicit create/destroy pairs; the
// class that creates one owns it and destroys it.
#pragma once

#include <string>
#include <vulkan/vulkan.h>

#include "vk/context.h"

namespace vk {

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    VkDeviceAddress address = 0; // when created with SHADER_DEVICE_ADDRESS usage
    void* mapped = nullptr;      // when host-visible: persistently mapped
    VkDeviceSize allocated = 0;  // bytes of `memory`
};

// Device-local unless `memoryFlags` says otherwise. Buffers with SHADER_DEVICE_ADDRESS usage
// get their address filled in.
Buffer createBuffer(Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                    VkMemoryPropertyFlags memoryFlags, const std::string& name);
void destroyBuffer(Device& device, Buffer& buffer);

// Device-local buffer filled from `data` through a staging buffer (waits for the copy).
Buffer createBufferWithData(Device& device, const void* data, VkDeviceSize size,
                            VkBufferUsageFlags usage, const std::string& name);

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{};
    VkDeviceSize allocated = 0; // bytes of `memory`
};

Image createImage2D(Device& device, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                    VkImageAspectFlags aspect, const std::string& name,
                    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT);
void destroyImage(Device& device, Image& image);

} // namespace vk
