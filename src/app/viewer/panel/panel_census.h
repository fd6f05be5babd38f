// panel_census.h - the panel's Visibility section: a census of views over a sphere (its
// views and size, Run, its progress and Cancel), what it found and what to do with the parts
// it never saw, Export seen... (what it saw, to a .glb or .step file), and "visible from
// here": the parts of the window's picture by pixel area.
#pragma once

#include "app/viewer/panel/panel.h"

namespace app {

void visibilitySection(ViewSettings& view, const PanelInfo& info, PanelActions& actions);

} // namespace app
