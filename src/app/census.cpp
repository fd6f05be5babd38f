// census.cpp - the census's runs on an offscreen device, and `idview --census` (see census.h).
#include "app/census.h"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "app/census_run.h"
#include "app/exit_code.h"
#include "app/exterior_export.h"
#include "app/headless.h"
#include "app/offscreen.h"
#include "app/scene_source.h"
#include "scene/explode.h"
#include "scene/formats.h"
#include "util/json_writer.h"
#include "vk/context.h"

namespace app {
namespace {

// The run's options at the census's size, single-sampled (the targets' MSAA).
Options censusOptions(const Options& options) {
    Options drawn = options;
    drawn.width = drawn.height = options.census.size;
    drawn.live.render.pipeline.msaa = 1;
    return drawn;
}

// The scene-pass GPU time of the newest `views` frames.
double newestGpuMs(const render::FrameSlots& slots, uint32_t views) {
    const std::vector<double>& ms = slots.gpuMilliseconds();
    const size_t count = std::min<size_t>(views, ms.size());
    return std::accumulate(ms.end() - long(count), ms.end(), 0.0);
}

} // namespace

CensusOutcome renderCensus(const Options& options, const scene::Scene& scene,
                           const scene::Bounds& bounds, uint32_t repeats) {
    Options drawn = censusOptions(options);
    CensusOutcome outcome;
    outcome.hidden = hiddenParts(options, scene);
    vk::Instance instance({options.validation, {}, options.syncValidation});
    {
        Offscreen rig(instance, drawn);
        outcome.deviceName = rig.device.info().name;
        drawn.live.render =
            censusSettings(drawn.live.render, rig.device,
                           given(options, "--renderer") || given(options, "--mode"));
        uploadScene(rig.renderer, sourceOf(options.live.scene), scene, drawn.live.render);
        outcome.pipeline = rig.renderer.pipelineName();
        rig.renderer.setHidden(outcome.hidden);
        rig.renderer.setSelection(scene::PartSet(scene.uniquePartCount()));
        const render::CensusPass pass(rig.device, rig.compiler, rig.renderer.driverCache());
        uint64_t frame = 0;
        for (uint32_t r = 0; r < repeats; ++r) {
            CensusRun run(rig.device, rig.renderer, pass, scene.uniquePartCount(), bounds,
                          options.census, drawn.live.animation.explode);
            while (!run.done()) run.step(rig.slots, frame++);
            rig.slots.finish();
            outcome.runs.push_back(run.result());
            outcome.scenePassMs.push_back(newestGpuMs(rig.slots, run.views()));
        }
        savePipelineCache(rig.renderer);
    }
    outcome.validationMessages = instance.validationMessages();
    return outcome;
}

namespace {

void printParts(const scene::Scene& scene, const scene::Census& census) {
    for (uint32_t part = 0; part < census.parts.size(); ++part)
        std::printf("%s\n", censusPartJson(scene, census, part).c_str());
}

// The benchmark's line: every run's milliseconds, the first a warm-up.
std::string timingJson(const Options& options, const scene::Scene& scene,
                       const CensusOutcome& outcome) {
    util::JsonWriter json;
    json.beginObject()
        .member("census_views", options.census.views)
        .member("size", options.census.size)
        .member("triangles", scene.drawnTriangleCount())
        .member("parts", scene.uniquePartCount())
        .member("device", outcome.deviceName)
        .member("pipeline", outcome.pipeline)
        .beginArray("ms");
    for (const scene::Census& run : outcome.runs) json.value(util::Fixed{run.ms, 3});
    json.endArray().beginArray("scene_pass_gpu_ms");
    for (double ms : outcome.scenePassMs) json.value(util::Fixed{ms, 3});
    return json.endArray().endObject().text();
}

} // namespace

int runCensus(const Options& options) {
    const LoadedScene loaded = loadScene(options.live.scene);
    for (const auto& warning : loaded.warnings)
        std::fprintf(stderr, "idview: warning: %s: %s\n", loaded.source.c_str(), warning.c_str());
    // Exploded, the views hold the objects where they are drawn, and the answers name them.
    std::optional<scene::Scene> exploded;
    if (options.live.animation.explode > 0.0f)
        exploded = scene::explodedScene(loaded.scene, options.live.animation.explode);
    const scene::Scene& scene = exploded ? *exploded : loaded.scene;
    if (!options.censusExport.empty()) // before drawing: a STEP export needs a CAD file
        checkExteriorExport(options.censusExport, loaded.scene, loaded.source);
    const uint32_t repeats = options.benchmark ? 3 : 1;
    const CensusOutcome outcome = renderCensus(options, loaded.scene, scene.bounds(), repeats);
    const scene::Census& census = outcome.runs.back();
    if (options.benchmark) {
        std::printf("%s\n", timingJson(options, scene, outcome).c_str());
        return exitCode(outcome.validationMessages);
    }
    // The files first: a refused export ends the run in its one line, before any answer.
    if (!options.censusExport.empty())
        writeExterior(options.censusExport, scene, census, options.live.scene.model,
                      options.live.scene.cad.healing);
    if (!options.censusCsv.empty()) writeCensusCsv(options.censusCsv, scene, census);
    printParts(scene, census);
    const scene::CensusSummary sum = scene::summarize(scene, census, outcome.hidden);
    std::printf("%s\n", censusSummaryJson(census, sum).c_str());
    std::fprintf(stderr,
                 "idview: census of %u views of %ux%u on %s with %s; %u of %u parts seen, %u "
                 "never seen (%u solids or objects); %.1f ms\n",
                 census.views, census.width, census.height, outcome.deviceName.c_str(),
                 outcome.pipeline.c_str(), sum.partsSeen, sum.parts, sum.partsNeverSeen,
                 sum.objectsNeverSeen, census.ms);
    return exitCode(outcome.validationMessages);
}

} // namespace app
