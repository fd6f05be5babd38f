// frame_slots.cpp - fences, command buffers and timestamp reads of the frames in flight.
#include "render/frame_slots.h"

#include <cstring>
#include <string>

#include "shared.h"
#include "vk/check.h"

namespace render {

FrameSlots::FrameSlots(vk::Device& device) : device_(device) {
    try {
        create();
    } catch (...) {
        release();
        throw;
    }
}

void FrameSlots::create() {
    vk::Device& device = device_;
    VkDevice dev = device.handle();
    for (uint32_t i = 0; i < count; ++i) {
        FrameSlot& slot = slots_[i];
        const std::string suffix = " (slot " + std::to_string(i) + ")";
        auto pool = vk::init<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
        pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
        pool.queueFamilyIndex = device.queueFamily();
        vk::check(vkCreateCommandPool(dev, &pool, nullptr, &slot.pool), "vkCreateCommandPool");
        device.name(VK_OBJECT_TYPE_COMMAND_POOL, slot.pool, "frame pool" + suffix);

        auto alloc =
            vk::init<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
        alloc.commandPool = slot.pool;
        alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        alloc.commandBufferCount = 1;
        vk::check(vkAllocateCommandBuffers(dev, &alloc, &slot.cmd), "vkAllocateCommandBuffers");
        device.name(VK_OBJECT_TYPE_COMMAND_BUFFER, slot.cmd, "frame commands" + suffix);

        auto fence = vk::init<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
        fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;
        vk::check(vkCreateFence(dev, &fence, nullptr, &slot.done), "vkCreateFence");
        device.name(VK_OBJECT_TYPE_FENCE, slot.done, "frame done" + suffix);

        auto query = vk::init<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
        query.queryType = VK_QUERY_TYPE_TIMESTAMP;
        query.queryCount = 2;
        vk::check(vkCreateQueryPool(dev, &query, nullptr, &slot.timestamps), "vkCreateQueryPool");
        device.name(VK_OBJECT_TYPE_QUERY_POOL, slot.timestamps, "scene timestamps" + suffix);

        slot.frameData =
            vk::createBuffer(device, sizeof(gpu::FrameData),
                             VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                 VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                             0, "frame data" + suffix);
        slot.pickReadback = vk::createBuffer(
            device, sizeof(uint64_t), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
            VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
            "pick readback" + suffix);
    }
}

FrameSlots::~FrameSlots() {
    vkDeviceWaitIdle(device_.handle()); // teardown: nothing may still use the slots
    release();
}

void FrameSlots::release() {
    VkDevice dev = device_.handle();
    for (FrameSlot& slot : slots_) {
        vk::destroyBuffer(device_, slot.frameData);
        vk::destroyBuffer(device_, slot.pickReadback);
        if (slot.timestamps) vkDestroyQueryPool(dev, slot.timestamps, nullptr);
        if (slot.done) vkDestroyFence(dev, slot.done, nullptr);
        if (slot.pool) vkDestroyCommandPool(dev, slot.pool, nullptr);
        slot = {};
    }
}

// A frame that has not finished after a minute means a hung GPU (the slowest frames seen, on
// lavapipe with millions of draws, take seconds): say so instead of waiting forever.
static void waitForFrame(vk::Device& device, VkFence fence) {
    constexpr uint64_t minute = 60'000'000'000ull;
    const VkResult result = vkWaitForFences(device.handle(), 1, &fence, VK_TRUE, minute);
    if (result == VK_TIMEOUT)
        throw vk::Error("the GPU has not finished a frame in 60 s: it hangs or was lost");
    vk::check(result, "waiting for a frame");
}

FrameSlot& FrameSlots::begin(uint64_t frameNumber) {
    FrameSlot& slot = slots_[frameNumber % count];
    VkDevice dev = device_.handle();
    waitForFrame(device_, slot.done);
    collect(slot);
    vk::check(vkResetFences(dev, 1, &slot.done), "vkResetFences");
    slot.frameNumber = frameNumber;
    slot.pickPixel.reset();
    vk::check(vkResetCommandPool(dev, slot.pool, 0), "vkResetCommandPool");
    auto info = vk::init<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vk::check(vkBeginCommandBuffer(slot.cmd, &info), "vkBeginCommandBuffer");
    vkCmdResetQueryPool(slot.cmd, slot.timestamps, 0, 2);
    return slot;
}

void FrameSlots::submit(FrameSlot& slot, const std::vector<VkSemaphore>& wait,
                        const std::vector<VkPipelineStageFlags>& waitStages,
                        const std::vector<VkSemaphore>& signal) {
    vk::check(vkEndCommandBuffer(slot.cmd), "vkEndCommandBuffer");
    auto info = vk::init<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
    info.waitSemaphoreCount = static_cast<uint32_t>(wait.size());
    info.pWaitSemaphores = wait.data();
    info.pWaitDstStageMask = waitStages.data();
    info.commandBufferCount = 1;
    info.pCommandBuffers = &slot.cmd;
    info.signalSemaphoreCount = static_cast<uint32_t>(signal.size());
    info.pSignalSemaphores = signal.data();
    vk::check(vkQueueSubmit(device_.queue(), 1, &info, slot.done), "vkQueueSubmit");
    slot.submitted = true;
}

void FrameSlots::finish() {
    for (FrameSlot& slot : slots_) {
        waitForFrame(device_, slot.done);
        collect(slot);
    }
}

void FrameSlots::collect(FrameSlot& slot) {
    if (!slot.submitted) return;
    slot.submitted = false;
    if (slot.pickPixel && (!latestPick_ || latestPick_->frame < slot.frameNumber)) {
        uint64_t value;
        std::memcpy(&value, slot.pickReadback.mapped, sizeof value);
        latestPick_ = decodePick(value, slot.frameNumber, *slot.pickPixel);
    }
    uint64_t ticks[2];
    VkResult result = vkGetQueryPoolResults(device_.handle(), slot.timestamps, 0, 2, sizeof ticks,
                                            ticks, sizeof(uint64_t), VK_QUERY_RESULT_64_BIT);
    if (result == VK_NOT_READY) return; // fence signalled, so only a driver quirk gets here
    vk::check(result, "vkGetQueryPoolResults");
    const double period = device_.info().timestampPeriodNs;
    gpuMs_.push_back(double(ticks[1] - ticks[0]) * period * 1e-6);
    ++timedFrames_;
    if (gpuMs_.size() >= 2 * historyLimit)
        gpuMs_.erase(gpuMs_.begin(), gpuMs_.end() - long(historyLimit));
}

} // namespace render
