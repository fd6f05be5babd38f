// census.h - `idview --census VIEWSxSIZE`: the visibility census of the model (scene/census.h,
// render/census.h) as one JSON line per unique part and a summary line, --census-csv's CSV,
// --census-export's exterior (glTF of the seen parts; STEP of the seen solids), and with
// --benchmark the census timed.
#pragma once

#include <string>
#include <vector>

#include "app/cli.h"
#include "scene/census.h"
#include "scene/scene.h"

namespace app {

struct CensusOutcome {
    std::vector<scene::Census> runs; // one, or the benchmark's repeats (the first warms up)
    // Per run: the GPU time of the views' scene passes, summed.
    std::vector<double> scenePassMs;
    scene::PartSet hidden; // the parts --hide / --isolate left out
    std::string deviceName;
    std::string pipeline; // render::describePipeline of what drew it
    uint32_t validationMessages = 0;
};

// The census of `scene` (as loaded; --explode draws it exploded) whose views hold `bounds`
// (the scene as drawn), with options.census's views and size, --hide / --isolate and the
// section; `repeats` censuses on one device. Throws vk::Error with a message for people.
CensusOutcome renderCensus(const Options& options, const scene::Scene& scene,
                           const scene::Bounds& bounds, uint32_t repeats = 1);

// {"part","object","name","path","pixels","views","largest_share"}.
std::string censusPartJson(const scene::Scene& scene, const scene::Census& census, uint32_t part);
// The same fields as CSV, a header line first. Throws std::runtime_error naming the file.
void writeCensusCsv(const std::string& path, const scene::Scene& scene,
                    const scene::Census& census);
// {"census":{views,size,ms},"parts":..,"parts_seen",...}: CensusSummary's counts.
std::string censusSummaryJson(const scene::Census& census, const scene::CensusSummary& sum);

// `idview --census`: prints the lines, writes the files; returns the exit code.
int runCensus(const Options& options);

} // namespace app
