// benchmark.cpp - the rows a benchmark times, each drawn by the frame loop (frame_loop.h),
// then the fixed cost (benchmark_report.cpp has the table, JSON and CSV).
#include "app/benchmark.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <tuple>

#include <unistd.h>

#include "app/camera_frame.h"
#include "app/exit_code.h"
#include "app/frame_loop.h"
#include "app/headless.h"
#include "app/offscreen.h"
#include "app/progress_lines.h"
#include "app/scene_source.h"
#include "scene/camera_path.h"
#include "vk/check.h"

namespace app {
namespace {

// The settings of every row: the options' own, with the floors first in every chosen mode
// (what each row is divided by: no-id always, and the mesh floor when a mesh technique
// runs), then the chosen techniques. What the device cannot run goes to `skipped`.
std::vector<render::RenderSettings>
rows(const Options& options, const vk::DeviceInfo& device,
     std::vector<std::pair<std::string, std::string>>& skipped) {
    std::vector<const render::Technique*> techniques;
    for (const render::Technique* technique : options.benchmarkTechniques) {
        const std::string why = render::unavailableReason(*technique, device);
        if (why.empty())
            techniques.push_back(technique);
        else
            skipped.emplace_back(technique->name, why);
    }
    std::vector<const render::Technique*> floors{&render::floorTechnique()};
    for (const render::Technique* technique : techniques) {
        const render::Technique* floor = &render::floorOf(*technique);
        if (std::find(floors.begin(), floors.end(), floor) == floors.end()) floors.push_back(floor);
    }
    std::vector<render::CullMode> culling;
    for (const render::CullModeEntry* entry : options.benchmarkCulling)
        culling.push_back(entry->mode);
    if (culling.empty()) culling.push_back(options.live.render.culling.mode);
    std::vector<render::RenderSettings> list;
    auto add = [&](const render::Technique& technique, const render::DrawMode& mode,
                   render::CullMode cull, float lodError) {
        render::RenderSettings settings = options.live.render;
        settings.pipeline.technique = &technique;
        settings.pipeline.mode = &mode;
        settings.culling.mode = cull;
        settings.lod.errorPixels = lodError;
        // Levels of detail are chosen only where the cull pass lists the draws: elsewhere a
        // row with an error would time full detail again.
        if (lodError > 0.0f && !render::levelsChosenIn(mode)) return;
        list.push_back(settings);
    };
    for (float lodError : options.benchmarkLodErrors)
        for (render::CullMode cull : culling)
            for (const render::DrawMode* mode : options.benchmarkModes)
                for (const render::Technique* floor : floors) add(*floor, *mode, cull, lodError);
    // Each technique's culling modes and levels of detail side by side.
    for (const render::Technique* technique : techniques) {
        if (technique->isFloor()) continue;
        for (const render::DrawMode* mode : options.benchmarkModes)
            for (render::CullMode cull : culling)
                for (float lodError : options.benchmarkLodErrors)
                    add(*technique, *mode, cull, lodError);
    }
    return list;
}

// Whether the row's levels of detail were chosen (else it drew full detail).
bool lodApplied(const render::RenderSettings& settings) {
    return settings.lod.errorPixels > 0.0f && render::levelsChosenIn(*settings.pipeline.mode);
}

// Median over the frames of what the culling let through.
void countDrawn(BenchmarkRow& row, const std::vector<gpu::CullStats>& stats, bool mesh) {
    std::vector<double> draws, meshlets, triangles, computed;
    std::array<std::vector<double>, gpu::LOD_MAX_LEVELS> levels;
    for (const gpu::CullStats& s : stats) {
        const render::CullCounts c = render::countsOf(s, mesh);
        draws.push_back(double(c.draws));
        meshlets.push_back(double(c.meshlets));
        triangles.push_back(double(c.triangles));
        computed.push_back(double(c.computeTriangles));
        for (size_t l = 0; l < levels.size(); ++l) levels[l].push_back(double(c.levelTriangles[l]));
    }
    row.drawsDrawn = percentile(draws, 0.5);
    row.meshletsDrawn = percentile(meshlets, 0.5);
    row.trianglesDrawn = percentile(triangles, 0.5);
    row.computeTrianglesDrawn = percentile(computed, 0.5);
    for (size_t l = 0; l < levels.size(); ++l)
        row.levelTrianglesDrawn[l] = percentile(levels[l], 0.5);
}

} // namespace

uint64_t imageHash(const void* data, size_t bytes) {
    uint64_t hash = 0xcbf29ce484222325ull;
    const auto* p = static_cast<const uint8_t*>(data);
    for (size_t i = 0; i < bytes; ++i) hash = (hash ^ p[i]) * 0x100000001b3ull;
    return hash;
}

double percentile(std::vector<double> values, double fraction) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const size_t rank = static_cast<size_t>(fraction * double(values.size() - 1) + 0.5);
    return values[std::min(rank, values.size() - 1)];
}

