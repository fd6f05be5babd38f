// panel_browser.h - the panel's file browser (file_browser.h) drawn under the open field
// while it is open: the folder, Up and the recent folders, a filter that takes the keys, the
// entries, Open and Cancel.
#pragma once

#include <optional>

#include "app/viewer/state/events.h"
#include "app/viewer/state/file_browser.h"
#include "app/viewer/panel/panel.h"

namespace app {

// Draws `browser` when it is open; a chosen model becomes an Open command, and the browser
// closes with it or with Cancel and Esc. Changes of what it shows go to `events`.
void drawFileBrowser(std::optional<FileBrowser>& browser, PanelActions& actions,
                     const Events* events);

} // namespace app
