// pacer.cpp - the viewer's decisions to draw or rest (see pacer.h).
#include "app/viewer/pacer.h"

#include <algorithm>
#include <cmath>

#include "render/blink.h"

namespace app {
namespace {

// The blink's step at `seconds`: a frame is due when it changes.
double blinkStep(double seconds) {
    return std::floor(seconds * 2.0 * render::blinkHz);
}

} // namespace

bool FramePacer::due(const FrameWants& wants) {
    if (wants.events != seenEvents_) {
        seenEvents_ = wants.events;
        owed_ = settleFrames;
    }
    if (wants.continuous || wants.busy || owed_ > 0 || !lastFrame_) return true;
    if (wants.loading && wants.now - *lastFrame_ >= progressInterval) return true;
    if (wants.changeAt && *lastFrame_ < *wants.changeAt && wants.now >= *wants.changeAt)
        return true;
    return wants.hovering && blinkStep(wants.now) != blinkStep(*lastFrame_);
}

std::optional<double> FramePacer::rest(const FrameWants& wants) const {
    std::optional<double> wait = wants.scriptWake;
    auto sooner = [&](double seconds) { wait = std::min(wait.value_or(seconds), seconds); };
    if (wants.loading) sooner(progressInterval);
    if (wants.hovering) sooner(render::nextBlinkChange(wants.now) - wants.now);
    if (wants.changeAt && *wants.changeAt > wants.now) sooner(*wants.changeAt - wants.now);
    if (wait) wait = std::max(*wait, 0.0);
    return wait;
}

bool FramePacer::needsScene(const SceneKey& key, bool continuous) const {
    return continuous || !drawn_ || !(*drawn_ == key);
}

void FramePacer::drew(const FrameWants& wants, bool scene, const SceneKey& key) {
    lastFrame_ = wants.now;
    if (scene) {
        ++scenePasses_;
        drawn_ = key;
        owed_ = settleFrames; // its readbacks arrive in the frames after it
    } else {
        ++compositions_;
        owed_ = std::max(owed_ - 1, 0);
    }
}

} // namespace app
