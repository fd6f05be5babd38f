// measure_overlay.h - measure mode's points and distance drawn over the view (measure.h), and
// the Inspect section's closest points drawn the same way in another colour.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "app/viewer/state/measure.h"

namespace app {

// The overlays' colours (ImGui's packed RGBA): measure mode's points in yellow, the Inspect
// panel's closest points in cyan (inspect_panel.h), so the two never read as one another.
inline constexpr uint32_t measureColour = 0xFF3BEBFFu, inspectColour = 0xFFFFDC40u;

// The overlay: the points, and with two the line between them labelled with the distance,
// over the window of `size` seen through `viewProj`, the distance in `unit` rounded to
// `precision` (the scene's).
void drawMeasure(const std::vector<MeasurePoint>& points, const glm::dmat4& viewProj,
                 glm::vec2 size, const scene::LengthUnit& unit, const scene::Precision& precision,
                 uint32_t colour = measureColour);

} // namespace app
