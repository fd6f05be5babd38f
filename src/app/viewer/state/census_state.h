// census_state.h - the viewer's visibility census (the panel's Visibility section): a census
// (app/census_run.h) drawn a few views per frame on a renderer of its own, so the window
// keeps drawing and answering; what it found; and "visible from here", a count of the
// window's own ID image by part after one of its scene passes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "app/census_run.h"
#include "render/census.h"
#include "render/frame_slots.h"
#include "render/renderer.h"
#include "scene/census.h"

namespace app {

// What a finished census found, over the scene as it was drawn (exploded where it was).
struct CensusFound {
    scene::CensusSpec spec;
    scene::Census census;
    scene::CensusSummary summary;
    scene::PartSet neverSeen; // scene::neverSeenParts
    // The scene counted, as it was drawn (exploded where it was), for Export seen...: a copy
    // sharing its arrays and B-rep, kept as the viewer's scene moves on.
    std::shared_ptr<const scene::Scene> scene;
};

// One part of the window's picture: its pixels and their share of the image.
struct HerePart {
    uint32_t part = 0;
    uint64_t pixels = 0;
    double share = 0.0;
};

class CensusState {
  public:
    // `cacheFolder`: where the census's renderer keeps the driver's pipeline cache, as the
    // window's does; `cache`: the window's renderer's, for the count's compute pipeline.
    CensusState(vk::Device& device, const vk::ShaderCompiler& compiler,
                std::filesystem::path cacheFolder, const render::DiskPipelineCache& cache);
    ~CensusState();
    CensusState(const CensusState&) = delete;
    CensusState& operator=(const CensusState&) = delete;

    // Starts a census of `spec` over `atRest` (as the window's renderer holds it) drawn with
    // `render` single-sampled at full detail (as `idview --census` draws), `hidden` not drawn,
    // the objects exploded by `explode`; `bounds`: of the scene as drawn (exploded). Its
    // renderer and scene upload are made here, once per start (a pipeline the cache lacks is
    // compiled here too). A census running is replaced.
    void start(scene::CensusSpec spec, const scene::Scene& atRest, const scene::Bounds& bounds,
               render::RenderSettings render, const scene::PartSet& hidden, float explode);
    // Stops the census running (its views in flight finish on their own); false if none ran.
    bool cancel();
    bool running() const { return run_ != nullptr; }
    uint32_t viewsDrawn() const { return run_ ? run_->viewsDrawn() : 0; }
    uint32_t views() const { return run_ ? run_->views() : 0; }
    // Once per viewer frame: records views for about `budgetMs` of the CPU's time, never
    // waiting for a fence (a view whose slot is still busy waits for the next frame). True
    // when the census finished here: found() holds its answer over `drawn` (the scene as
    // the window draws it, exploded where it is).
    bool step(double budgetMs, const scene::Scene& drawn);
    const std::optional<CensusFound>& found() const { return found_; }
    // A new scene: the census running stops, what was found and counted here goes.
    void forget();

    // Tint by visibility (visibility_tint.h), on or off over census runs. tintColors: what
    // the window's renderer draws (Renderer::setTint), empty while off or before a census
    // has finished; tintVersion counts its changes (a toggle, a census started or done).
    void setTint(bool on);
    bool tint() const { return tint_; }
    std::vector<uint32_t> tintColors() const;
    uint64_t tintVersion() const { return tintVersion_; }

    // "Visible from here": after a scene pass into `targets` recorded in `slot` (frame
    // `frame`), counts its ID image's parts; hereReady() once that frame has finished.
    void recordHere(render::FrameSlot& slot, const render::SceneTargets& targets, uint32_t parts,
                    uint64_t frame);
    bool hereWaiting() const { return hereFrame_.has_value(); }
    // Once the counted frame has finished (slots.finished): the parts, largest first.
    bool hereReady(const render::FrameSlots& slots);
    const std::vector<HerePart>& here() const { return here_; }

  private:
    vk::Device& device_;
    const vk::ShaderCompiler& compiler_;
    std::filesystem::path cacheFolder_;
    const render::DiskPipelineCache& cache_;
    std::unique_ptr<render::Renderer> renderer_; // the census's own (census_state.cpp says why)
    std::unique_ptr<render::CensusPass> pass_;
    std::unique_ptr<CensusRun> run_;
    scene::CensusSpec spec_;
    scene::PartSet hidden_;
    uint64_t next_ = 0; // the census's frame numbers in slots_
    std::optional<uint64_t> hereFrame_;
    std::shared_ptr<const render::CensusCounters> hereCounters_;
    VkExtent2D hereExtent_{};
    std::vector<HerePart> here_;
    std::optional<CensusFound> found_;
    bool tint_ = false;
    uint64_t tintVersion_ = 0;
    std::unique_ptr<render::FrameSlots> slots_; // last: destroyed first, waiting for its frames
    const render::CensusPass& pass();
};

} // namespace app
