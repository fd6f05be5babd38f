// inspect_report.h - what the Inspect panel says of the selection and of things A and B: the
// selection's bounding box and size, each selected CAD solid's volume, area and centre of
// mass and their sum, and A's and B's distance (scene/inspect.h). Worked out once each time
// the selection or the things change, never per frame, and on a worker thread
// (inspect_query.h): exact answers take Open CASCADE milliseconds to seconds, which the frame
// does not wait for; the rows say "computing..." meanwhile. Plain C++ (no ImGui), unit-tested.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/viewer/state/events.h"
#include "app/viewer/state/things.h"
#include "scene/assembly_tree.h"
#include "scene/inspect.h"
#include "scene/part_set.h"
#include "util/latest_worker.h"

namespace app {

// One line of the panel: the component it is about (the selection's node, a solid's path,
// A, B, or A and B) and what is said of it, every value with its unit.
struct InspectRow {
    std::string component; // empty: the unit's heading, above every row (inspectRows)
    std::string text;
};

struct InspectReport {
    uint32_t selectedParts = 0;
    std::string selectionName; // the tree node the selection makes up, else "N parts"
    std::optional<scene::Bounds> bounds;
    bool exactBounds = false; // the B-rep's boxes of whole solids, else the triangles'
    std::vector<scene::SolidProperties> solids; // CAD scenes: each solid with a selected part
    uint32_t solidsLeftOut = 0;                 // past maxSolids
    // Two solids or more: scene::sumProperties (volumes and areas added, the centre of mass
    // weighted by volume, by area where one is open; `object` holds the count).
    std::optional<scene::SolidProperties> sum;
    std::optional<scene::Thing> a, b;
    std::optional<scene::DistanceReport> distance; // A and B both there
    std::vector<InspectRow> rows;                  // what the panel shows
    // Asked of the worker, not answered yet: the rows say "computing..." in their place.
    bool computingSelection = false, computingDistance = false;
};

// What the worker answers (inspect_query.h): the parts of a report it was asked for.
struct InspectAnswer {
    bool selection = false; // report's selection fields hold the answer
    InspectReport report;   // selectedParts, bounds, exactBounds, solids, solidsLeftOut, sum
    bool distance = false;  // `measured` holds the answer
    std::optional<scene::DistanceReport> measured;
};

// The panel's rows of a report; lengths, areas and volumes in `unit`.
std::vector<InspectRow> inspectRows(const scene::Scene& scene, const InspectReport& report);

// Keeps the report of the last selection and things: asks its worker again when they change,
// and takes the answer in when it lands. A newer question supersedes an older one, whose
// answer never shows.
class Inspector {
  public:
    // A selection of more solids than this lists the first ones: each costs a B-rep walk.
    static constexpr uint32_t maxSolids = 64;

    // `landed` is called on the worker thread when an answer is there (to wake a resting loop).
    explicit Inspector(std::function<void()> landed = {});
    ~Inspector(); // cancels the question being worked out and joins the worker

    // Whether update() has something to do now: a question to ask, or an answer to take in.
    bool due(const scene::PartSet& selected, const Things& things) const {
        return !valid_ || selected != selection_ || things.version() != version_ ||
               worker_.landed();
    }
    // Asks when the selection or things changed, takes a landed answer in; says the event
    // records: at once inspect_things and, where there is work, inspect_computing; with the
    // answer, a frame or more later, inspect_size, inspect_solids and inspect_distance.
    void update(const scene::Scene& scene, const std::vector<scene::TreeRow>& tree,
                const scene::PartSet& selected, const Things& things, const Events& events);
    void forget(); // a new scene: the same part IDs name other parts
    const InspectReport& report() const { return report_; }
    // Whether an answer is still being worked out (the script's `inspect ready` waits).
    bool computing() const { return report_.computingSelection || report_.computingDistance; }
    // Tests (the script's `inspect hold|release`): questions wait before they start.
    void hold(bool held) { worker_.hold(held); }
    // Tests and batch callers, never a frame: waits until the answer is there to take.
    void wait() { worker_.wait(); }

  private:
    void ask(const scene::Scene& scene, const scene::PartSet& selected, const Things& things,
             const Events& events);
    void takeIn(const scene::Scene& scene, InspectAnswer answer, const Events& events);

    bool valid_ = false;
    scene::PartSet selection_;
    uint64_t version_ = 0;
    std::string saidThings_ = "none|none";
    InspectReport report_;
    util::LatestWorker<InspectAnswer> worker_; // last: joined before the rest goes
};

} // namespace app
