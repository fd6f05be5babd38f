// scene_state.cpp - applying settings: renderer configuration, MSAA targets, model copies and
// opening scenes. A failure keeps what worked before.
#include "app/viewer/state/scene_state.h"

#include <algorithm>
#include <cstdio>

#include "app/pipeline_cache_file.h"
#include "scene/explode.h"
#include "vk/check.h"

namespace app {

SceneState::SceneState(vk::Device& device, const vk::ShaderCompiler& compiler, const Events& events,
                       const LiveSettings& settings, VkExtent2D extent)
    : device_(device), events_(events),
      renderer_(device, compiler, pipelineCacheFolder(settings.scene)),
      sampleCounts_(render::supportedSampleCounts(device)) {
    const uint32_t msaa = settings.render.pipeline.msaa;
    targets_ = std::make_shared<render::SceneTargets>(device, renderer_.pass(msaa), extent);
    // The window opens at once, drawing nothing until the model comes; the renderer is
    // configured now, so a device or technique that cannot be used ends the run as headless.
    LoadedScene nothing = nothingOpen();
    nothing.settings = settings.scene; // what is being opened: apply() leaves it to the load
    renderer_.setScene(nothing.scene, settings.render);
    base_ = std::move(nothing);
    sceneChanged();
    queued_.push_back(settings.scene);
    launchNext();
}

void SceneState::fail(const std::string& message) {
    error_ = message; // shown in the panel
    Events::problem(message);
}

SceneState::Change SceneState::apply(SceneSettings& wanted, render::RenderSettings& render) {
    Change change = Change::None;
    const SceneSettings& drawn = base_.settings;
    // A model shown as it loads keeps its settings until it is whole: its copies would be
    // placed by the extent of the solids meshed so far, which grows with each one.
    const bool growing = pending_ && pending_->shown;
    if (!growing && (wanted.model != drawn.model || wanted.builtin != drawn.builtin ||
                     wanted.parts != drawn.parts || wanted.lodLevels != drawn.lodLevels)) {
        if (openScene(wanted))
            change = Change::Model;
        else
            wanted = drawn; // the scene drawn stays, and so do its settings
    }
    if (!growing && (wanted.copies != drawn.copies || wanted.copyAxes != drawn.copyAxes)) {
        if (setCopies(wanted.copies, wanted.copyAxes))
            change = std::max(change, Change::Copies);
        else
            wanted = drawn;
    }
    renderer_.collectBuilds();
    if (render != renderer_.settings())
        configure(render);
    else
        settingsWait_.reset(); // switched back to what is drawn before its build was done
    return change;
}

bool SceneState::openScene(const SceneSettings& settings) {
    try {
        load(settings, renderer_.settings());
    } catch (const std::exception& e) {
        fail(e.what()); // one line naming the file; the previous scene stays
        return false;
    }
    opened();
    return true;
}

// The model alone is loaded; the copies are made here, so changing them needs no reload.
void SceneState::load(const SceneSettings& settings, const render::RenderSettings& render) {
    SceneSettings single = settings;
    single.copies = 1;
    use(loadScene(single), settings, render);
}

void SceneState::use(LoadedScene loaded, const SceneSettings& settings,
                     const render::RenderSettings& render) {
    std::optional<scene::Scene> copies;
    if (settings.copies > 1)
        copies = makeCopies(loaded.source, loaded.scene, settings.copies, settings.copyAxes);
    uploadScene(renderer_, loaded.source, copies ? *copies : loaded.scene, render);
    for (const auto& warning : loaded.warnings)
        Events::problem("warning: " + loaded.source + ": " + warning);
    loaded.settings = settings;
    base_ = std::move(loaded);
    copies_ = std::move(copies);
    sceneChanged();
}

// A count that cannot fit (IDs, host or GPU memory) is refused in the panel; the scene drawn
// before stays (the renderer uploads the new scene before letting go of the old).
bool SceneState::setCopies(uint32_t copies, uint32_t axes) {
    std::optional<scene::Scene> next;
    try {
        if (copies > 1) next = makeCopies(base_.source, base_.scene, copies, axes);
        uploadScene(renderer_, base_.source, next ? *next : base_.scene, renderer_.settings());
    } catch (const std::exception& e) {
        fail(e.what());
        return false;
    }
    copies_ = std::move(next);
    base_.settings.copies = copies;
    base_.settings.copyAxes = axes;
    sceneChanged();
    return true;
}

void SceneState::configure(render::RenderSettings& render) {
    const uint32_t msaa = render.pipeline.msaa;
    try {
        // A pipeline not built yet is built on a worker; what is drawn stays until then.
        if (const auto build = renderer_.prepare(atRest(), render)) {
            const bool cut = render.section.any();
            waitFor(settingsWait_, *build,
                    cut == renderer_.settings().section.any() ? "the switch happens"
                    : cut                                     ? "the section cut appears"
                                                              : "the section cut goes");
            return;
        }
        // New targets first: the renderer switches only once everything it needs is there.
        std::shared_ptr<const render::SceneTargets> targets = targets_;
        if (uint32_t(targets->pass().samples()) != msaa)
            targets = std::make_shared<render::SceneTargets>(device_, renderer_.pass(msaa),
                                                             targets_->extent());
        renderer_.configure(atRest(), render);
        targets_ = std::move(targets);
    } catch (const std::exception& e) {
        settingsWait_.reset();
        fail(e.what());
        render = renderer_.settings(); // what is drawn, so the panel shows it
        return;
    }
    arrived(settingsWait_);
    idBytes_ = scene::idDataBytes(atRest(), render.pipeline.searchBatch);
    error_.clear();
}

void SceneState::resize(VkExtent2D extent) {
    if (targets_->extent().width == extent.width && targets_->extent().height == extent.height)
        return;
    targets_ = std::make_shared<render::SceneTargets>(device_, targets_->pass(), extent);
}

void SceneState::reloadShaders() {
    try {
        renderer_.reloadShaders();
    } catch (const vk::ShaderError& e) {
        fail(e.what()); // the last good pipeline keeps drawing
        return;
    }
    error_.clear();
    events_.say("shaders_reloaded");
}

bool SceneState::showHidden(const scene::PartSet& hidden) {
    if (hidden == renderer_.hidden()) {
        hiddenWait_.reset(); // shown as it is, or back to it before its build was done
        return true;
    }
    try {
        if (const auto build = renderer_.prepareHidden(hidden)) {
            waitFor(hiddenWait_, *build,
                    hidden.empty() ? "the hidden parts reappear" : "the parts hidden vanish");
            return false;
        }
        renderer_.setHidden(hidden);
    } catch (...) {
        hiddenWait_.reset();
        throw;
    }
    arrived(hiddenWait_);
    return true;
}

void SceneState::waitFor(std::optional<Wait>& wait, const render::PipelineBuild& build,
                         std::string then) {
    if (wait && wait->pipeline == build.name) return;
    const auto start = std::chrono::steady_clock::now() -
                       std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                           std::chrono::duration<double>(build.seconds));
    wait = Wait{build.name, start, std::move(then)};
    events_.say("pipeline", [&](util::JsonWriter& j) {
        j.member("state", "building").member("name", build.name);
    });
}

