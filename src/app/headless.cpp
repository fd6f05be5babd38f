// headless.cpp - the frame loop without a window, and image readback.
#include "app/headless.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "app/image_io.h"
#include "app/offscreen.h"
#include "app/scene_source.h"
#include "render/frame_slots.h"
#include "render/renderer.h"
#include "render/targets.h"
#include "scene/explode.h"
#include "vk/check.h"
#include "vk/context.h"
#include "vk/shader_compiler.h"

namespace app {
namespace {

// Host-visible copies of the last frame's colour and ID images.
struct Readback {
    vk::Device& device;
    vk::Buffer color, ids;

    Readback(vk::Device& d, VkExtent2D extent) : device(d) {
        const VkDeviceSize bytes = VkDeviceSize(extent.width) * extent.height * 4;
        const VkMemoryPropertyFlags host =
            VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        color =
            vk::createBuffer(d, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, host, "readback colour");
        try {
            ids =
                vk::createBuffer(d, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, host, "readback IDs");
        } catch (...) {
            vk::destroyBuffer(d, color);
            throw;
        }
    }
    ~Readback() {
        vk::destroyBuffer(device, color);
        vk::destroyBuffer(device, ids);
    }

    // After the scene pass: both images are in TRANSFER_SRC_OPTIMAL (see ScenePass).
    void record(VkCommandBuffer cmd, const render::SceneTargets& targets) const {
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {targets.extent().width, targets.extent().height, 1};
        vkCmdCopyImageToBuffer(cmd, targets.color().image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               color.buffer, 1, &region);
        vkCmdCopyImageToBuffer(cmd, targets.ids().image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               ids.buffer, 1, &region);
        auto toHost = vk::init<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                             &toHost, 0, nullptr, 0, nullptr);
    }
};

std::string pickJson(const scene::Scene& scene, const render::PickReading& pick) {
    char head[64];
    std::snprintf(head, sizeof head, "{\"x\":%u,\"y\":%u,", pick.pixel.x, pick.pixel.y);
    const auto info = pick.part ? scene::describePart(scene, *pick.part) : std::nullopt;
    if (!info)
        return std::string(head) + "\"part\":null,\"object\":null,\"local_part\":null,"
                                   "\"depth\":null}";
    char body[160];
    std::snprintf(body, sizeof body, "\"part\":%u,\"object\":%u,\"local_part\":%u,\"depth\":%.9g}",
                  info->uniquePartId, info->object, info->localPart, double(pick.depth));
    return std::string(head) + body;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

} // namespace

render::RenderConfig renderConfig(const Options& options) {
    const render::Technique* technique = render::findTechnique(options.renderer);
    const render::DrawMode* mode = render::findDrawMode(options.mode);
    if (!technique || !mode) throw vk::Error("unknown renderer or mode");
    return renderConfig(options, *technique, *mode);
}

render::RenderConfig renderConfig(const Options& options, const render::Technique& technique,
                                  const render::DrawMode& mode) {
    render::RenderConfig config;
    config.technique = &technique;
    config.mode = &mode;
    config.searchBatch = options.searchBatch;
    config.sortDraws = options.sortDraws;
    config.gsPassthrough = options.gsPassthrough;
    config.nsearch = {options.nsearchN, options.nsearchGuess, options.nsearchLinear,
                      options.nsearchSteps};
    config.visible = options.visible;
    return config;
}

std::vector<HeadlessResult>
renderHeadlessSequence(const Options& options, const scene::Scene& scene,
                       const scene::Camera& camera,
                       const std::vector<render::RenderConfig>& configs) {
    std::vector<HeadlessResult> results(configs.size());
    vk::Instance instance({options.validation, {}, options.syncValidation});
    {
        Offscreen rig(instance, options);
        vk::Device& device = rig.device;
        const VkExtent2D extent = rig.extent;
        const render::SceneTargets& targets = rig.targets;
        render::FrameSlots& slots = rig.slots;
        render::Renderer& renderer = rig.renderer;
        renderer.setScene(scene);
        Readback readback(device, extent);

        render::FrameParams params;
        params.viewProj = camera.viewProjection(float(extent.width) / float(extent.height));
        params.eye = camera.eye;
        params.partColorWeight = options.partWeight;
        params.colorizeDraws = options.colorizeDraws;
        params.ignoreMaterials = options.ignoreMaterials;
        uint64_t frameNumber = 0;
        // --animate: the exploded view at --time, else at frame / 60 s; otherwise it stays put.
        auto explodeAt = [&](uint64_t frame) {
            return options.animate ? scene::explodeLoop(options.time.value_or(float(frame) / 60))
                                   : options.explode;
        };
        // One frame that picks `pixel`, waited for: headless has nothing else to overlap.
        auto pickFrame = [&](const Options::Pixel& pixel) {
            render::FrameParams pickParams = params;
            pickParams.pickPixel = glm::uvec2(pixel.x, pixel.y);
            pickParams.explode = explodeAt(frameNumber);
            render::FrameSlot& slot = slots.begin(frameNumber++);
            renderer.record(slot, targets, pickParams);
            slots.submit(slot);
            slots.finish();
            return *slots.latestPick();
        };
        for (size_t c = 0; c < configs.size(); ++c) {
            HeadlessResult& result = results[c];
            result.width = extent.width;
            result.height = extent.height;
            result.deviceName = device.info().name;
            renderer.configure(scene, configs[c]); // the same renderer, reconfigured
            result.stats = renderer.stats();
            params.selectedPart = gpu::BACKGROUND_ID;
            params.pickPixel.reset();
            for (const auto& pixel : options.selects) {
                result.selected = pickFrame(pixel).part;
                params.selectedPart = result.selected.value_or(gpu::BACKGROUND_ID);
            }
            for (const auto& pixel : options.picks) {
                result.picks.push_back(pickFrame(pixel));
                params.pickPixel = result.picks.back().pixel;
            }
            const uint64_t timedBefore = slots.timedFrames();
            for (uint32_t frame = 0; frame < options.frames; ++frame, ++frameNumber) {
                render::FrameSlot& slot = slots.begin(frameNumber);
                params.explode = explodeAt(frameNumber);
                renderer.record(slot, targets, params);
                if (frame + 1 == options.frames) readback.record(slot.cmd, targets);
                slots.submit(slot);
            }
            slots.finish();
            const auto& gpuMs = slots.gpuMilliseconds(); // the last historyLimit at most
            const size_t timed = std::min<size_t>(slots.timedFrames() - timedBefore, gpuMs.size());
            result.gpuMs.assign(gpuMs.end() - long(timed), gpuMs.end());
            const size_t pixels = size_t(extent.width) * extent.height;
            result.color.resize(pixels * 4);
            result.ids.resize(pixels);
            std::memcpy(result.color.data(), readback.color.mapped, pixels * 4);
            std::memcpy(result.ids.data(), readback.ids.mapped, pixels * 4);
        }
    }
    for (HeadlessResult& result : results)
        result.validationMessages = instance.validationMessages();
    return results;
}

HeadlessResult renderHeadless(const Options& options, const scene::Scene& scene,
                              const scene::Camera& camera) {
    return renderHeadlessSequence(options, scene, camera, {renderConfig(options)}).front();
}

int runHeadless(const Options& options) {
    const LoadedScene loaded = loadScene(options);
    const scene::Scene& scene = loaded.scene;
    for (const auto& warning : loaded.warnings)
        std::fprintf(stderr, "idview: warning: %s: %s\n", loaded.source.c_str(), warning.c_str());
    const float aspect = float(options.width) / float(options.height);
    HeadlessResult result = renderHeadless(options, scene, initialCamera(loaded, aspect));

    if (!options.screenshot.empty())
        writePng(options.screenshot, result.width, result.height, result.color);
    if (!options.idImage.empty()) writeIdImage(options.idImage, result.ids);
    for (const auto& pick : result.picks) std::printf("%s\n", pickJson(scene, pick).c_str());

    // With picks, stdout carries only their JSON lines; the summary goes to stderr.
    std::fprintf(
        options.picks.empty() ? stdout : stderr,
        "idview: %u frames of %ux%u on %s, %s%s + %s: %zu draws, %llu triangles, %u parts, "
        "scene pass GPU median %.3f ms\n",
        options.frames, result.width, result.height, result.deviceName.c_str(),
        options.renderer.c_str(), result.stats.gsPassthrough ? " (passthrough)" : "",
        options.mode.c_str(), result.stats.draws,
        static_cast<unsigned long long>(scene.drawnTriangleCount()), scene.uniquePartCount(),
        median(result.gpuMs));
    return exitCode(result.validationMessages);
}

int exitCode(uint32_t validationMessages) {
    if (validationMessages == 0) return 0;
    std::fprintf(stderr, "idview: the validation layer reported %u messages (see above)\n",
                 validationMessages);
    return 3;
}

} // namespace app
