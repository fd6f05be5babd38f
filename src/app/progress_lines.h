// progress_lines.h - the lines a long CAD load prints on stderr ("idview: loading FILE:
// tessellating 40%"), as command-line tools do: at a terminal, where a person reads them, once
// a load has taken a second; into a pipe or a log only when --progress asks (then from the
// start of every load). The viewer's panel shows its own progress either way.
#pragma once

#include <chrono>
#include <cstdio>
#include <functional>
#include <string>

#include "scene/cad/cad_loader.h"

namespace app {

// At a terminal, a load prints no progress line before it has taken this long.
constexpr std::chrono::seconds progressQuiet{1};

// Whether progress lines go to the file descriptor `fd`: asked for (--progress), or a terminal.
bool progressLinesWanted(bool asked, int fd);

// A reporter writing "idview: loading SOURCE: STAGE N%" lines to `out`, one per stage and
// tenth at most, none before `quiet` has passed since it was made; `now` is its clock.
using ProgressClock = std::function<std::chrono::steady_clock::time_point()>;
scene::CadProgress progressLines(const std::string& source, std::FILE* out,
                                 std::chrono::steady_clock::duration quiet,
                                 ProgressClock now = std::chrono::steady_clock::now);

// The reporter a load of `source` uses: progressLines on stderr where progressLinesWanted
// says so (asked: without the quiet second), else none (an empty function).
scene::CadProgress stderrProgress(const std::string& source, bool asked);

} // namespace app