void SceneState::arrived(std::optional<Wait>& wait) {
    // Said only when what was awaited is drawn, not when the wish moved to a pipeline built.
    if (!wait || wait->pipeline != renderer_.pipelineName()) {
        wait.reset();
        return;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wait->start).count();
    events_.say("pipeline", [&](util::JsonWriter& j) {
        j.member("state", "ready").member("name", wait->pipeline);
        j.member("seconds", util::Fixed{seconds, 2});
    });
    wait.reset();
}

std::optional<SceneState::Building> SceneState::building() const {
    const std::optional<Wait>& wait = settingsWait_ ? settingsWait_ : hiddenWait_;
    if (!wait) return std::nullopt;
    return Building{
        wait->pipeline,
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wait->start).count(),
        wait->then};
}

void SceneState::sceneChanged() {
    explodeOffsets_.clear();
    exploded_.reset();
    explodedAt_ = 0.0f;
    idBytes_ = scene::idDataBytes(atRest(), renderer_.settings().pipeline.searchBatch);
    emptyParts_ = scene::emptyParts(atRest());
    error_.clear();
}

const std::vector<glm::vec4>& SceneState::explodeOffsets() {
    if (!explodeOffsets_.empty() || atRest().objects.empty()) return explodeOffsets_;
    explodeOffsets_ = scene::explodeOffsets(atRest());
    double farthest = 0.0;
    for (const glm::vec4& offset : explodeOffsets_)
        farthest = std::max(farthest, double(glm::length(glm::vec3(offset))));
    // Every point moves by its object's offset at most, and lies within one radius at rest.
    const double radius = atRest().bounds().radius();
    explodeReach_ = radius > 0.0 ? 1.0 + farthest / radius : 1.0;
    return explodeOffsets_;
}

bool SceneState::explode(float explode) {
    explode = explode > 0.0f ? std::min(explode, 1.0f) : 0.0f; // as render::Animator clamps
    if (explode == explodedAt_) return false;
    explodedAt_ = explode;
    if (explode == 0.0f) {
        exploded_.reset(); // the copy's memory back while nothing is exploded
        return true;
    }
    // Copied once (the objects; the geometry stays shared); moving it again touches the
    // placements alone.
    if (!exploded_) exploded_ = atRest();
    scene::placeExploded(*exploded_, atRest(), explodeOffsets(), explode);
    return true;
}

double SceneState::explodeReach() {
    explodeOffsets();
    return explodeReach_;
}

} // namespace app
