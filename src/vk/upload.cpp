// upload.cpp - one staging buffer and one submit per batch of buffer uploads.
#include "vk/upload.h"

#include <algorithm>
#include <cstring>
#include <memory>

namespace vk {

Buffer UploadBatch::add(const void* data, VkDeviceSize size, VkBufferUsageFlags usage,
                        const std::string& name) {
    // Vulkan has no empty buffers; a 4-byte one keeps addresses valid for empty arrays.
    const VkDeviceSize bytes = std::max<VkDeviceSize>(size, 4);
    Buffer buffer(device_, bytes, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, 0, name);
    // 16-byte aligned offsets: any element type copies from an aligned place.
    const VkDeviceSize offset = (bytes_.size() + 15) & ~VkDeviceSize(15);
    bytes_.resize(offset + bytes);
    if (size) std::memcpy(bytes_.data() + offset, data, size);
    copies_.push_back({buffer.handle(), offset, bytes});
    return buffer;
}

void UploadBatch::submit() {
    if (copies_.empty()) return;
    // The staging buffer and the owners of the destinations, freed together once the GPU
    // has run the copies.
    struct InFlight {
        Buffer staging;
        std::vector<std::shared_ptr<const void>> owners;
    };
    auto inFlight = std::make_shared<InFlight>();
    inFlight->staging =
        hostBuffer(device_, bytes_.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "upload staging");
    const Buffer* staging = &inFlight->staging;
    std::memcpy(staging->mapped(), bytes_.data(), bytes_.size());
    CommandBuffer cmd = device_.beginOneTime();
    for (const Copy& copy : copies_) {
        const VkBufferCopy region{copy.offset, 0, copy.size};
        vkCmdCopyBuffer(cmd.get(), staging->handle(), copy.destination, 1, &region);
    }
    // Every later access, whatever it is (vertex, index, indirect, shader reads; the
    // animation's writes to the objects), comes after the copies.
    auto visible = vk::init<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    visible.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    visible.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
    vkCmdPipelineBarrier(cmd.get(), VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &visible, 0, nullptr, 0,
                         nullptr);
    inFlight->owners = std::move(owners_);
    owners_.clear();
    device_.submitUpload(std::move(cmd), std::move(inFlight));
    copies_.clear();
    bytes_.clear();
}

} // namespace vk
