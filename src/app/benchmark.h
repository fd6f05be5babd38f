// benchmark.h - `idview --headless --benchmark`: every chosen renderer x mode, and the no-id
// floor in each mode, timed on one device with the same scene, camera and settings, and the
// frame that draws nothing (the fixed cost every row pays). The report's formats are in
// benchmark_report.cpp.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "app/cli.h"
#include "app/scene_source.h"
#include "render/clear_choice.h"
#include "render/draw_list.h"

namespace app {

struct BenchmarkRow {
    std::string renderer, mode;
    std::string culling;                  // the culling mode asked for (render::cullModeName)
    std::string cullingApplied;           // what the technique and mode get of it (describeCulling)
    float lodError = 0.0f;                // --lod-error asked, in pixels
    bool lodApplied = false;              // and whether the cull pass chose levels by it
    double gpuMsMedian = 0, gpuMsP90 = 0; // timestamps around the scene pass, culling included
    double cullMsMedian = 0, pyramidMsMedian = 0; // GPU: the cull passes, the depth pyramid
    double earlyMsMedian = 0, lateMsMedian = 0;   // GPU: the scene pass's two halves' draws
    // Medians per frame of what was drawn (draws, meshlets, triangles); totals in `draws`,
    // `meshlets` and `triangles`.
    double drawsDrawn = 0, meshletsDrawn = 0, trianglesDrawn = 0;
    double computeTrianglesDrawn = 0; // of those, by the compute rasterizer (visbuffer-compute)
    std::array<double, gpu::LOD_MAX_LEVELS> levelTrianglesDrawn{}; // of which at each level
    std::vector<double> gpuMsFrames; // with --camera-path: every timed frame, in path order
    double cpuMsMedian = 0;          // recording and submitting one frame
    double cpuRecordMsMedian = 0;    // recording its commands alone (Renderer::record)
    double idPassMsMedian = 0;       // the passes over the ID image after it (--edges), GPU
    // What the configuration holds on the GPU (Renderer::stats): draws, triangles, the
    // technique's ID data, and the derived geometry drawn instead of the scene's indices
    // (vertex-*, mesh-*) with the vertices vertex-* duplicated.
    render::RenderStats stats;
    uint64_t meshlets = 0; // the meshlets mesh-* draws (Renderer::cullTotals)
    std::string floor;     // the floor row of this row's kind (render::floorOf)
    // gpuMsMedian / the floor's gpuMsMedian in the same mode and culling mode
    double ratioToFloor = 0;
    // gpuMsMedian - BenchmarkReport::fixedCost's: what drawing this row costs beyond a frame
    // that draws nothing (0 for the fixed-cost row itself).
    double aboveFixedMs = 0;
    std::string clearPath; // the clear path its frames drew with (Renderer::clearPath)
    uint32_t frames = 0;   // timed frames (after warm-up)
    // FNV-1a of the last frame's ID and colour images: every part-ID row of one run must
    // show the same ID image, and the colour shows that the shading settings took effect.
    uint64_t idImageHash = 0, colorImageHash = 0;
    // The switch to this row on the CPU, and whether its pipeline came from the cache.
    double switchMs = 0;
    bool pipelineCached = false;
};

struct BenchmarkReport {
    std::string deviceName, driver, api;
    std::string size, scene;
    uint32_t copies = 1, frames = 0;
    uint32_t lodLevels = 1, lodLevel = 0;  // built at load, and forced for every object
    std::vector<scene::LevelStats> levels; // what each level holds (--lod-levels above 1)
    render::RenderSettings settings;       // every row's, but for technique, mode and culling
    std::string cameraPath;                // --camera-path, "none" when the camera stands still
    uint32_t hiddenParts = 0;              // --hide / --isolate
    std::vector<BenchmarkRow> rows;        // floor rows first, then renderer-major order
    // The fixed cost: the frame that draws nothing (draws.visible 0), timed like a row, once
    // per run after the rows, with the first chosen technique and mode and culling off. Its
    // clears and resolve are what no culling or level of detail touches; culling's passes
    // and pyramid, which an empty frame with culling on would time too, are culling's cost
    // and count above it.
    BenchmarkRow fixedCost;
    std::string clearPath; // the clear path the renderer drew with (never "auto")
    // With --clear auto: both paths' empty-frame times at this MSAA, as the renderer found
    // them (timed now or read from the file beside the pipeline cache).
    std::optional<render::ClearTiming> clearTiming;
    // Techniques left out because the device cannot run them, each with the reason.
    std::vector<std::pair<std::string, std::string>> skipped;
    uint32_t validationMessages = 0;
};

// Runs the benchmark `options` describe on `scene` (already loaded, copies applied).
// Progress goes to stderr.
BenchmarkReport runBenchmark(const Options& options, const LoadedScene& loaded);

std::string benchmarkJson(const BenchmarkReport& report);
std::string benchmarkCsv(const BenchmarkReport& report);
std::string benchmarkTable(const BenchmarkReport& report);

// The command: loads the scene, runs, prints the table, writes --benchmark-out. Exit code.
int benchmarkCommand(const Options& options);

// Median and nearest-rank percentile of `values` (0 when empty).
double percentile(std::vector<double> values, double fraction);

// 64-bit FNV-1a over the bytes of `data`.
uint64_t imageHash(const void* data, size_t bytes);

} // namespace app