namespace {

// A row's names: what was asked for and what the technique and mode made of it.
BenchmarkRow namedRow(const render::RenderSettings& settings) {
    const render::PipelineKey& key = settings.pipeline;
    BenchmarkRow row;
    row.renderer = key.technique->name;
    row.mode = key.mode->name;
    row.culling = render::cullModeName(settings.culling.mode);
    row.cullingApplied = render::describeCulling(*key.technique, *key.mode, settings.culling.mode);
    row.lodError = settings.lod.errorPixels;
    row.lodApplied = lodApplied(settings);
    row.floor = render::floorOf(*key.technique).name;
    return row;
}

// The timed frames' medians (and every frame's GPU time along a camera path), and the last
// frame's images' hashes.
void addTimes(BenchmarkRow& row, const TimedFrames& timed, bool mesh, bool path) {
    std::vector<double> cullMs, pyramidMs, earlyMs, lateMs;
    for (const render::FrameTimes& t : timed.steps) {
        cullMs.push_back(t.cullMs);
        pyramidMs.push_back(t.pyramidMs);
        earlyMs.push_back(t.earlyMs);
        lateMs.push_back(t.lateMs);
    }
    row.cullMsMedian = percentile(cullMs, 0.5);
    row.pyramidMsMedian = percentile(pyramidMs, 0.5);
    row.earlyMsMedian = percentile(earlyMs, 0.5);
    row.lateMsMedian = percentile(lateMs, 0.5);
    countDrawn(row, timed.cullStats, mesh);
    if (path) row.gpuMsFrames = timed.gpuMs;
    row.gpuMsMedian = percentile(timed.gpuMs, 0.5);
    row.gpuMsP90 = percentile(timed.gpuMs, 0.9);
    row.cpuMsMedian = percentile(timed.cpuMs, 0.5);
    row.cpuRecordMsMedian = percentile(timed.cpuRecordMs, 0.5);
    row.idPassMsMedian = percentile(timed.idPassMs, 0.5);
    const HeadlessResult::Images& last = timed.last;
    row.idImageHash = imageHash(last.ids.data(), last.ids.size() * sizeof(uint32_t));
    row.colorImageHash = imageHash(last.color.data(), last.color.size());
}

// What the configuration holds on the GPU, and how the switch to it went.
void addRendererStats(BenchmarkRow& row, const render::Renderer& renderer) {
    row.stats = renderer.stats();
    row.meshlets = renderer.cullTotals().meshlets;
    row.switchMs = renderer.lastSwitch().ms;
    row.pipelineCached = renderer.lastSwitch().pipelineCached;
    // Read after the frames: with Auto the path may be settled by the first frame's timing.
    row.clearPath = render::clearPathName(renderer.clearPath());
}

// What stays the same over every row of a run: the rig, the frames' loop and the parameters
// every frame starts from.
struct RowTimer {
    const Options& options;
    Offscreen& rig;
    FrameLoop loop;
    render::FrameParams params;
    FrameRun frames; // each row's warm-up before its timed frames

