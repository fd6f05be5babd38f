// scene_state.h - what the viewer draws: the scene as loaded, its copies, the renderer and
// the targets it renders into. apply() brings them in line with the settings the panel,
// keys and scripts edit; a change that fails keeps what worked before, puts the settings
// back to it and leaves its message in error(). Nothing here waits for the GPU: what frames
// in flight still use lives on in their slots. Nor for the compiler: a pipeline not built yet
// (a technique, mode or MSAA switch, the first hide or section cut) is built on a worker while
// the configuration drawn goes on drawing, and the switch follows on the first frame after.
#pragma once

#include <atomic>
#include <chrono>
#include <deque>
#include <future>
#include <memory>
#include <optional>
#include <string>

#include "app/live_settings.h"
#include "app/scene_source.h"
#include "app/viewer/state/events.h"
#include "app/viewer/state/progressive.h"
#include "render/renderer.h"
#include "render/targets.h"
#include "scene/part_data.h"

namespace app {

class SceneState {
  public:
    // Configures the renderer for `settings.render` over a scene with nothing in it and starts
    // opening the model `settings.scene` names as a dropped one opens (startOpen): the window
    // shows it as it comes. Throws what the renderer refuses at start-up, as headless would
    // (exit 1); a model that cannot be opened is firstFailure()'s.
    SceneState(vk::Device& device, const vk::ShaderCompiler& compiler, const Events& events,
               const LiveSettings& settings, VkExtent2D extent);

    // What the camera and selection must follow.
    enum class Change {
        None,
        Copies,   // other copies: part IDs name other parts, the view stays
        Model,    // another model, or the first partial scene of one: its own view
        Grown,    // the model loading shows more solids, or all of them: the same part IDs
        Restored, // a load cancelled: the model shown before it is back
    };
    // Applies what differs between `wanted` and what is drawn. What fails is put back in
    // `wanted`, so the panel shows what is drawn.
    Change apply(SceneSettings& wanted, render::RenderSettings& render);
    // Starts opening another model (a dropped file) with the current parts mode and copies,
    // on a worker thread: the scene drawn stays interactive meanwhile. One at a time: a drop
    // while one loads waits for it, in the order dropped.
    void startOpen(const std::string& path, const SceneSettings& settings);
    // Once per frame: takes the newest partial scene of a big CAD file (progressive.h) when
    // the upload pace allows, and the model once it has loaded; puts the settings of a model
    // shown in `settings`. A load that failed leaves its message.
    Change poll(SceneSettings& settings);
    // The model being opened, for the panel's progress line.
    struct Loading {
        std::string path;
        double seconds = 0.0; // since the drop
        std::string stage;    // CAD files: reading, translating, tessellating, building
        double fraction = 0.0;
        std::string shown;        // a model shown as it loads: shownLine(), else ""
        uint32_t solidsShown = 0; // of a model shown as it loads
        bool modelBefore = false; // Cancel goes back to a model (else to nothing open)
        bool stopping = false;    // Stop or Cancel asked: the workers are being killed
    };
    std::optional<Loading> loading() const;
    // The panel's Cancel: the drops queued are forgotten and the load running is told to
    // stop; it fails with "<file>: cancelled" and the model shown before it is drawn again.
    void cancelOpen();
    // The panel's Stop here: as Cancel, but what the load has shown stays, marked incomplete.
    void stopOpen();
    // While the model given at start has shown nothing yet (the script waits for it).
    bool waitingForFirst() const { return !shownAny_ && pending_ && pending_->first; }
    // The message the model given at start failed with: the viewer ends with it.
    const std::optional<std::string>& firstFailure() const { return firstFailure_; }
    // The partial scene drawn (its boxes and each object's state; its scene is atRest()):
    // while a big CAD file loads, and after Stop; nullptr once a model is whole.
    const scene::CadPartial* partial() const { return partial_ ? &*partial_ : nullptr; }
    // After Stop: what the model shown lacks ("5 of 8 solids missing"), else "".
    const std::string& incomplete() const { return incomplete_; }
    // The box the camera frames a new model in: a partial scene's boxes (the whole assembly,
    // not the few solids meshed), else the scene's.
    scene::Bounds extent() const;
    // Targets at the window's new size.
    void resize(VkExtent2D extent);
    // R: shaders from disk, caches cleared; a compile error keeps the last good pipeline.
    void reloadShaders();
    // Hands the hidden parts to the renderer; false while the pipeline variant they need (the
    // first part hidden, the last shown) is being built: ask again next frame, the parts
    // hidden before stay so until it is ready. Throws what the renderer refuses.
    bool showHidden(const scene::PartSet& hidden);

    // The pipeline the settings or hidden parts wait for, for the panel's line.
    struct Building {
        std::string pipeline; // render::describePipeline
        double seconds = 0.0; // since its build started
        std::string then;     // what changes once it is ready
    };
    std::optional<Building> building() const;
    // Whether the settings or hidden parts wait for a pipeline: the viewer's loop keeps
    // polling while they do (Renderer::onPipelineBuilt wakes it when a build is done). Builds
    // no longer wanted finish into the cache unawaited (apply() collects them).
    bool pipelinePending() const { return settingsWait_ || hiddenWait_; }

