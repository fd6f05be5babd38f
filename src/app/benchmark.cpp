// benchmark.cpp - the timing loop, and the table, JSON and CSV it reports.
#include "app/benchmark.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "app/headless.h"
#include "app/offscreen.h"
#include "app/scene_source.h"
#include "scene/explode.h"
#include "vk/check.h"

namespace app {
namespace {

using Clock = std::chrono::steady_clock;

struct Combination {
    const render::Technique* technique;
    const render::DrawMode* mode;
};

// no-id first in every chosen mode (the floor each row is divided by), then the renderers.
std::vector<Combination> combinations(const Options& options) {
    std::vector<Combination> list;
    const auto modes = modeList(options.mode);
    for (const auto& mode : modes)
        list.push_back({&render::noIdTechnique(), render::findDrawMode(mode)});
    for (const auto& renderer : rendererList(options.renderer)) {
        if (renderer == render::noIdTechnique().name) continue;
        for (const auto& mode : modes)
            list.push_back({render::findTechnique(renderer), render::findDrawMode(mode)});
    }
    return list;
}

std::string fixed(double value, int digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", digits, value);
    return text;
}

} // namespace

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
    report.msaa = options.msaa;
    report.copies = options.copies;
    report.searchBatch = options.searchBatch;
    report.frames = options.frames;
    const auto list = combinations(options);
    // Enough frames for clocks to settle and pipelines to be warm, without wasting time.
    const uint32_t warmup = std::clamp(options.frames / 5, 5u, 50u);

    vk::Instance instance({options.validation, {}, options.syncValidation});
    {
        Offscreen rig(instance, options);
        const vk::DeviceInfo& info = rig.device.info();
        report.deviceName = info.name;
        report.driver = info.driverName + " " + vk::driverVersionString(info);
        report.api = vk::versionString(info.apiVersion);
        rig.renderer.setScene(scene);

        const float aspect = float(rig.extent.width) / float(rig.extent.height);
        const scene::Camera camera = initialCamera(loaded, aspect); // as headless and viewer
        render::FrameParams params;
        params.viewProj = camera.viewProjection(aspect);
        params.eye = camera.eye;
        params.partColorWeight = options.partWeight;
        params.ignoreMaterials = options.ignoreMaterials;

        std::map<std::string, double> floorByMode;
        uint64_t frameNumber = 0;
        for (size_t i = 0; i < list.size(); ++i) {
            const Combination& c = list[i];
            rig.renderer.configure(scene, renderConfig(options, *c.technique, *c.mode));
            std::vector<double> cpuMs;
            for (uint32_t f = 0; f < warmup + options.frames; ++f, ++frameNumber) {
                render::FrameSlot& slot = rig.slots.begin(frameNumber);
                // --animate: objects move while being timed, the compute pass included.
                if (options.animate)
                    params.explode =
                        scene::explodeLoop(options.time.value_or(float(frameNumber) / 60.0f));
                const auto start = Clock::now();
                rig.renderer.record(slot, rig.targets, params);
                rig.slots.submit(slot);
                if (f >= warmup)
                    cpuMs.push_back(
                        std::chrono::duration<double, std::milli>(Clock::now() - start).count());
            }
            rig.slots.finish();
            const auto& all = rig.slots.gpuMilliseconds();
            const size_t timed = std::min<size_t>(options.frames, all.size());
            const std::vector<double> gpuMs(all.end() - long(timed), all.end());

            BenchmarkRow row;
            row.renderer = c.technique->name;
            row.mode = c.mode->name;
            row.gpuMsMedian = percentile(gpuMs, 0.5);
            row.gpuMsP90 = percentile(gpuMs, 0.9);
            row.cpuMsMedian = percentile(cpuMs, 0.5);
            row.draws = rig.renderer.stats().draws;
            row.triangles = scene.drawnTriangleCount();
            row.idBytes = rig.renderer.stats().idBufferBytes;
            row.frames = options.frames;
            if (c.technique == &render::noIdTechnique()) floorByMode[row.mode] = row.gpuMsMedian;
            const double floor = floorByMode[row.mode];
            row.ratioToNoId = floor > 0 ? row.gpuMsMedian / floor : 0.0;
            report.rows.push_back(row);
            std::fprintf(stderr, "benchmark: [%zu/%zu] %s + %s: GPU %.3f ms, CPU %.3f ms\n", i + 1,
                         list.size(), row.renderer.c_str(), row.mode.c_str(), row.gpuMsMedian,
                         row.cpuMsMedian);
        }
    }
    report.validationMessages = instance.validationMessages();
    return report;
}

