// resources.cpp - buffer and image creation, and the device memory behind them.
#include "vk/resources.h"

#include <cstdint>
#include <string>
#include <utility>

#include "vk/check.h"

namespace vk {
namespace {

std::string mebibytes(VkDeviceSize bytes) {
    return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB";
}

} // namespace

// Too large for the memory heap at all: say so in words instead of letting the driver fail
// (or the validation layer object). Out of memory at allocation: the same, with the cause.
Allocation::Allocation(Device& device, const VkMemoryRequirements& requirements,
                       VkMemoryPropertyFlags flags, bool deviceAddress, const std::string& name) {
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
    faultPoint(name.c_str());
    const VkResult result = vkAllocateMemory(device.handle(), &info, nullptr, &memory_);
    if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
        throw Error("out of " + where + " memory allocating " + mebibytes(requirements.size) +
                    " for '" + name + "' (idview holds " +
                    mebibytes(VkDeviceSize(device.liveMemory().bytes)) +
                    "); try fewer --copies or a smaller model");
    check(result, "vkAllocateMemory");
    device_ = &device;
    bytes_ = requirements.size;
    device.countAllocation(int64_t(bytes_), +1);
    device.name(VK_OBJECT_TYPE_DEVICE_MEMORY, memory_, name + " memory");
}

Allocation::~Allocation() {
    if (!memory_) return;
    vkFreeMemory(device_->handle(), memory_, nullptr);
    device_->countAllocation(int64_t(bytes_), -1);
}

void Allocation::swap(Allocation& other) noexcept {
    std::swap(device_, other.device_);
    std::swap(memory_, other.memory_);
    std::swap(bytes_, other.bytes_);
}

Buffer::Buffer(Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
               VkMemoryPropertyFlags memoryFlags, const std::string& name)
    : size_(size) {
    auto info = vk::init<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    buffer_ = make(device, vkCreateBuffer, info, name);
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device.handle(), buffer_.get(), &requirements);
    const bool deviceAddress = usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
    if (!memoryFlags) memoryFlags = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    memory_ = Allocation(device, requirements, memoryFlags, deviceAddress, name);
    check(vkBindBufferMemory(device.handle(), buffer_.get(), memory_.get(), 0),
          "vkBindBufferMemory");
    if (memoryFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) {
        check(vkMapMemory(device.handle(), memory_.get(), 0, VK_WHOLE_SIZE, 0, &mapped_),
              "vkMapMemory");
        // lavapipe (Mesa 25) out of address space answers VK_SUCCESS with mmap's MAP_FAILED,
        // all ones, as the address: written to, that would crash; said as the allocation's
        // own failure is.
        if (!mapped_ || mapped_ == reinterpret_cast<void*>(~uintptr_t(0)))
            throw Error("out of host memory mapping " + mebibytes(requirements.size) + " for '" +
                        name + "'; try fewer --copies or a smaller model");
    }
    if (deviceAddress) {
        auto addressInfo =
            vk::init<VkBufferDeviceAddressInfo>(VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO);
        addressInfo.buffer = buffer_.get();
        address_ = vkGetBufferDeviceAddress(device.handle(), &addressInfo);
    }
}

Buffer hostBuffer(Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                  const std::string& name) {
    return Buffer(device, size, usage,
                  VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, name);
}

Image::Image(Device& device, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
             VkImageAspectFlags aspect, const std::string& name, VkSampleCountFlagBits samples)
    : format_(format), extent_(extent) {
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
    image_ = make(device, vkCreateImage, info, name);
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(device.handle(), image_.get(), &requirements);
    memory_ = Allocation(device, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, false, name);
    check(vkBindImageMemory(device.handle(), image_.get(), memory_.get(), 0), "vkBindImageMemory");
    auto view = vk::init<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
    view.image = image_.get();
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format;
    view.subresourceRange = {aspect, 0, 1, 0, 1};
    view_ = make(device, vkCreateImageView, view, name + " view");
}

} // namespace vk
