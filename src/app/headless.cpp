// headless.cpp - rendering without a window: a sequence of configurations on one device,
// each with its selection, picks and measurements, then its timed frames (frame_loop.h);
// and `idview --headless`, which prints what they found.
#include "app/headless.h"
#include "app/camera_frame.h"
#include "app/exit_code.h"
#include "app/pipeline_cache_file.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "app/frame_loop.h"
#include "app/image_io.h"
#include "app/offscreen.h"
#include "app/scene_source.h"
#include "render/frame_slots.h"
#include "render/renderer.h"
#include "render/targets.h"
#include "render/xray.h"
#include "scene/edge_info.h"
#include "scene/explode.h"
#include "scene/face_info.h"
#include "scene/inspect.h"
#include "util/cache_file.h"
#include "vk/context.h"

namespace app {

namespace {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

} // namespace

namespace {

// What one frame found in a rectangle: the parts, and their count as the GPU counted it.
struct RectResult {
    scene::PartSet parts;
    uint32_t count;
};

// One headless sequence on one device (renderHeadlessSequence): per configuration, the
// renderer switched to it, the selection made, the picks and measurements (one waited frame
// each), then the timed frames.
class HeadlessRun {
  public:
    HeadlessRun(Offscreen& rig, const Options& options, const scene::Scene& scene,
                const scene::Camera& camera)
        : rig_(rig), options_(options), scene_(scene), loop_(rig, options, scene, camera),
          params_(loop_.view(options.frames - 1)), hidden_(hiddenParts(options, scene)) {}

    HeadlessResult configuration(const render::RenderSettings& settings, bool first);
    std::optional<double> firstFrameMs() const { return loop_.firstFrameMs(); }

  private:
    // The same renderer, switched (its stats into `result`); nothing selected, nothing
    // hovered.
    void switchTo(const render::RenderSettings& settings, bool first, HeadlessResult& result);
    // Options::selects, then Options::selectRect: the selection they leave.
    scene::PartSet select(HeadlessResult& result);
    // Options::picks, measure, faceInfos and edgeInfos, in that order.
    void pickAll(HeadlessResult& result);
    void measure(HeadlessResult& result);
    void timedFrames(HeadlessResult& result);

    render::PickReading pickFrame(const Options::Pixel& pixel);
    RectResult rectFrame(const render::PartSetQuery& rect);
    glm::dvec2 imageSize() const { return {rig_.extent.width, rig_.extent.height}; }

