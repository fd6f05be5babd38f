// headless.cpp - the frame loop without a window, and image readback.
#include "app/headless.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "app/image_io.h"
#include "app/json.h"
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

std::string pickJson(const scene::Scene& scene, const render::PickReading& pick) {
    char head[64];
    std::snprintf(head, sizeof head, "{\"x\":%u,\"y\":%u,", pick.pixel.x, pick.pixel.y);
    const auto info = pick.part ? scene::describePart(scene, *pick.part) : std::nullopt;
    if (!info)
        return std::string(head) + "\"part\":null,\"object\":null,\"local_part\":null,"
                                   "\"name\":null,\"path\":null,\"depth\":null}";
    char ids[96], depth[48];
    std::snprintf(ids, sizeof ids, "\"part\":%u,\"object\":%u,\"local_part\":%u,",
                  info->uniquePartId, info->object, info->localPart);
    std::snprintf(depth, sizeof depth, ",\"depth\":%.9g}", double(pick.depth));
    return std::string(head) + ids + "\"name\":" + jsonString(info->name) +
           ",\"path\":" + jsonString(info->path) + depth;
}

namespace {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

} // namespace

render::FrameParams cameraFrame(const scene::Camera& camera, VkExtent2D extent) {
    render::FrameParams params;
    params.viewProj = camera.viewProjection(float(extent.width) / float(extent.height));
    params.eye = camera.eye;
    return params;
}

float explodeAt(const Animation& animation, uint64_t frame) {
    return animation.animate ? scene::explodeLoop(animation.time.value_or(float(frame) / 60))
                             : animation.explode;
}

std::vector<HeadlessResult>
renderHeadlessSequence(const Options& options, const scene::Scene& scene,
                       const scene::Camera& camera,
                       const std::vector<render::RenderSettings>& settings) {
    std::vector<HeadlessResult> results(settings.size());
    vk::Instance instance({options.validation, {}, options.syncValidation});
    {
        Offscreen rig(instance, options);
        vk::Device& device = rig.device;
        render::FrameSlots& slots = rig.slots;
        render::Renderer& renderer = rig.renderer;
        Readback readback(device, rig.extent);
        render::FrameParams params = cameraFrame(camera, rig.extent);
        uint64_t frameNumber = 0;
        // One frame that picks `pixel`, waited for: headless has nothing else to overlap.
        auto pickFrame = [&](const Options::Pixel& pixel) {
            render::FrameParams pickParams = params;
            pickParams.pickPixel = glm::uvec2(pixel.x, pixel.y);
            pickParams.explode = explodeAt(options.animation, frameNumber);
            render::FrameSlot& slot = slots.begin(frameNumber++);
            renderer.record(slot, rig.targets, pickParams);
            slots.submit(slot);
            slots.finish();
            return *slots.latestPick();
        };
        for (size_t c = 0; c < settings.size(); ++c) {
            HeadlessResult& result = results[c];
            result.width = rig.extent.width;
            result.height = rig.extent.height;
            result.deviceName = device.info().name;
            // The same renderer, switched.
            if (c == 0)
                renderer.setScene(scene, settings[c]);
            else
                renderer.configure(scene, settings[c]);
            rig.useMsaa(settings[c].pipeline.msaa);
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
                params.explode = explodeAt(options.animation, frameNumber);
                renderer.record(slot, rig.targets, params);
                if (frame + 1 == options.frames) readback.record(slot.cmd, *rig.targets);
                slots.submit(slot);
            }
            slots.finish();
            const auto& gpuMs = slots.gpuMilliseconds(); // the last historyLimit at most
            const size_t timed = std::min<size_t>(slots.timedFrames() - timedBefore, gpuMs.size());
            result.gpuMs.assign(gpuMs.end() - long(timed), gpuMs.end());
            result.color = readback.colorBytes();
            result.ids = readback.idValues();
        }
    }
    for (HeadlessResult& result : results)
        result.validationMessages = instance.validationMessages();
    return results;
}

HeadlessResult renderHeadless(const Options& options, const scene::Scene& scene,
                              const scene::Camera& camera) {
    return renderHeadlessSequence(options, scene, camera, {options.render}).front();
}

int runHeadless(const Options& options) {
    const LoadedScene loaded = loadScene(options.scene);
    const scene::Scene& scene = loaded.scene;
    for (const auto& warning : loaded.warnings)
        std::fprintf(stderr, "idview: warning: %s: %s\n", loaded.source.c_str(), warning.c_str());
    const float aspect = float(options.width) / float(options.height);
    HeadlessResult result = renderHeadless(options, scene, initialCamera(loaded, aspect));
    const render::PipelineKey& key = options.render.pipeline;

    if (!options.screenshot.empty())
        writePng(options.screenshot, result.width, result.height, result.color);
    if (!options.idImage.empty()) writeIdImage(options.idImage, result.ids);
    for (const auto& pick : result.picks) std::printf("%s\n", pickJson(scene, pick).c_str());

    // With picks, stdout carries only their JSON lines; the summary goes to stderr.
    std::fprintf(
        options.picks.empty() ? stdout : stderr,
        "idview: %u frames of %ux%u on %s, %s%s + %s: %zu draws, %llu triangles, %u parts, "
        "scene pass GPU median %.3f ms\n",
        options.frames, result.width, result.height, result.deviceName.c_str(), key.technique->name,
        result.stats.gsPassthrough ? " (passthrough)" : "", key.mode->name, result.stats.draws,
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
