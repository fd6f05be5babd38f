// progress_lines.cpp - a CAD load's progress lines on stderr (progress_lines.h).
#include "app/progress_lines.h"

#include <unistd.h>

#include <algorithm>
#include <memory>
#include <mutex>

namespace app {

bool progressLinesWanted(bool asked, int fd) {
    return asked || isatty(fd) == 1;
}

scene::CadProgress progressLines(const std::string& source, std::FILE* out,
                                 std::chrono::steady_clock::duration quiet, ProgressClock now) {
    // A load may report from other threads than the one that made the reporter.
    struct State {
        std::mutex mutex;
        std::chrono::steady_clock::time_point start;
        std::string stage;
        int tenth = -1;
    };
    auto state = std::make_shared<State>();
    state->start = now();
    return [state, source, out, quiet, now = std::move(now)](const char* stage, double fraction) {
        const std::lock_guard lock(state->mutex);
        if (now() - state->start < quiet) return;
        const int tenth = std::clamp(int(fraction * 10.0), 0, 10);
        if (state->stage == stage && tenth <= state->tenth) return;
        state->stage = stage;
        state->tenth = tenth;
        std::fprintf(out, "idview: loading %s: %s %d%%\n", source.c_str(), stage, tenth * 10);
        std::fflush(out);
    };
}

scene::CadProgress stderrProgress(const std::string& source, bool asked) {
    if (!progressLinesWanted(asked, STDERR_FILENO)) return {};
    return progressLines(source, stderr,
                         asked ? std::chrono::steady_clock::duration::zero()
                               : std::chrono::steady_clock::duration(progressQuiet));
}

} // namespace app
