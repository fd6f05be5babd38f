// panel_selection.h - the panel's Properties section: the visible parts, the selected and
// hovered parts (the selection named by its tree node), and the measure points and Inspect
// report, each in a box of fixed height, so the section keeps its height whatever the
// pointer, the selection and the clicks do.
#pragma once

#include "app/viewer/panel/panel.h"

namespace app {

void propertiesSection(const PanelInfo& info, PanelLayout& layout);

} // namespace app
