// benchmark_report.cpp - what a benchmark run reports: the table printed, and the JSON and
// CSV that --benchmark-out writes (the fields are documented in docs/command-line.md).
#include <cstdio>
#include <sstream>

#include "app/benchmark.h"
#include "app/json.h"

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

const char* boolean(bool value) {
    return value ? "true" : "false";
}

// The fields of one row, without braces: a result's, or the fixed cost's.
std::string rowJson(const BenchmarkRow& row) {
    std::ostringstream out;
    out << "\"renderer\":" << jsonString(row.renderer) << ",\"mode\":" << jsonString(row.mode)
        << ",\"culling\":" << jsonString(row.culling)
        << ",\"culling_applied\":" << jsonString(row.cullingApplied)
        << ",\"lod_error\":" << fixed(row.lodError, 3)
        << ",\"lod_applied\":" << boolean(row.lodApplied)
        << ",\"gpu_ms_median\":" << fixed(row.gpuMsMedian, 4)
        << ",\"gpu_ms_p90\":" << fixed(row.gpuMsP90, 4)
        << ",\"above_fixed_ms\":" << fixed(row.aboveFixedMs, 4)
        << ",\"cpu_ms_median\":" << fixed(row.cpuMsMedian, 4)
        << ",\"cpu_record_ms_median\":" << fixed(row.cpuRecordMsMedian, 4)
        << ",\"id_pass_ms_median\":" << fixed(row.idPassMsMedian, 4)
        << ",\"cull_ms_median\":" << fixed(row.cullMsMedian, 4)
        << ",\"pyramid_ms_median\":" << fixed(row.pyramidMsMedian, 4)
        << ",\"early_draw_ms_median\":" << fixed(row.earlyMsMedian, 4)
        << ",\"late_draw_ms_median\":" << fixed(row.lateMsMedian, 4)
        << ",\"draws\":" << row.draws
        << ",\"draws_drawn\":" << fixed(row.drawsDrawn, 1) << ",\"triangles\":" << row.triangles
        << ",\"triangles_drawn\":" << fixed(row.trianglesDrawn, 1)
        << ",\"meshlets_drawn\":" << fixed(row.meshletsDrawn, 1)
        << ",\"triangles_drawn_by_level\":[";
    for (size_t l = 0; l < row.levelTrianglesDrawn.size(); ++l)
        out << (l ? "," : "") << fixed(row.levelTrianglesDrawn[l], 1);
    out << "]"
        << ",\"id_bytes\":" << row.idBytes << ",\"geometry_bytes\":" << row.geometryBytes
        << ",\"added_vertices\":" << row.addedVertices
        << ",\"added_vertex_bytes\":" << row.addedVertexBytes << ",\"meshlets\":" << row.meshlets
        << ",\"floor\":" << jsonString(row.floor)
        << ",\"ratio_to_floor\":" << fixed(row.ratioToFloor, 3) << ",\"id_image_hash\":\""
        << hex(row.idImageHash) << "\""
        << ",\"color_image_hash\":\"" << hex(row.colorImageHash) << "\""
        << ",\"switch_ms\":" << fixed(row.switchMs, 3)
        << ",\"pipeline_cached\":" << boolean(row.pipelineCached)
        << ",\"clear_path\":" << jsonString(row.clearPath);
    if (!row.gpuMsFrames.empty()) {
        out << ",\"gpu_ms_frames\":[";
        for (size_t f = 0; f < row.gpuMsFrames.size(); ++f)
            out << (f ? "," : "") << fixed(row.gpuMsFrames[f], 4);
        out << "]";
    }
    return out.str();
}

// The clear path asked for, the one that ran and, with auto, what its timing found.
std::string clearJson(const BenchmarkReport& r) {
    std::ostringstream out;
    out << "\"clear\":" << jsonString(render::clearPathName(r.settings.clear))
        << ",\"clear_path\":" << jsonString(r.clearPath) << ",\"clear_timing\":";
    if (const auto& t = r.clearTiming)
        out << "{\"samples\":" << t->samples << ",\"pass_ms\":" << fixed(t->passMs, 4)
            << ",\"compute_ms\":" << fixed(t->computeMs, 4)
            << ",\"remembered\":" << boolean(t->remembered) << "}";
    else
        out << "null";
    return out.str();
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
    std::ostringstream out;
    const render::RenderSettings& s = r.settings;
    out << "{\"device\":{\"name\":" << jsonString(r.deviceName)
        << ",\"driver\":" << jsonString(r.driver) << ",\"api\":" << jsonString(r.api) << "},\n "
        << clearJson(r) << ",\n"
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
        << " \"fixed_cost\":{\"visible\":0.000," << rowJson(r.fixedCost) << "},\n"
        << " \"results\":[";
    for (size_t i = 0; i < r.rows.size(); ++i)
        out << (i ? ",\n  " : "\n  ") << "{" << rowJson(r.rows[i]) << "}";
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
           "pyramid_ms_median,above_fixed_ms,clear_path,visible\n";
    // The fixed cost first: the row whose visible is 0.
    auto write = [&](const BenchmarkRow& row, float visible) {
        out << row.renderer << ',' << row.mode << ',' << fixed(row.gpuMsMedian, 4) << ','
            << fixed(row.gpuMsP90, 4) << ',' << fixed(row.cpuMsMedian, 4) << ',' << row.draws << ','
            << row.triangles << ',' << row.idBytes << ',' << row.geometryBytes << ','
            << row.addedVertices << ',' << row.meshlets << ',' << row.floor << ','
            << fixed(row.ratioToFloor, 3) << ',' << hex(row.idImageHash) << ','
            << hex(row.colorImageHash) << ',' << row.culling << ',' << fixed(row.drawsDrawn, 1)
            << ',' << fixed(row.meshletsDrawn, 1) << ',' << fixed(row.trianglesDrawn, 1) << ','
            << fixed(row.cullMsMedian, 4) << ',' << fixed(row.pyramidMsMedian, 4) << ','
            << fixed(row.aboveFixedMs, 4) << ',' << row.clearPath << ',' << fixed(visible, 3)
            << '\n';
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
        std::snprintf(
            line, sizeof line, format, renderer, row.mode.c_str(), row.culling.c_str(),
            row.gpuMsMedian, row.gpuMsP90, row.aboveFixedMs, row.cpuMsMedian,
            row.cullMsMedian + row.pyramidMsMedian, percentOf(row.drawsDrawn, double(row.draws)),
            percentOf(row.trianglesDrawn, double(row.triangles)), row.ratioToFloor, floor.c_str());
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
