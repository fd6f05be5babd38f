// census_run.cpp - a census's views, one frame each (see census_run.h).
#include "app/census_run.h"

#include <chrono>

#include "app/camera_frame.h"
#include "app/cli.h"
#include "render/technique.h"

namespace app {

namespace {
constexpr const char* kCensusTechnique = "visbuffer-compute";
} // namespace

render::RenderSettings censusSettings(render::RenderSettings render, const vk::Device& device,
                                      bool keepPipeline) {
    render.pipeline.msaa = 1;
    render.lod.errorPixels = 0.0f;
    if (keepPipeline) return render;
    const render::PipelineKey viewer = viewerDefaults().live.render.pipeline;
    render.pipeline.technique =
        device.info().meshShader ? render::findTechnique(kCensusTechnique) : viewer.technique;
    render.pipeline.mode = viewer.mode;
    return render;
}

CensusRun::CensusRun(vk::Device& device, render::Renderer& renderer, const render::CensusPass& pass,
                     uint32_t parts, const scene::Bounds& bounds, scene::CensusSpec spec,
                     float explode)
    : renderer_(renderer), pass_(pass), directions_(scene::censusDirections(spec.views)),
      bounds_(bounds), explode_(explode),
      targets_(std::make_shared<render::SceneTargets>(
          device, renderer.pass(renderer.settings().pipeline.msaa),
          VkExtent2D{spec.size, spec.size})),
      counters_(std::make_shared<render::CensusCounters>(device, parts)) {}

scene::Camera CensusRun::camera(uint32_t view) const {
    return scene::censusCamera(bounds_, directions_[view]);
}

void CensusRun::step(render::FrameSlots& slots, uint64_t frameNumber,
                     const std::function<void(VkCommandBuffer)>& after) {
    if (done()) return;
    if (next_ == 0) start_ = std::chrono::steady_clock::now();
    const uint32_t view = next_++;
    render::FrameParams params = cameraFrame(camera(view), targets_->extent());
    params.explode = explode_;
    render::FrameSlot& slot = slots.begin(frameNumber);
    renderer_.record(slot, targets_, params);
    pass_.record(slot.cmd, *targets_, *counters_, view == 0, done());
    if (after) after(slot.cmd);
    slot.keep(counters_);
    slots.submit(slot);
}

scene::Census CensusRun::result() const {
    scene::Census census;
    census.views = views();
    census.width = targets_->extent().width;
    census.height = targets_->extent().height;
    census.parts = counters_->totals();
    census.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_)
                    .count();
    return census;
}

} // namespace app
