// thumbnail.h - idview --thumbnail: a file manager's preview of a model (the freedesktop
// thumbnail specification's Exec line, data/idview.thumbnailer), bounded in time and memory.
#pragma once

#include "app/cli.h"

namespace app {

// Renders options.live.scene's model headless, fitted, at options.thumbnail.size square, in a
// child process under a data-memory cap that is killed (with the load workers it started)
// after options.thumbnail.seconds. The PNG is written under a temporary name and renamed onto
// options.screenshot only when whole, so a refusal or a kill leaves no file. Returns 0, or
// non-zero after one line on stderr.
int runThumbnail(const Options& options);

} // namespace app