    Offscreen& rig_;
    const Options& options_;
    const scene::Scene& scene_;
    FrameLoop loop_;
    // Picks and selections see the last frame's view, which the images hold; the timed
    // frames keep its hovered pixel.
    render::FrameParams params_;
    const scene::PartSet hidden_;
};

render::PickReading HeadlessRun::pickFrame(const Options::Pixel& pixel) {
    render::FrameParams pickParams = params_;
    pickParams.pickPixel = glm::uvec2(pixel.x, pixel.y);
    loop_.waitedFrame(pickParams);
    return *rig_.slots.latestPick();
}

RectResult HeadlessRun::rectFrame(const render::PartSetQuery& rect) {
    render::FrameParams rectParams = params_;
    rectParams.partSets = {rect};
    loop_.waitedFrame(rectParams);
    const render::PartSetReading& reading = *rig_.slots.latestPartSets();
    return RectResult{reading.sets.front(), reading.counts.front()};
}

void HeadlessRun::switchTo(const render::RenderSettings& settings, bool first,
                           HeadlessResult& result) {
    render::Renderer& renderer = rig_.renderer;
    if (first)
        uploadScene(renderer, sourceOf(options_.live.scene), scene_, settings);
    else
        renderer.configure(scene_, settings);
    rig_.useMsaa(settings.pipeline.msaa);
    result.stats = renderer.stats();
    // X-ray of the configuration before is off until this one's selection is made.
    if (first || options_.live.xray) renderer.setHidden(hidden_);
    const scene::PartSet none(scene_.uniquePartCount());
    renderer.setSelection(none);
    if (options_.live.xray) renderer.setTranslucent(scene_, none);
    params_.pickPixel.reset();
}

scene::PartSet HeadlessRun::select(HeadlessResult& result) {
    scene::PartSet selection(scene_.uniquePartCount());
    for (const auto& pixel : options_.selects) {
        result.selected = pickFrame(pixel).part;
        selection.clear();
        if (result.selected) selection.insert(*result.selected);
        rig_.renderer.setSelection(selection);
    }
    if (options_.selectRect) {
        RectResult rect = rectFrame(*options_.selectRect);
        rig_.renderer.setSelection(rect.parts);
        selection = rect.parts;
        result.rectParts = std::move(rect.parts);
        result.rectCount = rect.count;
    }
    return selection;
}

void HeadlessRun::measure(HeadlessResult& result) {
    // The pick's depth is taken where sample 0 lies (the pixel centre without MSAA).
    for (size_t i = 0; i < 2; ++i) {
        const render::PickReading pick = pickFrame((*options_.measure)[i]);
        result.measured.push_back(pick);
        if (pick.part)
            result.measuredPoints[i] = scene::unprojectPixel(
                params_.worldViewProj, imageSize(),
                glm::dvec2(pick.pixel) + glm::dvec2(rig_.targets->pass().sampleZero()), pick.depth);
    }
}

void HeadlessRun::pickAll(HeadlessResult& result) {
    for (const auto& pixel : options_.picks) {
        result.picks.push_back(pickFrame(pixel));
        result.hovers.push_back(*rig_.slots.latestHover());
        params_.pickPixel = result.picks.back().pixel;
    }
    if (options_.measure) measure(result);
    for (const auto& pixel : options_.faceInfos) result.faceInfoPicks.push_back(pickFrame(pixel));
    for (const auto& pixel : options_.edgeInfos) {
        const render::PickReading pick = pickFrame(pixel);
        result.edgeInfoPicks.push_back(pick);
        // The cursor at the pixel's centre, as the viewer's mouse position is.
        result.edgeInfoEdges.push_back(
            pick.part ? scene::nearestEdge(scene_, *pick.part, params_.worldViewProj, imageSize(),
                                           glm::dvec2(pick.pixel) + 0.5, scene::edgePickPixels)
                      : std::nullopt);
    }
}

void HeadlessRun::timedFrames(HeadlessResult& result) {
    FrameRun how;
    how.keepEveryFrame = options_.keepEveryFrame;
    if (options_.visibleParts)
        how.lastFrameSets = {{{0, 0}, {rig_.extent.width - 1, rig_.extent.height - 1}}};
    TimedFrames timed = loop_.run(params_, how);
    if (options_.visibleParts) {
        const render::PartSetReading& reading = *rig_.slots.latestPartSets();
        result.visibleParts = reading.sets.front();
        result.visibleCount = reading.counts.front();
    }
    result.gpuMs = std::move(timed.gpuMs);
    result.idPassMs = std::move(timed.idPassMs);
    result.frameTimes = std::move(timed.steps);
    result.cullStats = std::move(timed.cullStats);
    result.frames = std::move(timed.everyFrame);
    result.ids = std::move(timed.last.ids);
    result.color = std::move(timed.last.color);
}

HeadlessResult HeadlessRun::configuration(const render::RenderSettings& settings, bool first) {
    HeadlessResult result;
    result.width = rig_.extent.width;
    result.height = rig_.extent.height;
    result.deviceName = rig_.device.info().name;
    switchTo(settings, first, result);
    const scene::PartSet selection = select(result);
    // The picks and the timed frames see the selection through X-ray.
    if (options_.live.xray) {
        const render::XrayParts xray = render::xrayParts(true, selection, hidden_);
        rig_.renderer.setHidden(xray.hidden);
        rig_.renderer.setTranslucent(scene_, xray.translucent);
    }
    pickAll(result);
    timedFrames(result);
    result.cullTotals = rig_.renderer.cullTotals();
    result.pipelineCache = rig_.renderer.driverCache().status();
    return result;
}

} // namespace

std::vector<HeadlessResult>
renderHeadlessSequence(const Options& options, const scene::Scene& scene,
                       const scene::Camera& camera,
                       const std::vector<render::RenderSettings>& settings) {
    std::vector<HeadlessResult> results;
    vk::Instance instance({options.validation, {}, options.syncValidation});
    {
        Offscreen rig(instance, options);
        HeadlessRun run(rig, options, scene, camera);
        for (size_t c = 0; c < settings.size(); ++c)
            results.push_back(run.configuration(settings[c], c == 0));
        for (HeadlessResult& result : results)
            result.firstFrameMs = run.firstFrameMs().value_or(0.0);
        savePipelineCache(rig.renderer);
    }
    for (HeadlessResult& result : results)
        result.validationMessages = instance.validationMessages();
    return results;
}

HeadlessResult renderHeadless(const Options& options, const scene::Scene& scene,
                              const scene::Camera& camera) {
    return renderHeadlessSequence(options, scene, camera, {options.live.render}).front();
}

namespace {

// The JSON lines a run prints, in this order; false when it prints none.
bool printJsonLines(const Options& options, const LoadedScene& loaded, const scene::Scene& scene,
                    const HeadlessResult& result, const std::vector<std::string>& inspection) {
    std::vector<std::string> lines;
    if (result.rectParts)
        lines.push_back(partSetJson(*result.rectParts, result.rectCount, options.selectRect));
    for (const auto& pick : result.picks) lines.push_back(pickJson(scene, pick));
    if (options.measure) lines.push_back(measureJson(result, scene.unit));
    for (const auto& pick : result.faceInfoPicks) lines.push_back(faceInfoJson(scene, pick));
    for (size_t i = 0; i < result.edgeInfoPicks.size(); ++i)
        lines.push_back(edgeInfoJson(scene, result.edgeInfoPicks[i], result.edgeInfoEdges[i]));
    if (result.visibleParts)
        lines.push_back(partSetJson(*result.visibleParts, result.visibleCount, std::nullopt));
    lines.insert(lines.end(), inspection.begin(), inspection.end());
    if (options.stats)
        lines.push_back(statsJson(loaded, options.live.render,
                                  FirstFrame{result.firstFrameMs, result.pipelineCache}));
    for (const std::string& line : lines) std::printf("%s\n", line.c_str());
    return !lines.empty();
}

// "idview: 10 frames of 1280x720 on ..., the last frame drew ...; scene pass GPU median
// 1.234 ms".
std::string summaryLine(const Options& options, const scene::Scene& scene,
                        const HeadlessResult& result) {
    const render::PipelineKey& key = options.live.render.pipeline;
    // What the last frame drew, culling's counters against their totals.
    const render::CullCounts drawn =
        result.cullStats.empty()
            ? render::CullCounts{}
            : render::countsOf(result.cullStats.back(), key.technique->usesMeshShader());
    std::string meshlets;
    if (result.cullTotals.meshlets)
        meshlets = std::to_string(drawn.meshlets) + " of " +
                   std::to_string(result.cullTotals.meshlets) + " meshlets, ";
    // With levels of detail chosen, the triangles of each level.
    std::string levels;
    if (options.live.render.lod.errorPixels > 0.0f) {
        levels = " (by level of detail:";
        for (uint64_t t : drawn.levelTriangles) levels.append(" ").append(std::to_string(t));
        levels += ")";
    }
    char line[1024];
    std::snprintf(line, sizeof line,
                  "idview: %u frames of %ux%u on %s, %s%s + %s, culling %s: %zu draws, %llu "
                  "triangles, %u parts; the last frame drew %llu draws, %s%llu triangles%s; "
                  "scene pass GPU median %.3f ms\n",
                  options.frames, result.width, result.height, result.deviceName.c_str(),
                  key.technique->name, result.stats.gsPassthrough ? " (passthrough)" : "",
                  key.mode->name, render::cullModeName(options.live.render.culling.mode),
                  result.stats.draws, static_cast<unsigned long long>(scene.drawnTriangleCount()),
                  scene.uniquePartCount(), static_cast<unsigned long long>(drawn.draws),
                  meshlets.c_str(), static_cast<unsigned long long>(drawn.triangles),
                  levels.c_str(), median(result.gpuMs));
    return line;
}

} // namespace

int runHeadless(const Options& options) {
    const LoadedScene loaded = loadScene(options.live.scene);
    for (const auto& warning : loaded.warnings)
        std::fprintf(stderr, "idview: warning: %s: %s\n", loaded.source.c_str(), warning.c_str());
    // --explode: the GPU draws it from the scene at rest (render/animator.h); what the CPU
    // answers (face reports, measurements, inspection) and the opening view take the objects
    // where they are drawn, bit for bit (scene::explodedScene).
    std::optional<scene::Scene> exploded;
    if (!options.live.animation.animate && options.live.animation.explode > 0.0f)
        exploded = scene::explodedScene(loaded.scene, options.live.animation.explode);
    const scene::Scene& scene = exploded ? *exploded : loaded.scene;
    // Before rendering: a part or object not in the scene ends the run at once.
    const std::vector<std::string> inspection = inspectionJson(options, scene);
    const float aspect = float(options.width) / float(options.height);
    const HeadlessResult result = renderHeadless(
        options, loaded.scene, initialCamera(loaded, aspect, options.live.camera, scene.bounds()));

    if (!options.screenshot.empty())
        writePng(options.screenshot, result.width, result.height, result.color);
    if (!options.idImage.empty()) writeIdImage(options.idImage, result.ids);
    // With JSON lines, stdout carries only them; the summary goes to stderr.
    const bool json = printJsonLines(options, loaded, scene, result, inspection);
    std::fputs(summaryLine(options, scene, result).c_str(), json ? stderr : stdout);
    return exitCode(result.validationMessages);
}

scene::PartSet hiddenParts(const Options& options, const scene::Scene& scene) {
    const uint32_t count = scene.uniquePartCount();
    scene::PartSet hidden(count);
    const bool isolate = !options.isolate.empty();
    for (uint32_t id : isolate ? options.isolate : options.hide) {
        if (id >= count)
            throw std::invalid_argument(
                std::string(isolate ? "--isolate" : "--hide") + ": part " + std::to_string(id) +
                " is not in the scene (its parts are 0 to " + std::to_string(count - 1) + ")");
        hidden.insert(id);
    }
    if (isolate) hidden.invert();
    return hidden;
}

} // namespace app