std::string benchmarkJson(const BenchmarkReport& r) {
    std::ostringstream out;
    out << "{\"device\":{\"name\":" << jsonString(r.deviceName)
        << ",\"driver\":" << jsonString(r.driver) << ",\"api\":" << jsonString(r.api) << "},\n"
        << " \"settings\":{\"size\":" << jsonString(r.size) << ",\"msaa\":" << r.msaa
        << ",\"scene\":" << jsonString(r.scene) << ",\"copies\":" << r.copies
        << ",\"search_batch\":" << r.searchBatch << ",\"frames\":" << r.frames << "},\n"
        << " \"results\":[";
    for (size_t i = 0; i < r.rows.size(); ++i) {
        const BenchmarkRow& row = r.rows[i];
        out << (i ? ",\n  " : "\n  ") << "{\"renderer\":" << jsonString(row.renderer)
            << ",\"mode\":" << jsonString(row.mode)
            << ",\"gpu_ms_median\":" << fixed(row.gpuMsMedian, 4)
            << ",\"gpu_ms_p90\":" << fixed(row.gpuMsP90, 4)
            << ",\"cpu_ms_median\":" << fixed(row.cpuMsMedian, 4) << ",\"draws\":" << row.draws
            << ",\"triangles\":" << row.triangles << ",\"id_bytes\":" << row.idBytes
            << ",\"ratio_to_no_id\":" << fixed(row.ratioToNoId, 3) << "}";
    }
    out << "\n ]}\n";
    return out.str();
}

std::string benchmarkCsv(const BenchmarkReport& r) {
    std::ostringstream out;
    out << "renderer,mode,gpu_ms_median,gpu_ms_p90,cpu_ms_median,draws,triangles,id_bytes,"
           "ratio_to_no_id\n";
    for (const BenchmarkRow& row : r.rows)
        out << row.renderer << ',' << row.mode << ',' << fixed(row.gpuMsMedian, 4) << ','
            << fixed(row.gpuMsP90, 4) << ',' << fixed(row.cpuMsMedian, 4) << ',' << row.draws << ','
            << row.triangles << ',' << row.idBytes << ',' << fixed(row.ratioToNoId, 3) << '\n';
    return out.str();
}

std::string benchmarkTable(const BenchmarkReport& r) {
    std::ostringstream out;
    out << r.deviceName << " (" << r.driver << ", Vulkan " << r.api << "), " << r.size << ", "
        << r.msaa << "x MSAA, " << r.scene << " x" << r.copies << ", search batch " << r.searchBatch
        << ", " << r.frames << " frames\n";
    char line[200];
    std::snprintf(line, sizeof line, "%-11s %-17s %9s %9s %9s %8s %11s %7s\n", "renderer", "mode",
                  "GPU ms", "GPU p90", "CPU ms", "draws", "ID bytes", "x no-id");
    out << line;
    for (const BenchmarkRow& row : r.rows) {
        std::snprintf(line, sizeof line, "%-11s %-17s %9.3f %9.3f %9.3f %8zu %11llu %7.3f\n",
                      row.renderer.c_str(), row.mode.c_str(), row.gpuMsMedian, row.gpuMsP90,
                      row.cpuMsMedian, row.draws, static_cast<unsigned long long>(row.idBytes),
                      row.ratioToNoId);
        out << line;
    }
    return out.str();
}

int benchmarkCommand(const Options& options) {
    const LoadedScene loaded = loadScene(options);
    std::fprintf(stderr, "benchmark: %s, %u objects, %u parts, %llu triangles\n",
                 loaded.source.c_str(), unsigned(loaded.scene.objects.size()),
                 loaded.scene.uniquePartCount(),
                 static_cast<unsigned long long>(loaded.scene.drawnTriangleCount()));
    const BenchmarkReport report = runBenchmark(options, loaded);
    std::printf("%s", benchmarkTable(report).c_str());
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
