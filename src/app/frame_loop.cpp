// frame_loop.cpp - one loop over the frame slots for headless runs and the benchmark.
#include "app/frame_loop.h"
#include "app/camera_frame.h"

#include <algorithm>
#include <chrono>

#include "scene/camera_path.h"

namespace app {

namespace {

using Clock = std::chrono::steady_clock;

double msBetween(Clock::time_point start, Clock::time_point end) {
    return std::chrono::duration<double, std::milli>(end - start).count();
}

// The last `count` entries of `history`.
template <typename T>
std::vector<T> lastOf(const std::vector<T>& history, size_t count) {
    return std::vector<T>(history.end() - long(count), history.end());
}

} // namespace

FrameLoop::FrameLoop(Offscreen& rig, const Options& options, const scene::Scene& scene,
                     const scene::Camera& camera)
    : rig_(rig), options_(options), readback_(rig.device, rig.extent), camera_(camera),
      bounds_(options.cameraPath == scene::CameraPath::None ? scene::Bounds{} : scene.bounds()) {}

render::FrameParams FrameLoop::view(uint32_t frame) const {
    return cameraFrame(
        scene::cameraOnPath(options_.cameraPath, camera_, bounds_, frame, options_.frames),
        rig_.extent);
}

void FrameLoop::firstFrameDone() {
    if (firstFrameMs_) return;
    rig_.slots.finish();
    firstFrameMs_ = msBetween(rig_.start, Clock::now());
}

HeadlessResult::Images FrameLoop::readImages() const {
    return {readback_.idValues(), readback_.colorBytes()};
}

void FrameLoop::waitedFrame(render::FrameParams params) {
    // --animate: every frame at its own moment, the picks' too.
    params.explode = explodeAt(options_.live.animation, frameNumber_);
    render::FrameSlot& slot = rig_.slots.begin(frameNumber_++);
    rig_.renderer.record(slot, rig_.targets, params);
    rig_.slots.submit(slot);
    rig_.slots.finish();
    firstFrameDone();
}

TimedFrames FrameLoop::run(const render::FrameParams& params, const FrameRun& how) {
    TimedFrames timed;
    const uint32_t total = how.warmup + options_.frames;
    for (uint32_t f = 0; f < total; ++f, ++frameNumber_) {
        const bool last = f + 1 == total, timedFrame = f >= how.warmup;
        render::FrameSlot& slot = rig_.slots.begin(frameNumber_);
        render::FrameParams frame = params;
        // --animate: objects move while being timed, the compute pass included.
        frame.explode = explodeAt(options_.live.animation, frameNumber_);
        frame.setView(view(f < how.warmup ? 0 : f - how.warmup));
        if (last && !how.lastFrameSets.empty()) frame.partSets = how.lastFrameSets;
        const auto begun = Clock::now();
        rig_.renderer.record(slot, rig_.targets, frame);
        const auto recorded = Clock::now();
        if (last || (timedFrame && how.keepEveryFrame)) readback_.record(slot.cmd, *rig_.targets);
        rig_.slots.submit(slot);
        if (timedFrame) {
            timed.cpuMs.push_back(msBetween(begun, Clock::now()));
            timed.cpuRecordMs.push_back(msBetween(begun, recorded));
        }
        firstFrameDone();
        if (timedFrame && how.keepEveryFrame) {
            rig_.slots.finish();
            timed.everyFrame.push_back(readImages());
        }
    }
    rig_.slots.finish();
    const render::FrameSlots& slots = rig_.slots;
    // The history keeps the newest FrameSlots::historyLimit frames at least.
    const size_t count = std::min<size_t>(options_.frames, slots.gpuMilliseconds().size());
    timed.gpuMs = lastOf(slots.gpuMilliseconds(), count);
    timed.idPassMs = lastOf(slots.idPassMilliseconds(), count);
    timed.steps = lastOf(slots.frameTimes(), count);
    timed.cullStats = lastOf(slots.cullStats(), count);
    timed.last = readImages();
    return timed;
}

} // namespace app
