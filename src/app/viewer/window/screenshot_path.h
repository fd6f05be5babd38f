// screenshot_path.h - where the screenshot key (F12) writes: the desktop's Pictures folder as
// xdg-user-dirs names it, else ~/Pictures, else the current folder, under a name with the
// date and time that never overwrites an earlier file. Plain C++, unit-tested.
#pragma once

#include <ctime>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace app {

// An environment variable's value, nullopt when unset (std::getenv in the viewer; tests pass
// their own).
using Environment = std::function<std::optional<std::string>(const char*)>;
Environment processEnvironment();

// $XDG_PICTURES_DIR, else XDG_PICTURES_DIR in $XDG_CONFIG_HOME/user-dirs.dirs (default
// ~/.config), else $HOME/Pictures; the first that is a folder. Else the current folder.
std::filesystem::path picturesFolder(const Environment& env);

// folder/idview-YYYYMMDD-HHMMSS.png at local time `when`, with -2, -3... before .png when
// that file exists.
std::filesystem::path screenshotPath(const std::filesystem::path& folder, std::time_t when);

} // namespace app
