// clear_choice.cpp - the timings file of ClearPath::Auto (see clear_choice.h).
#include "render/clear_choice.h"

#include <cstdio>
#include <sstream>

namespace render {
namespace {

constexpr const char* kHeader = "idview clear paths 1 driver ";

} // namespace

std::string clearTimingFileName(const PipelineCacheIdentity& identity) {
    // The pipeline cache's name, which already tells devices and driver builds apart.
    const std::string pipelines = pipelineFileName(identity); // "pipelines-...-<UUID>.bin"
    const std::string ids = pipelines.substr(pipelines.find('-'));
    return "clear-paths" + ids.substr(0, ids.size() - 4) + ".txt";
}

std::string encodeClearTimings(const PipelineCacheIdentity& identity,
                               const std::map<uint32_t, ClearTiming>& timings) {
    std::ostringstream out;
    out << kHeader << identity.driverVersion << "\n";
    out << "# samples, GPU ms of an empty frame: clear in the pass, clear depth and resolve in "
           "compute\n";
    for (const auto& [samples, t] : timings) {
        char line[96];
        std::snprintf(line, sizeof line, "%u %.4f %.4f\n", samples, t.passMs, t.computeMs);
        out << line;
    }
    return out.str();
}

std::map<uint32_t, ClearTiming> decodeClearTimings(const std::string& text,
                                                   const PipelineCacheIdentity& identity) {
    std::map<uint32_t, ClearTiming> timings;
    std::istringstream in(text);
    std::string line;
    if (!std::getline(in, line) || line != kHeader + std::to_string(identity.driverVersion))
        return timings;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        ClearTiming t;
        std::string rest;
        if (!(fields >> t.samples >> t.passMs >> t.computeMs) || (fields >> rest) ||
            t.samples == 0 || (t.samples & (t.samples - 1)) || !(t.passMs > 0.0) ||
            !(t.computeMs > 0.0))
            return {}; // damaged: time again
        t.remembered = true;
        timings[t.samples] = t;
    }
    return timings;
}

} // namespace render
