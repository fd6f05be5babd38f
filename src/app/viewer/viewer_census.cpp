// viewer_census.cpp - the Visibility section's census in the viewer (census_state.h): the
// `census` command, a few views per frame, "visible from here" after a scene pass, Export
// seen... (census_export.h), and their event records.
#include <algorithm>
#include <stdexcept>

#include "app/viewer/commands/commands.h"
#include "app/viewer/viewer.h"

namespace app {
namespace {

// The CPU's recording time a frame gives the census: the window keeps drawing at about
// 30 frames a second while it runs (the views' GPU work is not waited for).
constexpr double censusBudgetMs = 20.0;

} // namespace

void Viewer::census(const CensusAsk& ask) {
    const CensusFound* found = census_.found() ? &*census_.found() : nullptr;
    switch (ask.action) {
    case CensusAction::Run:
        return startCensus({ask.views, ask.size});
    case CensusAction::Cancel:
        return cancelCensus();
    case CensusAction::Part: {
        const uint32_t count = scene_.scene().uniquePartCount();
        if (ask.part >= count)
            throw CommandError("census part " + std::to_string(ask.part) +
                               ": the scene's parts are 0 to " + std::to_string(count - 1));
        scene::PartSet one(count);
        one.insert(ask.part);
        document_.select(one, SelectMode::Replace);
        selectionChanged();
        return;
    }
    case CensusAction::Here:
        hereAsked_ = true;
        redrawNext_ = true; // counted after a scene pass, whose ID image is the window's
        return;
    case CensusAction::Tint:
        census_.setTint(ask.on);
        events_.say("census", [&](util::JsonWriter& j) {
            j.member("state", "tint").member("on", ask.on).member("census", found != nullptr);
        });
        return;
    default:
        break;
    }
    if (!found) throw CommandError("no census has finished yet (census VIEWSxSIZE runs one)");
    if (ask.action == CensusAction::Export) return exportCensus(ask.path);
    if (ask.action == CensusAction::Select) {
        document_.select(found->neverSeen, SelectMode::Replace);
        selectionChanged();
        return;
    }
    scene::PartSet hide = found->neverSeen;
    if (ask.action == CensusAction::Isolate) hide.invert(); // everything else
    document_.hide(hide);
    selectionChanged(); // hidden parts are not selected
    partsChanged();
}

// Export seen...: refused here in its line (a STEP of a mesh, one still writing), else
// written on the export's worker from the scene the census counted.
void Viewer::exportCensus(const std::string& path) {
    const CensusFound& found = *census_.found();
    const LoadedScene& loaded = scene_.loaded();
    try {
        if (censusExport_.writing())
            throw std::runtime_error(path + ": an export is still being written");
        checkExteriorExport(path, *found.scene, loaded.source);
    } catch (const std::exception& e) {
        return sayExported(censusExport_.refuse(path, e.what()));
    }
    censusExport_.start(
        {path, found.scene, found.census, loaded.settings.model, loaded.settings.cad.healing});
}

void Viewer::sayExported(const ExportOutcome& outcome) {
    events_.say("census_export", [&](util::JsonWriter& j) {
        j.member("path", outcome.path);
        if (!outcome.written) {
            j.member("error", outcome.error);
            return;
        }
        j.member("parts", outcome.written->parts).member("objects", outcome.written->objects);
        j.member("replaced", outcome.replaced);
    });
}

void Viewer::startCensus(scene::CensusSpec spec) {
    render::RenderSettings render = settings_.render;
    render.section = document_.section();
    const float explode = settings_.animation.animate ? 0.0f : document_.explode();
    try {
        census_.start(spec, scene_.atRest(), scene_.scene().bounds(), render,
                      document_.selection().hidden(), explode);
    } catch (const std::exception& e) {
        throw CommandError(std::string("census: ") + e.what());
    }
    events_.say("census", [&](util::JsonWriter& j) {
        j.member("state", "started").member("views", spec.views).member("size", spec.size);
    });
}

void Viewer::cancelCensus() {
    const uint32_t drawn = census_.viewsDrawn(), views = census_.views();
    if (!census_.cancel()) return;
    events_.say("census", [&](util::JsonWriter& j) {
        j.member("state", "cancelled").member("views_drawn", drawn).member("views", views);
    });
}

// Each frame, after the window's: the census's next views, the answers that came.
void Viewer::stepCensus() {
    if (census_.step(censusBudgetMs, scene_.scene())) {
        const CensusFound& found = *census_.found();
        const scene::CensusSummary& sum = found.summary;
        events_.say("census", [&](util::JsonWriter& j) {
            j.member("state", "done").member("views", found.census.views);
            j.member("size", found.census.width).member("parts", sum.parts);
            j.member("seen", sum.partsSeen).member("never_seen", sum.partsNeverSeen);
            j.member("hidden", sum.partsHidden).member("empty", sum.partsEmpty);
            j.member("solids_never_seen", sum.objectsNeverSeen);
            j.member("triangles", sum.triangles);
            j.member("triangles_never_seen", sum.trianglesNeverSeen);
        });
    }
    if (const auto outcome = censusExport_.take()) sayExported(*outcome);
    if (!census_.hereReady(slots_)) return;
    events_.say("census_here", [&](util::JsonWriter& j) {
        j.member("count", census_.here().size()).beginArray("parts");
        for (const HerePart& part : census_.here()) j.value(part.part);
        j.endArray().beginArray("pixels");
        for (const HerePart& part : census_.here()) j.value(part.pixels);
        j.endArray();
    });
}

// Hands the tint by visibility to the window's renderer once per change: a toggle, a census
// started (its old colours go) or done (the new ones come, when on), a new scene.
void Viewer::showTint() {
    if (drawnTint_ == census_.tintVersion()) return;
    const std::vector<uint32_t> colors = census_.tintColors();
    drawnTint_ = census_.tintVersion();
    if (colors.empty() && !tintShown_) return; // off, and it was
    scene_.renderer().setTint(colors);
    tintShown_ = !colors.empty();
    redrawNext_ = true;
    const auto tinted = std::count_if(colors.begin(), colors.end(), [](uint32_t c) { return c; });
    events_.say("tint", [&](util::JsonWriter& j) { j.member("parts", uint64_t(tinted)); });
}

// After the frame's scene pass: `census here` counts its ID image.
void Viewer::countHere(render::FrameSlot& slot, bool scenePass) {
    if (!hereAsked_ || !scenePass) return;
    census_.recordHere(slot, *scene_.targets(), scene_.scene().uniquePartCount(), frameNumber_);
    hereAsked_ = false;
}

} // namespace app
