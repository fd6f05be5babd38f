// viewer.h - the interactive window: idview without --headless.
#pragma once

#include "app/cli.h"

namespace app {

// Opens the window on the options' scene and runs until it is closed (window close button,
// Esc with nothing selected, or a script's quit). Returns the exit code: 0, or 3 when the
// validation layer reported anything. Throws vk::Error and friends with a message for people
// (no display, no device that can present, a model that cannot be loaded at start).
int runViewer(const Options& options);

} // namespace app
