// frame_slots.h - the frames in flight: per slot a command buffer, a fence, the timestamp
// queries around the scene pass and the slot's FrameData buffer. A slot is reused only after
// its fence signalled, which is also when its timestamps are read (never with a wait flag).
//
// Objects a frame records with are kept alive by the frame's slot (FrameSlot::keep): whoever
// replaces a pipeline, a buffer or a render target just lets go of it, and the last frame
// that used it frees it once that frame's fence has signalled. No switch waits for the GPU.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "render/pick.h"
#include "vk/resources.h"

namespace render {

struct FrameSlot {
    vk::Handle<VkCommandPool> pool;
    VkCommandBuffer cmd = VK_NULL_HANDLE; // from `pool`
    vk::Handle<VkFence> done;
    // [0] before the scene pass, [1] after it, [2] after the passes over the ID image
    vk::Handle<VkQueryPool> timestamps;
    vk::Buffer frameData;    // gpu::FrameData, written with vkCmdUpdateBuffer
    vk::Buffer pickReadback; // host-visible uint64: the frame's PickData::current
    bool submitted = false;  // has work whose timestamps are not read yet
    uint64_t frameNumber = 0;
    std::optional<glm::uvec2> pickPixel; // set by Renderer::record when the frame picks
    // Part set queries of this frame (Renderer::record): PartSetResult and `partSetWords`
    // bitset words per query, on the device and copied to the host.
    std::vector<PartSetQuery> partSetQueries;
    uint32_t partSetWords = 0, partSetParts = 0;
    vk::Buffer partSets, partSetsReadback; // grown when a frame needs more
    // What this frame's commands use and someone else may let go of meanwhile.
    std::vector<std::shared_ptr<const void>> kept;

    void keep(std::shared_ptr<const void> object) { kept.push_back(std::move(object)); }
};

class FrameSlots {
  public:
    static constexpr uint32_t count = 2;

    explicit FrameSlots(vk::Device& device);
    // Waits for the frames in flight, so what they keep goes only when they are done.
    ~FrameSlots();
    FrameSlots(const FrameSlots&) = delete;
    FrameSlots& operator=(const FrameSlots&) = delete;

    // Waits for the slot of frame `frameNumber`, collects its previous GPU time and pick,
    // frees what it kept, resets it and begins its command buffer.
    FrameSlot& begin(uint64_t frameNumber);
    // Ends and submits the slot's command buffer, signalling its fence.
    void submit(FrameSlot& slot, const std::vector<VkSemaphore>& wait = {},
                const std::vector<VkPipelineStageFlags>& waitStages = {},
                const std::vector<VkSemaphore>& signal = {});
    // Waits for every slot and collects the remaining GPU times.
    void finish();
    // Whether frame `frameNumber` has finished on the GPU (or was never submitted); asks the
    // fence without waiting.
    bool finished(uint64_t frameNumber) const;

    // GPU milliseconds of the scene pass, one per completed frame, oldest first: the last
    // historyLimit frames at least (older ones are dropped, so a long session stays small).
    const std::vector<double>& gpuMilliseconds() const { return gpuMs_; }
    // GPU times collected since the start, dropped ones included.
    uint64_t timedFrames() const { return timedFrames_; }
    static constexpr size_t historyLimit = 1 << 16;
    // The pick of the newest completed frame that picked a pixel. Read from a slot whose
    // fence has signalled, so asking never stalls the CPU.
    const std::optional<PickReading>& latestPick() const { return latestPick_; }
    // The part sets of the newest completed frame that asked for some; the same way.
    const std::optional<PartSetReading>& latestPartSets() const { return latestPartSets_; }
    // GPU milliseconds of the passes over the ID image (edges, part sets), as above; 0 for
    // frames without them.
    const std::vector<double>& idPassMilliseconds() const { return idPassMs_; }

  private:
    void collect(FrameSlot& slot);

    vk::Device& device_;
    std::array<FrameSlot, count> slots_;
    std::vector<double> gpuMs_, idPassMs_;
    uint64_t timedFrames_ = 0;
    std::optional<PickReading> latestPick_;
    std::optional<PartSetReading> latestPartSets_;
};

} // namespace render
