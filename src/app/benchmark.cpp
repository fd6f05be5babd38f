// benchmark.cpp - the timing loop, and the table, JSON and CSV it reports.
#include "app/benchmark.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

#include "app/headless.h"
#include "app/json.h"
#include "app/offscreen.h"
#include "app/scene_source.h"
#include "scene/camera_path.h"
#include "scene/explode.h"
#include "vk/check.h"

namespace app {
namespace {

using Clock = std::chrono::steady_clock;

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
    if (culling.empty()) culling.push_back(options.render.culling.mode);
    std::vector<render::RenderSettings> list;
    auto add = [&](const render::Technique& technique, const render::DrawMode& mode,
                   render::CullMode cull, float lodError) {
        render::RenderSettings settings = options.render;
        settings.pipeline.technique = &technique;
        settings.pipeline.mode = &mode;
        settings.culling.mode = cull;
        settings.lod.errorPixels = lodError;
        // Levels of detail are chosen by the cull pass alone: where there is none, a row
        // with an error would time full detail again.
        if (lodError > 0.0f && !render::cullPlan(technique, mode, cull).gpuLists) return;
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
    return settings.lod.errorPixels > 0.0f &&
           render::cullPlan(*settings.pipeline.technique, *settings.pipeline.mode,
                            settings.culling.mode)
               .gpuLists;
}

// Median over the frames of what the culling let through.
void countDrawn(BenchmarkRow& row, const std::vector<gpu::CullStats>& stats, bool mesh) {
    std::vector<double> draws, meshlets, triangles;
    std::array<std::vector<double>, gpu::LOD_MAX_LEVELS> levels;
    for (const gpu::CullStats& s : stats) {
        const render::CullCounts c = render::countsOf(s, mesh);
        draws.push_back(double(c.draws));
        meshlets.push_back(double(c.meshlets));
        triangles.push_back(double(c.triangles));
        for (size_t l = 0; l < levels.size(); ++l) levels[l].push_back(double(c.levelTriangles[l]));
    }
    row.drawsDrawn = percentile(draws, 0.5);
    row.meshletsDrawn = percentile(meshlets, 0.5);
    row.trianglesDrawn = percentile(triangles, 0.5);
    for (size_t l = 0; l < levels.size(); ++l)
        row.levelTrianglesDrawn[l] = percentile(levels[l], 0.5);
}

std::string hex(uint64_t value) {
    char text[24];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

std::string fixed(double value, int digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", digits, value);
    return text;
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

BenchmarkReport runBenchmark(const Options& options, const LoadedScene& loaded) {
    const scene::Scene& scene = loaded.scene;
    BenchmarkReport report;
    report.size = std::to_string(options.width) + "x" + std::to_string(options.height);
    report.scene = loaded.source;
    report.copies = loaded.settings.copies;
    report.lodLevels = loaded.settings.lodLevels;
    report.lodLevel = loaded.settings.lodLevel;
    if (report.lodLevels > 1) report.levels = scene::levelStats(scene);
    report.frames = options.frames;
    report.settings = options.render;
    report.cameraPath = scene::cameraPathName(options.cameraPath);
    // Enough frames for clocks to settle and pipelines to be warm, without wasting time.
    const uint32_t warmup = std::clamp(options.frames / 5, 5u, 50u);

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
        Readback readback(rig.device, rig.extent);

        const float aspect = float(rig.extent.width) / float(rig.extent.height);
        // As headless and the viewer open the scene; with a path, timed frame f is frame f
        // of the path (the warm-up frames stay at its start).
        const scene::Camera start = initialCamera(loaded, aspect, options.camera);
        const scene::Bounds bounds =
            options.cameraPath == scene::CameraPath::None ? scene::Bounds{} : scene.bounds();
        render::FrameParams params = cameraFrame(start, rig.extent);
        // --visible-parts: every frame counts the parts it shows, as the viewer's panel does.
        if (options.visibleParts)
            params.partSets = {{{0, 0}, {rig.extent.width - 1, rig.extent.height - 1}}};
        std::map<std::tuple<std::string, std::string, render::CullMode, float>, double> floorMs;
        uint64_t frameNumber = 0;
        for (size_t i = 0; i < list.size(); ++i) {
            const render::PipelineKey& key = list[i].pipeline;
            if (i == 0) { // the scene's upload is timed with the first switch
                rig.renderer.setScene(scene, list[i]);
                rig.renderer.setHidden(hiddenParts(options, scene));
                report.hiddenParts = rig.renderer.hidden().size();
            } else
                rig.renderer.configure(scene, list[i]);
            std::vector<double> cpuMs, recordMs;
            const uint32_t total = warmup + options.frames;
            uint64_t reusedBefore = 0;
            for (uint32_t f = 0; f < total; ++f, ++frameNumber) {
                if (f == warmup) reusedBefore = rig.renderer.reusedFrames();
                render::FrameSlot& slot = rig.slots.begin(frameNumber);
                // --animate: objects move while being timed, the compute pass included.
                params.explode = explodeAt(options.animation, frameNumber);
                params.setView(
                    cameraFrame(scene::cameraOnPath(options.cameraPath, start, bounds,
                                                    f < warmup ? 0 : f - warmup, options.frames),
                                rig.extent));
                const auto start = Clock::now();
                rig.renderer.record(slot, rig.targets, params);
                const auto recorded = Clock::now();
                if (f + 1 == total) readback.record(slot.cmd, *rig.targets); // after the timing
                rig.slots.submit(slot);
                if (f >= warmup) {
                    cpuMs.push_back(
                        std::chrono::duration<double, std::milli>(Clock::now() - start).count());
                    recordMs.push_back(
                        std::chrono::duration<double, std::milli>(recorded - start).count());
                }
            }
            rig.slots.finish();
            const auto& all = rig.slots.gpuMilliseconds();
            const size_t timed = std::min<size_t>(options.frames, all.size());
            const std::vector<double> gpuMs(all.end() - long(timed), all.end());
            const auto& passes = rig.slots.idPassMilliseconds();
            const std::vector<double> idPassMs(passes.end() - long(timed), passes.end());
            std::vector<double> cullMs, pyramidMs, earlyMs, lateMs;
            for (auto t = rig.slots.frameTimes().end() - long(timed);
                 t != rig.slots.frameTimes().end(); ++t) {
                cullMs.push_back(t->cullMs);
                pyramidMs.push_back(t->pyramidMs);
                earlyMs.push_back(t->earlyMs);
                lateMs.push_back(t->lateMs);
            }
            const std::vector<gpu::CullStats> stats(rig.slots.cullStats().end() - long(timed),
                                                    rig.slots.cullStats().end());

            BenchmarkRow row;
            row.renderer = key.technique->name;
            row.mode = key.mode->name;
            const render::CullMode cull = list[i].culling.mode;
            row.culling = render::cullModeName(cull);
            row.lodError = list[i].lod.errorPixels;
            row.lodApplied = lodApplied(list[i]);
            row.cullingApplied = render::describeCulling(*key.technique, *key.mode, cull);
            row.reusedFrames = rig.renderer.reusedFrames() - reusedBefore;
            row.cullMsMedian = percentile(cullMs, 0.5);
            row.pyramidMsMedian = percentile(pyramidMs, 0.5);
            row.earlyMsMedian = percentile(earlyMs, 0.5);
            row.lateMsMedian = percentile(lateMs, 0.5);
            countDrawn(row, stats, key.technique->usesMeshShader());
            if (options.cameraPath != scene::CameraPath::None) row.gpuMsFrames = gpuMs;
            row.gpuMsMedian = percentile(gpuMs, 0.5);
            row.gpuMsP90 = percentile(gpuMs, 0.9);
            row.cpuMsMedian = percentile(cpuMs, 0.5);
            row.cpuRecordMsMedian = percentile(recordMs, 0.5);
            row.idPassMsMedian = percentile(idPassMs, 0.5);
            row.draws = rig.renderer.stats().draws;
            row.triangles = rig.renderer.stats().triangles;
            const render::RenderStats& renderStats = rig.renderer.stats();
            row.idBytes = renderStats.idBufferBytes;
            row.geometryBytes = renderStats.geometryBytes;
            row.addedVertices = renderStats.addedVertices;
            row.addedVertexBytes = renderStats.addedVertexBytes;
            row.meshlets = rig.renderer.cullTotals().meshlets;
            row.frames = options.frames;
            row.switchMs = rig.renderer.lastSwitch().ms;
            row.pipelineCached = rig.renderer.lastSwitch().pipelineCached;
            const std::vector<uint32_t> ids = readback.idValues();
            const std::vector<uint8_t> color = readback.colorBytes();
            row.idImageHash = imageHash(ids.data(), ids.size() * sizeof(uint32_t));
            row.colorImageHash = imageHash(color.data(), color.size());
            row.floor = render::floorOf(*key.technique).name;
            const auto floorKey = std::tuple(row.floor, row.mode, cull, row.lodError);
            if (key.technique->isFloor()) floorMs[floorKey] = row.gpuMsMedian;
            const double floor = floorMs[floorKey];
            row.ratioToFloor = floor > 0 ? row.gpuMsMedian / floor : 0.0;
            report.rows.push_back(row);
            std::fprintf(stderr,
                         "benchmark: [%zu/%zu] %s + %s, culling %s, LOD error %g: GPU %.3f ms "
                         "(cull %.3f, pyramid %.3f; + %.3f ID passes), CPU %.3f ms, %.0f of "
                         "%zu draws\n",
                         i + 1, list.size(), row.renderer.c_str(), row.mode.c_str(),
                         row.culling.c_str(), double(row.lodError), row.gpuMsMedian,
                         row.cullMsMedian, row.pyramidMsMedian, row.idPassMsMedian, row.cpuMsMedian,
                         row.drawsDrawn, row.draws);
        }
    }
    report.validationMessages = instance.validationMessages();
    return report;
}

std::string benchmarkJson(const BenchmarkReport& r) {
    std::ostringstream out;
    const render::RenderSettings& s = r.settings;
    out << "{\"device\":{\"name\":" << jsonString(r.deviceName)
        << ",\"driver\":" << jsonString(r.driver) << ",\"api\":" << jsonString(r.api) << "},\n"
        << " \"settings\":{\"size\":" << jsonString(r.size) << ",\"msaa\":" << s.pipeline.msaa
        << ",\"scene\":" << jsonString(r.scene) << ",\"copies\":" << r.copies
        << ",\"lod_levels\":" << r.lodLevels << ",\"lod_level\":" << r.lodLevel
        << ",\"levels\":" << levelStatsJson(r.levels)
        << ",\"search_batch\":" << s.pipeline.searchBatch << ",\"frames\":" << r.frames
        << ",\"visible\":" << fixed(s.draws.visible, 3)
        << ",\"sort_draws\":" << (s.draws.sortDraws ? "true" : "false")
        << ",\"part_weight\":" << fixed(s.shading.partWeight, 3)
        << ",\"colorize_draws\":" << (s.shading.colorizeDraws ? "true" : "false")
        << ",\"tint_levels\":" << (s.shading.tintLevels ? "true" : "false")
        << ",\"ignore_materials\":" << (s.shading.ignoreMaterials ? "true" : "false")
        << ",\"edges\":" << (s.edges.on ? "true" : "false") << ",\"edge_width\":" << s.edges.width
        << ",\"hidden_parts\":" << r.hiddenParts << ",\"camera_path\":" << jsonString(r.cameraPath)
        << "},\n"
        << " \"results\":[";
    for (size_t i = 0; i < r.rows.size(); ++i) {
        const BenchmarkRow& row = r.rows[i];
        out << (i ? ",\n  " : "\n  ") << "{\"renderer\":" << jsonString(row.renderer)
            << ",\"mode\":" << jsonString(row.mode) << ",\"culling\":" << jsonString(row.culling)
            << ",\"culling_applied\":" << jsonString(row.cullingApplied)
            << ",\"lod_error\":" << fixed(row.lodError, 3)
            << ",\"lod_applied\":" << (row.lodApplied ? "true" : "false")
            << ",\"gpu_ms_median\":" << fixed(row.gpuMsMedian, 4)
            << ",\"gpu_ms_p90\":" << fixed(row.gpuMsP90, 4)
            << ",\"cpu_ms_median\":" << fixed(row.cpuMsMedian, 4)
            << ",\"cpu_record_ms_median\":" << fixed(row.cpuRecordMsMedian, 4)
            << ",\"id_pass_ms_median\":" << fixed(row.idPassMsMedian, 4)
            << ",\"cull_ms_median\":" << fixed(row.cullMsMedian, 4)
            << ",\"pyramid_ms_median\":" << fixed(row.pyramidMsMedian, 4)
            << ",\"early_draw_ms_median\":" << fixed(row.earlyMsMedian, 4)
            << ",\"late_draw_ms_median\":" << fixed(row.lateMsMedian, 4)
            << ",\"reused_frames\":" << row.reusedFrames << ",\"draws\":" << row.draws
            << ",\"draws_drawn\":" << fixed(row.drawsDrawn, 1) << ",\"triangles\":" << row.triangles
            << ",\"triangles_drawn\":" << fixed(row.trianglesDrawn, 1)
            << ",\"meshlets_drawn\":" << fixed(row.meshletsDrawn, 1)
            << ",\"triangles_drawn_by_level\":[";
        for (size_t l = 0; l < row.levelTrianglesDrawn.size(); ++l)
            out << (l ? "," : "") << fixed(row.levelTrianglesDrawn[l], 1);
        out << "]"
            << ",\"id_bytes\":" << row.idBytes << ",\"geometry_bytes\":" << row.geometryBytes
            << ",\"added_vertices\":" << row.addedVertices
            << ",\"added_vertex_bytes\":" << row.addedVertexBytes
            << ",\"meshlets\":" << row.meshlets << ",\"floor\":" << jsonString(row.floor)
            << ",\"ratio_to_floor\":" << fixed(row.ratioToFloor, 3) << ",\"id_image_hash\":\""
            << hex(row.idImageHash) << "\""
            << ",\"color_image_hash\":\"" << hex(row.colorImageHash) << "\""
            << ",\"switch_ms\":" << fixed(row.switchMs, 3)
            << ",\"pipeline_cached\":" << (row.pipelineCached ? "true" : "false");
        if (!row.gpuMsFrames.empty()) {
            out << ",\"gpu_ms_frames\":[";
            for (size_t f = 0; f < row.gpuMsFrames.size(); ++f)
                out << (f ? "," : "") << fixed(row.gpuMsFrames[f], 4);
            out << "]";
        }
        out << "}";
    }
    out << "\n ],\n \"skipped\":[";
    for (size_t i = 0; i < r.skipped.size(); ++i)
        out << (i ? "," : "") << "{\"renderer\":" << jsonString(r.skipped[i].first)
            << ",\"reason\":" << jsonString(r.skipped[i].second) << "}";
    out << "]}\n";
    return out.str();
}

std::string benchmarkCsv(const BenchmarkReport& r) {
    std::ostringstream out;
    out << "renderer,mode,gpu_ms_median,gpu_ms_p90,cpu_ms_median,draws,triangles,id_bytes,"
           "geometry_bytes,added_vertices,meshlets,floor,ratio_to_floor,id_image_hash,"
           "color_image_hash,culling,draws_drawn,meshlets_drawn,triangles_drawn,cull_ms_median,"
           "pyramid_ms_median\n";
    for (const BenchmarkRow& row : r.rows)
        out << row.renderer << ',' << row.mode << ',' << fixed(row.gpuMsMedian, 4) << ','
            << fixed(row.gpuMsP90, 4) << ',' << fixed(row.cpuMsMedian, 4) << ',' << row.draws << ','
            << row.triangles << ',' << row.idBytes << ',' << row.geometryBytes << ','
            << row.addedVertices << ',' << row.meshlets << ',' << row.floor << ','
            << fixed(row.ratioToFloor, 3) << ',' << hex(row.idImageHash) << ','
            << hex(row.colorImageHash) << ',' << row.culling << ',' << fixed(row.drawsDrawn, 1)
            << ',' << fixed(row.meshletsDrawn, 1) << ',' << fixed(row.trianglesDrawn, 1) << ','
            << fixed(row.cullMsMedian, 4) << ',' << fixed(row.pyramidMsMedian, 4) << '\n';
    return out.str();
}

std::string benchmarkTable(const BenchmarkReport& r) {
    std::ostringstream out;
    out << r.deviceName << " (" << r.driver << ", Vulkan " << r.api << "), " << r.size << ", "
        << r.settings.pipeline.msaa << "x MSAA, " << r.scene << " x" << r.copies
        << ", search batch " << r.settings.pipeline.searchBatch << ", " << r.frames << " frames"
        << (r.cameraPath == "none" ? "" : ", camera path " + r.cameraPath) << "\n";
    char line[240];
    std::snprintf(line, sizeof line, "%-14s %-17s %-9s %9s %9s %9s %7s %7s %8s %7s %s\n",
                  "renderer", "mode", "culling", "GPU ms", "GPU p90", "CPU ms", "cull ms",
                  "draws %", "tris %", "x floor", "floor");
    out << line;
    auto percentOf = [](double part, double total) { return total > 0 ? 100 * part / total : 0.0; };
    for (const BenchmarkRow& row : r.rows) {
        std::snprintf(line, sizeof line,
                      "%-14s %-17s %-9s %9.3f %9.3f %9.3f %7.3f %7.1f %8.1f %7.3f %s\n",
                      row.renderer.c_str(), row.mode.c_str(), row.culling.c_str(), row.gpuMsMedian,
                      row.gpuMsP90, row.cpuMsMedian, row.cullMsMedian + row.pyramidMsMedian,
                      percentOf(row.drawsDrawn, double(row.draws)),
                      percentOf(row.trianglesDrawn, double(row.triangles)), row.ratioToFloor,
                      row.floor.c_str());
        out << line;
    }
    for (const auto& [name, why] : r.skipped) out << name << ": skipped, " << why << "\n";
    return out.str();
}

int benchmarkCommand(const Options& options) {
    const LoadedScene loaded = loadScene(options.scene);
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
