// offscreen.h - everything one offscreen rendering needs on a device: the device, shader
// compiler, renderer, the targets (at the options' size and MSAA) and the frames in flight.
// Members are built in order and destroyed in reverse: the frames first, which waits for
// them, so nothing they use goes while they run. The Instance outlives it, so the validation
// count read after destruction includes teardown.
#pragma once

#include <chrono>
#include <cstring>
#include <memory>
#include <vector>

#include "app/cli.h"
#include "app/headless.h"
#include "app/pipeline_cache_file.h"
#include "render/frame_slots.h"
#include "render/renderer.h"
#include "render/targets.h"
#include "vk/barrier.h"
#include "vk/context.h"
#include "vk/shader_compiler.h"

namespace app {

// Host-visible copies of the last frame's colour and ID images.
struct Readback {
    vk::Buffer color, ids;

    Readback(vk::Device& device, VkExtent2D extent) {
        const VkDeviceSize bytes = VkDeviceSize(extent.width) * extent.height * 4;
        color = vk::hostBuffer(device, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "readback colour");
        ids = vk::hostBuffer(device, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "readback IDs");
    }

    // After the scene pass: both images are in TRANSFER_SRC_OPTIMAL (see ScenePass).
    void record(VkCommandBuffer cmd, const render::SceneTargets& targets) const {
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {targets.extent().width, targets.extent().height, 1};
        vkCmdCopyImageToBuffer(cmd, targets.color().handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               color.handle(), 1, &region);
        vkCmdCopyImageToBuffer(cmd, targets.ids().handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               ids.handle(), 1, &region);
        vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
    }

    // Once the frame that recorded the copies has finished.
    std::vector<uint8_t> colorBytes() const { return read<uint8_t>(color); }
    std::vector<uint32_t> idValues() const { return read<uint32_t>(ids); }

  private:
    template <typename T>
    static std::vector<T> read(const vk::Buffer& from) {
        std::vector<T> values(from.size() / sizeof(T));
        std::memcpy(values.data(), from.mapped(), values.size() * sizeof(T));
        return values;
    }
};

struct Offscreen {
    Offscreen(vk::Instance& instance, const Options& options)
        : start(std::chrono::steady_clock::now()),
          device(instance, vk::chooseDevice(instance.devices(), options.device)),
          compiler(vk::ShaderCompiler::locate(options.shaderDir)),
          renderer(device, compiler, pipelineCacheFolder(options.live.scene)),
          extent{options.width, options.height}, slots(device) {
        useMsaa(options.live.render.pipeline.msaa);
    }

    // Targets for `msaa` (the ones before stay with the frames that drew into them).
    void useMsaa(uint32_t msaa) {
        if (targets && uint32_t(targets->pass().samples()) == msaa) return;
        targets = std::make_shared<render::SceneTargets>(device, renderer.pass(msaa), extent);
    }

    std::chrono::steady_clock::time_point start; // before the device: time to the first frame
    vk::Device device;
    vk::ShaderCompiler compiler;
    render::Renderer renderer;
    VkExtent2D extent;
    std::shared_ptr<const render::SceneTargets> targets;
    render::FrameSlots slots;
};

} // namespace app
