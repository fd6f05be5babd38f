// progressive.cpp - the pace of partial scene uploads and the words for a load's progress
// (progressive.h).
#include "app/viewer/state/progressive.h"

#include <algorithm>
#include <cstdio>

#include "scene/bounds.h"

namespace app {

void UploadPacer::uploaded(Clock::time_point start, Clock::time_point end) {
    const auto cost = std::chrono::duration<double>(end - start).count();
    const double gap = std::max(minGapSeconds, cost / costShare);
    next_ = end + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(gap));
}

std::string shownLine(const scene::CadPartial& partial) {
    std::string line = std::to_string(partial.solidsReady) + " of " +
                       std::to_string(partial.solidsTotal) + " solids shown";
    if (partial.solidsLost > 0) line += ", " + std::to_string(partial.solidsLost) + " lost";
    if (partial.bytesTotal > partial.bytesDone) {
        char left[48];
        std::snprintf(left, sizeof left, ", %.1f MB left",
                      double(partial.bytesTotal - partial.bytesDone) / 1e6);
        line += left;
    }
    return line;
}

std::string missingLine(const scene::CadPartial& partial) {
    return std::to_string(partial.solidsTotal - partial.solidsReady) + " of " +
           std::to_string(partial.solidsTotal) + " solids missing";
}

scene::Bounds extentOf(const std::vector<scene::Bounds>& boxes) {
    scene::Bounds all = scene::emptyBounds();
    for (const scene::Bounds& box : boxes)
        if (!scene::isEmpty(box)) all = scene::unite(all, box);
    return all;
}

} // namespace app
