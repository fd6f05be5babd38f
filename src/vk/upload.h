// upload.h - device-local buffers filled from host data, many at once: every add() of one
// batch is copied straight into host-visible staging memory (a few large chunks, so the host
// holds no second copy of what it uploads) and recorded into one queue submission, and
// nothing waits for it. The submission's last barrier makes the copies visible to everything
// submitted after it on the queue (the frames that draw with the buffers); the staging memory
// is freed once the GPU has run it (Device::collectFinishedUploads).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "vk/resources.h"

namespace vk {

class UploadBatch {
  public:
    explicit UploadBatch(Device& device) : device_(device) {}

    // A device-local buffer of `size` bytes (at least 4) that will hold `data`, copied now
    // into the batch. It must not be used before submit(). TRANSFER_DST is added to `usage`.
    Buffer add(const void* data, VkDeviceSize size, VkBufferUsageFlags usage,
               const std::string& name);
    template <typename T>
    Buffer add(const std::vector<T>& values, VkBufferUsageFlags usage, const std::string& name) {
        return add(values.data(), values.size() * sizeof(T), usage, name);
    }

    // What owns buffers of this batch: it lives at least until the copies into them are done,
    // so letting go of it before the GPU ran the batch is safe.
    void keep(std::shared_ptr<const void> owner) { owners_.push_back(std::move(owner)); }

    // Records every copy and submits them once; an empty batch submits nothing.
    void submit();
    VkDeviceSize bytes() const { return bytes_; } // added so far

  private:
    // The staging chunk with room for `bytes` more (a new one where the last is full), and
    // where in it they go.
    std::pair<size_t, VkDeviceSize> stagingFor(VkDeviceSize bytes);
    struct Copy {
        VkBuffer destination;
        size_t chunk;
        VkDeviceSize offset, size;
    };
    struct Chunk {
        Buffer staging;
        VkDeviceSize used = 0;
    };
    Device& device_;
    std::vector<Chunk> chunks_;
    std::vector<Copy> copies_;
    std::vector<std::shared_ptr<const void>> owners_;
    VkDeviceSize bytes_ = 0;
};

} // namespace vk