    // Configures `settings` (a setScene for the first row, which times the scene's upload
    // with its switch), draws warm-up and timed frames, and reads the last frame's images.
    BenchmarkRow time(const scene::Scene& scene, const render::RenderSettings& settings,
                      bool first) {
        if (first) {
            uploadScene(rig.renderer, sourceOf(options.live.scene), scene, settings);
            rig.renderer.setHidden(hiddenParts(options, scene));
        } else
            rig.renderer.configure(scene, settings);
        const TimedFrames timed = loop.run(params, frames);
        BenchmarkRow row = namedRow(settings);
        addTimes(row, timed, settings.pipeline.technique->usesMeshShader(),
                 options.cameraPath != scene::CameraPath::None);
        addRendererStats(row, rig.renderer);
        row.frames = options.frames;
        return row;
    }
};

// The fixed cost's settings: the first technique that knows parts (the floor where only
// floors run), in its mode, drawing no object, culling off and full detail, so that what is
// timed is the frame's clears, empty pass and resolve.
render::RenderSettings emptyFrame(const std::vector<render::RenderSettings>& list) {
    auto chosen = std::find_if(list.begin(), list.end(), [](const render::RenderSettings& s) {
        return !s.pipeline.technique->isFloor();
    });
    render::RenderSettings settings = chosen != list.end() ? *chosen : list.front();
    settings.draws.visible = 0.0f;
    settings.culling.mode = render::CullMode::Off;
    settings.lod.errorPixels = 0.0f;
    return settings;
}

// What the report says of the run before any row is timed.
BenchmarkReport reportHeader(const Options& options, const LoadedScene& loaded) {
    BenchmarkReport report;
    report.size = std::to_string(options.width) + "x" + std::to_string(options.height);
    report.scene = loaded.source;
    report.copies = loaded.settings.copies;
    report.lodLevels = loaded.settings.lodLevels;
    report.lodLevel = loaded.settings.lodLevel;
    if (report.lodLevels > 1) report.levels = scene::levelStats(loaded.scene);
    report.frames = options.frames;
    report.settings = options.live.render;
    report.cameraPath = scene::cameraPathName(options.cameraPath);
    return report;
}

// Every row of `list` in turn, each divided by its floor's time (floors come first).
void timeRows(RowTimer& timer, const scene::Scene& scene,
              const std::vector<render::RenderSettings>& list, BenchmarkReport& report) {
    std::map<std::tuple<std::string, std::string, render::CullMode, float>, double> floorMs;
    // A line per row as it is timed: progress, so at a terminal or with --progress only.
    const bool progress = progressLinesWanted(timer.options.live.scene.progress, STDERR_FILENO);
    for (size_t i = 0; i < list.size(); ++i) {
        BenchmarkRow row = timer.time(scene, list[i], i == 0);
        if (i == 0) report.hiddenParts = timer.rig.renderer.hidden().size();
        const auto floorKey = std::tuple(row.floor, row.mode, list[i].culling.mode, row.lodError);
        if (list[i].pipeline.technique->isFloor()) floorMs[floorKey] = row.gpuMsMedian;
        const double floor = floorMs[floorKey];
        row.ratioToFloor = floor > 0 ? row.gpuMsMedian / floor : 0.0;
        report.rows.push_back(row);
        if (!progress) continue;
        std::fprintf(stderr,
                     "benchmark: [%zu/%zu] %s + %s, culling %s, LOD error %g: GPU %.3f ms "
                     "(cull %.3f, pyramid %.3f; + %.3f ID passes), CPU %.3f ms, %.0f of "
                     "%zu draws\n",
                     i + 1, list.size(), row.renderer.c_str(), row.mode.c_str(),
                     row.culling.c_str(), double(row.lodError), row.gpuMsMedian, row.cullMsMedian,
                     row.pyramidMsMedian, row.idPassMsMedian, row.cpuMsMedian, row.drawsDrawn,
                     row.stats.draws);
    }
}

// After the rows, so that theirs are timed as they were before it existed: the frame that
// draws nothing, and every row's time above it.
void timeFixedCost(RowTimer& timer, const scene::Scene& scene,
                   const std::vector<render::RenderSettings>& list, BenchmarkReport& report) {
    report.fixedCost = timer.time(scene, emptyFrame(list), false);
    const BenchmarkRow& empty = report.fixedCost;
    for (BenchmarkRow& row : report.rows) row.aboveFixedMs = row.gpuMsMedian - empty.gpuMsMedian;
    const render::Renderer& renderer = timer.rig.renderer;
    report.clearPath = render::clearPathName(renderer.clearPath());
    report.clearTiming = renderer.clearTiming(timer.options.live.render.pipeline.msaa);
    std::fprintf(stderr,
                 "benchmark: fixed cost (%s + %s, culling off, nothing drawn): GPU %.3f ms, "
                 "%zu draws, %llu triangles; clear path %s\n",
                 empty.renderer.c_str(), empty.mode.c_str(), empty.gpuMsMedian, empty.stats.draws,
                 static_cast<unsigned long long>(empty.stats.triangles), report.clearPath.c_str());
}

} // namespace

