// census_run.h - drawing a visibility census view by view through a renderer: each view's
// scene pass into square single-sampled targets of its own, then the census pass over the
// ID image (render/census.h). A headless run draws every view at once; the viewer draws a
// few per frame, so it can show progress and stop half-way.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <vector>

#include "render/census.h"
#include "render/frame_slots.h"
#include "render/renderer.h"
#include "scene/census.h"

namespace app {

// What a census draws with, headless and in the viewer alike: `render` single-sampled (one ID
// per pixel) at full detail (a coarser level could show or hide a part the model has), and
// unless `keepPipeline` (--renderer or --mode given) the configuration that drew it fastest
// on the H200 (docs/census.md: visbuffer-compute, 3.6x faster than vertex-fs at 162 views of
// 1024x1024) where the device has mesh shaders, else the viewer's default.
render::RenderSettings censusSettings(render::RenderSettings render, const vk::Device& device,
                                      bool keepPipeline);

class CensusRun {
  public:
    // `renderer` has the scene set and is configured with what the census should draw: the
    // section, the hidden parts (headless runs configure it single-sampled at full detail;
    // the targets take its MSAA setting). `bounds`: of the
    // scene as drawn (exploded by `explode`), which every view holds.
    CensusRun(vk::Device& device, render::Renderer& renderer, const render::CensusPass& pass,
              uint32_t parts, const scene::Bounds& bounds, scene::CensusSpec spec, float explode);

    uint32_t views() const { return uint32_t(directions_.size()); }
    uint32_t viewsDrawn() const { return next_; }
    bool done() const { return next_ == directions_.size(); }
    // Records the next view into the slot of frame `frameNumber` and submits it; `after`,
    // if given, records more into the slot after the census pass (tests copy the ID image).
    void step(render::FrameSlots& slots, uint64_t frameNumber,
              const std::function<void(VkCommandBuffer)>& after = {});
    const render::SceneTargets& targets() const { return *targets_; }
    // The camera of view `view` (0 to views() - 1).
    scene::Camera camera(uint32_t view) const;
    // Once done() and the last view's frame has finished: what the census found.
    scene::Census result() const;

  private:
    render::Renderer& renderer_;
    const render::CensusPass& pass_;
    std::vector<glm::dvec3> directions_;
    scene::Bounds bounds_;
    float explode_;
    std::shared_ptr<const render::SceneTargets> targets_;
    std::shared_ptr<const render::CensusCounters> counters_;
    uint32_t next_ = 0;
    std::chrono::steady_clock::time_point start_;
};

} // namespace app
