// panel_selection.h - the panel's Selection section: what a click selects, the hovered and
// selected parts in fixed-height boxes (so the section keeps its height while the cursor
// moves), the selection named by its tree node, and hide, isolate and show all.
#pragma once

#include "app/viewer/panel.h"

namespace app {

void selectionSection(const ViewSettings& view, const PanelInfo& info, PanelActions& actions,
                      PanelLayout& layout);

} // namespace app
