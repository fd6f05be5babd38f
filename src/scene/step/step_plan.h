// step_plan.h - where each record of a lexed STEP file goes (step_plan.cpp): the geometry
// representations and their solid items, the styled items that follow the geometry into
// the pieces, and the records the skeleton leaves out. Internal to the splitter.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "scene/step/step_index.h"

namespace scene::step {

// Per-record marks.
enum Mark : uint16_t {
    kInGeometry = 1u << 0,       // reachable from a solid item
    kSolidItem = 1u << 1,        // a solid-like item of a geometry representation
    kGeometryRep = 1u << 2,      // a geometry representation (rewritten in the skeleton)
    kStyledOnGeometry = 1u << 3, // a styled item whose item is in geometry: goes to pieces
    kStyledTarget = 1u << 4,     // the item of such a styled item
    kDropped = 1u << 5,          // left out of the skeleton: it uses geometry
    kReferenced = 1u << 6,       // some record references it (else it is a root)
    kFiltered = 1u << 7,         // a presentation representation that loses items
    kEntered = 1u << 8,          // the drop pass has been here
    // A styled item on a representation's one solid whose style holds for one instance
    // (Open CASCADE writes an instance's colour so): it stays in the skeleton, on the
    // representation's set, where the reader gives the colour to that instance again.
    kInstanceStyle = 1u << 9,
};

struct GeometryRep {
    uint32_t record = 0;
    uint32_t context = kNoRecord;
    std::vector<uint32_t> solidItems; // in item order
    std::vector<uint32_t> otherItems; // placements and the like: they stay in the skeleton
};

struct Plan {
    std::vector<uint32_t> flags;                               // per type: step_types.h
    std::vector<uint16_t> marks;                               // per record: Mark
    std::vector<GeometryRep> reps;                             // in file order
    std::unordered_map<uint32_t, uint32_t> repOfSolid;         // solid item -> index in reps
    std::vector<std::pair<uint32_t, uint32_t>> styledByTarget; // (item, styled item), sorted
    std::unordered_map<uint32_t, uint32_t> repOfInstanceStyle; // kInstanceStyle -> rep
    // The items a filtered presentation representation keeps.
    std::unordered_map<uint32_t, std::vector<uint32_t>> keptItems;

    uint32_t flagsOf(const StepIndex& index, uint32_t record) const {
        return flags[index.type[record]];
    }
    bool marked(uint32_t record, uint16_t mark) const { return (marks[record] & mark) != 0; }
};

// Works out the plan, or why the file cannot be split (one line).
std::optional<std::string> makePlan(const StepIndex& index, Plan& plan);

} // namespace scene::step
