// benchmark_report.cpp - what a benchmark run reports: the table printed, and the JSON and
// CSV that --benchmark-out writes (the fields are documented in docs/command-line.md).
#include <cstdio>
#include <sstream>

#include "app/benchmark.h"
#include "util/json_writer.h"

namespace app {
namespace {

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

// GPU and CPU milliseconds with four decimals, as the JSON and CSV have always had them.
util::Fixed ms(double value) {
    return {value, 4};
}

// Medians of counts over frames: one decimal (a median of two frames may end in .5).
util::Fixed count(double value) {
    return {value, 1};
}

// The members of one row: a result's, or the fixed cost's.
void rowMembers(util::JsonWriter& json, const BenchmarkRow& row) {
    json.member("renderer", row.renderer)
        .member("mode", row.mode)
        .member("culling", row.culling)
        .member("culling_applied", row.cullingApplied)
        .member("lod_error", util::Fixed{row.lodError, 3})
        .member("lod_applied", row.lodApplied)
        .member("gpu_ms_median", ms(row.gpuMsMedian))
        .member("gpu_ms_p90", ms(row.gpuMsP90))
        .member("above_fixed_ms", ms(row.aboveFixedMs))
        .member("cpu_ms_median", ms(row.cpuMsMedian))
        .member("cpu_record_ms_median", ms(row.cpuRecordMsMedian))
        .member("id_pass_ms_median", ms(row.idPassMsMedian))
        .member("cull_ms_median", ms(row.cullMsMedian))
        .member("pyramid_ms_median", ms(row.pyramidMsMedian))
        .member("early_draw_ms_median", ms(row.earlyMsMedian))
        .member("late_draw_ms_median", ms(row.lateMsMedian))
        .member("draws", row.stats.draws)
        .member("draws_drawn", count(row.drawsDrawn))
        .member("triangles", row.stats.triangles)
        .member("triangles_drawn", count(row.trianglesDrawn))
        .member("triangles_drawn_compute", count(row.computeTrianglesDrawn))
        .member("meshlets_drawn", count(row.meshletsDrawn))
        .beginArray("triangles_drawn_by_level");
    for (double triangles : row.levelTrianglesDrawn) json.value(count(triangles));
    json.endArray().member("id_bytes", row.stats.idBufferBytes);
    derivedGeometryMembers(json, row.stats);
    json.member("meshlets", row.meshlets)
        .member("floor", row.floor)
        .member("ratio_to_floor", util::Fixed{row.ratioToFloor, 3})
        .member("id_image_hash", hex(row.idImageHash))
        .member("color_image_hash", hex(row.colorImageHash))
        .member("switch_ms", util::Fixed{row.switchMs, 3})
        .member("pipeline_cached", row.pipelineCached)
        .member("clear_path", row.clearPath);
    if (!row.gpuMsFrames.empty()) {
        json.beginArray("gpu_ms_frames");
        for (double frameMs : row.gpuMsFrames) json.value(ms(frameMs));
        json.endArray();
    }
}

// The clear path asked for, the one that ran and, with auto, what its timing found.
void clearMembers(util::JsonWriter& json, const BenchmarkReport& r) {
    json.member("clear", render::clearPathName(r.settings.clear)).member("clear_path", r.clearPath);
    if (const auto& t = r.clearTiming)
        json.beginObject("clear_timing")
            .member("samples", t->samples)
            .member("pass_ms", ms(t->passMs))
            .member("compute_ms", ms(t->computeMs))
            .member("remembered", t->remembered)
            .endObject();
    else
        json.key("clear_timing").null();
}

// The settings every row shares.
void settingsObject(util::JsonWriter& json, const BenchmarkReport& r) {
    const render::RenderSettings& s = r.settings;
    json.beginObject("settings")
        .member("size", r.size)
        .member("msaa", s.pipeline.msaa)
        .member("scene", r.scene)
        .member("copies", r.copies)
        .member("lod_levels", r.lodLevels)
        .member("lod_level", r.lodLevel)
        .key("levels");
    levelStatsArray(json, r.levels);
    json.member("search_batch", s.pipeline.searchBatch)
        .member("frames", r.frames)
        .member("visible", util::Fixed{s.draws.visible, 3})
        .member("sort_draws", s.draws.sortDraws)
        .member("part_weight", util::Fixed{s.shading.partWeight, 3})
        .member("colorize_draws", s.shading.colorizeDraws)
        .member("tint_levels", s.shading.tintLevels)
        .member("ignore_materials", s.shading.ignoreMaterials)
        .member("edges", s.edges.on)
        .member("edge_width", s.edges.width)
        .member("raster_pixels", s.raster.trianglePixels)
        .member("raster_all", s.raster.all)
        .member("hidden_parts", r.hiddenParts)
        .member("camera_path", r.cameraPath)
        .endObject();
}

// For the table's header: "clear compute (auto: pass 0.790 ms, compute 0.308 ms, timed)".
std::string clearSummary(const BenchmarkReport& r) {
    const std::string asked = render::clearPathName(r.settings.clear);
    std::string text = "clear " + r.clearPath;
    if (asked != "auto")
        return text + (asked == r.clearPath ? " (forced)" : " (asked " + asked + ")");
    if (!r.clearTiming) return text + " (auto)";
    char timing[128];
    std::snprintf(timing, sizeof timing, " (auto: pass %.3f ms, compute %.3f ms, %s)",
                  r.clearTiming->passMs, r.clearTiming->computeMs,
                  r.clearTiming->remembered ? "remembered" : "timed now");
    return text + timing;
}

} // namespace

std::string benchmarkJson(const BenchmarkReport& r) {
    // One line per part (device, clear path, settings, fixed cost) and per result, for
    // readers that take a file line by line (tests/benchmark_test.sh).
    util::JsonWriter json;
    json.beginObject()
        .beginObject("device")
        .member("name", r.deviceName)
        .member("driver", r.driver)
        .member("api", r.api)
        .endObject()
        .newline(1);
    clearMembers(json, r);
    json.newline(1);
    settingsObject(json, r);
    json.newline(1).beginObject("fixed_cost").member("visible", util::Fixed{0.0, 3});
    rowMembers(json, r.fixedCost);
    json.endObject().newline(1).beginArray("results");
    for (const BenchmarkRow& row : r.rows) {
        json.newline(2).beginObject();
        rowMembers(json, row);
        json.endObject();
    }
    json.newline(1).endArray().newline(1).beginArray("skipped");
    for (const auto& [renderer, reason] : r.skipped)
        json.beginObject().member("renderer", renderer).member("reason", reason).endObject();
    return json.endArray().endObject().text() + "\n";
}

std::string benchmarkCsv(const BenchmarkReport& r) {
    std::ostringstream out;
    out << "renderer,mode,gpu_ms_median,gpu_ms_p90,cpu_ms_median,draws,triangles,id_bytes,"
           "geometry_bytes,added_vertices,meshlets,floor,ratio_to_floor,id_image_hash,"
           "color_image_hash,culling,draws_drawn,meshlets_drawn,triangles_drawn,cull_ms_median,"
           "pyramid_ms_median,above_fixed_ms,clear_path,visible\n";
    // The fixed cost first: the row whose visible is 0.
    auto write = [&](const BenchmarkRow& row, float visible) {
        out << row.renderer << ',' << row.mode << ',' << fixed(row.gpuMsMedian, 4) << ','
            << fixed(row.gpuMsP90, 4) << ',' << fixed(row.cpuMsMedian, 4) << ',' << row.stats.draws
            << ',' << row.stats.triangles << ',' << row.stats.idBufferBytes << ','
            << row.stats.geometryBytes << ',' << row.stats.addedVertices << ',' << row.meshlets
            << ',' << row.floor << ',' << fixed(row.ratioToFloor, 3) << ',' << hex(row.idImageHash)
            << ',' << hex(row.colorImageHash) << ',' << row.culling << ','
            << fixed(row.drawsDrawn, 1) << ',' << fixed(row.meshletsDrawn, 1) << ','
            << fixed(row.trianglesDrawn, 1) << ',' << fixed(row.cullMsMedian, 4) << ','
            << fixed(row.pyramidMsMedian, 4) << ',' << fixed(row.aboveFixedMs, 4) << ','
            << row.clearPath << ',' << fixed(visible, 3) << '\n';
    };
    write(r.fixedCost, 0.0f);
    for (const BenchmarkRow& row : r.rows) write(row, r.settings.draws.visible);
    return out.str();
}

std::string benchmarkTable(const BenchmarkReport& r) {
    std::ostringstream out;
    out << r.deviceName << " (" << r.driver << ", Vulkan " << r.api << "), " << r.size << ", "
        << r.settings.pipeline.msaa << "x MSAA, " << r.scene << " x" << r.copies
        << ", search batch " << r.settings.pipeline.searchBatch << ", " << r.frames << " frames"
        << (r.cameraPath == "none" ? "" : ", camera path " + r.cameraPath) << "\n";
    out << clearSummary(r) << "\n";
    char line[256];
    const char* format = "%-14s %-17s %-9s %9.3f %9.3f %11.3f %9.3f %7.3f %7.1f %8.1f %7.3f %s\n";
    std::snprintf(line, sizeof line, "%-14s %-17s %-9s %9s %9s %11s %9s %7s %7s %8s %7s %s\n",
                  "renderer", "mode", "culling", "GPU ms", "GPU p90", "above fixed", "CPU ms",
                  "cull ms", "draws %", "tris %", "x floor", "floor");
    out << line;
    auto percentOf = [](double part, double total) { return total > 0 ? 100 * part / total : 0.0; };
    auto write = [&](const BenchmarkRow& row, const char* renderer, const std::string& floor) {
        std::snprintf(line, sizeof line, format, renderer, row.mode.c_str(), row.culling.c_str(),
                      row.gpuMsMedian, row.gpuMsP90, row.aboveFixedMs, row.cpuMsMedian,
                      row.cullMsMedian + row.pyramidMsMedian,
                      percentOf(row.drawsDrawn, double(row.stats.draws)),
                      percentOf(row.trianglesDrawn, double(row.stats.triangles)), row.ratioToFloor,
                      floor.c_str());
        out << line;
    };
    // The fixed cost first, named for what it is; the technique that drew nothing in the
    // floor column.
    write(r.fixedCost, "empty", "fixed cost: " + r.fixedCost.renderer + ", nothing drawn");
    for (const BenchmarkRow& row : r.rows) write(row, row.renderer.c_str(), row.floor);
    for (const auto& [name, why] : r.skipped) out << name << ": skipped, " << why << "\n";
    return out.str();
}

} // namespace app
