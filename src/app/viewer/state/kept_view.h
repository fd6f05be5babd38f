// kept_view.h - what only the window keeps between runs and no flag sets: the panel's layout
// (shown or hidden, its width) and the recent files, as `viewer.NAME = VALUE` lines after the
// flag lines of the settings file (saved_settings.h). Each is a field of ViewSettings, read
// into it at start and written from it at close.
#pragma once

#include <string>

#include "app/saved_settings.h"
#include "app/viewer/state/view_settings.h"

namespace app {

// The lines for `view`:
//   viewer.panel = shown | hidden
//   viewer.panel-width = 400
//   viewer.recent = /path/to/model.step   (one line a file, newest first)
std::string keptViewText(const ViewSettings& view);

// Reads the viewer. lines of `text` (the settings file, named `name` in warnings) into `view`;
// a line it cannot read costs one warning and changes nothing.
void readKeptView(const std::string& text, const std::string& name, ViewSettings& view,
                  const Warn& warn);

// At most this many recent files, newest first.
constexpr size_t maxRecentFiles = 10;

} // namespace app
