// frame_loop.h - the frames of a headless run and of the benchmark, drawn by one loop: the
// camera along its path, the animation's moment, record, submit, the last frame's readback
// and the GPU's timings. What the two do differently (warm-up, every frame's images, the
// part sets of the last frame) is a FrameRun they pass in.
#pragma once

#include <optional>
#include <vector>

#include "app/cli.h"
#include "app/headless.h"
#include "app/offscreen.h"
#include "render/frame_slots.h"
#include "render/renderer.h"
#include "scene/bounds.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace app {

// What differs between runs of frames.
struct FrameRun {
    // Frames drawn first and left out of the timings, all at the camera path's start: the
    // benchmark's, for clocks to settle and pipelines to be warm.
    uint32_t warmup = 0;
    // Read back the images of every timed frame, not only the last (Options::keepEveryFrame).
    bool keepEveryFrame = false;
    // Part sets the last frame collects (headless --visible-parts); the benchmark's every
    // frame collects those of the parameters it passes.
    std::vector<render::PartSetQuery> lastFrameSets;
};

// What the timed frames gave, one entry per frame, oldest first.
struct TimedFrames {
    std::vector<double> gpuMs;    // the scene pass, culling included
    std::vector<double> idPassMs; // the passes over the ID image (edges, part sets)
    std::vector<render::FrameTimes> steps;
    std::vector<gpu::CullStats> cullStats;
    // On the CPU: recording and submitting the frame, and recording it alone
    // (Renderer::record).
    std::vector<double> cpuMs, cpuRecordMs;
    std::vector<HeadlessResult::Images> everyFrame; // with FrameRun::keepEveryFrame
    HeadlessResult::Images last;                    // the last frame's images
};

class FrameLoop {
  public:
    // Timed frame f of Options::frames sees the camera at frame f of Options::cameraPath,
    // which starts at `camera` around `scene`.
    FrameLoop(Offscreen& rig, const Options& options, const scene::Scene& scene,
              const scene::Camera& camera);

    // The frame parameters of timed frame `frame`'s view.
    render::FrameParams view(uint32_t frame) const;
    // One frame of `params` at the animation's moment, waited for: picks and selections
    // read what it found (FrameSlots::latestPick, latestPartSets).
    void waitedFrame(render::FrameParams params);
    // `how`'s warm-up frames, then Options::frames timed frames of `params` along the camera
    // path, waited for.
    TimedFrames run(const render::FrameParams& params, const FrameRun& how);

    // From just before the device was created to the fence of the first frame this loop
    // drew, of whichever kind; nullopt before one.
    std::optional<double> firstFrameMs() const { return firstFrameMs_; }

  private:
    // After the first frame's submission: waits for it to time it.
    void firstFrameDone();
    // The images the readback holds, once their frame has finished.
    HeadlessResult::Images readImages() const;

    Offscreen& rig_;
    const Options& options_;
    Readback readback_;
    scene::Camera camera_;
    scene::Bounds bounds_; // of the scene, where a camera path needs them
    uint64_t frameNumber_ = 0;
    std::optional<double> firstFrameMs_;
};

} // namespace app
