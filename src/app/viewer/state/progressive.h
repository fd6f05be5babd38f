// progressive.h - a big CAD file shown as it loads (scene::CadPartial): the slot through which
// the loading thread hands the viewer its newest partial scene, how often the viewer uploads
// one, and the words for how far a load has come and what a stopped one lacks.
#pragma once

#include <chrono>
#include <mutex>
#include <optional>
#include <string>
#include <utility>

#include "scene/cad/cad_loader.h"

namespace app {

// Written on the loading thread, taken between frames. Only the newest partial waits: each
// holds a whole copy of the scene, and one not taken yet is of no use once a newer one came.
class PartialSlot {
  public:
    void put(const scene::CadPartial& partial) {
        const std::lock_guard lock(mutex_);
        newest_ = partial;
    }
    std::optional<scene::CadPartial> take() {
        const std::lock_guard lock(mutex_);
        return std::exchange(newest_, std::nullopt);
    }

  private:
    std::mutex mutex_;
    std::optional<scene::CadPartial> newest_;
};

// When the viewer may upload the next partial scene. An upload runs on the UI thread and takes
// CPU from the workers meshing the rest (lavapipe's "GPU" is the CPU as well), so the gap after
// one grows with what it cost: the loader's own pace (cad_session.cpp) already keeps them
// seconds apart on small files, and this keeps the uploads of a large one to a small share of
// a core. Measured on video.step (docs/viewer.md, "Big CAD files").
class UploadPacer {
  public:
    using Clock = std::chrono::steady_clock;
    static constexpr double minGapSeconds = 0.5;
    static constexpr double costShare = 0.1; // at most this share of the time uploading

    bool due(Clock::time_point now) const { return now >= next_; }
    // An upload ran from `start` to `end`: the next waits for its share.
    void uploaded(Clock::time_point start, Clock::time_point end);

  private:
    Clock::time_point next_{};
};

// Solids shown of the total, the lost ones and the bytes still to read, for the panel:
// "3 of 8 solids shown, 1 lost, 12.4 MB left".
std::string shownLine(const scene::CadPartial& partial);
// What a partial scene lacks: "5 of 8 solids missing" (waiting and lost together).
std::string missingLine(const scene::CadPartial& partial);
// The box of every object's box (scene::emptyBounds when there are none).
scene::Bounds extentOf(const std::vector<scene::Bounds>& boxes);

} // namespace app
