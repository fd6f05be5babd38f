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
#include "shared.h"
#include "vk/resources.h"

namespace render {

// The timestamps of a frame, in the order the GPU writes them. A step the frame leaves out
// (culling off: the cull passes, the pyramid and the second half) writes its stamp right
// after the one before, so it takes no time.
enum Stamp : uint32_t {
    StampStart,       // before the first cull pass
    StampEarlyCulled, // after it: the first (or whole) scene pass starts
    StampEarlyDrawn,  // the depth pyramid starts
    StampPyramid,     // the late cull starts
    StampLateCulled,  // the second half starts
    StampDrawn,       // the scene pass is done; the passes over the ID image start
    StampIdPasses,    // they are done (edges, part sets)
    StampCount
};

// What a frame's timestamps and culling counters say, once its fence has signalled.
struct FrameTimes {
    double sceneMs = 0.0;   // StampStart to StampDrawn: drawing, culling included
    double cullMs = 0.0;    // the cull passes
    double pyramidMs = 0.0; // building the depth pyramid
    double earlyMs = 0.0;   // drawing the first (or whole) half of the scene pass
    double lateMs = 0.0;    // drawing its second half (occlusion culling), or 0
    double idPassMs = 0.0;  // edges and part sets
};

struct FrameSlot {
    vk::Handle<VkCommandPool> pool;
    VkCommandBuffer cmd = VK_NULL_HANDLE; // from `pool`
    vk::Handle<VkFence> done;
    vk::Handle<VkQueryPool> timestamps; // StampCount of them
    vk::Buffer frameData;               // gpu::FrameData, written with vkCmdUpdateBuffer
    vk::Buffer pickReadback;            // host-visible uint64: the frame's PickData::current
    // Host-visible uint64 the composition writes itself: the part and depth at the hovered
    // pixel, encoded as PickData's (gpu::ComposePush::hoverAddress).
    vk::Buffer hoverReadback;
    // Host-visible gpu::HoverBox a whole composition fills (reset by the host when recorded).
    vk::Buffer hoverBoxReadback;
    bool composedWhole = false; // the frame composed the whole picture
    vk::Buffer cullReadback;    // host-visible gpu::CullStats of the frame
    bool submitted = false;     // has work whose timestamps are not read yet
    // Whether the frame ran the scene pass (Renderer::record) or only composed the picture
    // again from the images the last one left (Renderer::recordComposition): only the first
    // kind has timestamps, culling counters and a pick.
    bool scenePass = false;
    uint64_t frameNumber = 0;
    std::optional<glm::uvec2> pickPixel;  // set by Renderer::record when the frame picks
    std::optional<glm::uvec2> hoverPixel; // set when the frame's composition hovers a pixel
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

    // GPU milliseconds of the scene pass (culling included), one per completed frame, oldest
    // first: the last historyLimit frames at least (older ones are dropped, so a long session
    // stays small).
    const std::vector<double>& gpuMilliseconds() const { return gpuMs_; }
    // The same frames' times of each step, and their culling counters.
    const std::vector<FrameTimes>& frameTimes() const { return times_; }
    const std::vector<gpu::CullStats>& cullStats() const { return cullStats_; }
    // GPU times collected since the start, dropped ones included.
    uint64_t timedFrames() const { return timedFrames_; }
    static constexpr size_t historyLimit = 1 << 16;
    // The pick of the newest completed frame that picked a pixel. Read from a slot whose
    // fence has signalled, so asking never stalls the CPU.
    const std::optional<PickReading>& latestPick() const { return latestPick_; }
    // The part and depth under the hovered pixel of the newest completed frame that hovered
    // one, from its ID and depth images (scene pass or not); the same way.
    const std::optional<PickReading>& latestHover() const { return latestHover_; }
    // The part sets of the newest completed frame that asked for some; the same way.
    const std::optional<PartSetReading>& latestPartSets() const { return latestPartSets_; }
    // The hovered part's tiles of the newest completed frame that composed the whole
    // picture; the same way.
    const std::optional<HoveredTiles>& latestHoveredTiles() const { return latestTiles_; }
    // GPU milliseconds of the passes over the ID image (edges, part sets), as above; 0 for
    // frames without them.
    const std::vector<double>& idPassMilliseconds() const { return idPassMs_; }

  private:
    void collect(FrameSlot& slot);

    vk::Device& device_;
    std::array<FrameSlot, count> slots_;
    std::vector<double> gpuMs_, idPassMs_;
    std::vector<FrameTimes> times_;
    std::vector<gpu::CullStats> cullStats_;
    uint64_t timedFrames_ = 0;
    std::optional<PickReading> latestPick_, latestHover_;
    std::optional<PartSetReading> latestPartSets_;
    std::optional<HoveredTiles> latestTiles_;
};

} // namespace render
