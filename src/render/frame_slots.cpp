// frame_slots.cpp - fences, command buffers and timestamp reads of the frames in flight.
#include "render/frame_slots.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <string>

#include "shared.h"
#include "vk/check.h"

namespace render {

FrameSlots::FrameSlots(vk::Device& device) : device_(device) {
    for (uint32_t i = 0; i < count; ++i) {
        FrameSlot& slot = slots_[i];
        const std::string suffix = " (slot " + std::to_string(i) + ")";
        auto pool = vk::init<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
        pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
        pool.queueFamilyIndex = device.queueFamily();
        slot.pool = vk::make(device, vkCreateCommandPool, pool, "frame pool" + suffix);

        auto alloc =
            vk::init<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
        alloc.commandPool = slot.pool.get();
        alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        alloc.commandBufferCount = 1;
        vk::check(vkAllocateCommandBuffers(device.handle(), &alloc, &slot.cmd),
                  "vkAllocateCommandBuffers");
        device.name(VK_OBJECT_TYPE_COMMAND_BUFFER, slot.cmd, "frame commands" + suffix);

        auto fence = vk::init<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
        fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;
        slot.done = vk::make(device, vkCreateFence, fence, "frame done" + suffix);

        auto query = vk::init<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
        query.queryType = VK_QUERY_TYPE_TIMESTAMP;
        query.queryCount = StampCount;
        slot.timestamps = vk::make(device, vkCreateQueryPool, query, "scene timestamps" + suffix);

        slot.frameData =
            vk::Buffer(device, sizeof(gpu::FrameData),
                       VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                           VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                       0, "frame data" + suffix);
        slot.pickReadback = vk::hostBuffer(
            device, sizeof(uint64_t), VK_BUFFER_USAGE_TRANSFER_DST_BIT, "pick readback" + suffix);
        slot.hoverReadback = vk::hostBuffer(device, sizeof(uint64_t),
                                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                                VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                                            "hover readback" + suffix);
        slot.hoverBoxReadback = vk::hostBuffer(device, sizeof(gpu::HoverBox),
                                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                                   VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                                               "hovered tiles readback" + suffix);
        slot.cullReadback =
            vk::hostBuffer(device, sizeof(gpu::CullStats), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                           "cull counters readback" + suffix);
    }
}

FrameSlots::~FrameSlots() {
    // Teardown: a failure to wait cannot be acted on. A fence is either signalled or belongs
    // to a submitted frame (submit() resets it), so this always returns.
    for (FrameSlot& slot : slots_)
        if (slot.done) {
            const VkFence fence = slot.done.get();
            vkWaitForFences(device_.handle(), 1, &fence, VK_TRUE, UINT64_MAX);
        }
}

// A frame is waited for as long as it takes. A slow device is not a hung one: a CPU driver
// shares its cores with everything else (in CI's sanitizer pass, with other tests on both
// cores, a benchmark smoke frame of 0.2 s once took over a minute), and a GPU that does hang
// is the driver's to report, as VK_ERROR_DEVICE_LOST, which vk::check turns into an error.
// After a minute on one frame a line on stderr says what idview waits for, once per frame.
static void waitForFrame(vk::Device& device, VkFence fence) {
    constexpr uint64_t patience = 60'000'000'000ull; // nanoseconds
    VkResult result = vkWaitForFences(device.handle(), 1, &fence, VK_TRUE, patience);
    if (result == VK_TIMEOUT) {
        std::fprintf(stderr,
                     "idview: %s has worked on one frame for over a minute; still waiting "
                     "(a device that hangs is reported lost by its driver)\n",
                     device.info().name.c_str());
        result = vkWaitForFences(device.handle(), 1, &fence, VK_TRUE, UINT64_MAX);
    }
    vk::check(result, "waiting for a frame");
}

FrameSlot& FrameSlots::begin(uint64_t frameNumber) {
    FrameSlot& slot = slots_[frameNumber % count];
    VkDevice dev = device_.handle();
    waitForFrame(device_, slot.done.get());
    collect(slot);
    // The newer frames that have finished too, without waiting: what they read back (the
    // hovered part, its tiles) is known a frame sooner. Oldest first, as in finish().
    for (uint64_t newer = frameNumber - count + 1; newer < frameNumber; ++newer)
        if (FrameSlot& other = slots_[newer % count]; other.frameNumber == newer && finished(newer))
            collect(other);
    slot.frameNumber = frameNumber;
    slot.pickPixel.reset();
    slot.hoverPixel.reset();
    slot.composedWhole = false;
    slot.scenePass = false;
    slot.partSetQueries.clear();
    vk::check(vkResetCommandPool(dev, slot.pool.get(), 0), "vkResetCommandPool");
    auto info = vk::init<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vk::check(vkBeginCommandBuffer(slot.cmd, &info), "vkBeginCommandBuffer");
    vkCmdResetQueryPool(slot.cmd, slot.timestamps.get(), 0, StampCount);
    return slot;
}

void FrameSlots::submit(FrameSlot& slot, const std::vector<VkSemaphore>& wait,
                        const std::vector<VkPipelineStageFlags>& waitStages,
                        const std::vector<VkSemaphore>& signal) {
    vk::check(vkEndCommandBuffer(slot.cmd), "vkEndCommandBuffer");
    // Reset only now: a frame that never reaches its submit (an error while recording)
    // leaves the fence signalled, so nothing waits for it forever.
    const VkFence fence = slot.done.get();
    vk::check(vkResetFences(device_.handle(), 1, &fence), "vkResetFences");
    auto info = vk::init<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
    info.waitSemaphoreCount = static_cast<uint32_t>(wait.size());
    info.pWaitSemaphores = wait.data();
    info.pWaitDstStageMask = waitStages.data();
    info.commandBufferCount = 1;
    info.pCommandBuffers = &slot.cmd;
    info.signalSemaphoreCount = static_cast<uint32_t>(signal.size());
    info.pSignalSemaphores = signal.data();
    vk::check(vkQueueSubmit(device_.queue(), 1, &info, slot.done.get()), "vkQueueSubmit");
    slot.submitted = true;
}

void FrameSlots::finish() {
    // Oldest frame first, so the histories stay in frame order.
    std::array<FrameSlot*, count> order;
    for (size_t i = 0; i < count; ++i) order[i] = &slots_[i];
    std::sort(order.begin(), order.end(), [](const FrameSlot* a, const FrameSlot* b) {
        return a->frameNumber < b->frameNumber;
    });
    for (FrameSlot* slot : order) {
        waitForFrame(device_, slot->done.get());
        collect(*slot);
    }
}

bool FrameSlots::finished(uint64_t frameNumber) const {
    const FrameSlot& slot = slots_[frameNumber % count];
    if (slot.frameNumber != frameNumber || !slot.submitted) return true;
    const VkResult status = vkGetFenceStatus(device_.handle(), slot.done.get());
    if (status == VK_NOT_READY) return false;
    vk::check(status, "vkGetFenceStatus");
    return true;
}

// The slot's readback, once its fence has signalled: per query a PartSetResult, then words.
static PartSetReading readPartSets(const FrameSlot& slot) {
    PartSetReading reading;
    reading.frame = slot.frameNumber;
    reading.queries = slot.partSetQueries;
    const auto* base = static_cast<const uint32_t*>(slot.partSetsReadback.mapped());
    const size_t stride = sizeof(gpu::PartSetResult) / 4 + slot.partSetWords;
    for (size_t i = 0; i < slot.partSetQueries.size(); ++i) {
        const uint32_t* result = base + stride * i;
        reading.counts.push_back(result[0]);
        reading.sets.emplace_back(slot.partSetParts, result + sizeof(gpu::PartSetResult) / 4);
    }
    return reading;
}

void FrameSlots::collect(FrameSlot& slot) {
    // The fence has signalled: what the frame kept is free, and so is every upload submitted
    // before it (a fence covers all earlier work on its queue).
    slot.kept.clear();
    device_.collectFinishedUploads();
    if (!slot.submitted) return;
    slot.submitted = false;
    if (slot.pickPixel && (!latestPick_ || latestPick_->frame < slot.frameNumber)) {
        uint64_t value;
        std::memcpy(&value, slot.pickReadback.mapped(), sizeof value);
        latestPick_ = decodePick(value, slot.frameNumber, *slot.pickPixel);
    }
    if (slot.hoverPixel && (!latestHover_ || latestHover_->frame < slot.frameNumber)) {
        uint64_t value;
        std::memcpy(&value, slot.hoverReadback.mapped(), sizeof value);
        latestHover_ = decodePick(value, slot.frameNumber, *slot.hoverPixel);
    }
    if (slot.composedWhole && (!latestTiles_ || latestTiles_->frame < slot.frameNumber)) {
        gpu::HoverBox box;
        std::memcpy(&box, slot.hoverBoxReadback.mapped(), sizeof box);
        latestTiles_ = decodeHoverBox(box, slot.frameNumber);
    }
    if (!slot.partSetQueries.empty() &&
        (!latestPartSets_ || latestPartSets_->frame < slot.frameNumber))
        latestPartSets_ = readPartSets(slot);
    if (!slot.scenePass) return; // composed only: no timestamps, counters or pick
    uint64_t ticks[StampCount];
    VkResult result =
        vkGetQueryPoolResults(device_.handle(), slot.timestamps.get(), 0, StampCount, sizeof ticks,
                              ticks, sizeof(uint64_t), VK_QUERY_RESULT_64_BIT);
    if (result == VK_NOT_READY) return; // fence signalled, so only a driver quirk gets here
    vk::check(result, "vkGetQueryPoolResults");
    const double period = device_.info().timestampPeriodNs;
    auto ms = [&](Stamp from, Stamp to) { return double(ticks[to] - ticks[from]) * period * 1e-6; };
    FrameTimes t;
    t.sceneMs = ms(StampStart, StampDrawn);
    t.cullMs = ms(StampStart, StampEarlyCulled) + ms(StampPyramid, StampLateCulled);
    t.pyramidMs = ms(StampEarlyDrawn, StampPyramid);
    t.earlyMs = ms(StampEarlyCulled, StampEarlyDrawn);
    t.lateMs = ms(StampLateCulled, StampDrawn);
    t.idPassMs = ms(StampDrawn, StampIdPasses);
    gpu::CullStats stats;
    std::memcpy(&stats, slot.cullReadback.mapped(), sizeof stats);
    gpuMs_.push_back(t.sceneMs);
    idPassMs_.push_back(t.idPassMs);
    times_.push_back(t);
    cullStats_.push_back(stats);
    ++timedFrames_;
    if (gpuMs_.size() >= 2 * historyLimit) {
        const auto keep = [](auto& history) {
            history.erase(history.begin(), history.end() - long(historyLimit));
        };
        keep(gpuMs_);
        keep(idPassMs_);
        keep(times_);
        keep(cullStats_);
    }
}

} // namespace render
