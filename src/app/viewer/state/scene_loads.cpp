// scene_loads.cpp - opening models on a worker thread while the window goes on: the model
// given at start and dropped ones, one at a time; a big CAD file's partial scenes drawn as
// they come (progressive.h), and what Stop, Cancel and a failure leave drawn.
#include <cstdio>

#include "app/viewer/state/scene_state.h"
#include "scene/bounds.h"
#include "scene/inspect.h"

namespace app {
namespace {

using Clock = std::chrono::steady_clock;

} // namespace

LoadedScene SceneState::nothingOpen() {
    // An object whose one part has no triangles: what a CAD file's first partial scene is
    // made of, so the renderer and every CPU answer already take it (scene.h).
    LoadedScene nothing;
    scene::Scene& scene = nothing.scene;
    scene.parts.push_back({});
    scene::Geometry geometry;
    geometry.name = "nothing";
    geometry.partCount = 1;
    scene.geometries.push_back(geometry);
    scene::addMaterial(scene, "nothing", glm::vec4(0.7f, 0.7f, 0.7f, 1.0f));
    scene::addObject(scene, 0, 0, glm::dmat4(1.0), "nothing", "nothing");
    return nothing;
}

void SceneState::startOpen(const std::string& path, const SceneSettings& settings) {
    SceneSettings wanted = settings;
    wanted.model = path;
    wanted.builtin.clear();
    queued_.push_back(wanted);
    launchNext();
}

void SceneState::launchNext() {
    if (pending_ || queued_.empty()) return;
    SceneSettings single = queued_.front();
    single.copies = 1;
    // Loading touches no Vulkan object and nothing the frames use: safe on its own thread.
    auto progress = std::make_shared<LoadProgress>();
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    auto partials = std::make_shared<PartialSlot>();
    auto load = [single, progress, cancel, partials] {
        return loadScene(single, progress.get(), cancel.get(),
                         [partials](const scene::CadPartial& partial) { partials->put(partial); });
    };
    pending_ = PendingOpen{std::async(std::launch::async, std::move(load)),
                           queued_.front(),
                           Clock::now(),
                           progress,
                           cancel,
                           partials,
                           std::exchange(startModel_, false)};
    queued_.pop_front();
}

SceneState::Change SceneState::poll(SceneSettings& settings) {
    using namespace std::chrono_literals;
    if (!pending_) return Change::None;
    if (pending_->scene.wait_for(0s) == std::future_status::ready) return finishOpen(settings);
    // After Stop or Cancel what is drawn stays until the load has ended.
    if (pending_->ending != PendingOpen::Ending::Load || !uploads_.due(Clock::now()))
        return Change::None;
    std::optional<scene::CadPartial> partial = pending_->partials->take();
    return partial ? showPartial(std::move(*partial), settings) : Change::None;
}

// The partial scene replaces what is drawn; the model drawn before its first one is kept for
// Cancel. A partial the renderer refuses is skipped: the next, or the whole model, may fit.
SceneState::Change SceneState::showPartial(scene::CadPartial partial, SceneSettings& settings) {
    PendingOpen& open = *pending_;
    const auto start = Clock::now();
    LoadedScene loaded;
    loaded.scene = *partial.scene;
    partial.scene.reset(); // base_ holds the scene drawn
    loaded.scene.unit = scene::cadUnit(open.settings.model);
    loaded.scene.precision = scene::scenePrecision(loaded.scene); // as loadScene sets it
    loaded.source = open.settings.model;
    loaded.cad = true;
    loaded.settings = open.settings;
    loaded.settings.copies = 1; // made once the model is whole (apply waits)
    try {
        renderer_.setScene(loaded.scene, renderer_.settings());
    } catch (const std::exception& e) {
        fail(e.what());
        return Change::None;
    }
    const bool first = !open.shown;
    if (first && hasModel())
        before_ = Drawn{std::move(base_), std::move(copies_), std::move(partial_),
                        std::move(incomplete_)};
    incomplete_.clear();
    base_ = std::move(loaded);
    copies_.reset();
    partial_ = std::move(partial);
    open.shown = shownAny_ = true;
    sceneChanged();
    const auto end = Clock::now();
    uploads_.uploaded(start, end);
    tellPartial(open, first, std::chrono::duration<double, std::milli>(end - start).count());
    if (!first) return Change::Grown;
    settings = open.settings;
    return Change::Model;
}

void SceneState::tellPartial(PendingOpen& open, bool first, double uploadMs) {
    const double seconds = std::chrono::duration<double>(Clock::now() - open.start).count();
    const scene::CadPartial& p = *partial_;
    const util::Fixed after{seconds, 2};
    if (first)
        events_.say("loading", [&](util::JsonWriter& j) {
            j.member("state", "assembly").member("objects", base_.scene.objects.size());
            j.member("shown", p.solidsReady).member("of", p.solidsTotal).member("seconds", after);
        });
    events_.say("loading", [&](util::JsonWriter& j) {
        j.member("state", "partial").member("shown", p.solidsReady).member("of", p.solidsTotal);
        j.member("lost", p.solidsLost).member("upload_ms", util::Fixed{uploadMs, 1});
        j.member("seconds", after);
    });
    if (open.saidSolids || p.solidsReady == 0) return;
    open.saidSolids = true;
    events_.say("loading", [&](util::JsonWriter& j) {
        j.member("state", "shown").member("shown", p.solidsReady).member("of", p.solidsTotal);
        j.member("seconds", after);
    });
}

SceneState::Change SceneState::finishOpen(SceneSettings& settings) {
    PendingOpen done = std::move(*pending_);
    pending_.reset();
    launchNext();
    std::optional<LoadedScene> loaded;
    std::string error;
    try {
        loaded.emplace(done.scene.get());
    } catch (const std::exception& e) {
        error = e.what(); // one line naming the file
    }
    return loaded ? whole(done, std::move(*loaded), settings) : ended(done, error, settings);
}

// The model has loaded: it replaces what is drawn, its last partial scene included (the same
// part IDs: Grown), even where Stop or Cancel came too late to stop it.
SceneState::Change SceneState::whole(PendingOpen& done, LoadedScene loaded,
                                     SceneSettings& settings) {
    try {
        use(std::move(loaded), done.settings, renderer_.settings());
    } catch (const std::exception& e) {
        done.ending = PendingOpen::Ending::Load; // a failure, whatever was asked
        return ended(done, e.what(), settings);
    }
    if (done.shown) {
        const double seconds = std::chrono::duration<double>(Clock::now() - done.start).count();
        events_.say("loading", [&](util::JsonWriter& j) {
            j.member("state", "complete").member("objects", base_.scene.objects.size());
            j.member("seconds", util::Fixed{seconds, 2});
        });
    }
    partial_.reset();
    incomplete_.clear();
    before_.reset();
    shownAny_ = true;
    if (!done.first) opened(); // the model given at start opens without a line, as it did
    settings = done.settings;
    if (!done.shown) return Change::Model;
    return done.settings.copies > 1 ? Change::Copies : Change::Grown;
}

// A load that ended without its model: Stop keeps what it showed, marked incomplete; Cancel
// and failures go back to what was drawn before it. The model given at start failing ends
// the viewer with its message (firstFailure), as it did when it was loaded before the window.
SceneState::Change SceneState::ended(PendingOpen& done, const std::string& error,
                                     SceneSettings& settings) {
    if (done.ending == PendingOpen::Ending::Stop) {
        if (!done.shown) {
            events_.say("loading", [](util::JsonWriter& j) {
                j.member("state", "stopped").member("shown", 0);
            });
            return Change::None;
        }
        before_.reset();
        incomplete_ = missingLine(*partial_);
        const scene::CadPartial& p = *partial_;
        events_.say("loading", [&](util::JsonWriter& j) {
            j.member("state", "stopped").member("shown", p.solidsReady).member("of", p.solidsTotal);
            j.member("missing", p.solidsTotal - p.solidsReady);
        });
        return Change::None;
    }
    if (done.ending == PendingOpen::Ending::Load && done.first) {
        firstFailure_ = error;
        return Change::None;
    }
    fail(error); // "<file>: cancelled" after Cancel
    if (done.ending == PendingOpen::Ending::Cancel)
        events_.say("loading", [&](util::JsonWriter& j) {
            j.member("state", "cancelled");
            j.member("after", !done.shown ? "nothing shown" : before_ ? "back" : "nothing open");
            j.member("back_to",
                     before_ && done.shown ? std::optional(before_->base.source) : std::nullopt);
        });
    return done.shown ? restoreBefore(done.settings, settings) : Change::None;
}

SceneState::Change SceneState::restoreBefore(const SceneSettings& loadSettings,
                                             SceneSettings& settings) {
    const bool hadModel = before_.has_value();
    Drawn back = hadModel ? std::move(*before_) : Drawn{nothingOpen(), {}, {}, {}};
    before_.reset();
    if (!hadModel) back.base.settings = loadSettings; // nothing open: apply() asks for nothing
    try {
        renderer_.setScene(back.copies ? *back.copies : back.base.scene, renderer_.settings());
    } catch (const std::exception& e) {
        fail(e.what()); // the partial scene stays, as after Stop
        incomplete_ = missingLine(*partial_);
        return Change::None;
    }
    partial_ = std::move(back.partial);
    incomplete_ = std::move(back.incomplete);
    base_ = std::move(back.base);
    copies_ = std::move(back.copies);
    sceneChanged();
    settings = base_.settings;
    return Change::Restored;
}

void SceneState::cancelOpen() {
    endOpen(PendingOpen::Ending::Cancel);
}

void SceneState::stopOpen() {
    endOpen(PendingOpen::Ending::Stop);
}

void SceneState::endOpen(PendingOpen::Ending ending) {
    queued_.clear();
    if (!pending_ || pending_->ending != PendingOpen::Ending::Load) return;
    pending_->ending = ending;
    *pending_->cancel = true; // the loading thread kills its workers within a poll
}

std::optional<SceneState::Loading> SceneState::loading() const {
    if (!pending_) return std::nullopt;
    const auto [stage, fraction] = pending_->progress->get();
    Loading loading;
    loading.path = sourceOf(pending_->settings);
    loading.seconds = std::chrono::duration<double>(Clock::now() - pending_->start).count();
    loading.stage = stage;
    loading.fraction = fraction;
    if (pending_->shown && partial_) {
        loading.shown = shownLine(*partial_);
        loading.solidsShown = partial_->solidsReady;
    }
    loading.modelBefore = pending_->shown ? before_.has_value() : hasModel();
    loading.stopping = pending_->ending != PendingOpen::Ending::Load;
    return loading;
}

scene::Bounds SceneState::extent() const {
    if (partial_) {
        const scene::Bounds boxes = extentOf(partial_->boxes);
        if (!scene::isEmpty(boxes)) return boxes;
    }
    return atRest().bounds();
}

void SceneState::opened() {
    const scene::Scene& scene = atRest();
    events_.say("opened", [&](util::JsonWriter& j) {
        j.member("path", base_.source).member("objects", scene.objects.size());
        j.member("parts", scene.uniquePartCount()).member("triangles", scene.drawnTriangleCount());
    });
}

} // namespace app
