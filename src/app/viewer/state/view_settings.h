// view_settings.h - what only the window has and keeps: vsync, the panel's place and size,
// the tree pane's state, the open field and file browser, the recent files. The panel edits
// it in place; kept_view.h keeps its lasting part between runs.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/viewer/state/file_browser.h"

namespace app {

// What the layout keeps between frames (in ViewSettings).
struct PanelLayoutState {
    std::string anchor;   // the mark just above the pointer in the last frame, "" when none
    float anchorY = 0.0f; // its place then: content y, the blank room above not counted
    float roomAbove = 0.0f, roomBelow = 0.0f; // blank room, while the pointer stays
    // The event lines last told (each comes on a change only).
    std::string told, toldRows, toldPointer;
};

// What only the window has.
struct ViewSettings {
    bool vsync = true;
    // The panel's layout, kept between runs (kept_view.h): whether it shows (F9) and its
    // width in pixels, dragged by its right edge and kept between minPanelWidth and
    // maxPanelShare of the window's width.
    bool panelVisible = true;
    float panelWidth = 360.0f;
    std::array<char, 96> objectFilter{}; // the assembly tree's filter text
    // The assembly tree's state, per row of PanelInfo::tree: open nodes; and the rows the
    // filter keeps, worked out again only when the filter text changes.
    std::vector<uint8_t> treeOpen, treeShown;
    std::string treeFilterFor;
    float treeRows = 8.0f; // the tree pane's height in rows, dragged by the bar under it
    // What a click selects around the part under the cursor (scene::partsAround's level): 0
    // the part (a CAD face), 1 its object (a CAD solid), 2 the assembly node above that. A
    // double-click selects at least the object.
    uint32_t selectLevel = 0;
    std::array<char, 512> openPath{}; // the panel's "open" field, emptied when a model opens
    bool focusOpen = false;           // Ctrl+L: the open field takes the keys
    // The panel's own file browser, open when Open... found no desktop chooser.
    std::optional<FileBrowser> browser;
    // Models opened, newest first, at most 10; kept between runs (kept_view.h).
    std::vector<std::string> recentFiles;
    // Where the panel lay in the last frame, window x coordinates (both 0 while hidden): F
    // fits the scene in the area beside it.
    float panelLeft = 0.0f, panelRight = 0.0f;
    PanelLayoutState layout; // the row under the pointer, the clipping report
    // The Visibility section's census fields: views, and each view's size in pixels.
    uint32_t censusViews = 162, censusSize = 512;
    // Export seen...'s path field, and the proposal it was filled with (a new model, a new one).
    std::array<char, 512> exportPath{};
    std::string exportPathFor;
};

} // namespace app
