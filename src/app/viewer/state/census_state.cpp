// census_state.cpp - the viewer's census and "visible from here" (census_state.h).
//
// The census draws on a renderer of its own, not the window's. The window's renderer keeps
// state of the targets it drew last: the culling history and the view a still frame compares
// with, the composition a frame at rest redraws from (Renderer::Composed) and the compute
// rasterizer's samples, sized for the targets last drawn, which a composition at rest reads.
// A census view between two window frames would leave the window composing from samples of
// the census's square targets. It would also draw with the window's technique, MSAA and
// levels of detail, where the census draws as `idview --census` does (censusSettings), so
// the two answer alike. The cost: the scene's upload and pipelines once more per start.
// Its frames go through slots of their own too: the window's frame numbers key its picks and
// view matrices, and its GPU times feed the title and the Timing section.
#include "app/viewer/state/census_state.h"

#include <algorithm>
#include <chrono>

#include "app/viewer/state/visibility_tint.h"

namespace app {

CensusState::CensusState(vk::Device& device, const vk::ShaderCompiler& compiler,
                         std::filesystem::path cacheFolder, const render::DiskPipelineCache& cache)
    : device_(device), compiler_(compiler), cacheFolder_(std::move(cacheFolder)), cache_(cache) {}

CensusState::~CensusState() = default;

const render::CensusPass& CensusState::pass() {
    if (!pass_) pass_ = std::make_unique<render::CensusPass>(device_, compiler_, cache_);
    return *pass_;
}

void CensusState::start(scene::CensusSpec spec, const scene::Scene& atRest,
                        const scene::Bounds& bounds, render::RenderSettings render,
                        const scene::PartSet& hidden, float explode) {
    cancel();
    found_.reset();
    ++tintVersion_;
    render = censusSettings(render, device_, false); // as `idview --census` draws
    if (slots_) slots_->finish();                    // the old renderer's frames, before it goes
    renderer_ = std::make_unique<render::Renderer>(device_, compiler_, cacheFolder_);
    renderer_->setScene(atRest, render);
    renderer_->setHidden(hidden);
    renderer_->setSelection(scene::PartSet(atRest.uniquePartCount()));
    if (!slots_) slots_ = std::make_unique<render::FrameSlots>(device_);
    spec_ = spec;
    hidden_ = hidden;
    run_ = std::make_unique<CensusRun>(device_, *renderer_, pass(), atRest.uniquePartCount(),
                                       bounds, spec, explode);
}

bool CensusState::cancel() {
    if (!run_) return false;
    run_.reset(); // the slots keep its targets and counters until their views are done
    return true;
}

bool CensusState::step(double budgetMs, const scene::Scene& drawn) {
    if (!run_) return false;
    const auto start = std::chrono::steady_clock::now();
    auto spent = [&] {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count();
    };
    const uint64_t slotCount = render::FrameSlots::count;
    while (!run_->done() && spent() < budgetMs &&
           (next_ < slotCount || slots_->finished(next_ - slotCount)))
        run_->step(*slots_, next_++);
    if (!run_->done() || !slots_->finished(next_ - 1)) return false;
    CensusFound found{spec_, run_->result(), {}, {}, std::make_shared<const scene::Scene>(drawn)};
    found.summary = scene::summarize(drawn, found.census, hidden_);
    found.neverSeen = scene::neverSeenParts(drawn, found.census, hidden_);
    found_ = std::move(found);
    ++tintVersion_;
    run_.reset();
    return true;
}

void CensusState::forget() {
    cancel();
    found_.reset();
    ++tintVersion_;
    here_.clear();
    hereFrame_.reset();
    hereCounters_.reset();
}

void CensusState::setTint(bool on) {
    if (on == tint_) return;
    tint_ = on;
    ++tintVersion_;
}

std::vector<uint32_t> CensusState::tintColors() const {
    if (!tint_ || !found_) return {};
    return visibilityTint(found_->census, found_->neverSeen);
}

void CensusState::recordHere(render::FrameSlot& slot, const render::SceneTargets& targets,
                             uint32_t parts, uint64_t frame) {
    auto counters = std::make_shared<render::CensusCounters>(device_, parts);
    pass().record(slot.cmd, targets, *counters, true, true);
    slot.keep(counters);
    hereCounters_ = std::move(counters);
    hereExtent_ = targets.extent();
    hereFrame_ = frame;
}

bool CensusState::hereReady(const render::FrameSlots& slots) {
    if (!hereFrame_ || !slots.finished(*hereFrame_)) return false;
    const std::vector<gpu::CensusTotals> totals = hereCounters_->totals();
    const double image = double(hereExtent_.width) * hereExtent_.height;
    here_.clear();
    for (uint32_t part = 0; part < totals.size(); ++part)
        if (totals[part].pixels > 0)
            here_.push_back({part, totals[part].pixels, double(totals[part].pixels) / image});
    std::stable_sort(here_.begin(), here_.end(),
                     [](const HerePart& a, const HerePart& b) { return a.pixels > b.pixels; });
    hereFrame_.reset();
    hereCounters_.reset();
    return true;
}

} // namespace app
