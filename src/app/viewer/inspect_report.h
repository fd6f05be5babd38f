// inspect_report.h - what the Inspect panel says of the selection and of things A and B: the
// selection's bounding box and size, each selected CAD solid's volume, area and centre of
// mass and their sum, and A's and B's distance (scene/inspect.h). Worked out once each time
// the selection or the things change, never per frame: exact answers take Open CASCADE
// milliseconds to seconds. Plain C++ (no ImGui), unit-tested.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/viewer/things.h"
#include "scene/assembly_tree.h"
#include "scene/inspect.h"
#include "scene/part_set.h"

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
};

// The panel's rows of a report; lengths, areas and volumes in `unit`.
std::vector<InspectRow> inspectRows(const scene::Scene& scene, const InspectReport& report);

// Keeps the report of the last selection and things, and works it out again when they change.
class Inspector {
  public:
    // A selection of more solids than this lists the first ones: each costs a B-rep walk.
    static constexpr uint32_t maxSolids = 64;

    // Whether update() would work the report out again.
    bool stale(const scene::PartSet& selected, const Things& things) const {
        return !valid_ || selected != selection_ || things.version() != version_;
    }
    // Works the report out when stale; returns the event lines to say then ("inspect things
    // A|B", "inspect distance D mm", "inspect size ...", "inspect solids ..."), else none.
    std::vector<std::string> update(const scene::Scene& scene,
                                    const std::vector<scene::TreeRow>& tree,
                                    const scene::PartSet& selected, const Things& things);
    void forget() { valid_ = false; } // a new scene: the same part IDs name other parts
    const InspectReport& report() const { return report_; }

  private:
    bool valid_ = false;
    scene::PartSet selection_;
    uint64_t version_ = 0;
    std::string saidThings_ = "none|none";
    InspectReport report_;
};

} // namespace app