BenchmarkReport runBenchmark(const Options& options, const LoadedScene& loaded) {
    const scene::Scene& scene = loaded.scene;
    BenchmarkReport report = reportHeader(options, loaded);
    vk::Instance instance({options.validation, {}, options.syncValidation});
    {
        Offscreen rig(instance, options);
        const vk::DeviceInfo& info = rig.device.info();
        report.deviceName = info.name;
        report.driver = info.driverName + " " + vk::driverVersionString(info);
        report.api = vk::versionString(info.apiVersion);
        const auto list = rows(options, info, report.skipped);
        for (const auto& [name, why] : report.skipped)
            std::fprintf(stderr, "benchmark: %s skipped: %s\n", name.c_str(), why.c_str());

        const float aspect = float(rig.extent.width) / float(rig.extent.height);
        // As headless and the viewer open the scene; with a path, timed frame f is frame f
        // of the path (the warm-up frames stay at its start).
        const scene::Camera start = initialCamera(loaded, aspect, options.live.camera);
        RowTimer timer{options, rig, FrameLoop(rig, options, scene, start),
                       cameraFrame(start, rig.extent), FrameRun{}};
        // Enough frames for clocks to settle and pipelines to be warm, without wasting time.
        timer.frames.warmup = std::clamp(options.frames / 5, 5u, 50u);
        // --visible-parts: every frame counts the parts it shows, as the viewer's panel does.
        if (options.visibleParts)
            timer.params.partSets = {{{0, 0}, {rig.extent.width - 1, rig.extent.height - 1}}};
        timeRows(timer, scene, list, report);
        timeFixedCost(timer, scene, list, report);
    }
    report.validationMessages = instance.validationMessages();
    return report;
}

int benchmarkCommand(const Options& options) {
    const LoadedScene loaded = loadScene(options.live.scene);
    std::fprintf(stderr, "benchmark: %s, %u objects, %u parts, %llu triangles\n",
                 loaded.source.c_str(), unsigned(loaded.scene.objects.size()),
                 loaded.scene.uniquePartCount(),
                 static_cast<unsigned long long>(loaded.scene.drawnTriangleCount()));
    const BenchmarkReport report = runBenchmark(options, loaded);
    std::printf("%s", benchmarkTable(report).c_str());
    // Every technique must have drawn the same parts at the same levels of detail; say so
    // when one did not.
    std::map<float, const BenchmarkRow*> first; // by the error the levels were chosen by
    for (const BenchmarkRow& row : report.rows) {
        if (row.renderer == row.floor) continue;
        const BenchmarkRow*& same = first[row.lodApplied ? row.lodError : 0.0f];
        if (!same) same = &row;
        if (row.idImageHash != same->idImageHash)
            std::fprintf(stderr, "benchmark: warning: %s + %s drew another ID image than %s + %s\n",
                         row.renderer.c_str(), row.mode.c_str(), same->renderer.c_str(),
                         same->mode.c_str());
    }
    if (!options.benchmarkOut.empty()) {
        const std::string& path = options.benchmarkOut;
        const bool csv = path.size() > 4 && path.compare(path.size() - 4, 4, ".csv") == 0;
        std::ofstream file(path, std::ios::binary);
        file << (csv ? benchmarkCsv(report) : benchmarkJson(report));
        if (!file.flush()) throw vk::Error("cannot write '" + path + "'");
    }
    return exitCode(report.validationMessages);
}

} // namespace app
