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

#include "app/cli.h"
#include "app/scene_source.h"
#include "app/viewer/events.h"
#include "render/renderer.h"
#include "render/targets.h"
#include "scene/part_data.h"

namespace app {

class SceneState {
  public:
    // Opens the scene `settings.scene` names and configures the renderer for
    // `settings.render`. Throws at start-up, as headless would (exit 1).
    SceneState(vk::Device& device, const vk::ShaderCompiler& compiler, const Events& events,
               const Options& settings, VkExtent2D extent);

    enum class Change { None, Copies, Model }; // what the camera and selection must follow
    // Applies what differs between `wanted` and what is drawn. What fails is put back in
    // `wanted`, so the panel shows what is drawn.
    Change apply(SceneSettings& wanted, render::RenderSettings& render);
    // Starts opening another model (a dropped file) with the current parts mode and copies,
    // on a worker thread: the scene drawn stays interactive meanwhile. One at a time: a drop
    // while one loads waits for it, in the order dropped.
    void startOpen(const std::string& path, const SceneSettings& settings);
    // Once per frame: when the model being opened has loaded, uploads it and puts its
    // settings in `settings` (Change::Model); a load that failed leaves its message.
    Change poll(SceneSettings& settings);
    // The model being opened, for the panel's progress line.
    struct Loading {
        std::string path;
        double seconds = 0.0; // since the drop
        std::string stage;    // CAD files: reading, translating, tessellating, building
        double fraction = 0.0;
    };
    std::optional<Loading> loading() const;
    // The panel's Cancel: the drops queued are forgotten and the load running is told to
    // stop; it fails with "<file>: cancelled" and the scene drawn stays.
    void cancelOpen();
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
    struct PendingOpen {
        std::future<LoadedScene> scene;
        SceneSettings settings;
        std::chrono::steady_clock::time_point start;
        std::shared_ptr<LoadProgress> progress;    // written by the worker
        std::shared_ptr<std::atomic<bool>> cancel; // read by the worker
    };
    std::deque<SceneSettings> queued_;   // drops waiting for the one loading
    std::optional<PendingOpen> pending_; // destroyed first: waits for the worker
    void launchNext();
};

} // namespace app
