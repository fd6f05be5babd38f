// panel_tree.h - the panel's assembly tree: a row per node of the file's tree (STEP/IGES
// products and instances, glTF nodes, procedural groups), each with a visibility checkbox
// over every part under it, a click that selects those parts (Ctrl+click adds them) and a
// filter that keeps the matching nodes and their parents. Rows whose parts are all selected
// are highlighted; siblings come sorted (the viewer sorts the tree) and same names numbered.
// Only the rows on screen are drawn.
#pragma once

#include "app/viewer/panel/panel.h"

namespace app {

void assemblyTree(ViewSettings& view, const PanelInfo& info, PanelActions& actions,
                  PanelLayout& layout);

// Which rows the filter keeps: those whose name holds `filter` (any case), and every parent
// of one; all rows for an empty filter.
std::vector<uint8_t> rowsMatching(const std::vector<scene::TreeRow>& rows, const char* filter);

} // namespace app
