// inspect_panel.h - the panel's Inspect section (the rows of inspect_report.h, each under the
// component it is about) and the overlay of A's and B's two closest points, the line between
// them and its length, drawn as measure mode draws its points (measure.h).
#pragma once

#include <glm/glm.hpp>

#include "app/viewer/state/inspect_report.h"

namespace app {

void inspectSection(const InspectReport& report);

// Over the window of `size` seen through `viewProj` (world to clip); nothing without a
// distance.
void drawInspect(const InspectReport& report, const glm::dmat4& viewProj, glm::vec2 size,
                 const scene::LengthUnit& unit, const scene::Precision& precision);

} // namespace app
