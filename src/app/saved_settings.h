// saved_settings.h - the viewer's settings kept between runs: a small text file of
// command-line flags, one per line, read when the viewer starts (the command line, read
// after it, wins) and written when it closes. The flag table parses each line, so a setting
// is defined once, as its flag, and reaches the viewer as the command line would give it.
// The window's size and position are flags too (--size, --window-pos). What only the window
// has and no flag sets (the panel's layout, the recent files) follows as `viewer.NAME = VALUE`
// lines, which the viewer reads and writes itself (viewer/kept_view.h).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "app/live_settings.h"

namespace app {

struct Options; // cli.h: the command line

using Warn = std::function<void(const std::string&)>; // one line for people

// The start of the window's own lines, which the flag lines skip.
constexpr const char* viewLinePrefix = "viewer.";
bool isViewLine(const std::string& line);

// $XDG_CONFIG_HOME/idview/viewer.conf, else $HOME/.config/idview/viewer.conf; "" when
// neither variable is set.
std::string savedSettingsPath();

// The kept settings of `live` and the window's place that differ from viewerDefaults()', one
// flag per line.
std::string savedSettingsText(const LiveSettings& live, const WindowPlace& window);

// The arguments the lines of `text` hold. A line that names no kept setting or that its flag
// refuses is left out, with one warning naming `name`:line and why; blank lines and lines
// starting with '#' are skipped.
std::vector<std::string> savedArgs(const std::string& text, const std::string& name,
                                   const Warn& warn);

// The viewer's options: viewerDefaults(), then the settings kept at `path` (unless `args`
// hold --no-saved-settings, or no file is there), then `args`. Kept settings that `args`
// contradict are all left out, with one warning. Throws UsageError for bad `args` alone.
Options viewerOptions(const std::vector<std::string>& args, const std::string& path,
                      const Warn& warn);

// The kept settings of `live` back to viewerDefaults()' (the panel's Reset to defaults); the
// window's place stays where it is.
void resetSavedSettings(LiveSettings& live);

// The file's text; "" when there is none.
std::string readSavedSettings(const std::string& path);

// Writes savedSettingsText(live, window) and then `viewText` (the window's own lines) to
// `path`, making its folder; a failure is one warning.
void writeSavedSettings(const std::string& path, const LiveSettings& live,
                        const WindowPlace& window, const Warn& warn,
                        const std::string& viewText = {});

} // namespace app
