// scene_source.h - where the scene comes from: a model file (--model, in a format that
// scene/formats.h lists), a built-in or procedural scene (--scene), or the default model in
// assets/; then model copies. Shared by the headless path, the viewer and --stats.
#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/live_settings.h"
#include "scene/cad/cad_loader.h"
#include "scene/camera.h"
#include "scene/lod.h"
#include "scene/scene.h"

namespace util {
class JsonWriter;
}
namespace render {
class Renderer;
struct RenderSettings;
struct RenderStats;
} // namespace render

namespace app {

// A parsed --scene value: "assembly", "tiles" or "procedural[:preset=NAME][,seed=N]".
struct SceneSpec {
    std::string builtin; // "assembly", "tiles" or "procedural"
    std::string preset = "small";
    uint64_t seed = 1;
};
// Throws std::invalid_argument with a message for people.
SceneSpec parseSceneSpec(const std::string& text);

struct LoadedScene {
    scene::Scene scene;
    SceneSettings settings; // what it was loaded as (copies included)
    std::string source;     // file path or scene spec, for messages and stats
    double loadMs = 0.0;    // loading or generating, copies and levels of detail included
    double lodMs = 0.0;     // building the levels of detail
    // CAD files (STEP, IGES, BREP): what the load took and did, the cache's note "--no-cache"
    // where it was not asked; zeros (and cache "off") for other sources.
    bool cad = false;
    scene::CadLoadFigures cadLoad;
    std::vector<std::string> warnings;
    bool tilesLayout = false; // the test layout at its own camera
};

// The model idview opens when none is given: assets/default.glb beside the executable
// (a bundled copy), else in the source tree.
std::string defaultModelPath();
// What `settings` open, as messages name it: the model's path or the built-in scene's spec.
std::string sourceOf(const SceneSettings& settings);

// Loads or generates the scene `settings` name and makes its copies. Throws
// scene::ModelError / std::runtime_error with a one-line message.
// How far a load has come, for the viewer's progress bar: the loader writes it (from any
// thread), the viewer reads it between frames. Only CAD loads report stages.
class LoadProgress {
  public:
    void set(const char* stage, double fraction) {
        const std::lock_guard lock(mutex_);
        stage_ = stage;
        fraction_ = fraction;
    }
    // The stage ("" until one reports) and how far it is, 0..1.
    std::pair<std::string, double> get() const {
        const std::lock_guard lock(mutex_);
        return {stage_, fraction_};
    }

  private:
    mutable std::mutex mutex_;
    std::string stage_;
    double fraction_ = 0.0;
};

// A CAD load stops while `cancel` is set (the viewer's Cancel), with ModelError "<file>:
// cancelled".
// `partial` sees a big CAD file's solids as they come (scene::CadPartial), on the loading thread.
LoadedScene loadScene(const SceneSettings& settings, LoadProgress* progress = nullptr,
                      const std::atomic<bool>* cancel = nullptr,
                      const scene::CadPartialSink& partial = {});

// Throws std::runtime_error, one line, when `copies` of `scene` would not fit in this
// machine's memory (checked before any allocation).
void checkCopiesFit(const scene::Scene& scene, uint32_t copies);
// scene::replicate, checked first by checkCopiesFit; running out of memory making them is
// refused in one line naming `source` and the copies (app/out_of_memory.h).
scene::Scene makeCopies(const std::string& source, const scene::Scene& scene, uint32_t copies,
                        uint32_t axes);
// renderer.setScene, where running out of host memory is refused in one line naming `source`
// and what was uploaded (out of device memory, vk::Allocation names the buffer).
void uploadScene(render::Renderer& renderer, const std::string& source, const scene::Scene& scene,
                 const render::RenderSettings& settings);

// The camera idview opens a scene with, at this aspect ratio.
scene::Camera initialCamera(const LoadedScene& loaded, float aspect,
                            const CameraSettings& view = {});
// The same framing `bounds` instead of the scene's own (the scene exploded: the objects
// where they are drawn).
scene::Camera initialCamera(const LoadedScene& loaded, float aspect, const CameraSettings& view,
                            const scene::Bounds& bounds);

// How a headless run's first frame went, for --stats --headless: milliseconds from just
// before the device was created to the first frame's fence, and the pipeline cache's status
// (render::DiskPipelineCache::status).
struct FirstFrame {
    double ms = 0.0;
    std::string pipelineCache;
};

// One JSON object for --stats: objects, geometries, parts, triangles, load_ms, read_ms,
// tessellation_ms, faces_failed, deflection (those four 0 unless a CAD file), "unit" (the
// scene's: of the deflection and each level's max_error), ... and what
// the renderer `settings` choose would draw and upload; last first_frame_ms and
// pipeline_cache from `first`, null without it (nothing rendered).
std::string statsJson(const LoadedScene& loaded, const render::RenderSettings& settings,
                      const std::optional<FirstFrame>& first = std::nullopt);
// What each level of detail holds (scene::levelStats), as a JSON array for --stats and the
// benchmark: [{"level","geometries","unique_triangles","vertices","bytes","triangles",
// "max_error"},...].
void levelStatsArray(util::JsonWriter& json, const std::vector<scene::LevelStats>& levels);
// The derived geometry a configuration draws instead of the scene's indices, as the members
// --stats and the benchmark share: "geometry_bytes", "added_vertices", "added_vertex_bytes".
void derivedGeometryMembers(util::JsonWriter& json, const render::RenderStats& stats);

// --tree: the scene's assembly tree (scene/assembly_tree.h) as nested
// {"name","children":[...]}, each leaf {"name","object","parts":[first unique part, count]};
// the root is named after the file (or the built-in scene).
std::string treeJson(const LoadedScene& loaded);
// The tree's root: the file's name, or the built-in scene's spec.
std::string treeRootName(const LoadedScene& loaded);

} // namespace app
