// headless.h - offscreen rendering with no window and no surface extensions, through the same
// renderer the window uses. Used by `idview --headless` and, in-process, by the tests.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/cli.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/inspect.h"
#include "scene/scene.h"

namespace app {

struct HeadlessResult {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> color; // RGBA8 of the last frame, top row first
    std::vector<uint32_t> ids;  // unique part IDs of the last frame, gpu::BACKGROUND_ID if none
    std::vector<double> gpuMs;  // scene pass time of each frame
    std::vector<render::PickReading> picks; // one per Options::picks entry, in order
    // The same frames' composition: the part and depth it read from the ID and depth images
    // at the picked pixel, which the hover highlight shows (render/id_passes.h).
    std::vector<render::PickReading> hovers;
    // Options::measure: both picks, and the world points their depths give (none on
    // background).
    std::vector<render::PickReading> measured;
    std::array<std::optional<glm::dvec3>, 2> measuredPoints;
    std::vector<render::PickReading> faceInfoPicks; // one per Options::faceInfos entry
    std::optional<uint32_t> selected;               // the part Options::selects picked, if any
    // One per Options::edgeInfos entry: the pick and the edge of its part's face nearest it.
    std::vector<render::PickReading> edgeInfoPicks;
    std::vector<std::optional<scene::EdgeRef>> edgeInfoEdges;
    // Options::selectRect: the parts in the rectangle (the selection afterwards), and their
    // count as the GPU counted it.
    std::optional<scene::PartSet> rectParts;
    uint32_t rectCount = 0;
    // Options::visibleParts: the parts in the last frame's ID image, and the GPU's count.
    std::optional<scene::PartSet> visibleParts;
    uint32_t visibleCount = 0;
    // Options::keepEveryFrame: the images of every frame, in order (the last is ids, color).
    struct Images {
        std::vector<uint32_t> ids;
        std::vector<uint8_t> color;
    };
    std::vector<Images> frames;
    std::vector<double> idPassMs; // per frame: the passes over the ID image (edges)
    // Per timed frame: the GPU time of each step, and the culling counters; and what those
    // are counted against (render::Renderer::cullTotals).
    std::vector<render::FrameTimes> frameTimes;
    std::vector<gpu::CullStats> cullStats;
    render::CullCounts cullTotals;
    std::string deviceName;
    // From just before the device was created to the first frame's fence (all of the
    // sequence's results hold the same), and the pipeline cache's status when it was read.
    double firstFrameMs = 0.0;
    std::string pipelineCache;
    render::RenderStats stats;
    uint32_t validationMessages = 0; // counted until the device is destroyed
};

// One --pick JSON line: {"x","y","part","object","local_part","name","path","depth"}, with
// nulls for every field but x and y on background.
std::string pickJson(const scene::Scene& scene, const render::PickReading& pick);
// --face-info's line: scene::faceReportJson of the picked part, or {"part":null}.
std::string faceInfoJson(const scene::Scene& scene, const render::PickReading& pick);
// --edge-info's line: {"x","y"} then edgeReportJson's members, or {"x","y","part","edge":null}.
std::string edgeInfoJson(const scene::Scene& scene, const render::PickReading& pick,
                         const std::optional<scene::EdgeRef>& edge);

// --measure's line: {"p0":[x,y,z],"p1":[x,y,z],"distance":D,"delta":[dx,dy,dz],"parts":[A,B],
// "unit":"mm"}, null where a point shows no part (and the distance and delta then); the
// points and lengths are in `unit` (the scene's).
std::string measureJson(const HeadlessResult& result, const scene::LengthUnit& unit);

// Renders options.frames frames of `scene` seen by `camera` and reads back the last one, and
// saves the pipeline cache (pipelineCacheFolder) at the end.
// Options::hide / isolate apply first. Then the picks: Options::selects (one frame, its part
// becomes the selection), Options::selectRect (one frame, its parts become the selection),
// then one frame per Options::picks entry, then one per Options::measure point; the timed frames
// keep the last pick point hovered. With Options::live.xray, X-ray (render/xray.h) applies once the
// selection is made: the picks, measures and timed frames see the selection through it.
// Throws vk::Error / vk::ShaderError with a message for people.
HeadlessResult renderHeadless(const Options& options, const scene::Scene& scene,
                              const scene::Camera& camera);

// The same with one device and one renderer, switched to each of `settings` in turn (as the
// viewer switches at run time; options.live.render is not used). validationMessages counts the
// whole sequence.
std::vector<HeadlessResult>
renderHeadlessSequence(const Options& options, const scene::Scene& scene,
                       const scene::Camera& camera,
                       const std::vector<render::RenderSettings>& settings);

// The hidden parts Options::hide or isolate ask for in `scene`. Throws std::invalid_argument
// naming an ID that is not in the scene.
scene::PartSet hiddenParts(const Options& options, const scene::Scene& scene);

// The JSON lines of --distance and --properties (scene/inspect.h), in that order. Throws
// std::invalid_argument naming a part or object that is not in the scene.
std::vector<std::string> inspectionJson(const Options& options, const scene::Scene& scene);

// The JSON lines of --select-rect and --visible-parts.
std::string partSetJson(const scene::PartSet& parts, uint32_t count,
                        const std::optional<render::PartSetQuery>& rect);

// `idview --headless`: renders, writes the requested files, prints a summary line and returns
// the exit code (3 when validation reported anything).
int runHeadless(const Options& options);

} // namespace app
