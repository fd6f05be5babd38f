// resources.cpp - buffer and image creation; one device memory allocation per resource,
// which is plenty for the few large buffers a scene needs.
#include "vk/resources.h"

#include <cstring>
#include <string>

#include "vk/check.h"

namespace vk {

static std::string mebibytes(VkDeviceSize bytes) {
    return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB";
}

// Too large for the memory heap at all: say so in words instead of letting the driver fail
// (or the validation layer object). Out of memory at allocation: the same, with the cause.
static VkDeviceMemory allocate(Device& device, const VkMemoryRequirements& requirements,
                               VkMemoryPropertyFlags flags, bool deviceAddress,
                               const std::string& name) {
    const uint32_t type = device.memoryType(requirements.memoryTypeBits, flags);
    const VkMemoryHeap& heap =
        device.memory().memoryHeaps[device.memory().memoryTypes[type].heapIndex];
    const std::string where = (heap.flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) ? "GPU" : "host";
    if (requirements.size > heap.size)
        throw Error("out of " + where + " memory: '" + name + "' needs " +
                    mebibytes(requirements.size) + " but " + device.info().name + " has " +
                    mebibytes(heap.size) + " in that heap; try fewer --copies or a smaller model");
    auto flagsInfo =
        vk::init<VkMemoryAllocateFlagsInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO);
    flagsInfo.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
    auto info = vk::init<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    info.pNext = deviceAddress ? &flagsInfo : nullptr;
    info.allocationSize = requirements.size;
    info.memoryTypeIndex = type;
    VkDeviceMemory memory;
    const VkResult result = vkAllocateMemory(device.handle(), &info, nullptr, &memory);
    if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
        throw Error("out of " + where + " memory allocating " + mebibytes(requirements.size) +
                    " for '" + name + "' (idview holds " +
                    mebibytes(VkDeviceSize(device.liveMemory().bytes)) +
                    "); try fewer --copies or a smaller model");
    check(result, "vkAllocateMemory");
    device.countAllocation(int64_t(requirements.size), +1);
    return memory;
}

Buffer createBuffer(Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                    VkMemoryPropertyFlags memoryFlags, const std::string& name) {
    Buffer buffer;
    buffer.size = size;
    auto info = vk::init<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    check(vkCreateBuffer(device.handle(), &info, nullptr, &buffer.buffer), "vkCreateBuffer");
    try {
        VkMemoryRequirements requirements;
        vkGetBufferMemoryRequirements(device.handle(), buffer.buffer, &requirements);
        const bool deviceAddress = usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
        if (!memoryFlags) memoryFlags = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
        buffer.memory = allocate(device, requirements, memoryFlags, deviceAddress, name);
        buffer.allocated = requirements.size;
        check(vkBindBufferMemory(device.handle(), buffer.buffer, buffer.memory, 0),
              "vkBindBufferMemory");
        if (memoryFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
            check(vkMapMemory(device.handle(), buffer.memory, 0, VK_WHOLE_SIZE, 0, &buffer.mapped),
                  "vkMapMemory");
        if (deviceAddress) {
            auto addressInfo =
                vk::init<VkBufferDeviceAddressInfo>(VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO);
            addressInfo.buffer = buffer.buffer;
            buffer.address = vkGetBufferDeviceAddress(device.handle(), &addressInfo);
        }
    } catch (...) {
        destroyBuffer(device, buffer);
        throw;
    }
    device.name(VK_OBJECT_TYPE_BUFFER, buffer.buffer, name);
    device.name(VK_OBJECT_TYPE_DEVICE_MEMORY, buffer.memory, name + " memory");
    return buffer;
}

void destroyBuffer(Device& device, Buffer& buffer) {
    if (buffer.buffer) vkDestroyBuffer(device.handle(), buffer.buffer, nullptr);
    if (buffer.memory) {
        vkFreeMemory(device.handle(), buffer.memory, nullptr);
        device.countAllocation(int64_t(buffer.allocated), -1);
    }
    buffer = {};
}

Buffer createBufferWithData(Device& device, const void* data, VkDeviceSize size,
                            VkBufferUsageFlags usage, const std::string& name) {
    Buffer staging =
        createBuffer(device, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                     VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                     name + " staging");
    std::memcpy(staging.mapped, data, size);
    Buffer buffer;
    try {
        buffer = createBuffer(device, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, 0, name);
        device.submitNow([&](VkCommandBuffer cmd) {
            VkBufferCopy region{0, 0, size};
            vkCmdCopyBuffer(cmd, staging.buffer, buffer.buffer, 1, &region);
        });
    } catch (...) {
        destroyBuffer(device, buffer);
        destroyBuffer(device, staging);
        throw;
    }
    destroyBuffer(device, staging);
    return buffer;
}

Image createImage2D(Device& device, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                    VkImageAspectFlags aspect, const std::string& name,
                    VkSampleCountFlagBits samples) {
    Image image;
    image.format = format;
    image.extent = extent;
    auto info = vk::init<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {extent.width, extent.height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = samples;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    check(vkCreateImage(device.handle(), &info, nullptr, &image.image), "vkCreateImage");
    try {
        VkMemoryRequirements requirements;
        vkGetImageMemoryRequirements(device.handle(), image.image, &requirements);
        image.memory =
            allocate(device, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, false, name);
        image.allocated = requirements.size;
        check(vkBindImageMemory(device.handle(), image.image, image.memory, 0),
              "vkBindImageMemory");
        auto view = vk::init<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
        view.image = image.image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = format;
        view.subresourceRange = {aspect, 0, 1, 0, 1};
        check(vkCreateImageView(device.handle(), &view, nullptr, &image.view), "vkCreateImageView");
    } catch (...) {
        destroyImage(device, image);
        throw;
    }
    device.name(VK_OBJECT_TYPE_IMAGE, image.image, name);
    device.name(VK_OBJECT_TYPE_IMAGE_VIEW, image.view, name + " view");
    device.name(VK_OBJECT_TYPE_DEVICE_MEMORY, image.memory, name + " memory");
    return image;
}

void destroyImage(Device& device, Image& image) {
    if (image.view) vkDestroyImageView(device.handle(), image.view, nullptr);
    if (image.image) vkDestroyImage(device.handle(), image.image, nullptr);
    if (image.memory) {
        vkFreeMemory(device.handle(), image.memory, nullptr);
        device.countAllocation(int64_t(image.allocated), -1);
    }
    image = {};
}

} // namespace vk