    // The scene where it is drawn, for everything the CPU answers (picks' names, face
    // reports, measurements, bounds): while the exploded view is on, a copy whose objects sit
    // where the GPU draws them (scene::explodedScene, bit for bit), else the scene at rest.
    const scene::Scene& scene() const { return exploded_ ? *exploded_ : atRest(); }
    // The scene at rest, as the renderer holds it (the GPU moves the objects itself).
    const scene::Scene& atRest() const { return copies_ ? *copies_ : base_.scene; }
    // Moves scene()'s objects to the exploded view at `explode` (0: at rest, the copy
    // freed); true when they moved. A new scene starts at rest.
    bool explode(float explode);
    // How far from the centre of the scene at rest the exploded view at 1 reaches, in its
    // bounding radii (OrbitCamera::camera's reach), for the animation.
    double explodeReach();
    const LoadedScene& loaded() const { return base_; }
    const render::Renderer& renderer() const { return renderer_; }
    render::Renderer& renderer() { return renderer_; }
    const std::shared_ptr<const render::SceneTargets>& targets() const { return targets_; }
    const scene::IdDataBytes& idBytes() const { return idBytes_; }
    // The scene's parts without triangles (scene::emptyParts), which no frame shows.
    const scene::PartSet& emptyParts() const { return emptyParts_; }
    VkSampleCountFlags sampleCounts() const { return sampleCounts_; } // the device renders
    // The last failed action's message, until the next success.
    const std::string& error() const { return error_; }
    void fail(const std::string& message);

  private:
    bool openScene(const SceneSettings& settings); // false: refused, the error is kept
    void load(const SceneSettings& settings, const render::RenderSettings& render); // throws
    // Copies, upload and the switch to a scene loaded (with one copy) from `settings`.
    void use(LoadedScene loaded, const SceneSettings& settings,
             const render::RenderSettings& render); // throws
    void opened();
    bool setCopies(uint32_t copies, uint32_t axes);
    void configure(render::RenderSettings& render);
    void sceneChanged();
    struct Wait {
        std::string pipeline;
        std::chrono::steady_clock::time_point start;
        std::string then;
    };
    // A wish meets a pipeline still building ("pipeline: building" once per pipeline), and
    // the wish is drawn ("pipeline: ready").
    void waitFor(std::optional<Wait>& wait, const render::PipelineBuild& build, std::string then);
    void arrived(std::optional<Wait>& wait);

    vk::Device& device_;
    const Events& events_;
    render::Renderer renderer_;
    std::shared_ptr<const render::SceneTargets> targets_;
    LoadedScene base_; // as loaded, one copy (its settings: what is drawn)
    // With model copies, when more than one: objects of its own, base_'s geometry shared
    // (scene/shared_array.h).
    std::optional<scene::Scene> copies_;
    // The exploded view: the objects' offsets (worked out once a scene first explodes), and
    // the scene with them applied at explodedAt_ while that is above 0 (its objects moved, the
    // geometry shared with the scene at rest).
    std::vector<glm::vec4> explodeOffsets_;
    std::optional<scene::Scene> exploded_;
    float explodedAt_ = 0.0f;
    double explodeReach_ = 1.0;
    const std::vector<glm::vec4>& explodeOffsets();
    scene::IdDataBytes idBytes_;
    scene::PartSet emptyParts_;
    VkSampleCountFlags sampleCounts_;
    std::string error_;
    std::optional<Wait> settingsWait_, hiddenWait_; // what each waits for, while it builds
    // Opening models (scene_loads.cpp).
    struct PendingOpen {
        std::future<LoadedScene> scene;
        SceneSettings settings;
        std::chrono::steady_clock::time_point start;
        std::shared_ptr<LoadProgress> progress;    // written by the worker
        std::shared_ptr<std::atomic<bool>> cancel; // read by the worker
        std::shared_ptr<PartialSlot> partials;     // written by the worker
        bool first = false; // the model given at start: its failure ends the viewer
        enum class Ending { Load, Stop, Cancel } ending = Ending::Load; // what was asked
        bool shown = false;      // a partial scene of it is drawn
        bool saidSolids = false; // its first solids were told
    };
    // What was drawn before a load's first partial scene took its place, until the load ends
    // (a model stopped while it loaded has its partial's boxes and what it lacks).
    struct Drawn {
        LoadedScene base;
        std::optional<scene::Scene> copies;
        std::optional<scene::CadPartial> partial;
        std::string incomplete;
    };
    static LoadedScene nothingOpen(); // the empty start: one object that draws nothing
    void launchNext();
    void endOpen(PendingOpen::Ending ending); // Stop or Cancel: the workers are killed
    Change showPartial(scene::CadPartial partial, SceneSettings& settings);
    Change finishOpen(SceneSettings& settings);
    Change whole(PendingOpen& done, LoadedScene loaded, SceneSettings& settings);
    Change ended(PendingOpen& done, const std::string& error, SceneSettings& settings);
    Change restoreBefore(const SceneSettings& loadSettings, SceneSettings& settings);
    void tellPartial(PendingOpen& open, bool first, double uploadMs);
    bool hasModel() const { return !base_.source.empty(); } // not the empty start
    std::deque<SceneSettings> queued_;                      // drops waiting for the one loading
    bool startModel_ = true; // the next launch is the model given at start
    bool shownAny_ = false;  // a model or a partial scene of one has been drawn
    std::optional<std::string> firstFailure_;
    std::optional<Drawn> before_;              // Cancel draws it again
    std::optional<scene::CadPartial> partial_; // without its scene (base_ holds it)
    std::string incomplete_;
    UploadPacer uploads_;
    std::optional<PendingOpen> pending_; // destroyed first: waits for the worker
};

} // namespace app
