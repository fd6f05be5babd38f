// upload.cpp - staging chunks and one submit per batch of buffer uploads.
#include "vk/upload.h"

#include <algorithm>
#include <cstring>
#include <memory>

namespace vk {

namespace {
// A new staging chunk holds as much as the batch has added so far, up to this (an array larger
// than it gets a chunk of its own size): a batch of one array stages exactly that, as a single
// buffer did, and a scene's many arrays take a handful of chunks of growing size.
constexpr VkDeviceSize largestChunk = VkDeviceSize(4) << 20;
} // namespace

std::pair<size_t, VkDeviceSize> UploadBatch::stagingFor(VkDeviceSize bytes) {
    if (!chunks_.empty()) {
        Chunk& last = chunks_.back();
        // 16-byte aligned offsets: any element type copies from an aligned place.
        const VkDeviceSize offset = (last.used + 15) & ~VkDeviceSize(15);
        if (offset + bytes <= last.staging.size()) {
            last.used = offset + bytes;
            return {chunks_.size() - 1, offset};
        }
    }
    const VkDeviceSize size = std::max(bytes, std::min(bytes_, largestChunk));
    Chunk chunk{hostBuffer(device_, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "upload staging"),
                bytes};
    chunks_.push_back(std::move(chunk));
    return {chunks_.size() - 1, 0};
}

Buffer UploadBatch::add(const void* data, VkDeviceSize size, VkBufferUsageFlags usage,
                        const std::string& name) {
    // Vulkan has no empty buffers; a 4-byte one keeps addresses valid for empty arrays.
    const VkDeviceSize bytes = std::max<VkDeviceSize>(size, 4);
    Buffer buffer(device_, bytes, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, 0, name);
    const auto [chunk, offset] = stagingFor(bytes);
    std::byte* staged = static_cast<std::byte*>(chunks_[chunk].staging.mapped()) + offset;
    if (size) std::memcpy(staged, data, size);
    if (size < bytes) std::memset(staged + size, 0, bytes - size); // an empty array's 4 bytes
    copies_.push_back({buffer.handle(), chunk, offset, bytes});
    bytes_ += bytes;
    return buffer;
}

void UploadBatch::submit() {
    if (copies_.empty()) return;
    // The staging chunks and the owners of the destinations, freed together once the GPU has
    // run the copies.
    struct InFlight {
        std::vector<Chunk> staging;
        std::vector<std::shared_ptr<const void>> owners;
    };
    auto inFlight = std::make_shared<InFlight>();
    CommandBuffer cmd = device_.beginOneTime();
    for (const Copy& copy : copies_) {
        const VkBufferCopy region{copy.offset, 0, copy.size};
        vkCmdCopyBuffer(cmd.get(), chunks_[copy.chunk].staging.handle(), copy.destination, 1,
                        &region);
    }
    // Every later access, whatever it is (vertex, index, indirect, shader reads; the
    // animation's writes to the objects), comes after the copies.
    auto visible = vk::init<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    visible.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    visible.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
    vkCmdPipelineBarrier(cmd.get(), VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &visible, 0, nullptr, 0,
                         nullptr);
    inFlight->staging = std::move(chunks_);
    inFlight->owners = std::move(owners_);
    chunks_.clear();
    owners_.clear();
    device_.submitUpload(std::move(cmd), std::move(inFlight));
    copies_.clear();
    bytes_ = 0;
}

} // namespace vk
