// panel_tools.h - the panel's Tools section: what a CAD user does to the model, together in
// one place: the view (edges, projection, the standard views), what a click selects, hide,
// isolate and show all, X-ray, measure mode and the exploded view. Its rows depend on nothing
// the pointer or a selection changes, so they never move between two clicks.
#pragma once

#include "app/viewer/panel/panel.h"

namespace app {

void toolsSection(const LiveSettings& settings, const ViewSettings& view, const PanelInfo& info,
                  PanelActions& actions, PanelLayout& layout);

} // namespace app
