// panel_section.h - the panel's section planes: up to three, each on an axis or on the plane
// of the selected face, with an offset slider and a flip.
#pragma once

#include <optional>

#include "app/viewer/panel/panel_layout.h"
#include "scene/bounds.h"
#include "scene/section.h"
#include "scene/surface_info.h"
#include "scene/units.h"

namespace app {

// `bounds`: the scene's, which the offset sliders span. `selectedPlane`: the selected part's
// surface when it is a planar B-rep face (world coordinates), which a plane can be put on.
// Offsets are in `unit`, the scene's. Each plane is a group of rows in `layout`.
void sectionPlanes(scene::Section& section, const scene::Bounds& bounds,
                   const std::optional<scene::SurfaceInfo>& selectedPlane,
                   const scene::LengthUnit& unit, PanelLayout& layout);

// The offsets at which a plane of this normal touches the bounds: the slider's range.
glm::dvec2 offsetRange(const scene::Bounds& bounds, glm::dvec3 normal);

} // namespace app
