// census_export.h - the Visibility section's Export seen...: what the finished census saw
// written to a file (app/exterior_export.h) on a worker thread, as a STEP file of a big
// board takes Open CASCADE seconds: the window keeps drawing and resting meanwhile, and the
// answer wakes it. One export at a time; the panel shows its line (writing, wrote, the error).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "app/exterior_export.h"
#include "app/scene_source.h"
#include "util/latest_worker.h"

namespace app {

// What the worker writes from: its own copies, so the viewer may change its scene meanwhile.
struct ExportJob {
    std::string path;
    std::shared_ptr<const scene::Scene> scene; // the scene the census counted (CensusFound)
    scene::Census census;
    std::string source; // the CAD file the scene was loaded from, read again for STEP
    scene::Healing healing = scene::Healing::On;
};

// How an export ended: what it wrote, or the one line it failed with.
struct ExportOutcome {
    std::string path;
    std::optional<ExteriorWritten> written;
    bool replaced = false; // a file of that name was there before
    std::string error;
    bool solids = false;      // the objects are CAD solids (else meshes)
    std::string line() const; // the panel's
};

// Where Export seen... proposes to write: the model's folder (the working folder for a
// built-in or procedural scene), its stem with "-exterior.glb".
std::string defaultExportPath(const LoadedScene& loaded);

class CensusExport {
  public:
    // `landed` runs on the worker thread when an answer is there (to wake a resting loop).
    explicit CensusExport(std::function<void()> landed) : worker_(std::move(landed)) {}

    void start(ExportJob job);
    // An export refused before it started (no census, a STEP of a mesh): its line shows.
    ExportOutcome refuse(const std::string& path, const std::string& error);
    // From start() until its answer is taken: the script's census-done waits for it.
    bool writing() const { return writing_; }
    bool landed() const { return worker_.landed(); } // take() has an answer: a frame for it
    std::optional<ExportOutcome> take();
    const std::string& line() const { return line_; } // "" before the first export

  private:
    bool writing_ = false;
    std::string line_;
    util::LatestWorker<ExportOutcome> worker_;
};

} // namespace app
